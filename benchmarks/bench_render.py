"""Rendering against the encoder's own limit (run by hand, not in CI).

    python benchmarks/bench_render.py [--rounds 3] [--only ...]

Prints, in one run, each result with the load average at the time:

1. the stroked, detailed scene (100 shapes x 500 vertices, 2 px outline,
   1080p24, 5 s) and the encoder-bound busy scene (24 shapes of 40 vertices):
   ``tweenrender render`` with workers chosen automatically and with
   ``--workers 1``, against the same bundled ffmpeg encoding the very same
   frames, pre-rendered to a raw RGB file, with the same settings
   ("encode-only"; ffmpeg then converts to yuv420p itself), and from the
   yuv420p planes a render now sends it; ``--rounds`` interleaved runs, every
   ratio paired within a round and given as min / median; the floor is work
   over cores in CPU seconds alone ((encoder CPU + drawing CPU) / cores), so
   other load on the machine stretches the walls compared with it, never the
   floor itself: the load average is printed after each round;
2. where a stroked frame's drawing time goes, idea by idea;
3. peak memory of the whole process tree (tweenrender + ffmpeg, RSS of every
   descendant sampled from /proc every 20 ms) at 1080p and 4K, opaque frames
   sent as yuv420p made here (now) against RGB converted by ffmpeg (before),
   interleaved: memory, time, file size, the conversion's cost a frame, and the
   decoded pictures against the drawn ones; then x264 with today's tuning
   against its own defaults (time, size, memory);
   ``--only ffmpeg``: ffmpeg alone on those yuv420p frames, with today's
   options and each option tried for memory (queues, sliced threads, glibc's
   mmap threshold, no encoder at all);
4. ``--cluster local:2`` against a local render;
5. a two-icon morph, 1 s of 720p MP4 (wall, CPU, the heavy modules it loads;
   manim's wall on it when manim is installed, else said so);
6. the preview's save-to-frame latency on three shipped scenes
   (``benchmarks/bench_preview.py`` measures every scene);
7. the machine: ``nproc``, the CPU model, Python, the load average.

The correspondence search's growth in time and memory is measured apart:
``benchmarks/bench_correspond_memory.py``.
"""

from __future__ import annotations

import argparse
import os
import platform
import shutil
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

from make_busy import busy_scene, stroked_scene  # noqa: E402

TWEENRENDER = [sys.executable, "-m", "tweenrender"]
RGB_PIPE = [sys.executable, "-c", "import sys, tweenrender.encode.sinks as s; s.sends_yuv420 = lambda *a, **k: False; "
            "from tweenrender.cli.main import main; sys.exit(main())"]
"""``tweenrender`` as it was before opaque frames went to ffmpeg as yuv420p: RGB (skia's BGRA) through
the pipe, converted by ffmpeg."""


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


def run_measured(command: list[str], env: dict[str, str] | None = None) -> tuple[float, float, int, int]:
    """Run ``command`` (with ``env`` added to the environment): (wall seconds, CPU seconds of it and its
    children, peak RSS in MiB of the whole process tree and of the command's own process)."""
    before = os.times()
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, cwd=ROOT,
                               env={**os.environ, **(env or {})})
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


def prerender_raw(scene: Path, planes_file: Path, raw: Path | None = None) -> tuple[int, float]:
    """Every frame of ``scene`` as the very yuv420p planes a render sends ffmpeg (encode.yuv420) in
    ``planes_file`` and, if ``raw`` is given, as raw RGB there: (frames, CPU seconds spent drawing)."""
    import numpy as np

    from tweenrender.encode.yuv420 import Yuv420
    from tweenrender.plan.job import RenderJob
    from tweenrender.pipeline.workers import frame_stream
    from tweenrender.scenefile import load_scene

    job = RenderJob(load_scene(scene))
    planes = Yuv420(*job.frame_size, "rgba")
    count, drawing = 0, 0.0
    with open(planes_file, "wb") as yuv, open(raw or os.devnull, "wb") as rgb:
        stream = frame_stream(job)
        while True:
            start = time.process_time()  # CPU seconds: other load on the machine does not stretch them
            frame = next(stream, None)
            drawing += time.process_time() - start
            if frame is None:
                break
            if raw is not None:
                rgb.write(np.ascontiguousarray(frame[..., :3]).data)
            yuv.write(planes(frame).data)
            count += 1
    return count, drawing


