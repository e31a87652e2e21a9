"""Timing curves against independent facts: each Bézier sampled densely in its own parametric form,
CSS steps by the spec's own definition written as a loop, spacing charts through their ticks, and
frames of a scene landing where the curve says."""

from __future__ import annotations

import math

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.core.timing.easing import CubicBezier, EasingSyntaxError, Hold, Steps, parse_easing
from tweenrender.core.timing.spacing import SpacingError, fritsch_carlson_tangents, spacing_chart

CURVES = [
    "ease", "ease-in", "ease-out", "ease-in-out", "in", "out", "in-out",
    "cubic-bezier(0.25, 0.1, 0.25, 1)", "cubic-bezier(0.68, -0.55, 0.265, 1.55)",  # overshoot both ways
    "cubic-bezier(0, 1, 1, 0)", "cubic-bezier(0.9, 0, 0.1, 1)",  # x(s) flat at the ends, nearly flat mid-way
    "cubic-bezier(0.1, 3, 0.9, -2)", "cubic-bezier(0, 0, 1, 1)",
]


def _xy(s: np.ndarray, x1: float, y1: float, x2: float, y2: float) -> tuple[np.ndarray, np.ndarray]:
    """The curve's own parametric form (x(s), y(s))."""
    r = 1.0 - s
    return 3 * r * r * s * x1 + 3 * r * s * s * x2 + s ** 3, 3 * r * r * s * y1 + 3 * r * s * s * y2 + s ** 3


def _dense_reference(x1: float, y1: float, x2: float, y2: float, u: np.ndarray) -> np.ndarray:
    """y where x = u, from the curve sampled at a million values of s, interpolated in x: no Newton."""
    x, y = _xy(np.linspace(0.0, 1.0, 1_000_001), x1, y1, x2, y2)
    return np.interp(u, x, y)


