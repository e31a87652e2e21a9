"""``tweenrender preview``: a real server process, driven through HTTP and a real headless chromium.

Colours are checked against the scene file's own (the pixel read from chromium's screenshot), frame
numbers against the page's text, errors against the one-line message the loader gives.
"""

from __future__ import annotations

import io
import json
import os
import re
import select
import signal
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path
from typing import Any, Iterator

import numpy as np
import pytest

from tests.browser import chromium, live_page
from tests.helpers import ROOT

SCENE = """size = [160, 90]
fps = 12
view = [0, 0, 16, 9]

[[shape]]
name = "box"
fill = "{fill}"

[[shape.key]]
time = 0.0
points = [[4, 1], [12, 1], [12, 8], [4, 8]]

[[shape.key]]
time = 2.0
points = [[5, 1], [13, 1], [13, 8], [5, 8]]
"""
RED, BLUE = (0xD0, 0x30, 0x30), (0x20, 0x40, 0xC0)


def _hex(rgb: tuple[int, int, int]) -> str:
    return "#" + "".join(f"{v:02x}" for v in rgb)


def _replace(path: Path, text: str) -> None:
    """Save as editors do: a new file renamed over the old one."""
    part = path.with_name(f".{path.name}.part")
    part.write_text(text)
    os.replace(part, path)


class Preview:
    def __init__(self, process: subprocess.Popen[str], url: str) -> None:
        self.process, self.url = process, url
        self._token: str | None = None

    @property
    def token(self) -> str:
        """The token of the run, read from the page as the page's own script reads it."""
        if self._token is None:
            page = self.get("/")[1].decode()
            found = re.search(r'<meta name="tweenrender-token" content="([^"]*)">', page)
            assert found, page[:300]
            self._token = found[1]
        return self._token

    def post(self, path: str, payload: dict[str, Any]) -> tuple[int, bytes]:
        """A POST of ``payload`` (JSON, the token added) as the page sends it."""
        body = json.dumps({"token": self.token, **payload}).encode()
        request = urllib.request.Request(self.url + path.lstrip("/"), data=body, method="POST",
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=30) as reply:
                return reply.status, reply.read()
        except urllib.error.HTTPError as error:
            return error.code, error.read()

    def get(self, path: str, **headers: str) -> tuple[int, bytes]:
        request = urllib.request.Request(self.url + path.lstrip("/"), headers=headers)
        try:
            with urllib.request.urlopen(request, timeout=10) as reply:
                return reply.status, reply.read()
        except urllib.error.HTTPError as error:
            return error.code, error.read()

    def state(self) -> dict[str, Any]:
        return json.loads(self.get(f"/state?token={self.token}")[1])

    def wait_state(self, test: Any, timeout: float = 30.0) -> dict[str, Any]:
        deadline, since = time.monotonic() + timeout, -1
        while time.monotonic() < deadline:
            state = json.loads(self.get(f"/state?since={since}&token={self.token}")[1])  # within a second
            if test(state):
                return state
            since = state["version"]
        raise TimeoutError(f"state never passed the test; last {state}")


def start_preview(*args: str, cwd: Path) -> Preview:
    process = subprocess.Popen([sys.executable, "-m", "tweenrender", "preview", *args], cwd=cwd,
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True,
                               env={**os.environ, "PYTHONPATH": str(ROOT)},
                               preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))
    assert process.stdout is not None
    ready, _, _ = select.select([process.stdout], [], [], 60)
    assert ready, "no address printed within a minute"
    url = process.stdout.readline().strip()
    assert url.startswith("http://127.0.0.1:") and url.endswith("/"), url
    return Preview(process, url)


def stop(preview: Preview, signum: int = signal.SIGTERM) -> tuple[int, str]:
    preview.process.send_signal(signum)
    try:
        _, err = preview.process.communicate(timeout=15)
    except subprocess.TimeoutExpired:
        preview.process.kill()
        preview.process.communicate()
        raise
    return preview.process.returncode, err


@pytest.fixture
def box_preview(tmp_path: Path) -> Iterator[tuple[Preview, Path]]:
    scene = tmp_path / "box.toml"
    scene.write_text(SCENE.format(fill=_hex(RED)))
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        yield preview, scene
    finally:
        if preview.process.poll() is None:
            stop(preview)


def _pixel_at_canvas(page: Any, x: int, y: int) -> tuple[int, int, int]:
    import imageio.v3 as iio

    left, top = page.evaluate("(() => { const r = document.getElementById('stage').getBoundingClientRect(); "
                              "return [Math.round(r.left), Math.round(r.top)]; })()")
    picture = iio.imread(io.BytesIO(page.screenshot()), extension=".png")
    return tuple(int(v) for v in picture[top + y, left + x, :3])


