"""Q-curves (maths §3, thesis ch. 4), motion classification and the ``auto`` method.

The Q-curve of a vertex follows ``(F·B, F×B)`` of its forward and backward edge
vectors while both are interpolated linearly; it is a quadratic Bézier curve
whose angle ``atan2(y, x)`` is the vertex angle at every t. Keys here are
already in correspondence: ``k0, k1`` of shape ``(N, 2)``.

Q values are products of two edge vectors, so they scale with length²: every
tolerance on them is a relative tolerance times a squared length of the shape.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ...errors import GeometryError
from . import joints as _joints
from . import paths
from ..contours import roles
from ..geometry import area, best_fit_rotation, cross, edge_lengths
from ..balance import spread_copies
from .injective import injective, injective_contours
from ..stray import STRAY_REACH, stray_shares, stroke_stray_shares
from ..tangles import contact_times, linear_tangles

__all__ = [
    "control_points", "evaluate", "angle_at", "passes_through_zero", "non_monotonic",
    "sweeps_over_180", "Motion", "vertex_kinds", "classify", "AutoChoice", "auto_choice",
    "auto_choice_contours", "auto", "drawn_choice", "straight", "STRAY_LIMIT", "QUALITY_T", "candidate_paths",
    "candidate_quality", "stray_reach", "stroke_stray",
]

Array = NDArray[np.float64]
QCurves = NDArray[np.float64]
"""Control points of N Q-curves: ``(N, 3, 2)``, ``Q0, Q1, Q2`` per vertex."""

Joints = Sequence[tuple[int, int]]

# Values this small relative to the curve's own size are rounding noise: a curve
# that stays on the x-axis, or a d(t) that is zero for a rigid turn, must not
# report roots that only the last bits of the arithmetic put there.
_NOISE = 1e-10


def _keys(k0: ArrayLike, k1: ArrayLike) -> tuple[Array, Array]:
    k0 = np.asarray(k0, dtype=np.float64)
    k1 = np.asarray(k1, dtype=np.float64)
    if k0.ndim != 2 or k0.shape[1] != 2 or k0.shape != k1.shape:
        raise GeometryError(
            f"keys must both be (N, 2) with the same N, found {k0.shape} and {k1.shape}"
        )
    return k0, k1


def control_points(k0: ArrayLike, k1: ArrayLike) -> QCurves:
    """``Q0, Q1, Q2`` of every vertex's Q-curve: ``(N, 3, 2)``.

    With ``B = V[i-1] - V[i]`` and ``F = V[i+1] - V[i]`` in each key:
    ``Q0 = (F0·B0, F0×B0)``, ``Q1 = ((F1·B0 + F0·B1)/2, (F1×B0 + F0×B1)/2)``,
    ``Q2 = (F1·B1, F1×B1)``.
    """
    k0, k1 = _keys(k0, k1)
    b0, f0 = np.roll(k0, 1, axis=0) - k0, np.roll(k0, -1, axis=0) - k0
    b1, f1 = np.roll(k1, 1, axis=0) - k1, np.roll(k1, -1, axis=0) - k1

    def q(f: Array, b: Array) -> Array:
        return np.stack([(f * b).sum(axis=-1), cross(f, b)], axis=-1)

    return np.stack([q(f0, b0), 0.5 * (q(f1, b0) + q(f0, b1)), q(f1, b1)], axis=1)


def evaluate(q: QCurves, t: ArrayLike) -> Array:
    """``Q(t)`` of every curve: ``(T, N, 2)``."""
    return paths.bezier2(q[:, 0], q[:, 1], q[:, 2], t)


def angle_at(q: QCurves, t: ArrayLike) -> Array:
    """Vertex angles ``atan2(Q.y, Q.x)`` in radians, (−π, π]: ``(T, N)``.

    Positive angles open counter-clockwise from the forward edge to the backward
    edge (the interior angle of a convex counter-clockwise polygon).
    """
    point = evaluate(q, t)
    return np.arctan2(point[..., 1], point[..., 0])


def _roots(c0: Array, c1: Array, c2: Array, simple: bool) -> tuple[Array, Array]:
    """Real roots in (0, 1) of ``c0(1-t)² + 2c1·t(1-t) + c2·t²``, per row.

    Returns ``roots (N, 2)`` and ``valid (N, 2)``. A quadratic that is zero within
    rounding has no roots; ``simple`` keeps only roots where the sign changes.
    """
    a = c0 - 2.0 * c1 + c2
    b = 2.0 * (c1 - c0)
    c = c0
    disc = b * b - 4.0 * a * c
    real = disc > 0 if simple else disc >= 0
    # The cancellation-free form: q = -(b + sign(b)·√disc)/2, roots q/a and c/q.
    # It also gives -c/b when a = 0, and an exact 0 when c = 0.
    half = -0.5 * (b + np.copysign(np.sqrt(np.maximum(disc, 0.0)), b))
    r1 = np.divide(half, a, out=np.full_like(a, -1.0), where=a != 0)
    r2 = np.divide(c, half, out=np.where(a != 0, 0.0, -1.0), where=half != 0)
    roots = np.stack([r1, r2], axis=-1)
    valid = (roots > 0) & (roots < 1) & real[:, None]
    return roots, valid


def _size(q: QCurves) -> Array:
    """Largest control-point norm of each curve: ``(N,)``."""
    return np.linalg.norm(q, axis=-1).max(axis=-1)


def passes_through_zero(q: QCurves) -> NDArray[np.bool_]:
    """Whether ``Q(t)`` meets the positive x-axis for some 0 < t < 1: ``(N,)`` bool.

    That is the moment the two edges fold onto each other (S&G penalise it).
    A curve that stays on the axis throughout (edges collinear at every t) does
    not cross it.
    """
    y = q[..., 1]
    roots, valid = _roots(y[:, 0], y[:, 1], y[:, 2], simple=False)
    flat = np.abs(y).max(axis=-1) <= _NOISE * _size(q)
    x0, x1, x2 = q[:, 0, 0][:, None], q[:, 1, 0][:, None], q[:, 2, 0][:, None]
    s = 1.0 - roots
    x = s * s * x0 + 2.0 * s * roots * x1 + roots * roots * x2
    return (valid & (x > 0)).any(axis=-1) & ~flat


def _d(q: QCurves) -> tuple[Array, Array, Array]:
    """Bernstein coefficients of ``d(t) = Q(t)×Q'(t)/2``, the sign of the angle's change."""
    q0, q1, q2 = q[:, 0], q[:, 1], q[:, 2]
    return cross(q0, q1), 0.5 * cross(q0, q2), cross(q1, q2)


def _constant_angle(q: QCurves, d0: Array, d1: Array, d2: Array) -> NDArray[np.bool_]:
    """Curves whose d(t) is zero within rounding: the Q-curve lies on a line through
    the origin (as for a rigid turn), so the angle does not change."""
    largest = np.maximum(np.abs(d0), np.maximum(np.abs(d1), np.abs(d2)))
    return largest <= _NOISE * _size(q) ** 2


def non_monotonic(q: QCurves) -> NDArray[np.bool_]:
    """Whether the vertex angle turns back: ``d(t)`` changes sign in (0, 1): ``(N,)`` bool.

    ``d0 = Q0×Q1``, ``d1 = (Q0×Q2)/2``, ``d2 = Q1×Q2`` (maths §3). A d(t) that only
    touches zero pauses the angle without reversing it, and a rigid turn (d ≡ 0)
    keeps the angle constant: neither counts.
    """
    d0, d1, d2 = _d(q)
    _, valid = _roots(d0, d1, d2, simple=True)
    return valid.any(axis=-1) & ~_constant_angle(q, d0, d1, d2)


def sweeps_over_180(q: QCurves) -> NDArray[np.bool_]:
    """Whether the vertex angle sweeps over 180°: ``d1² - d0·d2 < 0`` and the origin
    lies strictly inside the triangle ``Q0 Q1 Q2``: ``(N,)`` bool."""
    d0, d1, d2 = _d(q)
    q0, q1, q2 = q[:, 0], q[:, 1], q[:, 2]
    # The origin O is inside when the three edge crosses (Qj - Qi)×(O - Qi) agree in sign.
    s = np.stack([cross(q1 - q0, -q0), cross(q2 - q1, -q1), cross(q0 - q2, -q2)], axis=-1)
    inside = (s > 0).all(axis=-1) | (s < 0).all(axis=-1)
    return (d1 * d1 - d0 * d2 < 0) & inside & ~_constant_angle(q, d0, d1, d2)


@dataclass(frozen=True, slots=True)
class Motion:
    """How a shape moves between two keys, read off its Q-curves."""

    kind: str  # "translation" | "rotation" | "nonrigid"
    rotation_deg: float  # signed best-fit rotation in degrees; 0.0 for a translation
    why: str  # one line in words


def vertex_kinds(q: QCurves, tolerance: float | ArrayLike) -> list[str]:
    """Per vertex ``"translation"``, ``"rotation"`` or ``"nonrigid"``.

    Translation: ``Q0 = Q1 = Q2``. Rotation by φ: ``Q0 = Q2`` and ``Q1 = cos φ·Q0``,
    i.e. Q1 on the segment from ``Q0`` to ``-Q0`` (Q1 beyond ``Q0`` would mean one
    edge grew while the other shrank). Equalities hold within ``tolerance``, in
    Q units (length²); a scalar or one value per vertex.
    """
    q = np.asarray(q, dtype=np.float64)
    tol = np.broadcast_to(np.asarray(tolerance, dtype=np.float64), q.shape[:1])
    q0, q1, q2 = q[:, 0], q[:, 1], q[:, 2]
    qm = 0.5 * (q0 + q2)
    norm2 = (qm * qm).sum(axis=-1)
    cos_phi = np.clip(
        np.divide((q1 * qm).sum(axis=-1), norm2, out=np.ones_like(norm2), where=norm2 > 0),
        -1.0,
        1.0,
    )
    gap02 = np.linalg.norm(q2 - q0, axis=-1)
    still = (
        (gap02 <= tol)
        & (np.linalg.norm(q1 - q0, axis=-1) <= tol)
        & (np.linalg.norm(q2 - q1, axis=-1) <= tol)
    )
    turning = (gap02 <= tol) & (np.linalg.norm(q1 - cos_phi[:, None] * qm, axis=-1) <= tol)
    return [
        "translation" if s else "rotation" if r else "nonrigid"
        for s, r in zip(still.tolist(), turning.tolist())
    ]


def _length_scale2(k0: Array, k1: Array) -> float:
    """Mean squared edge length over both keys: the shape's size in Q units."""
    lengths = np.concatenate([edge_lengths(k0), edge_lengths(k1)])
    return float((lengths * lengths).mean()) if lengths.size else 0.0


