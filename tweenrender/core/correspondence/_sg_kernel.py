"""Compiled kernels of the Sederberg–Greenwood cost (maths §2.1, numba): each step's stretching and each
node's bending on the grid of ``_dtw_grid``, the dynamic program over it, the every-start reference
search and a path's energy. The API is in ``correspond.py``; ``_sg_search`` searches the starts by
branch and bound; ``_cyclic_dtw`` holds the distance cost's kernels and gives these with them.
"""

from __future__ import annotations

import math

import numpy as np

from ._dtw_grid import STEP_A, STEP_AB, STEP_B, copy_nodes
from ..jit import cached_jit as _jit

__all__ = ["stretch_work", "angle_change", "bend_work", "sg_tables", "sg_forward", "sg_trace", "sg_every_start_search",
           "sg_path_energy"]


@_jit
def stretch_work(l0: float, l1: float, ks: float, cs: float, es: float) -> float:
    """Stretching work of an edge of length ``l0`` becoming ``l1`` (maths §2.1); 0 when equal."""
    if l0 == l1:
        return 0.0
    shorter, longer = min(l0, l1), max(l0, l1)
    return ks * abs(l1 - l0) ** es / ((1.0 - cs) * shorter + cs * longer)


@_jit
def _roots_inside(c0: float, c1: float, c2: float) -> tuple[float, float, int]:
    """The roots in (0, 1) of ``c0(1-t)² + 2c1 t(1-t) + c2 t²``: ``(first, second, count)``, unused ones 2.0.

    Scalars, not an array: this runs nine times a node, where allocating would cost more than the sums.
    """
    qa = c0 - 2.0 * c1 + c2
    qb = 2.0 * (c1 - c0)
    qc = c0
    count = 0
    if qa == 0.0:
        if qb != 0.0:
            t = -qc / qb
            if 0.0 < t < 1.0:
                return t, 2.0, 1
        return 2.0, 2.0, 0
    disc = qb * qb - 4.0 * qa * qc
    if disc < 0.0:
        return 2.0, 2.0, 0
    # The cancellation-free pair of quadratic roots.
    q = -0.5 * (qb + math.copysign(math.sqrt(disc), qb))
    if q == 0.0:
        return 2.0, 2.0, 0  # a double root at t = 0
    first, second = 2.0, 2.0
    t = q / qa
    if 0.0 < t < 1.0:
        first = t
        count += 1
    t = qc / q
    if 0.0 < t < 1.0:
        if count == 0:
            first = t
        else:
            second = t
        count += 1
    return first, second, count


@_jit
def _order(x: float, y: float) -> tuple[float, float]:
    return (x, y) if x <= y else (y, x)


@_jit
def _bezier(p0: float, p1: float, p2: float, t: float) -> float:
    s = 1.0 - t
    return p0 * s * s + 2.0 * p1 * s * t + p2 * t * t


