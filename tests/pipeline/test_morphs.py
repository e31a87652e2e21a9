"""Morphs of whole drawings, measured on the frames: holes stay holes, open strokes stay open,
colours blend perceptually, elements come and go."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA, write_scene
from tweenrender.core.contours import roles

MDI = DATA / "icons" / "mdi"
FEATHER = DATA / "icons" / "feather"
SIZE = 240  # a 24-unit icon at 10 pixels a unit


def svg(folder: Path, name: str, body: str, box: str = "0 0 24 24") -> Path:
    path = folder / name
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="{box}">{body}</svg>')
    return path


def pixel(img: np.ndarray, world: np.ndarray) -> np.ndarray:
    """The RGB at a world point of a 24 × 24 view drawn at 10 px a unit (world y = -svg y)."""
    x, y = world
    return img[int(-y * 10), int(x * 10), :3].astype(int)


def shapes_at(scene: tr.Scene, time: float):  # type: ignore[no-untyped-def]
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob

    return Frames(RenderJob(scene)).shapes_at(None, time)


@pytest.mark.parametrize("method", ["linear", "nonlinear", "rigid", "auto"])
def test_letters_keep_their_holes_through_the_morph(method: str) -> None:
    """The holes in both keys of a segment stay holes. From o to b the o's hole becomes b's lower one
    and b's upper hole (2 units square) grows down from the o hole's top edge, its area linear in t
    (SPEC §5.17): its depth 2√t outruns the other's top edge retreating by 4t for t < 1/4, so there
    the two overlap; the holes in both keys stay holes throughout."""
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob

    scene = tr.load_scene([MDI / "alpha-a.svg", MDI / "alpha-o.svg", MDI / "alpha-b.svg"])
    frames = Frames(RenderJob(scene))
    for time in np.linspace(0.0, 2.0, 9):
        contours = tr.outlines(scene, time, method=method)
        kinds = roles(contours, [True] * len(contours))
        (at,) = frames.shapes_at(method, time)
        moving = [c for c, share in zip(at.contours, at.widths or (1.0,) * len(at.contours))
                  if share == 1.0 and np.ptp(c, axis=0).max() > 0]  # neither growing nor shrinking
        assert "hole" in roles(moving, [True] * len(moving)), (time, kinds)
        img = tr.frame(scene, time, method=method, size=(SIZE, SIZE))
        for contour, kind in zip(contours, kinds):
            if kind == "hole":  # the hole's middle shows the background, its rim shows ink
                assert (pixel(img, contour.mean(axis=0)) > 245).all(), time
        ink = (img[..., :3] < 128).all(axis=-1).mean()
        assert 0.02 < ink < 0.25


def test_an_open_stroke_stays_open(tmp_path: Path) -> None:
    scene = tr.load_scene([FEATHER / "check.svg", svg(tmp_path, "v.svg",
                           '<polyline points="4 6 12 20 20 6" fill="none" stroke="#000" stroke-width="2"/>')])
    for time in (0.0, 0.5, 1.0):
        (shape,) = shapes_at(scene, time)
        assert shape.closed == (False,) and shape.paint.fill is None
        corners = shape.contours[0]
        img = tr.frame(scene, time, size=(SIZE, SIZE))
        # the middle of the triangle the stroke's ends would close is not filled
        middle = corners[[0, len(corners) // 2, -1]].mean(axis=0)
        assert (pixel(img, middle) > 245).all(), time
        dark = (img[..., :3] < 100).all(axis=-1).mean()
        assert 0.005 < dark < 0.13  # a stroke: the filled triangle with its stroke would cover ~0.18


def test_red_to_blue_is_a_perceptual_purple_half_way(tmp_path: Path) -> None:
    from coloraide import Color

    red = svg(tmp_path, "red.svg", '<rect x="4" y="4" width="16" height="16" fill="red"/>')
    blue = svg(tmp_path, "blue.svg", '<rect x="4" y="4" width="16" height="16" fill="#0000ff"/>')
    scene = tr.load_scene([red, blue], step=2.0)
    mid = tr.frame(scene, 1.0, size=(SIZE, SIZE))
    expected = Color.interpolate([Color("red"), Color("blue")], space="oklab")(0.5).convert("srgb")
    expected_rgb = np.array([round(255 * c) for c in expected.coords()])
    assert np.abs(pixel(mid, np.array([12.0, -12.0])) - expected_rgb).max() <= 1
    assert tuple(pixel(tr.frame(scene, 0.0, size=(SIZE, SIZE)), np.array([12.0, -12.0]))) == (255, 0, 0)


def _three(tmp_path: Path) -> list[Path]:
    """A circle; the circle and a square; the circle again."""
    circle = '<circle cx="6" cy="12" r="4" fill="#3b6fd8"/>'
    return [svg(tmp_path, "a.svg", circle),
            svg(tmp_path, "b.svg", circle + '<rect x="14" y="14" width="8" height="8" fill="#2e9e44"/>'),
            svg(tmp_path, "c.svg", circle)]


def _covered(img: np.ndarray, colour: tuple[int, int, int], box: tuple[int, int, int, int]) -> float:
    """Pixels of ``box`` (x0, y0, x1, y1 in drawing units) close to ``colour``, in square drawing units."""
    x0, y0, x1, y1 = (10 * v for v in box)
    region = img[y0:y1, x0:x1, :3].astype(int)
    return float((np.abs(region - colour).max(axis=-1) < 40).sum()) / 100.0


def test_an_element_appears_and_goes(tmp_path: Path) -> None:
    scene = tr.load_scene(_three(tmp_path), step=1.0)
    assert sorted(len(s.keys) for s in scene.shapes) == [3, 3]
    green, blue = (0x2E, 0x9E, 0x44), (0x3B, 0x6F, 0xD8)
    for time in (0.0, 0.25, 0.5, 0.75, 1.0, 1.5, 2.0):
        img = tr.frame(scene, time, size=(SIZE, SIZE))
        share = 1.0 - abs(time - 1.0)  # the square grows from its centre, then shrinks back: its area linearly
        assert _covered(img, green, (13, 13, 23, 23)) == pytest.approx(64 * share, abs=0.6 + 3 * np.sqrt(share))
        assert _covered(img, blue, (1, 7, 11, 17)) == pytest.approx(np.pi * 16, abs=1.0)  # the circle stays
    assert len(tr.outlines(scene, 0.0)) == len(tr.outlines(scene, 2.0)) == 1  # not drawn before or after
    assert len(tr.outlines(scene, 1.0)) == 2


def test_a_grin_puts_on_sunglasses(tmp_path: Path) -> None:
    """Twemoji's grinning face to its one with sunglasses: the mouth becomes the smile, an eye the glasses,
    and what has no partner (the teeth, the other eye) shrinks away; nothing is lost or added."""
    twemoji = DATA / "icons" / "twemoji"
    scene = tr.load_scene([twemoji / "1f600.svg", twemoji / "1f60e.svg"])
    appear = [s for s in scene.shapes if s.keys[0].hidden]
    go = [s for s in scene.shapes if s.keys[-1].hidden]
    assert len(go) == 2 and not appear
    names = {s.name: s for s in scene.shapes}
    assert names["path2"].keys[-1].hidden  # the teeth (white) go
    mouth = names["path1"]
    assert mouth.keys[0].paint.fill == mouth.keys[1].paint.fill == (0x66, 0x45, 0x00, 255)  # mouth to smile
    assert len(scene.shapes) - len(appear) == len(tr.load_scene(twemoji / "1f600.svg").shapes)
    assert len(scene.shapes) - len(go) == len(tr.load_scene(twemoji / "1f60e.svg").shapes)
    for time in np.linspace(0.0, 1.0, 5):
        assert np.isfinite(tr.frame(scene, time, size=(64, 64)).astype(float)).all()


def test_elements_fade_when_the_scene_says_so(tmp_path: Path) -> None:
    a, b, _ = _three(tmp_path)
    scene = tr.load_scene(write_scene(tmp_path, f'unmatched = "fade"\n[[drawing]]\ntime = 0\nsvg = "{a.name}"\n'
                                                f'[[drawing]]\ntime = 1\nsvg = "{b.name}"\n', "fade.toml"))
    img = tr.frame(scene, 0.5, size=(SIZE, SIZE))
    half_green = (np.array([0x2E, 0x9E, 0x44]) + 255) / 2
    assert np.abs(pixel(img, np.array([18.0, -18.0])) - half_green).max() <= 3  # full size, half opacity
    assert tuple(pixel(tr.frame(scene, 0.0, size=(SIZE, SIZE)), np.array([18.0, -18.0]))) == (255, 255, 255)


def test_icons_of_different_view_boxes_line_up(tmp_path: Path) -> None:
    small = svg(tmp_path, "s.svg", '<rect x="2" y="2" width="12" height="12"/>', box="0 0 16 16")
    large = svg(tmp_path, "l.svg", '<rect x="3" y="3" width="18" height="18"/>', box="0 0 24 24")
    scene = tr.load_scene([large, small])
    (end,) = tr.outlines(scene, 1.0)
    np.testing.assert_allclose(np.sort(end, axis=0), np.sort(tr.outlines(scene, 0.0)[0], axis=0), atol=1e-9)


@pytest.mark.parametrize("unmatched", ["fade", "grow"])
def test_a_hole_without_partner_fades_or_shrinks(tmp_path: Path, unmatched: str) -> None:
    scene = tr.load_scene(write_scene(tmp_path, f'''unmatched = "{unmatched}"
view = [-1, -1, 5, 5]
size = [120, 120]
[[shape]]
name = "ring"
fill = "#3b6fd8"
[[shape.key]]
time = 0
contours = [[[0, 0], [4, 0], [4, 4], [0, 4]], [[1, 1], [1, 3], [3, 3], [3, 1]]]
[[shape.key]]
time = 1
contours = [[[0, 0], [4, 0], [4, 4], [0, 4]]]
''', "ring.toml"))
    blue, white = np.array([0x3B, 0x6F, 0xD8]), np.array([255, 255, 255])
    for time in (0.0, 0.25, 0.5, 0.75, 1.0):
        img = tr.frame(scene, time)
        centre, rim = img[60, 60, :3].astype(int), img[20, 20, :3].astype(int)
        assert np.abs(rim - blue).max() <= 2  # the outline never changes
        if unmatched == "fade":  # the hole fills in evenly: the background cross-fades into the fill
            assert np.abs(centre - ((1 - time) * white + time * blue)).max() <= 2, time
        else:  # the hole shrinks to its centre, its area linearly: a square of side 2·√(1 - t) units, 20 px a unit
            hole = (np.abs(img[..., :3].astype(int) - white).max(axis=-1) < 60)[20:100, 20:100].sum()
            assert hole == pytest.approx(1600 * (1 - time), abs=4 + 160 * np.sqrt(1 - time)), time


@pytest.mark.parametrize("method", ["arap", "intrinsic", "intrinsic-length"])
def test_one_outline_methods_move_a_ring_as_one(tmp_path: Path, method: str) -> None:
    """A plate with an off-centre hole turning a quarter, rigidly: each contour takes the method on
    its own and goes where the shape's rigid paths put it, so the whole turns exactly."""
    scene = tr.load_scene(write_scene(tmp_path, """[[shape]]
name = "plate"
[[shape.key]]
time = 0
contours = [[[0, 0], [6, 0], [6, 4], [0, 4]], [[4, 1], [4, 3], [5, 3], [5, 1]]]
[[shape.key]]
time = 1
contours = [[[0, 0], [0, 6], [-4, 6], [-4, 0]], [[-1, 4], [-3, 4], [-3, 5], [-1, 5]]]
""", "plate.toml"))
    for time in (0.25, 0.5, 0.8):
        got = tr.outlines(scene, time, method=method)
        exact = tr.outlines(scene, time, method="rigid")
        assert len(got) == 2
        for a, b in zip(got, exact):
            np.testing.assert_allclose(a, b, atol=1e-9)
