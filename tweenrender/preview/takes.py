"""What the preview shows: takes (one rendering of the scene each), drawn on a thread as files change.

A take is the scene as loaded at one moment with one method; its frames are drawn in order
and published one by one as PNG bytes. A new take replaces the shown one once its first frame
is drawn; a scene that fails to load, or a take that fails before its first frame, leaves the
shown take as it is and sets the error line instead.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Sequence

from ..errors import TweenrenderError, printable
from ..api import method_names

__all__ = ["Take", "Previewer", "MAX_FRAMES"]

MAX_FRAMES = 100_000
"""The most frames a take keeps (the render command's default ``--max-frames``)."""


@dataclass
class Take:
    """One rendering: ``frames[i]`` is frame ``i``'s PNG, None until drawn."""

    number: int
    method: str | None
    fps: float
    size: tuple[int, int]
    frames: list[bytes | None]
    changed_at: float  # time.monotonic() when the change that started it was seen
    first_frame_seconds: float | None = None  # from changed_at to frame 0 published
    drawn: int = 0

    def describe(self) -> dict[str, Any]:
        return {"number": self.number, "method": self.method, "fps": self.fps, "width": self.size[0],
                "height": self.size[1], "total": len(self.frames), "drawn": self.drawn,
                "first_frame_seconds": self.first_frame_seconds}


@dataclass
class Previewer:
    """Loads ``inputs`` (a scene file, or SVG drawings ``step`` seconds apart) and draws takes of it.

    :meth:`changed` asks for a new take (a file changed, or the method); :meth:`state` is what the
    page polls. Drawing happens on one thread of its own, started by :meth:`start`.
    """

    inputs: Sequence[Path]
    step: float = 1.0
    timing: dict[str, Any] = field(default_factory=dict)  # drawings' ease, hold and stagger (load_scene's names)
    method: str | None = None
    size: tuple[int, int] | None = None
    fps: float | None = None
    on_sources: Any = None  # called with the files a loaded scene read (the watcher's list)
    version: int = 0
    error: str | None = None
    take: Take | None = None
    scene_method: str | None = None
    editing: dict[str, Any] | None = None  # the shown take's keys, hints and page transform (api.editing_state)
    _condition: threading.Condition = field(default_factory=threading.Condition, repr=False)
    _dirty: threading.Event = field(default_factory=threading.Event, repr=False)
    _stop: threading.Event = field(default_factory=threading.Event, repr=False)
    _changed_at: float = 0.0
    _takes: int = 0
    _thread: threading.Thread | None = field(default=None, repr=False)

    # -- the page's side ------------------------------------------------------------------------

    def state(self, since: int = -1, wait: float = 0.0) -> dict[str, Any]:
        """The preview's state once its version is past ``since`` (or after ``wait`` seconds)."""
        with self._condition:
            if since >= self.version and wait > 0:
                self._condition.wait_for(lambda: self.version > since or self._stop.is_set(), timeout=wait)
            return {"version": self.version, "error": self.error, "method": self.method,
                    "scene_method": self.scene_method, "methods": list(method_names()),
                    "take": self.take.describe() if self.take else None,
                    **(self.editing or {"to_page": None, "shapes": [], "easings": {}})}

    def frame(self, take: int, index: int) -> bytes | None:
        """Frame ``index`` of take ``take`` as PNG bytes, or None (another take, or not drawn yet)."""
        shown = self.take
        if shown is None or shown.number != take or not 0 <= index < len(shown.frames):
            return None
        return shown.frames[index]

    def use_scene_file(self, path: Path) -> None:
        """Show the scene file ``path`` from now on (the one the first edit of drawings wrote)."""
        self.inputs = [path]
        self.timing = {}
        if self.on_sources is not None:
            self.on_sources((path,))

    def choose_method(self, name: str | None) -> None:
        """Draw with ``name`` from now on (None: each shape's own); a ValueError for an unknown one."""
        if name is not None and name not in method_names():
            raise ValueError(f"unknown method {name!r}; expected one of {', '.join(method_names())}")
        self.method = name
        self.changed()

    # -- the drawing thread ---------------------------------------------------------------------

    def changed(self) -> None:
        """Ask for a new take: the take being drawn stops after its current frame."""
        self._changed_at = time.monotonic()
        self._dirty.set()

    def start(self) -> None:
        self.changed()
        self._thread = threading.Thread(target=self._run, name="tweenrender-draw", daemon=True)
        self._thread.start()

    def stop(self, timeout: float = 2.0) -> None:
        self._stop.set()
        self._dirty.set()
        with self._condition:
            self._condition.notify_all()
        if self._thread is not None and self._thread.is_alive():
            self._thread.join(timeout)  # a frame being drawn finishes first; a long one is left (daemon)

    def _run(self) -> None:
        while not self._stop.is_set():
            if not self._dirty.wait(0.5):
                continue
            self._dirty.clear()
            if self._stop.is_set():
                return
            try:
                self._draw_take(self._changed_at)
            except TweenrenderError as error:
                self._publish(error=printable(str(error)) or "no message")
            except Exception as error:  # noqa: BLE001 - the page shows it; the preview goes on
                text = " | ".join(line.strip() for line in str(error).splitlines() if line.strip())
                self._publish(error=printable(f"unexpected {type(error).__name__}: {text}"))

    def _draw_take(self, changed_at: float) -> None:
        from ..api import editing_state, frame_count, frames, load_scene, png_bytes

        inputs = [str(p) for p in self.inputs]
        timing = self.timing if all(p.lower().endswith(".svg") for p in inputs) else {}
        scene = load_scene(inputs if len(inputs) > 1 else inputs[0], self.step, **timing)
        if self.on_sources is not None:
            self.on_sources(scene.sources or tuple(self.inputs))
        method = self.method
        rate = self.fps or scene.fps
        total = frame_count(scene, rate)
        if total > MAX_FRAMES:
            raise TweenrenderError(f"{self.inputs[0]}: {total} frames at {rate:g} fps; the preview shows at most "
                                   f"{MAX_FRAMES}")
        pictures = frames(scene, method=method, size=self.size, fps=rate)
        first = next(pictures)
        self._takes += 1
        take = Take(self._takes, method, rate, (first.shape[1], first.shape[0]), [None] * total, changed_at)
        take.frames[0] = png_bytes(first)
        take.drawn = 1
        take.first_frame_seconds = time.monotonic() - changed_at
        self._publish(take=take, scene_method=scene.method)
        try:
            editing = editing_state(scene, self.size, method)
        except TweenrenderError:
            editing = None
        with self._condition:
            self.editing = editing
        self._publish()
        for index, picture in enumerate(pictures, start=1):
            if self._dirty.is_set() or self._stop.is_set():
                return
            take.frames[index] = png_bytes(picture)
            take.drawn = index + 1
            self._publish()

    def _publish(self, take: Take | None = None, error: str | None = None, scene_method: str | None = None) -> None:
        """A new version of the state: a new take (which clears the error), an error, or a frame drawn."""
        with self._condition:
            if take is not None:
                self.take, self.error, self.scene_method = take, None, scene_method
            elif error is not None:
                self.error = error
            self.version += 1
            self._condition.notify_all()
