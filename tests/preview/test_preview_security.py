"""The preview answers its own page only: a token of the run, the page's own ``Origin``, a loopback ``Host``.

Requests are raw ``http.client`` ones (so every header is what the test says), and one real headless
chromium visit from a page of another origin (a second local server) that tries a ``no-cors`` POST.
"""

from __future__ import annotations

import http.client
import http.server
import json
import re
import threading
import time
from pathlib import Path
from typing import Iterator

import pytest

from tests.browser import live_page
from tests.preview.test_preview import Preview, needs_chromium, start_preview, stop, SCENE
from tweenrender.preview.server import REQUEST_SECONDS

RED = "#d03030"


@pytest.fixture
def preview(tmp_path: Path) -> Iterator[Preview]:
    scene = tmp_path / "box.toml"
    scene.write_text(SCENE.format(fill=RED))
    running = start_preview(str(scene), cwd=tmp_path)
    try:
        running.wait_state(lambda s: s["take"] is not None)
        yield running
    finally:
        if running.process.poll() is None:
            stop(running)


def _request(preview: Preview, method: str, path: str, body: bytes | None = None,
             **headers: str) -> tuple[int, bytes]:
    """One raw request with exactly ``headers`` (``Host`` included when given; http.client adds it otherwise)."""
    port = int(preview.url.rsplit(":", 1)[1].rstrip("/"))
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
    try:
        skip_host = "Host" in headers
        connection.putrequest(method, path, skip_host=skip_host, skip_accept_encoding=True)
        for name, value in headers.items():
            connection.putheader(name, value)
        if body is not None:
            connection.putheader("Content-Length", str(len(body)))
        connection.endheaders(body)
        reply = connection.getresponse()
        return reply.status, reply.read()
    finally:
        connection.close()


def _method_now(preview: Preview) -> str | None:
    return preview.state()["method"]


def _own_origin(preview: Preview) -> str:
    return preview.url.rstrip("/")


def test_the_page_carries_a_token_of_the_run(preview: Preview, tmp_path: Path) -> None:
    status, page = _request(preview, "GET", "/")
    assert status == 200
    found = re.search(rb'<meta name="tweenrender-token" content="([A-Za-z0-9_-]{20,})">', page)
    assert found, page[:400]
    assert found[1].decode() == preview.token
    other_scene = tmp_path / "other.toml"
    other_scene.write_text(SCENE.format(fill=RED))
    other = start_preview(str(other_scene), cwd=tmp_path)
    try:
        assert other.token != preview.token  # a token of the run, not of the program
    finally:
        stop(other)


def test_cross_origin_method_post_is_refused_and_changes_nothing(preview: Preview) -> None:
    before = preview.state()
    body = json.dumps({"token": preview.token, "method": "injective"}).encode()
    for origin in ("http://evil.example", "null", "http://127.0.0.1:1", "https://127.0.0.1"):
        status, _ = _request(preview, "POST", "/method", body, Origin=origin, **{"Content-Type": "text/plain"})
        assert status == 403, origin
    # the original finding: the body a page sends with a no-cors fetch, the method's bare name
    assert _request(preview, "POST", "/method", b"injective", Origin="http://evil.example")[0] == 403
    assert _request(preview, "POST", "/method", b"injective")[0] == 403  # no token at all
    time.sleep(0.5)
    after = preview.state()
    assert after["method"] is None and after["take"]["number"] == before["take"]["number"]


def test_state_needs_the_token(preview: Preview) -> None:
    assert _request(preview, "GET", "/state")[0] == 403
    assert _request(preview, "GET", "/state?token=wrong")[0] == 403
    status, body = _request(preview, "GET", f"/state?token={preview.token}")
    assert status == 200 and json.loads(body)["take"] is not None
    assert _request(preview, "GET", f"/state?token={preview.token}", Origin="http://evil.example")[0] == 403



def test_a_cross_site_request_without_origin_is_refused(preview: Preview) -> None:
    """A browser marks every request a page of another site makes ``Sec-Fetch-Site: cross-site`` (Fetch
    Metadata), a GET without ``Origin`` too: refused even with the token; the page's own are answered."""
    for site in ("cross-site", "same-site"):
        assert _request(preview, "GET", f"/state?token={preview.token}", **{"Sec-Fetch-Site": site})[0] == 403
        body = json.dumps({"token": preview.token, "method": "injective"}).encode()
        assert _request(preview, "POST", "/method", body, **{"Sec-Fetch-Site": site})[0] == 403
    assert _request(preview, "GET", f"/state?token={preview.token}", **{"Sec-Fetch-Site": "same-origin"})[0] == 200
    assert _method_now(preview) is None


