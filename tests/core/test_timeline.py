"""Timelines through the library: easing curves by their closed forms, segments, times outside the keys.

A square slides 10 units right between keys at 1 s and 3 s (the segment does not start
at 0), so its x offset at time ``1 + 2u`` is ``10·e(u)`` for the segment's easing ``e``:
``in`` t², ``out`` 1 − (1 − t)², ``in-out`` 3t² − 2t³ (smoothstep), ``linear`` t.
"""

from __future__ import annotations

import numpy as np
import pytest

import tweenrender as tr

SQ = [[0, 0], [2, 0], [2, 2], [0, 2]]
EASINGS = {
    "linear": lambda u: u,
    "in": lambda u: u * u,
    "out": lambda u: 1 - (1 - u) ** 2,
    "in-out": lambda u: 3 * u * u - 2 * u ** 3,
}


def _scene(tmp_path, keys: list[tuple[float, list[list[float]], str]]) -> tr.Scene:
    text = 'size = [64, 48]\n[[shape]]\nname = "s"\nmethod = "linear"\n'
    for time, points, ease in keys:
        text += f'[[shape.key]]\ntime = {time}\npoints = {points}\nease = "{ease}"\n'
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return tr.load_scene(path)


def _shifted(dx: float, dy: float = 0.0) -> list[list[float]]:
    return [[x + dx, y + dy] for x, y in SQ]


@pytest.mark.parametrize("kind", sorted(EASINGS))
def test_each_easing_is_its_closed_form(tmp_path, kind: str) -> None:
    scene = _scene(tmp_path, [(1.0, SQ, kind), (3.0, _shifted(10), "linear")])
    for u in (0.1, 0.25, 0.5, 0.6, 0.9):
        (outline,) = tr.outlines(scene, 1.0 + 2.0 * u)
        offset = outline - np.array(SQ, float)
        assert offset[:, 0] == pytest.approx(np.full(4, 10 * EASINGS[kind](u)), abs=1e-12)
        assert offset[:, 1] == pytest.approx(np.zeros(4), abs=1e-12)


def test_in_is_slow_then_fast_and_out_the_mirror(tmp_path) -> None:
    """Whatever the formulas: "in" starts slowly (behind the linear path), "out" ends slowly (ahead of it)."""
    ahead = {}
    for kind in ("in", "out", "in-out"):
        scene = _scene(tmp_path, [(1.0, SQ, kind), (3.0, _shifted(10), "linear")])
        ahead[kind] = [float(tr.outlines(scene, 1.0 + 2.0 * u)[0][0, 0]) - 10 * u for u in (0.25, 0.75)]
    assert ahead["in"][0] < 0 and ahead["in"][1] < 0
    assert ahead["out"][0] > 0 and ahead["out"][1] > 0
    assert ahead["in-out"][0] < 0 < ahead["in-out"][1]  # slow at both ends: behind, then ahead


def test_each_segment_eases_by_the_key_that_starts_it(tmp_path) -> None:
    scene = _scene(tmp_path, [(0.0, SQ, "in"), (1.0, _shifted(10), "out"), (2.0, _shifted(20), "linear")])
    assert tr.outlines(scene, 0.25)[0][0, 0] == pytest.approx(10 * 0.25 ** 2)
    assert tr.outlines(scene, 1.25)[0][0, 0] == pytest.approx(10 + 10 * (1 - 0.75 ** 2))


def test_before_the_first_key_and_after_the_last_the_keys_hold(tmp_path) -> None:
    scene = _scene(tmp_path, [(1.0, SQ, "linear"), (3.0, _shifted(10, 4), "linear")])
    for time in (0.0, 0.5, 0.999):
        assert np.array_equal(tr.outlines(scene, time)[0], np.array(SQ, float))
    for time in (3.001, 4.0, 100.0):
        assert np.array_equal(tr.outlines(scene, time)[0], np.array(_shifted(10, 4), float))


