"""The page's edits written into the scene file, with undo and redo.

Each edit is checked by the loader before it is written (atomically); a refused one writes nothing
and answers the loader's one line. Undo and redo are kept here, as the scene's whole texts before and
after each edit: an undo writes back the text before the last edit, unless the file was changed by
something else since (then the history is dropped: the user's own save is never undone). Drawings
given on the command line are never written: the first edit saves the scene ``init`` writes for the
same command line (``<a>-<b>.toml`` in the current folder, never over an existing file) and
edits that from then on.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path
from typing import Any, Callable

from ..api import drawings_scene_text, edit_scene_text, save_scene_text
from ..errors import TweenrenderError, printable
from .takes import Previewer

__all__ = ["SceneEditor", "MAX_HISTORY"]

MAX_HISTORY = 200
"""Edits that can be undone."""


class SceneEditor:
    """Edits the scene the :class:`Previewer` shows; ``announce`` is told the path of a scene it creates."""

    def __init__(self, previewer: Previewer, announce: Callable[[str], None] = print,
                 folder: Path | None = None) -> None:
        self.previewer = previewer
        self.announce = announce
        self.folder = folder or Path.cwd()
        self._undo: list[str] = []
        self._redo: list[str] = []
        self._written: str | None = None  # the text this editor last wrote
        self._lock = threading.Lock()

    @property
    def scene_file(self) -> Path | None:
        """The scene file edits go to (None: drawings from the command line, until the first edit)."""
        inputs = self.previewer.inputs
        if len(inputs) == 1 and inputs[0].suffix.lower() not in (".svg", ".json"):
            return Path(inputs[0])
        return None

    def describe(self) -> dict[str, Any]:
        file = self.scene_file
        return {"scene_file": None if file is None else str(file), "can_undo": bool(self._undo),
                "can_redo": bool(self._redo)}

    def apply(self, ops: object) -> dict[str, Any]:
        """Apply ``ops`` (DESIGN's ops) to the scene file: ``{"ok": true}`` or ``{"ok": false, "error": line}``."""
        with self._lock:
            try:
                path, text = self._current()
                edited = edit_scene_text(text, path, ops)
                if self.scene_file is None:  # drawings: the scene `init` writes comes first
                    save_scene_text(path, text)
                    self.previewer.use_scene_file(path)
                    self.announce(str(path))
                save_scene_text(path, edited)
            except TweenrenderError as error:
                return {"ok": False, "error": printable(str(error)) or "refused"}
            self._undo = [*self._undo, text][-MAX_HISTORY:]
            self._redo = []
            self._written = edited
        self.previewer.changed()
        return {"ok": True}

    def history(self, which: object) -> dict[str, Any]:
        """``"undo"`` the last edit or ``"redo"`` the last undone one."""
        if which not in ("undo", "redo"):
            return {"ok": False, "error": "expected history \"undo\" or \"redo\""}
        with self._lock:
            taken, given = (self._undo, self._redo) if which == "undo" else (self._redo, self._undo)
            path = self.scene_file
            if not taken or path is None:
                return {"ok": False, "error": f"nothing to {which}"}
            try:
                now = path.read_text(encoding="utf-8")
            except OSError as error:
                return {"ok": False, "error": f"{path}: cannot be read ({error.strerror or error})"}
            if now != self._written:
                self._undo, self._redo = [], []
                return {"ok": False, "error": f"{path} changed on disk since the last edit; nothing to {which}"}
            text = taken.pop()
            try:
                save_scene_text(path, text)
            except TweenrenderError as error:
                taken.append(text)
                return {"ok": False, "error": printable(str(error))}
            given.append(now)
            self._written = text
        self.previewer.changed()
        return {"ok": True}

    def _current(self) -> tuple[Path, str]:
        """The scene file to edit and its text; for drawings, a new file's name and the text ``init`` writes."""
        path = self.scene_file
        if path is not None:
            try:
                return path, path.read_text(encoding="utf-8")
            except OSError as error:
                raise TweenrenderError(f"{path}: cannot be read ({error.strerror or error})") from None
            except UnicodeDecodeError:
                raise TweenrenderError(f"{path}: expected UTF-8 text") from None
        inputs = self.previewer.inputs
        if any(p.suffix.lower() == ".json" for p in inputs):
            raise TweenrenderError(f"{inputs[0]}: the preview edits TOML scenes; this one is JSON")
        target = _fresh_name(self.folder, "-".join(p.stem for p in inputs[:4]))
        timing = self.previewer.timing
        return target, drawings_scene_text(inputs, self.folder, self.previewer.step, timing.get("ease", "linear"),
                                           timing.get("hold", 0.0), timing.get("stagger", 0.0))


def _fresh_name(folder: Path, stem: str) -> Path:
    """``folder/stem.toml``, or ``stem-2.toml``… where that is taken: an existing file is never replaced."""
    for number in range(1, 10_000):
        path = folder / (f"{stem}.toml" if number == 1 else f"{stem}-{number}.toml")
        if not os.path.lexists(path):
            return path
    raise TweenrenderError(f"{folder}: no free name for {stem}.toml")
