"""Own only what we wrote: a folder is replaced only when its manifest lists every entry, unchanged.

The frames folder and the report folder are checked through the real command line: a refusal
is one line naming the first foreign or changed entry, exit 2, and every byte that was there
is still there.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

from tests.helpers import SCENES, SQUARE, run_main, write_scene

MANIFEST = ".tweenrender-manifest.json"


def _tree(folder: Path) -> dict[str, bytes | None]:
    """Every entry under ``folder`` (hidden ones too) with its bytes (None for a folder or link)."""
    return {str(p.relative_to(folder)): (p.read_bytes() if p.is_file() and not p.is_symlink() else None)
            for p in sorted(folder.rglob("*"))}


def _render(cli, scene: Path, frames: Path) -> tuple[int, str, str]:
    return cli("render", scene, "-o", frames, "--format", "png", "--frames", "0:3", "-q")


def test_a_frames_folder_carries_a_manifest_of_its_files(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    code, _, err = _render(cli, scene, tmp_path / "frames")
    assert code == 0, err
    listed = json.loads((tmp_path / "frames" / MANIFEST).read_text())["files"]
    on_disk = {p.name: p.stat().st_size for p in (tmp_path / "frames").iterdir() if p.name != MANIFEST}
    assert sorted(on_disk) == ["frame_0000.png", "frame_0001.png", "frame_0002.png"]
    assert {name: entry["bytes"] for name, entry in listed.items()} == on_disk


def test_our_own_frames_are_replaced(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    frames = tmp_path / "frames"
    assert cli("render", scene, "-o", frames, "--frames", "0:5", "-q")[0] == 0
    code, _, err = _render(cli, scene, frames)
    assert code == 0, err
    assert sorted(p.name for p in frames.iterdir()) == [MANIFEST, "frame_0000.png", "frame_0001.png",
                                                         "frame_0002.png"]


def test_a_folder_of_the_users_own_frames_is_refused(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    frames = tmp_path / "frames"
    frames.mkdir()
    for index in range(1, 4):
        (frames / f"frame_{index:04d}.png").write_bytes(b"the user's own drawing")
    before = _tree(tmp_path)
    code, out, err = _render(cli, scene, frames)
    assert code == 2 and out == ""
    assert err.startswith(f"tweenrender: error: {frames}: ") and err.count("\n") == 1, err
    assert "frame_0001.png" in err and MANIFEST in err  # the first entry, and what is missing
    assert _tree(tmp_path) == before


@pytest.mark.parametrize("change", ["add", "grow", "touch", "subfolder", "link"])
def test_a_foreign_or_changed_entry_is_named_and_kept(cli, tmp_path: Path, change: str) -> None:
    scene = write_scene(tmp_path, SQUARE)
    frames = tmp_path / "frames"
    assert _render(cli, scene, frames)[0] == 0
    named = {"add": "notes.txt", "grow": "frame_0001.png", "touch": "frame_0002.png", "subfolder": "a-sub",
             "link": "frame_0003.png"}[change]
    if change == "add":
        (frames / named).write_bytes(b"a note saved among the frames")
    elif change == "grow":
        with (frames / named).open("ab") as handle:
            handle.write(b"!")
    elif change == "touch":  # same size, rewritten: another picture of the same length
        data = (frames / named).read_bytes()
        stamp = (frames / named).stat().st_mtime_ns
        (frames / named).write_bytes(data[::-1])
        os.utime(frames / named, ns=(stamp + 5_000_000_000, stamp + 5_000_000_000))
    elif change == "subfolder":
        (frames / named).mkdir()
    else:
        (frames / named).symlink_to(scene)
    before = _tree(tmp_path)
    code, _, err = _render(cli, scene, frames)
    assert code == 2 and err.count("\n") == 1, err
    assert err.startswith(f"tweenrender: error: {frames}: ") and named in err
    assert _tree(tmp_path) == before


def test_a_manifest_that_is_a_folder_owns_nothing(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    frames = tmp_path / "frames"
    frames.mkdir()
    (frames / MANIFEST).mkdir()
    before = _tree(tmp_path)
    code, _, err = _render(cli, scene, frames)
    assert code == 2 and MANIFEST in err and err.count("\n") == 1, err
    assert _tree(tmp_path) == before


def test_a_manifest_listing_names_the_tool_never_writes_owns_nothing(cli, tmp_path: Path) -> None:
    """A frames manifest is trusted for frame names only: ``frame_0000.png.orig`` is not one."""
    scene = write_scene(tmp_path, SQUARE)
    frames = tmp_path / "frames"
    frames.mkdir()
    for name in ("frame_0000.png", "frame_0000.png.orig"):
        (frames / name).write_bytes(b"a picture")
    stamp = (frames / "frame_0000.png.orig").stat().st_mtime_ns
    listing = {name: {"bytes": 9, "mtime_ns": (frames / name).stat().st_mtime_ns}
               for name in ("frame_0000.png", "frame_0000.png.orig")}
    (frames / MANIFEST).write_text(json.dumps({"written_by": "tweenrender", "files": listing}))
    assert stamp
    before = _tree(tmp_path)
    code, _, err = _render(cli, scene, frames)
    assert code == 2 and "frame_0000.png.orig" in err and err.count("\n") == 1, err
    assert _tree(tmp_path) == before


def test_a_report_folder_with_a_note_or_the_scene_inside_is_kept(tmp_path: Path) -> None:
    folder = tmp_path / "square-report"
    assert run_main("report", SCENES / "square.toml", "--compare", "linear", "-o", folder, "-q").returncode == 0
    assert (folder / MANIFEST).is_file()
    (folder / "my notes.txt").write_text("what I saw in the linear column")
    before = _tree(tmp_path)
    done = run_main("report", SCENES / "square.toml", "--compare", "linear", "-o", folder, "-q")
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert "my notes.txt" in done.stderr and "Traceback" not in done.stderr
    assert _tree(tmp_path) == before


def test_a_report_written_before_manifests_is_refused_with_the_way_out(tmp_path: Path) -> None:
    folder = tmp_path / "old-report"
    folder.mkdir()
    (folder / ".tweenrender-report").write_text("a report written by tweenrender; the folder is replaced whole\n")
    (folder / "index.html").write_text("<!doctype html>")
    before = _tree(tmp_path)
    done = run_main("report", SCENES / "square.toml", "--compare", "linear", "-o", folder, "-q")
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert MANIFEST in done.stderr and "remove" in done.stderr
    assert _tree(tmp_path) == before


def test_a_report_marker_that_is_a_folder_owns_nothing(tmp_path: Path) -> None:
    folder = tmp_path / "report"
    (folder / ".tweenrender-report").mkdir(parents=True)
    before = _tree(tmp_path)
    done = run_main("report", SCENES / "square.toml", "--compare", "linear", "-o", folder, "-q")
    assert done.returncode == 2 and done.stderr.count("\n") == 1, done.stderr
    assert _tree(tmp_path) == before


def test_a_listing_not_stamped_by_tweenrender_owns_nothing(cli, tmp_path: Path) -> None:
    """Another tool's ``files`` list in a file of that name is not ours: only a stamped manifest counts."""
    scene = write_scene(tmp_path, SQUARE)
    frames = tmp_path / "frames"
    frames.mkdir()
    (frames / "frame_0000.png").write_bytes(b"the user's picture")
    info = (frames / "frame_0000.png").stat()
    listing = {"frame_0000.png": {"bytes": info.st_size, "mtime_ns": info.st_mtime_ns}}
    (frames / MANIFEST).write_text(json.dumps({"files": listing}))
    before = _tree(tmp_path)
    code, _, err = _render(cli, scene, frames)
    assert code == 2 and MANIFEST in err and err.count("\n") == 1, err
    assert _tree(tmp_path) == before