def load() -> str:
    return f"load {os.getloadavg()[0]:.2f}"


def median(values: list[float]) -> float:
    ordered = sorted(values)
    middle = len(ordered) // 2
    return ordered[middle] if len(ordered) % 2 else 0.5 * (ordered[middle - 1] + ordered[middle])


def _min_median(values: list[float], digits: int = 3) -> str:
    return f"{min(values):.{digits}f} / {median(values):.{digits}f}"


def against_encoder(folder: Path, name: str, text: str, rounds: int) -> None:
    """Encode-only, render (auto workers) and render --workers 1 of one scene, interleaved.

    The floor is work over cores, in CPU seconds only: (the encoder's CPU on these frames + the
    drawing's CPU) / cores, no render that draws and encodes them here can take less wall time.
    Every ratio pairs runs of the same round (so a burst of other load stretches both sides), and
    is given as min / median over the rounds, with the load average after each round.
    """
    from tweenrender.encode.sinks import ffmpeg_command

    scene = folder / f"{name}.toml"
    scene.write_text(text)
    raw, planes = folder / f"{name}.rgb", folder / f"{name}.yuv"
    frames, drawing = prerender_raw(scene, planes, raw)
    outputs = {key: folder / f"{name}-{key}.mp4" for key in ("alone", "planes", "auto", "one")}
    commands = {
        "alone": ffmpeg_command("mp4", 1920, 1080, 24, str(raw), str(outputs["alone"]), "rgb24"),
        "planes": ffmpeg_command("mp4", 1920, 1080, 24, str(planes), str(outputs["planes"]), "yuv420p"),
        "auto": [*TWEENRENDER, "render", str(scene), "-o", str(outputs["auto"]), "-q"],
        "one": [*TWEENRENDER, "render", str(scene), "-o", str(outputs["one"]), "-q", "--workers", "1"],
    }
    runs: dict[str, list[tuple[float, float, int, int]]] = {key: [] for key in commands}
    loads = []
    for _ in range(rounds):  # interleaved, so a burst of other work hits all alike
        for key, command in commands.items():
            runs[key].append(run_measured(command))
        loads.append(os.getloadavg()[0])
    raw.unlink()
    planes.unlink()
    from tweenrender.plan.job import RenderJob
    from tweenrender.pipeline.workers import default_workers, measure_cost
    from tweenrender.scenefile import load_scene

    job = RenderJob(load_scene(scene))
    cost = measure_cost(job, "mp4")
    chosen = default_workers(job, "mp4", cost=cost)
    cores = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count() or 1
    encoder_cpu = median([r[1] for r in runs["planes"]])
    floor = (encoder_cpu + drawing) / cores
    print(f"## {name}: {frames} frames of 1080p24, H.264 CRF 18 medium; {rounds} interleaved rounds")
    print(f"drawing, in-process: {1000 * drawing / frames:.1f} CPU ms/frame; the encoder on the yuv420p frames: "
          f"{1000 * encoder_cpu / frames:.1f} CPU ms/frame; measured here as a render measures it: draw "
          f"{1000 * cost.draw:.1f} ms, encoder {1000 * cost.encode:.1f} CPU ms -> {chosen} worker(s) "
          f"(each render measures for itself, so near the balance it may choose otherwise)")
    print(f"floor on {cores} cores: (encoder {encoder_cpu:.2f} CPU s + drawing {drawing:.2f} CPU s) / {cores} "
          f"= {floor:.2f} s")
    print("| run | wall s (min / median) | all rounds | CPU s (median) | peak tree MiB (max) | "
          "/ encode-only RGB, same round (min / median) | / floor (min / median) |")
    print("|---|---|---|---|---|---|---|")
    for key, label in (("alone", "encode-only: ffmpeg from raw RGB (it converts)"),
                       ("planes", "encode-only: ffmpeg from the raw yuv420p a render sends"),
                       ("auto", "render, auto workers"), ("one", "render --workers 1")):
        walls = [r[0] for r in runs[key]]
        paired = [r[0] / a[0] for r, a in zip(runs[key], runs["alone"])]
        print(f"| {label} | {_min_median(walls, 2)} | {', '.join(f'{w:.2f}' for w in walls)} | "
              f"{median([r[1] for r in runs[key]]):.2f} | {max(r[2] for r in runs[key])} | "
              f"{_min_median(paired)} | {_min_median([w / floor for w in walls])} |")
    auto_one = [a[0] / o[0] for a, o in zip(runs["auto"], runs["one"])]
    print(f"auto / --workers 1, same round: {_min_median(auto_one)}; file size render / encode-only: "
          f"{outputs['auto'].stat().st_size / outputs['alone'].stat().st_size:.4f}; "
          f"load averages after each round: {', '.join(f'{x:.2f}' for x in loads)}")
    print()


