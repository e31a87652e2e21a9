"""A vector file's content, as plain arrays: each element's runs of frames, keyframed paths and paint.

Built by :mod:`tweenrender.pipeline.vector_export`; written by :mod:`.lottie` and :mod:`.animated_svg`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..model import Color

__all__ = ["Handles", "STRAIGHT", "EASE_HANDLES", "VectorRun", "VectorClip"]

Array = NDArray[np.float64]


Handles = tuple[float, float, float, float]
"""A CSS ``cubic-bezier(x1, y1, x2, y2)``: the timing between two keyframes."""

STRAIGHT: Handles = (0.0, 0.0, 1.0, 1.0)
"""Even timing: a straight line through (0, 0) and (1, 1)."""

EASE_HANDLES: dict[str, Handles] = {
    "linear": (0.0, 0.0, 1.0, 1.0),
    "in": (1 / 3, 0.0, 2 / 3, 1 / 3),  # x(u) = u, y(u) = u²
    "out": (1 / 3, 2 / 3, 2 / 3, 1.0),  # y(u) = 1 - (1 - u)²
    "in-out": (1 / 3, 0.0, 2 / 3, 1.0),  # y(u) = 3u² - 2u³
}
"""Each easing as the CSS ``cubic-bezier(x1, y1, x2, y2)`` that draws it exactly (its x(u) is u)."""


@dataclass(frozen=True)
class VectorRun:
    """One element drawn over clip frames ``first .. stop - 1``, as keyframes.

    ``path_frames (K,)`` are clip frame indices (increasing; they may reach past the run, to the keys
    it moves between), ``paths`` one ``(K, L_i, 2)`` pixel array per contour, ``closed`` per contour;
    ``eases`` the cubic-bezier timing of each span between consecutive path keyframes (K - 1).
    ``paint_frames (P,)`` with ``fill``/``stroke (P, 4)`` straight RGBA in [0, 1] (``None``: never
    drawn), ``width (P,)`` pixels, ``opacity (P,)``, keyed straight. ``exact_frames``: every
    contour's exact pixels at every frame of the run, side by side, ``(stop - first, sum L_i, 2)``,
    kept for measuring. ``contour_widths (P, C)``: each contour's stroke width where some contour grows
    from (or shrinks to) a point and is stroked with its share of the width (``None``: all ``width``).
    """

    element: str
    first: int
    stop: int
    path_frames: tuple[int, ...]
    paths: tuple[Array, ...]
    closed: tuple[bool, ...]
    eases: tuple[Handles, ...]
    paint_frames: tuple[int, ...]
    fill: Array | None
    stroke: Array | None
    width: Array
    opacity: Array
    fill_rule: str
    cap: str
    join: str
    miter_limit: float
    exact_frames: Array
    contour_widths: Array | None = None

    def stroke_groups(self) -> list[tuple[list[int], Array]]:
        """The contours stroked alike and their width at each paint keyframe: ``[(contour indices, (P,))]``
        (one group of all unless some contour grows from a point with its share of the width)."""
        if self.contour_widths is None:
            return [(list(range(len(self.paths))), self.width)]
        groups: list[tuple[list[int], Array]] = []
        for index in range(len(self.paths)):
            column = self.contour_widths[:, index]
            for members, widths in groups:
                if np.array_equal(widths, column):
                    members.append(index)
                    break
            else:
                groups.append(([index], column))
        return groups


@dataclass(frozen=True)
class VectorClip:
    """The whole file: ``frames`` frames at ``fps`` of ``size`` pixels over ``background``; ``runs`` in
    paint order (first drawn first)."""

    size: tuple[int, int]
    fps: float
    frames: int
    background: Color
    runs: tuple[VectorRun, ...]
    max_error: float
