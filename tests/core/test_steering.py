"""Steering by the scene (maths §5.13–5.15): turn direction and whole turns, arcs through a point,
breakdown keys — each against a closed form: rigid turns in complex numbers, arc-length shares,
straight lines split at their own point."""

from __future__ import annotations

import cmath
import math

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.core.geometry import perimeter

SQUARE = [[0, 0], [2, 0], [2, 2], [0, 2]]
TURNED = [[7, 1], [7, 3], [5, 3], [5, 1]]  # the square turned +90° about its centre and moved (thesis fig. 6.1)
RIGID_METHODS = ("rigid", "nonlinear", "arap", "intrinsic", "intrinsic-length", "injective", "jointed")


def _points(points) -> str:
    return "[" + ", ".join(f"[{float(x)!r}, {float(y)!r}]" for x, y in points) + "]"


def _scene(first: str = "", method: str = "rigid", keys=(SQUARE, TURNED), times=(0, 2), middle: str = ""):
    text = f'method = "{method}"\n[[shape]]\nname = "s"\n'
    if method == "jointed":
        text += "joints = [[0, 2]]\n"
    text += f"[[shape.key]]\ntime = {times[0]}\npoints = {_points(keys[0])}\n{first}\n"
    text += middle
    text += f"[[shape.key]]\ntime = {times[1]}\npoints = {_points(keys[1])}\n"
    return tr.parse_scene(text, "steer.toml")


def _rigid_turn(points, centre_from, centre_to, t: float, angle: float) -> np.ndarray:
    """The closed form: the centre moves straight, every spoke turns by ``t·angle`` (complex numbers)."""
    c0, c1 = complex(*centre_from), complex(*centre_to)
    centre = (1 - t) * c0 + t * c1
    out = [centre + cmath.exp(1j * t * angle) * (complex(x, y) - c0) for x, y in points]
    return np.array([[z.real, z.imag] for z in out])


@pytest.mark.parametrize("method", RIGID_METHODS)
def test_clockwise_turns_the_long_way(method: str) -> None:
    scene = _scene('turn = "cw"', method)
    for t in (0.25, 0.5, 0.75):
        expected = _rigid_turn(SQUARE, (1, 1), (6, 2), t, -1.5 * math.pi)  # −270°
        np.testing.assert_allclose(tr.outlines(scene, 2 * t)[0], expected, atol=1e-9)
        assert float(perimeter(tr.outlines(scene, 2 * t)[0])) / 8 == pytest.approx(1.0, abs=5e-6)
    np.testing.assert_array_equal(tr.outlines(scene, 0)[0], SQUARE)
    np.testing.assert_array_equal(tr.outlines(scene, 2)[0], TURNED)


def test_the_mid_frame_of_a_clockwise_turn_is_turned_by_minus_135() -> None:
    mid = tr.outlines(_scene('turn = "cw"'), 1.0)[0]
    spoke = mid[0] - mid.mean(axis=0)  # vertex 0 starts at −135° from the centre; −135° more is +90°
    assert math.degrees(math.atan2(spoke[1], spoke[0])) == pytest.approx(90.0, abs=1e-9)
    r = math.sqrt(2)  # about the centre half way from (1, 1) to (6, 2)
    np.testing.assert_allclose(mid, [[3.5, 1.5 + r], [3.5 - r, 1.5], [3.5, 1.5 - r], [3.5 + r, 1.5]], atol=1e-12)


@pytest.mark.parametrize("fields, angle", [('turn = "ccw"', 90), ('turn = "shortest"', 90), ("turns = 1", 450),
                                           ('turn = "ccw"\nturns = 2', 810), ('turn = "cw"\nturns = 1', -630)])
def test_turns_add_whole_turns_in_the_chosen_direction(fields: str, angle: float) -> None:
    scene = _scene(fields)
    for t in (0.3, 0.5):
        expected = _rigid_turn(SQUARE, (1, 1), (6, 2), t, math.radians(angle))
        np.testing.assert_allclose(tr.outlines(scene, 2 * t)[0], expected, atol=1e-9)


@pytest.mark.parametrize("fields, angle", [('turn = "ccw"', 270), ("turns = 1", -450), ('turn = "cw"', -90)])
def test_a_clockwise_turn(fields: str, angle: float) -> None:
    back = [TURNED[2], TURNED[3], TURNED[0], TURNED[1]]  # the square turned −90°
    scene = _scene(fields, keys=(SQUARE, back))
    expected = _rigid_turn(SQUARE, (1, 1), (6, 2), 0.5, math.radians(angle))
    np.testing.assert_allclose(tr.outlines(scene, 1.0)[0], expected, atol=1e-9)


