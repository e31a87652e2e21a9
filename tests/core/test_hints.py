"""Shape hints: the hinted correspondence is the least-work one among every closed monotone path through
the hinted pairs (brute force over all of them on small keys), a hinted point lands exactly on its
partner, and hints pair contours and survive spread balancing."""

from __future__ import annotations

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.core.correspondence.correspond import is_cyclic_monotone, path_work
from tweenrender.core.geometry import signed_area
from tweenrender.core.correspondence.hint_search import correspond_hinted
from tweenrender.core.correspondence.hints import snap_point
from tweenrender.core.timing.timeline import build_track
from tweenrender.model import Matching


def _every_closed_path(m: int, n: int, backwards: bool) -> list[np.ndarray]:
    """Every closed monotone path winding once round the m × n grid, starting where i first is 0."""
    out = []

    def walk(i: int, j: int, di: int, dj: int, path: list[tuple[int, int]]) -> None:
        if di == m and dj == n:
            out.append(np.array(path[:-1]))
            return
        for a, b in ((0, 1), (1, 1), (1, 0)):
            if di + a <= m and dj + b <= n:
                ni, nj = (i + a) % m, ((j - b) if backwards else (j + b)) % n
                walk(ni, nj, di + a, dj + b, path + [(ni, nj)])

    for j0 in range(n):
        walk(0, j0, 0, 0, [(0, j0)])
    return out


def _star(count: int, rng: np.random.Generator, clockwise: bool = False) -> np.ndarray:
    angles = np.sort(rng.uniform(0, 2 * np.pi, count))
    radii = rng.uniform(0.5, 2.0, count)
    points = np.column_stack([radii * np.cos(angles), radii * np.sin(angles)]) + rng.normal(size=2)
    return points[::-1] if clockwise else points


@pytest.mark.parametrize("cost", ["distance", "sg"])
@pytest.mark.parametrize("seed", range(12))
def test_hinted_search_is_the_brute_force_minimum(cost: str, seed: int) -> None:
    rng = np.random.default_rng(seed)
    m, n = int(rng.integers(3, 6)), int(rng.integers(3, 6))
    a, b = _star(m, rng), _star(n, rng, clockwise=seed % 3 == 0)
    backwards = bool(signed_area(a) * signed_area(b) < 0)
    k = int(rng.integers(1, min(m, n, 3) + 1))
    ia = sorted(rng.choice(m, k, replace=False).tolist())
    jb = sorted(rng.choice(n, k, replace=False).tolist(), reverse=backwards)  # the same cyclic order
    hinted = list(zip(ia, jb))
    matching = Matching(cost=cost)
    found = correspond_hinted(a, b, hinted, matching)
    assert is_cyclic_monotone(found.pairs, m, n, found.reversed)
    assert found.pairs[0, 0] == 0
    nodes = {tuple(p) for p in found.pairs.tolist()}
    assert all(h in nodes for h in hinted)
    honouring = [p for p in _every_closed_path(m, n, backwards)
                 if all(h in {tuple(q) for q in p.tolist()} for h in hinted)]
    best = min(path_work(a, b, p, matching) for p in honouring)
    assert found.work == pytest.approx(best, rel=1e-9, abs=1e-12)
    assert found.work == pytest.approx(path_work(a, b, found.pairs, matching), rel=1e-12)


def test_snap_takes_the_nearest_point_of_any_contour() -> None:
    square = np.array([[0.0, 0], [4, 0], [4, 4], [0, 4]])
    hole = np.array([[1.0, 1], [1, 3], [3, 3], [3, 1]])
    snap = snap_point([square, hole], [True, True], (2.0, 0.1))
    assert (snap.contour, snap.edge, snap.at) == (0, 0, (2.0, 0.0)) and snap.distance == pytest.approx(0.1)
    snap = snap_point([square, hole], [True, True], (1.2, 2.0))
    assert (snap.contour, snap.at) == (1, (1.0, 2.0))
    snap = snap_point([square, hole], [True, True], (-0.5, 4.5))  # past a corner: the corner
    assert snap.at == (0.0, 4.0)


