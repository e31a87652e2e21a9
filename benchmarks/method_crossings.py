"""Which methods tangle on unrelated real icons, how far they bend the area, what a frame costs.

A fixed sample of pairs of real icons from ``tests/data/icons`` (drawn with a seeded generator
from the sorted file list), each loaded as a two-drawing morph (``tweenrender.load_scene``).
Every element that moves through the segment in both keys is one *case*; its keys must not
tangle themselves (:mod:`tweenrender.core.tangles`), else it is left out. For every method:

* cases and frames (t = .05 … .95) where the shape tangles: a contour crossing itself
  properly, a hole leaving its outline (exact orientation signs);
* area deviation ``|A(t) / ((1-t)·A0 + t·A1) - 1|`` at t = .25, .5, .75 (signed areas summed
  over the element's closed contours), median and 90th percentile, single outlines apart;
* sawtooth: total absolute turning of each closed contour at t = .5 over the larger of the
  two keys' (single outlines), and the share of cases above 1.5 — raw (``saw``), and
  ``seen``: each outline first simplified (Douglas–Peucker) to 0.5 % of the keys' size,
  so that wiggles below a pixel or so of a rendered icon do not count;
* milliseconds per frame (the first call of a segment, mesh included, over the 19 frames).

Then the compatible triangulation of two 500-vertex keys (two real outlines resampled by arc
length) and one frame of it. Times are printed with the machine's load, never asserted.

Flubber (npm ``flubber``, the web's usual shape morph) is measured beside them on the single
outlines when ``FLUBBER_DIR`` names a folder where ``npm install flubber`` was run
(``benchmarks/flubber_morph.js`` runs it under node).

Run: ``[FLUBBER_DIR=...] python benchmarks/method_crossings.py [pairs]`` (default 40).
"""

from __future__ import annotations

import os
import random
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import tweenrender as tr  # noqa: E402
from tweenrender.core import injective as injective_module  # noqa: E402
from tweenrender.core.tangles import parents, tangles  # noqa: E402
from tweenrender.core.timing.timeline import build_track, pair_paths  # noqa: E402
from tweenrender.core.methods.registry import METHODS  # noqa: E402

T = np.round(np.arange(1, 20) * 0.05, 2)
AREA_T = (0.25, 0.5, 0.75)
SEEN = 0.005  # wiggles below this share of the keys' size are left out of "seen" turning (1.3 px at 256 px)
METHOD_LIST = [m for m in METHODS if m not in ("jointed", "intrinsic-length")]


def sample(count: int, seed: int = 2026) -> list[tuple[Path, Path]]:
    icons = sorted((ROOT / "tests" / "data" / "icons").glob("*/*.svg"))
    rng = random.Random(seed)
    return [tuple(rng.sample(icons, 2)) for _ in range(count)]  # type: ignore[misc]


def signed_area(points: np.ndarray) -> float:
    x, y = points[:, 0], points[:, 1]
    return 0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y))


def turning(points: np.ndarray) -> float:
    """Total absolute turning of a closed polygon, zero-length edges skipped."""
    edges = np.roll(points, -1, axis=0) - points
    edges = edges[np.linalg.norm(edges, axis=1) > 0]
    if len(edges) < 3:
        return 0.0
    angle = np.arctan2(edges[:, 1], edges[:, 0])
    turn = (np.roll(angle, -1) - angle + np.pi) % (2 * np.pi) - np.pi
    return float(np.abs(turn).sum())


def simplify(points: np.ndarray, tolerance: float) -> np.ndarray:
    """Douglas–Peucker on a closed polygon (split at vertex 0 and the vertex farthest from it):
    the outline less every wiggle smaller than ``tolerance``."""
    def chain(run: np.ndarray) -> np.ndarray:
        if len(run) < 3:
            return run
        a, b = run[0], run[-1]
        d = b - a
        length = float(np.hypot(*d))
        if length == 0:
            distance = np.linalg.norm(run - a, axis=1)
        else:
            distance = np.abs(d[0] * (run[:, 1] - a[1]) - d[1] * (run[:, 0] - a[0])) / length
        k = int(np.argmax(distance))
        if distance[k] <= tolerance:
            return np.array([a, b])
        return np.vstack([chain(run[:k + 1])[:-1], chain(run[k:])])

    far = int(np.argmax(np.linalg.norm(points - points[0], axis=1)))
    first = chain(points[:far + 1])
    second = chain(np.vstack([points[far:], points[:1]]))
    return np.vstack([first[:-1], second[:-1]])