@_jit
def angle_change(q0x: float, q0y: float, q1x: float, q1y: float,
                 q2x: float, q2y: float) -> tuple[float, float, bool]:
    """How the angle of a Q-curve changes over t in [0, 1]: ``(Δθ, Δθ*, through_zero)``.

    θ(t) is the continuous angle of ``Q(t)``; ``Δθ = |θ(1) - θ(0)|`` (so the long
    way round when the curve sweeps past 180°); ``Δθ*`` is how far θ(t) leaves
    the range between θ(0) and θ(1), above plus below; ``through_zero`` is whether
    ``Q(t)`` meets the positive x-axis for some 0 < t < 1 (the edges fold).
    Exact: θ's extremes are at roots of ``d(t)`` (maths §3), and between the roots
    of ``x(t)``, ``y(t)`` and ``d(t)`` the curve stays in one quadrant, where the
    angle between two of its points is their plain atan2 difference.
    """
    s0, s1, _ = _roots_inside(q0x, q1x, q2x)
    s2, s3, _ = _roots_inside(q0y, q1y, q2y)
    y_first, y_second = s2, s3  # y's roots, kept before the sorting below mixes them with the others
    d0 = q0x * q1y - q0y * q1x
    d1 = 0.5 * (q0x * q2y - q0y * q2x)
    d2 = q1x * q2y - q1y * q2x
    s4, s5, _ = _roots_inside(d0, d1, d2)
    # The six candidate splits in increasing order (2.0: none), by a sorting network of 12 exchanges.
    s0, s5 = _order(s0, s5)
    s1, s3 = _order(s1, s3)
    s2, s4 = _order(s2, s4)
    s1, s2 = _order(s1, s2)
    s3, s4 = _order(s3, s4)
    s0, s3 = _order(s0, s3)
    s2, s5 = _order(s2, s5)
    s0, s1 = _order(s0, s1)
    s2, s3 = _order(s2, s3)
    s4, s5 = _order(s4, s5)
    s1, s2 = _order(s1, s2)
    s3, s4 = _order(s3, s4)
    ts = (s0, s1, s2, s3, s4, s5, 1.0)

    theta, low, high = 0.0, 0.0, 0.0
    px, py = q0x, q0y
    for k in range(7):
        t = ts[k]
        if t > 1.0:
            t = 1.0
        x = _bezier(q0x, q1x, q2x, t)
        y = _bezier(q0y, q1y, q2y, t)
        theta += math.atan2(px * y - py * x, px * x + py * y)
        low, high = min(low, theta), max(high, theta)
        px, py = x, y
        if t == 1.0:
            break
    sweep = abs(theta)
    overshoot = (high - max(0.0, theta)) + (min(0.0, theta) - low)

    through_zero = False
    if q0y == 0.0 and q1y == 0.0 and q2y == 0.0:
        # On the x-axis throughout: folded wherever x > 0 (x's extreme included).
        through_zero = q0x > 0.0 or q2x > 0.0
        curvature = q0x - 2.0 * q1x + q2x
        if curvature != 0.0:
            t = (q0x - q1x) / curvature
            through_zero = through_zero or (0.0 < t < 1.0 and _bezier(q0x, q1x, q2x, t) > 0.0)
    else:
        for root in (y_first, y_second):
            if root < 1.0 and _bezier(q0x, q1x, q2x, root) > 0.0:
                through_zero = True
    return sweep, overshoot, through_zero


@_jit
def bend_work(b0x: float, b0y: float, f0x: float, f0y: float,
              b1x: float, b1y: float, f1x: float, f1y: float,
              kb: float, eb: float, mb: float, pb: float) -> float:
    """Bending work of a vertex with backward/forward edges ``B0, F0`` (key 0) and ``B1, F1`` (key 1).

    ``kb·(Δθ + mb·Δθ*)^eb``, plus ``pb`` if the angle passes through zero, over
    the Q-curve of maths §3. A zero edge (a duplicated vertex) makes that key's
    end of the Q-curve vanish: the vertex then counts as straight there, the end
    being replaced by ``(-r, 0)`` with ``r`` the other end's length (or ``|Q1|``
    when both ends vanish). No bending at all when ``Q0 = Q1 = Q2 = 0``.
    """
    q0x = f0x * b0x + f0y * b0y
    q0y = f0x * b0y - f0y * b0x
    q2x = f1x * b1x + f1y * b1y
    q2y = f1x * b1y - f1y * b1x
    q1x = 0.5 * ((f1x * b0x + f1y * b0y) + (f0x * b1x + f0y * b1y))
    q1y = 0.5 * ((f1x * b0y - f1y * b0x) + (f0x * b1y - f0y * b1x))
    r0 = math.hypot(q0x, q0y)
    r2 = math.hypot(q2x, q2y)
    if r0 == 0.0 and r2 == 0.0:
        r = math.hypot(q1x, q1y)
        if r == 0.0:
            return 0.0
        q0x, q0y, q2x, q2y = -r, 0.0, -r, 0.0
    elif r0 == 0.0:
        q0x, q0y = -r2, 0.0
    elif r2 == 0.0:
        q2x, q2y = -r0, 0.0
    sweep, overshoot, through_zero = angle_change(q0x, q0y, q1x, q1y, q2x, q2y)
    work = kb * (sweep + mb * overshoot) ** eb
    if through_zero:
        work += pb
    return work


@_jit
def _node_bend(a: np.ndarray, b: np.ndarray, i: int, j: int, into: int, out: int,
               kb: float, eb: float, mb: float, pb: float) -> float:
    """Bending at node ``(i, j)`` entered by step ``into`` and left by step ``out``."""
    m, n = a.shape[0], b.shape[0]
    b0x = b0y = f0x = f0y = b1x = b1y = f1x = f1y = 0.0
    if into != STEP_B:
        b0x, b0y = a[(i - 1) % m, 0] - a[i, 0], a[(i - 1) % m, 1] - a[i, 1]
    if into != STEP_A:
        b1x, b1y = b[(j - 1) % n, 0] - b[j, 0], b[(j - 1) % n, 1] - b[j, 1]
    if out != STEP_B:
        f0x, f0y = a[(i + 1) % m, 0] - a[i, 0], a[(i + 1) % m, 1] - a[i, 1]
    if out != STEP_A:
        f1x, f1y = b[(j + 1) % n, 0] - b[j, 0], b[(j + 1) % n, 1] - b[j, 1]
    return bend_work(b0x, b0y, f0x, f0y, b1x, b1y, f1x, f1y, kb, eb, mb, pb)


