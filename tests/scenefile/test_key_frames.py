"""A key frame is its drawing: morphs between pairs of different real icons start on the first icon
and end on the second, as librsvg's ``rsvg-convert`` (an independent SVG renderer) draws them.

The measures are those of the design's acceptance: over a white background, a pixel is *ink*
where any channel differs from white by more than 32/255; *coverage IoU* is |ink ∩ ink'| /
|ink ∪ ink'| and *colour error* the mean absolute RGB difference / 255 over the union of ink.
"""

from __future__ import annotations

import functools
import itertools
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA
from tests.scenefile.test_icons import RSVG, needs_rsvg

SIZE = 256  # at 96 px a one-pixel rim of antialiasing alone costs a thin stroked icon 1 % of its ink
ICONS = DATA / "icons"
SETS = sorted(p for p in ICONS.iterdir() if p.is_dir())


def _pairs() -> list[tuple[Path, Path]]:
    """Every two icons of one set, and from every two sets the icons of the same rank (A before B)."""
    within = [pair for folder in SETS for pair in itertools.combinations(sorted(folder.glob("*.svg")), 2)]
    across = []
    for one, other in itertools.combinations(SETS, 2):
        a, b = sorted(one.glob("*.svg")), sorted(other.glob("*.svg"))
        for rank in range(0, min(len(a), len(b)), 2):
            across += [(a[rank], b[rank]), (b[rank + 1 if rank + 1 < len(b) else rank], a[rank])]
    return within + across


def _evenodd_at_second_key(a: str, b: str) -> bool:
    return "evenodd" in b and "evenodd" not in a


def _many_elements_and_colours(a: str) -> bool:
    return a.count("<path") >= 7 and a.count('fill="#') >= 5


def _sample(pairs: list[tuple[Path, Path]]) -> list[tuple[Path, Path]]:
    """Every fourth pair, and every pair of the rarest hard cases (an even-odd fill only at the
    second key; many elements of many colours)."""
    def hard(a: str, b: str) -> bool:
        return _evenodd_at_second_key(a, b) or _many_elements_and_colours(a)

    return [(a, b) for i, (a, b) in enumerate(pairs) if i % 4 == 0 or hard(a.read_text(), b.read_text())]


ALL_PAIRS = _pairs()
PAIRS = ALL_PAIRS if os.environ.get("TWEENRENDER_ALL_PAIRS") else _sample(ALL_PAIRS)
"""About a third of the pairs, every set in (``TWEENRENDER_ALL_PAIRS=1`` checks all of them)."""


def reference(svg: Path, size: int = SIZE) -> np.ndarray:
    """librsvg's picture of ``svg`` over white: RGB floats ``(size, size, 3)`` in [0, 255] (a fresh copy of
    the one drawn the first time: an icon takes part in several pairs)."""
    return _librsvg_picture(svg, svg.read_bytes(), size).astype(float)


@functools.lru_cache(maxsize=256)
def _librsvg_picture(svg: Path, text: bytes, size: int) -> np.ndarray:
    """librsvg's picture of ``svg`` (whose content is ``text``, the key with its path): RGB ``(size, size, 3)``
    uint8."""
    import imageio.v3 as iio

    done = subprocess.run([RSVG, "-w", str(size), "-h", str(size), "-b", "white", str(svg)], capture_output=True,
                          check=True)
    return iio.imread(done.stdout)[..., :3]


def measures(ours: np.ndarray, theirs: np.ndarray) -> tuple[float, float]:
    """(coverage IoU, colour error) of two RGB pictures over white (values in [0, 255]), as the design defines
    them: ink where a channel is more than 32 below white, the colour error over the union of ink."""
    def ink(picture: np.ndarray) -> np.ndarray:  # channel by channel: numpy reduces a last axis of 3 slowly
        return (picture[..., 0] < 255.0 - 32) | (picture[..., 1] < 255.0 - 32) | (picture[..., 2] < 255.0 - 32)

    ink_a, ink_b = ink(ours), ink(theirs)
    union = ink_a | ink_b
    count = np.count_nonzero(union)
    if count == 0:
        return 1.0, 0.0
    return (float(np.count_nonzero(ink_a & ink_b) / count),
            float(np.abs(ours[union] - theirs[union]).mean() / 255.0))


def key_frames(a: Path, b: Path, size: int = SIZE) -> tuple[np.ndarray, np.ndarray]:
    """Frame 0 and the last frame of the morph ``a → b``, RGB over white."""
    scene = tr.load_scene([a, b])
    first = tr.frame(scene, 0.0, size=(size, size), background="#ffffff")
    last = tr.frame(scene, scene.duration, size=(size, size), background="#ffffff")
    return first[..., :3].astype(float), last[..., :3].astype(float)


