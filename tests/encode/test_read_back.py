"""A written video whose frame count, as read back from the file, is not the count sent is not an output:
the sink refuses it and keeps what the target held, leaving no temporary beside it."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tweenrender.encode import open_sink
from tweenrender.errors import EncodeError


@pytest.mark.parametrize(("fmt", "reader"), [("mp4", "media_boxes"), ("mov", "media_boxes"),
                                             ("webm", "webm_elements"), ("gif", "gif_blocks")])
def test_a_sink_whose_file_reads_back_wrong_keeps_the_earlier_output(tmp_path: Path, monkeypatch, fmt: str,
                                                                      reader: str) -> None:
    target = tmp_path / f"movie.{fmt}"
    target.write_bytes(b"old movie")
    monkeypatch.setattr(f"tweenrender.encode.{reader}.video_track", lambda path: (4, (64, 48)))
    sink = open_sink(fmt, target, 64, 48, 24.0, 5)
    for shade in range(5):
        sink.write(np.full((48, 64, 4), (40 * shade, 0, 0, 255), dtype=np.uint8))
    with pytest.raises(EncodeError, match="has 4 frames"):
        sink.close()
    assert target.read_bytes() == b"old movie"
    assert sorted(p.name for p in tmp_path.iterdir()) == [f"movie.{fmt}"]