@_jit
def sg_tables(a: np.ndarray, b: np.ndarray, ks: float, cs: float, es: float,
              kb: float, eb: float, mb: float, pb: float) -> tuple[np.ndarray, np.ndarray]:
    """Every step's stretching ``(m, n, 3)`` and every node's bending ``(m, n, 3 in, 3 out)``."""
    m, n = a.shape[0], b.shape[0]
    stretch = np.empty((m, n, 3))
    bend = np.empty((m, n, 3, 3))
    for i in range(m):
        la = math.hypot(a[(i + 1) % m, 0] - a[i, 0], a[(i + 1) % m, 1] - a[i, 1])
        for j in range(n):
            lb = math.hypot(b[(j + 1) % n, 0] - b[j, 0], b[(j + 1) % n, 1] - b[j, 1])
            stretch[i, j, STEP_B] = stretch_work(0.0, lb, ks, cs, es)
            stretch[i, j, STEP_AB] = stretch_work(la, lb, ks, cs, es)
            stretch[i, j, STEP_A] = stretch_work(la, 0.0, ks, cs, es)
            for into in range(3):
                for out in range(3):
                    bend[i, j, into, out] = _node_bend(a, b, i, j, into, out, kb, eb, mb, pb)
    return stretch, bend


@_jit
def sg_forward(stretch: np.ndarray, bend: np.ndarray, first: int, width: int, closing: int,
               lo: np.ndarray, hi: np.ndarray, energy: np.ndarray, choice: np.ndarray, least: np.ndarray,
               tilt: float = 0.0) -> float:
    """Least energy of a path from a start ``(0, s)``, ``first ≤ s < first + width``, to ``(m, t + n)``.

    Columns are offsets ``k = c - first``; row ``i`` is solved in columns ``lo[i]..hi[i]`` only
    (``(m + 1,)`` each; no step comes from outside them). State: (node, step that entered it);
    a node's bending is added when it is left, so a start's bending is paid once, with the step
    that entered it as the closing step.

    With ``width`` 1 and ``closing ≥ 0`` this is the closed paths' energy from ``(0, first)`` whose
    closing step is ``closing``: the start counts as entered by it, and ``(m, first + n)`` must be.
    Otherwise it *relaxes* the closed paths of every start of the span at once: a path may end at
    any ``t + n`` of the span (``t ≠ s`` too), its start and end counting as entered by
    ``closing`` (or, when ``closing < 0``, each by any step), and it pays ``tilt·(s - t)`` more
    (0 for a closed path, so any ``tilt`` keeps the relaxation a lower bound; one near a column's
    energy keeps paths from gaining by ending early or late). The sums are the closed paths'
    own, in the same order, so with ``tilt`` 0 the relaxation is at most each start's energy as
    rounded too.

    ``energy (2, C, 3)``, ``C ≥ n + width``, holds two rows of state energies in turn (row ``m``'s
    at ``m % 2`` on return). Unless they have a single row, ``choice (m + 1, C, 3)`` receives the
    step that entered each state's predecessor, for :func:`sg_trace`, and ``least (m + 1, C)``
    each node's least state energy.
    """
    m, n = stretch.shape[0], stretch.shape[1]
    keep_choice = choice.shape[0] == m + 1
    keep_least = least.shape[0] == m + 1
    for i in range(m + 1):
        here = energy[i % 2]
        node_i = i if i < m else 0
        for k in range(lo[i], hi[i] + 1):
            for step in range(3):
                pi = i - 1 if step != STEP_B else i
                pk = k - 1 if step != STEP_A else k
                if pi < 0 or pk < lo[pi] or pk > hi[pi]:
                    here[k, step] = np.inf
                    continue
                source = energy[pi % 2]
                node_pi = node_i if pi == i else pi
                pj = (first + pk) % n
                best, best_into = np.inf, 0
                for into in range(3):
                    value = source[pk, into] + bend[node_pi, pj, into, step]
                    if value < best:
                        best, best_into = value, into
                here[k, step] = best + stretch[node_pi, pj, step]
                if keep_choice:
                    choice[i, k, step] = best_into
            if i == 0 and k < width:  # a start: entered by the closing step, at no cost yet
                for step in range(3):
                    if (closing < 0 or step == closing) and not here[k, step] < tilt * k:
                        here[k, step] = tilt * k
            if keep_least:
                least[i, k] = min(here[k, 0], here[k, 1], here[k, 2])
    last = energy[m % 2]
    lowest = np.inf
    for k in range(max(n, lo[m]), min(n + width - 1, hi[m]) + 1):
        for step in range(3):
            if (closing < 0 or step == closing) and last[k, step] - tilt * (k - n) < lowest:
                lowest = last[k, step] - tilt * (k - n)
    return lowest


