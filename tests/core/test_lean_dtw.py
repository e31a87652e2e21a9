"""The checkpointed closed search: node for node the path of ``maes_search`` over the whole matrix
(itself checked against brute force and every start in test_correspond), in memory that no longer
holds an ``m × n`` matrix."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pytest

from tests.core.test_correspond import brute_force_distance, close, small_pair, star
from tests.helpers import ROOT
from tweenrender.core.correspondence import _cyclic_dtw, _lean_dtw


@pytest.mark.parametrize("seed", range(40))
def test_the_same_path_as_the_whole_matrix_search(seed: int) -> None:
    rng = np.random.default_rng(seed)
    m, n = (int(v) for v in rng.integers(2, 70, 2))
    a, b = (star(rng, m), star(rng, n, (0.3, 0.1))) if seed % 3 else (rng.random((m, 2)), rng.random((n, 2)))
    if seed % 2:  # a coarse grid: many equal costs, so the tie rules decide
        a, b = np.round(a * 3) / 3, np.round(b * 3) / 3
    expected = _cyclic_dtw.maes_search(_cyclic_dtw.distance_matrix(a, b))
    for every in (1, 3, _lean_dtw.checkpoint_rows(m), m + 5):  # a checkpoint every row .. none but row 0
        found = _lean_dtw.lean_maes_search(a, b, every)
        assert found[0] == expected[0]
        assert np.array_equal(found[1], expected[1])


@pytest.mark.parametrize("seed", range(12))
def test_least_work_of_brute_force(seed: int) -> None:
    a, b = small_pair(np.random.default_rng(seed), seed % 3)
    work, nodes = _lean_dtw.lean_maes_search(np.ascontiguousarray(a), np.ascontiguousarray(b), 2)
    assert close(work, brute_force_distance(a, b, "none", backwards=False))


def test_a_large_search_holds_no_matrix() -> None:
    """3000 × 3000 vertices: the matrix and the steps would be 3000 · 3000 · (8 + 2) bytes = 86 MiB;
    the checkpointed search's own arrays are about 4 MiB (peak resident memory, counted by the kernel)."""
    code = ("import resource, numpy as np\n"
            "from tweenrender.core.correspondence import _lean_dtw\n"
            "rng = np.random.default_rng(1)\n"
            "def star(n):\n"
            "    t = np.sort(rng.uniform(0, 2 * np.pi, n)); r = rng.uniform(0.5, 1.5, n)\n"
            "    return np.column_stack([r * np.cos(t), r * np.sin(t)])\n"
            "_lean_dtw.lean_maes_search(star(50), star(60), 8)\n"
            "a, b = star(3000), star(3000)\n"
            "before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss\n"
            "_lean_dtw.lean_maes_search(a, b, _lean_dtw.checkpoint_rows(3000))\n"
            "print((resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before) / 1024)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=600, cwd=ROOT)
    assert done.returncode == 0, done.stderr
    assert float(done.stdout) < 20.0
