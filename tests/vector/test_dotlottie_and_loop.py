"""dotLottie archives and looping files: the archive unzipped by the standard library and read as the dotLottie
format lays it out (a manifest, the animation under ``animations/``); the animated SVG's ``--loop`` played by
headless Chromium past its end, against the project's own frames at the same point of the clip."""

from __future__ import annotations

import json
import zipfile
from pathlib import Path

import pytest

import tweenrender as tr
from tests.helpers import DATA, run_main, write_scene
from tests.vector.test_vector_output import ROUND, TURN
from tests.vector_players import check_pictures, chromium_svg_frames, rlottie_frames


def _scene(tmp_path: Path) -> tr.Scene:
    return tr.load_scene(write_scene(tmp_path, ROUND.format(method="nonlinear")))


@pytest.mark.parametrize("loop", [False, True])
def test_dotlottie_holds_the_lottie_json_and_a_manifest(tmp_path: Path, loop: bool) -> None:
    scene = _scene(tmp_path)
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    json_file = tr.write(scene, tmp_path / "a" / "morph.json")
    archive = tr.write(scene, tmp_path / "b" / "morph.lottie", loop=loop)
    assert archive == tmp_path / "b" / "morph.lottie"
    with zipfile.ZipFile(archive) as opened:
        assert opened.testzip() is None
        assert sorted(opened.namelist()) == ["animations/morph.json", "manifest.json"]
        assert all(info.compress_type == zipfile.ZIP_DEFLATED for info in opened.infolist())
        manifest = json.loads(opened.read("manifest.json"))
        animation = opened.read("animations/morph.json")
    assert animation == json_file.read_bytes()  # the same animation, byte for byte
    assert manifest["version"].startswith("1")
    assert manifest["activeAnimationId"] == "morph"
    (entry,) = manifest["animations"]
    assert entry["id"] == "morph" and entry["loop"] is loop and entry["speed"] == 1


def test_dotlottie_animation_plays_in_rlottie(tmp_path: Path) -> None:
    """No player here reads the archive itself (ThorVG's Python wheel answers NonSupport), so rlottie plays the
    animation unzipped from it, every frame."""
    scene = _scene(tmp_path)
    archive = tr.write(scene, tmp_path / "blob.lottie")
    with zipfile.ZipFile(archive) as opened:
        (tmp_path / "blob.json").write_bytes(opened.read("animations/blob.json"))
    frames = list(range(41))
    check_pictures(scene, rlottie_frames(tmp_path / "blob.json", frames, (400, 300)), frames, None, "rlottie")


def test_format_flag_and_odd_names(tmp_path: Path) -> None:
    scene_file = write_scene(tmp_path, ROUND.format(method="linear"))
    done = run_main("render", scene_file, "--format", "dotlottie", "-o", tmp_path / "out.lottie", "-q")
    assert done.returncode == 0, done.stderr
    with zipfile.ZipFile(tmp_path / "out.lottie") as opened:
        assert "animations/out.json" in opened.namelist()
    archive = tr.write(tr.load_scene(scene_file), tmp_path / "my morph #2.lottie")
    with zipfile.ZipFile(archive) as opened:  # the id keeps letters, digits, - and _
        assert json.loads(opened.read("manifest.json"))["animations"][0]["id"] == "my_morph__2"
        assert "animations/my_morph__2.json" in opened.namelist()


def test_loop_on_a_file_that_cannot_say_is_a_usage_error(tmp_path: Path) -> None:
    scene_file = write_scene(tmp_path, TURN.format(method="rigid", ease="linear", rule="evenodd"))
    kept = tmp_path / "out.json"
    kept.write_text("mine")
    done = run_main("render", scene_file, "--loop", "-o", kept, "-q")
    assert done.returncode == 2
    lines = done.stderr.strip().splitlines()
    assert len(lines) == 1 and "--loop" in lines[0] and "lottie" in lines[0]
    assert "dotlottie (.lottie)" in lines[0] and "svg (.svg)" in lines[0]  # what can, from the format table
    assert "Traceback" not in done.stderr and "Warning" not in done.stderr
    assert kept.read_text() == "mine"
    with pytest.raises(tr.OptionError, match="loop"):
        tr.write(tr.load_scene(scene_file), tmp_path / "x.mp4", loop=True)
    with pytest.raises(tr.OptionError, match="True or False"):
        tr.write(tr.load_scene(scene_file), tmp_path / "x.svg", loop="yes")
    help_text = run_main("render", "--help").stdout
    assert "--loop" in help_text and "repeats indefinitely" in " ".join(help_text.split())


def test_svg_loop_repeats_every_animation(tmp_path: Path) -> None:
    scene = _scene(tmp_path)
    once = tr.write(scene, tmp_path / "once.svg").read_text()
    looped = tr.write(scene, tmp_path / "looped.svg", loop=True).read_text()
    count = once.count("<animate")
    assert count > 0 and once.count('fill="freeze"') == count and "repeatCount" not in once
    assert looped.count('repeatCount="indefinite"') == count and "freeze" not in looped
    assert looped.replace('repeatCount="indefinite"', 'fill="freeze"').replace("<title>looped", "<title>once") == once


def test_looped_svg_in_chromium_past_its_end(tmp_path: Path) -> None:
    """Paused one and a half clips in, Chromium draws what the clip shows half way; played once, its end."""
    from tests.browser import chromium

    if chromium() is None:
        pytest.skip("no chromium on this machine to play the animated SVG")
    scene = tr.load_scene([DATA / "icons" / "feather" / "heart.svg", DATA / "icons" / "feather" / "star.svg"])
    from tweenrender.plan.job import total_frames

    count = total_frames(scene)
    seconds = count / scene.fps
    looped = tr.write(scene, tmp_path / "looped.svg", loop=True)
    once = tr.write(scene, tmp_path / "once.svg")
    frames = [count // 4, count // 2]
    shots = chromium_svg_frames([(looped, [seconds + f / scene.fps for f in frames], scene.size),
                                 (once, [seconds + f / scene.fps for f in frames], scene.size)])
    check_pictures(scene, shots[0], frames, None, "Chromium, looped")
    check_pictures(scene, shots[1], [count - 1] * len(frames), None, "Chromium, played once")


def test_the_schema_check_sees_a_broken_file(tmp_path: Path) -> None:
    """The check every test's Lottie goes through finds real faults: a path whose tangents are not points."""
    from tests.lottie_schema import check_folder, schema_errors

    target = tr.write(_scene(tmp_path), tmp_path / "good.json")
    assert check_folder(tmp_path) == 1
    document = json.loads(target.read_text())
    assert schema_errors(document) == []
    path = next(item for layer in document["layers"] if "shapes" in layer
                for group in layer["shapes"] for item in group.get("it", []) if item["ty"] == "sh")
    path["ks"]["k"][0]["s"][0]["i"] = "not points"
    assert schema_errors(document)
    del document["layers"]
    assert schema_errors(document)
