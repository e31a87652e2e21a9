"""Gradient fills between keys: an in-between's stops are each key's colour at every offset, blended (the
colour in OKLab by an independent colour library, alpha linearly)."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.gradient_blend import blend_gradient
from tweenrender.model import Gradient, Paint

BOX = (0.0, 0.0, 10.0, 5.0)


def _gradient(offsets: list[float], colours: list[tuple[int, int, int, int]]) -> Gradient:
    return Gradient("linear", (0.0, 0.0, 1.0, 0.0), (10.0, 0.0, 0.0, 5.0, 0.0, 0.0), tuple(zip(offsets, colours)))


def _mixed(a: tuple[int, ...], b: tuple[int, ...], t: float) -> tuple[int, ...]:
    """Stop colours ``a → b`` at ``t`` as coloraide mixes them in OKLab, straight (not premultiplied), alpha
    linearly: ``(R, G, B, A)`` rounded."""
    from coloraide import Color

    mix = Color.interpolate([Color("srgb", [v / 255 for v in a[:3]]), Color("srgb", [v / 255 for v in b[:3]])],
                            space="oklab")
    rgb = [round(255 * min(max(c, 0.0), 1.0)) for c in mix(t).convert("srgb").coords()]
    return (*rgb, round((1 - t) * a[3] + t * b[3]))


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
        expected = _mixed(_by_hand(o0, c0, offset), _by_hand(o1, c1, offset), t)
        assert all(abs(p - q) <= 1 for p, q in zip(colour, expected)), offset  # a rounding apart at most


def test_a_thousand_stops_are_each_blended() -> None:
    rng = np.random.default_rng(8)
    offsets = list(np.linspace(0.0, 1.0, 1000))
    c0 = [tuple(int(v) for v in rng.integers(0, 256, 4)) for _ in offsets]
    c1 = [tuple(int(v) for v in rng.integers(0, 256, 4)) for _ in offsets]
    blended = blend_gradient(Paint(gradient=_gradient(offsets, c0)), Paint(gradient=_gradient(offsets, c1)),
                             BOX, BOX, BOX, 0.4)
    assert len(blended.stops) == 1000
    for (offset, colour), a, b in zip(blended.stops, c0, c1):
        expected = _mixed(a, b, 0.4)
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


def _drawn_over_white(colour: tuple[int, ...]) -> np.ndarray:
    """A straight RGBA colour as it shows over white: ``(3,)`` levels."""
    rgb, alpha = np.array(colour[:3], dtype=float), colour[3] / 255.0
    return alpha * rgb + (1.0 - alpha) * 255.0


@pytest.mark.parametrize("toward", [0, 1])
def test_a_stop_that_turns_transparent_keeps_the_drawn_ramp_continuous_at_its_key(toward: int) -> None:
    """SVG draws the ramp between two stops from their straight colours, so a transparent stop's colour
    shows in its neighbour's ramp (pink to transparent red is reddish half-way). An in-between a hair from
    the key draws what the key draws, at every offset: a stop whose colour waited for the key before it
    moved jumped there in one frame (a pop on the last frame of a morph into a fluent emoji)."""
    offsets = [0.0, 1.0]
    pink, grey, red = (250, 110, 140, 255), (200, 210, 220, 255), (230, 50, 70, 0)
    plain, fading = [pink, grey], [pink, red]
    colours = (plain, fading) if toward == 1 else (fading, plain)
    g0, g1 = _gradient(offsets, colours[0]), _gradient(offsets, colours[1])
    key = colours[toward]
    for t in ([0.999, 0.9999] if toward == 1 else [0.001, 0.0001]):
        blended = blend_gradient(Paint(gradient=g0), Paint(gradient=g1), BOX, BOX, BOX, t)
        got = [o for o, _ in blended.stops], [c for _, c in blended.stops]
        for at in (0.25, 0.5, 0.75):
            near = _drawn_over_white(_by_hand(*got, at))
            there = _drawn_over_white(_by_hand(offsets, key, at))
            assert np.abs(near - there).max() <= 2.0, (t, at, near, there)
