"""World ↔ pixel mapping: y up in the world, y down on the canvas, aspect kept."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterable

import numpy as np
from numpy.typing import NDArray

from ..model import Gradient

__all__ = ["Viewport", "fit_box", "pixel_affine"]

Box = tuple[float, float, float, float]
_MAX_SCALE = 1e307
_FAR = 1e300  # pixel coordinates are kept within ±_FAR: finite, and their differences too


def fit_box(polygons: Iterable[NDArray[np.float64]], margin: float = 0.08) -> Box:
    """The bounding box of every polygon ``(N, 2)``, grown by ``margin`` of its larger side."""
    stacked = np.concatenate([np.asarray(p, dtype=np.float64).reshape(-1, 2) for p in polygons])
    stacked = stacked[np.all(np.isfinite(stacked), axis=1)]
    if len(stacked) == 0:
        return (-1.0, -1.0, 1.0, 1.0)
    (x0, y0), (x1, y1) = stacked.min(axis=0), stacked.max(axis=0)
    side = max(x1 - x0, y1 - y0)
    pad = margin * side if side > 0 else 1.0
    return (float(x0 - pad), float(y0 - pad), float(x1 + pad), float(y1 + pad))


@dataclass(frozen=True, slots=True)
class Viewport:
    """Maps the world box ``view`` into a ``width × height`` pixel canvas, centred, aspect kept."""

    view: Box
    width: int
    height: int

    @property
    def scale(self) -> float:
        """Pixels per world unit (at most 1e307: a view of 1e-320 would make it infinite)."""
        x0, y0, x1, y1 = self.view
        with np.errstate(over="ignore", divide="ignore"):
            return float(min(self.width / (x1 - x0), self.height / (y1 - y0), _MAX_SCALE))

    def _placement(self) -> tuple[float, float, float]:
        """``(scale, ox, oy)``: the view scaled, then moved ``ox, oy`` pixels to sit centred (y up)."""
        x0, y0, x1, y1 = self.view
        s = self.scale
        return s, 0.5 * (self.width - s * (x1 - x0)), 0.5 * (self.height - s * (y1 - y0))

    @property
    def matrix(self) -> NDArray[np.float64]:
        """World → pixel as a ``(3, 3)`` affine matrix (what :meth:`to_pixels` does, without its clamp)."""
        x0, y0 = self.view[0], self.view[1]
        s, ox, oy = self._placement()
        return np.array([[s, 0.0, ox - s * x0], [0.0, -s, self.height - oy + s * y0], [0.0, 0.0, 1.0]])

    def to_pixels(self, points: NDArray[np.float64]) -> NDArray[np.float64]:
        """World ``(..., 2)`` → pixel ``(..., 2)`` (origin top-left, y down), each within ±1e300.

        A view of 1e-300 magnifies by 1e302: far vertices overflow to ±inf, deliberately, and are
        brought back to ±1e300 (far off any canvas; see :mod:`.clip` for what is then drawn).
        """
        x0, y0 = self.view[0], self.view[1]
        s, ox, oy = self._placement()
        with np.errstate(over="ignore", invalid="ignore"):
            px = (points[..., 0] - x0) * s + ox
            py = self.height - ((points[..., 1] - y0) * s + oy)
        return np.clip(np.stack([px, py], axis=-1), -_FAR, _FAR)


def pixel_affine(gradient: Gradient, viewport: Viewport) -> NDArray[np.float64]:
    """Gradient space → canvas pixels as a ``(3, 3)`` affine matrix: the gradient's own matrix, then the
    viewport's (y flipped)."""
    a, b, c, d, e, f = gradient.matrix
    return viewport.matrix @ np.array([[a, c, e], [b, d, f], [0.0, 0.0, 1.0]])