def _dense_bracket(x1: float, y1: float, x2: float, y2: float, u: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """For each u, the y values of two samples of the curve whose x bracket u, found by sampling alone:
    10 001 values of s, then 10 001 between the bracketing pair, twice more. x is non-decreasing, so
    y at x = u lies between them however steep y is in x there."""
    low_s, high_s = np.zeros_like(u), np.ones_like(u)
    for _ in range(4):
        s = low_s[:, None] + (high_s - low_s)[:, None] * np.linspace(0.0, 1.0, 10_001)[None]  # (U, 10001)
        x, _ = _xy(s, x1, y1, x2, y2)
        left = np.clip((x <= u[:, None]).sum(axis=1) - 1, 0, s.shape[1] - 1)  # the last sample with x <= u
        right = np.clip(s.shape[1] - (x >= u[:, None]).sum(axis=1), 0, s.shape[1] - 1)  # the first with x >= u
        rows = np.arange(len(u))
        low_s, high_s = np.minimum(s[rows, left], s[rows, right]), np.maximum(s[rows, left], s[rows, right])
    _, y_low = _xy(low_s, x1, y1, x2, y2)
    _, y_high = _xy(high_s, x1, y1, x2, y2)
    return np.minimum(y_low, y_high), np.maximum(y_low, y_high)


@pytest.mark.parametrize("text", CURVES)
def test_cubic_bezier_matches_its_parametric_form_at_every_frame(text: str) -> None:
    curve = parse_easing(text)
    assert isinstance(curve, CubicBezier)
    u = np.arange(0, 24 * 3 + 1) / (24 * 3)  # every frame of a 3 s segment at 24 fps
    u = np.concatenate([u, np.arange(0, 61) / 60, [1e-9, 0.5, 1 - 1e-9]])
    got = curve(u)
    low, high = _dense_bracket(*curve.handles, u)
    assert np.max(high - low) < 9e-7  # the reference pins y to better than 1e-6 ...
    assert np.all(got >= low - 1e-7) and np.all(got <= high + 1e-7)  # ... and the solved y lies in it


def test_the_css_keywords_have_the_spec_handles() -> None:
    assert parse_easing("ease").handles == (0.25, 0.1, 0.25, 1.0)
    assert parse_easing("ease-in").handles == (0.42, 0.0, 1.0, 1.0)
    assert parse_easing("ease-out").handles == (0.0, 0.0, 0.58, 1.0)
    assert parse_easing("ease-in-out").handles == (0.42, 0.0, 0.58, 1.0)


@pytest.mark.parametrize("name, closed_form", [("in", lambda u: u * u), ("out", lambda u: 1 - (1 - u) ** 2),
                                                ("in-out", lambda u: 3 * u * u - 2 * u ** 3)])
def test_the_older_names_are_their_polynomials_and_their_beziers(name: str, closed_form) -> None:
    u = np.linspace(0, 1, 97)
    curve = parse_easing(name)
    assert curve(u) == pytest.approx(closed_form(u), abs=1e-15)
    assert _dense_reference(*curve.handles, u) == pytest.approx(closed_form(u), abs=1e-9)


def test_overshoot_leaves_zero_one_between_keys_only() -> None:
    curve = parse_easing("cubic-bezier(0.68, -0.55, 0.265, 1.55)")
    assert curve.overshoots
    values = curve(np.linspace(0, 1, 1001))
    assert values.min() < -0.05 and values.max() > 1.05
    assert values[0] == 0.0 and values[-1] == 1.0


def _css_steps(u: float, n: int, jump: str) -> float:
    """CSS Easing Level 1, 'the step easing function', for input progress u in [0, 1] (before flag unset)."""
    current = math.floor(u * n)
    if jump in ("jump-start", "jump-both"):
        current += 1
    jumps = {"jump-start": n, "jump-end": n, "jump-none": n - 1, "jump-both": n + 1}[jump]
    if current > jumps:
        current = jumps
    return current / jumps


@pytest.mark.parametrize("n, jump", [(n, jump) for n in (1, 2, 3, 5)
                                     for jump in ("jump-start", "jump-end", "jump-none", "jump-both")
                                     if not (jump == "jump-none" and n < 2)])  # CSS refuses steps(1, jump-none)
def test_steps_follow_css_strictly_between_keys(n: int, jump: str) -> None:
    curve = parse_easing(f"steps({n}, {jump})")
    u = np.arange(1, 240) / 240
    assert curve(u).tolist() == [_css_steps(float(x), n, jump) for x in u]
    assert curve(np.array([0.0, 1.0])).tolist() == [0.0, 1.0]  # the keys themselves


def test_steps_default_and_aliases() -> None:
    assert parse_easing("steps(4)") == Steps(4, "jump-end", "steps(4)")
    assert parse_easing("steps(4, start)").jump == "jump-start"
    assert parse_easing("steps(4,end)").jump == "jump-end"


def test_hold_keeps_the_first_key_until_the_next() -> None:
    assert isinstance(parse_easing("hold"), Hold)
    assert parse_easing("hold")(np.array([0.0, 0.3, 0.999999, 1.0])).tolist() == [0, 0, 0, 1]


@pytest.mark.parametrize("text, expected", [
    ("cubic-bezier(1.2, 0, 0.5, 1)", "x1 and x2 from 0 to 1"),
    ("cubic-bezier(0.2, 0, 0.5)", "four numbers"),
    ("steps(0)", "n from 1"),
    ("steps(1, jump-none)", "n from 2"),
    ("steps(3, middle)", "jump-start, jump-end"),
    ("bounce", "unknown easing"),
])
def test_bad_curves_say_what_was_expected(text: str, expected: str) -> None:
    with pytest.raises(EasingSyntaxError, match=expected):
        parse_easing(text)


# -- spacing charts ------------------------------------------------------------------------------


def test_spacing_passes_through_its_ticks_and_never_runs_back() -> None:
    ticks = [0, 0.02, 0.1, 0.1, 0.5, 0.9, 0.98, 1.0]
    chart = spacing_chart(ticks)
    m = len(ticks) - 1
    assert chart(np.arange(m + 1) / m).tolist() == ticks
    dense = chart(np.linspace(0, 1, 20001))
    assert np.all(np.diff(dense) >= -1e-15)
    # a flat interval stays flat: the two equal ticks hold between them
    assert np.all(chart(np.linspace(2 / m, 3 / m, 51)) == pytest.approx(0.1, abs=1e-15))


def test_evenly_spaced_ticks_are_linear() -> None:
    chart = spacing_chart([0, 0.25, 0.5, 0.75, 1])
    u = np.linspace(0, 1, 101)
    assert chart(u) == pytest.approx(u, abs=1e-15)


def test_fritsch_carlson_tangents_by_hand() -> None:
    # ticks 0, 0.1, 1 at 0, 1/2, 1: secants 0.2 and 1.8; ends take their secant, inside the mean 1.0.
    # First interval: alpha = 0.2/0.2 = 1, beta = 1.0/0.2 = 5, 1 + 25 > 9: both scaled by 3/sqrt(26)
    d = fritsch_carlson_tangents([0.0, 0.1, 1.0])
    tau = 3 / math.sqrt(26)
    assert d[0] == pytest.approx(tau * 1 * 0.2, rel=1e-12)
    assert d[1] == pytest.approx(tau * 5 * 0.2, rel=1e-12)
    # second interval: alpha = d1 / 1.8, beta = 1.8 / 1.8 = 1: inside the circle, kept
    assert d[2] == pytest.approx(1.8, rel=1e-12)


def test_a_subnormal_tick_is_drawn_as_a_flat_start() -> None:
    # a first secant of 2e-320 makes beta = d1 / delta0 overflow; the chart is then, within rounding,
    # that of [0, 0, 1]: flat to the middle, then tangents 0 and 2 on the second half, -h³ + 2h²
    import warnings

    with warnings.catch_warnings():
        warnings.simplefilter("error")
        chart = spacing_chart([0, 1e-320, 1])
        h = np.linspace(0, 1, 101)
        second_half = chart(0.5 + 0.5 * h)
        first_half = chart(0.5 * h)
    assert np.all(np.isfinite(chart.tangents))
    assert second_half == pytest.approx(-h ** 3 + 2 * h ** 2, abs=1e-12)
    assert np.all(np.abs(first_half) <= 1e-300)


@pytest.mark.parametrize("ticks, expected", [([0.1, 1], "0 first"), ([0, 0.5, 0.4, 1], "non-decreasing"),
                                             ([0], "at least two")])
def test_bad_spacing(ticks, expected) -> None:
    with pytest.raises(SpacingError, match=expected):
        spacing_chart(ticks)


# -- through a scene: frames land where the curve says -----------------------------------------


SQ = [[0, 0], [2, 0], [2, 2], [0, 2]]


def _slide(tmp_path, timing: str, fps: int = 24) -> tr.Scene:
    text = (f'size = [64, 48]\nfps = {fps}\n[[shape]]\nname = "s"\nmethod = "linear"\n'
            f'[[shape.key]]\ntime = 1.0\npoints = {SQ}\n{timing}\n'
            f'[[shape.key]]\ntime = 3.0\npoints = {[[x + 10, y] for x, y in SQ]}\n')
    path = tmp_path / "scene.toml"
    path.write_text(text)
    return tr.load_scene(path)


@pytest.mark.parametrize("timing, curve", [
    ('ease = "cubic-bezier(0.68, -0.55, 0.265, 1.55)"', lambda u: _dense_reference(0.68, -0.55, 0.265, 1.55, u)),
    ('ease = "steps(3, jump-both)"', lambda u: np.array([_css_steps(x, 3, "jump-both") for x in u])),
    ('ease = "hold"', lambda u: np.zeros_like(u)),
])
def test_frames_land_where_the_curve_says(tmp_path, timing: str, curve) -> None:
    scene = _slide(tmp_path, timing)
    frames = np.arange(25, 72)  # strictly inside the segment (1 s to 3 s at 24 fps)
    u = (frames / 24 - 1.0) / 2.0
    x = np.array([tr.outlines(scene, f / 24)[0][0, 0] for f in frames])
    assert x == pytest.approx(10 * curve(u), abs=1e-5)
    assert tr.outlines(scene, 1.0)[0][0, 0] == 0.0 and tr.outlines(scene, 3.0)[0][0, 0] == 10.0


@pytest.mark.parametrize("fps", [24, 30, 7])
def test_spacing_chart_frames_at_any_fps(tmp_path, fps: int) -> None:
    ticks = [0, 0.05, 0.2, 0.5, 0.8, 0.95, 1]
    scene = _slide(tmp_path, f"spacing = {ticks}", fps)
    for k, tick in enumerate(ticks):  # the ticks fall at 1 + 2k/6 seconds whatever the frame rate
        assert tr.outlines(scene, 1.0 + 2.0 * k / 6)[0][0, 0] == pytest.approx(10 * tick, abs=1e-12)
    times = 1.0 + np.arange(0, 2 * fps + 1) / fps
    x = [tr.outlines(scene, t)[0][0, 0] for t in times]
    assert np.all(np.diff(x) >= -1e-12)


def test_scene_level_ease_is_every_keys_default(tmp_path) -> None:
    text = ('ease = "ease-out"\n[[shape]]\nname = "s"\nmethod = "linear"\n'
            f'[[shape.key]]\ntime = 0\npoints = {SQ}\n[[shape.key]]\ntime = 1\npoints = {[[x + 10, y] for x, y in SQ]}\n'
            f'ease = "linear"\n[[shape.key]]\ntime = 2\npoints = {[[x + 20, y] for x, y in SQ]}\n')
    path = tmp_path / "s.toml"
    path.write_text(text)
    scene = tr.load_scene(path)
    assert scene.shapes[0].keys[0].ease == "ease-out"
    want = 10 * _dense_reference(0.0, 0.0, 0.58, 1.0, np.array([0.25]))[0]
    assert tr.outlines(scene, 0.25)[0][0, 0] == pytest.approx(want, abs=1e-6)
    assert tr.outlines(scene, 1.25)[0][0, 0] == pytest.approx(12.5, abs=1e-12)  # its own ease wins


def test_overshoot_moves_the_shape_past_the_keys_and_a_growing_contour_never_inverts(tmp_path) -> None:
    ring = [[[0, 0], [8, 0], [8, 8], [0, 8]], [[2, 2], [2, 6], [6, 6], [6, 2]]]
    text = ('[[shape]]\nname = "s"\nmethod = "linear"\n'
            f'[[shape.key]]\ntime = 0\ncontours = {ring[:1]}\nease = "cubic-bezier(0.5, -1, 0.5, 2)"\n'
            f'[[shape.key]]\ntime = 2\ncontours = {[[[x + 10, y] for x, y in c] for c in ring]}\n')
    path = tmp_path / "s.toml"
    path.write_text(text)
    scene = tr.load_scene(path)
    times = np.linspace(0, 2, 49)
    eased = CubicBezier(0.5, -1, 0.5, 2)(times / 2)
    assert eased.min() < -0.1 and eased.max() > 1.1
    sizes = []
    for time, t in zip(times, eased):
        outer, *hole = tr.outlines(scene, float(time))
        assert outer[0, 0] == pytest.approx(10 * t, abs=1e-6)  # the outer overshoots both ways
        if t <= 0:  # the hole has not begun to grow: nothing of it, never a hole turned inside out
            assert not hole or np.ptp(hole[0], axis=0).max() == 0.0
        size = np.ptp(hole[0], axis=0) if hole else np.zeros(2)
        assert size[0] == pytest.approx(size[1], rel=1e-12)  # a square, scaled
        if size[0] > 0:  # inside the outer while it grows (the outer's x-range is [10t, 10t + 8])
            assert hole[0][:, 0].min() > 10 * t and hole[0][:, 0].max() < 10 * t + 8
        sizes.append(size[0])
    # its area is linear in the eased t from its start on (the key's side is 4): side = 4 √((t - s) / (1 - s))
    sizes = np.array(sizes)
    grown = np.flatnonzero(sizes > 0)
    share = (sizes[grown[0]] / 4) ** 2
    start = (eased[grown[0]] - share) / (1 - share)
    assert 0.0 <= start < 0.9
    np.testing.assert_allclose(sizes, 4 * np.sqrt(np.clip((eased - start) / (1 - start), 0, None)), rtol=1e-9,
                               atol=1e-12)


@pytest.mark.parametrize("method", ["linear", "nonlinear", "rigid", "jointed", "arap", "intrinsic", "auto"])
def test_every_method_follows_an_overshoot_without_nan(tmp_path, method: str) -> None:
    from pathlib import Path

    walk = (Path(__file__).parents[2] / "scenes" / "walk.toml").read_text()
    path = tmp_path / "walk.toml"
    import re

    walk = re.sub(r"^ease = .*$", "", walk, flags=re.MULTILINE)  # every key takes the scene's curve
    path.write_text('ease = "cubic-bezier(0.6, -0.8, 0.4, 1.8)"\n' + walk)
    scene = tr.load_scene(path)
    assert all(key.ease == "cubic-bezier(0.6, -0.8, 0.4, 1.8)" for key in scene.shapes[0].keys)
    for time in np.linspace(0, scene.duration, 25):
        for contour in tr.outlines(scene, float(time), method=method):
            assert np.all(np.isfinite(contour))
    # the first segment, where its curve dips lowest (t < 0): the shape has moved back past its first key
    keys = scene.shapes[0].keys
    u = np.linspace(0, 1, 2001)
    low = u[np.argmin(CubicBezier(0.6, -0.8, 0.4, 1.8)(u))]
    time = keys[0].time + low * (keys[1].time - keys[0].time)
    if method == "linear":
        t = float(CubicBezier(0.6, -0.8, 0.4, 1.8)(np.array([low]))[0])
        assert t < -0.1
        want = keys[0].points + t * (keys[1].points - keys[0].points)
        assert tr.outlines(scene, time, method=method)[0] == pytest.approx(want, abs=1e-9)


def test_injective_overshoots_rigidly_with_its_weights_clamped(tmp_path) -> None:
    """Past a key, injective keeps that key's shape (its weights stop at 0) while its frame moves on."""
    k0 = [[0, 0], [4, 0], [4, 1], [1, 1], [1, 3], [0, 3]]
    k1 = [[10, 0], [13, 0], [13, 3], [12, 3], [12, 1], [11, 1], [10, 1]]
    text = ('[[shape]]\nname = "s"\nmethod = "injective"\n'
            f'[[shape.key]]\ntime = 0\npoints = {k0}\nease = "cubic-bezier(0.6, -0.8, 0.4, 1.8)"\n'
            f'[[shape.key]]\ntime = 2\npoints = {k1}\n')
    path = tmp_path / "s.toml"
    path.write_text(text)
    scene = tr.load_scene(path)
    curve = CubicBezier(0.6, -0.8, 0.4, 1.8)
    u = np.linspace(0, 1, 2001)
    low = float(u[np.argmin(curve(u))])
    assert curve(np.array([low]))[0] < -0.1
    first = tr.outlines(scene, 1e-9)[0]  # t just above 0: the balanced first key, as the mesh holds it
    past = tr.outlines(scene, 2 * low)[0]

    def gaps(points: np.ndarray) -> np.ndarray:
        return np.linalg.norm(points[:, None] - points[None], axis=-1)

    assert np.all(np.isfinite(past))
    assert gaps(past) == pytest.approx(gaps(first), abs=1e-6)  # the same shape ...
    assert not np.allclose(past.mean(axis=0), first.mean(axis=0), atol=1e-3)  # ... moved back past the key
