"""CPU seconds and peak memory of ``stats`` and ``report`` on seeded pairs of the shipped icons.

    python benchmarks/bench_analysis.py [--pairs 50] [--seed 1] [--commands stats,report]
                                        [--pair A.svg B.svg] [--code DIR] [--json-out DIR]

Draws ``--pairs`` seeded ordered pairs of different icons from ``tests/data/icons/<set>/*.svg`` (or
measures the one ``--pair`` given) and runs ``tweenrender stats A.svg B.svg --json`` and ``tweenrender
report A.svg B.svg -o <scratch>`` on each, one fresh process a run, as a user would. Each run's CPU
seconds (user + sys of the command and every process it started, ffmpeg included) and its peak
resident memory (the largest single process among them, from the kernel's ``wait4`` accounting) are
printed with the 1-minute load average when it ended; then, per command, the median, the worst pair
(named) and how many pairs stay within the targets (``stats`` ≤ 3 CPU s, ``report`` ≤ 10 CPU s, either
≤ 400 MiB). The package's bytecode is compiled first, as an install does. ``--code DIR`` runs another
copy of the package (``PYTHONPATH=DIR``), to measure a change against the code before it; ``--json-out
DIR`` keeps each pair's ``stats --json``, to diff two copies'.
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path
from typing import NamedTuple

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
ICONS = ROOT / "tests" / "data" / "icons"
TARGETS = {"stats": 3.0, "report": 10.0}
"""CPU seconds a pair may take, per command."""
PEAK_MIB = 400.0


class Run(NamedTuple):
    cpu: float
    """User + sys CPU seconds of the command and its children."""
    peak_mib: float
    """The largest resident set of any one of its processes."""
    load: float
    """The 1-minute load average when it ended."""
    code: int


def shipped_icons() -> list[Path]:
    """Every SVG of the shipped icon sets, in a fixed order."""
    return sorted(ICONS.glob("*/*.svg"))


def sample_pairs(count: int, seed: int) -> list[tuple[Path, Path]]:
    """``count`` ordered pairs of different shipped icons, drawn with ``seed``, no pair twice."""
    icons = shipped_icons()
    rng = np.random.default_rng(seed)
    pairs: list[tuple[Path, Path]] = []
    while len(pairs) < min(count, len(icons) * (len(icons) - 1)):
        a, b = rng.choice(len(icons), size=2, replace=False)
        pair = (icons[int(a)], icons[int(b)])
        if pair not in pairs:
            pairs.append(pair)
    return pairs


def run(command: list[str], code: Path, scratch: Path, stdout: Path | None = None) -> Run:
    """``python -m tweenrender *command`` in a fresh process, measured (run in ``scratch``: ``-m`` puts the
    current folder first on the path, which must not be another copy of the package)."""
    env = {**os.environ, "PYTHONPATH": str(code.resolve())}
    out = open(stdout, "wb") if stdout is not None else subprocess.DEVNULL
    try:
        process = subprocess.Popen([sys.executable, "-m", "tweenrender", *command], env=env, stdout=out,
                                   stderr=subprocess.PIPE, cwd=scratch)
        _, status, usage = os.wait4(process.pid, 0)
        process.returncode = os.waitstatus_to_exitcode(status)
        assert process.stderr is not None
        error = process.stderr.read().decode(errors="replace").strip()
    finally:
        if stdout is not None:
            out.close()  # type: ignore[union-attr]
    if process.returncode != 0:
        print(f"    exit {process.returncode}: {error[-300:]}", file=sys.stderr)
    return Run(usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024, os.getloadavg()[0], process.returncode)


def measure(pair: tuple[Path, Path], commands: list[str], code: Path, json_out: Path | None) -> dict[str, Run]:
    """Each command on one pair."""
    a, b = pair[0].resolve(), pair[1].resolve()
    found = {}
    with tempfile.TemporaryDirectory(prefix="tweenrender-analysis-") as name:
        scratch = Path(name)
        for command in commands:
            if command == "stats":
                target = json_out / f"{a.parent.name}-{a.stem}--{b.parent.name}-{b.stem}.json" if json_out else None
                found[command] = run(["stats", str(a), str(b), "--json"], code, scratch, target)
            else:
                found[command] = run(["report", str(a), str(b), "-o", str(scratch / "report"), "-q"], code, scratch)
    return found


def installed_bytecode(code: Path) -> None:
    """Compile the package's bytecode in ``code``, as ``pip install`` does: each run then loads it, as an
    installed package's does, however ``PYTHONDONTWRITEBYTECODE`` is set (it stops writing, not reading),
    rather than compiling every module it imports from source (0.3–0.4 CPU s a run on this machine)."""
    import compileall

    compileall.compile_dir(str(code / "tweenrender"), quiet=1)


def name(pair: tuple[Path, Path]) -> str:
    return " -> ".join(f"{p.parent.name}/{p.stem}" for p in pair)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", type=int, default=50)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--commands", default="stats,report")
    parser.add_argument("--pair", nargs=2, metavar="SVG", help="measure this pair only")
    parser.add_argument("--code", type=Path, default=ROOT, help="the copy of the package to run (default this one)")
    parser.add_argument("--json-out", type=Path, help="keep each pair's stats --json in this folder")
    args = parser.parse_args()
    commands = [c for c in args.commands.split(",") if c]
    pairs = [(Path(args.pair[0]), Path(args.pair[1]))] if args.pair else sample_pairs(args.pairs, args.seed)
    if args.json_out:
        args.json_out = args.json_out.resolve()
        args.json_out.mkdir(parents=True, exist_ok=True)
    installed_bytecode(args.code)
    print(f"code {args.code}; {len(pairs)} pairs (seed {args.seed}); nproc {os.cpu_count()}; "
          f"load at start {os.getloadavg()[0]:.2f}")
    results: list[tuple[tuple[Path, Path], dict[str, Run]]] = []
    for k, pair in enumerate(pairs):
        found = measure(pair, commands, args.code, args.json_out)
        results.append((pair, found))
        print(f"{k + 1:3d} {name(pair):60s} " + "  ".join(
            f"{c} {r.cpu:6.2f} CPU s {r.peak_mib:5.0f} MiB (load {r.load:.1f})" + ("" if r.code == 0 else " FAILED")
            for c, r in found.items()), flush=True)
    print()
    for command in commands:
        runs = [(pair, found[command]) for pair, found in results]
        cpu = [r.cpu for _, r in runs]
        worst_pair, worst = max(runs, key=lambda item: item[1].cpu)
        heaviest_pair, heaviest = max(runs, key=lambda item: item[1].peak_mib)
        within = sum(r.cpu <= TARGETS[command] and r.peak_mib <= PEAK_MIB for _, r in runs)
        print(f"{command}: median {statistics.median(cpu):.2f} CPU s, total {sum(cpu):.1f}; worst {worst.cpu:.2f} CPU s "
              f"({name(worst_pair)}); peak {heaviest.peak_mib:.0f} MiB ({name(heaviest_pair)}); "
              f"{within}/{len(runs)} pairs within {TARGETS[command]:g} CPU s and {PEAK_MIB:g} MiB; "
              f"failed {sum(r.code != 0 for _, r in runs)}")
    print(f"load at end {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
