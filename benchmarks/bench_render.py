"""Rendering against the encoder's own limit (run by hand, not in CI).

    python benchmarks/bench_render.py [--rounds 3] [--quick]

Prints, in one run:

1. the target: ``tweenrender render`` of a busy 1080p24 scene (24 shapes of 40
   vertices, 5 s) straight to H.264, against the same bundled ffmpeg encoding
   the very same frames, pre-rendered to a raw RGB file, with the same settings
   (ratio of wall times and of file sizes; the best of ``--rounds`` interleaved
   runs each, since other work on the machine only adds time);
2. frames/s at 720p, 1080p and 4K: drawing alone, and rendering to MP4;
3. ``--workers 1`` against ``--workers 2`` for MP4 and PNG output;
4. peak memory of the whole process tree (tweenrender + ffmpeg, RSS sampled
   from /proc every 20 ms) for 5 s and 20 s clips;
5. the machine: ``nproc``, the CPU model, the load average.
"""

from __future__ import annotations

import argparse
import os
import platform
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(HERE))

from make_busy import busy_scene  # noqa: E402

TWEENRENDER = [sys.executable, "-m", "tweenrender"]


def _tree(pid: int) -> list[int]:
    """``pid`` and all its descendants (Linux /proc)."""
    found, stack = [], [pid]
    while stack:
        current = stack.pop()
        found.append(current)
        try:
            for task in os.listdir(f"/proc/{current}/task"):
                with open(f"/proc/{current}/task/{task}/children") as handle:
                    stack.extend(int(c) for c in handle.read().split())
        except OSError:
            pass
    return found


def _rss_kib(pid: int) -> int:
    try:
        with open(f"/proc/{pid}/status") as handle:
            for line in handle:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1])
    except OSError:
        pass
    return 0


def run_measured(command: list[str]) -> tuple[float, float, int, int]:
    """Run ``command``: (wall seconds, CPU seconds of it and its children, peak RSS in MiB of the
    whole process tree and of the command's own process)."""
    before = os.times()
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=ROOT)
    peak = own = 0
    done = threading.Event()

    def sample() -> None:
        nonlocal peak, own
        while not done.is_set():
            peak = max(peak, sum(_rss_kib(p) for p in _tree(process.pid)))
            own = max(own, _rss_kib(process.pid))
            done.wait(0.02)

    sampler = threading.Thread(target=sample, daemon=True)
    sampler.start()
    _, err = process.communicate()
    wall = time.perf_counter() - start
    done.set()
    sampler.join()
    after = os.times()
    if process.returncode != 0:
        raise SystemExit(f"{' '.join(command)} failed: {err.decode()[-500:]}")
    cpu = (after.children_user - before.children_user) + (after.children_system - before.children_system)
    return wall, cpu, peak // 1024, own // 1024


def write_scene(folder: Path, seconds: float, name: str) -> Path:
    path = folder / name
    path.write_text(busy_scene(seconds))
    return path


def prerender_raw(scene: Path, raw: Path) -> tuple[int, float]:
    """Every frame of ``scene`` as raw RGB in ``raw``: (frames, seconds spent drawing)."""
    import numpy as np

    from tweenrender.pipeline.job import RenderJob
    from tweenrender.pipeline.workers import frame_stream
    from tweenrender.scenefile import load_scene

    job = RenderJob(load_scene(scene))
    count, drawing = 0, 0.0
    with open(raw, "wb") as handle:
        stream = frame_stream(job)
        while True:
            start = time.perf_counter()
            frame = next(stream, None)
            drawing += time.perf_counter() - start
            if frame is None:
                break
            handle.write(np.ascontiguousarray(frame[..., :3]).data)
            count += 1
    return count, drawing


def target_ratio(folder: Path, rounds: int) -> None:
    from tweenrender.encode.sinks import ffmpeg_command

    scene = write_scene(folder, 5.0, "busy.toml")
    raw = folder / "busy.rgb"
    frames, drawing = prerender_raw(scene, raw)
    alone_out, render_out = folder / "alone.mp4", folder / "render.mp4"
    alone_cmd = ffmpeg_command("mp4", 1920, 1080, 24, str(raw), str(alone_out), "rgb24")
    render_cmd = [*TWEENRENDER, "render", str(scene), "-o", str(render_out), "-q"]
    alone, rendered = [], []
    for _ in range(rounds):  # interleaved, so a burst of other work hits both alike
        alone.append(run_measured(alone_cmd))
        rendered.append(run_measured(render_cmd))
    a, r = min(alone), min(rendered)
    size_a, size_r = alone_out.stat().st_size, render_out.stat().st_size
    raw.unlink()
    print(f"## Target: busy 1080p24 scene, 24 shapes x 40 vertices, {frames} frames, H.264 CRF 18 medium")
    print(f"drawing alone (in-process, no encode)   {frames / drawing:7.1f} frames/s  ({1000 * drawing / frames:.1f} ms/frame)")
    print(f"ffmpeg alone from raw RGB (best of {rounds})   {a[0]:7.2f} s wall  {a[1]:6.2f} s CPU  {frames / a[0]:6.1f} frames/s")
    print(f"tweenrender render (best of {rounds})         {r[0]:7.2f} s wall  {r[1]:6.2f} s CPU  {frames / r[0]:6.1f} frames/s")
    print(f"  all rounds, ffmpeg alone: {', '.join(f'{x[0]:.2f}' for x in alone)} s; "
          f"render: {', '.join(f'{x[0]:.2f}' for x in rendered)} s")
    print(f"time ratio render / encode-only          {r[0] / a[0]:7.3f}   (target <= 1.3)")
    print(f"CPU ratio render / encode-only           {r[1] / a[1]:7.3f}")
    print(f"file size: render {size_r / 1e6:.3f} MB, encode-only {size_a / 1e6:.3f} MB, ratio {size_r / size_a:.3f}"
          "   (target <= 1.5)")
    print()


