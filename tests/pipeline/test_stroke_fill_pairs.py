"""An element drawn with a stroke alone morphing into one drawn with a fill alone (an outline icon into
a filled one): the stroke is outlined, so its band of ink becomes the filled shape's ring, instead of a
disc of fill fading in over the ring's hole while the stroke fades out.

Measured on the rendered frames (alpha of a transparent background, an independent picture of what is
drawn): the ink at t = 1/4, 1/2, 3/4 stays within 15 % (of the larger key's ink) of the straight blend
of the keys' ink; before, 24–43 % more, a grey disc filling the ring.
"""

from __future__ import annotations

import numpy as np
import pytest

import tweenrender as tr
from tests.helpers import DATA

ICONS = DATA / "icons"


def ink(scene: tr.Scene, t: float) -> float:
    return float(tr.frame(scene, t, size=(160, 160), background="#00000000")[..., 3].astype(np.float64).mean() / 255)


@pytest.mark.parametrize("first, second", [
    ("lucide/circle-check.svg", "bootstrap/emoji-smile.svg"),  # before: 0.27, 0.41, 0.27
    ("octicons/smiley-24.svg", "lucide/heart.svg"),  # 0.24, 0.37, 0.30
    ("feather/smile.svg", "octicons/star-24.svg"),  # 0.28, 0.43, 0.34
])
def test_a_stroke_becomes_a_fill_without_a_disc_of_fill(first: str, second: str) -> None:
    scene = tr.load_scene([ICONS / first, ICONS / second], step=1.0)
    a, b = ink(scene, 0.0), ink(scene, 1.0)
    for t in (0.25, 0.5, 0.75):
        assert abs(ink(scene, t) - ((1 - t) * a + t * b)) <= 0.15 * max(a, b), t


def test_the_keys_are_drawn_as_they_were() -> None:
    """Outlining a stroke draws the same picture at its key: compared with the element drawn alone."""
    outline = tr.load_scene([ICONS / "lucide/circle-check.svg", ICONS / "bootstrap/emoji-smile.svg"], step=1.0)
    alone = tr.load_scene([ICONS / "lucide/circle-check.svg", ICONS / "lucide/circle-check.svg"], step=1.0)
    x = tr.frame(outline, 0.0, size=(160, 160), background="#00000000")[..., 3].astype(np.float64) / 255
    y = tr.frame(alone, 0.0, size=(160, 160), background="#00000000")[..., 3].astype(np.float64) / 255
    assert np.abs(x - y).mean() < 0.002 and np.abs(x - y).max() < 0.5
