"""Lottie numbers are written short: whole pixels as integers, no negative zero, the rest to a hundredth —
the same values the file held before (parsed back, each equals the float rounded to a hundredth)."""

from __future__ import annotations

import json
import re

import numpy as np

from tweenrender.encode.lottie_values import compact


def test_compact_numbers_parse_back_to_the_rounded_values() -> None:
    rng = np.random.default_rng(4)
    values = np.concatenate([rng.uniform(-500, 500, (50, 2)), np.round(rng.uniform(-500, 500, (50, 2))),
                             [[-0.0, -0.0004], [0.0004, 1e300], [-1e300, 2.0 ** 60]]])
    text = json.dumps(compact(values), separators=(",", ":"))
    assert not re.search(r"(?<![\d.e+-])-?\d+\.0(?![\d])", text), "a whole number written with .0"
    assert not re.search(r"(?<![\d.])-0(?![\d.])", text), "a negative zero"
    back = np.array(json.loads(text), dtype=np.float64)
    np.testing.assert_array_equal(back, np.round(values, 2) + 0.0)
    assert isinstance(json.loads(text)[50][0], int)