def _twist_scene(tmp_path, hints: bool, balance: str = "copies"):
    """A square that turns a quarter: unhinted, least work keeps each corner near where it is; the hint
    sends the first key's corner (4, 0) to the second key's (0, 4) — a half turn."""
    k0 = [[0, 0], [4, 0], [4, 4], [0, 4]]
    k1 = [[0, 0], [2, 0], [4, 0], [4, 4], [0, 4]]
    h0 = '\nhints = { a = [4, 0], b = [0, 4] }' if hints else ''
    h1 = '\nhints = { a = [0, 4], b = [4, 0] }' if hints else ''
    text = (f'balance = "{balance}"\n[[shape]]\nname = "s"\nmethod = "linear"\n'
            f'[[shape.key]]\ntime = 0\npoints = {k0}{h0}\n[[shape.key]]\ntime = 1\npoints = {k1}{h1}\n')
    path = tmp_path / f"twist{hints}.toml"
    path.write_text(text)
    return tr.load_scene(path)


@pytest.mark.parametrize("balance", ["copies", "spread"])
def test_a_hinted_point_lands_exactly_on_its_partner(tmp_path, balance: str) -> None:
    scene = _twist_scene(tmp_path, True, balance)
    start = tr.outlines(scene, 0.0)[0]
    end = tr.outlines(scene, 1.0)[0]
    assert len(start) == len(end)
    for here, there in (((4, 0), (0, 4)), ((0, 4), (4, 0))):
        rows = np.flatnonzero(np.all(start == here, axis=1))
        assert len(rows) >= 1
        assert any(np.array_equal(end[r], there) for r in rows)
    # and in between it travels the straight line (method linear) between them
    middle = tr.outlines(scene, 0.5)[0]
    rows = np.flatnonzero(np.all(start == (4, 0), axis=1))
    assert any(np.allclose(middle[r], (2, 2)) for r in rows)


def test_without_the_hint_the_corner_stays(tmp_path) -> None:
    scene = _twist_scene(tmp_path, False)
    start, end = tr.outlines(scene, 0.0)[0], tr.outlines(scene, 1.0)[0]
    rows = np.flatnonzero(np.all(start == (4, 0), axis=1))
    assert any(np.array_equal(end[r], (4, 0)) for r in rows)


def test_hints_pair_contours_against_the_assignment(tmp_path) -> None:
    """Two equal squares side by side: the assignment keeps each where it is; a hint crosses them."""
    left = [[0, 0], [2, 0], [2, 2], [0, 2]]
    right = [[5, 0], [7, 0], [7, 2], [5, 2]]
    text = ('[[shape]]\nname = "s"\nmethod = "linear"\n'
            f'[[shape.key]]\ntime = 0\ncontours = {[left, right]}\nhints = {{ a = [0, 0] }}\n'
            f'[[shape.key]]\ntime = 1\ncontours = {[left, right]}\nhints = {{ a = [5, 0] }}\n')
    path = tmp_path / "pair.toml"
    path.write_text(text)
    scene = tr.load_scene(path)
    track = build_track(scene.shapes[0], scene.matching)
    assert sorted(p.source for p in track.segments[0].pairs) == [(0, 1), (1, 0)]


def test_hints_make_equal_counts_search(tmp_path) -> None:
    k = [[0, 0], [4, 0], [4, 4], [0, 4]]
    text = ('[[shape]]\nname = "s"\nmethod = "linear"\n'
            f'[[shape.key]]\ntime = 0\npoints = {k}\nhints = {{ a = [0, 0] }}\n'
            f'[[shape.key]]\ntime = 1\npoints = {k}\nhints = {{ a = [4, 4] }}\n')
    path = tmp_path / "eq.toml"
    path.write_text(text)
    scene = tr.load_scene(path)
    start, end = tr.outlines(scene, 0.0)[0], tr.outlines(scene, 1.0)[0]
    rows = np.flatnonzero(np.all(start == (0, 0), axis=1))
    assert any(end[r].tolist() == [4, 4] for r in rows)  # drawn order would keep it at (0, 0)


