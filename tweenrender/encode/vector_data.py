"""A vector file's content, as plain arrays: each element's runs of frames, keyframed paths and paint.

Built by :mod:`tweenrender.vector.export`; written by :mod:`.lottie` and :mod:`.animated_svg`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import NDArray

from ..model import Color

__all__ = ["into_gradient_frame", "PIXEL_DIGITS", "SCALE_DIGITS", "HANDLE_DIGITS", "Handles", "STRAIGHT", "GradientKeys", "ClipPathKeys", "ContourMove", "VectorRun", "VectorClip"]

Array = NDArray[np.float64]


PIXEL_DIGITS = 2
"""Decimals the files write a path's pixels with (a hundredth: each point moves at most 0.0071 px, which the
keyframes leave room for; a thousandth wrote one more digit a number for nothing a player shows)."""

SCALE_DIGITS = 3
"""Decimals to which the files write a scale, in percent (a still contour placed by a :class:`ContourMove`)."""

HANDLE_DIGITS = 6
"""Decimals to which the files write a timing's handles: a span's progress moves by about a millionth, a thousandth
of a pixel on a path crossing a thousand."""

Handles = tuple[float, float, float, float]
"""A CSS ``cubic-bezier(x1, y1, x2, y2)``: the timing between two keyframes."""

STRAIGHT: Handles = (0.0, 0.0, 1.0, 1.0)
"""Even timing: a straight line through (0, 0) and (1, 1)."""


def into_gradient_frame(points: Array, centre: Array, angle: float, ratio: float) -> Array:
    """Pixels ``(..., 2)`` in the frame ``pixel = centre + R(angle) · diag(1, ratio) · u`` (angle in degrees)."""
    theta = np.radians(angle)
    c, s = np.cos(theta), np.sin(theta)
    d = points - centre
    return np.stack([c * d[..., 0] + s * d[..., 1], (-s * d[..., 0] + c * d[..., 1]) / ratio], axis=-1)


@dataclass(frozen=True)
class GradientKeys:
    """A run's gradient fill at each of its paint keyframes, in output pixels (y down), as the raster draws it.

    ``kind`` ``linear`` or ``radial``; ``spread`` ``pad``, ``reflect`` or ``repeat``; ``offsets (S,)`` the
    stops' offsets, common to every keyframe; ``colours (P, S, 4)`` their straight RGBA in [0, 1] (a
    plain fill is a gradient of its one colour). ``start``/``end (P, 2)``: a linear gradient's points at
    offsets 0 and 1; a radial one's centre and the end of its first axis. A radial gradient is a circle
    of radius ``|end - start|`` in its own frame, which ``pixel = start + R(angle) · diag(1, ratio) · u``
    places: ``angle (P,)`` degrees (clockwise on screen, unwrapped), ``ratio (P,)`` the second axis's radius
    over the first, ``focal (P, 2)`` the focal point in that frame (``(0, 0)``: the centre). Linear
    gradients hold ratio 1, angle and focal 0. ``circular``: every frame's ellipse is a circle within the
    clip's tolerance.
    """

    kind: str
    spread: str
    offsets: Array
    colours: Array
    start: Array
    end: Array
    angle: Array
    ratio: Array
    focal: Array
    circular: bool


@dataclass(frozen=True)
class ClipPathKeys:
    """A run's clip paths as keyframes: at clip ``frames (K,)``, ``regions``, each a tuple of closed contours
    ``(K, N, 2)`` in output pixels filled nonzero; what is drawn is the intersection of the regions."""

    frames: tuple[int, ...]
    regions: tuple[tuple[Array, ...], ...]


@dataclass(frozen=True)
class ContourMove:
    """A still contour's place over time: drawn at ``centres[k] + scales[k] · (x - anchor)`` at clip frame
    ``frames[k]`` (``centres (K, 2)`` and ``anchor (2,)`` pixels, ``scales (K,)`` fractions), straight between
    keyframes through each span's ``eases`` (K - 1), held before the first and after the last."""

    frames: tuple[int, ...]
    centres: Array
    scales: Array
    eases: tuple[Handles, ...]
    anchor: Array

    def shifted(self, offset: int) -> "ContourMove":
        """The same move with its frames ``offset`` later."""
        return replace(self, frames=tuple(f + offset for f in self.frames))


