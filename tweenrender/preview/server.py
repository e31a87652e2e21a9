"""The preview's HTTP server: the page, its state (long-polled), the frames and the edits, on 127.0.0.1 only.

Routes: ``GET /`` the page; ``GET /state?token=T&since=V`` the state as JSON once its version passes
``V`` (at most a second later); ``GET /frame/T/I.png`` frame ``I`` of take ``T``; ``POST /method``
with ``{"token": T, "method": name}`` (``null``: each shape's own); ``POST /edit`` with ``{"token": T,
"ops": [...]}`` or ``{"token": T, "history": "undo" | "redo"}``, answered ``{"ok": true}`` or
``{"ok": false, "error": line}``.

Only the page this server served may change anything (any page the user visits can reach 127.0.0.1):
a request whose ``Host`` is not this server's loopback address and port, whose ``Origin`` (or
``Sec-Fetch-Site``) says it comes from another origin, or that lacks the token of the run (embedded
in the page as ``<meta name="tweenrender-token">``, which another origin cannot read), is answered
403 before its body is read. Connections are bounded: a request not received within
``REQUEST_SECONDS`` is dropped, and beyond ``MAX_CONNECTIONS`` at once the answer is 503.
"""

from __future__ import annotations

import hmac
import json
import re
import secrets
import socket
import threading
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from importlib import resources
from typing import Any
from urllib.parse import parse_qs, urlsplit

from .edits import SceneEditor
from .takes import Previewer

__all__ = ["PreviewServer", "MAX_CONNECTIONS", "REQUEST_SECONDS"]

_FRAME = re.compile(r"/frame/(\d{1,9})/(\d{1,9})\.png")
_LONG_POLL_SECONDS = 1.0
_MAX_BODY = 1 << 20  # an edit's JSON
MAX_CONNECTIONS = 32
"""Connections served at once (each on a thread); more are answered 503 and closed."""
REQUEST_SECONDS = 5.0
"""How long a connection may stay silent (idle, or part of a request sent) before it is closed."""
_TOKEN_MARK = b"__TWEENRENDER_TOKEN__"
_BUSY = (b"HTTP/1.0 503 Service Unavailable\r\nContent-Type: text/plain\r\nContent-Length: 20\r\n"
         b"Connection: close\r\n\r\ntoo many connections")


class PreviewServer(ThreadingHTTPServer):
    """Serves one :class:`Previewer` (and its :class:`SceneEditor`) on ``127.0.0.1`` at a free port."""

    daemon_threads = True  # a page's open request does not hold up the end
    request_queue_size = 128  # connections waiting to be accepted (then served, or answered 503)

    def __init__(self, previewer: Previewer, editor: SceneEditor | None = None) -> None:
        super().__init__(("127.0.0.1", 0), _Handler)
        self.previewer = previewer
        self.editor = editor
        self.token = secrets.token_urlsafe(24)
        page = resources.files(__package__).joinpath("page.html").read_bytes()
        self.page = page.replace(_TOKEN_MARK, self.token.encode())
        port = self.server_address[1]
        self.hosts = {f"127.0.0.1:{port}", f"localhost:{port}"}
        self.origins = {f"http://{host}" for host in self.hosts}
        self._slots = threading.BoundedSemaphore(MAX_CONNECTIONS)

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.server_address[1]}/"

    def process_request(self, request: Any, client_address: Any) -> None:
        """A thread per connection, at most :data:`MAX_CONNECTIONS` at once; beyond, 503 and closed."""
        if not self._slots.acquire(blocking=False):
            try:
                request.setblocking(False)
                request.send(_BUSY)
            except OSError:
                pass
            self.shutdown_request(request)
            return
        try:
            super().process_request(request, client_address)
        except Exception:  # no thread was started (an interruption while it starts is not caught here:
            self._slots.release()  # the thread runs, and gives its slot back itself)
            raise

    def process_request_thread(self, request: Any, client_address: Any) -> None:
        try:
            super().process_request_thread(request, client_address)
        finally:
            self._slots.release()

    def handle_error(self, request: Any, client_address: Any) -> None:
        """A page that closed mid-answer is no error of ours: nothing is printed."""

    def token_matches(self, given: object) -> bool:
        return isinstance(given, str) and hmac.compare_digest(given.encode(), self.token.encode())


