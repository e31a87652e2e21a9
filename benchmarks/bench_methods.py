"""Time per frame of every method on a 500-vertex shape (run by hand, not in CI).

    python benchmarks/bench_methods.py [--vertices 500]

The keys are a five-lobed 500-vertex outline and the same outline stretched,
its lobes shifted and turned 40°. Frames are asked for as the renderer asks:
blocks of 32 t at once. ``arap`` is timed twice: the one-off cost (triangulation,
decomposition, sparse factorisation, done once per pair of keys and cached) and
the cost of each frame afterwards (one back-substitution); the target is at most
2 ms per frame after the one-off. Each figure is the best of a few runs: other
work on the machine only adds. Linear paths are printed first as the yardstick,
and every method's time is also given as a multiple of linear's, measured in
the same run.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tweenrender.core import arap as arap_module  # noqa: E402
from tweenrender.core.methods.registry import interpolate  # noqa: E402
from tweenrender.core.methods.registry import METHODS  # noqa: E402

BLOCK = 32
REPEATS = 5
TARGET_MS = 2.0


def keys(n: int) -> tuple[np.ndarray, np.ndarray]:
    theta = np.linspace(0.0, 2.0 * np.pi, n, endpoint=False)
    k0 = np.column_stack([np.cos(theta), np.sin(theta)]) * (1.0 + 0.3 * np.sin(5 * theta))[:, None]
    lobes = (1.0 + 0.3 * np.sin(5 * theta + 0.4))[:, None]
    stretched = np.column_stack([1.3 * np.cos(theta), np.sin(theta)]) * lobes
    turn = np.radians(40.0)
    rotation = np.array([[np.cos(turn), -np.sin(turn)], [np.sin(turn), np.cos(turn)]])
    return k0, stretched @ rotation.T + [3.0, 1.0]


def best(seconds: list[float]) -> float:
    return min(seconds)


def per_frame(method: str, k0: np.ndarray, k1: np.ndarray) -> float:
    """Best seconds per frame over ``REPEATS`` blocks of ``BLOCK`` frames (caches warm)."""
    t = np.linspace(0.0, 1.0, BLOCK + 2)[1:-1]
    interpolate(k0, k1, t, method)  # warm: numba, caches
    runs = []
    for _ in range(REPEATS):
        start = time.perf_counter()
        interpolate(k0, k1, t, method)
        runs.append((time.perf_counter() - start) / BLOCK)
    return best(runs)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--vertices", type=int, default=500)
    n = parser.parse_args().vertices
    k0, k1 = keys(n)

    one_off = []
    for _ in range(3):
        arap_module._cache.clear()
        start = time.perf_counter()
        paths = arap_module.arap_paths(k0, k1)
        one_off.append(time.perf_counter() - start)
    mesh = arap_module.compatible_mesh(k0, k1)

    print(f"{n}-vertex keys, blocks of {BLOCK} frames, best of {REPEATS}")
    linear = per_frame("linear", k0, k1)
    print(f"{'method':18}{'ms per frame':>14}{'× linear':>10}")
    for method in METHODS:
        seconds = per_frame(method, k0, k1)
        print(f"{method:18}{1e3 * seconds:>14.3f}{seconds / linear:>10.1f}")
    print(f"\narap one-off (triangulate, decompose, factor): {1e3 * best(one_off):.0f} ms "
          f"({len(mesh.p0)} mesh vertices, {len(mesh.triangles)} triangles, {mesh.folds} folds)")
    arap_ms = 1e3 * per_frame("arap", k0, k1)
    verdict = "meets" if arap_ms <= TARGET_MS else "misses"
    print(f"arap per frame after it: {arap_ms:.3f} ms — {verdict} the target of {TARGET_MS:g} ms")
    del paths


if __name__ == "__main__":
    main()
