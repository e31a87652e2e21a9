"""The compiled round stroke: its coverage against brute force (beside skia's own), its blending, and
where :class:`Raster` uses it or leaves the stroke to skia."""

from __future__ import annotations

import functools
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.helpers import ring_scene, stroke_cases, stroke_coverage

import skia

from tweenrender.raster.round_stroke import stroke_contours, worth_compiling  # noqa: E402
from tweenrender.raster.surface import Raster, StrokeStyle, contours_path  # noqa: E402

SIZE = (48, 40)
WHITE = np.array([255.0, 255.0, 255.0, 255.0])


def _black() -> np.ndarray:
    pixels = np.zeros((SIZE[1], SIZE[0], 4), np.uint8)
    pixels[..., 3] = 255
    return pixels


def _skia_coverage(contours: list[np.ndarray], closed: list[bool], width: float) -> np.ndarray:
    pixels = _black()
    surface = skia.Surface(pixels, colorType=skia.kBGRA_8888_ColorType)
    surface.getCanvas().drawPath(contours_path(contours, closed), skia.Paint(
        AntiAlias=True, Style=skia.Paint.kStroke_Style, StrokeWidth=width, Color=skia.ColorWHITE,
        StrokeJoin=skia.Paint.kRound_Join, StrokeCap=skia.Paint.kRound_Cap))
    return pixels[..., 0] / 255


@pytest.mark.parametrize("case", stroke_cases(), ids=lambda case: case[0])
def test_coverage_is_as_close_to_the_exact_area_as_skias(case) -> None:
    label, contours, closed, width = case
    truth = stroke_coverage(contours, closed, width, SIZE)
    pixels = _black()
    stroke_contours(pixels, contours, closed, width, WHITE)
    ours = np.abs(pixels[..., 0] / 255 - truth)
    theirs = np.abs(_skia_coverage(contours, closed, width) - truth)
    assert ours.mean() <= theirs.mean() + 1e-4, label
    # where two parts of a spiky outline cross one pixel the two-edge model is approximate
    assert ours.max() <= (0.36 if "spikes" in label else 0.16), label


def test_a_straight_stroke_has_the_closed_form_coverage_and_blends_source_over() -> None:
    # a horizontal 2 px stroke centred on y = 20.25 spans y 19.25 to 21.25: three quarters of row 19,
    # all of row 20, a quarter of row 21; drawn 60 % opaque red over a blue background
    pixels = np.zeros((SIZE[1], SIZE[0], 4), np.uint8)
    pixels[...] = (200, 0, 0, 255)  # BGRA blue
    alpha = 153
    colour = np.array([0.0, 0.0, 255.0, 255.0]) * (alpha / 255)  # premultiplied BGRA red
    stroke_contours(pixels, [np.array([[5.0, 20.25], [40.0, 20.25]])], [False], 2.0, colour)
    for row, covered in ((18, 0.0), (19, 0.75), (20, 1.0), (21, 0.25), (22, 0.0)):
        a = covered * alpha / 255
        expected = (200 * (1 - a), 0, 255 * a, 255)
        assert np.abs(pixels[row, 20].astype(float) - expected).max() <= 1.0, row


def test_degenerate_outlines_draw_without_nan_or_escape() -> None:
    pixels = _black()
    far = 2.0 ** 21
    touched = stroke_contours(pixels, [np.array([[-far, -far], [far, far]]),  # across the canvas, ends far off
                                       np.array([[40.0, 5.0]]),  # one point: nothing
                                       np.array([[30.0, 30.0], [30.0, 30.0], [30.0, 30.0]])],  # a dot
                              [False, True, True], 3.0, WHITE)
    assert touched > 0
    # the diagonal through the canvas: the pixel on it is lit, one 5 px off it is not
    assert pixels[20, 20, 0] == 255 and pixels[20, 26, 0] == 0
    assert pixels[30, 30, 0] == 255  # the dot
    assert pixels[5, 40, 0] == 0
    assert stroke_contours(_black(), [], [], 2.0, WHITE) == 0