def stroke_costs(folder: Path) -> None:
    """Per-frame drawing time of the stroked scene, idea by idea (same polygons, same surface)."""
    import numpy as np
    import skia

    from tweenrender.plan.job import Frames, RenderJob
    from tweenrender.raster.round_stroke import stroke_contours
    from tweenrender.raster.surface import polygon_path
    from tweenrender.scenefile import load_scene

    scene = folder / "stroked.toml"
    scene.write_text(stroked_scene(5.0))
    job = RenderJob(load_scene(scene))
    frames = Frames(job, "bgra")
    frames(0)
    count = 12
    composer = frames.composer
    raster, view = composer.raster, composer.viewport
    polygons = [[at.contours[0] for at in frames.frame_shapes(None, i * 10)] for i in range(count)]
    pixels = [[view.to_pixels(p) for p in ps] for ps in polygons]
    paths = [[polygon_path(p) for p in ps] for ps in pixels]
    ink = np.array([80.0, 43.0, 29.0, 255.0])  # premultiplied BGRA
    stroke_contours(raster.bgra(), pixels[0][:1], [True], 2.0, ink)  # loaded before timing

    def paint(**settings: object) -> skia.Paint:
        return skia.Paint(**{"AntiAlias": True, "Color": skia.ColorSetARGB(255, 29, 43, 80), **settings})

    stroke = paint(Style=skia.Paint.kStroke_Style, StrokeWidth=2.0, StrokeJoin=skia.Paint.kRound_Join,
                   StrokeCap=skia.Paint.kRound_Cap)
    fill, aliased = paint(), paint(AntiAlias=False)
    geometry = []
    for ps in paths:
        row = []
        for path in ps:
            out = skia.Path()
            stroke.getFillPath(path, out)
            row.append(out)
        geometry.append(row)

    def timed(draw: object, source: list = paths) -> float:
        start = time.perf_counter()
        for row in source:
            raster.clear(job.scene.background)
            for path in row:
                draw(path)  # type: ignore[operator]
        return 1000 * (time.perf_counter() - start) / count

    def with_join(join: skia.Paint.Join) -> skia.Paint:
        other = skia.Paint(stroke)
        other.setStrokeJoin(join)
        return other

    miter, bevel = with_join(skia.Paint.kMiter_Join), with_join(skia.Paint.kBevel_Join)
    both = skia.Paint(stroke)
    both.setStyle(skia.Paint.kStrokeAndFill_Style)
    start = time.perf_counter()
    for ps in polygons:
        for polygon in ps:
            polygon_path(view.to_pixels(polygon))
    building = 1000 * (time.perf_counter() - start) / count
    rows = [
        ("building the paths (to pixels, numpy -> skia.Path)", building),
        ("fill, antialiased", timed(lambda p: raster.canvas.drawPath(p, fill))),
        ("fill, aliased (hidden under an opaque stroke >= 2 px)", timed(lambda p: raster.canvas.drawPath(p, aliased))),
        ("stroke, round joins (skia's stroker each frame)", timed(lambda p: raster.canvas.drawPath(p, stroke))),
        ("stroke, miter joins", timed(lambda p: raster.canvas.drawPath(p, miter))),
        ("stroke, bevel joins", timed(lambda p: raster.canvas.drawPath(p, bevel))),
        ("stroke geometry only (getFillPath, no drawing)", timed(lambda p: stroke.getFillPath(p, skia.Path()))),
        ("stroke geometry cached, filled (a cached skia.Path)", timed(lambda p: raster.canvas.drawPath(p, fill), geometry)),
        ("fill and stroke in one pass (kStrokeAndFill, one colour)", timed(lambda p: raster.canvas.drawPath(p, both))),
        ("fill + stroke as drawn before", timed(lambda p: (raster.canvas.drawPath(p, fill),
                                                          raster.canvas.drawPath(p, stroke)))),
        ("fill + stroke, aliased fill under skia's stroke",
         timed(lambda p: (raster.canvas.drawPath(p, aliased), raster.canvas.drawPath(p, stroke)))),
        ("stroke from distances (raster/round_stroke.py, compiled)",
         timed(lambda p: stroke_contours(raster.bgra(), [p], [True], 2.0, ink), pixels)),
        ("fill + stroke as drawn now (aliased fill under the compiled stroke)",
         timed(lambda p: (raster.canvas.drawPath(polygon_path(p), aliased),
                          stroke_contours(raster.bgra(), [p], [True], 2.0, ink)), pixels)),
    ]
    lengths = np.concatenate([np.hypot(*np.diff(view.to_pixels(p), axis=0).T) for p in polygons[0]])
    print(f"## Where a stroked frame's drawing goes (100 shapes x 500 vertices, 2 px outline, 1080p; {load()})")
    print(f"segments at 1080p: median {np.median(lengths):.2f} px, 5th percentile {np.percentile(lengths, 5):.2f} px "
          f"(so little is below a pixel to thin)")
    print("| idea | ms per frame |")
    print("|---|---|")
    for label, ms in rows:
        print(f"| {label} | {ms:.1f} |")
    print()


