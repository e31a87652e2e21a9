"""The preview's HTTP server: the page, its state (long-polled) and the frames, on 127.0.0.1 only.

Routes: ``GET /`` the page; ``GET /state?since=V`` the state as JSON once its version passes
``V`` (at most a second later); ``GET /frame/T/I.png`` frame ``I`` of take ``T``; ``POST /method``
with a method's name as the body (empty: each shape's own). Requests whose ``Host`` is not this
server's loopback address are refused, so a page elsewhere cannot reach it by renaming itself.
"""

from __future__ import annotations

import json
import re
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from importlib import resources
from typing import Any
from urllib.parse import parse_qs, urlsplit

from .takes import Previewer

__all__ = ["PreviewServer"]

_FRAME = re.compile(r"/frame/(\d{1,9})/(\d{1,9})\.png")
_LONG_POLL_SECONDS = 1.0
_MAX_BODY = 64


class PreviewServer(ThreadingHTTPServer):
    """Serves one :class:`Previewer` on ``127.0.0.1`` at a free port (``url`` says which)."""

    daemon_threads = True  # a page's open request does not hold up the end

    def __init__(self, previewer: Previewer) -> None:
        super().__init__(("127.0.0.1", 0), _Handler)
        self.previewer = previewer
        self.page = resources.files(__package__).joinpath("page.html").read_bytes()
        port = self.server_address[1]
        self.hosts = {f"127.0.0.1:{port}", f"localhost:{port}"}

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.server_address[1]}/"

    def handle_error(self, request: Any, client_address: Any) -> None:
        """A page that closed mid-answer is no error of ours: nothing is printed."""


class _Handler(BaseHTTPRequestHandler):
    server: PreviewServer

    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002 - the base class's name
        """Requests are not logged: the terminal stays the user's."""

    def do_GET(self) -> None:  # noqa: N802 - http.server's name
        if not self._from_here():
            return
        url = urlsplit(self.path)
        previewer = self.server.previewer
        if url.path == "/":
            self._send(200, "text/html; charset=utf-8", self.server.page)
        elif url.path == "/state":
            try:
                since = int(parse_qs(url.query).get("since", ["-1"])[0])
            except ValueError:
                since = -1
            state = previewer.state(since, wait=_LONG_POLL_SECONDS)
            self._send(200, "application/json", json.dumps(state).encode())
        elif (match := _FRAME.fullmatch(url.path)) is not None:
            picture = previewer.frame(int(match[1]), int(match[2]))
            if picture is None:
                self._send(404, "text/plain", b"no such frame (yet)")
            else:
                self._send(200, "image/png", picture, cache="max-age=31536000, immutable")
        else:
            self._send(404, "text/plain", b"not found")

    def do_POST(self) -> None:  # noqa: N802
        if not self._from_here():
            return
        if urlsplit(self.path).path != "/method":
            self._send(404, "text/plain", b"not found")
            return
        try:
            length = int(self.headers.get("Content-Length", "0"))
        except ValueError:
            length = -1
        if not 0 <= length <= _MAX_BODY:
            self._send(400, "text/plain", b"expected a method name")
            return
        name = self.rfile.read(length).decode("utf-8", "replace").strip()
        try:
            self.server.previewer.choose_method(name or None)
        except ValueError as error:
            self._send(400, "text/plain", str(error).encode())
            return
        self._send(204, "text/plain", b"")

    def _from_here(self) -> bool:
        if self.headers.get("Host", "") in self.server.hosts:
            return True
        self._send(403, "text/plain", b"this preview answers its own address only")
        return False

    def _send(self, status: int, kind: str, body: bytes, cache: str = "no-store") -> None:
        self.send_response(status)
        self.send_header("Content-Type", kind)
        self.send_header("Cache-Control", cache)
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        if body and self.command != "HEAD":
            self.wfile.write(body)