def _nonrigid_why(k0: Array, k1: Array, q: QCurves) -> str:
    l0, l1 = edge_lengths(k0), edge_lengths(k1)
    grown = (l0 > 0) & (l1 > 0)
    parts = []
    if np.any(grown):
        change = np.abs(l1[grown] / l0[grown] - 1.0).max()
        if round(100 * change) > 0:
            parts.append(f"edge lengths change by up to {100 * change:.0f}%")
    if np.any((l0 > 0) != (l1 > 0)):
        parts.append("an edge collapses or opens from zero length")
    turn = np.diff(angle_at(q, [0.0, 1.0]), axis=0)[0]
    turn = np.abs((turn + np.pi) % (2 * np.pi) - np.pi)
    if turn.size and round(np.degrees(turn.max()), 1) > 0:
        parts.append(f"vertex angles change by up to {np.degrees(turn.max()):.1f} degrees")
    return "non-rigid change" + (f" ({', '.join(parts)})" if parts else "")


def classify(k0: ArrayLike, k1: ArrayLike, rel_tol: float = 1e-3) -> Motion:
    """Classify the motion from ``k0`` to ``k1`` (each ``(N, 2)``) from its Q-curves.

    The tolerance on Q values is ``rel_tol·L²`` with ``L²`` the mean squared edge
    length over both keys: Q values scale with length², so the answer does not
    depend on the scene's units. Since ``|Q1 - Q0| = (1 - cos φ)·|Q0|``, rotations
    below about ``√(2·rel_tol)`` rad (2.6° at the default) read as translation;
    linear paths shorten such a shape by roughly ``rel_tol/4`` at most.
    The neighbourhood of a vertex only sees edge vectors, so a translation added
    to a rotation does not change the answer.
    """
    k0, k1 = _keys(k0, k1)
    scale2 = _length_scale2(k0, k1)
    if scale2 == 0.0:
        return Motion("translation", 0.0, "pure translation")
    q = control_points(k0, k1)
    kinds = vertex_kinds(q, rel_tol * scale2)
    if "nonrigid" in kinds:
        deg = float(np.degrees(best_fit_rotation(k0, k1)))
        return Motion("nonrigid", deg, _nonrigid_why(k0, k1, q))
    if "rotation" in kinds:
        deg = float(np.degrees(best_fit_rotation(k0, k1)))
        return Motion("rotation", deg, f"rigid rotation of {deg:.1f} degrees")
    return Motion("translation", 0.0, "pure translation")