def test_the_clip_box_is_kept() -> None:
    pixels = _black()
    stroke_contours(pixels, [np.array([[2.0, 20.0], [46.0, 20.0]])], [False], 4.0, WHITE, clip=(10, 0, 30, 40))
    assert pixels[20, 10:30, 0].min() == 255
    assert pixels[:, :10, 0].max() == 0 and pixels[:, 30:, 0].max() == 0


def _spiky(count: int = 300) -> list[np.ndarray]:
    rng = np.random.default_rng(7)
    turn = np.linspace(0, 2 * np.pi, count, endpoint=False)
    radius = 14 + rng.uniform(-3, 3, count)
    return [np.stack([32 + radius * np.cos(turn), 24 + radius * np.sin(turn)], 1)]


def _drawn(round_strokes: bool, style: StrokeStyle = StrokeStyle(), opacity: float = 1.0,
           transform: tuple[str, float] | None = None, fill: tuple[int, int, int, int] | None = (59, 111, 216, 255),
           width: float = 2.0, closed: bool = True) -> np.ndarray:
    raster = Raster(64, 48, round_strokes=round_strokes)
    raster.clear((250, 248, 240, 255))
    raster.canvas.save()
    if transform is not None:
        how, amount = transform
        if how == "scale":
            raster.canvas.scale(amount, amount)
        elif how == "stretch":
            raster.canvas.scale(amount, 1.0)
        elif how == "layer":
            raster.canvas.saveLayerAlpha(None, int(amount))
        elif how == "round clip":
            raster.canvas.clipRRect(skia.RRect.MakeRectXY(skia.Rect.MakeWH(64, 48), 9, 9))
    raster.draw_contours(_spiky(), [closed], "nonzero", fill, (29, 43, 80, 255), width, style, opacity)
    raster.canvas.restore()
    if transform is not None and transform[0] == "layer":
        raster.canvas.restore()
    return raster.rgba().astype(int)


def test_raster_draws_round_strokes_like_skia_does() -> None:
    ours, skias = _drawn(True), _drawn(False)
    difference = np.abs(ours - skias)
    assert not np.array_equal(ours, skias)  # the kernel drew it
    assert difference.mean() < 1.5 and difference.max() <= 120  # antialiasing differences only
    assert (difference[..., :3].max(axis=2) > 40).mean() < 0.01


@pytest.mark.parametrize("variant", [
    {"style": StrokeStyle(join="miter")}, {"style": StrokeStyle(join="bevel")},
    {"style": StrokeStyle(cap="butt"), "closed": False}, {"opacity": 0.5},
    {"transform": ("stretch", 1.5)}, {"transform": ("layer", 128)}, {"transform": ("round clip", 0)},
    {"width": 0.5},
], ids=["miter", "bevel", "open-butt", "translucent-with-fill", "stretched", "in-a-layer", "round-clip", "thin"])
def test_strokes_the_kernel_cannot_draw_are_skias_bit_for_bit(variant: dict) -> None:
    assert np.array_equal(_drawn(True, **variant), _drawn(False, **variant))


@pytest.mark.parametrize("variant", [
    {"transform": ("scale", 1.5)}, {"fill": None, "opacity": 0.5}, {"style": StrokeStyle(cap="butt")},
], ids=["uniform-scale", "translucent-stroke-alone", "closed-with-butt-caps"])
def test_strokes_it_can_draw_are_drawn_by_it_and_agree_with_skia(variant: dict) -> None:
    ours, skias = _drawn(True, **variant), _drawn(False, **variant)
    assert not np.array_equal(ours, skias)
    assert np.abs(ours - skias).mean() < 1.5


def test_only_scenes_with_many_round_stroked_segments_use_it(tmp_path: Path) -> None:
    from tweenrender.scenefile import load_scene

    # 40 rings of 500 vertices: 20 000 segments a frame, the least that uses the kernel
    for text, expected in ((ring_scene(40, 500), True), (ring_scene(40, 499), False), (ring_scene(24, 40), False),
                           (ring_scene(40, 500, stroke="none"), False), (ring_scene(40, 500, join="miter"), False)):
        scene = tmp_path / "scene.toml"
        scene.write_text(text)
        assert worth_compiling(load_scene(scene)) is expected


