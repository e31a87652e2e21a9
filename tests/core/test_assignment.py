"""Least-cost assignment without scipy for small problems: the optimum of brute force over every
injection, and scipy's on larger ones; and a two-icon morph no longer imports ``scipy.optimize``."""

from __future__ import annotations

import itertools
import subprocess
import sys

import numpy as np
import pytest

from tests.helpers import DATA, ROOT
from tweenrender.core.correspondence.assignment import SMALL_ASSIGNMENT, min_cost_assignment


def brute_force(cost: np.ndarray) -> float:
    """The least total over every way to give each row of the shorter side its own column."""
    m, n = cost.shape
    if m > n:
        return brute_force(cost.T)
    return min(sum(cost[r, c] for r, c in zip(range(m), cols)) for cols in itertools.permutations(range(n), m))


@pytest.mark.parametrize("seed", range(40))
def test_small_assignments_reach_the_brute_force_optimum(seed: int) -> None:
    rng = np.random.default_rng(seed)
    m, n = (int(v) for v in rng.integers(1, 8, 2))
    # ties (small integers), spread values, and the 1e9 walls match_elements uses
    cost = rng.integers(0, 4, (m, n)).astype(float) if seed % 3 == 0 else rng.random((m, n)) * 10.0
    if seed % 3 == 2:
        cost[rng.random((m, n)) < 0.3] = 1e9
    rows, cols = min_cost_assignment(cost)
    assert len(rows) == min(m, n)
    assert list(rows) == sorted(set(rows.tolist())) and len(set(cols.tolist())) == len(cols)
    assert cost[rows, cols].sum() == pytest.approx(brute_force(cost), rel=1e-12, abs=1e-9)


@pytest.mark.parametrize("shape", [(SMALL_ASSIGNMENT, SMALL_ASSIGNMENT), (20, 45), (45, 20)])
def test_the_largest_small_assignments_match_scipy(shape: tuple[int, int]) -> None:
    from scipy.optimize import linear_sum_assignment

    cost = np.random.default_rng(7).random(shape)
    rows, cols = min_cost_assignment(cost)
    expected_rows, expected_cols = linear_sum_assignment(cost)
    assert cost[rows, cols].sum() == pytest.approx(cost[expected_rows, expected_cols].sum(), rel=1e-12)


def test_empty_and_refused_inputs() -> None:
    rows, cols = min_cost_assignment(np.zeros((0, 3)))
    assert len(rows) == len(cols) == 0
    with pytest.raises(ValueError):
        min_cost_assignment(np.array([[1.0, np.inf]]))


def test_a_two_icon_morph_does_not_import_scipy_optimize() -> None:
    icons = DATA / "icons" / "feather"
    code = ("import sys, tweenrender as tr\n"
            f"scene = tr.load_scene([{str(icons / 'heart.svg')!r}, {str(icons / 'star.svg')!r}])\n"
            "tr.frame(scene, 0.5, size=(160, 90))\n"
            f"scene = tr.load_scene([{str(icons / 'smile.svg')!r}, {str(icons / 'x-circle.svg')!r}])\n"
            "tr.frame(scene, 0.5, size=(160, 90))\n"
            "print(sorted(m for m in sys.modules if m.startswith('scipy.optimize')))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == "[]"
