"""The preview bounds its connections: a silent or half-sent request is closed after a few seconds, and
beyond a cap of connections at once the answer is 503 — a page cannot pile up threads in it."""

from __future__ import annotations

import socket
import time
from pathlib import Path
from typing import Iterator

import pytest

from tests.preview.test_preview import SCENE, Preview, start_preview, stop
from tweenrender.preview.server import MAX_CONNECTIONS, REQUEST_SECONDS


@pytest.fixture
def preview(tmp_path: Path) -> Iterator[Preview]:
    scene = tmp_path / "box.toml"
    scene.write_text(SCENE.format(fill="#d03030"))
    running = start_preview(str(scene), cwd=tmp_path)
    try:
        running.wait_state(lambda s: s["take"] is not None and s["take"]["drawn"] == s["take"]["total"])
        yield running
    finally:
        if running.process.poll() is None:
            stop(running)


def _threads(preview: Preview) -> int:
    status = Path(f"/proc/{preview.process.pid}/status").read_text()
    return int(next(line.split()[1] for line in status.splitlines() if line.startswith("Threads:")))


def _port(preview: Preview) -> int:
    return int(preview.url.rsplit(":", 1)[1].rstrip("/"))


def _closed_within(connection: socket.socket, seconds: float) -> bytes | None:
    """What the server sent before closing ``connection`` within ``seconds``; None if it is still open."""
    connection.settimeout(0.2)
    deadline, got = time.monotonic() + seconds, b""
    while time.monotonic() < deadline:
        try:
            chunk = connection.recv(4096)
        except TimeoutError:
            continue
        except ConnectionResetError:
            return got
        if not chunk:
            return got
        got += chunk
    return None


@pytest.mark.parametrize("sent", [b"", b"GET /state HTTP/1.1\r\nHost: 127.0.0.1:"], ids=["idle", "half-sent"])
def test_silent_connections_are_closed_and_their_threads_end(preview: Preview, sent: bytes) -> None:
    before = _threads(preview)
    connections = []
    for _ in range(50):
        connection = socket.create_connection(("127.0.0.1", _port(preview)), timeout=5)
        connection.sendall(sent)
        connections.append(connection)
    try:
        started = time.monotonic()
        for connection in connections:
            assert _closed_within(connection, REQUEST_SECONDS + 5 - (time.monotonic() - started)) is not None
        assert time.monotonic() - started < REQUEST_SECONDS + 5
        time.sleep(0.5)
        assert _threads(preview) <= before + 1
        assert preview.state()["take"] is not None  # still answering
    finally:
        for connection in connections:
            connection.close()


def test_beyond_the_cap_the_answer_is_503(preview: Preview) -> None:
    before = _threads(preview)
    held = [socket.create_connection(("127.0.0.1", _port(preview)), timeout=5) for _ in range(MAX_CONNECTIONS + 8)]
    try:
        time.sleep(0.5)
        assert _threads(preview) <= before + MAX_CONNECTIONS + 1
        answers = []
        for connection in held:  # what each has been sent by now, without waiting on any
            connection.setblocking(False)
            try:
                answers.append(connection.recv(4096))
            except BlockingIOError:
                answers.append(None)
        busy = [a for a in answers if a is not None and a.startswith(b"HTTP/1.0 503")]
        assert len(busy) >= 8 and answers.count(None) >= MAX_CONNECTIONS - 2, answers
    finally:
        for connection in held:
            connection.close()
    time.sleep(REQUEST_SECONDS + 1)
    assert preview.state()["take"] is not None


def test_an_interruption_while_a_handler_starts_is_not_swallowed(monkeypatch: pytest.MonkeyPatch) -> None:
    """Ctrl-C or SIGTERM arriving while the serving loop starts a connection's thread reaches the loop's
    caller (else the preview would go on serving after it): the slot is given back once, by the thread."""
    import threading

    from tweenrender.preview.server import PreviewServer

    class Idle:
        def state(self, since: int = -1, wait: float = 0.0) -> dict:
            return {}

    server = PreviewServer(Idle())  # type: ignore[arg-type]
    start = threading.Thread.start

    def start_then_interrupt(thread: threading.Thread) -> None:
        start(thread)
        thread.join(5)  # the thread has served its request and given back its slot
        raise KeyboardInterrupt

    client = socket.create_connection(server.server_address, timeout=5)
    try:
        client.sendall(b"GET /nothing HTTP/1.0\r\nHost: 127.0.0.1\r\n\r\n")
        monkeypatch.setattr(threading.Thread, "start", start_then_interrupt)
        with pytest.raises(KeyboardInterrupt):
            server._handle_request_noblock()
    finally:
        monkeypatch.undo()
        client.close()
        server.server_close()