def _shown(page: Any) -> tuple[int, int]:
    """(take, frame) the canvas shows, by the page's own record of what it drew."""
    take, frame = page.evaluate("[document.body.dataset.shownTake, document.body.dataset.shownFrame]")
    return int(take), int(frame)


needs_chromium = pytest.mark.skipif(chromium() is None, reason="needs Debian's chromium")


@needs_chromium
def test_page_plays_and_shows_the_saved_change(box_preview: tuple[Preview, Path]) -> None:
    preview, scene = box_preview
    with live_page(preview.url) as page:
        page.wait_for("document.body.dataset.shownFrame !== undefined")
        first = _shown(page)
        # it plays: the frame shown advances, and the frame number says which
        page.wait_for(f"document.body.dataset.shownFrame !== '{first[1]}'")
        take, frame = _shown(page)
        assert take == 1
        assert page.evaluate("document.getElementById('frame').textContent").startswith("frame ")
        assert _pixel_at_canvas(page, 80, 45) == RED
        _replace(scene, SCENE.format(fill=_hex(BLUE)))
        page.wait_for("document.body.dataset.shownTake === '2'")
        assert _pixel_at_canvas(page, 80, 45) == BLUE
        frame = _shown(page)[1]
        page.wait_for(f"document.body.dataset.shownFrame !== '{frame}'")  # still playing
        assert page.evaluate("document.getElementById('error').textContent") == ""
        assert page.exceptions() == []


@needs_chromium
def test_bad_save_shows_the_error_line_and_keeps_the_last_good_frames(box_preview: tuple[Preview, Path]) -> None:
    preview, scene = box_preview
    with live_page(preview.url) as page:
        page.wait_for("document.body.dataset.shownFrame !== undefined")
        _replace(scene, SCENE.format(fill="#zzzzzz"))
        error = page.wait_for("document.getElementById('error').textContent")
        assert "\n" not in error
        assert "box.toml" in error and "shape[0].fill" in error and "line 7" in error, error
        assert page.evaluate("getComputedStyle(document.getElementById('error')).display") == "block"
        # the previous take still plays, in its colour
        frame = _shown(page)[1]
        page.wait_for(f"document.body.dataset.shownFrame !== '{frame}'")
        assert _shown(page)[0] == 1
        assert _pixel_at_canvas(page, 80, 45) == RED
        assert preview.state()["take"]["number"] == 1
        # fixed: the error goes and the new take shows
        _replace(scene, SCENE.format(fill=_hex(BLUE)))
        page.wait_for("document.body.dataset.shownTake === '2'")
        assert page.evaluate("document.getElementById('error').textContent") == ""
        assert _pixel_at_canvas(page, 80, 45) == BLUE
        assert page.exceptions() == []


@needs_chromium
def test_method_picker_lists_every_method_and_redraws_with_the_choice(box_preview: tuple[Preview, Path]) -> None:
    from tweenrender.core.methods.registry import METHODS

    preview, _ = box_preview
    with live_page(preview.url) as page:
        page.wait_for("document.body.dataset.shownTake === '1'")
        options = page.evaluate("Array.from(document.getElementById('method').options).map(o => o.value)")
        assert options == ["", *METHODS]
        page.evaluate("(() => { const s = document.getElementById('method'); s.value = 'linear'; "
                      "s.dispatchEvent(new Event('change')); })()")
        page.wait_for("document.body.dataset.shownTake === '2'")
        assert preview.state()["take"]["method"] == "linear"


def test_an_svg_the_scene_reads_is_watched_too(tmp_path: Path) -> None:
    import imageio.v3 as iio

    svg = tmp_path / "art" / "box.svg"
    svg.parent.mkdir()
    drawing = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 16 9"><rect x="4" y="1" width="8" ' \
              'height="7" fill="{fill}"/></svg>'
    svg.write_text(drawing.format(fill=_hex(RED)))
    scene = tmp_path / "scene.toml"
    scene.write_text('size = [160, 90]\nfps = 4\n[[drawing]]\ntime = 0\nsvg = "art/box.svg"\n'
                     '[[drawing]]\ntime = 1\nsvg = "art/box.svg"\n')
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        state = preview.wait_state(lambda s: s["take"] is not None)
        picture = iio.imread(preview.get(f"/frame/{state['take']['number']}/0.png")[1], extension=".png")
        assert tuple(picture[45, 80, :3]) == RED
        _replace(svg, drawing.format(fill=_hex(BLUE)))
        state = preview.wait_state(lambda s: s["take"] is not None and s["take"]["number"] == 2)
        picture = iio.imread(preview.get("/frame/2/0.png")[1], extension=".png")
        assert tuple(picture[45, 80, :3]) == BLUE
        assert preview.get("/frame/1/0.png")[0] == 404  # the old take is gone
    finally:
        stop(preview)


