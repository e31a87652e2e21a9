"""Jointed nonlinear paths (SPEC §5.1, thesis ch. 7).

A joint is a chord ``(a, b)`` between two vertices of a polygon. Non-crossing
chords cut the polygon into *local bodies*; each body gets the nonlinear paths
of SPEC §4 around its own center of mass, and a joint vertex, which belongs to
two or more bodies, follows the mean of its bodies' paths so the outline never
cracks.
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from . import paths

__all__ = ["JointError", "PathFunction", "validate_joints", "bodies", "jointed"]

Array = NDArray[np.float64]
PathFunction = Callable[[Array, Array, ArrayLike], Array]
"""``f(k0 (N, 2), k1 (N, 2), t (T,)) -> (T, N, 2)``, like the functions of :mod:`paths`."""


class JointError(ValueError):
    """A joint that cannot split the polygon; ``index`` is its position in the joint list."""

    def __init__(self, index: int, message: str) -> None:
        self.index = index
        super().__init__(message)


def _as_pair(index: int, joint: object) -> tuple[int, int]:
    try:
        a, b = joint  # type: ignore[misc]
        return operator.index(a), operator.index(b)
    except (TypeError, ValueError):
        message = f"joint {index} must be a pair of vertex indices, found {joint!r}"
        raise JointError(index, message) from None


def _inside(x: int, a: int, b: int, n: int) -> bool:
    """Whether vertex ``x`` lies strictly inside the run going forward from ``a`` to ``b``."""
    return 0 < (x - a) % n < (b - a) % n


def validate_joints(n: int, joints: Sequence[tuple[int, int]]) -> None:
    """Raise :class:`JointError` unless ``joints`` can cut an ``n``-vertex polygon into bodies.

    Each chord must join two distinct, non-neighbouring vertices in ``0..n-1``
    (so each side keeps at least 3 vertices, joint ends included); chords may
    share an endpoint but must not cross or repeat. The error names the first
    offending joint in list order.
    """
    seen: list[tuple[int, int]] = []
    for k, joint in enumerate(joints):
        a, b = _as_pair(k, joint)
        for v in (a, b):
            if not 0 <= v < n:
                raise JointError(
                    k,
                    f"joint {k} [{a}, {b}] is out of range: "
                    f"a polygon of {n} vertices has indices 0..{n - 1}",
                )
        if a == b:
            raise JointError(k, f"joint {k} [{a}, {b}] joins vertex {a} to itself")
        if (b - a) % n < 2 or (a - b) % n < 2:
            raise JointError(
                k,
                f"joint {k} [{a}, {b}] joins neighbouring vertices: "
                "each side of a joint needs at least 3 vertices",
            )
        for j, (c, d) in enumerate(seen):
            if {a, b} == {c, d}:
                raise JointError(k, f"joint {k} [{a}, {b}] repeats joint {j} [{c}, {d}]")
            if len({a, b, c, d}) == 4 and _inside(c, a, b, n) != _inside(d, a, b, n):
                raise JointError(k, f"joint {k} [{a}, {b}] crosses joint {j} [{c}, {d}]")
        seen.append((a, b))


def bodies(n: int, joints: Sequence[tuple[int, int]]) -> list[NDArray[np.intp]]:
    """The local bodies cut by ``joints``, each an ascending array of vertex indices.

    Every body includes its joint vertices, so a joint vertex appears in two or
    more bodies. Bodies are sorted lexicographically by their indices; with no
    joints there is one body, ``0..n-1``. Raises :class:`JointError` for bad joints.
    """
    validate_joints(n, joints)
    # Each body is kept as a cyclic run of polygon vertices; a chord lies inside
    # exactly one current body (chords do not cross) and splits it in two.
    runs: list[list[int]] = [list(range(n))]
    for k, joint in enumerate(joints):
        a, b = _as_pair(k, joint)
        holder = next(i for i, run in enumerate(runs) if a in run and b in run)
        run = runs.pop(holder)
        i, j = sorted((run.index(a), run.index(b)))
        runs.append(run[i : j + 1])
        runs.append(run[j:] + run[: i + 1])
    return [np.array(r, dtype=np.intp) for r in sorted(sorted(run) for run in runs)]


def jointed(
    k0: Array,
    k1: Array,
    t: ArrayLike,
    joints: Sequence[tuple[int, int]],
    body_paths: PathFunction | Sequence[PathFunction] | None = None,
) -> Array:
    """Per-body paths, joint vertices averaged over their bodies: ``(T, N, 2)``.

    ``body_paths`` is one path function for every body, or one per body in the
    order of :func:`bodies`; the default is :func:`paths.nonlinear`, so each body
    turns about its own center of mass. With no joints this is ``body_paths``
    (or ``paths.nonlinear``) of the whole shape.
    """
    k0 = np.asarray(k0, dtype=np.float64)
    k1 = np.asarray(k1, dtype=np.float64)
    if k0.shape != k1.shape or k0.ndim != 2 or k0.shape[1] != 2:
        raise ValueError(f"keys must both be (N, 2), found {k0.shape} and {k1.shape}")
    t = paths.as_times(t)
    n = k0.shape[0]
    parts = bodies(n, joints)
    if body_paths is None:
        body_paths = paths.nonlinear
    functions = [body_paths] * len(parts) if callable(body_paths) else list(body_paths)
    if len(functions) != len(parts):
        raise ValueError(
            f"{len(parts)} bodies need {len(parts)} path functions, found {len(functions)}"
        )

    # A joint vertex's mean is taken as first path + mean deviation from it, so
    # that where all bodies agree (t = 0 and 1) the key is hit bit for bit.
    out = np.zeros((t.shape[0], n, 2))
    offset = np.zeros_like(out)
    count = np.zeros(n)
    for index, f in zip(parts, functions):
        path = np.asarray(f(k0[index], k1[index], t), dtype=np.float64)
        first = count[index] == 0
        out[:, index[first]] = path[:, first]
        offset[:, index] += path - out[:, index]
        count[index] += 1
    return out + offset / count[None, :, None]
