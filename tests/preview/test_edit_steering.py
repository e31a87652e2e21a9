"""The steering edits end to end (``turn``, ``arcs``, breakdown keys): through ``POST /edit`` of a real
preview, checked by the loader, written, drawn. They pass once the loader knows those fields."""

from __future__ import annotations

import tomllib
from pathlib import Path

import numpy as np

from tests.preview.test_preview_edits import _box, _edit
from tests.preview.test_preview import start_preview, stop


def test_turn_arc_and_breakdown_edits_are_written_and_drawn(tmp_path: Path) -> None:
    scene = _box(tmp_path)
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        preview.wait_state(lambda s: s["take"] is not None)
        hint = [{"op": "hint", "shape": "box", "key": k, "letter": "a", "point": p}
                for k, p in ((0, [12, 8]), (1, [13, 8]))]
        assert _edit(preview, {"ops": [*hint, {"op": "arc", "shape": "box", "key": 0, "letter": "a",
                                               "point": [12.5, 8.5]}]}) == {"ok": True}
        assert _edit(preview, {"ops": [{"op": "turn", "shape": "box", "key": 0, "turn": "cw", "turns": 0}]}) \
            == {"ok": True}
        assert _edit(preview, {"ops": [{"op": "breakdown", "shape": "box", "key": 0, "time": 0.5,
                                        "breakdown": 0.25}]}) == {"ok": True}
        keys = tomllib.loads(scene.read_text())["shape"][0]["key"]
        assert keys[0]["arcs"] == {"a": [12.5, 8.5]} and keys[0]["turn"] == "cw"
        assert keys[1] == {"time": 0.5, "breakdown": 0.25}
        state = preview.wait_state(lambda s: s["shapes"] and len(s["shapes"][0]["keys"]) == 3 and s["error"] is None)
        assert state["shapes"][0]["keys"][1]["breakdown"] == 0.25
        assert _edit(preview, {"ops": [{"op": "bake", "shape": "box", "key": 1}]}) == {"ok": True}
        baked = tomllib.loads(scene.read_text())["shape"][0]["key"][1]
        assert "breakdown" not in baked and np.asarray(baked["points"]).shape[1] == 2
    finally:
        stop(preview)


def test_turn_breakdown_and_arc_by_pointing(tmp_path: Path) -> None:
    import pytest

    from tests.browser import chromium, live_page
    from tests.helpers import SCENES
    from tests.preview.test_preview_page_edits import _ready, _where

    if chromium() is None:
        pytest.skip("needs Debian's chromium")
    scene = tmp_path / "arrow.toml"
    scene.write_text((SCENES / "arrow-hints.toml").read_text())
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        with live_page(preview.url) as page:
            state = _ready(preview, page)
            # the arc of hint a first (a turn moves the hinted point's path, and the view may follow it):
            # drag its middle square to a chosen point
            keys = state["shapes"][0]["keys"]
            start, end = keys[0]["hints"]["a"], keys[1]["hints"]["a"]
            middle = [(start[0] + end[0]) / 2, (start[1] + end[1]) / 2]
            target = [middle[0], middle[1] + 1.0]
            page.drag(_where(page, state, middle), _where(page, state, target))
            page.wait_for("Number(document.body.dataset.edited || 0) >= 1")
            arc = tomllib.loads(scene.read_text())["shape"][0]["key"][0]["arcs"]["a"]
            assert abs(arc[0] - target[0]) * state["to_page"][0] <= 1 and abs(arc[1] - target[1]) * state["to_page"][0] <= 1
            page.evaluate("document.getElementById('turn').click()")
            page.wait_for("Number(document.body.dataset.edited || 0) >= 2")
            assert tomllib.loads(scene.read_text())["shape"][0]["key"][0]["turn"] == "cw"
            # a breakdown at the scrubber's time (frame 24 of 24 fps: 1 s), its favour the slider's
            page.evaluate("(() => { const s = document.getElementById('scrub'); s.value = '24'; "
                          "s.dispatchEvent(new Event('input')); })()")
            page.evaluate("document.getElementById('breakdown').click()")
            page.wait_for("Number(document.body.dataset.edited || 0) >= 3")
            keys = tomllib.loads(scene.read_text())["shape"][0]["key"]
            assert keys[1]["time"] == 1.0 and keys[1]["breakdown"] == 0.5
            assert page.exceptions() == []
    finally:
        stop(preview)
