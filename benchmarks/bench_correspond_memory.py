"""Time and peak memory of the correspondence search as keys grow (run by hand, not in CI).

    PYTHONPATH=. python benchmarks/bench_correspond_memory.py [--sizes 1000,2000,5000,10000]

Each measurement is a fresh process (peak RSS from ``getrusage``, numba's cached kernels
loaded first and the baseline printed), on random star-shaped keys of m and n vertices, for
the distance cost: the search the package runs now (``correspond``) against the previous one
(``maes_search`` over the whole distance matrix, with every node's step kept), interleaved,
min / median of ``--rounds``; the ratio of successive sizes' times shows how it grows (n² log n
gives 4.4x for twice the vertices at 1000, 4.2x at 5000). Then ``sg`` at the sizes its O(m n²)
search allows.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

CHILD = """
import json, resource, time, numpy as np
def star(n, seed):
    rng = np.random.default_rng(seed)
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    radii = rng.uniform(0.5, 1.5, n)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])
from tweenrender.core.correspondence import correspond as c, _cyclic_dtw as k, _lean_dtw
from tweenrender.model import Matching
c.correspond(star(40, 1), star(300, 2))  # loads numba and the cached kernels
k.maes_search(k.distance_matrix(star(30, 1), star(40, 2)))
base = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
a, b = star({m}, 1), star({n}, 2)
start = time.perf_counter()
if "{how}" == "before":
    k.maes_search(k.distance_matrix(a, b))
else:
    c.correspond(a, b, Matching(cost="{cost}", align="none", max_memory=1 << 40))  # measured, not guarded
seconds = time.perf_counter() - start
print(json.dumps({{"seconds": seconds, "peak_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                  "base_mib": base / 1024}}))
"""


def run(m: int, n: int, how: str, cost: str = "distance") -> dict:
    done = subprocess.run([sys.executable, "-c", CHILD.format(m=m, n=n, how=how, cost=cost)], capture_output=True,
                          text=True, env={**os.environ, "PYTHONPATH": str(ROOT)}, timeout=3600)
    if done.returncode:
        raise RuntimeError(done.stderr)
    return json.loads(done.stdout)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--sizes", default="1000,2000,5000,10000")
    parser.add_argument("--rounds", type=int, default=2)
    parser.add_argument("--sg-sizes", default="100,200,400")
    args = parser.parse_args()
    pairs = [(int(s), int(s)) for s in args.sizes.split(",")] + [(10000, 2000)]
    print(f"load average at start: {os.getloadavg()[0]:.2f} (cores: {os.cpu_count()})")
    print(f"{'m x n':>13}  {'now: s (min / median)':>22} {'peak MiB':>9}   {'before: s':>16} {'peak MiB':>9}"
          f"   (baseline after loading: MiB)")
    previous = None
    for m, n in pairs:
        rows: dict[str, list[dict]] = {"now": [], "before": []}
        for _ in range(args.rounds):
            for how in ("now", "before"):
                rows[how].append(run(m, n, how))
        now, before = rows["now"], rows["before"]
        t_now = [r["seconds"] for r in now]
        t_before = [r["seconds"] for r in before]
        growth = ""
        if previous is not None and m == n and previous[0] == previous[1]:
            growth = f"   x{statistics.median(t_now) / previous[2]:.2f} for x{m / previous[0]:.1f} vertices"
        print(f"{m:6d} x {n:<6d} {min(t_now):9.2f} / {statistics.median(t_now):6.2f} "
              f"{max(r['peak_mib'] for r in now):9.0f}   {min(t_before):7.2f} / {statistics.median(t_before):6.2f} "
              f"{max(r['peak_mib'] for r in before):9.0f}   ({now[0]['base_mib']:.0f}){growth}", flush=True)
        if m == n:
            previous = (m, n, statistics.median(t_now))
    print("sg (O(m n^2) time):")
    for size in (int(s) for s in args.sg_sizes.split(",")):
        result = run(size, size, "now", "sg")
        print(f"{size:6d} x {size:<6d} {result['seconds']:9.2f} s {result['peak_mib']:9.0f} MiB", flush=True)
    print(f"load average at end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
