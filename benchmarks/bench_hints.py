"""How much shape hints cost the correspondence search (maths §5.10): hinted against unhinted, side by side.

k hints turn the cyclic search into k open searches between consecutive hints: for ``distance``
the unhinted search is Maes' O(mn log n) over every start and the hinted one O(mn) in all; for
``sg`` the unhinted search tries every start, O(27 m n²), and the hinted one solves each piece
for each of three entering steps, O(81 m n). Each pair of keys is timed both ways in alternation
(best of ``--repeat``), after one call of each to compile the kernels; the ratio is what to read,
since the machine may be busy.

Run: ``python benchmarks/bench_hints.py [--repeat 5]``
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tweenrender.core.correspondence.correspond import correspond, forget_correspondences  # noqa: E402
from tweenrender.core.correspondence.hint_search import correspond_hinted  # noqa: E402
from tweenrender.model import Matching  # noqa: E402


def _star(count: int, rng: np.random.Generator) -> np.ndarray:
    angles = np.sort(rng.uniform(0, 2 * np.pi, count))
    radii = rng.uniform(0.6, 1.4, count)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


def _best(call, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        call()
        times.append(time.perf_counter() - started)
    return min(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    rng = np.random.default_rng(7)
    print(f"{'cost':9} {'m x n':>9} {'hints':>5} {'unhinted ms':>12} {'hinted ms':>10} {'ratio':>7}")
    for cost, sizes in (("distance", (100, 300, 600)), ("sg", (30, 60, 100))):
        matching = Matching(cost=cost)
        for m in sizes:
            a, b = _star(m, rng), _star(m + m // 5, rng)
            for k in (1, 3):
                hinted = [(int(i), int(j)) for i, j in zip(np.arange(k) * (m // k), np.arange(k) * (len(b) // k))]
                correspond(a, b, matching), correspond_hinted(a, b, hinted, matching)  # compile
                plain = _best(lambda: (forget_correspondences(), correspond(a, b, matching)), args.repeat)
                pinned = _best(lambda: correspond_hinted(a, b, hinted, matching), args.repeat)
                print(f"{cost:9} {f'{m}x{len(b)}':>9} {k:5d} {plain * 1e3:12.2f} {pinned * 1e3:10.2f} "
                      f"{plain / pinned:7.2f}")


if __name__ == "__main__":
    main()