@dataclass(frozen=True)
class VectorRun:
    """One element drawn over clip frames ``first .. stop - 1``, as keyframes.

    ``path_frames (K,)`` are clip frame indices (increasing; they may reach past the run, to the keys
    it moves between), ``paths`` one array per contour: ``(K, M_i, 3, 2)`` pixels, a cubic Bézier path
    (per vertex its in control point, the vertex and its out control point; an open contour's first in
    and last out are its vertex), or ``(K, L_i, 2)`` straight edges; ``closed`` per contour;
    ``eases`` the cubic-bezier timing of each span between consecutive path keyframes (K - 1).
    ``paint_frames (P,)`` with ``fill``/``stroke (P, 4)`` straight RGBA in [0, 1] (``None``: never
    drawn), ``width (P,)`` pixels, ``opacity (P,)``, keyed straight. ``exact_frames``: every
    contour's exact pixels at every frame of the run, side by side, ``(stop - first, sum L_i, 2)``,
    kept for measuring, ``exact_lengths`` each contour's L_i (``()``: the paths' own). ``contour_widths
    (P, C)``: each contour's stroke width where some contour grows from (or shrinks to) a point and is
    stroked with its share of the width (``None``: all ``width``).
    ``gradient``: the fill as a gradient at the paint keyframes (``fill`` is then ``None``); ``clip_paths``:
    the clip paths the run is drawn through (``None``: not clipped). ``gradient_paths``: for an elliptical
    radial gradient, the contours in the gradient's own frame (a Lottie group's transform places that
    frame), as ``(frames (K',), (one array per contour, as ``paths``), eases (K' - 1,))``. ``contour_keys``:
    each contour keyed on its own, for files that animate contours apart (Lottie), as ``(frames, path,
    eases)`` per contour (``None``: the run's keyframes). ``dash``: per contour, ``(P, C + 1)``, the stroke's
    dash lengths (dash, gap, …; the same even count C at every paint keyframe) then its offset, in pixels, for
    the contour drawn from its vertex 0 (``None``: solid). ``contour_moves``: per contour, a :class:`ContourMove`
    placing its one still keyframe in :attr:`contour_keys` (a contour that only grows, shrinks and moves), or
    ``None`` (``None`` for all: no contour moves so). ``rule_switch``: the clip frame from which the fill rule
    is the one it names instead of ``fill_rule`` (a plain fill only; ``None``: ``fill_rule`` throughout).
    ``pieces``: the contours grouped so that no contour of one group comes near, crosses or lies inside one of
    another at any frame (:func:`..vector.pieces.apart_pieces`), so each group may be drawn as a path of its own
    (``None``: not looked for); ``piece_cuts``, per piece, the holes a mask cuts out of it (each stays apart from
    the piece's other contours, holds none, and the fill leaves its inside empty: :func:`..vector.pieces.cut_holes`;
    ``None``: none); ``piece_keys``, per piece, the keyframes of the piece's other contours where they are several,
    fitted over them alone (``(frames, one path per contour, eases)``), ``None`` where one is left (its own, with
    its move: :meth:`keys_of`, :meth:`move_of`), as are the holes cut out; set whenever ``pieces`` is.
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
    gradient: GradientKeys | None = None
    clip_paths: ClipPathKeys | None = None
    gradient_paths: tuple[tuple[int, ...], tuple[Array, ...], tuple[Handles, ...]] | None = None
    exact_lengths: tuple[int, ...] = ()
    contour_keys: tuple[tuple[tuple[int, ...], Array, tuple[Handles, ...]], ...] | None = None
    dash: tuple[Array, ...] | None = None
    contour_moves: tuple[ContourMove | None, ...] | None = None
    rule_switch: tuple[int, str] | None = None
    pieces: tuple[tuple[int, ...], ...] | None = None
    piece_keys: tuple[tuple[tuple[int, ...], tuple[Array, ...], tuple[Handles, ...]] | None, ...] | None = None
    piece_cuts: tuple[tuple[int, ...], ...] | None = None

    def move_of(self, index: int) -> ContourMove | None:
        """Contour ``index``'s place over time where its path (:meth:`keys_of`, then one still keyframe) only grows,
        shrinks and moves (:attr:`contour_moves`); ``None``: drawn where its path says."""
        return None if self.contour_moves is None else self.contour_moves[index]

    def drawn_keys(self, index: int) -> tuple[tuple[int, ...], Array, tuple[Handles, ...], ContourMove | None]:
        """Contour ``index``'s keyframes as the animated SVG draws it where it draws the run's pieces apart: a hole
        cut out, or the one contour left of its piece, by its own and its move; another by its piece's own
        (:attr:`piece_keys`), else the run's: ``(frames, path, eases, move)``."""
        for number, members in enumerate(self.pieces or ()):
            if index not in members:
                continue
            cut = self.cut_of(number)
            drawn = [i for i in members if i not in cut]
            if index in cut or len(drawn) == 1:
                return (*self.keys_of(index), self.move_of(index))
            own = None if self.piece_keys is None else self.piece_keys[number]
            if own is not None:
                return own[0], own[1][drawn.index(index)], own[2], None
        return self.path_frames, self.paths[index], self.eases, None

    def cut_of(self, piece: int) -> tuple[int, ...]:
        """The holes a mask cuts out of piece number ``piece`` (:attr:`piece_cuts`)."""
        return () if self.piece_cuts is None else self.piece_cuts[piece]

    def keys_of(self, index: int) -> tuple[tuple[int, ...], Array, tuple[Handles, ...]]:
        """Contour ``index``'s own keyframes where it has them (:attr:`contour_keys`), else the run's:
        ``(frames (K_i,), path (K_i, …) as in ``paths``, eases (K_i - 1,))``."""
        if self.contour_keys is not None:
            return self.contour_keys[index]
        return self.path_frames, self.paths[index], self.eases

    def gradient_matted(self) -> bool:
        """Whether a Lottie draws the run's fill, where its gradient is an ellipse, through a matte of its own paths
        (neither stroked nor clipped), rather than with the paths written in the gradient's frame."""
        return self.stroke is None and self.clip_paths is None

    def gradient_placed(self, frames: Array) -> tuple[Array, Array, Array]:
        """Where a player places the gradient's own frame at clip ``frames (F,)``, each value keyed straight at the
        paint keyframes: centres ``(F, 2)``, angles ``(F,)`` (degrees), ratios ``(F,)`` (:class:`GradientKeys`)."""
        gradient = self.gradient
        assert gradient is not None, "a run filled by a gradient"
        keys = np.array(self.paint_frames, dtype=np.float64)
        centre = np.stack([np.interp(frames, keys, gradient.start[:, k]) for k in range(2)], axis=1)
        return centre, np.interp(frames, keys, gradient.angle), np.interp(frames, keys, gradient.ratio)

    def exact_contours(self) -> list[Array]:
        """:attr:`exact_frames` split per contour: ``(stop - first, L_i, 2)`` each."""
        lengths = self.exact_lengths or tuple(p.shape[1] for p in self.paths)
        return np.split(self.exact_frames, np.cumsum(lengths)[:-1], axis=1) if lengths else []

    def stroke_groups(self) -> list[tuple[list[int], Array]]:
        """The contours stroked alike and their width at each paint keyframe: ``[(contour indices, (P,))]``
        (one group of all unless some contour grows from a point with its share of the width, or contours'
        dash patterns differ)."""
        if self.contour_widths is None and self.dash is None:
            return [(list(range(len(self.paths))), self.width)]
        groups: list[tuple[list[int], Array]] = []
        for index in range(len(self.paths)):
            column = self.width if self.contour_widths is None else self.contour_widths[:, index]
            for members, widths in groups:
                if np.array_equal(widths, column) and (self.dash is None or
                                                        np.array_equal(self.dash[members[0]], self.dash[index])):
                    members.append(index)
                    break
            else:
                groups.append(([index], column))
        return groups


@dataclass(frozen=True)
class VectorClip:
    """The whole file: ``frames`` frames at ``fps`` of ``size`` pixels over ``background``; ``runs`` in
    paint order (first drawn first); ``loop``: played over and over (else once, held at its last frame)."""

    size: tuple[int, int]
    fps: float
    frames: int
    background: Color
    runs: tuple[VectorRun, ...]
    max_error: float
    loop: bool = False