def test_a_body_too_long_is_refused_before_it_is_sent(preview: Preview) -> None:
    """A request announcing a 2 GB body is answered at once (not read, not waited for)."""
    port = int(preview.url.rsplit(":", 1)[1].rstrip("/"))
    connection = http.client.HTTPConnection("127.0.0.1", port, timeout=REQUEST_SECONDS + 5)
    try:
        connection.putrequest("POST", "/edit")
        connection.putheader("Content-Length", str(2 << 30))
        connection.endheaders()
        reply = connection.getresponse()
        assert reply.status == 400
    finally:
        connection.close()


def test_own_origin_with_the_token_is_answered(preview: Preview) -> None:
    body = json.dumps({"token": preview.token, "method": "linear"}).encode()
    status, _ = _request(preview, "POST", "/method", body, Origin=_own_origin(preview))
    assert status == 204
    assert preview.wait_state(lambda s: s["method"] == "linear" and s["take"]["method"] == "linear")
    port = _own_origin(preview).rsplit(":", 1)[1]
    body = json.dumps({"token": preview.token, "method": "rigid"}).encode()
    assert _request(preview, "POST", "/method", body, Origin=f"http://localhost:{port}",
                    Host=f"localhost:{port}")[0] == 204
    assert preview.wait_state(lambda s: s["method"] == "rigid")


def test_a_foreign_host_is_refused_even_with_the_token(preview: Preview) -> None:
    port = _own_origin(preview).rsplit(":", 1)[1]
    body = json.dumps({"token": preview.token, "method": "linear"}).encode()
    for host in (f"evil.example:{port}", "127.0.0.1", f"127.0.0.1:{int(port) + 1}", ""):
        assert _request(preview, "POST", "/method", body, Host=host)[0] == 403, host
        assert _request(preview, "GET", f"/state?token={preview.token}", Host=host)[0] == 403, host
    assert _method_now(preview) is None


def test_edit_is_refused_across_origins_and_without_the_token(preview: Preview) -> None:
    ops = [{"op": "ease", "shape": "box", "key": 0, "ease": "in"}]
    scene = Path(preview.state()["scene_file"])
    before = scene.read_bytes()
    for token, origin in ((preview.token, "http://evil.example"), (preview.token, "null"), ("", None), (None, None)):
        payload: dict[str, object] = {"ops": ops}
        if token is not None:
            payload["token"] = token
        headers = {"Origin": origin} if origin else {}
        assert _request(preview, "POST", "/edit", json.dumps(payload).encode(), **headers)[0] == 403
    assert scene.read_bytes() == before


class _Elsewhere(http.server.ThreadingHTTPServer):
    """A page on another origin (another port) that tries the finding's request."""


@needs_chromium
def test_a_page_of_another_origin_cannot_switch_the_method(preview: Preview) -> None:
    port = _own_origin(preview).rsplit(":", 1)[1]
    attack = f"""<!doctype html><title>elsewhere</title><script>
    const target = "http://127.0.0.1:{port}";
    Promise.allSettled([
      fetch(target + "/method", {{method: "POST", mode: "no-cors", body: "injective"}}),
      fetch(target + "/method", {{method: "POST", mode: "no-cors",
                                 body: JSON.stringify({{token: "guess", method: "injective"}})}}),
      fetch(target + "/edit", {{method: "POST", mode: "no-cors",
                               body: JSON.stringify({{ops: [{{op: "ease", shape: "box", key: 0, ease: "in"}}]}})}}),
    ]).then(() => {{ document.title = "sent"; }});
    </script>""".encode()

    class Handler(http.server.BaseHTTPRequestHandler):
        def do_GET(self) -> None:  # noqa: N802
            self.send_response(200)
            self.send_header("Content-Type", "text/html")
            self.send_header("Content-Length", str(len(attack)))
            self.end_headers()
            self.wfile.write(attack)

        def log_message(self, *args: object) -> None:
            pass

    elsewhere = _Elsewhere(("127.0.0.1", 0), Handler)
    thread = threading.Thread(target=elsewhere.serve_forever, daemon=True)
    thread.start()
    scene = Path(preview.state()["scene_file"])
    before_text = scene.read_bytes()
    take = preview.state()["take"]["number"]
    try:
        with live_page(f"http://127.0.0.1:{elsewhere.server_address[1]}/") as page:
            page.wait_for("document.title === 'sent'")
        time.sleep(0.5)
        state = preview.state()
        assert state["method"] is None and state["take"]["number"] == take
        assert scene.read_bytes() == before_text
    finally:
        elsewhere.shutdown()
        elsewhere.server_close()