@dataclass(frozen=True, slots=True)
class AutoChoice:
    """What ``auto`` does with a shape and why."""

    method: str  # "nonlinear" | "linear" | "injective", or "jointed" when joints cut the shape into bodies
    why: str  # one line in words
    bodies: tuple[str, ...]  # "nonlinear" | "linear" per local body (joints.bodies order)
    holds: bool = False  # injective paths holding the contours without a partner in their mesh

    @property
    def balance(self) -> str | None:
        """How the copies of a vertex are placed on the paths drawn: ``"spread"`` along its edges for
        auto's straight and injective paths, None (the shape's own rule) for the others."""
        return "spread" if self.method in ("linear", "injective") else None


def _method(motion: Motion) -> str:
    # Thesis §2.3: only a rigid turn suffers linear foreshortening; a translation
    # is exact under linear paths and a non-rigid change has no rigid path to keep.
    return "nonlinear" if motion.kind == "rotation" else "linear"


def _short(motion: Motion) -> str:
    if motion.kind == "rotation":
        return f"rotation of {motion.rotation_deg:.1f} degrees"
    return "pure translation" if motion.kind == "translation" else "non-rigid change"


def _untangled(choice: AutoChoice, k0s: Sequence[Array], k1s: Sequence[Array],
               closed: Sequence[bool] | None = None) -> AutoChoice:
    """``choice``, or ``injective`` where it is ``linear`` and the straight inbetweens of contours
    ``k0s``, ``k1s`` (closed where ``closed`` says; default: those of three vertices or more)
    tangle while the keys do not (maths §5.9)."""
    if choice.method != "linear" or not k0s:
        return choice
    closed = [len(k) >= 3 for k in k0s] if closed is None else [bool(c) and len(k) >= 3 for c, k in zip(closed, k0s)]
    spread_keys = [spread_copies(a, b) if shut else (a, b) for a, b, shut in zip(k0s, k1s, closed)]
    crossed = linear_tangles([a for a, _ in spread_keys], [b for _, b in spread_keys], closed)
    if not crossed or crossed[0] == 0.0 or crossed[-1] == 1.0:
        return choice  # straight paths never tangle, or a key does already: nothing to keep clean
    return AutoChoice("injective", f"{choice.why}; straight paths would cross at t = {crossed[0]:g}",
                      tuple("injective" for _ in choice.bodies))


