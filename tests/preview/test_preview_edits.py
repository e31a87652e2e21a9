"""``POST /edit`` and ``GET /state`` of a real preview process: edits land in the scene file (checked by the
loader first, written whole), the watcher draws a new take, undo and redo walk the texts back and forth,
and drawings from the command line are never written (the first edit saves a scene beside them)."""

from __future__ import annotations

import json
import re
import select
import tomllib
from pathlib import Path

import numpy as np

from tests.helpers import SCENES
from tests.preview.test_preview import SCENE, Preview, start_preview, stop

HINT_OPS = [{"op": "hint", "shape": "box", "key": 0, "letter": "a", "point": [12, 8]},
            {"op": "hint", "shape": "box", "key": 1, "letter": "a", "point": [13, 8]}]


def _edit(preview: Preview, payload: dict) -> dict:
    status, body = preview.post("/edit", payload)
    assert status == 200, body
    return json.loads(body)


def _box(tmp_path: Path) -> Path:
    scene = tmp_path / "box.toml"
    scene.write_text("# my box, my comment\n" + SCENE.format(fill="#d03030"))
    return scene


def test_an_edit_is_written_drawn_undone_and_redone(tmp_path: Path) -> None:
    scene = _box(tmp_path)
    original = scene.read_bytes()
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        state = preview.wait_state(lambda s: s["take"] is not None and s["shapes"])
        assert state["scene_file"] == str(scene) and state["can_undo"] is False
        keys = state["shapes"][0]["keys"]
        assert [k["time"] for k in keys] == [0.0, 2.0]
        assert keys[0]["outlines"] == [[[4, 1], [12, 1], [12, 8], [4, 8]]]
        # the page's transform: view [0, 0, 16, 9] in 160 × 90 pixels, y down
        assert state["to_page"] == [10.0, 0.0, 0.0, -10.0, 0.0, 90.0]
        assert _edit(preview, {"ops": HINT_OPS}) == {"ok": True}
        edited = scene.read_text()
        assert edited.startswith("# my box, my comment\n")
        assert tomllib.loads(edited)["shape"][0]["key"][1]["hints"] == {"a": [13, 8]}
        state = preview.wait_state(lambda s: s["take"] and s["take"]["number"] >= 2 and s["shapes"]
                                   and s["shapes"][0]["keys"][0]["hints"])
        assert state["shapes"][0]["keys"][0]["hints"] == {"a": [12, 8]} and state["can_undo"]
        assert _edit(preview, {"history": "undo"}) == {"ok": True}
        assert scene.read_bytes() == original
        preview.wait_state(lambda s: s["shapes"] and not s["shapes"][0]["keys"][0]["hints"] and s["can_redo"])
        assert _edit(preview, {"history": "redo"}) == {"ok": True}
        assert scene.read_text() == edited
        assert _edit(preview, {"history": "redo"})["ok"] is False  # nothing left to redo
        leftovers = [p.name for p in tmp_path.iterdir() if p.name != "box.toml"]
        assert leftovers == [], leftovers  # written atomically: no temporary left beside it
    finally:
        stop(preview)


def test_a_refused_edit_writes_nothing_and_answers_the_loaders_line(tmp_path: Path) -> None:
    scene = _box(tmp_path)
    original = scene.read_bytes()
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        preview.wait_state(lambda s: s["take"] is not None)
        reply = _edit(preview, {"ops": HINT_OPS[:1]})  # a letter on one key only
        assert reply["ok"] is False and "\n" not in reply["error"]
        assert reply["error"].startswith(f"{scene}: shape[0].key[0].hints.a"), reply
        reply = _edit(preview, {"ops": [{"op": "ease", "shape": "box", "key": 0, "ease": "<script>"}]})
        assert reply["ok"] is False and "shape[0].key[0].ease" in reply["error"]
        assert _edit(preview, {"ops": "nonsense"})["ok"] is False
        assert scene.read_bytes() == original
        assert preview.state()["can_undo"] is False
    finally:
        stop(preview)


def test_undo_never_overwrites_the_users_own_save(tmp_path: Path) -> None:
    scene = _box(tmp_path)
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        preview.wait_state(lambda s: s["take"] is not None)
        assert _edit(preview, {"ops": [{"op": "ease", "shape": "box", "key": 0, "ease": "in"}]})["ok"]
        mine = scene.read_text().replace('ease = "in"', 'ease = "out"  # mine')
        scene.write_text(mine)
        reply = _edit(preview, {"history": "undo"})
        assert reply["ok"] is False and "changed on disk" in reply["error"]
        assert scene.read_text() == mine
    finally:
        stop(preview)