def name(a: Path, b: Path) -> str:
    return f"{a.parent.name}/{a.stem} -> {b.parent.name}/{b.stem}"


def test_the_pairs_span_every_set_and_the_hard_cases() -> None:
    assert {a.parent for a, _ in PAIRS} | {b.parent for _, b in PAIRS} == set(SETS)
    assert len(ALL_PAIRS) >= 450 and len(PAIRS) >= 120
    text = {p: p.read_text() for pair in PAIRS for p in pair}
    assert any(_evenodd_at_second_key(text[a], text[b]) for a, b in PAIRS)
    assert any(_many_elements_and_colours(text[a]) for a, _ in PAIRS)


@needs_rsvg
def test_every_key_frame_is_its_drawing() -> None:
    scores = []
    for a, b in PAIRS:
        first, last = key_frames(a, b)
        scores.append((name(a, b) + " @0", *measures(first, reference(a))))
        scores.append((name(a, b) + " @end", *measures(last, reference(b))))
    good = [s for s in scores if s[1] >= 0.99 and s[2] <= 0.02]
    worst = sorted(scores, key=lambda s: s[1] - s[2])[:8]
    report = "; ".join(f"{n}: IoU {iou:.3f} error {err:.3f}" for n, iou, err in worst)
    assert len(good) >= 0.98 * len(scores), f"{len(scores) - len(good)} of {len(scores)} key frames off: {report}"
    assert min(s[1] for s in scores) >= 0.95, report


@needs_rsvg
def test_the_measure_fails_a_key_frame_that_is_not_the_drawing() -> None:
    """The test above can fail: the first icon's picture compared with the second's scores low."""
    a, b = ICONS / "mdi" / "alpha-a.svg", ICONS / "mdi" / "alpha-o-box.svg"
    first, _ = key_frames(a, b)
    iou, error = measures(first, reference(b))
    assert iou < 0.9 and error > 0.02


def _last_key_like(a: str, b: str) -> tuple[float, float]:
    first, last = key_frames(ICONS / a, ICONS / b)
    return measures(last, reference(ICONS / b))


@needs_rsvg
@pytest.mark.parametrize("a, b", [("feather/check.svg", "feather/heart.svg"),
                                  ("tabler/circle-check.svg", "tabler/sun.svg")])
def test_a_contour_without_a_partner_leaves_no_stroked_dot_at_the_key(a: str, b: str) -> None:
    # the check's second contour has none in the heart: it shrinks to a point, which a stroke drew as a dot
    iou, error = _last_key_like(a, b)
    assert iou >= 0.99 and error <= 0.02, (iou, error)


@needs_rsvg
@pytest.mark.parametrize("a, b", [("mdi/alpha-a.svg", "mdi/alpha-o-box.svg"),
                                  ("feather/smile.svg", "bootstrap/emoji-smile.svg")])
def test_holes_stay_holes_whatever_the_winding_of_their_partner(a: str, b: str) -> None:
    # the partners' windings differ, so the balanced contours of the second key ran the other way
    iou, error = _last_key_like(a, b)
    assert iou >= 0.99 and error <= 0.02, (iou, error)


@needs_rsvg
def test_the_second_key_keeps_its_own_evenodd_fill_rule() -> None:
    assert "evenodd" in (ICONS / "heroicons" / "check-circle.svg").read_text()
    assert "evenodd" not in (ICONS / "bootstrap" / "apple.svg").read_text()
    iou, error = _last_key_like("bootstrap/apple.svg", "heroicons/check-circle.svg")
    assert iou >= 0.99 and error <= 0.02, (iou, error)


@needs_rsvg
def test_the_second_key_keeps_its_own_stroke_ends() -> None:
    # mdi's filled A becomes feather's round-capped check: its stroke ends are the check's, not square
    iou, error = _last_key_like("mdi/alpha-a.svg", "feather/check.svg")
    assert iou >= 0.99 and error <= 0.02, (iou, error)


@needs_rsvg
@pytest.mark.parametrize("a, b", [("twemoji/1f4c4.svg", "twemoji/1f69a.svg"), ("twemoji/1f60e.svg", "twemoji/1f69a.svg")])
def test_the_last_key_is_painted_in_its_own_order(a: str, b: str) -> None:
    # the page's and the face's elements are stacked otherwise than their partners in the truck
    iou, error = _last_key_like(a, b)
    assert iou >= 0.99 and error <= 0.02, (iou, error)


def _two_squares(folder: Path, first: str, second: str, x: float, paints: tuple[str, str] = ('fill="#ff0000"',
                                                                                 'fill="#0000ff"')) -> Path:
    squares = {"a": f'<rect id="a" x="{x}" y="4" width="2" height="2" {paints[0]}/>',
               "b": f'<rect id="b" x="8.5" y="4" width="2" height="2" {paints[1]}/>'}
    path = folder / f"{first}{second}{x}.svg"
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 20 10">{squares[first]}{squares[second]}</svg>')
    return path


