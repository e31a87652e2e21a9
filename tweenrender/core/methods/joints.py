"""Jointed nonlinear paths (maths §5.1, thesis ch. 7).

A joint is a chord ``(a, b)`` between two vertices of a polygon. Non-crossing
chords cut the polygon into *local bodies*, which form a tree joined by the
chords. The body with most vertices leads: it gets the nonlinear paths of maths §4
around its own center of mass. Each other body turns about its joint, the
midpoint of the chord to the body it hangs from, and that midpoint moves with
the leading side, so the outline never cracks. (maths §5.1's first rule, every
body about its own center of mass and joint vertices on the mean of their bodies'
paths, is kept as ``rule="mean"``; it bends a limb that swings about a hinge.)
"""

from __future__ import annotations

import operator
from collections.abc import Callable, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...errors import GeometryError
from . import paths
from ..geometry import best_fit_rotation, rotate

__all__ = ["JointError", "PathFunction", "RULES", "validate_joints", "bodies", "pivoted", "misfit", "root_body",
           "jointed_paths"]

Array = NDArray[np.float64]
RULES = ("chain", "mean")
"""How bodies share their joint vertices; see :func:`jointed_paths`."""

PathFunction = Callable[[Array, Array, ArrayLike], Array]
"""``f(k0 (N, 2), k1 (N, 2), t (T,)) -> (T, N, 2)``, like the functions of :mod:`paths`."""


class JointError(GeometryError):
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


def pivoted(u0: Array, u1: Array, t: ArrayLike) -> Array:
    """The thesis's nonlinear paths for offsets ``(N, 2)`` that turn about a fixed origin: ``(T, N, 2)``.

    maths §4 with both centers at the origin (see :func:`paths.nonlinear_controls`).
    """
    origin = np.zeros(2)
    return paths.bezier2(*paths.nonlinear_controls(u0, u1, centers=(origin, origin)), t)


def _about_joint(f: PathFunction) -> PathFunction:
    """``f`` for a body that turns about its joint: offsets from the joint, not from the body's center."""
    if f is paths.nonlinear:
        return pivoted
    return f  # linear paths do not depend on the origin; any other f sees the offsets


def misfit(k0: Array, k1: Array) -> float:
    """How far ``k0 → k1`` (each ``(N, 2)``) is from a rigid motion: RMS residual of the best
    rigid fit over the RMS distance from the center of mass (0 for a rigid motion)."""
    u0 = k0 - k0.mean(axis=0)
    u1 = k1 - k1.mean(axis=0)
    size = float(np.sqrt(0.5 * ((u0 * u0).sum() + (u1 * u1).sum()) / len(u0)))
    if size == 0.0:
        return 0.0
    residual = rotate(u0, float(best_fit_rotation(k0, k1))) - u1
    return float(np.sqrt((residual * residual).sum() / len(u0))) / size


def root_body(k0: Array, k1: Array, parts: Sequence[NDArray[np.intp]]) -> int:
    """Index in ``parts`` of the body that leads: the most vertices, then the least turn, then the first."""
    turns = [abs(float(best_fit_rotation(k0[b], k1[b]))) for b in parts]
    return min(range(len(parts)), key=lambda i: (-len(parts[i]), turns[i], i))


def jointed_paths(
    k0: Array,
    k1: Array,
    t: ArrayLike,
    joints: Sequence[tuple[int, int]],
    body_paths: PathFunction | Sequence[PathFunction] | None = None,
    rule: str = "chain",
) -> Array:
    """Per-body paths of a polygon cut by ``joints``: ``(T, N, 2)``.

    ``body_paths`` is one path function for every body, or one per body in the
    order of :func:`bodies`; the default is :func:`paths.nonlinear`. With no
    joints this is ``body_paths`` (or ``paths.nonlinear``) of the whole shape.

    ``rule = "chain"`` (the default): the body with most vertices (the thesis's
    larger mass that drags the others along) gets its paths about its own
    center of mass; every other body turns about the midpoint of the chord
    that joins it to the body before it, and that midpoint moves with that
    body. The chord itself turns with whichever of its two bodies is closer to
    rigid (:func:`misfit`), so the joint keeps its width. ``rule = "mean"``: every body turns about its
    own center of mass and a joint vertex follows the mean of its bodies' paths
    (maths §5.1's first choice; see the README for what was measured).
    """
    k0 = np.asarray(k0, dtype=np.float64)
    k1 = np.asarray(k1, dtype=np.float64)
    if k0.shape != k1.shape or k0.ndim != 2 or k0.shape[1] != 2:
        raise GeometryError(f"keys must both be (N, 2), found {k0.shape} and {k1.shape}")
    if rule not in RULES:
        raise GeometryError(f"unknown joint rule {rule!r}; expected chain or mean")
    t = paths.as_times(t)
    n = k0.shape[0]
    parts = bodies(n, joints)
    if body_paths is None:
        body_paths = paths.nonlinear
    functions = [body_paths] * len(parts) if callable(body_paths) else list(body_paths)
    if len(functions) != len(parts):
        raise GeometryError(
            f"{len(parts)} bodies need {len(parts)} path functions, found {len(functions)}"
        )
    if rule == "mean":
        return _mean(k0, k1, t, parts, functions)
    return _chain(k0, k1, t, joints, parts, functions)


def _mean(k0: Array, k1: Array, t: Array, parts: list[NDArray[np.intp]],
          functions: list[PathFunction]) -> Array:
    # A joint vertex's mean is taken as first path + mean deviation from it, so
    # that where all bodies agree (t = 0 and 1) the key is hit bit for bit.
    n = k0.shape[0]
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


def _chain(k0: Array, k1: Array, t: Array, joints: Sequence[tuple[int, int]],
           parts: list[NDArray[np.intp]], functions: list[PathFunction]) -> Array:
    n = k0.shape[0]
    out = np.empty((t.shape[0], n, 2))
    root = root_body(k0, k1, parts) if len(parts) > 1 else 0
    out[:, parts[root]] = functions[root](k0[parts[root]], k1[parts[root]], t)
    members = [set(b.tolist()) for b in parts]
    placed, queue = {root}, [root]
    while queue:  # breadth first over the tree of bodies, whose edges are the chords
        parent = queue.pop(0)
        for k, joint in enumerate(joints):
            a, b = _as_pair(k, joint)
            if not {a, b} <= members[parent]:
                continue
            child = next((i for i, m in enumerate(members) if i not in placed and {a, b} <= m), None)
            if child is None:  # the chord to this body's own parent
                continue
            # The chord turns with whichever of its two bodies keeps its shape better,
            # so a joint keeps its width when one side of it is rigid.
            carried = misfit(k0[parts[child]], k1[parts[child]]) < misfit(k0[parts[parent]], k1[parts[parent]])
            own = np.array([v for v in parts[child].tolist() if carried or v not in (a, b)], dtype=np.intp)
            j0, j1 = 0.5 * (k0[a] + k0[b]), 0.5 * (k1[a] + k1[b])
            hinge = 0.5 * (out[:, a] + out[:, b])  # (T, 2): the chord's midpoint, carried by the parent
            turn = _about_joint(functions[child])(k0[own] - j0, k1[own] - j1, t)
            # Written as deviations from the straight path so that t = 0 and 1 give the keys bit for bit.
            straight = paths.linear(k0[own], k1[own], t)
            drift = hinge - paths.linear(j0[None], j1[None], t)[:, 0]  # (T, 2)
            out[:, own] = straight + (turn - paths.linear(k0[own] - j0, k1[own] - j1, t)) + drift[:, None]
            placed.add(child)
            queue.append(child)
    return out
