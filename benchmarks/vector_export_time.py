"""How vector export time grows with the frames of a clip and with the contours of a drawing (run by hand).

1. Frames: two-icon morphs (``mdi/alpha-a`` to ``mdi/alpha-b``, 61 vertices drawn, and ``tabler/sun`` to
   ``mdi/heart``, about 460; the default method) made 121, 481 and 1 921 frames long by their step (5, 20 and
   80 s at 24 fps): wall and CPU seconds of ``tweenrender render A B --step S -o X.json`` against ``-o X.mp4``,
   each a fresh process as a user runs it (the MP4 with its default workers), the values the keyframe fit
   measured (frames × ends × vertices, summed, counted in this process; grows as the work does) and the
   Lottie's size.
2. Contours: one element of n small squares in a grid, each moving and growing (``--method rigid``, 25
   frames), n = 1 000 and 5 000: seconds to write the Lottie file.

Run: ``python benchmarks/vector_export_time.py [--steps 5,20,80] [--contours 1000,5000] [--no-mp4]``
(prints the load average: the two writes of each row run one after the other, so compare them within a row)
"""

from __future__ import annotations

import argparse
import os
import resource
import subprocess
import sys
import tempfile
import time
from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import tweenrender as tr  # noqa: E402
from tweenrender.vector import keyframes  # noqa: E402

ICONS = ROOT / "tests" / "data" / "icons"


def _count_fit(work: Counter[str]) -> None:
    """Add to ``work`` the values each room of the keyframe fit measures: ends × frames × vertices."""
    inner: Callable[..., Any] = keyframes._room

    def counted(values: np.ndarray, a: int, start: np.ndarray, ends: np.ndarray, eases: np.ndarray,
                limit: Any, between: np.ndarray | None = None) -> Any:
        frames = int(max(ends)) - a - 1 if between is None else len(between)
        work["values"] += len(ends) * frames * values.shape[1]
        return inner(values, a, start, ends, eases, limit, *([] if between is None else [between]))

    keyframes._room = counted  # type: ignore[assignment]


def _timed(function: Callable[..., Any], *args: Any) -> float:
    """Seconds ``function(*args)`` takes."""
    start = time.perf_counter()
    function(*args)
    return time.perf_counter() - start


def _command(args: list[str]) -> tuple[float, float]:
    """Wall and CPU seconds (user + sys, its children included) of ``python -m tweenrender ARGS`` run afresh."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "tweenrender", *args], check=True, cwd=ROOT,
                   stdout=subprocess.DEVNULL)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


PAIRS = (("mdi/alpha-a", "mdi/alpha-b"), ("tabler/sun", "mdi/heart"))


def frames_growth(steps: list[float], mp4: bool, folder: Path) -> None:
    work: Counter[str] = Counter()
    _count_fit(work)
    print("pair                          frames vertices  lottie wall/cpu s   mp4 wall/cpu s  wall ratio  fit values   bytes")
    for a, b in PAIRS:
        icons = [str(ICONS / f"{a}.svg"), str(ICONS / f"{b}.svg")]
        for step in steps:
            scene = tr.load_scene(icons, step=step)
            vertices = sum(len(c.points) for c in tr.contours(scene, step / 2))
            work.clear()
            counted = folder / f"counted-{step:g}.json"
            tr.write(scene, counted)
            target = folder / f"morph-{step:g}.json"
            lottie = _command(["render", *icons, "--step", f"{step:g}", "-o", str(target), "-q"])
            video = _command(["render", *icons, "--step", f"{step:g}", "-o", str(folder / "morph.mp4"), "-q"]) \
                if mp4 else (float("nan"), float("nan"))
            count = round(step * scene.fps) + 1
            print(f"{a + ' -> ' + b:28s}  {count:6d} {vertices:8d}  {lottie[0]:7.1f} {lottie[1]:7.1f}   "
                  f"{video[0]:7.1f} {video[1]:7.1f}  {lottie[0] / video[0]:10.2f}  {work['values']:10d}  "
                  f"{target.stat().st_size:6d}")


def _grid(count: int) -> str:
    """A scene of one element of ``count`` squares that move right and grow over one second."""
    side = int(np.ceil(np.sqrt(count)))

    def squares(shift: float, size: float) -> str:
        out = []
        for i in range(count):
            x, y = (i % side) + shift, float(i // side)
            out.append(f"[[{x:.3f},{y:.3f}],[{x + size:.3f},{y:.3f}],[{x + size:.3f},{y + size:.3f}],"
                       f"[{x:.3f},{y + size:.3f}]]")
        return "[" + ",".join(out) + "]"

    return (f'size = [640, 640]\nfps = 24\nview = [-1, -1, {side + 2}, {side + 2}]\nmethod = "rigid"\n'
            f'[[shape]]\nname = "grid"\nfill = "#336699"\n[[shape.key]]\ntime = 0\ncontours = {squares(0, 0.5)}\n'
            f'[[shape.key]]\ntime = 1\ncontours = {squares(0.3, 0.7)}\n')


def contours_growth(counts: list[int], folder: Path) -> None:
    print("contours  lottie s   bytes")
    for count in counts:
        path = folder / f"grid-{count}.toml"
        path.write_text(_grid(count), encoding="utf-8")
        scene = tr.load_scene(path)
        target = folder / f"grid-{count}.json"
        seconds = _timed(tr.write, scene, target)
        print(f"{count:8d}  {seconds:8.1f}  {target.stat().st_size:8d}")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--steps", default="5,20,80")
    parser.add_argument("--contours", default="1000,5000")
    parser.add_argument("--no-mp4", action="store_true")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory(prefix="tweenrender-bench-") as folder:
        frames_growth([float(s) for s in args.steps.split(",") if s], not args.no_mp4, Path(folder))
        contours_growth([int(c) for c in args.contours.split(",") if c], Path(folder))
    print(f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")


if __name__ == "__main__":
    main()
