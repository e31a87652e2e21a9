"""``balance`` in a scene: per scene and per shape, checked like every other choice."""

from __future__ import annotations

from pathlib import Path

import pytest

from tweenrender.errors import SceneError
from tweenrender.model import DEFAULT_BALANCE
from tweenrender.scenefile import load_scene

from ..helpers import SQUARE, write_scene


def test_balance_per_scene_and_per_shape(tmp_path: Path) -> None:
    text = 'balance = "spread"\n' + SQUARE.replace('name = "sq"', 'name = "sq"\nbalance = "copies"')
    scene = load_scene(write_scene(tmp_path, text))
    assert scene.balance == "spread"
    assert scene.balance_of(scene.shapes[0]) == "copies"
    plain = load_scene(write_scene(tmp_path, SQUARE, "plain.toml"))
    assert plain.balance == DEFAULT_BALANCE and plain.balance_of(plain.shapes[0]) == DEFAULT_BALANCE


@pytest.mark.parametrize("text, where", [
    ('balance = "spred"\n' + SQUARE, "balance"),
    (SQUARE.replace('name = "sq"', 'name = "sq"\nbalance = 3'), "shape[0].balance"),
])
def test_a_bad_balance_is_refused_with_its_place(tmp_path: Path, text: str, where: str) -> None:
    with pytest.raises(SceneError) as caught:
        load_scene(write_scene(tmp_path, text))
    assert caught.value.where is not None and caught.value.where.startswith(where)
    assert "copies" in str(caught.value) or "string" in str(caught.value)
