"""How kernels are compiled: numba's array maths loaded without importing ``scipy.linalg`` for its BLAS
probe, and everything that needs ``scipy.linalg`` or inner products still working (fresh processes)."""

from __future__ import annotations

import subprocess
import sys

SCRIPT = """
import sys
import numpy as np
from tweenrender.raster import _stroke_kernel as kernel
segments = kernel.polyline_segments(np.array([[0.0, 0.0], [3.0, 1.0]]), np.array([2]), np.array([False]),
                                    1.0, 0.0, 0.0)
kernel.stroke_segments(np.zeros((4, 4, 4), np.uint8), segments, 1.0, np.zeros(4), 0, 0, 4, 4)
print("after a kernel ran:", "scipy.linalg" in sys.modules, "numba.np.arraymath" in sys.modules)
from numba import njit
inner = njit(lambda a, b: np.dot(a, b))
print("inner product:", inner(np.array([1.0, 2.0, 3.0]), np.array([4.0, 5.0, 6.0])))
from scipy.sparse import csc_matrix
from scipy.sparse.linalg import splu
print("sparse solve:", splu(csc_matrix(np.array([[2.0, 0.0], [0.0, 4.0]]))).solve(np.array([2.0, 2.0])).tolist())
"""


def _run(script: str) -> str:
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert done.stderr == ""  # no warning either
    return done.stdout


def test_a_kernel_runs_without_scipy_linalg_and_both_still_work_after() -> None:
    out = _run(SCRIPT)
    assert "after a kernel ran: False True" in out
    assert "inner product: 32.0" in out  # 4 + 10 + 18
    assert "sparse solve: [1.0, 0.5]" in out


def test_nothing_is_refused_where_scipy_linalg_is_loaded_first() -> None:
    out = _run("import scipy.linalg\nimport numba.np.linalg as L\n" + SCRIPT +
               "\nimport numba.np.arraymath as A\nprint('blas:', A._HAVE_BLAS)")
    assert "after a kernel ran: True True" in out and "blas: True" in out


def test_another_thread_may_import_scipy_linalg_meanwhile() -> None:
    # the refusal is for the importing thread alone: a thread importing scipy.linalg while the kernels'
    # module loads gets it
    out = _run("""
import threading, sys
got = []
started = threading.Event()
def load():
    started.set()
    import scipy.linalg
    got.append(scipy.linalg.__name__)
thread = threading.Thread(target=load)
thread.start()
started.wait()
import tweenrender.core.jit
thread.join()
print("thread got", got)
""")
    assert "thread got ['scipy.linalg']" in out
