"""Once a stroked frame is drawn with the compiled kernel, LLVM's code is paged out of the process (counted
in bytes resident), and the kernel draws the same pixels afterwards."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

_PROBE = """
import sys
import numpy as np
from tweenrender.pipeline.compiler_pages import compiler_resident_bytes, page_out_compiler
from tweenrender.raster.round_stroke import stroke_contours

assert page_out_compiler() == 0 and compiler_resident_bytes() == 0  # numba not loaded: nothing to do
rng = np.random.default_rng(3)
outline = rng.uniform(4, 60, (300, 2))

def drawn():
    pixels = np.zeros((64, 64, 4), np.uint8)
    stroke_contours(pixels, [outline], [True], 2.0, np.array([20.0, 40.0, 200.0, 255.0]))
    return pixels

before = drawn()
resident = compiler_resident_bytes()
asked = page_out_compiler()
after_page_out = compiler_resident_bytes(private=True)
again = drawn()
print(resident, asked, after_page_out, compiler_resident_bytes(private=True), int(np.array_equal(before, again)),
      int(before.any()))
"""

_NEIGHBOUR = """
import sys
from numba import njit
njit(lambda x: x + 1)(1)
print("ready", flush=True)
sys.stdin.read()
"""


@pytest.mark.skipif(sys.platform != "linux", reason="paging out is Linux's madvise(MADV_PAGEOUT)")
def test_the_compilers_code_is_paged_out_and_the_kernel_still_draws_the_same() -> None:
    """Another process holds LLVM's library mapped meanwhile (a second worker, a render beside the tests): the
    pages it shares cannot leave memory, and are not this process's to count; its own pages must go."""
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    neighbour = subprocess.Popen([sys.executable, "-c", _NEIGHBOUR], stdin=subprocess.PIPE, stdout=subprocess.PIPE,
                                 text=True, cwd=ROOT, env=env)
    try:
        assert neighbour.stdout is not None and neighbour.stdout.readline().strip() == "ready"
        done = subprocess.run([sys.executable, "-c", _PROBE], capture_output=True, text=True, cwd=ROOT, env=env,
                              timeout=600)
    finally:
        neighbour.communicate("", timeout=60)
    assert done.returncode == 0, done.stderr
    resident, asked, after_page_out, after_drawing, same, drew = (int(v) for v in done.stdout.split())
    if asked == 0:
        pytest.skip("this kernel refuses MADV_PAGEOUT (Linux before 5.4)")
    assert resident > 20 << 20  # LLVM's code, resident once a kernel is linked
    assert after_page_out < 4 << 20 and after_drawing < 4 << 20  # drawing again does not need it back
    assert same and drew


def test_the_first_frame_drawn_pages_the_compiler_out(monkeypatch) -> None:
    from tweenrender.pipeline import compiler_pages
    from tweenrender.pipeline.frames import Frames
    from tweenrender.plan.job import RenderJob
    from tweenrender.scenefile import load_scene

    calls: list[int] = []
    monkeypatch.setattr(compiler_pages, "page_out_compiler", lambda: calls.append(1) or 0)
    frames = Frames(RenderJob(load_scene(ROOT / "scenes" / "square.toml"), size=(64, 36)))
    for index in range(5):
        frames(index)
    assert calls == [1]
