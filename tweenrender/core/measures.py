"""The thesis's ch. 6 measures: perimeter and area ratios, edge-length error."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from .geometry import area, edge_lengths, perimeter
from .methods import interpolate

__all__ = ["SWEEP", "MethodReport", "report", "edge_error"]

Array = NDArray[np.float64]

SWEEP = np.linspace(0.0, 1.0, 101)
"""The t values over which minima and maxima are taken."""


def edge_error(frames: Array, k0: Array, k1: Array, t: Array) -> Array:
    """``|L(t) / ((1-t)·L0 + t·L1) - 1|`` per frame and edge: ``(T, N)``; NaN where the reference is 0."""
    reference = (1.0 - t)[:, None] * edge_lengths(k0) + t[:, None] * edge_lengths(k1)
    lengths = edge_lengths(frames)
    with np.errstate(divide="ignore", invalid="ignore"):
        error = np.abs(lengths / reference - 1.0)
    return np.where(reference > 0, error, np.nan)


@dataclass(frozen=True, slots=True)
class MethodReport:
    """One method's measures on one segment at the asked ``t`` values."""

    t: tuple[float, ...]
    perimeter: tuple[float, ...]
    perimeter_keys: tuple[float, float]
    perimeter_mean: float
    ratio: tuple[float, ...]
    ratio_min: float
    ratio_max: float
    edge_error_max: float
    area_ratio: tuple[float, ...]

    def as_dict(self) -> dict[str, object]:
        return {name: getattr(self, name) for name in self.__slots__}


def report(k0: Array, k1: Array, method: str, t: Sequence[float],
           joints: Sequence[tuple[int, int]] = ()) -> MethodReport:
    """Measures of ``method`` between corresponding keys ``(N, 2)`` at ``t``."""
    asked = np.asarray(t, dtype=np.float64)
    keys_perimeter = (float(perimeter(k0)), float(perimeter(k1)))
    mean = 0.5 * sum(keys_perimeter)
    mean_area = 0.5 * (float(area(k0)) + float(area(k1)))
    frames = interpolate(k0, k1, asked, method, joints)
    swept = interpolate(k0, k1, SWEEP, method, joints)
    swept_ratio = perimeter(swept) / mean if mean > 0 else np.ones(len(SWEEP))
    errors = edge_error(swept, k0, k1, SWEEP)
    return MethodReport(
        t=tuple(float(x) for x in asked),
        perimeter=tuple(float(p) for p in perimeter(frames)),
        perimeter_keys=keys_perimeter,
        perimeter_mean=mean,
        ratio=tuple(float(p / mean) if mean > 0 else 1.0 for p in perimeter(frames)),
        ratio_min=float(swept_ratio.min()),
        ratio_max=float(swept_ratio.max()),
        edge_error_max=float(np.nanmax(errors)) if np.any(np.isfinite(errors)) else 0.0,
        area_ratio=tuple(float(a / mean_area) if mean_area > 0 else 1.0 for a in area(frames)),
    )
