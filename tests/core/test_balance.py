"""Spread balancing: the keys' outlines are unchanged, copies land at the other key's proportions."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.balance import coincident_runs, spread
from tweenrender.core.correspondence.correspond import correspond
from tweenrender.core.geometry import edge_lengths, perimeter, signed_area
from tweenrender.core.timing.timeline import build_track
from tweenrender.scenefile import load_scene

from ..helpers import SCENES


def test_copies_take_the_other_keys_arc_length_proportions() -> None:
    # vertex 1 of a square is matched to three vertices of b, spaced 1 and 3 apart along b
    a = np.array([[0, 0], [4, 0], [4, 0], [4, 0], [4, 4], [0, 4]], dtype=np.float64)
    b = np.array([[0, 0], [2, 0], [3, 0], [6, 0], [6, 6], [0, 6]], dtype=np.float64)
    spread_a, spread_b = spread(a, b)
    assert np.array_equal(spread_b, b)  # b has no copies
    # b's stretch: half its edge in (1), then 1, 3, then half its edge out (3): total 8
    # the copies sit at proportions 1/8, 2/8, 5/8 (kept within 5 %..95 %) of a's stretch of
    # outline, half an edge each side of (4, 0): 2 before, 2 after
    share = 0.05 + 0.9 * np.array([1, 2, 5]) / 8
    place = share * 4.0
    expected = [[2 + p, 0] if p < 2 else [4, p - 2] for p in place]
    stay = int(np.argmin(np.abs(place - 2.0)))
    expected[stay] = [4, 0]
    assert np.allclose(spread_a[1:4], expected)


def test_the_outline_is_unchanged_and_no_edge_is_zero() -> None:
    rng = np.random.default_rng(1)
    for _ in range(30):
        m, n = rng.integers(3, 12, size=2)
        ta, tb = np.sort(rng.uniform(0, 2 * np.pi, m)), np.sort(rng.uniform(0, 2 * np.pi, n))
        a = np.column_stack([np.cos(ta), np.sin(ta)]) * rng.uniform(0.5, 1.5, (m, 1))
        b = np.column_stack([np.cos(tb), np.sin(tb)]) * rng.uniform(0.5, 1.5, (n, 1)) + 3.0
        found = correspond(a, b)
        k0, k1 = found.apply(a, b)
        s0, s1 = spread(k0, k1)
        for before, after in ((k0, s0), (k1, s1)):
            assert float(perimeter(after)) == pytest.approx(float(perimeter(before)), rel=1e-12)
            assert float(signed_area(after)) == pytest.approx(float(signed_area(before)), rel=1e-12)
            assert np.all(edge_lengths(after) > 0)
            # every vertex of the key as drawn is still a vertex
            for vertex in np.unique(before, axis=0):
                assert np.any(np.all(after == vertex, axis=1))
        assert not coincident_runs(s0) and not coincident_runs(s1)


def test_spread_balance_in_a_scene_keeps_the_keys_outlines() -> None:
    scene = load_scene(SCENES / "eight-to-three.toml")
    copies = build_track(scene.shapes[0], scene.matching, balance="copies").segments[0]
    spread_ = build_track(scene.shapes[0], scene.matching, balance="spread").segments[0]
    assert coincident_runs(copies.k1) and not coincident_runs(spread_.k1)
    assert float(perimeter(spread_.k1)) == pytest.approx(float(perimeter(copies.k1)))
    assert float(signed_area(spread_.k1)) == pytest.approx(float(signed_area(copies.k1)))
    assert not spread_.k1.flags.writeable  # the model's arrays stay read-only


def test_copies_on_subnormal_edges_are_spread_as_on_unit_edges() -> None:
    # spreading is by arc-length proportions, so it commutes with scaling; a power of two scales exactly,
    # and at 2**-1000 an edge's squared length underflows to zero (the place a naive norm divides by 0)
    a = np.array([[0, 0], [4, 0], [4, 0], [4, 0], [4, 4], [0, 4]], dtype=np.float64)
    b = np.array([[0, 0], [2, 0], [3, 0], [6, 0], [6, 6], [0, 6]], dtype=np.float64)
    tiny = 2.0 ** -1000
    with np.errstate(divide="raise", invalid="raise", over="raise"):
        spread_a, spread_b = spread(a * tiny, b * tiny)
    unit_a, unit_b = spread(a, b)
    assert np.allclose(spread_a / tiny, unit_a, rtol=1e-12, atol=0)
    assert np.allclose(spread_b / tiny, unit_b, rtol=1e-12, atol=0)


NEAR_COINCIDENT = """size = [160, 120]
fps = 4
[[shape]]
name = "s"
stroke = "#000000"
[[shape.key]]
time = 0
points = [[0, 0], [1e-300, 0], [0, 1e-300]]
[[shape.key]]
time = 1
points = [[0, 0], [1e-300, 0], [1e-300, 1e-300], [0, 1e-300], [5e-301, 5e-301]]
"""


@pytest.mark.parametrize("method", ["auto", "arap", "injective"])
def test_a_key_of_subnormal_size_draws_finite_outlines(tmp_path, method: str) -> None:
    import warnings

    from tweenrender import api

    scene_path = tmp_path / "tiny.toml"
    scene_path.write_text(NEAR_COINCIDENT)
    scene = api.load_scene(scene_path)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        for time in np.linspace(0.0, 1.0, 9):
            drawn = api.outlines(scene, float(time), method=method)
            assert drawn and all(np.isfinite(c).all() for c in drawn)
            # nothing blows up: every vertex stays near the keys' box, [0, 1e-300]² (injective paths may
            # bulge a little past it, as they do at unit size)
            assert all((c >= -0.25e-300).all() and (c <= 1.25e-300).all() for c in drawn)
