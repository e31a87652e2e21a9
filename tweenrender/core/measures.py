"""Quality measures of inbetweens: the thesis's ch. 6 perimeter ratio and its companions.

For keys ``K0``, ``K1`` (corresponding, ``(N, 2)``) and an inbetween ``V(t)``:

* perimeter ratio ``P(t) / P̄`` with ``P̄`` the keys' mean (the thesis's ratio), and
  ``P(t) / ((1-t)·P0 + t·P1)`` against the keys' interpolated perimeter;
* area ratio ``A(t) / ((1-t)·A0 + t·A1)``, signed areas as drawn (1 where that reference is 0);
* edge error ``|L(t) / ((1-t)·L0 + t·L1) - 1|`` per edge (skipped where the reference is 0);
* angle error ``|θ(t) - (θ0 + t·Δθ)|`` per vertex, in degrees, θ the turning angle and ``Δθ``
  its shorter change from ``K0`` to ``K1`` (skipped where an edge has zero length);
* self-intersection: the outline crosses or touches itself (:mod:`.crossings`).

Extremes are taken over :data:`SWEEP`, 101 evenly spaced t of the segment.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from .angles import shorter_change, turning_angles, wrap
from .crossings import self_crossings
from .tangles import SWEEP as _SWEEP
from .geometry import edge_lengths, perimeter, signed_area
from .methods.registry import interpolate

__all__ = ["SWEEP", "MethodReport", "Curves", "report", "curves", "edge_error", "angle_error",
           "area_ratio", "perimeter_ratio"]

Array = NDArray[np.float64]

SWEEP = _SWEEP
"""The t values over which minima and maxima are taken: 101 evenly spaced."""


def edge_error(frames: Array, k0: Array, k1: Array, t: Array) -> Array:
    """``|L(t) / ((1-t)·L0 + t·L1) - 1|`` per frame and edge: ``(T, N)``; NaN where the reference is 0."""
    reference = (1.0 - t)[:, None] * edge_lengths(k0) + t[:, None] * edge_lengths(k1)
    lengths = edge_lengths(frames)
    with np.errstate(divide="ignore", invalid="ignore"):
        error = np.abs(lengths / reference - 1.0)
    return np.where(reference > 0, error, np.nan)


def angle_error(frames: Array, k0: Array, k1: Array, t: Array) -> Array:
    """``|θ(t) - (θ0 + t·Δθ)|`` in degrees per frame and vertex: ``(T, N)``; NaN where θ is undefined."""
    theta0, theta1 = turning_angles(k0), turning_angles(k1)
    reference = theta0 + t[:, None] * shorter_change(theta0, theta1)
    return np.degrees(np.abs(wrap(turning_angles(frames) - reference)))


def area_ratio(frames: Array, k0: Array, k1: Array, t: Array) -> Array:
    """``A(t) / ((1-t)·A0 + t·A1)``, signed areas: ``(T,)``; 1 where the reference area is 0."""
    reference = (1.0 - t) * float(signed_area(k0)) + t * float(signed_area(k1))
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = signed_area(frames) / reference
    return np.where(reference != 0, ratio, 1.0)


def perimeter_ratio(frames: Array, k0: Array, k1: Array, t: Array) -> Array:
    """``P(t) / ((1-t)·P0 + t·P1)``: ``(T,)``; 1 where the reference perimeter is 0."""
    reference = (1.0 - t) * float(perimeter(k0)) + t * float(perimeter(k1))
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = perimeter(frames) / reference
    return np.where(reference > 0, ratio, 1.0)


def _worst(values: Array) -> Array:
    """Per-row maximum of ``(T, N)`` ignoring NaN: ``(T,)``, 0 for a row with no number."""
    finite = np.where(np.isnan(values), -np.inf, values)
    worst = finite.max(axis=1, initial=-np.inf)
    return np.where(np.isfinite(worst), worst, 0.0)


@dataclass(frozen=True, slots=True)
class Curves:
    """One method's measures over ``t (T,)``, each ``(T,)``; ``crossings`` a point or None per t."""

    t: Array
    perimeter_ratio: Array
    area_ratio: Array
    edge_error: Array
    angle_error: Array
    crossings: tuple[Array | None, ...]

    @property
    def self_intersects(self) -> list[float]:
        """The t at which the outline crosses itself."""
        return [float(t) for t, where in zip(self.t, self.crossings) if where is not None]


