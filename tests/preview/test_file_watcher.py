"""The preview's file watcher: a save is never missed, even one made while the watch is being set up.

``watchfiles.watch`` is replaced by a stand-in whose watch is armed only when the test says so, so a
save can be placed before, during or after arming without depending on how busy the machine is.
"""

from __future__ import annotations

import os
import threading
from contextlib import contextmanager
from pathlib import Path
from typing import Any, Callable, Iterator

import pytest

from tweenrender.preview.watcher import FileWatcher


class SlowArming:
    """Stands in for ``watchfiles.watch``: arms only once ``arm`` is set, then reports no event."""

    def __init__(self) -> None:
        self.arming, self.arm = threading.Event(), threading.Event()

    def __call__(self, *folders: str, stop_event: threading.Event, yield_on_timeout: bool = False,
                 **_: Any) -> Iterator[set[Any]]:
        self.arming.set()
        self.arm.wait(10)
        while not stop_event.is_set():  # armed; the save came before, so inotify has nothing to say
            stop_event.wait(0.05)
            if yield_on_timeout:
                yield set()


@contextmanager
def watching(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, on_change: Callable[[], None],
             before_start: Callable[[Path], None] = lambda scene: None) -> Iterator[tuple[Path, SlowArming]]:
    """A watcher of ``scene.toml`` (written "first") over a :class:`SlowArming` watch; ``before_start`` runs
    between :meth:`FileWatcher.watch` and :meth:`FileWatcher.start`."""
    import watchfiles

    scene = tmp_path / "scene.toml"
    scene.write_text("first")
    fake = SlowArming()
    monkeypatch.setattr(watchfiles, "watch", fake)
    watcher = FileWatcher(on_change)
    watcher.watch([scene])
    before_start(scene)
    watcher.start()
    try:
        yield scene, fake
    finally:
        watcher.stop()


def test_a_save_made_while_the_watch_is_armed_is_seen(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    seen = threading.Event()
    with watching(tmp_path, monkeypatch, seen.set) as (scene, fake):
        assert fake.arming.wait(10)
        seen_before = seen.wait(1.0)  # longer than any fixed grace period the watcher might give arming
        part = tmp_path / ".scene.toml.part"
        part.write_text("second, saved as editors do")
        os.replace(part, scene)
        fake.arm.set()
        assert not seen_before
        assert seen.wait(10), "a save made before the watch was armed was missed"


def test_nothing_is_reported_when_nothing_changed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    calls: list[int] = []
    with watching(tmp_path, monkeypatch, lambda: calls.append(1)) as (_, fake):
        assert fake.arming.wait(10)
        fake.arm.set()
        threading.Event().wait(0.5)
        assert calls == []


def test_a_save_made_before_the_watch_thread_runs_is_seen(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The scene is read once ``watch`` is called; the watching thread may start (and import) much later."""
    seen = threading.Event()
    with watching(tmp_path, monkeypatch, seen.set,
                  before_start=lambda scene: scene.write_text("second, written in place")) as (_, fake):
        fake.arm.set()
        assert seen.wait(10), "a save made before the watching thread ran was missed"


def test_a_folder_removed_and_made_again_is_watched_again(tmp_path: Path) -> None:
    """As a branch checkout does: the scene's folder goes, comes back, and later saves are still seen."""
    import shutil
    import time

    folder = tmp_path / "project"
    folder.mkdir()
    scene = folder / "scene.toml"
    scene.write_text("first")
    seen = threading.Event()
    watcher = FileWatcher(seen.set)
    watcher.watch([scene])
    watcher.start()
    try:
        time.sleep(1.0)  # armed
        scene.write_text("second")
        assert seen.wait(5), "a plain save was not seen"
        shutil.rmtree(folder)
        time.sleep(1.0)
        folder.mkdir()
        scene.write_text("third, in the folder made again")
        time.sleep(2.0)
        for text in ("fourth", "fifth, longer than the fourth"):
            seen.clear()
            scene.write_text(text)
            assert seen.wait(5), f"the save {text!r} after the folder came back was not seen"
            time.sleep(0.5)
    finally:
        watcher.stop()
