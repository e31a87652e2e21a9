"""Time the vertex-correspondence search (run by hand, not in CI).

    PYTHONPATH=. python benchmarks/bench_correspond.py [--naive-2000]

Prints, for random star-shaped polygons: the first call in a fresh process with
an empty numba cache (JIT compile included) and with the on-disk cache, the
warm in-process time of ``correspond`` (Maes' divide and conquer) and of
``naive_correspond`` (every start, O(m n²); at 2000² only estimated unless
asked, it takes over half a minute), their ratio, and the wall time of a
whole ``python -c`` command that imports, builds 2000-vertex keys and solves.
Each warm timing is the best of a few runs: other work on the machine only adds.
"""

from __future__ import annotations

import argparse
import inspect
import json
import os
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SIZES = (200, 500, 2000)
REPEATS = 3


def star(n: int, seed: int) -> np.ndarray:
    """A random counter-clockwise polygon of ``n`` vertices, star-shaped about the origin."""
    rng = np.random.default_rng(seed)
    angles = np.sort(rng.uniform(0, 2 * np.pi, n))
    radii = rng.uniform(0.5, 1.5, n)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


# The child processes build the very same keys.
STAR_SOURCE = "import numpy as np\n" + inspect.getsource(star)

FIRST_CALL_CHILD = STAR_SOURCE + """
import json, time
a, b = star({n}, 1), star({n}, 2)
start = time.perf_counter()
from tweenrender.core.correspond import correspond
from tweenrender.model import Matching
imported = time.perf_counter()
correspond(a, b, Matching(cost={cost!r}))
print(json.dumps({{"import": imported - start, "first_call": time.perf_counter() - imported}}))
"""

WHOLE_COMMAND = STAR_SOURCE + """
from tweenrender.core.correspond import correspond
found = correspond(star(2000, 1), star(2000, 2))
print(found.balanced, found.work)
"""


def child_env(cache_dir: str | None) -> dict[str, str]:
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    if cache_dir is not None:
        env["NUMBA_CACHE_DIR"] = cache_dir  # numba's first choice: an empty one means compiling
    return env


def run_child(code: str, cache_dir: str | None) -> tuple[float, str]:
    """Wall seconds of ``python -c code`` and what it printed."""
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                          cwd=ROOT, env=child_env(cache_dir))
    return time.perf_counter() - start, done.stdout.strip()


def first_call(n: int, cost: str, cold: bool) -> float:
    """Seconds of the first ``correspond`` call in a new process (compiling it when ``cold``)."""
    code = FIRST_CALL_CHILD.format(n=n, cost=cost)
    if cold:
        with tempfile.TemporaryDirectory() as empty_cache:
            _, out = run_child(code, empty_cache)
    else:
        _, out = run_child(code, None)
    return float(json.loads(out)["first_call"])


def best_time(call: Callable[[], object], repeats: int = REPEATS) -> float:
    times = []
    for _ in range(repeats):
        start = time.perf_counter()
        call()
        times.append(time.perf_counter() - start)
    return min(times)


def distance_rows(naive_2000: bool) -> None:
    from tweenrender.core.correspond import correspond, naive_correspond

    print("cost 'distance', random star-shaped polygons, m = n")
    print(f"{'size':>10} {'1st call':>9} {'1st call':>9} {'warm':>8} {'naive':>9} {'speed-up':>9}")
    print(f"{'':>10} {'compiled':>9} {'cached':>9} {'':>8} {'warm':>9} {'':>9}")
    naive_500 = float("nan")
    for n in SIZES:
        a, b = star(n, 1), star(n, 2)
        cold = first_call(n, "distance", cold=True)
        cached = first_call(n, "distance", cold=False)
        warm = best_time(lambda: correspond(a, b))
        estimated = n > 500 and not naive_2000
        if estimated:
            # O(n³) here: the 500² time scaled by (n / 500)³, a lower bound (it
            # ignores the larger working set), marked with "~".
            naive = naive_500 * (n / 500) ** 3
        else:
            naive = best_time(lambda: naive_correspond(a, b), repeats=REPEATS if n <= 500 else 1)
            naive_500 = naive if n == 500 else naive_500
        mark = "~" if estimated else ""
        print(f"{f'{n}x{n}':>10} {cold:9.3f} {cached:9.3f} {warm:8.4f} {mark + f'{naive:.3f}':>9} "
              f"{mark + f'{naive / warm:.0f}x':>9}")


def sg_rows() -> None:
    from tweenrender.core.correspond import correspond
    from tweenrender.model import Matching

    print("\ncost 'sg' (exact, every start: O(27 m n²))")
    sg = Matching(cost="sg")
    for n in (60, 100):
        a, b = star(n, 1), star(n, 2)
        cold = first_call(n, "sg", cold=True)
        cached = first_call(n, "sg", cold=False)
        warm = best_time(lambda: correspond(a, b, sg))
        print(f"{f'{n}x{n}':>10} {cold:9.3f} {cached:9.3f} {warm:8.4f}")


def whole_command_rows() -> None:
    print("\nwhole command, 2000x2000: python -c 'from tweenrender.core.correspond import correspond; ...'")
    walls = [run_child(WHOLE_COMMAND, None)[0] for _ in range(REPEATS)]
    print(f"  cached kernels: {min(walls):.2f} s wall (best of {REPEATS}; start-up, imports, keys, solve)")
    with tempfile.TemporaryDirectory() as empty_cache:
        wall, _ = run_child(WHOLE_COMMAND, empty_cache)
    print(f"  empty cache:    {wall:.2f} s wall (JIT compile included)")
    startup, _ = run_child("import numpy", None)
    print(f"  for scale, python -c 'import numpy': {startup:.2f} s wall")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--naive-2000", action="store_true",
                        help="time the naive search at 2000x2000 (over half a minute), not estimate it")
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT))
    from tweenrender.core.correspond import correspond, naive_correspond

    correspond(star(5, 1), star(6, 2))  # compile or load the kernels before any timing
    naive_correspond(star(5, 1), star(6, 2))
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores; seconds; warm = best of {REPEATS}; "
          "1st call = in a new process, with an empty numba cache (compiled) or the cache on disk\n")
    distance_rows(args.naive_2000)
    sg_rows()
    whole_command_rows()


if __name__ == "__main__":
    main()
