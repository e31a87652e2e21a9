"""Stray (maths §5.16, ``stats``' ``stray_max``): the share of an in-between's area far from both keys, on
shapes whose answer is known by construction and on real icons' in-betweens against shapely."""

from __future__ import annotations

from collections import defaultdict

import numpy as np
import pytest

import tweenrender as tr
from tests.core.shapely_areas import drawn_area, stray_share
from tests.helpers import DATA
from tweenrender.core.stray import stray_shares

SQUARE = np.array([[0, 0], [4, 0], [4, 4], [0, 4]], dtype=float)


def test_a_square_sliding_away_strays_by_what_lies_past_the_reach() -> None:
    reach = 1.2
    shifts = np.linspace(0.0, 8.0, 17)
    found = stray_shares([([SQUARE + [x, 0.0]], "nonzero") for x in shifts], ([SQUARE], "nonzero"),
                         ([SQUARE], "nonzero"), reach)
    # the part right of x = 4 + reach is farther than the reach from the key: (x - reach) / 4 of it
    expected = np.clip((shifts - reach) / 4.0, 0.0, 1.0)
    assert np.abs(found - expected).max() <= 0.02, (found, expected)


def test_what_lies_near_either_key_does_not_stray() -> None:
    far = SQUARE + [20.0, 0.0]
    between = SQUARE + [10.0, 0.0]  # x from 10 to 14, 6 from each key
    found = stray_shares([([SQUARE], "nonzero"), ([far], "nonzero"), ([between], "nonzero")],
                         ([SQUARE], "nonzero"), ([far], "nonzero"), 7.0)
    # within 7 of the first key up to x = 11, of the second from x = 13: the middle half strays
    assert found[0] == 0.0 and found[1] == 0.0 and found[2] == pytest.approx(0.5, abs=0.05)


@pytest.mark.parametrize("rule, inner", [("nonzero", SQUARE[::-1] * 3.0 + [-4.0, -4.0]),
                                         ("evenodd", SQUARE * 3.0 + [-4.0, -4.0])])
def test_a_hole_is_no_drawn_area_to_be_near(rule: str, inner: np.ndarray) -> None:
    # a ring: 20 wide outside, 12 wide hole (wound against it under nonzero); a dot in the hole's middle
    # is 6 from the ring, farther than the reach of 4, though inside the ring's outline
    outer = SQUARE * 5.0 + [-8.0, -8.0]
    ring = ([outer, inner], rule)
    dot = ([SQUARE * 0.25 + [1.5, 1.5]], rule)
    assert stray_shares([dot], ring, ring, 4.0)[0] == 1.0
    assert stray_shares([dot], ring, ring, 6.5)[0] == 0.0


def _areas(scene: tr.Scene, t: float, method: str) -> dict[str, tuple[list[np.ndarray], str]]:
    """Each element's closed contours as drawn at ``t`` (windings as drawn) and its fill rule."""
    out: dict[str, tuple[list[np.ndarray], str]] = defaultdict(lambda: ([], "nonzero"))
    for c in tr.contours(scene, t, method=method):
        if c.closed:
            out[c.element] = (out[c.element][0] + [c.points[::-1] if c.reversed else c.points], c.fill_rule)
    return out


@pytest.mark.parametrize("a, b", [("mdi/alpha-o-box", "mdi/alpha-a"), ("bootstrap/emoji-smile", "twemoji/1f319"),
                                  ("mdi/weather-night", "mdi/weather-sunny")])
def test_real_icons_stray_as_shapely_measures(a: str, b: str) -> None:
    """Holes, pieces and both fill rules: the raster's share within 0.01 of shapely's exact one."""
    scene = tr.load_scene([DATA / "icons" / f"{a}.svg", DATA / "icons" / f"{b}.svg"], step=1.0)
    x0, y0, x1, y1 = scene.view
    reach = 0.02 * max(x1 - x0, y1 - y0)  # a small reach, so that the shares are far from 0
    keys0, keys1 = _areas(scene, 0.0, "linear"), _areas(scene, 1.0, "linear")
    shares = []
    for t in (0.25, 0.5, 0.75):
        for element, area in _areas(scene, t, "linear").items():
            if element in keys0 and element in keys1:
                ours = stray_shares([area], keys0[element], keys1[element], reach)[0]
                exact = stray_share(drawn_area(*area), drawn_area(*keys0[element]), drawn_area(*keys1[element]), reach)
                shares.append((ours, exact))
    assert shares and max(exact for _, exact in shares) > 0.01
    assert max(abs(ours - exact) for ours, exact in shares) <= 0.01, shares


def test_an_open_stroke_flung_away_strays_by_its_length() -> None:
    # auto's holding of contours without a partner (maths §5.16) measures strokes by their length: two
    # strokes of length 4 whose keys lie on y = 0; one stays, the other is carried up by 10 sin(πt). The
    # reach is 12 % of the keys' larger side (the two strokes span x = 0 .. 10): 1.2; the moving one is past
    # it where 10 sin(πt) > 1.2 (the keys are straight lines: every point of it is as far as its shift)
    from tweenrender.core.methods.qcurves import QUALITY_T, stroke_stray

    stay, move = np.array([[0.0, 0.0], [4.0, 0.0]]), np.array([[6.0, 0.0], [8.0, 0.0], [10.0, 0.0]])
    lift = (10.0 * np.sin(np.pi * QUALITY_T))[:, None, None] * np.array([0.0, 1.0])
    frames = [np.broadcast_to(stay, (len(QUALITY_T), 2, 2)), move[None] + lift]
    assert stroke_stray(frames, [stay, move], [stay, move], [False, False]) == pytest.approx(0.5, abs=1e-9)
    assert stroke_stray([frames[1]], [move], [move], [False]) == pytest.approx(1.0, abs=1e-9)
    # within the reach (a lift of at most 1.1) nothing strays
    low = move[None] + 0.11 * lift
    assert stroke_stray([frames[0], low], [stay, move], [stay, move], [False, False]) == 0.0