def test_drawings_from_the_command_line_are_never_written(tmp_path: Path) -> None:
    svgs = sorted((SCENES / "svg").glob("*.svg"))[:2]
    before = [p.read_bytes() for p in svgs]
    preview = start_preview(*map(str, svgs), "--step", "1.5", cwd=tmp_path)
    try:
        state = preview.wait_state(lambda s: s["take"] is not None and s["shapes"])
        assert state["scene_file"] is None
        drawing = state["shapes"][0]
        assert drawing["drawing"] is True and len(drawing["keys"]) == 2
        assert [k["time"] for k in drawing["keys"]] == [0.0, 1.5]
        # a point of each drawing in its SVG's units: the first outline's first vertex taken back
        points = []
        for key in drawing["keys"]:
            a, b, c, d, e, f = key["to_scene"]
            x, y = key["outlines"][0][0]
            inverse = np.linalg.inv(np.array([[a, c, e], [b, d, f], [0, 0, 1]]))
            points.append((inverse @ [x, y, 1])[:2].tolist())
        point = points[0]
        reply = _edit(preview, {"ops": [{"op": "ease", "shape": drawing["name"], "key": 0, "ease": "in-out"}]})
        assert reply == {"ok": True}
        written = tmp_path / f"{svgs[0].stem}-{svgs[1].stem}.toml"
        assert written.is_file()
        assert [p.read_bytes() for p in svgs] == before
        assert preview.process.stdout is not None
        ready, _, _ = select.select([preview.process.stdout], [], [], 10)
        assert ready and preview.process.stdout.readline().strip() == str(written)
        data = tomllib.loads(written.read_text())
        assert [d["time"] for d in data["drawing"]] == [0, 1.5] and data["drawing"][0]["ease"] == "in-out"
        assert [(tmp_path / d["svg"]).resolve() for d in data["drawing"]] == [p.resolve() for p in svgs]
        state = preview.wait_state(lambda s: s["scene_file"] == str(written) and s["take"]["number"] >= 2)
        assert _edit(preview, {"ops": [{"op": "hint", "shape": drawing["name"], "key": 0, "letter": "a",
                                        "point": point}]})["ok"] is False  # one key only: refused, nothing written
        assert re.search(r"drawing\[0\]\.hints\.a", _edit(preview, {"ops": [
            {"op": "hint", "shape": drawing["name"], "key": 0, "letter": "a", "point": point}]})["error"])
        # on both drawings it is taken: the points, in each SVG's own units, lie on the outlines
        both = [{"op": "hint", "shape": drawing["name"], "key": k, "letter": "a", "point": p} for k, p in enumerate(points)]
        assert _edit(preview, {"ops": both}) == {"ok": True}, points
        hints = [d["hints"]["a"] for d in tomllib.loads(written.read_text())["drawing"]]
        assert np.allclose(hints, points, atol=1e-6)
        assert _edit(preview, {"history": "undo"}) == {"ok": True}
        assert _edit(preview, {"history": "undo"}) == {"ok": True}
        assert "ease" not in tomllib.loads(written.read_text())["drawing"][0]
    finally:
        stop(preview)


def test_timing_flags_are_taken_for_drawings_and_refused_for_a_scene_file(tmp_path: Path) -> None:
    from tests.helpers import run_module

    scene = _box(tmp_path)
    done = run_module("preview", str(scene), "--ease", "in", cwd=tmp_path)
    assert done.returncode == 2 and done.stderr.count("\n") == 1 and "--ease" in done.stderr, done.stderr
    svgs = sorted((SCENES / "svg").glob("*.svg"))[:2]
    preview = start_preview(*map(str, svgs), "--ease", "in-out", "--hold", "0.5", "--stagger", "0.05",
                            cwd=tmp_path)
    try:
        state = preview.wait_state(lambda s: s["take"] is not None or s["error"])
        assert state["error"] is None
        # each drawing held 0.5 s then moving 1 s: the last at 1.5 s, held to 2 s; 24 fps
        assert state["take"]["total"] == 2 * 24 + 1
    finally:
        stop(preview)


def test_the_first_edit_of_drawings_never_replaces_a_file_of_that_name(tmp_path: Path) -> None:
    """Where ``a-b.toml`` is already the user's, the first edit of drawings ``a`` and ``b`` saves
    ``a-b-2.toml``; the user's file keeps its bytes."""
    from types import SimpleNamespace

    from tweenrender.preview.edits import SceneEditor

    svgs = sorted((SCENES / "svg").glob("*.svg"))[:2]
    mine = tmp_path / f"{svgs[0].stem}-{svgs[1].stem}.toml"
    mine.write_bytes(b"# mine\n")
    previewer = SimpleNamespace(inputs=list(svgs), timing={}, step=1.0, changed=lambda: None)
    previewer.use_scene_file = lambda path: setattr(previewer, "inputs", [path])
    announced: list[str] = []
    editor = SceneEditor(previewer, announced.append, folder=tmp_path)  # type: ignore[arg-type]
    reply = editor.apply([{"op": "ease", "shape": "any", "key": 0, "ease": "in-out"}])
    assert reply == {"ok": True}, reply
    written = tmp_path / f"{svgs[0].stem}-{svgs[1].stem}-2.toml"
    assert announced == [str(written)] and mine.read_bytes() == b"# mine\n"
    assert tomllib.loads(written.read_text())["drawing"][0]["ease"] == "in-out"
