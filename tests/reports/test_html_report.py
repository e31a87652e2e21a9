"""The HTML report: in a real headless browser, on disk, and its refusal to replace a stranger's folder."""

from __future__ import annotations

import html
import re
from pathlib import Path

import numpy as np
import pytest

from ..browser import chromium, open_page, page_url
from ..helpers import SCENES, decode, read_png, run_main

METHODS = "linear,arap,intrinsic,jointed"


@pytest.fixture(scope="module")
def report(tmp_path_factory: pytest.TempPathFactory) -> Path:
    folder = tmp_path_factory.mktemp("report") / "hinge-report"
    done = run_main("report", SCENES / "hinge.toml", "--compare", METHODS, "-o", folder, "-q")
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip() == str(folder / "index.html")
    return folder


def test_the_page_is_self_contained(report: Path) -> None:
    text = (report / "index.html").read_text()
    references = re.findall(r'(?:src|href)="([^"]+)"', text)
    assert references
    for reference in references:
        assert reference.startswith("data:") or (report / reference).is_file(), reference
    assert "http://" not in text and "https://" not in text
    assert [f"{m}.webm" for m in METHODS.split(",")] == re.findall(r'<video src="([^"]+)"', text)
    # every file in the folder belongs to the page (and the manifest that makes it ours)
    assert {p.name for p in report.iterdir()} == set(references) - {"data:,"} | {"index.html",
                                                                                ".tweenrender-manifest.json"}


def test_the_videos_play_the_whole_clip_in_step(report: Path) -> None:
    sizes = set()
    for method in METHODS.split(","):
        meta, frames = decode(report / f"{method}.webm")
        assert len(frames) == 49  # hinge: 2 s at 24 fps, both ends included
        sizes.add(frames[0].shape)
    assert len(sizes) == 1  # one size, one view, one clock


def test_the_table_has_every_method_and_its_measures(report: Path) -> None:
    text = (report / "index.html").read_text()
    for method in METHODS.split(","):
        assert f"<tr><td>{method}</td>" in text
    assert "worst edge error" in text and "crosses itself" in text


def test_the_page_in_a_real_browser(report: Path) -> None:
    if chromium() is None:
        pytest.skip("Debian's chromium is not installed (apt-get install chromium); .ci/run installs it")
    seen = open_page(page_url(report / "index.html"))
    assert seen.errors == []
    videos = [m for m in seen.media if m["tag"] == "video"]
    images = [m for m in seen.media if m["tag"] == "img"]
    assert len(videos) == 4 and len(images) == 3
    for video in videos:
        assert video["error"] is None and video["readyState"] >= 2 and video["width"] > 0, video
        assert abs(video["duration"] - 2.0) < 0.1 and not video["paused"]
    times = [v["time"] for v in videos]
    assert max(times) - min(times) < 0.25  # playing together
    for image in images:
        assert image["complete"] and image["naturalWidth"] > 0, image
    shot = read_png_bytes(seen.screenshot)
    # not blank: many colours, and the drawing's fill colour is on screen
    assert len(np.unique(shot.reshape(-1, shot.shape[-1]), axis=0)) > 50
    assert shot[..., :3].std() > 10


def read_png_bytes(data: bytes) -> np.ndarray:
    import imageio.v3 as iio

    return np.asarray(iio.imread(data, extension=".png"))


def test_a_stranger_folder_is_never_replaced(tmp_path: Path) -> None:
    folder = tmp_path / "mine"
    folder.mkdir()
    (folder / "notes.txt").write_text("keep me")
    done = run_main("report", SCENES / "square.toml", "--compare", "linear", "-o", folder, "-q")
    assert done.returncode == 2
    assert "'notes.txt'" in done.stderr and "Traceback" not in done.stderr
    assert [p.name for p in folder.iterdir()] == ["notes.txt"]
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # no temporary left behind


def test_an_earlier_report_is_replaced_whole(tmp_path: Path) -> None:
    folder = tmp_path / "square-report"
    assert run_main("report", SCENES / "square.toml", "--compare", "linear,rigid", "-o", folder, "-q").returncode == 0
    assert (folder / "rigid.webm").is_file()
    assert run_main("report", SCENES / "square.toml", "--compare", "arap", "-o", folder, "-q").returncode == 0
    assert sorted(p.name for p in folder.glob("*.webm")) == ["arap.webm"]
    assert read_png(folder / "metrics.png").shape[1] == 960
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]


