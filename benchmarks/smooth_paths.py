"""Whether injective vertex paths turn corners, on seeded random pairs of held-out icons.

For each pair (drawn as ``bench_inbetweens.py --holdout`` draws them), the pair's contours from
``tweenrender.contours(scene, t, method="injective", points=True)`` (each element's contours in their
order, whatever order the elements are drawn in) at ``--frames`` steps over the segment and at twice as
many. At each frame, the angle each vertex's path turns through between its two steps, 90th percentile
over the vertices that move (more than 1/1000 of the drawing's size a step); then the worst frame. A
smooth path turns about half as sharply sampled twice as finely; a corner turns through its whole angle
however finely it is sampled. A pair's *ratio* compares the fine sampling (the three fine frames about
each coarse one) with the coarse, from the second sixteenth of the segment to the fifteenth (next to a
key the chain of grid points from the other key comes in, a tight bend); a pair is *cornered* above 0.7.

Run: ``python benchmarks/smooth_paths.py [--seed 5] [--pairs 25] [--frames 48] [--only NAME]``
(``--only``: pairs whose name holds NAME, with the times of their sharpest turns).
"""

from __future__ import annotations

import argparse
import signal
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import tweenrender as tr  # noqa: E402
from bench_inbetweens import holdout_icons, sample_pairs  # noqa: E402

CORNERED = 0.7
_DEADLINE = 120  # seconds a pair may take


def turns(scene: tr.Scene, frames: int) -> tuple[np.ndarray, np.ndarray] | None:
    """Each inner frame's 90th-percentile turn (radians) and its t, two ``(frames - 3,)``; None where the
    vertex count changes over the segment."""
    t = np.arange(1, frames) / frames
    drawn = [sorted(tr.contours(scene, float(s), method="injective", points=True), key=lambda c: c.element)
             for s in t]  # the drawing order of the elements may change mid-way; their own contours' does not
    if len({sum(len(c.points) for c in frame) for frame in drawn}) != 1:
        return None
    paths = np.stack([np.concatenate([c.points for c in frame]) for frame in drawn])  # (T, V, 2)
    steps = np.diff(paths, axis=0)
    size = float(np.ptp(paths.reshape(-1, 2), axis=0).max())
    a, b = steps[:-1], steps[1:]
    least = 1e-3 * size / frames
    moving = (np.linalg.norm(a, axis=-1) > least) & (np.linalg.norm(b, axis=-1) > least)
    turn = np.abs(np.arctan2(a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0], np.sum(a * b, axis=-1)))
    worst = np.array([np.percentile(row[keep], 90) if keep.any() else 0.0 for row, keep in zip(turn, moving)])
    return worst, t[1:-1]


def _ring(signum: int, frame: object) -> None:
    raise TimeoutError


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=5)
    parser.add_argument("--pairs", type=int, default=25)
    parser.add_argument("--frames", type=int, default=48)
    parser.add_argument("--only", default=None)
    args = parser.parse_args()
    sets = holdout_icons()
    if sets is None:
        print("npm is not available (or fetched nothing) and no icon package is cached: nothing held out")
        return 2
    pairs = sample_pairs(sets, args.pairs, np.random.default_rng([args.seed, 0x401D]), by_set=True)
    signal.signal(signal.SIGALRM, _ring)
    ratios = []
    for a, b in pairs:
        name = f"{a.parent.name}/{a.stem} -> {b.parent.name}/{b.stem}"
        if args.only and args.only not in name:
            continue
        signal.alarm(_DEADLINE)
        try:
            scene = tr.load_scene([a, b])
            coarse, fine = turns(scene, args.frames), turns(scene, 2 * args.frames)
        except (Exception, TimeoutError) as error:  # a pair the loader refuses, or one past the deadline
            print(f"{name:72} skipped: {type(error).__name__}")
            continue
        finally:
            signal.alarm(0)
        if coarse is None or fine is None:
            print(f"{name:72} skipped: its vertex count changes")
            continue
        (worst, at), (finer, _) = coarse, fine
        count = len(worst)
        near = np.max(np.stack([finer[k::2][:count] for k in (1, 2, 3)]), axis=0)  # coarse frame i is fine 2i + 2
        inner = (at > 1 / 16) & (at < 15 / 16)
        c, f = float(worst[inner].max()), float(near[inner].max())
        if c <= 1e-9:
            print(f"{name:72} still")
            continue
        ratios.append(f / c)
        print(f"{name:72} coarse {c:.3f} fine {f:.3f} ratio {f / c:.2f}", flush=True)
        if args.only:
            print("  sharpest, coarse:", [(round(float(at[i]), 3), round(float(worst[i]), 2)) for i in np.argsort(-worst)[:6]])
            print("  sharpest, fine:  ", [(round(float(at[i]), 3), round(float(near[i]), 2)) for i in np.argsort(-near)[:6]])
    if ratios:
        r = np.array(ratios)
        print(f"{len(r)} pairs: ratio median {np.median(r):.2f}; cornered (ratio > {CORNERED}) {int((r > CORNERED).sum())}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