def test_at_a_key_time_the_key_is_shown_as_drawn(tmp_path) -> None:
    """Between a square and a triangle the balanced keys have extra (repeated) vertices; at the
    triangle's own time, where the next segment (triangle to triangle) starts, it is drawn as drawn."""
    triangle = [[5, 0], [7, 0], [6, 2]]
    moved = [[x + 5, y] for x, y in triangle]
    scene = _scene(tmp_path, [(0.0, SQ, "linear"), (1.0, triangle, "linear"), (2.0, moved, "linear")])
    (at_key,) = tr.outlines(scene, 1.0)
    assert np.array_equal(at_key, np.array(triangle, float))
    (inbetween,) = tr.outlines(scene, 0.5)
    assert len(inbetween) >= 4  # the first segment's balanced count


def test_the_last_key_has_its_frame(tmp_path) -> None:
    """Frames run from time 0 to the last key, both included."""
    scene = _scene(tmp_path, [(0.0, SQ, "linear"), (2.0, _shifted(10), "linear")])
    pictures = list(tr.frames(scene, fps=4))
    assert len(pictures) == 9
    last = pictures[-1][..., :3].astype(int)
    assert np.array_equal(last, tr.frame(scene, 2.0)[..., :3].astype(int))
    assert not np.array_equal(pictures[-2], pictures[-1])


@pytest.mark.parametrize("duration, fps, count", [(2.0, 4, 9), (1.01, 24, 26), (1.99, 4, 9), (2.1, 4, 10),
                                                  (0.1 * 3, 10, 4), (1 / 3, 3, 2), (0.0, 24, 1)])
def test_the_last_frame_is_the_last_key_when_it_falls_between_frames(tmp_path, duration: float, fps: float,
                                                                     count: int) -> None:
    """ceil(T · fps − 1e-9) + 1 frames (DESIGN, "Frames and the last key"): a last key between two
    frame times gets the later one, which shows it; 0.1·3·10 and (1/3)·3 are whole in exact arithmetic."""
    keys = [(0.0, SQ, "linear")] + ([(duration, _shifted(10), "linear")] if duration else [])
    scene = _scene(tmp_path, keys)
    pictures = list(tr.frames(scene, fps=fps))
    assert len(pictures) == count
    assert np.array_equal(pictures[-1], tr.frame(scene, duration))


def test_a_scenes_tracks_are_built_once_for_its_shapes_matching_and_rules(tmp_path,
                                                                          monkeypatch: pytest.MonkeyPatch) -> None:
    """A report asks for one scene's tracks a dozen times: they are built once (counted), again only for
    other shapes, another matching or other rules, and are what building them anew gives."""
    from dataclasses import replace

    from tweenrender.core.timing import timeline

    built: list[str] = []
    original = timeline.build_track

    def counted(shape, *args, **kwargs):  # type: ignore[no-untyped-def]
        built.append(shape.name)
        return original(shape, *args, **kwargs)

    monkeypatch.setattr(timeline, "build_track", counted)
    path = tmp_path / "scene.toml"
    path.write_text(f'[[shape]]\nname = "s"\n[[shape.key]]\ntime = 0\npoints = {SQ}\n'
                    f'[[shape.key]]\ntime = 1\npoints = {_shifted(3, 1)}\n')
    scene = tr.load_scene(path)  # its shape drawn by the scene's method
    first = timeline.tracks_of(scene)
    assert timeline.tracks_of(scene) is first and built == ["s"]
    assert timeline.tracks_of(replace(scene, view=(0.0, 0.0, 9.0, 9.0), fps=12.0)) is first and built == ["s"]
    assert timeline.tracks_of(replace(scene, method="rigid")) is not first and built == ["s", "s"]
    timeline.tracks_of(scene, replace(scene.matching, cost="sg"))
    timeline.tracks_of(replace(scene, balance="spread"))
    timeline.tracks_of(replace(scene, shapes=tuple(scene.shapes)[::-1]))  # an equal tuple, not the same one
    assert built == ["s"] * 5
    fresh = original(scene.shapes[0], scene.matching, unmatched=scene.unmatched,
                     balance=scene.balance_of(scene.shapes[0]), method=scene.method_of(scene.shapes[0]))
    (segment,), (again,) = first[0].segments, fresh.segments
    assert np.array_equal(segment.pairs[0].k0, again.pairs[0].k0)
    assert np.array_equal(segment.pairs[0].k1, again.pairs[0].k1)