def test_a_report_of_every_method_can_be_written_again(tmp_path: Path) -> None:
    # every method's video is a file the report wrote, whatever characters its name has
    folder = tmp_path / "square-report"
    for _ in range(2):
        done = run_main("report", SCENES / "square.toml", "--compare", "intrinsic-length", "-o", folder, "-q")
        assert done.returncode == 0, done.stderr
    assert sorted(p.name for p in folder.glob("*.webm")) == ["intrinsic-length.webm"]


def test_the_reports_videos_are_encoded_as_drafts(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A report's videos are for a look side by side: each VP9 encode runs at the encoder's quickest settings
    (the format table's draft, whose frames tests/encode/test_video.py decodes), a render's at its usual."""
    import tweenrender as tr
    from tweenrender.encode import sinks
    from tweenrender.encode.formats import TABLE

    started: list[list[str]] = []
    real = sinks.start_program

    def recorded(command: list[str], *args: object, **named: object) -> object:
        started.append(list(command))
        return real(command, *args, **named)

    monkeypatch.setattr(sinks, "start_program", recorded)
    scene = tr.load_scene(SCENES / "square.toml")
    tr.report(scene, tmp_path / "square-report", compare=["linear", "rigid"])
    tr.write(scene, tmp_path / "square.webm", workers=1)
    encodes = [c for c in started if "libvpx-vp9" in c]
    assert len(encodes) == 3
    for command, draft in zip(encodes, (True, True, False)):
        for option, value in TABLE["webm"].draft:
            quick = command[command.index(option) + 1] == value
            assert quick == draft, (option, command)


def test_the_page_says_what_auto_draws_what_tangles_and_why_injective_fell_back() -> None:
    """The report prints what `render` draws and why (auto's method, balance and reason, as `stats` has them), the
    whole-element tangles and stray of every method, and, where `injective` has no mesh, the reason: every text
    escaped."""
    import tweenrender as tr
    from tests.helpers import DATA
    from tweenrender.reports.html_report import page
    from tweenrender.reports.stats import stats_dict

    icons = DATA / "icons"
    scene = tr.load_scene([icons / "bootstrap" / "check-circle.svg", icons / "simple-icons" / "python.svg"], step=1.0)
    stats = stats_dict(scene, [0.25, 0.5, 0.75], ["linear", "injective"])
    text = page(scene, [], stats, (64, 64))
    entry = next(e for e in stats["shapes"] if e["methods"]["injective"]["fallback"])
    auto = entry["auto"]
    assert f"auto draws {auto['method']} (balance {auto['balance']})" in text
    assert html.escape(auto["why"], quote=False) in text
    assert html.escape(entry["methods"]["injective"]["fallback"], quote=False) in text
    tangled = entry["methods"]["linear"]["crossings"]
    assert tangled and f"t = {tangled[0]:g}" in text
    assert f"{entry['methods']['linear']['stray_max']:.3f}" in text
    stats["shapes"][0]["auto"]["why"] = "<b>bold</b> & more"
    assert "&lt;b&gt;bold&lt;/b&gt; &amp; more" in page(scene, [], stats, (64, 64))


def test_the_page_says_where_an_element_of_strokes_alone_crosses(tmp_path) -> None:
    """An element of open strokes alone (an upright stroke sliding through a level one) has a table of its own
    (``others``):
    what auto draws and, per method, where its strokes cross, as `stats` has them; its name escaped."""
    import tweenrender as tr
    from tweenrender.reports.html_report import page
    from tweenrender.reports.stats import stats_dict

    def drawing(x: float):  # noqa: ANN202
        path = tmp_path / f"s{x:g}.svg"
        path.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40"><path id="a&amp;b" fill="none" '
                        f'stroke="#000" d="M{x} 10 L{x} 30 M18.5 20 L21.5 20"/></svg>')
        return path

    scene = tr.load_scene([drawing(10), drawing(30)], step=1.0)
    stats = stats_dict(scene, [0.5], ["linear"])
    text = page(scene, [], stats, (64, 64))
    (entry,) = stats["others"]
    crossed = entry["methods"]["linear"]["stroke_crossings"]
    assert crossed and f"t = {crossed[0]:g}–{crossed[-1]:g}" in text
    assert "element a&amp;b, segment 0" in text and "2 open strokes" in text
    assert html.escape(entry["auto"]["why"], quote=False) in text
    assert "measured for tangles" in text
