"""Editing by pointing, in a real headless chromium: the test clicks where ``GET /state``'s ``to_page`` says
the keys' points are, reads the scene file back, and checks the next take as the hints say."""

from __future__ import annotations

import re
import shutil
import time
import tomllib
from pathlib import Path
from typing import Any

import pytest

from tests.browser import live_page
from tests.helpers import SCENES
from tests.preview.test_preview import Preview, needs_chromium, start_preview, stop
from tweenrender import api

# the arrow's tip and tail corners in its two keys, as its scene file writes them
MARKS = [([2.5714, 0], [6.7731, 1.2857]), ([-2.4286, -0.5], [11.3532, -0.7813]), ([-2.4286, 0.5], [10.8532, -1.6473])]


def _where(page: Any, state: dict[str, Any], point: list[float]) -> tuple[float, float]:
    """The page's CSS pixel at scene point ``point``: ``to_page`` to the picture's pixels, then the canvas's place."""
    a, b, c, d, e, f = state["to_page"]
    x, y = a * point[0] + c * point[1] + e, b * point[0] + d * point[1] + f
    left, top, width, height, w, h = page.evaluate(
        "(() => { const r = document.getElementById('stage').getBoundingClientRect(); const s = "
        "document.getElementById('stage'); return [r.left, r.top, r.width, r.height, s.width, s.height]; })()")
    return left + x * width / w, top + y * height / h


def _synced(preview: Preview, page: Any, test: Any = lambda s: True) -> dict[str, Any]:
    """The state once it passes ``test`` and the page holds the same ``to_page`` (the view may move as the
    scene changes: both must mean the same pixels before the test clicks)."""
    deadline = time.monotonic() + 30
    while True:
        state = preview.wait_state(lambda s: s["take"] is not None and s["shapes"] and test(s))
        held = page.evaluate("state && state.to_page")
        if held and max(abs(a - b) for a, b in zip(held, state["to_page"])) < 1e-9:
            return state
        assert time.monotonic() < deadline, (held, state["to_page"])
        time.sleep(0.05)


def _ready(preview: Preview, page: Any) -> dict[str, Any]:
    page.wait_for("document.body.dataset.shownTake !== undefined && "
                  "document.getElementById('marks').querySelectorAll('polygon').length >= 2")
    return _synced(preview, page)


@pytest.fixture
def arrow(tmp_path: Path) -> Path:
    scene = tmp_path / "arrow.toml"
    scene.write_text(re.sub(r"^hints = .*\n", "", (SCENES / "arrow-hints.toml").read_text(), flags=re.M))
    return scene


@needs_chromium
def test_three_hints_by_six_clicks_untwist_the_arrow(arrow: Path) -> None:
    untouched = arrow.read_text()
    assert api.stats(api.load_scene(arrow), methods=["rigid"])["shapes"][0]["methods"]["rigid"]["crossings"]
    preview = start_preview(str(arrow), cwd=arrow.parent)
    try:
        with live_page(preview.url) as page:
            state = _ready(preview, page)
            scale = state["to_page"][0]  # pixels per scene unit
            for count, (first, second) in enumerate(MARKS, start=1):
                page.click(*_where(page, state, first))
                page.wait_for("document.body.dataset.pending === '1'")
                page.click(*_where(page, state, second))
                page.wait_for(f"Number(document.body.dataset.edited || 0) >= {count}")
                assert page.evaluate("document.getElementById('error').textContent") == ""
                state = _synced(preview, page, lambda s, n=count: len(s["shapes"][0]["keys"][0]["hints"]) == n)
            assert page.evaluate("document.getElementById('error').textContent") == ""
            keys = tomllib.loads(arrow.read_text())["shape"][0]["key"]
            for letter, (first, second) in zip("abc", MARKS):
                for key, point in ((keys[0], first), (keys[1], second)):
                    placed = key["hints"][letter]
                    assert max(abs(placed[0] - point[0]), abs(placed[1] - point[1])) * scale <= 1.0, (letter, placed)
            # the letters show on both keys of the page
            page.wait_for("document.querySelectorAll('#marks text').length === 6")
            letters = page.evaluate("Array.from(document.querySelectorAll('#marks text')).map(t => t.textContent)")
            assert sorted(letters) == ["a", "a", "b", "b", "c", "c"]
            # the next take is drawn, and the scene as written no longer crosses itself at any swept t
            take = preview.wait_state(lambda s: s["take"]["number"] >= 4 and s["error"] is None)["take"]["number"]
            page.wait_for(f"Number(document.body.dataset.shownTake) >= {take}")
            report = api.stats(api.load_scene(arrow), methods=["rigid"])
            assert report["shapes"][0]["methods"]["rigid"]["crossings"] == []
            # everything but the two hints lines is the file as it was
            assert [line for line in arrow.read_text().splitlines() if not line.startswith("hints = ")] == \
                untouched.splitlines()
            # undo from the page: the last pair of hints goes
            page.evaluate("document.getElementById('undo').click()")
            preview.wait_state(lambda s: s["shapes"] and len(s["shapes"][0]["keys"][0]["hints"]) == 2)
            assert set(tomllib.loads(arrow.read_text())["shape"][0]["key"][1]["hints"]) == {"a", "b"}
            assert page.exceptions() == []
    finally:
        stop(preview)