STRAY_LIMIT = 0.02
"""The stray (maths §5.16) beyond the straight paths' that an in-between may have for ``auto`` to take it."""
BALLOON = 0.25
"""How far the area a shape's closed contours fill (holes taken away) may leave the straight blend of the keys'
areas, as a share of the larger, for ``auto`` to take its in-betweens (maths §5.16): straight paths that close a
hole early, or swell outlines over it, fill a drawing of lines into a blob. Joins are weighed on it too."""
QUALITY_T = np.arange(1, 20) / 20.0
"""The t at which ``auto`` measures its candidates: .05, .10, … .95."""
_CACHED = 512  # shapes whose measured choice is kept (frames are evaluated block by block)
_measured_cache: OrderedDict[bytes, AutoChoice] = OrderedDict()


def candidate_paths(method: str, k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool],
                     t: Array) -> list[Array]:
    """One ``(T, L_i, 2)`` per contour: the shape's nonlinear paths as one point set, auto's straight
    paths contour by contour (open strokes straight), or the injective paths of all in one mesh."""
    if method == "injective":
        return injective_contours(k0s, k1s, closed, t, paced=False)  # the path's states, however it is timed
    if method == "nonlinear":
        cuts = np.cumsum([len(k) for k in k0s])[:-1]
        return np.split(paths.nonlinear(np.concatenate(k0s), np.concatenate(k1s), t), cuts, axis=1)
    return [straight(a, b, t) if shut else paths.linear(a, b, t) for a, b, shut in zip(k0s, k1s, closed)]


