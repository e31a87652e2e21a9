"""The format table drives what writes, reads back, tunes and lists each format: every name an entry
gives resolves, and every list of formats shown to a user is the table's."""

from __future__ import annotations

import inspect
from pathlib import Path

import pytest

from tweenrender.encode import formats
from tweenrender.encode.formats import TABLE
from tweenrender.encode.sinks import encoder_options
from tweenrender.encode.targets import check_output_name
from tweenrender.errors import OptionError

SINK_ARGUMENTS = ["fmt", "target", "width", "height", "fps", "frames", "pixel_format", "alpha", "draft"]


@pytest.mark.parametrize("fmt", sorted(TABLE))
def test_every_format_names_a_writer_that_resolves(fmt: str) -> None:
    made = formats.writer(fmt)
    assert callable(made)
    taken = list(inspect.signature(made).parameters)
    if TABLE[fmt].vector:  # writes a VectorClip
        assert taken[:2] == ["clip", "target"]
    else:  # a sink, as open_sink makes it
        assert taken == SINK_ARGUMENTS


@pytest.mark.parametrize("fmt", sorted(TABLE))
def test_every_encoded_format_names_a_reader_that_resolves(fmt: str) -> None:
    read = formats.reader(fmt)
    if TABLE[fmt].ffmpeg:
        assert callable(read) and list(inspect.signature(read).parameters) == ["path"]
    else:  # PNG frames are counted as they are written; a vector file holds no frames
        assert read is None


@pytest.mark.parametrize("fmt", sorted(TABLE))
def test_a_tuning_resolves_and_goes_after_the_encoder_name(fmt: str) -> None:
    tune = formats.tuning(fmt)
    options = encoder_options(fmt, 1920, 1080)
    if tune is None:
        assert options == TABLE[fmt].options()
        return
    encoder = TABLE[fmt].ffmpeg.index("-c:v") + 2
    added = tune(1920, 1080)
    assert added and options == [*TABLE[fmt].ffmpeg[:encoder], *added, *TABLE[fmt].ffmpeg[encoder:]]
    assert encoder_options(fmt) == TABLE[fmt].options()  # no size: no tuning


@pytest.mark.parametrize("fmt", sorted(f for f in TABLE if TABLE[f].join == "copy"))
def test_a_format_joined_by_stream_copy_names_its_muxer(fmt: str) -> None:
    assert TABLE[fmt].muxer == TABLE[fmt].ffmpeg[TABLE[fmt].ffmpeg.index("-f") + 1]


def test_the_lists_shown_to_users_are_the_tables() -> None:
    listed = [f for f in TABLE.values() if f.listed]
    assert formats.names() == formats.FORMATS == tuple(f.name for f in listed)
    assert set(formats.names(vector=True)) == {f.name for f in listed if f.vector}
    assert all(formats.is_vector(name) for name in formats.names(vector=True))
    assert not any(formats.is_vector(name) for name in formats.names(vector=False))
    assert not formats.is_vector("nut") and not formats.is_vector("no such format")
    text = formats.outputs_text()
    files = [f.suffix for f in listed if not f.folder]
    assert formats.suffixes() == tuple(files) and all(suffix in text for suffix in files)
    assert all(f"a folder of {f.codec} frames" in text for f in listed if f.folder)
    pictures = formats.outputs_text(vector=False)
    assert all((f.suffix in pictures) != f.vector for f in listed if not f.folder)
    assert formats.listing([]) == "" and formats.listing(["a"]) == "a"
    assert formats.listing(["a", "b"]) == "a and b" and formats.listing(["a", "b", "c"], "or") == "a, b or c"


def test_a_name_that_is_no_output_is_told_every_suffix(tmp_path: Path) -> None:
    with pytest.raises(OptionError) as caught:
        check_output_name(tmp_path / "..")
    assert all(suffix in str(caught.value) for suffix in formats.suffixes())


def test_a_vector_format_is_no_sink(tmp_path: Path) -> None:
    from tweenrender.encode import open_sink

    for fmt in formats.names(vector=True):
        with pytest.raises(OptionError, match="animated paths"):
            open_sink(fmt, tmp_path / f"clip{TABLE[fmt].suffix}", 64, 48, 24.0, 2)
    assert list(tmp_path.iterdir()) == []