def cases(pairs: list[tuple[Path, Path]]):
    for a, b in pairs:
        scene = tr.load_scene([a, b])
        for shape in scene.shapes:
            track = build_track(shape, scene.matching, unmatched=scene.unmatched, balance=scene.balance_of(shape))
            for segment in track.segments:
                moving = [k for k, p in enumerate(segment.pairs) if p.moving]
                if not all(segment.shown) or not moving:
                    continue
                closed = [segment.pairs[k].closed for k in moving]
                k0s = [segment.pairs[k].k0 for k in moving]
                k1s = [segment.pairs[k].k1 for k in moving]
                parent = parents(k0s, closed)
                if tangles(k0s, closed, parent) or tangles(k1s, closed, parent):
                    continue
                yield f"{a.parent.name}/{a.stem}->{b.parent.name}/{b.stem}:{shape.name}", segment, moving, parent


def measure(pairs: list[tuple[Path, Path]]) -> None:
    found = list(cases(pairs))
    single = [c for c in found if len(c[2]) == 1 and c[1].pairs[c[2][0]].closed]
    print(f"{len(pairs)} pairs of icons, {len(found)} moving elements with simple keys "
          f"({len(single)} single outlines)")
    print(f"{'method':<18}{'tangled cases':>14}{'frames':>8}{'area p50':>10}{'area p90':>10}"
          f"{'1-outline p50':>15}{'p90':>7}{'saw>1.5':>9}{'seen>1.5':>9}{'ms/frame':>10}")
    for method in METHOD_LIST:
        bad_cases = bad_frames = 0
        deviations, single_deviations, saw, seen = [], [], [], []
        spent = 0.0
        for name, segment, moving, parent in found:
            closed = [segment.pairs[k].closed for k in moving]
            start = time.perf_counter()
            frames = pair_paths(segment, np.concatenate([T, AREA_T]), method)
            spent += time.perf_counter() - start
            frames = [frames[k] for k in moving]
            tangled = [tangles([f[i] for f in frames], closed, parent) for i in range(len(T))]
            bad_frames += sum(tangled)
            bad_cases += any(tangled)
            pairs_k = [segment.pairs[k] for k in moving]
            a0 = sum(signed_area(p.k0) for p in pairs_k if p.closed)
            a1 = sum(signed_area(p.k1) for p in pairs_k if p.closed)
            is_single = len(moving) == 1 and closed[0]
            for i, t in enumerate(AREA_T):
                reference = (1 - t) * a0 + t * a1
                area = sum(signed_area(f[len(T) + i]) for f, c in zip(frames, closed) if c)
                if reference != 0:
                    deviation = abs(area / reference - 1)
                    deviations.append(deviation)
                    if is_single:
                        single_deviations.append(deviation)
            if is_single:
                mid = frames[0][len(T) + 1]
                a, b = pairs_k[0].k0, pairs_k[0].k1
                keys = max(turning(a), turning(b))
                saw.append(turning(mid) / keys if keys > 0 else 1.0)
                tolerance = SEEN * max(np.ptp(a, axis=0).max(), np.ptp(b, axis=0).max())
                keys = max(turning(simplify(a, tolerance)), turning(simplify(b, tolerance)))
                seen.append(turning(simplify(mid, tolerance)) / keys if keys > 0 else 1.0)
        frame_count = len(found) * (len(T) + len(AREA_T))
        print(f"{method:<18}{bad_cases:>14}{bad_frames:>8}{np.median(deviations):>10.3f}"
              f"{np.percentile(deviations, 90):>10.3f}{np.median(single_deviations):>15.3f}"
              f"{np.percentile(single_deviations, 90):>7.3f}{np.mean(np.array(saw) > 1.5):>9.1%}"
              f"{np.mean(np.array(seen) > 1.5):>9.1%}"
              f"{1000 * spent / frame_count:>10.2f}")