@_jit
def sg_trace(choice: np.ndarray, first: int, width: int, end: int, closing: int) -> np.ndarray:
    """The nodes ``(L + 1, 2)`` in unrolled coordinates, end first, of the path that :func:`sg_forward`
    solved into ``choice`` and that ends at ``(m, first + end)`` entered by ``closing``: back to the
    first node of row 0 whose offset is below ``width`` (a start).

    Where every path costs +inf the steps kept are arbitrary: a step from outside the grid is then
    replaced by one along its edge, so that the path still runs back to a start.
    """
    m = choice.shape[0] - 1
    nodes = np.empty((m + end + 1, 2), np.int64)
    i, k, step = m, end, closing
    count = 0
    while True:
        nodes[count, 0] = i
        nodes[count, 1] = first + k
        count += 1
        if i == 0 and k < width:
            break
        if i == 0:
            step = STEP_B
        elif k == 0:
            step = STEP_A
        into = choice[i, k, step]
        if step != STEP_A:
            k -= 1
        if step != STEP_B:
            i -= 1
        step = into
    return copy_nodes(nodes, np.empty((count, 2), np.int64), count)


@_jit
def sg_every_start_search(stretch: np.ndarray, bend: np.ndarray) -> tuple[float, np.ndarray]:
    """Least-energy closed path over every start and closing step: O(27 m n²) time, O(mn) memory.

    The reference for ``_sg_search.sg_search``. Among equal energies the first start, then the
    first closing step (STEP_B, STEP_AB, STEP_A) wins. Returns the energy and the nodes
    ``(L + 1, 2)`` in unrolled coordinates, end first.
    """
    m, n = stretch.shape[0], stretch.shape[1]
    energy = np.empty((2, n + 1, 3))
    choice = np.zeros((m + 1, n + 1, 3), np.int8)
    lo = np.zeros(m + 1, np.int64)
    hi = np.full(m + 1, n, np.int64)
    no_choice = np.zeros((1, 1, 3), np.int8)
    no_least = np.zeros((1, 1))
    best, best_start, best_closing = np.inf, 0, STEP_AB
    for s in range(n):
        for closing in range(3):
            value = sg_forward(stretch, bend, s, 1, closing, lo, hi, energy, no_choice, no_least)
            if value < best:
                best, best_start, best_closing = value, s, closing
    sg_forward(stretch, bend, best_start, 1, best_closing, lo, hi, energy, choice, no_least)
    return best, sg_trace(choice, best_start, 1, n, best_closing)


@_jit
def sg_path_energy(a: np.ndarray, b: np.ndarray, pairs: np.ndarray, ks: float, cs: float,
                   es: float, kb: float, eb: float, mb: float, pb: float) -> float:
    """S&G energy of the closed path ``pairs (L, 2)``: every step's stretching, every node's bending."""
    count = pairs.shape[0]
    total = 0.0
    for k in range(count):
        i, j = pairs[k, 0], pairs[k, 1]
        pi, pj = pairs[(k - 1) % count, 0], pairs[(k - 1) % count, 1]
        ni, nj = pairs[(k + 1) % count, 0], pairs[(k + 1) % count, 1]
        l0 = math.hypot(a[ni, 0] - a[i, 0], a[ni, 1] - a[i, 1])
        l1 = math.hypot(b[nj, 0] - b[j, 0], b[nj, 1] - b[j, 1])
        total += stretch_work(l0, l1, ks, cs, es)
        total += bend_work(a[pi, 0] - a[i, 0], a[pi, 1] - a[i, 1],
                           a[ni, 0] - a[i, 0], a[ni, 1] - a[i, 1],
                           b[pj, 0] - b[j, 0], b[pj, 1] - b[j, 1],
                           b[nj, 0] - b[j, 0], b[nj, 1] - b[j, 1], kb, eb, mb, pb)
    return total