def test_the_order_switches_once_where_the_swapped_elements_overlap_least(tmp_path: Path) -> None:
    """Square a (x from 4 to 14, side 2) passes over the still square b (x 8.5 to 10.5); a is under b
    in the first drawing, over it in the second. They overlap while 6.5 < x < 10.5, i.e. for
    0.25 < t < 0.65: the overlap is 0 from t = 0.65 on, and of the t = k/32 where it is 0 the one
    nearest 0.5 is 21/32 (8/32, the last before, is farther)."""
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob

    scene = tr.load_scene([_two_squares(tmp_path, "a", "b", 4), _two_squares(tmp_path, "b", "a", 14)])
    drawer = Frames(RenderJob(scene))
    (switch,) = drawer.stacking
    assert switch.t == 21 / 32
    names = [s.name for s in scene.shapes]
    assert [names[i] for i in switch.before] == ["a", "b"] and [names[i] for i in switch.after] == ["b", "a"]
    assert switch.areas[8] > 0 and switch.areas[19] > 0 and switch.areas[20] == 0 and switch.areas[6] == 0  # t = (i+1)/32
    # at t = 0.5 (a at x 9, over b's left half) b is still painted over a; at the keys each its own
    size = (200, 100)
    middle = tr.frame(scene, 0.5, size=size)
    assert tuple(middle[50, 95, :3]) == (0, 0, 255)  # x = 9.5, inside both: b's blue on top
    assert tuple(drawer.order_at(0.0)) == switch.before and tuple(drawer.order_at(1.0)) == switch.after


@pytest.mark.parametrize("paints, counted", [(('fill="#000000"', 'fill="#000000"'), False),
                                             (('fill="#000000"', 'fill="#000" stroke="#000000"'), False),
                                             (('fill="#000000"', 'fill="#000000" fill-opacity="0.5"'), True),
                                             (('fill="#000000"', 'fill="#000001"'), True)])
def test_the_overlap_of_elements_is_counted_only_where_their_order_shows(tmp_path: Path, monkeypatch, paints,  # type: ignore[no-untyped-def]
                                                                         counted: bool) -> None:
    """Two elements of one opaque colour draw the same picture in either order (source-over of one colour is
    symmetric): the switch does not count where they overlap, and falls at t = 1/2. Another colour, or a
    translucent one, shows which is on top: the overlap is counted as above."""
    import tweenrender.core.stacking as stacking
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob

    calls = []
    counting = stacking.overlap_area
    monkeypatch.setattr(stacking, "overlap_area", lambda *a: calls.append(1) or counting(*a))
    scene = tr.load_scene([_two_squares(tmp_path, "a", "b", 4, paints), _two_squares(tmp_path, "b", "a", 14, paints)])
    (switch,) = Frames(RenderJob(scene)).stacking
    assert (len(calls) == 31, switch.t) == ((True, 21 / 32) if counted else (False, 16 / 32))


@pytest.mark.parametrize("a, b", [("octicons/smiley-24.svg", "tabler/letter-a.svg"),
                                  ("fluent-emoji/potato.svg", "fluent-emoji/olive.svg"),
                                  ("twemoji/1f4c4.svg", "twemoji/1f69a.svg"), ("twemoji/1f4c4.svg", "twemoji/1f600.svg")])
def test_at_a_key_the_order_is_the_plans_without_working_it_out(a: str, b: str, monkeypatch) -> None:
    """Every switch falls strictly between two key times, so at a key the paint order is the one the whole
    plan gives there (checked against the plan itself, on pairs whose keys are stacked otherwise than the
    scene and one with no switch at all), and a still of a key works no plan out (it took one: every
    swapped pair's overlap at 31 t)."""
    import tweenrender.core.stacking as stacking
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob

    scene = tr.load_scene([ICONS / a, ICONS / b])
    planned = Frames(RenderJob(scene))
    for time in (0.0, scene.duration):
        assert stacking.order_at_key(scene.shapes, time) == stacking.order_at(planned.stacking, scene.shapes, time)
    assert stacking.order_at_key(scene.shapes, 0.5 * scene.duration) is None
    import tweenrender.plan.job as job

    plans = []
    working = job.stacking_plan
    monkeypatch.setattr(job, "stacking_plan", lambda *args: plans.append(1) or working(*args))
    for time in (0.0, scene.duration):
        tr.frame(tr.load_scene([ICONS / a, ICONS / b]), time, size=(64, 64))
    assert plans == []
    tr.frame(tr.load_scene([ICONS / a, ICONS / b]), 0.5 * scene.duration, size=(64, 64))
    assert plans == [1] or not stacking.layered(scene.shapes)