def conversion_ms(scene: Path, size: tuple[int, int], count: int = 20) -> float:
    """Milliseconds a ``size`` frame of ``scene`` takes to become yuv420p planes in this process."""
    from tweenrender.encode.yuv420 import Yuv420
    from tweenrender.plan.job import Frames, RenderJob
    from tweenrender.scenefile import load_scene

    picture = Frames(RenderJob(load_scene(scene), size=size), "bgra")(12)
    convert = Yuv420(*size)
    convert(picture)
    start = time.perf_counter()
    for _ in range(count):
        convert(picture)
    return 1000 * (time.perf_counter() - start) / count


def decoded_errors(scene: Path, videos: list[Path], frames: int) -> list[tuple[float, float]]:
    """Each of ``videos`` (1080p renders of ``scene``) decoded to RGB against the frames drawn: mean and 99th
    percentile of the absolute difference, over every channel of every 10th frame."""
    import imageio_ffmpeg
    import numpy as np

    from tweenrender.plan.job import Frames, RenderJob
    from tweenrender.scenefile import load_scene

    draw = Frames(RenderJob(load_scene(scene)))
    readers = [imageio_ffmpeg.read_frames(str(v)) for v in videos]
    width, height = next(readers[0])["size"]
    for reader in readers[1:]:
        next(reader)
    errors: list[list[np.ndarray]] = [[] for _ in videos]
    for index in range(frames):
        pictures = [np.frombuffer(next(r), np.uint8).reshape(height, width, 3) for r in readers]
        if index % 10 == 0:
            drawn = draw(index)[..., :3].astype(np.int16)
            for kept, picture in zip(errors, pictures):
                kept.append(np.abs(picture.astype(np.int16) - drawn).ravel())
    for reader in readers:
        reader.close()
    every = [np.concatenate(kept) for kept in errors]
    return [(float(e.mean()), float(np.percentile(e, 99))) for e in every]