def candidate_quality(frames: Sequence[Array], k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool],
                      view: float = 0.0) -> tuple[int, float]:
    """How many of :data:`QUALITY_T` tangle (crossings over the whole shape, strokes' included) and the largest
    stray (of the filled area or of the strokes' length, :func:`_stray`), the reach 12 % of the view's larger
    side ``view`` (:func:`stray_reach`)."""
    return _tangled(frames, k0s, k1s, closed), _stray(frames, k0s, k1s, closed, view)


def balloon(frames: Sequence[Array], k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool],
            grown: bool = False) -> float:
    """How far the area the closed contours of ``frames`` (``(T, L_i, 2)`` at :data:`QUALITY_T`) fill leaves the
    straight blend of the keys' (``k0s``, ``k1s``, ``(L_i, 2)``), at most, over the larger key's: each contour
    counted whatever way it winds, holes (by their nesting in the keys) taken away. 0 where the keys nest
    differently (no one area to follow) or fill nothing. With ``grown``, a contour that is a point in one key
    (growing from it or shrinking to it) is a hole or not by its nesting in the other."""
    shut = [k for k, c in enumerate(closed) if c and len(k0s[k]) >= 3]
    kinds = [roles([key[k] for k in shut], [True] * len(shut)) for key in (k0s, k1s)]
    if grown:  # each by the key where it is more than a point
        kinds[0] = [b if area(k0s[k]) == 0.0 else a for k, a, b in zip(shut, *kinds)]
        kinds[1] = [a if area(k1s[k]) == 0.0 else b for k, a, b in zip(shut, *kinds)]
    if not shut or kinds[0] != kinds[1]:
        return 0.0
    signs = np.array([-1.0 if kind == "hole" else 1.0 for kind in kinds[0]])
    first = float(signs @ np.array([area(k0s[k]) for k in shut]))
    last = float(signs @ np.array([area(k1s[k]) for k in shut]))
    filled = sum((s * area(frames[k]) for s, k in zip(signs, shut)), np.zeros(len(QUALITY_T)))
    return off_blend(filled, QUALITY_T, first, last)


def off_blend(filled: Array, t: Array, first: float, last: float) -> float:
    """How far the areas ``filled (T,)`` at ``t (T,)`` leave the straight blend of ``first`` and ``last``, at most,
    over the larger of those (0 where both are 0): what :data:`BALLOON` bounds."""
    larger = max(abs(first), abs(last))
    if not larger > 0:
        return 0.0
    return float(np.abs(filled - ((1.0 - t) * first + t * last)).max() / larger)


def _tangled(frames: Sequence[Array], k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool]) -> int:
    """How many of :data:`QUALITY_T` tangle (crossings over the whole shape, strokes' included; a contour
    crossing itself in a key does so near it under every method, and is not counted)."""
    tangled, stroked = contact_times(frames, closed, QUALITY_T, k0s, k1s, with_key_crossings=False)
    return len(set(tangled) | set(stroked))


def _stray(frames: Sequence[Array], k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool],
           view: float = 0.0) -> float:
    """The largest stray of ``frames`` at :data:`QUALITY_T`, within :func:`stray_reach` of ``view``: of the area the
    closed contours fill, or of the open strokes' length (:func:`stroke_stray`), whichever strays more (a stroke
    encloses no area, yet a viewer sees it swing out)."""
    return max(_area_stray(frames, k0s, k1s, closed, view), stroke_stray(frames, k0s, k1s, closed, view))


