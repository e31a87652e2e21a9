"""Steering a segment by eye (maths §5.13–5.14): the direction and count of its turn, arcs through
chosen points.

A segment's rigid frame turns by its best-fit rotation φ ∈ (−π, π]; a ``turn`` chooses another
total turn φ' = φ + δ, δ a whole number of turns. Where δ ≠ 0 the method runs from the first key to
the second turned back by φ' about its centre (what is left of the change), and its in-betweens turn
by ``t·φ'`` about the centre's straight path: the keys stay exact and a rigid turn turns by ``t·φ'``.
An arc moves a hinted vertex through a chosen point at t = 0.5; the vertices between hinted ones
take the correction interpolated by arc length, each drawn at ``P_i(t) + 4t(1 − t)·Δ_i``.
"""

from __future__ import annotations

import math
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ..geometry import best_fit_rotation, centroid, rotate

__all__ = ["total_turn", "extra_turn", "whole_turns_to", "spin", "unturned", "arc_corrections", "bend"]

Array = NDArray[np.float64]
TAU = 2.0 * math.pi


def total_turn(phi: float, turn: str | None, turns: int = 0) -> float:
    """The total turn φ' of a rigid frame whose best-fit rotation is ``phi`` (radians, (−π, π]) under
    ``turn`` (``"cw"``, ``"ccw"``, ``"shortest"`` or ``None``, the shortest) and ``turns`` extra whole
    turns, added in the chosen direction (the shortest's own; counter-clockwise from φ = 0)."""
    if turn == "cw":
        base = phi - TAU if phi > 0 else phi
        return base - TAU * turns
    if turn == "ccw":
        base = phi + TAU if phi < 0 else phi
        return base + TAU * turns
    return phi + (TAU * turns if phi >= 0 else -TAU * turns)


def extra_turn(k0: Array, k1: Array, turn: str | None, turns: int = 0) -> float:
    """δ = φ' − φ in radians for keys ``(N, 2)`` (a whole number of turns; 0 for the shortest)."""
    if (turn in (None, "shortest") and turns == 0) or len(k0) == 0:
        return 0.0
    phi = float(best_fit_rotation(np.asarray(k0), np.asarray(k1)))
    return total_turn(phi, turn, turns) - phi


def whole_turns_to(target: float, k0: Array, k1: Array) -> float:
    """The whole number of turns (radians) to add to the best-fit rotation of keys ``(N, 2)`` so that it is
    nearest ``target`` radians."""
    if len(k0) == 0:
        return 0.0
    phi = float(best_fit_rotation(np.asarray(k0), np.asarray(k1)))
    return TAU * round((target - phi) / TAU)


def spin(frames: Sequence[Array], k0: Array, k1: Array, t: Array, angle: float) -> list[Array]:
    """``frames`` (each ``(T, L_i, 2)``) turned by ``t·angle`` about the straight path from the vertex mean
    of ``k0`` to that of ``k1`` (all the moving contours' keys, ``(N, 2)``), at ``t (T,)``."""
    c0, c1 = centroid(np.asarray(k0)), centroid(np.asarray(k1))
    centre = ((1.0 - t)[:, None] * c0 + t[:, None] * c1)[:, None, :]  # (T, 1, 2)
    turn = (t * angle)[:, None]  # (T, 1)
    return [centre + rotate(f - centre, turn) for f in frames]


def unturned(points: Array, about: Array, angle: float) -> Array:
    """``points (N, 2)`` turned back by ``angle`` about ``about (2,)``: the key a method runs to when the
    rigid frame's whole turn is taken out (maths §5.13)."""
    return about + rotate(np.asarray(points) - about, -angle)


def arc_corrections(outline: Array, closed: bool, anchors: Sequence[tuple[int, Array | None]]) -> Array:
    """Per vertex of ``outline (L, 2)`` (a segment's first key, balanced), the arc correction Δ ``(L, 2)``:
    at each anchor ``(vertex, Δ)`` its own Δ (``None``: 0, a hinted vertex without an arc), between
    consecutive anchors along the contour Δ interpolated linearly by arc length; an open contour's ends
    take their nearest anchor's. No anchor: all 0."""
    count = len(outline)
    out = np.zeros((count, 2))
    found = sorted({int(v): (np.zeros(2) if d is None else np.asarray(d, dtype=np.float64)) for v, d in anchors
                    if 0 <= int(v) < count}.items())
    if not found:
        return out
    step = np.linalg.norm(np.diff(np.vstack([outline, outline[:1]]) if closed else outline, axis=0), axis=1)
    along = np.concatenate([[0.0], np.cumsum(step)])  # arc length at each vertex (closed: and back at 0)
    total = float(along[-1]) if closed else 0.0
    vertices = [v for v, _ in found]
    values = [d for _, d in found]
    if not closed:
        out[: vertices[0] + 1] = values[0]
        out[vertices[-1]:] = values[-1]
    runs = list(zip(found, found[1:]))
    if closed:
        runs.append((found[-1], (found[0][0] + count, found[0][1])))  # the run round past vertex 0
    for (a, da), (b, db) in runs:
        for v in range(a, b + 1):
            s = along[v % count] + (total if v >= count else 0.0)
            s_a, s_b = along[a], along[b % count] + (total if b >= count else 0.0)
            share = (s - s_a) / (s_b - s_a) if s_b > s_a else 0.0
            out[v % count] = da + share * (db - da)
    for v, d in found:  # each anchor its own, exactly
        out[v] = d
    return out


def bend(frames: Array, t: Array, correction: Array) -> Array:
    """``frames (T, L, 2)`` bent by ``4t(1 − t)·correction (L, 2)`` at ``t (T,)``: the keys unchanged."""
    weight = (4.0 * t * (1.0 - t))[:, None, None]
    bent = frames + weight * correction
    bent[t == 0.0] = frames[t == 0.0]
    bent[t == 1.0] = frames[t == 1.0]
    return bent
