"""The fast paths give the same pictures as the plain ones: opaque readout, zero-copy
BGRA, numpy-built paths, BGRA into ffmpeg, streaming, light start-up (no timings here)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import SCENES, SQUARE, decode, write_scene

import skia


def _raster(background: tuple[int, int, int, int], width: int = 64, height: int = 48):
    from tweenrender.raster.surface import Raster

    raster = Raster(width, height)
    raster.clear(background)
    return raster


def test_opaque_background_reads_out_exact_colours_and_opaque_edges() -> None:
    raster = _raster((250, 240, 230, 255))
    raster.polygon(np.array([[10.3, 5.0], [50.0, 9.7], [30.0, 40.2]]), (59, 111, 216, 255))
    rgba = raster.rgba()
    assert tuple(rgba[0, 0]) == (250, 240, 230, 255)
    assert tuple(rgba[20, 30]) == (59, 111, 216, 255)  # well inside the triangle
    assert rgba[..., 3].min() == 255  # antialiased edges over an opaque background stay opaque
    edge = rgba[5:12, 10:50].reshape(-1, 4)
    mixed = edge[(edge[:, 0] < 250) & (edge[:, 0] > 59)]
    assert len(mixed) > 0  # a blend of the two colours on the edge, not a hard step


def test_translucent_pixels_come_out_straight_not_premultiplied() -> None:
    raster = _raster((0, 0, 0, 0))
    raster.polygon(np.array([[0.0, 0.0], [64.0, 0.0], [64.0, 48.0], [0.0, 48.0]]), (200, 100, 40, 128))
    rgba = raster.rgba()
    # straight: the colour itself with alpha 128; premultiplied would be about half of each channel
    assert np.abs(rgba[24, 32].astype(int) - (200, 100, 40, 128)).max() <= 1
    assert not raster.opaque()


def test_bgra_is_the_surface_itself_and_matches_rgba_when_opaque() -> None:
    raster = _raster((10, 20, 30, 255))
    first = raster.bgra()
    raster.polygon(np.array([[0.0, 0.0], [40.0, 0.0], [40.0, 40.0]]), (200, 150, 100, 255))
    assert raster.bgra() is first and tuple(first[5, 30]) == (100, 150, 200, 255)  # drawn into, no copy
    assert np.array_equal(first[..., [2, 1, 0, 3]], raster.rgba())
    assert raster.opaque()


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 40), st.integers(1, 40), st.integers(0, 255), st.integers(0, 1599))
def test_all_opaque_agrees_with_brute_force(width: int, height: int, alpha: int, where: int) -> None:
    from tweenrender.raster.surface import _all_opaque

    pixels = np.full((height, width, 4), 255, dtype=np.uint8)
    pixels[..., :3] = 7
    spot = where % (width * height)
    pixels.reshape(-1, 4)[spot, 3] = alpha
    assert _all_opaque(pixels) == (alpha == 255)


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(-50, 500, allow_nan=False), st.floats(-50, 500, allow_nan=False)),
                min_size=1, max_size=60), st.booleans())
def test_numpy_built_path_has_the_points_and_verbs_of_add_poly(points: list, closed: bool) -> None:
    from tweenrender.raster.surface import _SERIAL_OK, polygon_path

    assert _SERIAL_OK  # else the slow route is used and this test proves nothing about the fast one
    pts = np.array(points, dtype=np.float64)
    path = polygon_path(pts, closed)
    reference = skia.Path()
    reference.addPoly([skia.Point(x, y) for x, y in pts.tolist()], closed)
    got = np.array([(p.x(), p.y()) for p in path.getPoints(path.countPoints())], dtype=np.float32)
    assert np.array_equal(got, pts.astype(np.float32))
    assert path.countVerbs() == reference.countVerbs() == len(pts) + int(closed)
    assert path.getBounds() == reference.getBounds()


def test_numpy_built_paths_draw_the_same_pixels(monkeypatch: pytest.MonkeyPatch) -> None:
    import tweenrender.raster.surface as raster_module

    rng = np.random.default_rng(5)
    star = rng.uniform(0, 64, size=(40, 2))

    def draw() -> np.ndarray:
        raster = _raster((255, 255, 255, 255))
        raster.polygon(star, (20, 90, 200, 255), (0, 0, 0, 255), 1.5)
        return raster.rgba().copy()

    fast = draw()
    monkeypatch.setattr(raster_module, "_SERIAL_OK", False)
    assert np.array_equal(fast, draw())


def test_bgra_frames_into_ffmpeg_keep_their_colours(tmp_path: Path) -> None:
    from tweenrender.encode import open_sink

    target = tmp_path / "bgra.mp4"
    sink = open_sink("mp4", target, 64, 48, 24, 3, pixel_format="bgra")
    colours = [(255, 0, 0), (0, 255, 0), (0, 0, 255)]  # as RGB
    for r, g, b in colours:
        frame = np.empty((48, 64, 4), dtype=np.uint8)
        frame[...] = (b, g, r, 255)  # BGRA order in memory
        sink.write(frame)
    sink.close()
    meta, frames = decode(target)
    assert meta["size"] == (64, 48) and len(frames) == 3
    for (r, g, b), frame in zip(colours, frames):
        assert np.abs(frame[24, 32].astype(int) - (r, g, b)).max() <= 12  # yuv420p rounding


def test_a_frame_of_the_wrong_shape_is_refused(tmp_path: Path) -> None:
    from tweenrender.encode import open_sink
    from tweenrender.errors import EncodeError

    target = tmp_path / "bad.mp4"
    sink = open_sink("mp4", target, 64, 48, 24, 1)
    with pytest.raises(EncodeError, match=r"expected uint8 \(48, 64, 4\)"):
        sink.write(np.zeros((48, 64, 3), dtype=np.uint8))
    assert not target.exists() and not list(tmp_path.iterdir())


def test_frames_stream_one_at_a_time(tmp_path: Path) -> None:
    """Nothing is drawn ahead of the sink, and every frame lands in the same reused buffer."""
    from tweenrender.pipeline import workers as parallel
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import load_scene

    drawn: list[int] = []
    original = parallel.draw_frame

    def counting(frames, index):  # type: ignore[no-untyped-def]
        drawn.append(index)
        return original(frames, index)

    job = RenderJob(load_scene(write_scene(tmp_path, SQUARE)))
    parallel.draw_frame, saved = counting, parallel.draw_frame
    try:
        stream = parallel.frame_stream(job)
        assert drawn == []  # lazy: nothing drawn before the first frame is asked for
        first = next(stream)
        second = next(stream)
        assert drawn == [0, 1] and first is second  # one buffer, whatever the clip's length
        assert sum(1 for _ in stream) == len(job.frame_range) - 2
    finally:
        parallel.draw_frame = saved


def _imported_after(*argv: str) -> set[str]:
    code = ("import sys; from tweenrender.cli.main import main; code = main(sys.argv[1:]); "
            "print(' '.join(sorted({m.split('.')[0] for m in sys.modules})))")
    done = subprocess.run([sys.executable, "-c", code, *argv], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    return set(done.stdout.splitlines()[-1].split())  # the last line: the top-level modules


def test_check_imports_neither_skia_nor_ffmpeg_nor_numba() -> None:
    loaded = _imported_after("check", str(SCENES / "square.toml"))
    assert "tweenrender" in loaded
    assert not loaded & {"skia", "imageio", "imageio_ffmpeg", "numba"}


def _ring(count: int, radius: float) -> str:
    angles = np.linspace(0.0, 2.0 * np.pi, count, endpoint=False)
    return str([[round(float(radius * np.cos(a)), 6), round(float(radius * np.sin(a)), 6)] for a in angles])


def test_numba_is_imported_only_for_large_keys_of_different_counts(tmp_path: Path) -> None:
    same = _imported_after("check", "--json", str(SCENES / "square.toml"))
    assert "numba" not in same and "skia" not in same
    # a few vertices: searched in numpy (core/_small_dtw), numba not loaded
    differ = write_scene(tmp_path, SQUARE.replace("[[7, 1], [7, 3], [5, 3], [5, 1]]",
                                                  "[[7, 1], [7, 3], [6, 4], [5, 3], [5, 1]]"))
    assert "numba" not in _imported_after("check", "--json", str(differ))
    # 200 against 230 vertices: 9 million nodes, past the numpy search's 1.5 million
    large = write_scene(tmp_path, SQUARE.replace("[[0, 0], [2, 0], [2, 2], [0, 2]]", _ring(200, 1.0))
                        .replace("[[7, 1], [7, 3], [5, 3], [5, 1]]", _ring(230, 1.5)), "large.toml")
    assert "numba" in _imported_after("check", "--json", str(large))


@pytest.mark.parametrize("fmt", ["mp4", "gif"])
def test_probe_reads_frame_count_and_size_in_one_pass(tmp_path: Path, fmt: str) -> None:
    from tweenrender.encode import open_sink
    from tweenrender.encode.sinks import probe_video

    target = tmp_path / f"probe.{fmt}"
    sink = open_sink(fmt, target, 66, 40, 10, 7)
    for shade in range(7):
        sink.write(np.full((40, 66, 4), (30 * shade, 90, 200, 255), dtype=np.uint8))
    sink.close()
    _, frames = decode(target)
    assert len(frames) == 7 and frames[0].shape == (40, 66, 3)  # what a decoder sees
    assert probe_video(target) == (7, (66, 40))
    with pytest.raises(ValueError):
        probe_video(write_scene(tmp_path, "not a video", "fake.mp4"))


def _outlines(seed: int, shapes: int = 24, vertices: int = 500) -> list[np.ndarray]:
    """Detailed outlines in a 640x360 frame: wobbly rings with a random radius at every vertex
    (sharp spikes a pixel apart) and smooth ones, some overlapping."""
    rng = np.random.default_rng(seed)
    angles = np.linspace(0.0, 2 * np.pi, vertices, endpoint=False)
    out = []
    for index in range(shapes):
        radius = rng.uniform(20, 60) * (1 + 0.25 * np.sin(5 * angles + rng.uniform(0, 6)))
        if index % 2:
            radius = radius * (1 + 0.1 * rng.uniform(-1, 1, vertices))
        centre = rng.uniform([40, 40], [600, 320])
        out.append(centre + radius[:, None] * np.c_[np.cos(angles), np.sin(angles)])
    return out


def _plain_drawing(outlines: list[np.ndarray], width: float, stroke_alpha: int) -> np.ndarray:
    """The unoptimised drawing, straight skia: antialiased fill, then the stroke, per shape."""
    from tweenrender.raster.surface import Raster, polygon_path

    raster = Raster(640, 360)
    raster.clear((253, 253, 248, 255))
    fill = skia.Paint(AntiAlias=True, Style=skia.Paint.kFill_Style)
    stroke = skia.Paint(AntiAlias=True, Style=skia.Paint.kStroke_Style, StrokeWidth=width,
                        StrokeJoin=skia.Paint.kRound_Join, StrokeCap=skia.Paint.kRound_Cap)
    for index, points in enumerate(outlines):
        path = polygon_path(points)
        fill.setColor(skia.ColorSetARGB(255, 40 * (index % 6), 90, 200 - 30 * (index % 5)))
        raster.canvas.drawPath(path, fill)
        stroke.setColor(skia.ColorSetARGB(stroke_alpha, 29, 43, 80))
        raster.canvas.drawPath(path, stroke)
    return raster.rgba().astype(int)


def _drawn(outlines: list[np.ndarray], width: float, stroke_alpha: int) -> np.ndarray:
    from tweenrender.raster.surface import Raster

    raster = Raster(640, 360)
    raster.clear((253, 253, 248, 255))
    for index, points in enumerate(outlines):
        raster.polygon(points, (40 * (index % 6), 90, 200 - 30 * (index % 5), 255), (29, 43, 80, stroke_alpha),
                       width)
    return raster.rgba().astype(int)


@pytest.mark.parametrize("width", [2.0, 3.5])
def test_fill_under_an_opaque_stroke_looks_the_same_drawn_aliased(width: float) -> None:
    outlines = _outlines(7)
    plain, fast = _plain_drawing(outlines, width, 255), _drawn(outlines, width, 255)
    difference = np.abs(plain - fast).max(axis=2)
    # antialiasing noise: skia itself changes edge pixels by up to ~60 levels when the same
    # geometry gets extra points; here far less, and at a handful of pixels
    assert difference.max() <= 24
    assert np.count_nonzero(difference > 8) <= 1e-4 * difference.size
    assert difference.mean() < 0.01


@pytest.mark.parametrize("width, alpha", [(1.5, 255), (2.0, 200)])
def test_thin_or_translucent_strokes_keep_the_antialiased_fill(width: float, alpha: int) -> None:
    outlines = _outlines(8, shapes=6)
    assert np.array_equal(_plain_drawing(outlines, width, alpha), _drawn(outlines, width, alpha))


def test_hides_fill_edge_only_for_plain_opaque_strokes_two_device_pixels_wide() -> None:
    from tweenrender.raster.surface import hides_fill_edge

    def paint(**settings: object) -> skia.Paint:
        base = {"AntiAlias": True, "Style": skia.Paint.kStroke_Style, "StrokeWidth": 2.0, "Color": skia.ColorBLACK}
        return skia.Paint(**{**base, **settings})

    fill = paint(Style=skia.Paint.kFill_Style, Color=skia.ColorRED)
    assert hides_fill_edge(paint(), fill)
    assert not hides_fill_edge(paint(), fill, skia.Matrix.Scale(0.5, 0.5))
    assert hides_fill_edge(paint(StrokeWidth=1.0), fill, skia.Matrix.Scale(2, 2))
    assert not hides_fill_edge(paint(StrokeWidth=1.9), fill)
    assert not hides_fill_edge(paint(Color=skia.ColorSetARGB(254, 0, 0, 0)), fill)
    assert not hides_fill_edge(paint(), paint(Style=skia.Paint.kFill_Style, Color=skia.ColorSetARGB(128, 255, 0, 0)))
    assert not hides_fill_edge(paint(AntiAlias=False), fill)
    assert not hides_fill_edge(paint(), fill, skia.Matrix.RotateDeg(30))


def test_an_mp4_render_runs_ffmpeg_once_and_loads_no_pool_nor_masked_arrays(tmp_path: Path) -> None:
    icons = Path(__file__).resolve().parents[1] / "data" / "icons" / "feather"
    code = (
        "import sys\n"
        "from tweenrender.encode import lifeline, sinks\n"
        "ran = []\n"
        "for module in (lifeline, sinks):\n"
        "    for name in ('run_program', 'start_program'):\n"
        "        if hasattr(module, name):\n"
        "            def counted(command, *a, _f=getattr(module, name), **k):\n"
        "                ran.append(command[1] if len(command) > 1 else '')\n"
        "                return _f(command, *a, **k)\n"
        "            setattr(module, name, counted)\n"
        "from tweenrender.cli.main import main\n"
        "code = main(sys.argv[1:])\n"
        "print(len(ran), int('numpy.ma' in sys.modules), int('concurrent.futures.process' in sys.modules))\n")
    target = tmp_path / "icons.mp4"
    done = subprocess.run([sys.executable, "-c", code, "render", str(icons / "heart.svg"), str(icons / "star.svg"),
                           "--size", "128x72", "-o", str(target), "-q"], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    runs, masked, pool = (int(v) for v in done.stdout.split()[-3:])
    assert (runs, masked, pool) == (1, 0, 0)  # the encoder alone: the file is read back from its boxes
    _, frames = decode(target)
    assert len(frames) == 25