def _every_open_path(m: int, n: int) -> list[np.ndarray]:
    """Every monotone path from (0, 0) to (m - 1, n - 1)."""
    out = []

    def walk(i: int, j: int, path: list[tuple[int, int]]) -> None:
        if (i, j) == (m - 1, n - 1):
            out.append(np.array(path))
            return
        for a, b in ((0, 1), (1, 1), (1, 0)):
            if i + a < m and j + b < n:
                walk(i + a, j + b, path + [(i + a, j + b)])

    walk(0, 0, [(0, 0)])
    return out


@pytest.mark.parametrize("seed", range(10))
def test_hinted_open_search_is_the_brute_force_minimum(seed: int) -> None:
    from tweenrender.core.correspondence.correspond import is_open_monotone
    from tweenrender.core.correspondence.hint_search import correspond_hinted_open

    rng = np.random.default_rng(100 + seed)
    m, n = int(rng.integers(3, 7)), int(rng.integers(3, 7))
    a, b = rng.normal(size=(m, 2)), rng.normal(size=(n, 2))
    k = int(rng.integers(1, 3))
    ia = sorted(rng.choice(m, k, replace=False).tolist())
    backwards = bool(seed % 2)
    jb = sorted(rng.choice(n, k, replace=False).tolist(), reverse=backwards)
    hinted = list(zip(ia, jb))
    found = correspond_hinted_open(a, b, hinted, Matching())
    assert is_open_monotone(found.pairs, m, n, found.reversed)
    candidates = []
    for reverse in (False, True):
        for path in _every_open_path(m, n):
            pairs = path.copy()
            if reverse:
                pairs[:, 1] = n - 1 - pairs[:, 1]
            if all(h in {tuple(p) for p in pairs.tolist()} for h in hinted):
                candidates.append(path_work(a, b, pairs, Matching(), closed=False))
    assert found.work == pytest.approx(min(candidates), rel=1e-9, abs=1e-12)


def test_open_strokes_take_hints(tmp_path) -> None:
    stroke0 = [[0, 0], [4, 0], [8, 0]]
    stroke1 = [[0, 4], [2, 4], [4, 4], [6, 4], [8, 4]]
    text = ('[[shape]]\nname = "s"\nmethod = "linear"\nclosed = false\nstroke = "#000"\n'
            f'[[shape.key]]\ntime = 0\npoints = {stroke0}\nhints = {{ a = [4, 0] }}\n'
            f'[[shape.key]]\ntime = 1\npoints = {stroke1}\nhints = {{ a = [2, 4] }}\n')
    path = tmp_path / "open.toml"
    path.write_text(text)
    scene = tr.load_scene(path)
    start, end = tr.outlines(scene, 0.0)[0], tr.outlines(scene, 1.0)[0]
    rows = np.flatnonzero(np.all(start == (4, 0), axis=1))
    assert any(end[r].tolist() == [2, 4] for r in rows)


def test_spread_keeps_a_hinted_copy_on_its_vertex() -> None:
    from tweenrender.core.balance import spread

    # key a: the corner (4, 0) copied three times (balanced indices 1, 2, 3); key b walks four points there
    k0 = np.array([[0.0, 0], [4, 0], [4, 0], [4, 0], [4, 4], [0, 4]])
    k1 = np.array([[0.0, 0], [3, 0], [4, 1], [4, 2], [4, 4], [0, 4]])
    free, _ = spread(k0, k1)
    assert free[3].tolist() != [4, 0]  # unpinned, the last copy moves off the corner
    pinned, _ = spread(k0, k1, fixed=[3])
    assert pinned[3].tolist() == [4, 0]
    # the copies before it go onto the half-edge before the corner, in order, none on the corner
    assert all(p[1] == 0 and 2 <= p[0] < 4 for p in pinned[1:3])
    assert pinned[1][0] < pinned[2][0]