def _octagon(turn: float = 0.0, shift=(0.0, 0.0)) -> np.ndarray:
    angles = np.arange(8) * np.pi / 4 + turn
    return np.c_[2 * np.cos(angles) + shift[0], 2 * np.sin(angles) + shift[1]]


@pytest.mark.parametrize("method", ("linear", "nonlinear", "rigid", "arap", "injective"))
def test_an_arc_passes_through_its_point_at_the_middle(method: str) -> None:
    k0, k1 = _octagon(), _octagon(math.pi / 2, (6, 0))
    hints0 = f"hints = {{ a = {_points(k0[:1])[1:-1]}, b = {_points(k0[4:5])[1:-1]} }}"
    hints1 = f"hints = {{ a = {_points(k1[:1])[1:-1]}, b = {_points(k1[4:5])[1:-1]} }}"
    text = (f'method = "{method}"\n[[shape]]\nname = "o"\n[[shape.key]]\ntime = 0\npoints = {_points(k0)}\n'
            f"{hints0}\n%s\n[[shape.key]]\ntime = 1\npoints = {_points(k1)}\n{hints1}\n")
    plain = tr.parse_scene(text % "", "plain.toml")
    bent = tr.parse_scene(text % "arcs = { a = [3.5, 4.0] }", "bent.toml")
    start = tr.outlines(bent, 0.0)[0]  # balanced: copies of a vertex are where it is
    mid, own = tr.outlines(bent, 0.5)[0], tr.outlines(plain, 0.5)[0]
    correction = mid - own
    hinted = int(np.flatnonzero(np.all(start == k0[0], axis=1) & np.all(tr.outlines(bent, 1.0)[0] == k1[0], axis=1))[0])
    np.testing.assert_allclose(mid[hinted], [3.5, 4.0], atol=1e-12)
    full = np.array([3.5, 4.0]) - own[hinted]
    for vertex, share in ((4, 0.0), (2, 0.5), (6, 0.5), (1, 0.75), (7, 0.75), (3, 0.25)):
        at = np.all(start == k0[vertex], axis=1)  # every balanced copy of this vertex of the first key
        assert at.any()
        np.testing.assert_allclose(correction[at], np.broadcast_to(share * full, correction[at].shape), atol=1e-12)
    for t in (0.0, 1.0):
        np.testing.assert_array_equal(tr.outlines(bent, t)[0], tr.outlines(plain, t)[0])
    t = 0.2  # and 4t(1 − t) of it in between
    np.testing.assert_allclose(tr.outlines(bent, t)[0] - tr.outlines(plain, t)[0], 4 * t * (1 - t) * correction,
                               atol=1e-12)


def test_a_breakdown_at_its_own_time_leaves_straight_paths_unchanged() -> None:
    five = [[10, 0], [10, 2], [8, 2], [8, 0], [9, -1]]
    split = _scene(method="linear", keys=(SQUARE, five), middle="[[shape.key]]\ntime = 0.75\nbreakdown = 0.375\n")
    whole = _scene(method="linear", keys=(SQUARE, five))
    times = np.linspace(0, 2, 49)
    for t in times:
        np.testing.assert_allclose(np.concatenate(tr.outlines(split, t)), np.concatenate(tr.outlines(whole, t)),
                                   atol=1e-12)
    for t in (0.5, 0.75, 1.25):
        np.testing.assert_array_equal(tr.frame(split, t, size=(64, 48)), tr.frame(whole, t, size=(64, 48)))


def test_a_breakdown_is_the_in_between_at_its_favour() -> None:
    split = _scene(middle="[[shape.key]]\ntime = 1.5\nbreakdown = 0.25\n")  # rigid, at 1.5 s but a quarter way
    made = split.shapes[0].keys[1]
    assert made.breakdown == 0.25 and made.time == 1.5
    expected = _rigid_turn(SQUARE, (1, 1), (6, 2), 0.25, math.pi / 2)
    np.testing.assert_allclose(made.contours[0].points, expected, atol=1e-12)
    np.testing.assert_allclose(tr.outlines(split, 1.5)[0], expected, atol=1e-12)
    # each half turns rigidly on: half way through the first, an eighth of the whole turn
    np.testing.assert_allclose(tr.outlines(split, 0.75)[0], _rigid_turn(SQUARE, (1, 1), (6, 2), 0.125, math.pi / 2),
                               atol=1e-9)