def _area_stray(frames: Sequence[Array], k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool],
                view: float = 0.0) -> float:
    """The largest stray of the area the closed contours of ``frames`` fill at :data:`QUALITY_T`."""
    filled = [len(k) >= 3 and shut for k, shut in zip(k0s, closed)]
    reach = stray_reach(k0s, k1s, view)
    if not any(filled) or not reach > 0:
        return 0.0
    areas = [([f[k] for f, keep in zip(frames, filled) if keep], "evenodd") for k in range(len(QUALITY_T))]
    keys = [([k for k, keep in zip(key, filled) if keep], "evenodd") for key in (k0s, k1s)]
    return float(stray_shares(areas, keys[0], keys[1], reach).max(initial=0.0))


def stroke_stray(frames: Sequence[Array], k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool],
                 view: float = 0.0) -> float:
    """The largest share of the open strokes' length in ``frames`` (``(T, L_i, 2)`` at :data:`QUALITY_T`) lying
    farther than the reach (:func:`stray_reach` of ``view``) from both keys' areas and contours (0 without open
    strokes)."""
    filled = [len(k) >= 3 and shut for k, shut in zip(k0s, closed)]
    reach = stray_reach(k0s, k1s, view)
    if all(filled) or not reach > 0:
        return 0.0
    keys = [([k for k, keep in zip(key, filled) if keep], "evenodd") for key in (k0s, k1s)]
    strokes = [[f[k] for f, keep in zip(frames, filled) if not keep] for k in range(len(QUALITY_T))]
    lines = [(k, shut) for key in (k0s, k1s) for k, shut in zip(key, closed)]
    return float(stroke_stray_shares(strokes, keys[0], keys[1], lines, reach).max(initial=0.0))


def stray_reach(k0s: Sequence[Array], k1s: Sequence[Array], view: float = 0.0) -> float:
    """How far an in-between may go from both keys before it strays (maths §5.16): 12 % of the larger side of
    the view, ``view`` (the drawing's, where the caller knows it), or of both keys together where they are
    larger (0: the keys alone)."""
    points = np.concatenate([*k0s, *k1s])
    return STRAY_REACH * max(float(view), float(np.ptp(points, axis=0).max(initial=0.0)))


