"""The preview's file watcher: a save is never missed, even one made while the watch is being set up.

``watchfiles.watch`` is replaced by a stand-in whose watch is armed only when the test says so, so a
save can be placed before, during or after arming without depending on how busy the machine is.
"""

from __future__ import annotations

import os
import threading
from pathlib import Path
from typing import Any, Iterator

import pytest

from tweenrender.pipeline.preview.watcher import FileWatcher


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


def test_a_save_made_while_the_watch_is_armed_is_seen(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import watchfiles

    scene = tmp_path / "scene.toml"
    scene.write_text("first")
    fake = SlowArming()
    monkeypatch.setattr(watchfiles, "watch", fake)
    seen = threading.Event()
    watcher = FileWatcher(seen.set)
    watcher.watch([scene])
    watcher.start()
    try:
        assert fake.arming.wait(10)
        seen_before = seen.wait(1.0)  # longer than any fixed grace period the watcher might give arming
        part = tmp_path / ".scene.toml.part"
        part.write_text("second, saved as editors do")
        os.replace(part, scene)
        fake.arm.set()
        assert not seen_before
        assert seen.wait(10), "a save made before the watch was armed was missed"
    finally:
        watcher.stop()


def test_nothing_is_reported_when_nothing_changed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import watchfiles

    scene = tmp_path / "scene.toml"
    scene.write_text("first")
    fake = SlowArming()
    monkeypatch.setattr(watchfiles, "watch", fake)
    calls: list[int] = []
    watcher = FileWatcher(lambda: calls.append(1))
    watcher.watch([scene])
    watcher.start()
    try:
        assert fake.arming.wait(10)
        fake.arm.set()
        threading.Event().wait(0.5)
        assert calls == []
    finally:
        watcher.stop()


def test_a_save_made_before_the_watch_thread_runs_is_seen(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """The scene is read once ``watch`` is called; the watching thread may start (and import) much later."""
    import watchfiles

    scene = tmp_path / "scene.toml"
    scene.write_text("first")
    fake = SlowArming()
    monkeypatch.setattr(watchfiles, "watch", fake)
    seen = threading.Event()
    watcher = FileWatcher(seen.set)
    watcher.watch([scene])
    scene.write_text("second, written in place")
    watcher.start()
    try:
        fake.arm.set()
        assert seen.wait(10), "a save made before the watching thread ran was missed"
    finally:
        watcher.stop()
