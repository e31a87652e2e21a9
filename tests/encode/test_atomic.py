"""Writing through a temporary: the target changes only when the writing finished."""

from __future__ import annotations

from pathlib import Path

import pytest

from tweenrender.encode.atomic import replacing
from tweenrender.errors import EncodeError


@pytest.mark.parametrize("failure", [KeyboardInterrupt, SystemExit, RuntimeError])
def test_an_interrupted_write_leaves_the_target_and_no_temporary(tmp_path: Path, failure: type) -> None:
    target = tmp_path / "picture.png"
    target.write_bytes(b"the earlier picture")
    with pytest.raises(failure):
        with replacing(target, ".png") as temporary:
            temporary.write_bytes(b"half a pict")
            raise failure()
    assert target.read_bytes() == b"the earlier picture"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["picture.png"]


def test_a_failed_write_names_the_target_and_leaves_no_temporary(tmp_path: Path) -> None:
    target = tmp_path / "picture.png"
    with pytest.raises(EncodeError, match=f"{target}: cannot write the picture \\(No space left on device\\)"):
        with replacing(target, ".png", "the picture") as temporary:
            temporary.write_bytes(b"half")
            raise OSError(28, "No space left on device")
    assert list(tmp_path.iterdir()) == []


def test_a_finished_write_replaces_the_target(tmp_path: Path) -> None:
    target = tmp_path / "picture.png"
    target.write_bytes(b"the earlier picture")
    with replacing(target, ".png") as temporary:
        temporary.write_bytes(b"the new picture")
        assert not target.read_bytes() == b"the new picture"  # not before the end
    assert target.read_bytes() == b"the new picture"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["picture.png"]
