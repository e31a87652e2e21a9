"""Vector export's work grows linearly with the frames of a clip: the same motion sampled four times as
finely costs about four times the values measured (counted, not timed) by the keyframe fit alone and by a
whole export (the fits of curves, path keyframes and paint keyframes). Quadratic work (a span's end searched
one frame at a time, each try measuring every frame of the span) would cost sixteen times."""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import write_scene
from tweenrender.vector import curves, keyframes

LINEAR = 4.5
"""At most this many times the work for four times the frames (4: exactly linear; the work of the searches
varies a little with how the frames fall)."""


def _counting(monkeypatch: pytest.MonkeyPatch) -> Counter[str]:
    """Count the values each measuring step of the fit evaluates: frames × ends × vertices."""
    work: Counter[str] = Counter()

    def wrap(module: Any, name: str, cost: Callable[..., int]) -> None:
        inner = getattr(module, name)

        def counted(*args: Any, **kwargs: Any) -> Any:
            work[name] += cost(*args, **kwargs)
            return inner(*args, **kwargs)

        monkeypatch.setattr(module, name, counted)

    wrap(keyframes, "_room", lambda values, a, start, ends, eases, limit, between=None:
         len(ends) * (int(max(ends)) - a if between is None else len(between)) * values.shape[1])
    wrap(keyframes, "_within", lambda values, a, b, *_: (b - a) * values.shape[1])
    wrap(keyframes, "_farthest", lambda values, a, *_: (len(values) - a) * values.shape[1])
    wrap(curves, "curve_error", lambda controls, u, polyline: polyline.shape[0] * polyline.shape[1])
    return work


def _turning(frames: int) -> np.ndarray:
    """Twelve points of a ring of radius 100 px turning a quarter turn, eased in and out, while it swells and
    shrinks back: ``(F, 12, 2)``."""
    t = np.linspace(0.0, 1.0, frames)[:, None]
    angle = np.linspace(0, 2 * np.pi, 12, endpoint=False)[None] + np.pi / 2 * (3 * t ** 2 - 2 * t ** 3)
    radius = 100 + 20 * np.sin(np.pi * t)
    return np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=-1)


def test_keyframe_fit_work_is_linear_in_frames(monkeypatch: pytest.MonkeyPatch) -> None:
    work = _counting(monkeypatch)
    counts = []
    for frames in (241, 961):
        work.clear()
        fitted = keyframes.fit_keyframes(_turning(frames), 0.2)
        assert keyframes.max_deviation(_turning(frames), fitted) <= 0.2
        counts.append(sum(work.values()))
    assert counts[1] <= LINEAR * counts[0], f"work {counts[0]} for 241 frames, {counts[1]} for 961"


SCENE = """size = [320, 320]
fps = 60
view = [0, 0, 10, 10]
method = "{method}"
[[shape]]
name = "blob"
fill = "#336699"
[[shape.key]]
time = 0
points = [[2, 2], [5, 1.5], [8, 2], [8.5, 5], [8, 8], [5, 8.5], [2, 8], [1.5, 5]]
[[shape.key]]
time = {seconds}
points = [[5, 1], [7, 3], [9, 5], [7, 7], [5, 9], [3, 7], [1, 5], [3, 3]]
"""


@pytest.mark.parametrize("method", ["nonlinear", "rigid"])
def test_export_work_is_linear_in_frames(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, method: str) -> None:
    work = _counting(monkeypatch)
    counts = []
    for seconds in (2, 8):  # 121 and 481 frames of the same motion
        scene = tr.load_scene(write_scene(tmp_path, SCENE.format(seconds=seconds, method=method), f"{seconds}.toml"))
        work.clear()
        tr.write(scene, tmp_path / f"{seconds}.json")
        counts.append(sum(work.values()))
    assert counts[1] <= LINEAR * counts[0], f"work {counts[0]} for 121 frames, {counts[1]} for 481"


