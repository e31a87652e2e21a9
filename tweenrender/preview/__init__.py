"""``tweenrender preview``: a page on 127.0.0.1 that plays a scene while it renders, draws it again
whenever the scene or a drawing it reads is saved, and edits the scene by pointing.

:mod:`.takes` draws (on a thread), :mod:`.watcher` watches the files, :mod:`.edits` writes the page's
edits into the scene file, :mod:`.server` serves the page (``page.html``, self-contained), its state,
the frames and the edits. Nothing here starts a process.
"""

from __future__ import annotations

from pathlib import Path
from typing import Callable, Sequence

from .edits import SceneEditor
from .server import PreviewServer
from .takes import Previewer
from .watcher import FileWatcher

__all__ = ["serve_preview"]


def serve_preview(inputs: Sequence[str | Path], *, method: str | None = None, size: tuple[int, int] | None = None,
                  fps: float | None = None, step: float = 1.0, ease: str = "linear", hold: float = 0.0,
                  stagger: float = 0.0, announce: Callable[[str], None] = print) -> None:
    """Serve the preview of ``inputs`` (a scene file, or SVG drawings ``step`` seconds apart, each held
    ``hold`` seconds, moving under ``ease``, their elements ``stagger`` seconds apart) until interrupted;
    ``announce`` is given the page's address once it answers, and the path of a scene file an edit
    of drawings creates.

    A scene that fails to load is shown as its one-line error on the page, as a later bad save is.
    KeyboardInterrupt and SystemExit (the CLI's SIGTERM) end it after the threads are stopped.
    """
    from ..api import check_preview_settings

    method, size, fps = check_preview_settings(method, size, fps)
    paths = [Path(p) for p in inputs]
    timing = {name: value for name, value, plain in (("ease", ease, "linear"), ("hold", hold, 0.0),
                                                      ("stagger", stagger, 0.0)) if value != plain}
    previewer = Previewer(paths, step=step, timing=timing, method=method, size=size, fps=fps)
    watcher = FileWatcher(previewer.changed)
    previewer.on_sources = lambda files: watcher.watch([*previewer.inputs, *files])
    watcher.watch(paths)
    server = PreviewServer(previewer, SceneEditor(previewer, announce))
    try:
        watcher.start()
        previewer.start()
        announce(server.url)
        server.serve_forever(poll_interval=0.25)
    finally:
        previewer.stop()
        watcher.stop()
        server.server_close()
