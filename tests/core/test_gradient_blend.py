"""Gradient fills between keys: an in-between's stops are each key's colour at every offset, blended."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.gradient_blend import blend_gradient
from tweenrender.core.paint import blend_colors
from tweenrender.model import Gradient, Paint

BOX = (0.0, 0.0, 10.0, 5.0)


def _gradient(offsets: list[float], colours: list[tuple[int, int, int, int]]) -> Gradient:
    return Gradient("linear", (0.0, 0.0, 1.0, 0.0), (10.0, 0.0, 0.0, 5.0, 0.0, 0.0), tuple(zip(offsets, colours)))


def _by_hand(offsets: list[float], colours: list[tuple[int, int, int, int]], at: float) -> tuple[int, ...]:
    """SVG's colour at ``at``: the stops' straight RGBA, linear between the two around it (rounded)."""
    if at <= offsets[0]:
        return colours[0]
    for (o0, c0), (o1, c1) in zip(zip(offsets, colours), zip(offsets[1:], colours[1:])):
        if o0 <= at <= o1:
            share = (at - o0) / (o1 - o0)
            return tuple(int(round(a + share * (b - a))) for a, b in zip(c0, c1))
    return colours[-1]


@pytest.mark.parametrize("t", [0.0, 0.3, 0.5, 0.8, 1.0])
def test_every_stop_is_the_blend_of_both_keys_colours_there(t: float) -> None:
    rng = np.random.default_rng(7)
    o0 = [0.0, 0.25, 0.6, 1.0]
    o1 = [0.0, 0.1, 0.5, 0.9, 1.0]
    c0 = [tuple(int(v) for v in rng.integers(0, 256, 4)) for _ in o0]
    c1 = [tuple(int(v) for v in rng.integers(0, 256, 4)) for _ in o1]
    g0, g1 = _gradient(o0, c0), _gradient(o1, c1)
    blended = blend_gradient(Paint(gradient=g0), Paint(gradient=g1), BOX, BOX, BOX, t)
    offsets = sorted(set(o0) | set(o1))
    assert [o for o, _ in blended.stops] == offsets
    for offset, colour in blended.stops:
        expected = blend_colors(_by_hand(o0, c0, offset), _by_hand(o1, c1, offset), [t])[0]
        assert colour == expected, offset


def test_a_thousand_stops_are_each_blended() -> None:
    rng = np.random.default_rng(8)
    offsets = list(np.linspace(0.0, 1.0, 1000))
    c0 = [tuple(int(v) for v in rng.integers(0, 256, 4)) for _ in offsets]
    c1 = [tuple(int(v) for v in rng.integers(0, 256, 4)) for _ in offsets]
    blended = blend_gradient(Paint(gradient=_gradient(offsets, c0)), Paint(gradient=_gradient(offsets, c1)),
                             BOX, BOX, BOX, 0.4)
    assert len(blended.stops) == 1000
    for (offset, colour), a, b in zip(blended.stops, c0, c1):
        expected = blend_colors(a, b, [0.4])[0]
        assert all(abs(p - q) <= 1 for p, q in zip(colour, expected)), offset  # a rounding apart at most


@pytest.mark.parametrize("t", [0.0, 0.25, 0.5, 0.9, 1.0])
@pytest.mark.parametrize("filled_first", [True, False])
def test_a_gradient_coming_from_a_key_without_fill_fades_in_by_the_share_of_its_key(t: float,
                                                                                   filled_first: bool) -> None:
    """A key without fill is the other key's gradient at alpha 0 (as a plain colour blends with none): each
    stop's alpha is its own times that key's share, so the fill comes in evenly (it was drawn whole from the
    first in-between on: a pop)."""
    colours = [(200, 10, 40, 255), (20, 30, 220, 128)]
    g = _gradient([0.0, 1.0], colours)
    filled, bare = Paint(fill=(0, 0, 0, 255), gradient=g), Paint(fill=None, stroke=(0, 0, 0, 255))
    blended = blend_gradient(filled if filled_first else bare, bare if filled_first else filled, BOX, BOX, BOX, t)
    share = 1.0 - t if filled_first else t
    assert [o for o, _ in blended.stops] == [0.0, 1.0]
    for (_, got), want in zip(blended.stops, colours):
        assert tuple(got[:3]) == want[:3]
        assert got[3] == round(want[3] * share)