def flubber_row(pairs: list[tuple[Path, Path]]) -> None:
    """The same measures for flubber on the single outlines, if ``FLUBBER_DIR`` names a folder where
    ``npm install flubber`` was run (flubber matches the drawn outlines itself: copies are dropped)."""
    import json
    import shutil
    import subprocess

    folder = os.environ.get("FLUBBER_DIR")
    if not folder or shutil.which("node") is None:
        print("flubber: not run (set FLUBBER_DIR to a folder with node_modules/flubber)")
        return
    from tweenrender.core.crossings import distinct_outline

    single = [c for c in cases(pairs) if len(c[2]) == 1 and c[1].pairs[c[2][0]].closed]
    asked = []
    for _, segment, moving, _ in single:
        pair = segment.pairs[moving[0]]
        a, b = distinct_outline(pair.k0), distinct_outline(pair.k1)
        size = max(np.ptp(a, axis=0).max(), np.ptp(b, axis=0).max())
        asked.append({"a": a.tolist(), "b": b.tolist(), "t": [*T.tolist(), *AREA_T], "segment": size / 50})
    done = subprocess.run(["node", str(ROOT / "benchmarks" / "flubber_morph.js")], input=json.dumps(asked),
                          capture_output=True, text=True, check=True,
                          env={**os.environ, "NODE_PATH": str(Path(folder) / "node_modules")})
    bad_cases = bad_frames = 0
    deviations, saw, seen, spent = [], [], [], []
    for (name, segment, moving, _), found in zip(single, json.loads(done.stdout)):
        pair = segment.pairs[moving[0]]
        rings = [np.array(r, dtype=np.float64) for r in found["rings"]]
        tangled = [tangles([r], [True], [None]) for r in rings[:len(T)]]
        bad_frames += sum(tangled)
        bad_cases += any(tangled)
        a0, a1 = signed_area(pair.k0), signed_area(pair.k1)
        for i, t in enumerate(AREA_T):
            reference = (1 - t) * a0 + t * a1
            if reference != 0:
                # flubber winds its rings its own way: areas compared unsigned
                deviations.append(abs(abs(signed_area(rings[len(T) + i])) / abs(reference) - 1))
        mid = rings[len(T) + 1]
        keys = max(turning(pair.k0), turning(pair.k1))
        saw.append(turning(mid) / keys if keys > 0 else 1.0)
        tolerance = SEEN * max(np.ptp(pair.k0, axis=0).max(), np.ptp(pair.k1, axis=0).max())
        keys = max(turning(simplify(pair.k0, tolerance)), turning(simplify(pair.k1, tolerance)))
        seen.append(turning(simplify(mid, tolerance)) / keys if keys > 0 else 1.0)
        spent.append(found["ms"])
    print(f"{'flubber (1-outline)':<18}{bad_cases:>14}{bad_frames:>8}{'':>10}{'':>10}"
          f"{np.median(deviations):>15.3f}{np.percentile(deviations, 90):>7.3f}{np.mean(np.array(saw) > 1.5):>9.1%}"
          f"{np.mean(np.array(seen) > 1.5):>9.1%}{np.mean(spent):>10.2f}  (node, frames only)")


def resample(points: np.ndarray, count: int) -> np.ndarray:
    """``count`` points evenly by arc length around a closed polygon, from its topmost vertex."""
    points = np.roll(points, -int(np.argmax(points[:, 1])), axis=0)
    closed = np.vstack([points, points[:1]])
    steps = np.linalg.norm(np.diff(closed, axis=0), axis=1)
    at = np.concatenate([[0], np.cumsum(steps)])
    where = np.linspace(0, at[-1], count, endpoint=False)
    return np.column_stack([np.interp(where, at, closed[:, 0]), np.interp(where, at, closed[:, 1])])


def big_mesh() -> None:
    icons = ROOT / "tests" / "data" / "icons"
    for a, b in (("simple-icons/apple", "lucide/star"), ("feather/moon", "octicons/heart-24"),
                 ("twemoji/1f319", "heroicons/check-circle")):
        outlines = []
        for name in (a, b):
            scene = tr.load_scene(icons / f"{name}.svg")
            outlines.append(max(tr.outlines(scene, 0.0), key=lambda c: abs(signed_area(c))))
        k0, k1 = (resample(c, 500) for c in outlines)
        if np.sign(signed_area(k0)) != np.sign(signed_area(k1)):
            k1 = k1[::-1].copy()
        start = time.perf_counter()
        paths = injective_module._Paths(k0, k1, [0, 500], [True])
        built = time.perf_counter() - start
        start = time.perf_counter()
        paths(np.array([0.5]))
        frame = time.perf_counter() - start
        print(f"500-vertex keys {a} -> {b}: compatible triangulation {1000 * built:.0f} ms "
              f"({paths.mesh.steiner} Steiner points, {len(paths.mesh.triangles)} triangles), "
              f"one frame {1000 * frame:.1f} ms")


def main() -> None:
    count = int(sys.argv[1]) if len(sys.argv) > 1 else 40
    print(f"load average {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    injective_module._Paths(np.array([[0, 0], [1, 0], [0, 1.0]]), np.array([[0, 0], [1, 0], [0, 1.0]]),
                            [0, 3], [True])  # scipy's import, paid once before timing
    pairs = sample(count)
    measure(pairs)
    flubber_row(pairs)
    big_mesh()
    print(f"load average {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