def _measured(first: AutoChoice, k0s: Sequence[Array], k1s: Sequence[Array], closed: Sequence[bool],
              view: float = 0.0, weigh_area: bool = True) -> AutoChoice:
    """``auto``'s choice by measured quality (maths §5.16), among ``first`` where it is ``nonlinear`` (the
    Q-curves' rigid turn), straight paths with spread copies, and injective paths: the first whose
    in-betweens never tangle, stray at most :data:`STRAY_LIMIT` more than the straight paths do (they
    sweep what the motion itself sweeps; a rigid turn's arc is the turn itself, so ``nonlinear`` needs no
    tangle only) and fill an area within :data:`BALLOON` of the straight blend of the keys' (:func:`balloon`:
    straight paths can close a hole into a blob); else, of those straying at most as much more (a way round
    that leaves the keys looks worse than straight paths that cross), the one tangling at the fewest t, then
    ballooning least past :data:`BALLOON` (straight paths, in the list's order, on a tie): by these measures,
    over the contours that move, never more tangled than straight paths, nor straying more than
    :data:`STRAY_LIMIT` past them. ``first``'s reason stands where it passes; elsewhere the measures are the
    reason. Stray is measured within 12 % of the drawing's view, ``view`` its larger side
    (:func:`stray_reach`). Without ``weigh_area`` (a shape whose contours without a partner come and go beside these,
    so that their area is not the shape's) the area is not measured."""
    k0s = [np.asarray(k, dtype=np.float64) for k in k0s]
    k1s = [np.asarray(k, dtype=np.float64) for k in k1s]
    closed = [bool(c) and len(k) >= 3 for c, k in zip(closed, k0s)]
    if not k0s or not all(np.all(np.isfinite(k)) for k in [*k0s, *k1s]):
        return first
    key = b"|".join(k.tobytes() for k in [*k0s, *k1s]) + repr((first, closed, float(view), weigh_area)).encode()
    found = _measured_cache.get(key)
    if found is not None:
        _measured_cache.move_to_end(key)
        return found
    straight_choice = first if first.method == "linear" else AutoChoice("linear", first.why, ("linear",))
    candidates = ([first] if first.method == "nonlinear" else []) + [straight_choice]
    candidates.append(AutoChoice("injective", first.why, ("injective",)))

    def quality(method: str) -> tuple[int, float, float]:
        frames = candidate_paths(method, k0s, k1s, closed, QUALITY_T)
        return (*candidate_quality(frames, k0s, k1s, closed, view),
                balloon(frames, k0s, k1s, closed) if weigh_area and method != "nonlinear" else 0.0)

    # the first candidate passes on no tangle (and, straight, no balloon) alone (straight paths' stray is the
    # limit itself, a rigid turn's arc no stray): where it passes, no stray is measured
    measured: dict[str, tuple[int, float, float]] = {}
    if first.method in ("linear", "nonlinear"):
        frames = candidate_paths(first.method, k0s, k1s, closed, QUALITY_T)
        crossed = _tangled(frames, k0s, k1s, closed)
        swell = balloon(frames, k0s, k1s, closed) if weigh_area and first.method == "linear" else 0.0
        if crossed == 0 and swell <= BALLOON:
            _remember(key, first)
            return first
        measured[first.method] = (crossed, _stray(frames, k0s, k1s, closed, view), swell)
    for c in candidates:
        if c.method not in measured and c.method != "injective":
            measured[c.method] = quality(c.method)
    # straight paths sweep what the motion itself sweeps: a method strays where it goes past that
    limit = STRAY_LIMIT + measured["linear"][1]
    scores: list[tuple[int, float, float, int, AutoChoice]] = []
    chosen = None
    for rank, candidate in enumerate(candidates):
        if candidate.method not in measured:
            measured[candidate.method] = quality(candidate.method)
        crossed, stray, swell = measured[candidate.method]
        scores.append((crossed, stray, swell, rank, candidate))
        # a rigid turn's arc is the motion itself, not a stray: it keeps the shape at every t
        if crossed == 0 and (stray <= limit or candidate.method == "nonlinear") and swell <= BALLOON:
            chosen = candidate if rank == 0 else replace(candidate, why=f"{first.why}; {_measures(scores)}")
            break
    if chosen is None:  # none passes: the least tangled of those that stray no more than the limit
        kept = [s for s in scores if s[1] <= limit or s[4].method == "nonlinear"]
        best = min(kept, key=lambda s: (s[0], max(s[2], BALLOON), s[3]))[4]
        chosen = replace(best, why=f"{first.why}; {_measures(scores)}; {best.method} the least tangled of those that stray no further")
    _remember(key, chosen)
    return chosen


def _remember(key: bytes, chosen: AutoChoice) -> None:
    _measured_cache[key] = chosen
    while len(_measured_cache) > _CACHED:
        _measured_cache.popitem(last=False)


def _measures(scores: Sequence[tuple[int, float, float, int, AutoChoice]]) -> str:
    return "; ".join(f"{c.method}: tangled at {n} of {len(QUALITY_T)} t, stray {s:.3f}"
                     + (f", area {b:.3f} off the keys' blend" if b > BALLOON else "") for n, s, b, _, c in scores)


def auto_choice(k0: ArrayLike, k1: ArrayLike, joints: Joints = (), closed: bool = True, view: float = 0.0,
                weigh_area: bool = True) -> AutoChoice:
    """Choose by measured quality (maths §5.16, :func:`_measured`): nonlinear paths where the Q-curves show
    a rigid rotation, straight paths, injective paths — the first that neither tangles nor strays.

    With ``joints`` the choice is made per local body (each with its own size
    for the tolerance); the method is then ``"jointed"`` if any body turns, and
    ``"linear"`` (or ``"injective"``) if none does (averaged linear paths are the linear paths).
    ``closed=False`` reads the keys as an open stroke when it looks for crossings; ``weigh_area=False`` leaves
    the area out of the measures (:func:`_measured`).
    Raises :class:`joints.JointError` for bad joints.
    """
    k0, k1 = _keys(k0, k1)
    if len(joints) == 0:
        motion = classify(k0, k1)
        return _measured(AutoChoice(_method(motion), motion.why, (_method(motion),)), [k0], [k1], [closed], view,
                         weigh_area)
    motions = [classify(k0[b], k1[b]) for b in _joints.bodies(k0.shape[0], joints)]
    methods = tuple(_method(m) for m in motions)
    method = "jointed" if "nonlinear" in methods else "linear"
    return _untangled(AutoChoice(method, "bodies: " + " / ".join(_short(m) for m in motions), methods), [k0], [k1],
                      [closed])


