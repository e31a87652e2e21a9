"""What an output may replace: a PNG target replaces only an earlier frame set; a target must be a name.

Through the real command line and the library: the refusal is one line, exit 2,
before anything is drawn, and every file that was there is still there, byte for byte.
"""

from __future__ import annotations

import os
from pathlib import Path

import pytest

import tweenrender as tr
from tweenrender.errors import OptionError

from tests.helpers import SQUARE, read_png, run_main, write_scene


def _tree(folder: Path) -> dict[str, bytes | None]:
    """Every entry under ``folder`` (hidden ones too) with its bytes (None for a folder or link)."""
    found: dict[str, bytes | None] = {}
    for path in sorted(folder.rglob("*")):
        name = str(path.relative_to(folder))
        found[name] = path.read_bytes() if path.is_file() and not path.is_symlink() else None
    return found


@pytest.mark.parametrize("extra", ["notes.txt", "frame_0000.jpg", ".hidden", "sub/frame_0001.png", "frame_1.png"])
def test_a_folder_with_anything_but_frames_is_refused(cli, tmp_path: Path, extra: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    docs = tmp_path / "mydocs"
    (docs / extra).parent.mkdir(parents=True, exist_ok=True)
    (docs / extra).write_bytes(b"the user's own file")
    (docs / "frame_0000.png").write_bytes(b"an earlier frame")
    before = _tree(tmp_path)
    code, out, err = cli("render", scene, "-o", docs, "--format", "png", "-q")
    assert code == 2 and out == ""
    assert err.startswith(f"tweenrender: error: {docs}: ") and err.count("\n") == 1, err
    assert ".tweenrender-manifest.json" in err
    assert _tree(tmp_path) == before


def test_output_slash_is_refused_and_its_videos_kept(tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    (tmp_path / "output").mkdir()
    (tmp_path / "output" / "earlier.mp4").write_bytes(b"an earlier video")
    before = _tree(tmp_path)
    done = run_main("render", scene, "-o", "output/", "-q", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.startswith("tweenrender: error: output: "), done.stderr
    assert done.stderr.count("\n") == 1
    assert _tree(tmp_path) == before


def test_a_scene_whose_stem_is_a_dot_does_not_replace_the_output_folder(tmp_path: Path) -> None:
    write_scene(tmp_path, SQUARE, "..toml")  # its stem is ".": output/<stem> would be output/ itself
    (tmp_path / "output").mkdir()
    (tmp_path / "output" / "earlier.mp4").write_bytes(b"an earlier video")
    before = _tree(tmp_path)
    done = run_main("render", "..toml", "--format", "png", "-q", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "Traceback" not in done.stderr and "output" in done.stderr
    assert _tree(tmp_path) == before


@pytest.mark.parametrize("name, words", [(".", "the current folder"), ("", "empty"), ("/", "the root folder"),
                                         ("..", "a parent folder"), ("sub/..", "a parent folder")])
@pytest.mark.parametrize("fmt", ["png", "mp4"])
def test_no_name_is_a_usage_error(tmp_path: Path, name: str, words: str, fmt: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    (tmp_path / "sub").mkdir()
    before = _tree(tmp_path)
    done = run_main("render", scene, "-o", name, "--format", fmt, "-q", cwd=tmp_path)
    assert done.returncode == 2, done.stderr
    assert done.stderr == f"tweenrender: error: output {name!r} is {words}; expected a file name " \
                          "(.mp4, .webm, .mov, .gif, .json, .lottie, .svg) or a folder's name for PNG frames\n"
    assert _tree(tmp_path) == before


def test_an_earlier_frame_set_or_an_empty_folder_is_replaced(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    frames = tmp_path / "frames"
    code, out, err = cli("render", scene, "-o", frames, "--size", "64x48", "-q")
    assert code == 0, err
    code, out, err = cli("render", scene, "-o", frames, "--frames", "0:3", "-q")  # fewer: none of the 49 survive
    assert code == 0, err
    assert sorted(p.name for p in frames.iterdir()) == [".tweenrender-manifest.json"] + [
        f"frame_{i:04d}.png" for i in range(3)]
    assert read_png(frames / "frame_0000.png").shape == (240, 320, 4)
    empty = tmp_path / "empty"
    empty.mkdir()
    code, _, err = cli("render", scene, "-o", empty, "--frames", "0:2", "-q")
    assert code == 0, err
    assert sorted(p.name for p in empty.iterdir()) == [".tweenrender-manifest.json", "frame_0000.png",
                                                        "frame_0001.png"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["empty", "frames", "scene.toml"]


def test_a_file_where_the_frames_folder_would_go_is_refused(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    (tmp_path / "notes").write_bytes(b"the user's notes")
    code, _, err = cli("render", scene, "-o", tmp_path / "notes", "-q")
    assert code == 2 and err.startswith(f"tweenrender: error: {tmp_path / 'notes'}: ") and err.count("\n") == 1
    assert (tmp_path / "notes").read_bytes() == b"the user's notes"


def test_a_symlinked_frames_target_leaves_nothing_behind(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    real = tmp_path / "real"
    assert cli("render", scene, "-o", real, "--frames", "0:1", "-q")[0] == 0  # an earlier frame set
    earlier = _tree(real)
    (tmp_path / "frames").symlink_to(real, target_is_directory=True)
    code, _, err = cli("render", scene, "-o", tmp_path / "frames", "--frames", "0:3", "-q")
    assert code == 0, err
    # the link is replaced, like a linked video would be; what it pointed to is left alone
    assert not (tmp_path / "frames").is_symlink()
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == [".tweenrender-manifest.json"] + [
        f"frame_{i:04d}.png" for i in range(3)]
    assert _tree(real) == earlier
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frames", "real", "scene.toml"]


def test_the_library_refuses_what_the_command_line_refuses(cli, tmp_path: Path) -> None:
    scene_path = write_scene(tmp_path, SQUARE)
    scene = tr.load_scene(scene_path)
    docs = tmp_path / "mydocs"
    docs.mkdir()
    (docs / "notes.txt").write_bytes(b"the user's own file")
    before = _tree(tmp_path)
    for target, fmt in ((docs, None), (docs, "png"), ("", None), (".", "png"), ("/", None), ("..", "mp4")):
        with pytest.raises(OptionError) as caught:
            tr.write(scene, target, format=fmt, workers=1)
        args = ["render", scene_path, "-o", target, "-q"] + (["--format", fmt] if fmt else [])
        code, _, err = cli(*args)
        assert code == 2 and err == f"tweenrender: error: {caught.value}\n"
    assert _tree(tmp_path) == before


def test_a_folder_filled_while_rendering_is_not_replaced(tmp_path: Path, monkeypatch) -> None:
    """The rule holds when the frames are moved into place, not only when the render starts."""
    from tweenrender.encode import sinks

    scene = tr.load_scene(write_scene(tmp_path, SQUARE))
    frames = tmp_path / "frames"
    frames.mkdir()
    real_close = sinks.PngSequence.close

    def close_after_a_save(self: sinks.PngSequence) -> Path:
        (frames / "notes.txt").write_bytes(b"saved here during the render")
        return real_close(self)

    monkeypatch.setattr(sinks.PngSequence, "close", close_after_a_save)
    with pytest.raises(OptionError, match="notes.txt"):
        tr.write(scene, frames, frames="0:2", workers=1)
    assert _tree(tmp_path / "frames") == {"notes.txt": b"saved here during the render"}
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frames", "scene.toml"]


def test_the_roll_back_puts_the_old_frames_back(tmp_path: Path, monkeypatch) -> None:
    """When the finished folder cannot take the target's name, the old folder is moved back, whole."""
    from tweenrender.encode import atomic
    from tweenrender.errors import EncodeError

    scene = tr.load_scene(write_scene(tmp_path, SQUARE))
    frames = tmp_path / "frames"
    tr.write(scene, frames, frames="0:1", workers=1)  # an earlier frame set
    earlier = _tree(frames)
    real_replace = os.replace
    calls: list[tuple[str, str]] = []

    def second_rename_fails(source: object, destination: object) -> None:
        calls.append((Path(source).name, Path(destination).name))
        if len(calls) == 2:  # the new folder taking the target's name
            raise OSError(28, "No space left on device")
        real_replace(source, destination)

    monkeypatch.setattr(atomic.os, "replace", second_rename_fails)
    with pytest.raises(EncodeError, match="No space left on device"):
        tr.write(scene, frames, frames="0:2", workers=1)
    assert len(calls) == 3 and calls[2][1] == "frames"  # aside, (failed) in, back
    assert _tree(tmp_path / "frames") == earlier
    assert sorted(p.name for p in tmp_path.iterdir()) == ["frames", "scene.toml"]
