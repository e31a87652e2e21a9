"""``tweenrender preview``: a page on 127.0.0.1 that plays a scene while it renders, and draws it
again whenever the scene or a drawing it reads is saved.

:mod:`.takes` draws (on a thread), :mod:`.watcher` watches the files, :mod:`.server` serves the
page (``page.html``, self-contained), its state and the frames. Nothing here starts a process.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable, Sequence

from .server import PreviewServer
from .takes import Previewer
from .watcher import FileWatcher

__all__ = ["serve_preview"]


def serve_preview(inputs: Sequence[str | Path], *, method: str | None = None, size: tuple[int, int] | None = None,
                  fps: float | None = None, step: float = 1.0,
                  announce: Callable[[str], None] = print) -> None:
    """Serve the preview of ``inputs`` (a scene file, or SVG drawings ``step`` seconds apart) until
    interrupted; ``announce`` is given the page's address once it answers.

    A scene that fails to load is shown as its one-line error on the page, as a later bad save is.
    KeyboardInterrupt and SystemExit (the CLI's SIGTERM) end it after the threads are stopped.
    """
    from ..api import check_preview_settings

    method, size, fps = check_preview_settings(method, size, fps)
    paths = [Path(p) for p in inputs]
    previewer = Previewer(paths, step=step, method=method, size=size, fps=fps)
    watcher = FileWatcher(previewer.changed)
    previewer.on_sources = lambda files: watcher.watch([*paths, *files])
    watcher.watch(paths)
    server = PreviewServer(previewer)
    try:
        watcher.start()
        previewer.start()
        announce(server.url)
        server.serve_forever(poll_interval=0.25)
    finally:
        previewer.stop()
        watcher.stop()
        server.server_close()
