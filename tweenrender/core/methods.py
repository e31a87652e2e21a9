"""One entry point for every interpolation method."""

from __future__ import annotations

from typing import Callable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..errors import GeometryError
from . import paths
from .arap import arap
from .injective import injective
from .intrinsic import intrinsic
from .joints import jointed
from .qcurves import auto

__all__ = ["interpolate"]

Array = NDArray[np.float64]
Joints = Sequence[tuple[int, int]]


def _linear(k0: Array, k1: Array, t: ArrayLike, joints: Joints) -> Array:
    return paths.linear(k0, k1, t)


def _nonlinear(k0: Array, k1: Array, t: ArrayLike, joints: Joints) -> Array:
    return paths.nonlinear(k0, k1, t)


def _rigid(k0: Array, k1: Array, t: ArrayLike, joints: Joints) -> Array:
    return paths.rigid(k0, k1, t)


def _arap(k0: Array, k1: Array, t: ArrayLike, joints: Joints) -> Array:
    return arap(k0, k1, t)


def _intrinsic(k0: Array, k1: Array, t: ArrayLike, joints: Joints) -> Array:
    return intrinsic(k0, k1, t, closure="paper")


def _intrinsic_length(k0: Array, k1: Array, t: ArrayLike, joints: Joints) -> Array:
    return intrinsic(k0, k1, t, closure="length")


_METHODS: dict[str, Callable[[Array, Array, ArrayLike, Joints], Array]] = {
    "linear": _linear,
    "nonlinear": _nonlinear,
    "rigid": _rigid,
    "jointed": jointed,  # without joints: the nonlinear paths of the whole shape
    "arap": _arap,  # joints are not needed: the triangulated shape bends where it must
    "intrinsic": _intrinsic,  # the paper's closing weights
    "intrinsic-length": _intrinsic_length,  # closing weighted by edge length (docs/intrinsic.md)
    "injective": injective,  # never crosses itself (maths §5.9)
    "auto": auto,
}


def interpolate(k0: Array, k1: Array, t: ArrayLike, method: str, joints: Joints = ()) -> Array:
    """Inbetweens of corresponding keys ``(N, 2)`` at ``t (T,)`` by ``method``: ``(T, N, 2)``.

    At t = 0 and t = 1 the keys themselves are returned, bit for bit.
    """
    try:
        fn = _METHODS[method]
    except KeyError:
        raise GeometryError(f"unknown method {method!r}; expected one of {', '.join(_METHODS)}") from None
    k0, k1 = np.asarray(k0, dtype=np.float64), np.asarray(k1, dtype=np.float64)
    if k0.ndim != 2 or k0.shape[-1:] != (2,) or k0.shape != k1.shape:
        raise GeometryError(f"keys must both be (N, 2) with the same N, found {k0.shape} and {k1.shape}")
    t = paths.as_times(t)
    frames = fn(k0, k1, t, joints)
    frames[t == 0.0] = k0
    frames[t == 1.0] = k1
    return frames
