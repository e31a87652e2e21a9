"""The numpy searches for small keys: the least work of brute force over every path, the very same
nodes as the compiled kernels (ties included), and the two-icon morph that no longer loads numba."""

from __future__ import annotations

import itertools
import subprocess
import sys

import numpy as np
import pytest

from tests.core.test_correspond import brute_force_distance, close, small_pair
from tests.helpers import DATA, ROOT
from tweenrender.core.correspondence import _cyclic_dtw, _small_dtw


def _pairs(nodes: np.ndarray, m: int, n: int) -> np.ndarray:
    """Unrolled nodes, end first (the closing node included), as (vertex of a, vertex of b)."""
    return np.column_stack([nodes[::-1][:-1, 0] % m, nodes[::-1][:-1, 1] % n])


@pytest.mark.parametrize("seed", range(24))
def test_closed_search_reaches_the_brute_force_least_work(seed: int) -> None:
    a, b = small_pair(np.random.default_rng(seed), seed % 3)
    work, nodes = _small_dtw.maes_search(_small_dtw.distance_matrix(a, b))
    pairs = _pairs(nodes, len(a), len(b))
    assert close(work, float(np.hypot(*(a[pairs[:, 0]] - b[pairs[:, 1]]).T).sum()))
    assert close(work, brute_force_distance(a, b, "none", backwards=False)), seed


def _open_brute_force(w: np.ndarray) -> float:
    """The least sum over every monotone path from (0, 0) to (m-1, n-1), by enumeration."""
    m, n = w.shape
    best = np.inf

    def walk(i: int, j: int, total: float) -> None:
        nonlocal best
        if (i, j) == (m - 1, n - 1):
            best = min(best, total)
            return
        for di, dj in ((1, 0), (0, 1), (1, 1)):
            if i + di < m and j + dj < n:
                walk(i + di, j + dj, total + w[i + di, j + dj])

    walk(0, 0, w[0, 0])
    return best


@pytest.mark.parametrize("m, n", list(itertools.product((1, 2, 4, 6), (1, 3, 5))))
def test_open_search_reaches_the_brute_force_least_work(m: int, n: int) -> None:
    w = np.random.default_rng(m * 10 + n).integers(0, 4, (m, n)).astype(float)  # ties
    work, path = _small_dtw.open_search(w)
    assert path[0].tolist() == [0, 0] and path[-1].tolist() == [m - 1, n - 1]
    steps = np.diff(path, axis=0)
    assert np.all((steps >= 0) & (steps <= 1)) and np.all(steps.sum(axis=1) >= 1)
    assert work == w[path[:, 0], path[:, 1]].sum() == _open_brute_force(w)


@pytest.mark.parametrize("seed", range(60))
def test_the_same_nodes_as_the_compiled_kernels(seed: int) -> None:
    rng = np.random.default_rng(seed)
    m, n = (int(v) for v in rng.integers(2, 40, 2))
    a, b = rng.random((m, 2)), rng.random((n, 2))
    if seed % 2:  # points on a coarse grid: many equal costs, so the tie rules decide
        a, b = np.round(a * 3) / 3, np.round(b * 3) / 3
    w = _small_dtw.distance_matrix(a, b)
    assert np.array_equal(w, _cyclic_dtw.distance_matrix(a, b))
    for ours, theirs in ((_small_dtw.maes_search(w), _cyclic_dtw.maes_search(w)),
                         (_small_dtw.open_search(w), _cyclic_dtw.open_search(w))):
        assert ours[0] == theirs[0]
        assert np.array_equal(ours[1], theirs[1])


def test_steps_are_numbered_as_the_kernels_number_them() -> None:
    assert (_small_dtw.STEP_B, _small_dtw.STEP_AB, _small_dtw.STEP_A) == \
        (_cyclic_dtw.STEP_B, _cyclic_dtw.STEP_AB, _cyclic_dtw.STEP_A)


def test_a_two_icon_morph_loads_neither_numba_nor_scipy_optimize() -> None:
    icons = DATA / "icons"
    code = ("import sys, tweenrender as tr\n"
            f"for pair in [('feather/heart.svg', 'feather/star.svg'), ('lucide/sun.svg', 'lucide/moon.svg')]:\n"
            f"    scene = tr.load_scene([{str(icons)!r} + '/' + p for p in pair])\n"
            "    tr.frame(scene, 0.5, size=(160, 90))\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] == 'numba' or m.startswith('scipy.optimize')))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"


def test_large_searches_and_a_spent_budget_go_to_the_kernels(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delitem(sys.modules, "numba", raising=False)
    monkeypatch.setattr(_small_dtw, "_spent", 0)
    assert not _small_dtw.takes(400, 400)  # 64 million nodes
    assert _small_dtw.takes(100, 100)  # 1 030 301 nodes
    assert _small_dtw._spent == 101 * 101 * 100
    monkeypatch.setattr(_small_dtw, "_spent", _small_dtw.PROCESS_NODES - 1000)
    assert not _small_dtw.takes(100, 100)
    monkeypatch.setattr(_small_dtw, "_spent", 0)
    monkeypatch.setitem(sys.modules, "numba", sys)  # loaded already: the kernels cost nothing more
    assert not _small_dtw.takes(10, 10)