def test_side_by_side_panels_keep_the_kernels_strokes_inside_their_own(tmp_path: Path) -> None:
    # a detailed stroked scene in two panels (each translated and clipped): drawn with the kernel and
    # with skia, the pictures agree to antialiasing, panel edges included
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import load_scene

    scene = tmp_path / "rings.toml"
    scene.write_text(ring_scene(40, 500).replace("view = [0, 0, 16, 9]", "view = [3, 1, 11, 5.5]"))  # rings cut
    pictures = []
    for kernel in (True, False):
        frames = Frames(RenderJob(load_scene(scene), methods=("linear", "nonlinear")), "rgba")
        frames(0)
        assert frames.composer.raster.round_strokes  # a scene this detailed uses the kernel
        frames.composer.raster.round_strokes = kernel
        pictures.append(frames(12).astype(int))
    difference = np.abs(pictures[0] - pictures[1])
    assert difference.mean() < 1.5
    # a 6 px band each side of the divider: no stroke of one panel drawn into the other
    assert difference[:, 480 - 6:480 + 6].mean() < 3.0


@pytest.mark.parametrize("rise", [1e-310, 1e-12, -1e-9, 0.0])
def test_a_nearly_level_segment_on_a_pixel_centre_row_draws_its_band(rise: float) -> None:
    # ey far below a pixel (subnormal, even): the slab along it would need ex / ey; the box is used
    pixels = _black()
    stroke_contours(pixels, [np.array([[3.0, 20.5], [45.0, 20.5 + rise]])], [False], 2.0, WHITE)
    assert pixels[20, 4:44, 0].min() == 255 and pixels[18, :, 0].max() == 0 and pixels[23, :, 0].max() == 0
    assert 126 <= pixels[19, 10, 0] <= 129 and 126 <= pixels[21, 10, 0] <= 129  # its edges: half a pixel each


@settings(max_examples=40, deadline=None)
@given(st.lists(st.tuples(st.floats(-6, 30), st.floats(-6, 30)), min_size=2, max_size=7),
       st.booleans(), st.floats(1.0, 6.0))
def test_any_polyline_is_covered_like_brute_force_and_nothing_beyond_its_reach(points, closed, width) -> None:
    outline = np.array(points, dtype=float)
    size = (24, 24)
    pixels = np.zeros((size[1], size[0], 4), np.uint8)
    pixels[..., 3] = 255
    stroke_contours(pixels, [outline], [closed], width, WHITE)
    ours = pixels[..., 0] / 255
    truth = stroke_coverage([outline], [closed], width, size, samples=8)
    assert np.abs(ours - truth).mean() <= 0.02
    # a pixel whose whole square lies farther than half the width from the outline stays untouched
    far = stroke_coverage([outline], [closed], width + 2 * 1.5, size, samples=1) == 0
    assert ours[far].max(initial=0) == 0


@pytest.mark.parametrize("slope", [1.0, 0.4142, 0.0])
def test_a_straight_band_has_the_exact_area_at_every_pixel(slope: float) -> None:
    # a 2 px band at 45°, 22.5° and level, its ends far off the canvas: each pixel's coverage is the area
    # of the square inside one or two straight edges, which brute force with 256 × 256 samples a pixel
    # gives to within 0.004; the pixels a diagonal edge just grazes (centres up to √½ beyond it) included
    size = (12, 12)
    line = np.array([[-20.0, 5.3 - 25.3 * slope], [40.0, 5.3 + 34.7 * slope]])
    pixels = np.zeros((size[1], size[0], 4), np.uint8)
    pixels[..., 3] = 255
    stroke_contours(pixels, [line], [False], 2.0, WHITE)
    truth = stroke_coverage([line], [False], 2.0, size, samples=256)
    assert np.abs(pixels[..., 0] / 255 - truth).max() <= 0.004 + 0.5 / 255