def test_server_answers_loopback_names_only_and_refuses_unknown_methods(box_preview: tuple[Preview, Path]) -> None:
    preview, _ = box_preview
    port = preview.url.rsplit(":", 1)[1].rstrip("/")
    assert preview.get(f"/state?token={preview.token}", Host=f"example.com:{port}")[0] == 403
    assert preview.get(f"/state?token={preview.token}", Host=f"localhost:{port}")[0] == 200
    assert preview.get("/frame/99/0.png")[0] == 404
    status, message = preview.post("/method", {"method": "lnear"})
    assert status == 400 and b"lnear" in message
    # bound to the loopback address only: the port does not answer on another of this machine's addresses
    listening = Path(f"/proc/{preview.process.pid}/net/tcp").read_text().splitlines()[1:]
    ours = [line.split() for line in listening if line.split()[1].endswith(f":{int(port):04X}")]
    assert ours and all(fields[1].startswith("0100007F:") for fields in ours), ours


@pytest.mark.parametrize("signum, code", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_signals_end_it_cleanly_with_no_child_left(box_preview: tuple[Preview, Path], signum: int, code: int) -> None:
    from tests.cli.test_signals import descendants

    preview, _ = box_preview
    preview.wait_state(lambda s: s["take"] is not None and s["take"]["drawn"] == s["take"]["total"])
    assert descendants(preview.process.pid) == set()
    returned, err = stop(preview, signum)
    assert returned == code
    assert "Traceback" not in err and "Warning" not in err, err


def test_a_bad_scene_at_start_is_shown_not_fatal(tmp_path: Path) -> None:
    scene = tmp_path / "bad.toml"
    scene.write_text(SCENE.format(fill="#12"))
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        state = preview.wait_state(lambda s: s["error"])
        assert state["take"] is None and "bad.toml" in state["error"] and "shape[0].fill" in state["error"]
        _replace(scene, SCENE.format(fill=_hex(RED)))
        state = preview.wait_state(lambda s: s["take"] is not None)
        assert state["error"] is None
    finally:
        assert stop(preview)[0] == 143


def test_watchfiles_is_imported_by_the_preview_only(tmp_path: Path) -> None:
    scene = tmp_path / "box.toml"
    scene.write_text(SCENE.format(fill=_hex(RED)))
    code = ("import sys\n"
            "from tweenrender.cli.main import main\n"
            f"code = main(['render', {str(scene)!r}, '-o', {str(tmp_path / 'f')!r}, '-q', '--frames', '0:2'])\n"
            "import tweenrender.preview\n"
            "print('result', code, 'watchfiles' in sys.modules)\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=300, cwd=ROOT,
                          env={**os.environ, "PYTHONPATH": str(ROOT)})
    assert done.stdout.splitlines()[-1] == "result 0 False", done.stderr


def test_the_scene_folder_removed_and_made_again_is_still_watched(tmp_path: Path) -> None:
    """As a branch checkout does: the folder goes and comes back; the next save is drawn."""
    import shutil

    folder = tmp_path / "project"
    folder.mkdir()
    scene = folder / "box.toml"
    scene.write_text(SCENE.format(fill=_hex(RED)))
    preview = start_preview(str(scene), cwd=tmp_path)
    try:
        preview.wait_state(lambda s: s["take"] is not None and s["take"]["number"] == 1)
        shutil.rmtree(folder)
        time.sleep(1.0)
        folder.mkdir()
        scene.write_text(SCENE.format(fill=_hex(RED)))
        first = preview.wait_state(lambda s: s["take"] is not None and s["take"]["number"] >= 2)["take"]["number"]
        time.sleep(1.0)
        _replace(scene, SCENE.format(fill=_hex(BLUE)))
        state = preview.wait_state(lambda s: s["take"]["number"] > first)
        import imageio.v3 as iio

        picture = iio.imread(preview.get(f"/frame/{state['take']['number']}/0.png")[1], extension=".png")
        assert tuple(picture[45, 80, :3]) == BLUE
    finally:
        stop(preview)