@needs_chromium
def test_dragging_a_handle_of_the_timing_graph_writes_the_ease(arrow: Path) -> None:
    preview = start_preview(str(arrow), cwd=arrow.parent)
    try:
        with live_page(preview.url) as page:
            _ready(preview, page)
            # the first key's ease is "ease-in-out": handles (0.42, 0) and (0.58, 1), the graph's y from 1.5 to -0.5
            left, top, width = page.evaluate("(() => { const r = document.getElementById('graph')"
                                             ".getBoundingClientRect(); return [r.left, r.top, r.width]; })()")
            inner = width - 32

            def at(x: float, y: float) -> tuple[float, float]:
                return left + 16 + x * inner, top + 16 + (1.5 - y) / 2.0 * inner

            page.drag(at(0.42, 0.0), at(0.1, 0.8))
            page.wait_for("Number(document.body.dataset.edited || 0) >= 1")
            ease = tomllib.loads(arrow.read_text())["shape"][0]["key"][0]["ease"]
            numbers = [float(v) for v in re.fullmatch(r"cubic-bezier\((.*)\)", ease)[1].split(",")]
            assert numbers[2:] == [0.58, 1.0]
            assert abs(numbers[0] - 0.1) < 0.02 and abs(numbers[1] - 0.8) < 0.03, ease
            # a named curve from the picker
            page.evaluate("(() => { const s = document.getElementById('curve'); s.value = 'ease-out'; "
                          "s.dispatchEvent(new Event('change')); })()")
            page.wait_for("Number(document.body.dataset.edited || 0) >= 2")
            assert tomllib.loads(arrow.read_text())["shape"][0]["key"][0]["ease"] == "ease-out"
            assert page.exceptions() == []
    finally:
        stop(preview)


@needs_chromium
def test_the_curve_picker_names_the_scenes_curves_when_the_first_state_had_none(arrow: Path) -> None:
    """The first state the page sees may come before the take's keys are known (no shapes, no easings): the
    picker must still offer the named curves once they arrive (it once kept only "hold", and picking
    "ease-out" then sent nothing)."""
    preview = start_preview(str(arrow), cwd=arrow.parent)
    try:
        with live_page(preview.url) as page:
            _ready(preview, page)
            names = page.evaluate("""(() => {
                const known = state;
                document.getElementById('curve').replaceChildren();
                apply({...known, shapes: [], easings: {}, to_page: null});
                apply(known);
                return Array.from(document.getElementById('curve').options).map(o => o.value);
            })()""")
            assert {"ease-in", "ease-out", "ease-in-out", "hold"} <= set(names), names
            assert page.exceptions() == []
    finally:
        stop(preview)


@needs_chromium
def test_a_letter_in_the_scene_shows_as_text_never_as_markup(tmp_path: Path) -> None:
    """The page shows the loader's line (which quotes the file) as text: markup in a scene runs nothing."""
    scene = tmp_path / "x.toml"
    shutil.copy(SCENES / "square.toml", scene)
    scene.write_text(scene.read_text().replace('title =', 'title = "<img src=x onerror=document.title=1>"\n#', 1)
                     .replace("[[shape]]", '[[shape]]\nbogus = "<img src=x onerror=\'document.title=2\'>"', 1))
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        with live_page(preview.url) as page:
            error = page.wait_for("document.getElementById('error').textContent")
            assert "bogus" in error
            time.sleep(0.3)
            assert page.evaluate("document.getElementById('error').children.length") == 0
            assert page.evaluate("document.title") == "tweenrender preview"
    finally:
        stop(preview)
