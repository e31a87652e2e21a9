"""The preview's save-to-frame latency for the shipped scenes (run by hand, not in CI).

    python benchmarks/bench_preview.py [--rounds 5] [SCENE ...]

For each scene (default every ``scenes/*.toml``), a copy of ``scenes/`` is previewed by a real
``tweenrender preview`` process; once its first take is drawn, the scene file is saved again
(as an editor does: a new file renamed over the old one, here with one more comment line), and
the time from the rename to the first frame of the new take being served over HTTP is measured
from the outside, by a client long-polling ``/state``. Prints min / median of ``--rounds`` saves
per scene, with the server's own count (from the change it saw to frame 0 published) and the
load average.
"""

from __future__ import annotations

import argparse
import json
import os
import select
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def _state(url: str, since: int) -> dict:
    with urllib.request.urlopen(f"{url}state?since={since}", timeout=10) as reply:
        return json.loads(reply.read())


def _wait(url: str, test, timeout: float = 120.0) -> dict:  # type: ignore[no-untyped-def]
    deadline, since = time.monotonic() + timeout, -1
    while time.monotonic() < deadline:
        state = _state(url, since)
        if test(state):
            return state
        since = state["version"]
    raise TimeoutError(url)


def measure(scene: Path, rounds: int) -> tuple[list[float], list[float], int]:
    """Client-side save-to-frame seconds, the server's own, and the frames of a take."""
    with tempfile.TemporaryDirectory(prefix="tweenrender-bench-preview-") as folder:
        copy = Path(folder) / "scenes"
        shutil.copytree(scene.parent, copy)
        target = copy / scene.name
        process = subprocess.Popen([sys.executable, "-m", "tweenrender", "preview", str(target)],
                                   stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True,
                                   env={**os.environ, "PYTHONPATH": str(ROOT)}, start_new_session=True)
        try:
            assert process.stdout is not None
            if not select.select([process.stdout], [], [], 120)[0]:
                raise TimeoutError("no address")
            url = process.stdout.readline().strip()
            state = _wait(url, lambda s: s["take"] and s["take"]["drawn"] == s["take"]["total"])
            take, total = state["take"]["number"], state["take"]["total"]
            outside, inside = [], []
            text = target.read_text()
            for round_ in range(rounds):
                time.sleep(0.3)  # the watcher settles
                part = target.with_name(f".{target.name}.part")
                part.write_text(text + f"\n# saved {round_}\n")
                since = _state(url, -1)["version"]
                start = time.perf_counter()
                os.replace(part, target)
                while True:
                    state = _state(url, since)
                    since = state["version"]
                    if state["error"]:
                        raise RuntimeError(state["error"])
                    if state["take"]["number"] > take:
                        break
                outside.append(time.perf_counter() - start)
                inside.append(state["take"]["first_frame_seconds"])
                take = state["take"]["number"]
                _wait(url, lambda s: s["take"]["drawn"] == s["take"]["total"])
            return outside, inside, total
        finally:
            process.send_signal(signal.SIGTERM)
            process.wait(timeout=15)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("scenes", nargs="*", type=Path)
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    scenes = args.scenes or sorted((ROOT / "scenes").glob("*.toml"))
    print(f"load average at start: {os.getloadavg()[0]:.2f} (cores: {os.cpu_count()})")
    print(f"{'scene':28} {'frames':>6}  save -> frame served, s (min / median)  server's own (min / median)")
    worst = 0.0
    for scene in scenes:
        outside, inside, total = measure(scene, args.rounds)
        worst = max(worst, statistics.median(outside))
        print(f"{scene.name:28} {total:6d}  {min(outside):.3f} / {statistics.median(outside):.3f}"
              f"{'':24}{min(inside):.3f} / {statistics.median(inside):.3f}", flush=True)
    print(f"worst median: {worst:.3f} s; load average at end: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