def test_coordinates_scaled_past_any_canvas_or_to_infinity_are_safe() -> None:
    pixels = _black()
    huge = np.array([[1e300, 5.0], [3.0, 1e300], [-1e300, -1e300], [10.0, 10.0]])
    stroke_contours(pixels, [huge], [True], 2.0, WHITE, scale=1e10)  # some ends overflow to ±inf
    stroke_contours(pixels, [np.array([[2.0, 3.0], [40.0, 30.0]])], [False], 2.0, WHITE, scale=1e-300)
    assert np.isfinite(pixels).all() and pixels[..., 3].min() == 255


@functools.lru_cache(maxsize=1)
def _both_in_closed_form():
    """The kernel's area of the pixel inside two edges, callable from Python (it is inlined where used),
    compiled once for the tests that call it (not cached on disk: the kernel it inlines may change)."""
    from numba import njit

    from tweenrender.raster import _stroke_kernel as kernel

    return njit(error_model="numpy")(lambda u1, n1x, n1y, u2, n2x, n2y: kernel._both(u1, n1x, n1y, u2, n2x, n2y))


def test_the_pixel_inside_two_edges_has_the_area_brute_force_counts() -> None:
    both = _both_in_closed_form()
    samples = (np.arange(400) + 0.5) / 400 - 0.5
    x, y = np.meshgrid(samples, samples)
    rng = np.random.default_rng(7)
    cases = [(rng.uniform(0, 2 * np.pi), rng.uniform(0, 2 * np.pi), *rng.uniform(-1, 1, 2)) for _ in range(120)]
    # the same line, opposite lines (a band), axis-aligned normals (slopes of zero) and a corner
    cases += [(0.3, 0.3, 0.1, -0.2), (0.3, 0.3 + np.pi, 0.25, 0.1), (0.3, 0.3 + np.pi, -0.2, 0.1),
              (0.0, np.pi / 2, 0.2, -0.1), (np.pi, -np.pi / 2, 0.4, 0.4), (0.0, np.pi, 0.6, 0.6)]
    for first, second, u1, u2 in cases:
        n1, n2 = (np.cos(first), np.sin(first)), (np.cos(second), np.sin(second))
        truth = ((n1[0] * x + n1[1] * y <= u1) & (n2[0] * x + n2[1] * y <= u2)).mean()
        assert abs(both(u1, *n1, u2, *n2) - truth) <= 0.006, (first, second, u1, u2)


def test_the_pixel_inside_two_axis_aligned_edges_is_a_rectangle() -> None:
    both = _both_in_closed_form()
    for a, b in ((0.1, -0.2), (0.5, 0.5), (-0.5, 0.3), (0.7, -0.7), (0.25, 0.0)):
        # x <= a and y <= b: the rectangle from the pixel's lower left corner, (a + ½)(b + ½) held to [0, 1]
        expected = min(1.0, max(0.0, a + 0.5)) * min(1.0, max(0.0, b + 0.5))
        assert both(a, 1.0, 0.0, b, 0.0, 1.0) == pytest.approx(expected, abs=1e-12)
        # -x <= a and -y <= b: the same from the upper right corner
        assert both(a, -1.0, 0.0, b, 0.0, -1.0) == pytest.approx(expected, abs=1e-12)


def test_edges_on_the_pixels_sides_or_on_each_other_count_once() -> None:
    both = _both_in_closed_form()
    assert both(0.5, 1.0, 0.0, 0.5, 0.0, 1.0) == pytest.approx(1.0)  # both lines on the pixel's sides
    assert both(0.2, 0.6, 0.8, 0.2, 0.6, 0.8) == pytest.approx(both(0.2, 0.6, 0.8, 9.0, 0.6, 0.8))  # one line
    assert both(0.2, 0.6, 0.8, -0.2, -0.6, -0.8) == pytest.approx(0.0, abs=1e-12)  # a band of no width
    assert both(0.0, 1.0, 0.0, 0.0, -1.0, 0.0) == pytest.approx(0.0, abs=1e-12)
