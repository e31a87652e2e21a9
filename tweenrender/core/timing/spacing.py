"""Spacing charts (maths §5.11): the animator's ticks, made a timing curve by a monotone cubic.

A chart gives positions ``s_0 = 0 ≤ s_1 ≤ … ≤ s_m = 1`` (fractions of the way) at the evenly
spaced time fractions ``k / m`` of a segment, as an animator marks where the in-betweens fall.
Between ticks the position follows the Fritsch–Carlson (1980) monotone piecewise cubic Hermite
curve, so any frame rate samples it and it never runs backwards:

1. secants ``δ_k = (s_{k+1} - s_k) · m``;
2. tangents: ``d_0 = δ_0``, ``d_m = δ_{m-1}``, inside the mean ``(δ_{k-1} + δ_k) / 2``, or 0 where
   a neighbouring secant is 0;
3. on a flat interval (``δ_k = 0``) both end tangents are 0; otherwise with ``α = d_k / δ_k``,
   ``β = d_{k+1} / δ_k``, where ``α² + β² > 9`` both are scaled by ``3 / √(α² + β²)``
   (intervals in order, each seeing the tangents the one before left).

(scipy's ``PchipInterpolator`` takes Fritsch–Butland's weighted harmonic mean for the tangents:
another curve.)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = ["Spacing", "SpacingError", "spacing_chart", "fritsch_carlson_tangents"]

Array = NDArray[np.float64]


class SpacingError(ValueError):
    """Ticks that make no chart; the message says what was expected (the caller adds where);
    ``index`` is the offending position's, when one is to blame."""

    def __init__(self, message: str, index: int | None = None) -> None:
        super().__init__(message)
        self.index = index


@dataclass(frozen=True, slots=True)
class Spacing:
    """A spacing chart: ``ticks (m + 1,)`` at time fractions ``k / m``, and their tangents."""

    ticks: tuple[float, ...]
    tangents: tuple[float, ...]

    @property
    def text(self) -> str:
        return "spacing"

    @property
    def overshoots(self) -> bool:
        return False

    def __call__(self, u: ArrayLike) -> Array:
        """Positions at time fractions ``u (T,)`` in [0, 1]: ``(T,)``, exactly the ticks at ``k / m``."""
        u = np.atleast_1d(np.asarray(u, dtype=np.float64))
        s, d = np.array(self.ticks), np.array(self.tangents)
        m = len(s) - 1
        x = np.clip(u, 0.0, 1.0) * m
        k = np.minimum(np.floor(x).astype(np.intp), m - 1)
        h = x - k  # in [0, 1] within interval k (width 1/m in u: tangents scale by 1/m)
        h2, h3 = h * h, h * h * h
        out = ((2 * h3 - 3 * h2 + 1) * s[k] + (h3 - 2 * h2 + h) * d[k] / m
               + (-2 * h3 + 3 * h2) * s[k + 1] + (h3 - h2) * d[k + 1] / m)
        at_tick = h == 0.0
        out[at_tick] = s[k[at_tick]]
        out[u >= 1.0] = 1.0
        out[u <= 0.0] = 0.0
        return out


def fritsch_carlson_tangents(ticks: ArrayLike) -> Array:
    """Tangents ``(m + 1,)`` (per unit of time fraction) of the monotone cubic through ``ticks (m + 1,)``
    at ``k / m`` (see the module's docstring)."""
    s = np.asarray(ticks, dtype=np.float64)
    m = len(s) - 1
    delta = np.diff(s) * m
    d = np.empty(m + 1)
    d[0], d[m] = delta[0], delta[m - 1]
    for k in range(1, m):
        if delta[k - 1] == 0.0 or delta[k] == 0.0 or (delta[k - 1] > 0) != (delta[k] > 0):
            d[k] = 0.0
        else:
            d[k] = 0.5 * (delta[k - 1] + delta[k])
    for k in range(m):
        if delta[k] == 0.0:
            d[k] = d[k + 1] = 0.0
            continue
        # alpha² + beta² > 9 and the scaling by 3 / sqrt(alpha² + beta²), written without dividing
        # by delta_k, whose quotients overflow when it is subnormal ([0, 1e-320, 1])
        length = math.hypot(d[k], d[k + 1])
        if length > 3.0 * delta[k]:
            d[k], d[k + 1] = 3.0 * delta[k] * (d[k] / length), 3.0 * delta[k] * (d[k + 1] / length)
    return d


def spacing_chart(ticks: ArrayLike) -> Spacing:
    """The chart of ``ticks``: at least two numbers, 0 first, 1 last, non-decreasing; else :class:`SpacingError`."""
    values = [float(v) for v in np.atleast_1d(np.asarray(ticks, dtype=np.float64))]
    if len(values) < 2:
        raise SpacingError(f"expected at least two positions (0 first, 1 last), found {len(values)}")
    if not all(math.isfinite(v) for v in values):
        raise SpacingError("expected finite positions")
    if values[0] != 0.0 or values[-1] != 1.0:
        raise SpacingError(f"expected 0 first and 1 last, found {values[0]:g} first and {values[-1]:g} last")
    for k in range(1, len(values)):
        if values[k] < values[k - 1]:
            raise SpacingError(f"expected non-decreasing positions, found {values[k]:g} after {values[k - 1]:g}", k)
    return Spacing(tuple(values), tuple(float(d) for d in fritsch_carlson_tangents(values)))
