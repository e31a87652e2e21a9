"""Conformance with resvg's public test suite: frame 0 of each test drawing is its reference picture.

The drawings and reference PNGs are the suite's own (``tests/data/resvg``, MIT), compared by the key-frame
measure (over white; coverage IoU ≥ 0.99 and colour error ≤ 0.02). The tests tweenrender does not pass yet
are listed in ``expected-failures.txt`` and marked strict expected failures: one that starts passing fails
here until it is taken off the list, so the list only shrinks. Text is drawn in the suite's own font (Noto
Sans, OFL, cut down to Latin and Cyrillic: ``tests/data/resvg/fonts``), found through ``TWEENRENDER_FONT_PATH``.
"""

from __future__ import annotations

import warnings

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA
from tests.scenefile.test_key_frames import measures

SUITE = DATA / "resvg"
FONTS = SUITE / "fonts"
DRAWINGS = SUITE / "tests"  # as in the suite, beside its ``resources`` (pictures the tests link to)
TESTS = sorted(p.relative_to(DRAWINGS).as_posix() for p in DRAWINGS.glob("*/*/*.svg"))
EXPECTED_FAILURES = set((SUITE / "expected-failures.txt").read_text().split())


@pytest.fixture(autouse=True)
def _suite_fonts(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("TWEENRENDER_FONT_PATH", str(FONTS))


def _over_white(rgba: np.ndarray) -> np.ndarray:
    """Straight RGBA uint8 ``(H, W, 4)`` over white: RGB floats ``(H, W, 3)`` in [0, 255]."""
    if np.all(rgba[..., 3] == 255):
        return rgba[..., :3].astype(float)  # opaque: the colours themselves
    alpha = rgba[..., 3:4].astype(float) / 255.0
    return rgba[..., :3].astype(float) * alpha + 255.0 * (1.0 - alpha)


def _scores(name: str) -> tuple[float, float]:
    import imageio.v3 as iio

    svg = DRAWINGS / name
    reference = _over_white(iio.imread(svg.with_suffix(".png"), mode="RGBA"))
    height, width = reference.shape[:2]
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the reference PNGs' palettes
            picture = tr.frame(tr.load_scene(svg), 0.0, size=(width, height), background="#ffffff")
    except tr.TweenrenderError:
        return 0.0, 1.0  # refused: counted as not drawn
    return measures(_over_white(picture), reference)


def test_the_selection_is_the_suite_with_its_licence() -> None:
    assert len(TESTS) >= 500 and (SUITE / "LICENSE").read_text().startswith("The MIT License")
    assert all((DRAWINGS / name).with_suffix(".png").exists() for name in TESTS)
    assert EXPECTED_FAILURES <= set(TESTS), sorted(EXPECTED_FAILURES - set(TESTS))


@pytest.mark.parametrize("name", [pytest.param(n, marks=pytest.mark.xfail(strict=True, reason="expected failure"))
                                  if n in EXPECTED_FAILURES else n for n in TESTS])
def test_frame_zero_is_the_reference_picture(name: str) -> None:
    iou, error = _scores(name)
    assert iou >= 0.99 and error <= 0.02, (iou, error)
