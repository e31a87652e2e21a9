"""How tight is the cheapest lower bound of the ``sg`` bending term? (run by hand, not in CI)

    python benchmarks/sg_bending_bound.py [--sizes 200,400]

A search of the ``sg`` cost in memory linear in n cannot keep the 96-byte tables of every node, so
every pass would compute nine Q-curves a node again (measured 6–19× slower: docs/correspondence.md).
It could instead bound its spans with a bending term computed from each key alone and analyse
Q-curves only where that bound leaves a node in play. The cheapest such bound drops what couples the
keys: a Q-curve's angle changes by at least the angle between its two ends, and those ends are each
key's own turn at its vertex (or the straight ``(-r, 0)`` where a key's end vanishes); the overshoot
and the folding penalty are dropped. For the pairs of ``bench_correspond.py`` and random stars, this
prints the least closed-path energy with the exact tables and with the bound in their place (the
same stretching), their ratio, and the share of table entries the bound equals. A bound to prune
with needs a ratio near 1.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[1]))

from bench_correspond import sg_pairs  # noqa: E402

from tweenrender.core.correspondence._cyclic_dtw import STEP_A, STEP_B, sg_tables  # noqa: E402
from tweenrender.core.correspondence._sg_search import sg_search  # noqa: E402
from tweenrender.model import Matching  # noqa: E402


def turns(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each vertex's Q-curve end (backward edge against forward edge, maths §3): its angle and length, ``(n,)``."""
    back = np.roll(points, 1, axis=0) - points
    forward = np.roll(points, -1, axis=0) - points
    x = forward[:, 0] * back[:, 0] + forward[:, 1] * back[:, 1]
    y = forward[:, 0] * back[:, 1] - forward[:, 1] * back[:, 0]
    return np.arctan2(y, x), np.hypot(x, y)


def bending_bound(a: np.ndarray, b: np.ndarray, kb: float, eb: float) -> np.ndarray:
    """``(m, n, 3, 3)``: for each node and (entering, leaving) step, ``kb · d^eb`` with ``d`` the angle between
    the Q-curve's two ends, each from one key (an end whose key does not move through the node, or whose
    edge vanishes, is the straight ``(-r, 0)``; both vanished: no bending)."""
    angle_a, length_a = turns(a)
    angle_b, length_b = turns(b)
    bound = np.zeros((len(a), len(b), 3, 3))
    for into in range(3):
        for out in range(3):
            has_a = np.broadcast_to(((length_a > 0) & (into != STEP_B) & (out != STEP_B))[:, None], bound.shape[:2])
            has_b = np.broadcast_to(((length_b > 0) & (into != STEP_A) & (out != STEP_A))[None, :], bound.shape[:2])
            first = np.where(has_a, angle_a[:, None], np.pi)
            last = np.where(has_b, angle_b[None, :], np.pi)
            gap = np.abs(first - last)
            gap = np.maximum(np.minimum(gap, 2 * np.pi - gap) - 1e-12, 0.0)  # below the exact sums' rounding
            bound[:, :, into, out] = np.where(has_a | has_b, kb * gap ** eb, 0.0)
    return bound


def star(n: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    radii = rng.uniform(0.5, 1.5, n)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="200,400")
    args = parser.parse_args()
    c = Matching()
    pairs = {**sg_pairs(), "stars": lambda n: (star(n, 1), star(n + n // 10, 2))}
    print("| keys | m × n | least energy, exact | with the bound | ratio | entries the bound equals |")
    print("|---|---|---|---|---|---|")
    for size in (int(s) for s in args.sizes.split(",")):
        for name, make in pairs.items():
            a, b = (np.ascontiguousarray(k, dtype=np.float64) for k in make(size))
            stretch, bend = sg_tables(a, b, c.ks, c.cs, c.es, c.kb, c.eb, c.mb, c.pb)
            bound = bending_bound(a, b, c.kb, c.eb)
            if not (bound <= bend).all():
                raise SystemExit(f"{name}: the bound exceeds a table entry by {(bound - bend).max():g}")
            exact, relaxed = sg_search(stretch, bend).work, sg_search(stretch, bound).work
            equal = np.isclose(bound, bend, rtol=1e-9, atol=1e-12).mean()
            print(f"| {name} | {len(a)} × {len(b)} | {exact:.4g} | {relaxed:.4g} | {relaxed / exact:.3f} | "
                  f"{100 * equal:.0f} % |")


if __name__ == "__main__":
    main()