def planes_against_ffmpeg(scene: Path, size: tuple[int, int] = (1920, 1080)) -> str:
    """One drawn frame of ``scene`` made yuv420p here and by ffmpeg's own conversion (swscale, its defaults):
    per plane, the mean and largest absolute difference and the share of samples that differ."""
    import numpy as np

    from tweenrender.encode.sinks import ffmpeg_exe
    from tweenrender.encode.yuv420 import Yuv420
    from tweenrender.plan.job import Frames, RenderJob
    from tweenrender.scenefile import load_scene

    width, height = size
    picture = Frames(RenderJob(load_scene(scene), size=size), "bgra")(60)
    ours = Yuv420(width, height)(picture)
    done = subprocess.run([ffmpeg_exe(), "-v", "error", "-f", "rawvideo", "-pix_fmt", "bgra", "-s", f"{width}x{height}",
                           "-i", "-", "-f", "rawvideo", "-pix_fmt", "yuv420p", "-"],
                          input=picture.tobytes(), capture_output=True, check=True)
    theirs = np.frombuffer(done.stdout, np.uint8)
    area = width * height
    said = []
    for name, part in (("Y", slice(0, area)), ("U", slice(area, area * 5 // 4)), ("V", slice(area * 5 // 4, None))):
        difference = np.abs(ours[part].astype(int) - theirs[part].astype(int))
        said.append(f"{name} mean {difference.mean():.3f}, max {difference.max()}, "
                    f"{100 * (difference > 0).mean():.1f} % differ")
    return "; ".join(said)


def memory(folder: Path, rounds: int) -> None:
    from tweenrender.encode.sinks import ffmpeg_command, x264_tuning

    scene = folder / "busy.toml"
    scene.write_text(busy_scene(5.0))
    ways = {"before": RGB_PIPE, "now": TWEENRENDER}
    print(f"## Peak memory of the process tree (tweenrender + ffmpeg), busy scene to MP4, default settings; "
          f"RGB to ffmpeg (before) against yuv420p made here (now), {rounds} interleaved rounds")
    print("| size | frames | frames sent as | wall s (median) | CPU s (median) | peak tree MiB (median; all) "
          "| tweenrender alone MiB | file bytes | load |")
    print("|---|---|---|---|---|---|---|---|---|")
    outputs: dict[str, Path] = {}
    for label, size, count in (("1080p", "1920x1080", 121), ("4K", "3840x2160", 48)):
        runs: dict[str, list[tuple[float, float, int, int]]] = {way: [] for way in ways}
        for _ in range(rounds):  # interleaved, so a burst of other work hits both alike
            for way, command in ways.items():
                outputs[way + label] = folder / f"{way}-{label}.mp4"
                runs[way].append(run_measured([*command, "render", str(scene), "-o", str(outputs[way + label]),
                                               "-q", "--size", size, "--frames", f"0:{count}"]))
        for way, sent in (("before", "bgra, ffmpeg converts"), ("now", "yuv420p")):
            done = runs[way]
            peaks = ", ".join(str(r[2]) for r in done)
            print(f"| {label} | {count} | {sent} | {median([r[0] for r in done]):.2f} | "
                  f"{median([r[1] for r in done]):.2f} | {median([r[2] for r in done]):.0f} ({peaks}) | "
                  f"{max(r[3] for r in done)} | {outputs[way + label].stat().st_size} | {load()} |")
        ratio = {i: median([r[i] for r in runs["now"]]) / median([r[i] for r in runs["before"]]) for i in range(3)}
        sizes = outputs["now" + label].stat().st_size / outputs["before" + label].stat().st_size
        print(f"| {label} now / before | | | {ratio[0]:.3f} | {ratio[1]:.3f} | {ratio[2]:.3f} | | {sizes:.4f} | |")
    width_height = [(1920, 1080), (3840, 2160)]
    costs = ", ".join(f"{w}x{h} {conversion_ms(scene, (w, h)):.1f} ms" for w, h in width_height)
    print(f"converting a drawn frame to yuv420p here: {costs} a frame ({load()})")
    print(f"planes of a 1080p frame, made here against ffmpeg's conversion: {planes_against_ffmpeg(scene)}")
    (before, before_p99), (now, now_p99) = decoded_errors(scene, [outputs["before1080p"], outputs["now1080p"]], 121)
    print(f"1080p decoded against the frames drawn (every 10th frame, RGB): before mean {before:.3f} "
          f"(99th percentile {before_p99:.0f}), now mean {now:.3f} (99th percentile {now_p99:.0f})")
    print()
    stroked = folder / "stroked.toml"
    stroked.write_text(stroked_scene(5.0))
    print(f"## Peak memory of the process tree, stroked scene (100 x 500 vertices, compiled round stroke) to MP4, "
          f"default settings (auto workers), {rounds} rounds")
    print("| size | frames | wall s (median) | peak tree MiB (max; all) | tweenrender alone MiB (max) | load |")
    print("|---|---|---|---|---|---|")
    for label, size, count in (("1080p", "1920x1080", 121), ("4K", "3840x2160", 48)):
        done = [run_measured([*TWEENRENDER, "render", str(stroked), "-o", str(folder / f"stroked-{label}.mp4"), "-q",
                              "--size", size, "--frames", f"0:{count}"]) for _ in range(rounds)]
        print(f"| {label} | {count} | {median([r[0] for r in done]):.2f} | {max(r[2] for r in done)} "
              f"({', '.join(str(r[2]) for r in done)}) | {max(r[3] for r in done)} | {load()} |")
    print()
    raw = folder / "busy.yuv"
    frames, _ = prerender_raw(scene, raw)
    print(f"## x264 tuned (threads and lookahead from the machine) vs x264's defaults, encode-only, {frames} "
          "frames of 1080p, medians of 3 interleaved")
    tuned = ffmpeg_command("mp4", 1920, 1080, 24, str(raw), str(folder / "tuned.mp4"), "yuv420p")
    options = x264_tuning(1920, 1080)
    start = tuned.index(options[0])
    plain = tuned[:start] + tuned[start + len(options):]
    plain[-1] = str(folder / "plain.mp4")
    results: dict[str, list[tuple[float, float, int, int]]] = {"plain": [], "tuned": []}
    for _ in range(3):
        results["plain"].append(run_measured(plain))
        results["tuned"].append(run_measured(tuned))
    raw.unlink()
    for key, label in (("plain", "x264 defaults"), ("tuned", " ".join(options))):
        wall = median([r[0] for r in results[key]])
        cpu = median([r[1] for r in results[key]])
        peak = max(r[2] for r in results[key])
        size = (folder / f"{key}.mp4").stat().st_size
        print(f"{label:60s} wall {wall:6.2f} s  CPU {cpu:6.2f} s  peak {peak} MiB  size {size}")
    ratio_wall = median([r[0] for r in results["tuned"]]) / median([r[0] for r in results["plain"]])
    ratio_size = (folder / "tuned.mp4").stat().st_size / (folder / "plain.mp4").stat().st_size
    print(f"tuned / defaults: wall {ratio_wall:.3f}, size {ratio_size:.4f}; {load()}")
    print()


def prerender_yuv420(scene: Path, raw: Path, size: tuple[int, int], count: int) -> None:
    """The first ``count`` frames of ``scene`` at ``size``, as the renderer now sends them (yuv420p), in ``raw``."""
    from tweenrender.encode.yuv420 import Yuv420
    from tweenrender.plan.job import RenderJob
    from tweenrender.pipeline.workers import frame_stream
    from tweenrender.scenefile import load_scene

    convert = Yuv420(*size)
    with open(raw, "wb") as handle:
        for frame in frame_stream(RenderJob(load_scene(scene), size=size, frames=range(count)), layout="bgra"):
            handle.write(convert(frame).data)


def ffmpeg_options(folder: Path, rounds: int) -> None:
    """ffmpeg alone encoding the busy scene's yuv420p frames from a file, with today's options and with each
    other option tried for memory: peak RSS, time and file size, interleaved."""
    from tweenrender.encode.sinks import ffmpeg_command, x264_tuning

    scene = folder / "busy.toml"
    scene.write_text(busy_scene(5.0))
    print(f"## ffmpeg alone on yuv420p frames (what renders send now): options tried for memory, medians of "
          f"{rounds} interleaved ({load()})")
    print("| size | ffmpeg | wall s | CPU s | peak MiB (all rounds) | file size / today's |")
    print("|---|---|---|---|---|---|")
    for label, (width, height), count in (("1080p", (1920, 1080), 121), ("4K", (3840, 2160), 48)):
        raw = folder / f"busy-{label}.yuv"
        prerender_yuv420(scene, raw, (width, height), count)
        today = ffmpeg_command("mp4", width, height, 24, str(raw), str(folder / "today.mp4"), "yuv420p")
        lookahead = today.index("-x264-params") + 1
        sliced = list(today)
        sliced[lookahead] += ":sliced-threads=1"
        output = today.index("-an") + 1
        queues = [*today[:output], "-max_muxing_queue_size", "1", *today[output:]]
        source = today.index("-f")
        variants: dict[str, tuple[list[str], dict[str, str]]] = {
            "today's options": (today, {}),
            "input -thread_queue_size 1": ([*today[:source], "-thread_queue_size", "1", *today[source:]], {}),
            "-max_muxing_queue_size 1": (queues, {}),
            "x264 sliced-threads=1": (sliced, {}),
            "MALLOC_MMAP_THRESHOLD_=1048576": (today, {"MALLOC_MMAP_THRESHOLD_": str(1 << 20)}),
            "no encoder (-c:v rawvideo -f null)": ([*today[:output], "-c:v", "rawvideo", "-f", "null", "-"], {}),
        }
        runs: dict[str, list[tuple[float, float, int, int]]] = {name: [] for name in variants}
        sizes: dict[str, int] = {}
        for _ in range(rounds):
            for name, (command, env) in variants.items():
                target = folder / "option.mp4"
                if command[-1] != "-":
                    command = [*command[:-1], str(target)]
                runs[name].append(run_measured(command, env))
                sizes[name] = target.stat().st_size if command[-1] != "-" else 0
        raw.unlink()
        base = sizes["today's options"]
        for name, done in runs.items():
            ratio = f"{sizes[name] / base:.4f}" if sizes[name] else "-"
            peaks = ", ".join(str(r[2]) for r in done)
            print(f"| {label} | {name} | {median([r[0] for r in done]):.2f} | {median([r[1] for r in done]):.2f} | "
                  f"{median([r[2] for r in done]):.0f} ({peaks}) | {ratio} |")
    print(f"({x264_tuning(1920, 1080)} at 1080p; {load()})")
    print()


def cluster(folder: Path, rounds: int) -> None:
    scene = folder / "busy.toml"
    scene.write_text(busy_scene(5.0))
    try:
        import distributed  # noqa: F401
    except ImportError:
        print("## Cluster: skipped, dask.distributed is not installed (pip install '.[cluster]')\n")
        return
    local, remote = [], []
    for _ in range(rounds):
        local.append(run_measured([*TWEENRENDER, "render", str(scene), "-o", str(folder / "local.mp4"), "-q"])[0])
        remote.append(run_measured([*TWEENRENDER, "render", str(scene), "-o", str(folder / "cluster.mp4"), "-q",
                                    "--cluster", "local:2"])[0])
    print(f"## Cluster: busy scene, 121 frames of 1080p to MP4, medians of {rounds} interleaved ({load()})")
    print(f"local render (auto workers)           {median(local):6.2f} s   ({', '.join(f'{x:.2f}' for x in local)})")
    print(f"--cluster local:2 (start-up included)  {median(remote):6.2f} s   ({', '.join(f'{x:.2f}' for x in remote)})")
    print(f"ratio cluster / local: {median(remote) / median(local):.3f}")
    print()


def manim_command(manim: str | None, folder: Path) -> list[str] | None:
    """The command that renders ``manim_morph.py``'s morph with ``manim`` (a path, else ``manim`` on the PATH)
    into ``folder``, or None when there is none."""
    executable = manim or shutil.which("manim")
    if executable is None:
        return None
    media = folder / "manim"
    return [executable, "render", "-r", "1280,720", "--frame_rate", "24", "--disable_caching", "--progress_bar",
            "none", "-v", "WARNING", "--media_dir", str(media), "-o", "icons",
            str(Path(__file__).resolve().parent / "manim_morph.py"), "IconMorph"]


def icon_morph(folder: Path, rounds: int, manim: str | None = None) -> None:
    """A two-icon morph, 1 s of 720p MP4: wall and CPU of the whole command, what it imported, and
    manim's wall on the same motion (``manim_morph.py``), interleaved, when a manim is given or on the PATH."""
    icons = ROOT / "tests" / "data" / "icons" / "feather"
    target = folder / "icons.mp4"
    command = [*TWEENRENDER, "render", str(icons / "heart.svg"), str(icons / "star.svg"), "--size", "1280x720",
               "-o", str(target), "-q"]
    theirs = manim_command(manim, folder)
    runs, manim_runs = [], []
    for _ in range(rounds):
        runs.append(run_measured(command))
        if theirs is not None:
            manim_runs.append(run_measured(theirs))
    print(f"## A two-icon morph (feather heart -> star), 1 s of 1280x720 MP4, {rounds} runs ({load()})")
    print(f"wall {_min_median([r[0] for r in runs], 2)} s (min / median), CPU {median([r[1] for r in runs]):.2f} s, "
          f"peak tree {max(r[2] for r in runs)} MiB")
    if theirs is None:
        print("manim is not installed (give --manim PATH): no comparison")
    else:
        ratios = [ours[0] / other[0] for ours, other in zip(runs, manim_runs)]
        print(f"manim ({theirs[0]}): wall {_min_median([r[0] for r in manim_runs], 2)} s, CPU "
              f"{median([r[1] for r in manim_runs]):.2f} s, peak tree {max(r[2] for r in manim_runs)} MiB; "
              f"tweenrender / manim wall, same round: {_min_median(ratios)} (min / median)")
    check = ("import sys, tweenrender as tr\n"
             f"scene = tr.load_scene([{str(icons / 'heart.svg')!r}, {str(icons / 'star.svg')!r}])\n"
             "tr.frame(scene, 0.5, size=(1280, 720))\n"
             "print(', '.join(m for m in ('scipy.optimize', 'numba', 'skia') if m in sys.modules) or 'none')\n")
    loaded = subprocess.run([sys.executable, "-c", check], capture_output=True, text=True, cwd=ROOT,
                            env={**os.environ, "PYTHONPATH": str(ROOT)}).stdout.strip()
    print(f"heavy modules loaded by loading and drawing it: {loaded}")
    print()


def preview_latency(rounds: int) -> None:
    """The preview's save-to-frame latency on three shipped scenes (benchmarks/bench_preview.py does all)."""
    from bench_preview import measure

    print(f"## Preview: a save to the first frame of the new drawing served, {rounds} saves each ({load()})")
    for name in ("square.toml", "foot-svg.toml", "walk.toml"):
        outside, inside, total = measure(ROOT / "scenes" / name, rounds)
        print(f"{name:16s} {total:4d} frames: {_min_median(outside)} s (min / median) from the rename to the "
              f"frame served; the server's own count {_min_median(inside)} s")
    print()


def machine() -> None:
    model = next((line.split(":", 1)[1].strip() for line in Path("/proc/cpuinfo").read_text().splitlines()
                  if line.startswith("model name")), platform.processor())
    cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else os.cpu_count()
    average = ", ".join(f"{x:.2f}" for x in os.getloadavg())
    print(f"## Machine: nproc {cpus}, {model}, Python {platform.python_version()}, load average {average}")
    print()


def installed_bytecode() -> None:
    """Compile the package's bytecode, as ``pip install`` does: renders started here then load it, as they
    do when installed, however ``PYTHONDONTWRITEBYTECODE`` is set (it stops writing, not reading), rather
    than compiling every module from source in every process (about 35 ms each)."""
    import compileall

    import tweenrender

    compileall.compile_dir(str(Path(tweenrender.__file__).parent), quiet=1)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=3, help="interleaved runs of each comparison")
    parser.add_argument("--manim", help="a manim executable to compare the icon morph with (default: manim on the PATH)")
    parser.add_argument("--only", choices=("stroked", "busy", "drawing", "memory", "ffmpeg", "cluster", "icons",
                                           "preview"))
    args = parser.parse_args()
    machine()
    installed_bytecode()
    with tempfile.TemporaryDirectory(prefix="tweenrender-bench-") as name:
        folder = Path(name)
        if args.only in (None, "stroked"):
            against_encoder(folder, "stroked", stroked_scene(5.0), args.rounds)
        if args.only in (None, "busy"):
            against_encoder(folder, "busy", busy_scene(5.0), args.rounds)
        if args.only in (None, "drawing"):
            stroke_costs(folder)
        if args.only in (None, "memory"):
            memory(folder, args.rounds)
        if args.only in (None, "ffmpeg"):
            ffmpeg_options(folder, args.rounds)
        if args.only in (None, "cluster"):
            cluster(folder, args.rounds)
        if args.only in (None, "icons"):
            icon_morph(folder, max(args.rounds, 3), args.manim)
        if args.only in (None, "preview"):
            preview_latency(args.rounds)
    machine()


if __name__ == "__main__":
    main()
