"""What the core remembers by content (correspondences, keys' contours apart, sweeps' crossings) is
asked again by content: an array changed in place, or another matching, is worked out anew."""

from __future__ import annotations

import numpy as np

from tweenrender.core.correspondence.correspond import correspond, forget_correspondences, naive_correspond
from tweenrender.core.tangles import apart_in_keys
from tweenrender.model import Matching


def star(count: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    angles = np.sort(rng.uniform(0, 2 * np.pi, count))
    radii = rng.uniform(0.5, 2.0, count)
    return np.column_stack([radii * np.cos(angles), radii * np.sin(angles)])


def test_a_correspondence_is_remembered_by_its_keys_and_matching() -> None:
    a, b = star(9, 1), star(7, 2)
    first = correspond(a, b)
    assert correspond(a.copy(), b.copy()) is first  # the same keys again
    assert not first.pairs.flags.writeable
    a[3] += (0.7, -0.4)  # changed in place: searched again, the least work over every path (naive)
    moved = correspond(a, b)
    assert moved.work == naive_correspond(a, b).work and moved.work != first.work
    sg = correspond(a, b, Matching(cost="sg"))
    assert sg is not moved and sg.work == naive_correspond(a, b, Matching(cost="sg")).work
    forget_correspondences()
    again = correspond(a, b)
    assert again is not moved and np.array_equal(again.pairs, moved.pairs)


def test_contours_apart_are_remembered_by_the_keys() -> None:
    square = np.array([[0, 0], [1, 0], [1, 1], [0, 1]], dtype=float)
    k0 = [square, square + 3.0]
    apart = apart_in_keys(k0, k0, [True, True])
    assert apart.nested == () and apart.joined == frozenset()  # side by side in both keys
    touching = [square, square + (1.0, 0.0)]  # sharing an edge: not apart
    assert apart_in_keys(touching, touching, [True, True]).joined == {(0, 1)}
    assert apart_in_keys(k0, k0, [True, True]) == apart


def test_injective_inbetweens_are_remembered_but_each_caller_gets_its_own() -> None:
    from tweenrender.core.methods.injective import injective_contours

    square = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
    turned = np.array([[1, -0.5], [2.5, 1], [1, 2.5], [-0.5, 1]])
    t = np.linspace(0.0, 1.0, 5)
    (first,) = injective_contours([square], [turned], [True], t)
    first[2] = 99.0  # the caller's own copy
    (again,) = injective_contours([square], [turned], [True], t)
    assert not np.any(again == 99.0)
    assert np.array_equal(again[0], square) and np.array_equal(again[-1], turned)
    (moved,) = injective_contours([square], [turned + 1.0], [True], t)  # other keys: worked out anew
    assert np.array_equal(moved[-1], turned + 1.0)