def curves(k0: Array, k1: Array, method: str, t: Array = SWEEP,
           joints: Sequence[tuple[int, int]] = (), frames: Array | None = None) -> Curves:
    """Every measure of ``method`` between corresponding keys ``(N, 2)`` at each of ``t (T,)``;
    ``frames (T, N, 2)``, when given, are the inbetweens as drawn (a contour moving with others)."""
    t = np.asarray(t, dtype=np.float64)
    if frames is None:
        frames = interpolate(k0, k1, t, method, joints)
    return Curves(
        t=t,
        perimeter_ratio=perimeter_ratio(frames, k0, k1, t),
        area_ratio=area_ratio(frames, k0, k1, t),
        edge_error=_worst(edge_error(frames, k0, k1, t)),
        angle_error=_worst(angle_error(frames, k0, k1, t)),
        crossings=tuple(self_crossings(frames)),
    )


@dataclass(frozen=True, slots=True)
class MethodReport:
    """One method's measures on one segment at the asked ``t`` values (and over :data:`SWEEP`)."""

    t: tuple[float, ...]
    perimeter: tuple[float, ...]
    perimeter_keys: tuple[float, float]
    perimeter_mean: float
    ratio: tuple[float, ...]
    ratio_min: float
    ratio_max: float
    edge_error_max: float
    area_ratio: tuple[float, ...]
    perimeter_ratio: tuple[float, ...]
    angle_error_max: float
    self_intersects: tuple[float, ...]
    self_intersection_points: tuple[tuple[float, float], ...]

    def as_dict(self) -> dict[str, object]:
        return {name: _plain(getattr(self, name)) for name in self.__slots__}


def _plain(value: object) -> object:
    """Tuples as lists, so the report is JSON as it is."""
    if isinstance(value, tuple):
        return [_plain(v) for v in value]
    return value


def report(k0: Array, k1: Array, method: str, t: Sequence[float],
           joints: Sequence[tuple[int, int]] = (), paths: Callable[[Array], Array] | None = None) -> MethodReport:
    """Measures of ``method`` between corresponding keys ``(N, 2)`` at ``t``, extremes over :data:`SWEEP`.

    ``paths(t (T,)) -> (T, N, 2)`` gives the inbetweens when the contour does not move on its own
    (one of several contours of a shape, moved together); default ``interpolate(k0, k1, t, method)``.
    """
    if paths is None:
        def paths(at: Array) -> Array:
            return interpolate(k0, k1, at, method, joints)
    asked = np.asarray(t, dtype=np.float64)
    keys_perimeter = (float(perimeter(k0)), float(perimeter(k1)))
    mean = 0.5 * sum(keys_perimeter)
    frames = paths(asked)
    swept = paths(SWEEP)
    swept_ratio = perimeter(swept) / mean if mean > 0 else np.ones(len(SWEEP))
    errors = edge_error(swept, k0, k1, SWEEP)
    angles = angle_error(swept, k0, k1, SWEEP)
    crossings = self_crossings(swept)
    return MethodReport(
        t=tuple(float(x) for x in asked),
        perimeter=tuple(float(p) for p in perimeter(frames)),
        perimeter_keys=keys_perimeter,
        perimeter_mean=mean,
        ratio=tuple(float(p / mean) if mean > 0 else 1.0 for p in perimeter(frames)),
        ratio_min=float(swept_ratio.min()),
        ratio_max=float(swept_ratio.max()),
        edge_error_max=float(np.nanmax(errors)) if np.any(np.isfinite(errors)) else 0.0,
        area_ratio=tuple(float(r) for r in area_ratio(frames, k0, k1, asked)),
        perimeter_ratio=tuple(float(r) for r in perimeter_ratio(frames, k0, k1, asked)),
        angle_error_max=float(np.nanmax(angles)) if np.any(np.isfinite(angles)) else 0.0,
        self_intersects=tuple(float(x) for x, where in zip(SWEEP, crossings) if where is not None),
        self_intersection_points=tuple((float(w[0]), float(w[1])) for w in crossings if w is not None),
    )
