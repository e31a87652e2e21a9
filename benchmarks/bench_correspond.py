"""Time the vertex-correspondence search (run by hand, not in CI).

    PYTHONPATH=. python benchmarks/bench_correspond.py [--naive-2000] [--only distance|sg]
                                                       [--sg-sizes 100,200,400,1000,2000] [--every-up-to 400]

Prints, for random star-shaped polygons: the first call in a fresh process with
an empty numba cache (JIT compile included) and with the on-disk cache, the
warm in-process time of ``correspond`` (Maes' divide and conquer) and of
``naive_correspond`` (every start, O(m n²); at 2000² only estimated unless
asked, it takes over half a minute), their ratio, and the wall time of a
whole ``python -c`` command that imports, builds 2000-vertex keys and solves.
Each warm timing is the best of a few runs: other work on the machine only adds.

For the ``sg`` cost, on outlines resampled to n and about 1.1 n vertices (random smooth blobs,
the bird-feet scene's keys, two pairs of icons): CPU seconds of the search that solves every
start (``sg_every_start_search``; above ``--every-up-to`` vertices estimated from the largest
size measured, as n³, marked ``~``) and of the branch and bound (``sg_search``) on the same
tables, the (start, closing step) pairs it solved of the 3n, the spans it bounded, the growth
exponent of its time from the size before (n² log n would give the last column), and the
tables' own seconds.
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
from tweenrender.core.correspondence.correspond import correspond
from tweenrender.model import Matching
imported = time.perf_counter()
correspond(a, b, Matching(cost={cost!r}))
print(json.dumps({{"import": imported - start, "first_call": time.perf_counter() - imported}}))
"""

