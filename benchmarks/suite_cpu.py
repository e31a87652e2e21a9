"""Where the test suite's CPU time goes: a pytest plugin that reads ``getrusage`` around every test.

Run from the repository's root: ``python -m pytest -p benchmarks.suite_cpu`` (the whole suite, as the README
runs it). Each test's CPU is counted twice over: its own process's (user + system) and that of the children it
waited for (players, encoders, browsers, command-line runs). At the end the plugin prints the files that took
the most, and the whole, and writes every test's numbers to ``output/suite_cpu.json``. A child still running
when a test ends (a browser kept for a module) is counted with the test that waits for it.
"""

from __future__ import annotations

import json
import resource
import time
from collections import defaultdict
from pathlib import Path
from typing import Any, Iterator

import pytest

_ROWS: list[tuple[str, float, float, float]] = []  # node id, own CPU s, children's CPU s, wall s
_SHOWN = 25  # files printed, the costliest first


def _cpu() -> tuple[float, float]:
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime, children.ru_utime + children.ru_stime


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None) -> Iterator[None]:
    before, started = _cpu(), time.perf_counter()
    yield
    after = _cpu()
    _ROWS.append((item.nodeid, after[0] - before[0], after[1] - before[1], time.perf_counter() - started))


def pytest_terminal_summary(terminalreporter: Any) -> None:
    by_file: dict[str, list[float]] = defaultdict(lambda: [0.0, 0.0, 0.0, 0.0])
    for node, own, children, wall in _ROWS:
        row = by_file[node.split("::")[0]]
        row[0] += own
        row[1] += children
        row[2] += wall
        row[3] += 1
    write = terminalreporter.write_line
    own, children = sum(r[1] for r in _ROWS), sum(r[2] for r in _ROWS)
    write(f"suite CPU: {own + children:.1f} s over {len(_ROWS)} tests ({own:.1f} in pytest's process, "
          f"{children:.1f} in children it waited for); the costliest files:")
    write(f"{'CPU s':>8} {'own':>8} {'children':>9} {'wall s':>8} {'tests':>6}  file")
    for name, (mine, theirs, wall, count) in sorted(by_file.items(), key=lambda kv: -(kv[1][0] + kv[1][1]))[:_SHOWN]:
        write(f"{mine + theirs:8.1f} {mine:8.1f} {theirs:9.1f} {wall:8.1f} {int(count):6d}  {name}")
    target = Path("output") / "suite_cpu.json"
    target.parent.mkdir(exist_ok=True)
    target.write_text(json.dumps([{"test": n, "cpu": o, "children_cpu": c, "wall": w} for n, o, c, w in _ROWS]))
    write(f"every test: {target}")
