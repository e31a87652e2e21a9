"""render a.svg b.svg --ease --hold --stagger: the frames written land where the contract says."""

from __future__ import annotations

from pathlib import Path

import numpy as np
from PIL import Image

BOXES = ('<rect x="0" y="0" width="10" height="10"/><rect x="60" y="0" width="10" height="10"/>',
         '<rect x="0" y="80" width="10" height="10"/><rect x="60" y="80" width="10" height="10"/>')


def _drawings(tmp_path: Path) -> list[str]:
    out = []
    for name, body in zip("ab", BOXES):
        path = tmp_path / f"{name}.svg"
        path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">{body}</svg>')
        out.append(str(path))
    return out


def _ink_rows(frame: Path, left: bool) -> tuple[int, int]:
    """The first and last rows with ink in the left (or right) half of a frame."""
    pixels = np.asarray(Image.open(frame).convert("L"))
    half = pixels[:, : pixels.shape[1] // 2] if left else pixels[:, pixels.shape[1] // 2:]
    rows = np.flatnonzero((half < 128).any(axis=1))
    return int(rows[0]), int(rows[-1])


def test_hold_and_stagger_frames(cli, tmp_path) -> None:
    out = tmp_path / "frames"
    code, _, err = cli("render", *_drawings(tmp_path), "--hold", "0.5", "--step", "1", "--stagger", "0.5",
                       "--ease", "steps(2, jump-none)", "--fps", "4", "--size", "100x100", "--format", "png",
                       "-o", out)
    assert code == 0, err
    frames = sorted(out.glob("frame_*.png"))
    assert len(frames) == 9  # 0.5 s hold + 1 s move + 0.5 s hold at 4 fps, both ends included
    left = [_ink_rows(f, True) for f in frames]
    right = [_ink_rows(f, False) for f in frames]
    top, bottom = left[0], left[-1]
    assert top[0] == 0 and bottom[1] == 89
    # the left box: held until 0.5 s, then steps(2, jump-none) over 0.5..1.5 s (jumps 0 → 1 at u = 1/2)
    assert left[:4] == [top] * 4 and left[4:] == [bottom] * 5  # frame 4 = 1.0 s: u = 1/2, at the end already
    # the right box starts 0.5 s later: still held at 1.0 s, then over 1.0..1.5 s it jumps mid-way at 1.25 s
    assert right[:5] == [top] * 5 and right[5:] == [bottom] * 4


def test_timing_flags_are_for_drawings(cli, tmp_path) -> None:
    scene = tmp_path / "s.toml"
    scene.write_text('[[shape]]\nname = "s"\n[[shape.key]]\ntime = 0\npoints = [[0, 0], [1, 0], [0, 1]]\n')
    code, _, err = cli("render", scene, "--stagger", "0.1", "-o", tmp_path / "x.gif")
    assert code == 2 and err.strip().endswith("--stagger: applies to SVG drawings morphing into each other; "
                                              "a scene file sets ease and stagger itself")
    code, _, err = cli("render", *_drawings(tmp_path), "--ease", "steps(0)", "-o", tmp_path / "x.gif")
    assert code == 2 and "--ease: expected n from 1 to 10000 in steps(n), found 0" in err
    assert not (tmp_path / "x.gif").exists()


def test_the_library_names_the_keyword(tmp_path) -> None:
    import pytest

    import tweenrender as tr

    drawings = _drawings(tmp_path)
    with pytest.raises(tr.OptionError, match=r"^ease=: expected n from 1 to 10000 in steps\(n\), found 0$"):
        tr.load_scene(drawings, ease="steps(0)")
    with pytest.raises(tr.OptionError, match=r"^hold=: expected seconds from 0"):
        tr.load_scene(drawings, hold=-1)


def _path_keyframes(document: dict) -> list[list[dict]]:
    found: list[list[dict]] = []

    def walk(node: object) -> None:
        if isinstance(node, dict):
            if node.get("ty") == "sh" and isinstance(node.get("ks"), dict) and node["ks"].get("a") == 1:
                found.append(node["ks"]["k"])
            for value in node.values():
                walk(value)
        elif isinstance(node, list):
            for value in node:
                walk(value)

    walk(document)
    return found


def test_lottie_of_held_drawings_moves_after_the_hold(tmp_path) -> None:
    """Exact linear keyframes start where the hold ends, with the curve's own handles."""
    import json

    import tweenrender as tr

    scene = tr.load_scene(_drawings(tmp_path), step=1.0, hold=0.5, ease="ease-in")
    tr.write(scene, tmp_path / "held.json", fps=4, method="linear")
    keyframes = _path_keyframes(json.loads((tmp_path / "held.json").read_text()))
    assert keyframes
    for frames in keyframes:
        assert [k["t"] for k in frames] == [2, 6]  # 0.5 s held at 4 fps, then 1 s of motion
        assert frames[0]["o"]["x"] == [0.42] and frames[0]["o"]["y"] == [0.0]
        assert frames[0]["i"]["x"] == [1.0] and frames[0]["i"]["y"] == [1.0]