def frame_rates(folder: Path, quick: bool) -> None:
    from tweenrender.pipeline.job import RenderJob
    from tweenrender.pipeline.workers import frame_stream
    from tweenrender.scenefile import load_scene

    scene = write_scene(folder, 5.0, "busy.toml")
    print("## Frames/s by size (busy scene; drawing alone in-process, and `render` to MP4 including start-up)")
    print("| size | frames | drawing frames/s | render to MP4 frames/s |")
    print("|---|---|---|---|")
    for label, (w, h), count in (("720p", (1280, 720), 121), ("1080p", (1920, 1080), 121),
                                 ("4K", (3840, 2160), 24 if quick else 48)):
        job = RenderJob(load_scene(scene), size=(w, h), frames=range(count))
        best = float("inf")
        for _ in range(2):
            start = time.perf_counter()
            for _frame in frame_stream(job):
                pass
            best = min(best, time.perf_counter() - start)
        wall = min(run_measured([*TWEENRENDER, "render", str(scene), "-o", str(folder / "size.mp4"), "-q",
                                 "--size", f"{w}x{h}", "--frames", f"0:{count}"])[0] for _ in range(2))
        print(f"| {label} {w}x{h} | {count} | {count / best:.1f} | {count / wall:.1f} |")
    print()


def workers(folder: Path, quick: bool) -> None:
    scene = write_scene(folder, 5.0, "busy.toml")
    count = 48 if quick else 121
    print(f"## --workers (busy 1080p scene, {count} frames, best of 2 wall seconds)")
    print("| output | --workers 1 | --workers 2 |")
    print("|---|---|---|")
    for fmt, out in (("mp4", "w.mp4"), ("png", "w-frames")):
        walls = []
        for n in (1, 2):
            walls.append(min(run_measured([*TWEENRENDER, "render", str(scene), "-o", str(folder / out), "-q",
                                           "--frames", f"0:{count}", "--workers", str(n)])[0] for _ in range(2)))
        print(f"| {fmt} | {walls[0]:.2f} s | {walls[1]:.2f} s |")
    print()


def memory(folder: Path, quick: bool) -> None:
    print("## Peak memory, process tree (tweenrender + ffmpeg), 1080p24 busy scene to MP4")
    print("| clip | frames | wall s | peak RSS, tree MiB | peak RSS, tweenrender alone MiB |")
    print("|---|---|---|---|---|")
    for seconds in ((5.0, 10.0) if quick else (5.0, 20.0)):
        scene = write_scene(folder, seconds, f"busy{seconds:g}.toml")
        wall, _, peak, own = run_measured([*TWEENRENDER, "render", str(scene), "-o", str(folder / "mem.mp4"),
                                           "-q"])
        print(f"| {seconds:g} s | {int(seconds * 24) + 1} | {wall:.1f} | {peak} | {own} |")
    print()


def machine() -> None:
    model = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                  if line.startswith("model name")), platform.processor())
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    load = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"## Machine: nproc {cpus}, {model}, Python {platform.python_version()}, load average {load}")
    print()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3, help="interleaved runs of the target comparison")
    parser.add_argument("--quick", action="store_true", help="fewer frames for 4K, workers and memory")
    parser.add_argument("--only", choices=("target", "sizes", "workers", "memory"))
    args = parser.parse_args()
    machine()
    with tempfile.TemporaryDirectory(prefix="tweenrender-bench-") as name:
        folder = Path(name)
        if args.only in (None, "target"):
            target_ratio(folder, args.rounds)
        if args.only in (None, "sizes"):
            frame_rates(folder, args.quick)
        if args.only in (None, "workers"):
            workers(folder, args.quick)
        if args.only in (None, "memory"):
            memory(folder, args.quick)
    machine()


if __name__ == "__main__":
    main()
