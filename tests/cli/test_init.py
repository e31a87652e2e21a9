"""tweenrender init: the scene written renders exactly as the command line it came from, and it never
replaces a file."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import read_png
from tweenrender.errors import OptionError

SHAPES = ('<rect x="10" y="10" width="30" height="20" fill="#c03"/><circle cx="70" cy="70" r="12"/>',
          '<rect x="50" y="40" width="20" height="40" fill="#c03"/><circle cx="25" cy="70" r="18"/>',
          '<rect x="20" y="60" width="40" height="10" fill="#c03"/><circle cx="80" cy="20" r="8"/>')


def _drawings(folder: Path) -> list[Path]:
    folder.mkdir(parents=True, exist_ok=True)
    out = []
    for name, body in zip("abc", SHAPES):
        path = folder / f"{name}.svg"
        path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">{body}</svg>')
        out.append(path)
    return out


def _frames(folder: Path) -> list[np.ndarray]:
    return [read_png(p) for p in sorted(folder.glob("frame_*.png"))]


def test_init_then_render_equals_the_command_line(cli, tmp_path, monkeypatch) -> None:
    drawings = _drawings(tmp_path / "art")
    timing = ("--step", "0.5", "--ease", "cubic-bezier(0.3, 0, 0.2, 1)", "--hold", "0.25", "--stagger", "0.1")
    scene = tmp_path / "scenes" / "morph.toml"
    scene.parent.mkdir()
    code, out, err = cli("init", *drawings, *timing, "-o", scene)
    assert code == 0, err
    assert out.strip() == str(scene)
    assert '"../art/a.svg"' in scene.read_text()  # relative to the scene's folder
    small = ("--fps", "12", "--size", "80x80", "--format", "png", "-q")
    code, _, err = cli("render", *drawings, *timing, *small, "-o", tmp_path / "direct")
    assert code == 0, err
    code, _, err = cli("render", scene, *small, "-o", tmp_path / "scened")
    assert code == 0, err
    direct, scened = _frames(tmp_path / "direct"), _frames(tmp_path / "scened")
    assert len(direct) == len(scened) == 22  # keys at 0, 0.75, 1.5 s, the last held 0.25 s: 1.75 s at 12 fps, + 1
    assert len({d.tobytes() for d in direct}) > 5  # something moves
    for a, b in zip(direct, scened):
        np.testing.assert_array_equal(a, b)


def test_default_name_and_never_replacing(cli, tmp_path, monkeypatch) -> None:
    drawings = _drawings(tmp_path / "art")
    monkeypatch.chdir(tmp_path)
    code, out, err = cli("init", *drawings[:2])
    target = tmp_path / "a-b.toml"
    assert code == 0, err and out.strip() == "a-b.toml"
    written = target.read_bytes()
    assert b'svg = "art/a.svg"' in written
    code, out, err = cli("init", *drawings[1:], "-o", "a-b.toml")
    assert code == 2 and out == ""
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "a-b.toml: already exists" in lines[0] and "Traceback" not in err
    assert target.read_bytes() == written
    assert [p.name for p in tmp_path.iterdir() if p.name.startswith(".")] == []  # no temporary left


def test_init_refuses_what_render_refuses(cli, tmp_path, monkeypatch) -> None:
    drawings = _drawings(tmp_path)
    monkeypatch.chdir(tmp_path)
    code, _, err = cli("init", *drawings[:2], "--ease", "wobbly")
    assert code == 2 and len(err.strip().splitlines()) == 1 and "--ease" in err
    scene = tmp_path / "s.toml"
    scene.write_text('[[drawing]]\ntime = 0\nsvg = "a.svg"\n')
    code, _, err = cli("init", scene)
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert not (tmp_path / "a-b.toml").exists()


def test_the_library_returns_the_text(tmp_path) -> None:
    import tweenrender as tr

    drawings = _drawings(tmp_path)
    text = tr.init_scene([str(p) for p in drawings[:2]], step=2.0, path=tmp_path / "x.toml")
    assert (tmp_path / "x.toml").read_text() == text
    scene = tr.load_scene(tmp_path / "x.toml")
    assert [k.time for k in scene.shapes[0].keys] == [0.0, 2.0]


def test_names_init_cannot_write_are_one_line(cli, tmp_path, monkeypatch) -> None:
    drawings = _drawings(tmp_path / "art")
    monkeypatch.chdir(tmp_path)
    for name in ("n" * 300 + ".toml", "scene.txt", "no/such/folder/s.toml"):
        code, out, err = cli("init", *drawings[:2], "-o", name)
        assert code == 2 and out == "" and len(err.strip().splitlines()) == 1 and "Traceback" not in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["art"]


def test_a_scene_made_meanwhile_is_not_replaced(tmp_path, monkeypatch) -> None:
    """Another program takes the name between the check and the write: its file stays."""
    from tweenrender.encode import atomic

    target = tmp_path / "s.toml"
    real = atomic.sibling

    def racing(path, suffix=""):
        target.write_text("theirs")
        return real(path, suffix)

    monkeypatch.setattr(atomic, "sibling", racing)
    with pytest.raises(OptionError, match="already exists"):
        atomic.create_new(target, "ours")
    assert target.read_text() == "theirs"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]