WHOLE_COMMAND = STAR_SOURCE + """
from tweenrender.core.correspondence.correspond import correspond
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
    from tweenrender.core.correspondence.correspond import correspond, forget_correspondences, naive_correspond

    print("cost 'distance', random star-shaped polygons, m = n")
    print(f"{'size':>10} {'1st call':>9} {'1st call':>9} {'warm':>8} {'naive':>9} {'speed-up':>9}")
    print(f"{'':>10} {'compiled':>9} {'cached':>9} {'':>8} {'warm':>9} {'':>9}")
    naive_500 = float("nan")
    for n in SIZES:
        a, b = star(n, 1), star(n, 2)
        cold = first_call(n, "distance", cold=True)
        cached = first_call(n, "distance", cold=False)
        warm = best_time(lambda: (forget_correspondences(), correspond(a, b)))  # searched, not remembered
        estimated = n > 500 and not naive_2000
        if estimated:
            # O(n³) here: the 500² time scaled by (n / 500)³, a lower bound (it
            # ignores the larger working set), marked with "~".
            naive = naive_500 * (n / 500) ** 3
        else:
            naive = best_time(lambda: (forget_correspondences(), naive_correspond(a, b)),
                              repeats=REPEATS if n <= 500 else 1)
            naive_500 = naive if n == 500 else naive_500
        mark = "~" if estimated else ""
        print(f"{f'{n}x{n}':>10} {cold:9.3f} {cached:9.3f} {warm:8.4f} {mark + f'{naive:.3f}':>9} "
              f"{mark + f'{naive / warm:.0f}x':>9}")


def resampled(points: np.ndarray, count: int) -> np.ndarray:
    """A closed outline with ``count`` vertices spaced evenly along its length."""
    closed = np.vstack([points, points[:1]])
    at = np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(closed, axis=0).T))])
    u = np.linspace(0.0, at[-1], count, endpoint=False)
    return np.column_stack([np.interp(u, at, closed[:, 0]), np.interp(u, at, closed[:, 1])])


def blob(n: int, seed: int) -> np.ndarray:
    """A smooth random outline of ``n`` vertices (five harmonics of the radius)."""
    rng = np.random.default_rng(seed)
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    radius = 1 + sum(rng.normal(0, 0.25 / k) * np.cos(k * t + rng.uniform(0, 2 * np.pi)) for k in range(1, 6))
    return np.column_stack([radius * np.cos(t), radius * np.sin(t)])


def sg_pairs() -> dict[str, Callable[[int], tuple[np.ndarray, np.ndarray]]]:
    """Key pairs for the sg rows: each makes keys of about n and 1.1 n vertices."""
    import tweenrender as tr

    def first_contour(path: Path, key: int = 0) -> np.ndarray:
        return np.asarray(tr.load_scene(path).shapes[0].keys[key].contours[0].points)

    icons = ROOT / "tests" / "data" / "icons"
    feet = [first_contour(ROOT / "scenes" / "bird-feet.toml", key) for key in (0, 1)]
    hearts = first_contour(icons / "heroicons" / "heart.svg"), first_contour(icons / "heroicons" / "star.svg")
    moon = first_contour(icons / "mdi" / "heart.svg"), first_contour(icons / "mdi" / "weather-night.svg")
    return {
        "blobs": lambda n: (blob(n, 1), blob(n + n // 10, 2)),
        "bird-feet": lambda n: (resampled(feet[0], n), resampled(feet[1], n + n // 10)),
        "heart>star": lambda n: (resampled(hearts[0], n), resampled(hearts[1], n + n // 10)),
        "heart>moon": lambda n: (resampled(moon[0], n), resampled(moon[1], n + 7)),
    }


def cpu_time(call: Callable[[], object]) -> tuple[float, object]:
    """CPU seconds of one call (less disturbed than wall time by other work on the machine) and its value."""
    start = time.process_time()
    value = call()
    return time.process_time() - start, value


def sg_rows(sizes: list[int], every_up_to: int) -> None:
    from tweenrender.core.correspondence import _cyclic_dtw
    from tweenrender.core.correspondence._sg_search import sg_search
    from tweenrender.core.correspondence.correspond import _aligned, _as_polygon, _winds_opposite
    from tweenrender.model import Matching

    mt = Matching(cost="sg")
    print("\ncost 'sg', CPU seconds of the search on the same tables (every start: O(27 m n²))")
    print(f"{'keys':>11} {'m x n':>11} {'every':>9} {'b&b':>8} {'speed-up':>9} {'solved':>12} {'spans':>6} "
          f"{'growth':>7} {'n²log n':>8} {'tables':>7}")
    for name, make in sg_pairs().items():
        every_at: tuple[int, float] | None = None
        before: tuple[int, float] | None = None
        for n in sizes:
            a, b = make(n)
            a, b = _aligned(_as_polygon(a, "a"), _as_polygon(b, "b"), mt.align)
            walk = (-np.arange(len(b))) % len(b) if _winds_opposite(a, b) else np.arange(len(b))
            build, tables = cpu_time(lambda: _cyclic_dtw.sg_tables(
                a, np.ascontiguousarray(b[walk]), mt.ks, mt.cs, mt.es, mt.kb, mt.eb, mt.mb, mt.pb))
            ours, found = cpu_time(lambda: sg_search(*tables))
            if n <= every_up_to:
                every, (work, nodes) = cpu_time(lambda: _cyclic_dtw.sg_every_start_search(*tables))
                assert work == found.work and np.array_equal(nodes, found.nodes), "not the every-start path"
                every_at, mark = (n, every), ""
            else:
                assert every_at is not None
                every, mark = every_at[1] * (n / every_at[0]) ** 3, "~"
            growth = expected = ""
            if before is not None:
                ratio = np.log(n / before[0])
                growth = f"{np.log(ours / before[1]) / ratio:.2f}"
                expected = f"{np.log((n * n * np.log(n)) / (before[0] ** 2 * np.log(before[0]))) / ratio:.2f}"
            before = (n, ours)
            count = tables[0].shape[1]
            print(f"{name:>11} {f'{len(a)}x{count}':>11} {mark + f'{every:.3f}':>9} {ours:8.3f} "
                  f"{mark + f'{every / ours:.0f}x':>9} {f'{found.solved}/{3 * count}':>12} {found.bounded:6d} "
                  f"{growth:>7} {expected:>8} {build:7.2f}", flush=True)


def whole_command_rows() -> None:
    print("\nwhole command, 2000x2000: python -c 'from tweenrender.core.correspondence.correspond import correspond; ...'")
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
    parser.add_argument("--only", choices=("distance", "sg"), help="run one cost's rows only")
    parser.add_argument("--sg-sizes", default="100,200,400,1000,2000", help="vertex counts of the sg rows")
    parser.add_argument("--every-up-to", type=int, default=400,
                        help="largest sg keys whose every-start search is timed, not estimated")
    args = parser.parse_args()
    sys.path.insert(0, str(ROOT))
    from tweenrender.core.correspondence.correspond import correspond, naive_correspond
    from tweenrender.model import Matching

    for cost in ("distance", "sg"):  # compile or load the kernels before any timing
        correspond(star(5, 1), star(6, 2), Matching(cost=cost))
        naive_correspond(star(5, 1), star(6, 2), Matching(cost=cost))
    print(f"python {sys.version.split()[0]}, {os.cpu_count()} cores; seconds; warm = best of {REPEATS}; "
          "1st call = in a new process, with an empty numba cache (compiled) or the cache on disk\n")
    if args.only != "sg":
        distance_rows(args.naive_2000)
    if args.only != "distance":
        sg_rows([int(n) for n in args.sg_sizes.split(",")], args.every_up_to)
    if args.only is None:
        whole_command_rows()


if __name__ == "__main__":
    main()
