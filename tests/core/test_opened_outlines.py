"""An outline drawn as a stroke alone (round caps and joins, nothing filled) is an open stroke whose ends meet:
where it has no partner in its key and the other key has an open stroke without one, the two are paired,
rather than one shrinking to a point while the other grows across it (maths §5.17)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import shapely

import tweenrender as tr
from tweenrender.core.timing.timeline import tracks_of

_HEAD = ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40"><path id="e" stroke="#000" stroke-width="2" '
         'stroke-linecap="{cap}" stroke-linejoin="round" fill="{fill}" d="{d}"/></svg>')
_ARCH = "M10 32 L10 14 Q10 8 20 8 Q30 8 30 14 L30 32"  # an open stroke, its ends apart
_SQUARE = "M8 8 L32 8 L32 32 L8 32 Z"  # an outline, the arch's ends near its bottom side


def _scene(folder: Path, cap: str = "round", fill: str = "none") -> tr.Scene:
    a, b = folder / "a.svg", folder / "b.svg"
    a.write_text(_HEAD.format(cap=cap, fill=fill, d=_ARCH))
    b.write_text(_HEAD.format(cap=cap, fill=fill, d=_SQUARE))
    return tr.load_scene([a, b], step=1.0)


def test_a_stroke_and_an_outline_drawn_as_strokes_are_paired(tmp_path: Path) -> None:
    scene = _scene(tmp_path)
    (track,) = tracks_of(scene)
    (pair,) = track.segments[0].pairs  # one pair: nothing grows or shrinks
    assert pair.moving and not pair.closed
    assert np.allclose(pair.k1[0], pair.k1[-1])  # the outline, opened: its ends meet
    # it is opened at its vertex nearest where the arch's ends come together: a corner of the bottom side
    assert pair.k1[0][1] == pytest.approx(-32.0) and pair.k1[0][0] in (pytest.approx(8.0), pytest.approx(32.0))
    # the in-betweens are one stroke that never crosses itself (shapely)
    for t in np.linspace(0.05, 0.95, 19):
        (drawn,) = tr.contours(scene, float(t))
        assert shapely.LineString(drawn.points).is_simple


def test_the_opened_outline_draws_as_the_outline_did(tmp_path: Path) -> None:
    """At the second key the opened outline's picture is the outline's own (the drawing alone, as its own scene),
    pixel for pixel but for antialiasing where its ends meet."""
    scene = _scene(tmp_path)
    alone = tr.load_scene([tmp_path / "b.svg"])
    drawn = tr.frame(scene, 1.0, size=(200, 200), background="#ffffff").astype(int)
    own = tr.frame(alone, 0.0, size=(200, 200), background="#ffffff").astype(int)
    assert np.abs(drawn - own).max() <= 8
    assert (drawn[..., 0] < 128).sum() == pytest.approx((own[..., 0] < 128).sum(), rel=0.002)


@pytest.mark.parametrize("cap, fill", [("butt", "none"), ("round", "#808080")])
def test_an_outline_that_would_draw_otherwise_opened_is_left_closed(tmp_path: Path, cap: str, fill: str) -> None:
    """Butt caps would leave a notch where the ends meet, and a fill needs an outline: the contours stay
    without partners, one shrinking and one growing."""
    (track,) = tracks_of(_scene(tmp_path, cap, fill))
    pairs = track.segments[0].pairs
    assert len(pairs) == 2 and not any(p.moving for p in pairs)
    assert sorted(p.closed for p in pairs) == [False, True]
