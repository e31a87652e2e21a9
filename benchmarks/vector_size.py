"""How compact the vector outputs are, and how close (maths §5.12).

For every shipped scene and a few icon pairs, per method, at the default bound (0.25 output
pixels): path keyframes against frames drawn (summed over every layer: a run of frames of one
element in one segment), the Lottie and SVG bytes against the same files with a keyframe at every
frame, and the worst deviation measured at any frame and vertex between the played keyframes (as
the files hold them, rounded to a thousandth of a pixel; straight lines through each span's
cubic-bezier timing, found here by bisection) and the exact inbetween. Curved methods should export
at least 2× fewer path keyframes than frames.

Run: ``python benchmarks/vector_size.py [--methods linear,rigid] [--quick]``
"""

from __future__ import annotations

import argparse
import os
import sys
from dataclasses import replace
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import tweenrender as tr  # noqa: E402
from tweenrender.encode.animated_svg import svg_document  # noqa: E402
from tweenrender.encode.lottie import lottie_document  # noqa: E402
from tweenrender.encode.vector_data import STRAIGHT, VectorClip, VectorRun  # noqa: E402
from tweenrender.core.methods.registry import METHODS  # noqa: E402
from tweenrender.pipeline.library import render_job  # noqa: E402
from tweenrender.plan.options import RenderOptions  # noqa: E402
from tweenrender.vector.export import vector_clip  # noqa: E402
from tests.vector_players import bezier_timing  # noqa: E402

ICONS = ROOT / "tests" / "data" / "icons"
ICON_PAIRS = [("mdi/alpha-a.svg", "mdi/alpha-b.svg"), ("feather/heart.svg", "feather/star.svg"),
              ("twemoji/1f600.svg", "twemoji/1f60e.svg"), ("lucide/moon.svg", "lucide/sun.svg")]


def played(run: VectorRun) -> np.ndarray:
    """What a player draws at every frame of ``run`` from its keyframes as written (pixels to a
    thousandth): ``(stop - first, sum L_i, 2)``."""
    keys = np.array(run.path_frames)
    values = np.round(np.concatenate(run.paths, axis=1), 3)  # (K, sum L, 2)
    frames = np.arange(run.first, run.stop)
    index = np.clip(np.searchsorted(keys, frames, side="right") - 1, 0, len(keys) - 1)
    following = np.minimum(index + 1, len(keys) - 1)
    span = np.maximum(keys[following] - keys[index], 1)
    eases = np.array([*run.eases, STRAIGHT])[index]  # (T, 4): each frame's span
    s = bezier_timing(np.clip((frames - keys[index]) / span, 0.0, 1.0), eases)
    return values[index] + s[:, None, None] * (values[following] - values[index])


def every_frame(clip: VectorClip) -> VectorClip:
    """``clip`` with a path keyframe at every frame of every run (paint as it was)."""
    runs = []
    for run in clip.runs:
        cuts = np.cumsum([p.shape[1] for p in run.paths])[:-1]
        paths = tuple(np.split(run.exact_frames, cuts, axis=1))
        runs.append(replace(run, path_frames=tuple(range(run.first, run.stop)), paths=paths,
                            eases=(STRAIGHT,) * (run.stop - run.first - 1)))
    return replace(clip, runs=tuple(runs))


def sizes(clip: VectorClip) -> tuple[int, int]:
    import json

    lottie = json.dumps(lottie_document(clip), separators=(",", ":"))
    return len(lottie.encode()), len(svg_document(clip).encode())


def measure(scene: tr.Scene, method: str) -> dict[str, float]:
    clip = vector_clip(render_job(scene, RenderOptions.create(method=method)))
    keys = sum(len(r.path_frames) for r in clip.runs if r.paths)
    frames = sum(r.stop - r.first for r in clip.runs if r.paths)
    worst = max((float(np.linalg.norm(played(r) - r.exact_frames, axis=-1).max()) for r in clip.runs
                 if r.exact_frames.shape[1]), default=0.0)
    lottie, svg = sizes(clip)
    lottie_all, svg_all = sizes(every_frame(clip))
    return {"keys": keys, "frames": frames, "worst": worst, "lottie": lottie, "lottie_all": lottie_all, "svg": svg,
            "svg_all": svg_all}


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--methods", default=",".join(METHODS))
    parser.add_argument("--quick", action="store_true", help="the shipped scenes only")
    args = parser.parse_args()
    methods = [m for m in args.methods.split(",") if m]
    subjects: list[tuple[str, tr.Scene]] = [(p.stem, tr.load_scene(p))
                                            for p in sorted((ROOT / "scenes").glob("*.toml"))]
    shipped = len(subjects)
    if not args.quick:
        subjects += [(f"{a.split('/')[0]}:{Path(a).stem}>{Path(b).stem}", tr.load_scene([ICONS / a, ICONS / b]))
                     for a, b in ICON_PAIRS]
    print(f"load {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; bound 0.25 px")
    print(f"{'subject':32} {'method':17} {'keys':>5} {'frames':>6} {'ratio':>6} {'worst px':>8} "
          f"{'lottie B':>9} {'every fr.':>9} {'svg B':>8} {'every fr.':>9}")
    failed = False
    for method in methods:
        totals = {"keys": 0, "frames": 0, "worst": 0.0}
        for index, (name, scene) in enumerate(subjects):
            row = measure(scene, method)
            ratio = row["frames"] / max(row["keys"], 1)
            print(f"{name:32} {method:17} {row['keys']:5d} {row['frames']:6d} {ratio:6.2f} {row['worst']:8.5f} "
                  f"{row['lottie']:9d} {row['lottie_all']:9d} {row['svg']:8d} {row['svg_all']:9d}")
            if index < shipped:
                totals["keys"] += row["keys"]
                totals["frames"] += row["frames"]
            totals["worst"] = max(totals["worst"], row["worst"])
        ratio = totals["frames"] / max(totals["keys"], 1)
        verdict = "" if method == "linear" else ("  (≥ 2× fewer: yes)" if ratio >= 2 else "  (≥ 2× fewer: NO)")
        failed |= method != "linear" and ratio < 2
        print(f"{'shipped scenes, all':32} {method:17} {totals['keys']:5d} {totals['frames']:6d} {ratio:6.2f} "
              f"{totals['worst']:8.5f}{verdict}")
        print()
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main())