class _Handler(BaseHTTPRequestHandler):
    server: PreviewServer
    timeout = REQUEST_SECONDS  # the socket's: a silent or half-sent request ends in a timeout, then closed

    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002 - the base class's name
        """Requests are not logged: the terminal stays the user's."""

    def handle_one_request(self) -> None:
        try:
            super().handle_one_request()
        except TimeoutError:
            self.close_connection = True

    def do_GET(self) -> None:  # noqa: N802 - http.server's name
        if not self._from_here():
            return
        url = urlsplit(self.path)
        previewer = self.server.previewer
        if url.path == "/":
            self._send(200, "text/html; charset=utf-8", self.server.page)
        elif url.path == "/state":
            query = parse_qs(url.query)
            if not self.server.token_matches(query.get("token", [None])[0]):
                self._refuse()
                return
            try:
                since = int(query.get("since", ["-1"])[0])
            except ValueError:
                since = -1
            state = previewer.state(since, wait=_LONG_POLL_SECONDS)
            if self.server.editor is not None:
                state.update(self.server.editor.describe())
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
        path = urlsplit(self.path).path
        if path not in ("/method", "/edit"):
            self._send(404, "text/plain", b"not found")
            return
        payload = self._json_body()
        if payload is None:
            return
        if path == "/method":
            self._choose_method(payload)
        else:
            self._edit(payload)

    def _choose_method(self, payload: dict[str, Any]) -> None:
        name = payload.get("method")
        if name is not None and not isinstance(name, str):
            self._send(400, "text/plain", b"expected a method's name or null")
            return
        try:
            self.server.previewer.choose_method(name or None)
        except ValueError as error:
            self._send(400, "text/plain", str(error).encode())
            return
        self._send(204, "text/plain", b"")

    def _edit(self, payload: dict[str, Any]) -> None:
        editor = self.server.editor
        if editor is None:
            reply: dict[str, Any] = {"ok": False, "error": "this preview does not edit"}
        elif "history" in payload:
            reply = editor.history(payload["history"])
        else:
            reply = editor.apply(payload.get("ops"))
        self._send(200, "application/json", json.dumps(reply).encode())

    def _json_body(self) -> dict[str, Any] | None:
        """The request's JSON object once its token is the run's; else None, the refusal sent."""
        try:
            length = int(self.headers.get("Content-Length", "-1"))
        except ValueError:
            length = -1
        if not 0 <= length <= _MAX_BODY:
            self._send(400, "text/plain", b"expected a JSON body with its Content-Length")
            return None
        raw = self.rfile.read(length)
        try:
            payload = json.loads(raw.decode("utf-8"))
        except (UnicodeDecodeError, ValueError, RecursionError):
            payload = None
        if not isinstance(payload, dict) or not self.server.token_matches(payload.get("token")):
            self._refuse()
            return None
        return payload

    def _from_here(self) -> bool:
        """Whether the request is addressed to this server by its own name and comes from its own page
        (or from no page at all); else 403, sent."""
        headers = self.headers
        origin = headers.get("Origin")
        site = headers.get("Sec-Fetch-Site")
        if headers.get("Host", "") in self.server.hosts and (origin is None or origin in self.server.origins) \
                and site in (None, "same-origin", "none"):
            return True
        self._refuse()
        return False

    def _refuse(self) -> None:
        self.close_connection = True
        self._send(403, "text/plain", b"this preview answers its own page only")

    def _send(self, status: int, kind: str, body: bytes, cache: str = "no-store") -> None:
        self.send_response(status)
        self.send_header("Content-Type", kind)
        self.send_header("Cache-Control", cache)
        self.send_header("Content-Length", str(len(body)))
        self.send_header("X-Content-Type-Options", "nosniff")
        if kind.startswith("text/html"):
            self.send_header("Content-Security-Policy", "default-src 'none'; script-src 'unsafe-inline'; "
                             "style-src 'unsafe-inline'; img-src 'self'; connect-src 'self'; frame-ancestors 'none'")
        self.end_headers()
        if body and self.command != "HEAD":
            self.wfile.write(body)