def auto_choice_contours(k0s: Sequence[ArrayLike], k1s: Sequence[ArrayLike],
                         strokes0: Sequence[ArrayLike] = (), strokes1: Sequence[ArrayLike] = (), view: float = 0.0,
                         weigh_area: bool = True) -> AutoChoice:
    """``auto``'s choice for a shape of several closed contours, each ``(N_i, 2)`` in both keys (and
    the open strokes ``strokes0``, ``strokes1`` that move with them), by measured quality: nonlinear
    first where every closed contour turns rigidly by the same angle (within 1°), then straight paths,
    then injective (:func:`_measured`; ``weigh_area`` as there)."""
    motions = [classify(a, b) for a, b in zip(k0s, k1s)]
    every0 = [np.asarray(k, dtype=np.float64) for k in [*k0s, *strokes0]]
    every1 = [np.asarray(k, dtype=np.float64) for k in [*k1s, *strokes1]]
    closed = [True] * len(k0s) + [False] * len(strokes0)
    turns = [m.rotation_deg for m in motions if m.kind == "rotation"]
    if not motions:
        first = AutoChoice("linear", "no closed contour moves", ("linear",))
    elif len(turns) == len(motions) and max(turns) - min(turns) <= 1.0:
        first = AutoChoice("nonlinear", f"rigid rotation of {turns[0]:.1f} degrees ({len(motions)} contours)",
                           ("nonlinear",))
    elif all(m.kind == "translation" for m in motions):
        first = AutoChoice("linear", f"pure translation ({len(motions)} contours)", ("linear",))
    else:
        first = AutoChoice("linear", "contours change or move differently: " + " / ".join(_short(m) for m in motions),
                           ("linear",))
    return _measured(first, every0, every1, closed, view, weigh_area)


def straight(k0: Array, k1: Array, t: ArrayLike) -> Array:
    """``auto``'s straight paths: linear paths between the keys with copies of a vertex spread along
    its edges (maths §5.6), so a vertex that many of the other key's meet opens out along its
    edges instead of leaving a sawtooth: ``(T, N, 2)``."""
    if len(k0) < 3:
        return paths.linear(k0, k1, t)
    return paths.linear(*spread_copies(k0, k1), t)


_PATHS = {"nonlinear": paths.nonlinear, "linear": paths.linear, "injective": injective}


def auto(k0: ArrayLike, k1: ArrayLike, t: ArrayLike, joints: Joints = ()) -> Array:
    """The ``auto`` method's inbetweens: ``(T, N, 2)``.

    Per body, the nonlinear paths where its Q-curves show a rotation and linear
    paths otherwise; joint vertices follow the mean of their bodies' paths; the
    whole shape's injective paths where linear ones would cross (maths §5.9).
    """
    k0, k1 = _keys(k0, k1)
    return drawn_choice(auto_choice(k0, k1, joints), k0, k1, t, joints)


def drawn_choice(choice: AutoChoice, k0: ArrayLike, k1: ArrayLike, t: ArrayLike, joints: Joints = ()) -> Array:
    """The inbetweens ``(T, N, 2)`` of ``auto``'s ``choice`` for one outline: its injective paths, straight paths
    with spread copies, or each body's paths (joint vertices on the mean of their bodies')."""
    k0, k1 = _keys(k0, k1)
    if choice.method == "injective":
        return injective(k0, k1, t)
    if len(joints) == 0 and choice.method == "linear":
        return straight(k0, k1, t)
    functions = [_PATHS[m] for m in choice.bodies]
    if len(joints) == 0:
        return functions[0](k0, k1, t)
    return _joints.jointed_paths(k0, k1, t, joints, body_paths=functions)
