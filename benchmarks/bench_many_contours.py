"""One path of many small squares morphing: the work on contours (nesting, pairing, anchors, clearance,
crossings) must grow with the contours, not with their pairs.

    python benchmarks/bench_many_contours.py [--squares 500 2000 5000] [--timeout 300]

For each count, draws ``a.svg`` (one ``<path>`` of that many 2×2 squares on a grid of pitch 4),
``b.svg`` (the same grid shifted by 1) and ``c.svg`` (a quarter as many larger squares: three
quarters of the contours shrink to anchors and are placed clear of the rest), and prints the seconds
of ``tweenrender check a.svg b.svg`` and of ``tweenrender render`` to MP4 of a → b and of a → c.
Target: 5 000 squares render a → b in under a minute on one core.
"""

from __future__ import annotations

import argparse
import math
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def grid(count: int, offset: float = 0.0, side: float = 2.0, pitch: float = 4.0, columns: int = 0) -> str:
    """An SVG of one path holding ``count`` separate squares on a grid."""
    columns = columns or math.ceil(math.sqrt(count))
    squares = " ".join(f"M{(i % columns) * pitch + offset:g} {(i // columns) * pitch + offset:g}"
                       f"h{side:g}v{side:g}h-{side:g}z" for i in range(count))
    width = math.ceil(math.sqrt(count)) * 4.0 + 10
    return (f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {width:g} {width:g}" width="{width:g}" '
            f'height="{width:g}"><path d="{squares}" fill="black"/></svg>')


def timed(arguments: list[str], timeout: float) -> str:
    start = time.perf_counter()
    try:
        subprocess.run([sys.executable, "-m", "tweenrender", *arguments], check=True, timeout=timeout,
                       capture_output=True)
    except subprocess.TimeoutExpired:
        return f"> {timeout:g} s"
    return f"{time.perf_counter() - start:.1f} s"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--squares", type=int, nargs="+", default=[500, 2000, 5000])
    parser.add_argument("--timeout", type=float, default=300.0)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as folder:
        root = Path(folder)
        for count in args.squares:
            a, b, c = root / "a.svg", root / "b.svg", root / "c.svg"
            a.write_text(grid(count))
            b.write_text(grid(count, offset=1.0))
            side = math.ceil(math.sqrt(count))
            c.write_text(grid(count // 4, side=6.0, pitch=8.0, columns=max(1, side // 2)))
            out = str(root / "x.mp4")
            print(f"{count} squares: check a b {timed(['check', str(a), str(b)], args.timeout)}, "
                  f"render a b {timed(['render', str(a), str(b), '-o', out], args.timeout)}, "
                  f"render a c {timed(['render', str(a), str(c), '-o', out], args.timeout)}", flush=True)


if __name__ == "__main__":
    main()