def test_breakdowns_share_a_long_turn() -> None:
    split = _scene('turn = "cw"', middle="[[shape.key]]\ntime = 1\nbreakdown = 0.5\n")
    for t in (0.5, 1.0, 1.5):  # −270° in all, −135° at the breakdown, each half turning the same way
        expected = _rigid_turn(SQUARE, (1, 1), (6, 2), t / 2, -1.5 * math.pi)
        np.testing.assert_allclose(tr.outlines(split, t)[0], expected, atol=1e-9)
    np.testing.assert_array_equal(tr.outlines(split, 2)[0], TURNED)


def test_two_breakdowns_split_what_is_left() -> None:
    middle = "[[shape.key]]\ntime = 0.5\nbreakdown = 0.25\n[[shape.key]]\ntime = 1.5\nbreakdown = 0.5\n"
    split = _scene("turns = 1", middle=middle)
    whole = _rigid_turn(SQUARE, (1, 1), (6, 2), 0.25 + 0.75 * 0.5, 2.5 * math.pi)  # 450° in all
    np.testing.assert_allclose(split.shapes[0].keys[2].contours[0].points, whole, atol=1e-9)


def test_a_breakdown_turns_its_own_half_its_own_way() -> None:
    split = _scene(middle='[[shape.key]]\ntime = 1\nbreakdown = 0.5\nturn = "cw"\n')
    # the first half turns +45° the short way; from the breakdown, +45° more the long way: −315°
    np.testing.assert_allclose(tr.outlines(split, 0.5)[0], _rigid_turn(SQUARE, (1, 1), (6, 2), 0.25, math.pi / 2),
                               atol=1e-9)
    at = 45.0 - 315.0 / 2  # half way through the second half, the centre three quarters of the way
    np.testing.assert_allclose(tr.outlines(split, 1.5)[0],
                               _rigid_turn(SQUARE, (1, 1), (6, 2), 0.75, math.radians(at) / 0.75), atol=1e-9)


def test_a_breakdown_is_made_again_under_another_correspondence() -> None:
    from dataclasses import replace

    from tweenrender.core.timing.timeline import tracks_of

    six = [[10, 0], [10, 2], [9, 3], [8, 2], [8, 0], [9, -1]]
    split = _scene(method="linear", keys=(SQUARE, six), middle="[[shape.key]]\ntime = 0.5\nbreakdown = 0.25\n")
    whole = _scene(method="linear", keys=(SQUARE, six))
    other = replace(split.matching, cost="sg")
    made = tracks_of(split, other)[0]
    plain = tracks_of(whole, other)[0]
    assert len(made.segments[0].pairs[0].k0) == len(plain.segments[0].pairs[0].k0)
    for t in (0.25, 0.5, 1.0, 1.75):
        np.testing.assert_allclose(made.outlines(np.array([t]), "linear")[0][0],
                                   plain.outlines(np.array([t]), "linear")[0][0], atol=1e-12)


@pytest.mark.parametrize("method", ("jointed", "nonlinear", "linear"))
def test_an_arc_on_the_walks_toe(method: str) -> None:
    """The walk's toe (vertex 3) hinted on its first two keys, its arc through (1.5, 1.5): at 0.3 s, half
    way through the segment's time and (in-out being symmetric) its eased way, the toe is there."""
    from pathlib import Path

    text = (Path(__file__).resolve().parents[2] / "scenes" / "walk.toml").read_text()
    text = text.replace('ease = "in-out"\n', 'ease = "in-out"\nhints = { t = [-1.8454, 0.0] }\n'
                                             'arcs = { t = [1.5, 1.5] }\n', 1)
    text = text.replace('ease = "linear"\n', 'ease = "linear"\nhints = { t = [5.9238, 2.1475] }\n', 1)
    text = text.replace('method = "jointed"', f'method = "{method}"')
    scene = tr.parse_scene(text, "walk.toml")
    toe = tr.outlines(scene, 0.3)[0]
    assert np.min(np.hypot(*(toe - [1.5, 1.5]).T)) < 1e-12
    plain = tr.parse_scene(text.replace("arcs = { t = [1.5, 1.5] }\n", ""), "walk.toml")
    assert np.min(np.hypot(*(tr.outlines(plain, 0.3)[0] - [1.5, 1.5]).T)) > 0.5  # the arc moved it there
    for time in (0.0, 0.6, 1.2):
        np.testing.assert_array_equal(tr.outlines(scene, time)[0], tr.outlines(plain, time)[0])
