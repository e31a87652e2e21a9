"""Rasterised frames against closed-form pictures and a golden image."""

from __future__ import annotations


import numpy as np
import pytest

from tweenrender.model import Key, Paint, Scene, Shape, frozen_points
from tweenrender.pipeline.frames import Frames
from tweenrender.plan.job import RenderJob
from tweenrender.core.view import Viewport, fit_box

from tests.helpers import GOLDEN, SCENES, assert_close_to_golden, read_png


def _square_scene(background=(255, 255, 255, 255), fill=(200, 40, 10, 255)) -> Scene:
    square = frozen_points([[1, 1], [3, 1], [3, 3], [1, 3]])
    shape = Shape("sq", (Key.outline(0.0, square, paint=Paint(fill)), Key.outline(1.0, square, paint=Paint(fill))))
    return Scene((shape,), size=(200, 100), view=(0, 0, 8, 4), background=background)


def test_viewport_keeps_aspect_and_puts_y_up() -> None:
    port = Viewport((0, 0, 8, 4), 200, 100)
    assert port.scale == 25.0
    assert np.allclose(port.to_pixels(np.array([[0, 0], [8, 4], [1, 3]])), [[0, 100], [200, 0], [25, 25]])
    wide = Viewport((0, 0, 4, 4), 200, 100)  # square world into a 2:1 canvas: centred, not stretched
    assert wide.scale == 25.0
    assert np.allclose(wide.to_pixels(np.array([[0, 0], [4, 4]])), [[50, 100], [150, 0]])


def test_fit_box_adds_a_margin() -> None:
    assert fit_box([np.array([[0, 0], [10, 5]])], margin=0.1) == (-1.0, -1.0, 11.0, 6.0)


def test_plain_frame_is_the_exact_square_and_nothing_else() -> None:
    frame = Frames(RenderJob(_square_scene()))(0).copy()
    assert frame.shape == (100, 200, 4) and frame.dtype == np.uint8
    # world square [1, 3]² → pixels x 25..75, y 25..75 (y flipped): exactly 50 × 50 px, pixel-aligned
    inside = frame[25:75, 25:75]
    assert np.all(inside == [200, 40, 10, 255])
    outside = frame.copy()
    outside[25:75, 25:75] = 255
    assert np.all(outside == 255)  # no label, no watermark, no stray pixels


def test_antialiased_edge_has_fractional_coverage() -> None:
    square = frozen_points([[1.1, 1], [3.1, 1], [3.1, 3], [1.1, 3]])  # x edges at 27.5 and 77.5 px
    shape = Shape("sq", (Key.outline(0.0, square, paint=Paint((0, 0, 0, 255))),))
    frame = Frames(RenderJob(Scene((shape,), size=(200, 100), view=(0, 0, 8, 4))))(0)
    coverage = 1.0 - frame[50, :, 0].astype(float) / 255.0
    assert coverage.sum() == pytest.approx(50.0, abs=0.05)  # area is kept across the edge pixels
    assert 0.3 < coverage[27] < 0.7 and 0.3 < coverage[77] < 0.7


def test_translucent_background_comes_out_straight() -> None:
    frame = Frames(RenderJob(_square_scene(background=(10, 20, 30, 128))))(0)
    assert tuple(frame[0, 0]) == (10, 20, 30, 128)  # unpremultiplied, not (5, 10, 15, 128)


def test_comparison_frame_matches_golden(update_golden: bool) -> None:
    from tweenrender.scenefile import load_scene

    scene = load_scene(SCENES / "square.toml")
    job = RenderJob(scene, ("linear", "nonlinear"), labels=True, size=(320, 180))
    frame = Frames(job)(24)
    assert_close_to_golden(frame, "square-compare-24.png", update_golden)


def test_the_golden_comparison_fails_on_a_changed_picture() -> None:
    """The comparison above can fail: the golden frame with one shape moved by 3 pixels does not pass."""
    expected = read_png(GOLDEN / "square-compare-24.png")
    moved = np.roll(expected, 3, axis=1)
    with pytest.raises(AssertionError, match="mean difference"):
        assert_close_to_golden(moved, "square-compare-24.png", update=False)
    darker = expected.copy()
    darker[..., :3] //= 2
    with pytest.raises(AssertionError):
        assert_close_to_golden(darker, "square-compare-24.png", update=False)