@pytest.mark.parametrize("suffix", [".json", ".svg"])
def test_a_vector_file_past_the_sample_limit_is_refused_before_any_work(cli, tmp_path: Path, suffix: str) -> None:
    """A vector file samples every vertex at every frame before reducing them to keyframes: a triangle over
    three days at 24 fps (6.2 million frames, allowed by ``--max-frames``) would hold 19 million vertex samples
    (the old export took minutes to write it). It is refused at once, in one line naming the limit, and nothing is written."""
    scene = tmp_path / "long.toml"
    scene.write_text('size = [64, 64]\n[[shape]]\nname = "t"\n[[shape.key]]\ntime = 0.0\n'
                     'points = [[0, 0], [1, 0], [0, 1]]\n[[shape.key]]\ntime = 259200.0\n'
                     'points = [[0, 0], [2, 0], [0, 2]]\n')
    out = tmp_path / f"long{suffix}"
    sampled = []
    monkeypatch = pytest.MonkeyPatch()
    from tweenrender.core.timing import timeline

    at = timeline.Track.at

    def counting(self, times, *args, **kwargs):  # noqa: ANN001, ANN002, ANN003, ANN202
        sampled.append(len(times))
        return at(self, times, *args, **kwargs)

    monkeypatch.setattr(timeline.Track, "at", counting)
    try:
        code, _, err = cli("render", scene, "-o", out, "--max-frames", "10000000", "-q")
    finally:
        monkeypatch.undo()
    assert code == 2, err
    assert err.count("\n") == 1 and "vector" in err and "10,000,000" in err, err
    assert max(sampled, default=0) < 100 and not out.exists()  # the view's few probes at most, no frame


GROWING = """size = [400, 300]
fps = 20
view = [0, 0, 40, 30]
method = "linear"
[[shape]]
name = "squares"
fill = "#3366cc"
[[shape.key]]
time = 0
contours = [[[10, 10], [14, 10], [14, 14], [10, 14]]{first_extra}]
[[shape.key]]
time = 2
contours = [[[12, 10], [16, 10], [16, 14], [12, 14]], [[25, 18], [35, 18], [35, 28], [25, 28]]]
"""


@pytest.mark.parametrize("grows, fitted", [(True, 1), (False, 2)])
def test_contours_off_their_straight_path_are_not_fitted_for_two_keyframes(tmp_path: Path,
                                                                          monkeypatch: pytest.MonkeyPatch,
                                                                          grows: bool, fitted: int) -> None:
    """Between two keys of a ``linear`` segment a contour may take two keyframes only where its vertices stay
    within the bound (0.25 px) of the straight line between their keys at every frame. A square that grows from a
    point with its area even in time is scaled by about the square root of the time: a corner 50 px from the
    point (10 px a unit) leaves its chord by up to a quarter of that, 12 px, so it is not fitted for two keyframes
    (it was fitted, then the fit thrown away); the square that moves is, and keeps its two. Where both squares
    move (the second key's big square has a partner), both are fitted."""
    import json

    from tweenrender.vector import export

    calls = []
    fewest = export._fewest_cubics
    monkeypatch.setattr(export, "_fewest_cubics", lambda *args, **kwargs: calls.append(1) or fewest(*args, **kwargs))
    extra = "" if grows else ", [[20, 14], [30, 14], [30, 24], [20, 24]]"
    scene = tr.load_scene(write_scene(tmp_path, GROWING.format(first_extra=extra)))
    document = json.loads(tr.write(scene, tmp_path / "squares.json").read_text())
    assert len(calls) == fitted
    paths = [item for layer in document["layers"] if layer["nm"] != "background"
             for group in layer["shapes"] for item in group.get("it", []) if item["ty"] == "sh"]
    assert len(paths[0]["ks"]["k"]) == 2  # the moving square, straight between its keys


def test_a_blended_span_solves_its_least_squares_once_for_all_its_slides(monkeypatch: pytest.MonkeyPatch) -> None:
    """A span fitted between two keys is fitted at one set of parameters, then refitted four times to the points its
    cubics pass nearest (the slides): the least-squares map depends on the parameters alone, so it is worked out
    once a span (one 2 × 2 pseudo-inverse), not once a fit (five)."""
    slides, inverses = [], []
    slid, pinv = curves._slid_keys, np.linalg.pinv
    monkeypatch.setattr(curves, "_slid_keys", lambda *args: slides.append(1) or slid(*args))
    monkeypatch.setattr(np.linalg, "pinv", lambda *args, **kwargs: inverses.append(1) or pinv(*args, **kwargs))
    frames = _turning(25)
    curves.fit_curves(frames, True, 0.25, blend=curves.Blend(0, 24, np.linspace(0.0, 1.0, 25)))
    assert slides and len(inverses) <= len(slides), (len(inverses), len(slides))
