"""Loading and matching whole drawings: two 40-element drawings, read, flattened and matched.

    python benchmarks/bench_drawings.py [--elements 40] [--repeat 7]

Prints the median time of ``tweenrender.load_scene([a.svg, b.svg])`` (parse, CSS, flatten
every element, match elements and pair contours happen at render time), of building every
shape's segments (contour pairing and vertex correspondence), and of a twemoji pair from the
test data. Target: load and match a 40-element drawing in under 0.2 s.
"""

from __future__ import annotations

import argparse
import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]


def drawing(rng: np.random.Generator, count: int) -> str:
    """An icon-like drawing of ``count`` elements: circles, rounded rects, cubic blobs, strokes."""
    parts = []
    for k in range(count):
        x, y = rng.uniform(10, 90, size=2)
        r = rng.uniform(3, 9)
        colour = "#%02x%02x%02x" % tuple(rng.integers(0, 256, size=3))
        kind = k % 4
        if kind == 0:
            parts.append(f'<circle cx="{x:.2f}" cy="{y:.2f}" r="{r:.2f}" fill="{colour}"/>')
        elif kind == 1:
            parts.append(f'<rect x="{x:.2f}" y="{y:.2f}" width="{2 * r:.2f}" height="{r:.2f}" rx="2" fill="{colour}"/>')
        elif kind == 2:
            parts.append(f'<path d="M{x:.2f} {y:.2f} c {r:.1f} -{r:.1f} {2 * r:.1f} {r:.1f} {r:.1f} {2 * r:.1f} '
                         f's -{2 * r:.1f} 0 -{r:.1f} -{2 * r:.1f}z" fill="{colour}"/>')
        else:
            parts.append(f'<polyline points="{x:.1f},{y:.1f} {x + r:.1f},{y + r:.1f} {x + 2 * r:.1f},{y:.1f}" '
                         f'fill="none" stroke="{colour}" stroke-width="1.5" stroke-linecap="round"/>')
    return f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">{"".join(parts)}</svg>'


def median_time(fn, repeat: int) -> float:  # type: ignore[no-untyped-def]
    times = []
    for _ in range(repeat):
        started = time.perf_counter()
        fn()
        times.append(time.perf_counter() - started)
    return statistics.median(times)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--elements", type=int, default=40)
    parser.add_argument("--repeat", type=int, default=7)
    args = parser.parse_args()
    import tweenrender as tr
    from tweenrender.core.timing.timeline import build_track

    rng = np.random.default_rng(1)
    with tempfile.TemporaryDirectory() as folder:
        a, b = Path(folder) / "a.svg", Path(folder) / "b.svg"
        a.write_text(drawing(rng, args.elements))
        b.write_text(drawing(rng, args.elements))
        scene = tr.load_scene([a, b])  # warm: imports, numba's cache
        for shape in scene.shapes:
            build_track(shape, scene.matching)
        load = median_time(lambda: tr.load_scene([a, b]), args.repeat)
        vertices = sum(len(c.points) for s in scene.shapes for c in s.keys[-1].contours)
        tracks = median_time(lambda: [build_track(s, scene.matching) for s in scene.shapes], args.repeat)
    twemoji = ROOT / "tests" / "data" / "icons" / "twemoji"
    pair = [twemoji / "1f600.svg", twemoji / "1f60e.svg"]
    emoji = median_time(lambda: tr.load_scene(pair), args.repeat)
    print(f"{args.elements} + {args.elements} elements ({len(scene.shapes)} shapes, {vertices} vertices in one key)")
    print(f"  load and match (load_scene)          {1000 * load:8.1f} ms   target < 200 ms: "
          f"{'met' if load < 0.2 else 'NOT met'}")
    print(f"  pair contours and correspond         {1000 * tracks:8.1f} ms   (done once per render)")
    print(f"twemoji 1f600 → 1f60e, load and match   {1000 * emoji:8.1f} ms")


if __name__ == "__main__":
    main()
