"""Every interpolation method, in one registry, and one entry point that runs them.

:data:`REGISTRY` is the only list of methods: the scene file's validation, the command line's
choices, ``stats`` and the docs' method table all derive from it (a test holds the docs to it).
Adding a method is one :class:`Method` entry here and the module that computes its paths.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Callable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...errors import GeometryError, did_you_mean
from . import paths

__all__ = ["Method", "REGISTRY", "METHODS", "interpolate", "per_outline", "measured_methods", "unknown_method"]

Array = NDArray[np.float64]
Joints = Sequence[tuple[int, int]]
PathFunction = Callable[[Array, Array, Array, Joints], Array]


@dataclass(frozen=True, slots=True)
class Method:
    """One method: its ``name``, the function giving ``(T, N, 2)`` paths of keys ``(N, 2)`` at ``t (T,)``,
    and how the rest of the package treats it.

    ``summary`` is its row of the docs' method table; ``per_outline`` says it works on one closed
    outline at a time (a shape of several contours takes it contour by contour, placed by the rigid
    paths of the whole); ``needs_joints`` says it is measured only where a shape has joints.
    """

    name: str
    paths: PathFunction
    summary: str
    per_outline: bool = False
    needs_joints: bool = False
    closure: str | None = None  # intrinsic paths: how the walk of edges is closed (core/intrinsic.py)


def _linear(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    return paths.linear(k0, k1, t)


def _nonlinear(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    return paths.nonlinear(k0, k1, t)


def _rigid(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    return paths.rigid(k0, k1, t)


def _jointed(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    from .joints import jointed_paths

    return jointed_paths(k0, k1, t, joints)  # without joints: the nonlinear paths of the whole shape


def _arap(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    from .arap import arap

    return arap(k0, k1, t)  # joints are not needed: the triangulated shape bends where it must


def _intrinsic(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    from .intrinsic import intrinsic

    return intrinsic(k0, k1, t, closure="paper")


def _intrinsic_length(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    from .intrinsic import intrinsic

    return intrinsic(k0, k1, t, closure="length")


def _injective(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    from .injective import injective

    return injective(k0, k1, t, joints)  # never crosses itself (maths §5.9)


def _auto(k0: Array, k1: Array, t: Array, joints: Joints) -> Array:
    from .qcurves import auto

    return auto(k0, k1, t, joints)


REGISTRY: dict[str, Method] = {m.name: m for m in (
    Method("linear", _linear, "straight lines `(1−t)·K0 + t·K1`"),
    Method("nonlinear", _nonlinear,
           "the thesis's quadratic Béziers, through the mid-frame pushed back out to each vertex's distance "
           "from the center of mass"),
    Method("rigid", _rigid,
           "exact: the center moves straight while the shape turns by `t·φ`; a rigid motion is kept at every t"),
    Method("jointed", _jointed,
           "bodies cut by `joints`: the largest takes the nonlinear paths, each other body turns about the "
           "joint it hangs from", needs_joints=True),
    Method("arap", _arap,
           "as rigid as possible (Alexa et al. 2000): triangles turn and stretch by a share of their own "
           "change; bends at joints without `joints`", per_outline=True),
    Method("intrinsic", _intrinsic,
           "edge lengths and turning angles blended (Sederberg et al. 1993), closed with the paper's weights",
           per_outline=True, closure="paper"),
    Method("intrinsic-length", _intrinsic_length,
           "the same as `intrinsic`, the closing change weighted by edge length", per_outline=True,
           closure="length"),
    Method("injective", _injective,
           "never crosses itself: every contour of an element in one compatible triangulation of both keys, "
           "each triangle turning and stretching by a share of its own change, made injective by projection"),
    Method("auto", _auto,
           "by measured quality: nonlinear where the Q-curves show a rigid turn and it does not tangle; else "
           "straight paths where they do not tangle; else injective where it tangles less without straying further"),
)}

METHODS: tuple[str, ...] = tuple(REGISTRY)
"""Every method's name, in the order help texts and tables list them."""


def unknown_method(name: object) -> str:
    """The message for a method name that is not in the registry (with a "did you mean")."""
    return f"unknown method {name!r}{did_you_mean(str(name), METHODS)}; expected one of {', '.join(METHODS)}"


def per_outline(name: str) -> bool:
    """Whether ``name`` works on one closed outline at a time (a triangulation, a closed walk of edges)."""
    return REGISTRY[name].per_outline


def measured_methods(jointed: bool) -> tuple[str, ...]:
    """The methods ``stats`` and ``report`` measure on a shape: all, less those that need joints
    where the shape has none."""
    return tuple(m.name for m in REGISTRY.values() if jointed or not m.needs_joints)


MAX_T = 1e6
"""The largest ``|t|`` :func:`interpolate` takes: far past the keys, short of overflowing a coordinate."""


def _numbers(value: object, name: str) -> Array:
    """``value`` as a float64 array, or a :class:`GeometryError` naming ``name`` (text, ``None``, a mapping,
    an integer too large for a float are not numbers)."""
    try:
        if isinstance(value, (str, bytes, dict)) or value is None:
            raise TypeError
        return np.asarray(value, dtype=np.float64)
    except (TypeError, ValueError, OverflowError):
        shown = repr(value)
        shown = shown if len(shown) <= 40 else f"{shown[:20]}…"
        raise GeometryError(f"{name}: expected numbers, found {shown}") from None


def interpolate(k0: Array, k1: Array, t: ArrayLike, method: str, joints: Joints = ()) -> Array:
    """Inbetweens of corresponding keys ``(N, 2)`` at ``t (T,)`` by ``method``: ``(T, N, 2)``.

    At t = 0 and t = 1 the keys themselves are returned, bit for bit.
    """
    found = REGISTRY.get(method) if isinstance(method, str) else None
    if found is None:
        raise GeometryError(unknown_method(method))
    k0, k1 = _numbers(k0, "k0"), _numbers(k1, "k1")
    if k0.ndim != 2 or k0.shape[-1:] != (2,) or k0.shape != k1.shape:
        raise GeometryError(f"keys must both be (N, 2) with the same N, found {k0.shape} and {k1.shape}")
    for name, key in (("k0", k0), ("k1", k1)):
        if not np.all(np.isfinite(key)):  # keys near the float range's ends are drawn, without a warning
            raise GeometryError(f"{name}: expected finite coordinates, found NaN or infinity")
    t = np.atleast_1d(_numbers(t, "t"))
    if t.ndim != 1:
        raise GeometryError(f"t: expected a number or a list of numbers (T,), found shape {t.shape}")
    if not np.all(np.abs(t) <= MAX_T):
        raise GeometryError(f"t: expected finite times from {-MAX_T:g} to {MAX_T:g} (0 and 1 are the keys)")
    frames = found.paths(k0, k1, t, joints)
    frames[t == 0.0] = k0
    frames[t == 1.0] = k1
    return frames
