"""How compact the vector outputs are, and how close (maths §5.12).

For every shipped scene and ``--pairs`` seeded random pairs of shipped icons (drawn as
``bench_inbetweens.py`` draws them), at the scene's own method and the default bound (0.25 output
pixels): the Lottie, dotLottie and animated-SVG bytes against the MP4 of the same clip and against the
two source SVGs (a pair's), path keyframes against frames drawn (summed over every layer: a run of frames
of one element in one segment), and the worst replayed error: each contour's cubic Bézier path as the
file holds it (pixels to a hundredth, tangents relative to their vertex), vertices and tangents moved
straight between keyframes through each span's cubic-bezier timing (bisection), drawn from the cubic's
closed form and measured against the exact in-between polyline (shapely's Hausdorff distance, both
ways) at every frame. ``--methods`` adds the keyframes per method on the same subjects.

Targets: the Lottie (and the animated SVG) at most the MP4's size for every subject, and at most 6× the two sources at the
median over the pairs; the worst replayed error at most 0.25 px (plus the files' rounding).

Run: ``python benchmarks/vector_size.py [--pairs 20] [--seed 1] [--methods linear,rigid,...] [--quick]``
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
from pathlib import Path

import numpy as np
import shapely

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(ROOT / "benchmarks"))

import tweenrender as tr  # noqa: E402
from tweenrender.encode.animated_svg import svg_document  # noqa: E402
from tweenrender.encode.lottie import lottie_document  # noqa: E402
from tweenrender.encode.vector_data import HANDLE_DIGITS, PIXEL_DIGITS, SCALE_DIGITS, STRAIGHT, VectorClip, VectorRun  # noqa: E402
from tweenrender.pipeline.library import render_job  # noqa: E402
from tweenrender.plan.options import RenderOptions  # noqa: E402
from tweenrender.vector.export import vector_clip  # noqa: E402
from bench_inbetweens import sample_pairs, shipped_icons  # noqa: E402
from tests.vector_players import bezier_timing  # noqa: E402

_DRAWN = 32  # points of each cubic span the replay draws, at least
_STEP = 2.0  # pixels at most between them (by the longest span's control polygon): the drawing is the cubic's


def _as_written(points: np.ndarray) -> np.ndarray:
    """A path ``(K, M, 3, 2)`` (or straight ``(K, L, 2)``) as the files hold it: vertices to ``PIXEL_DIGITS``
    decimals, control points their vertex plus an offset to as many: ``(K, M, 3, 2)``."""
    if points.ndim == 3:
        points = points[:, :, None].repeat(3, axis=2)
    vertex = np.round(points[:, :, 1:2], PIXEL_DIGITS)
    return vertex + np.round(points - points[:, :, 1:2], PIXEL_DIGITS)


def _draw(curve: np.ndarray, closed: bool) -> np.ndarray:
    """The points a cubic Bézier contour ``(M, 3, 2)`` draws: ``(P, 2)``."""
    count = len(curve)
    ends = [(k, k + 1) for k in range(count - 1)] + ([(count - 1, 0)] if closed and count > 1 else [])
    if not ends:
        return curve[:, 1]
    polygon = max(float(np.linalg.norm(np.diff(np.array([curve[a, 1], curve[a, 2], curve[b, 0], curve[b, 1]]), axis=0),
                                       axis=1).sum()) for a, b in ends)
    u = np.linspace(0.0, 1.0, max(_DRAWN, int(np.ceil(polygon / _STEP)) + 1))[:, None]
    return np.concatenate([(1 - u) ** 3 * curve[a, 1] + 3 * (1 - u) ** 2 * u * curve[a, 2]
                           + 3 * (1 - u) * u ** 2 * curve[b, 0] + u ** 3 * curve[b, 1] for a, b in ends])


def _keyed(frames: np.ndarray, keys: tuple[int, ...], values: np.ndarray, eases: tuple) -> np.ndarray:
    """Values ``(K, …)`` keyed at ``keys``, played straight between keyframes through each span's cubic-bezier
    timing at clip ``frames (T,)``: ``(T, …)``."""
    keys_at = np.array(keys)
    index = np.clip(np.searchsorted(keys_at, frames, side="right") - 1, 0, len(keys_at) - 1)
    following = np.minimum(index + 1, len(keys_at) - 1)
    span = np.maximum(keys_at[following] - keys_at[index], 1)
    timing = np.round(np.array([*eases, STRAIGHT]), HANDLE_DIGITS)[index]  # as written
    s = bezier_timing(np.clip((frames - keys_at[index]) / span, 0.0, 1.0), timing)
    s = s.reshape(-1, *([1] * (values.ndim - 1)))
    return values[index] + s * (values[following] - values[index])


def _played(frames: np.ndarray, keys: tuple[int, ...], path: np.ndarray, eases: tuple) -> np.ndarray:
    """A path's keyframes ``(K, …)`` as written, played at clip ``frames (T,)``: ``(T, M, 3, 2)``."""
    return _keyed(frames, keys, _as_written(path), eases)


def replayed_error(run: VectorRun, own: bool | str) -> float:
    """The worst distance, over the run's frames and contours, between the curves played from the keyframes
    as written (``own``: each contour's own, as the Lottie holds them; ``"pieces"``: as the SVG draws them where it
    draws the run's pieces apart, ``VectorRun.drawn_keys``; else the run's, as the SVG draws one path) and the
    exact in-between polylines."""
    frames = np.arange(run.first, run.stop)
    worst = 0.0
    for i, (closed, exact) in enumerate(zip(run.closed, run.exact_contours())):
        keys, path, eases, move = (*run.keys_of(i), run.move_of(i)) if own is True else \
            run.drawn_keys(i) if own == "pieces" else (run.path_frames, run.paths[i], run.eases, None)
        if move is not None and own is not True:  # the SVG writes the still path about the anchor, the anchor not at all
            path = path - move.anchor
        played = _played(frames, keys, path, eases)
        if move is not None:  # a still path placed by its keyed position and scale, as written
            anchor = np.round(move.anchor, PIXEL_DIGITS) if own is True else np.zeros(2)
            place = _keyed(frames, move.frames, np.round(move.centres, PIXEL_DIGITS), move.eases)  # (T, 2)
            scale = _keyed(frames, move.frames, np.round(move.scales * 100, SCALE_DIGITS) / 100, move.eases)  # (T,)
            played = place[:, None, None] + scale[:, None, None, None] * (played - anchor)
        for f in range(len(frames)):
            drawn = _draw(played[f], closed)
            line = np.concatenate([exact[f], exact[f][:1]]) if closed else exact[f]
            geometries = [shapely.LineString(p) if len(p) > 1 else shapely.Point(p[0]) for p in (drawn, line)]
            worst = max(worst, float(shapely.hausdorff_distance(*geometries, densify=0.1)))
    return worst


def _bytes(clip: VectorClip, folder: Path) -> dict[str, int]:
    lottie = json.dumps(lottie_document(clip), separators=(",", ":")).encode()
    return {"lottie": len(lottie), "svg": len(svg_document(clip).encode())}


def measure(scene: tr.Scene, method: str | None, folder: Path, video: bool = True) -> dict[str, float]:
    """Sizes, keyframes and the worst replayed error of ``scene`` at ``method`` (``None``: its own)."""
    options = RenderOptions.create(method=method) if method else RenderOptions.create()
    clip = vector_clip(render_job(scene, options))
    row: dict[str, float] = {
        "keys": sum(len(r.path_frames) for r in clip.runs if r.paths),
        "frames": sum(r.stop - r.first for r in clip.runs if r.paths),
        **_bytes(clip, folder)}
    if video:
        named = {"method": method} if method else {}
        row["mp4"] = tr.write(scene, folder / "clip.mp4", **named).stat().st_size
        row["dotlottie"] = tr.write(scene, folder / "clip.lottie", **named).stat().st_size
        row["worst"] = max((replayed_error(r, own) for r in clip.runs if r.paths for own in (True, False, "pieces")),
                           default=0.0)
    return row


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--pairs", type=int, default=20)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--methods", default="", help="comma-separated: keyframes per method as well")
    parser.add_argument("--quick", action="store_true", help="the shipped scenes only")
    args = parser.parse_args()
    subjects: list[tuple[str, tr.Scene, int | None]] = [
        (p.stem, tr.load_scene(p), None) for p in sorted((ROOT / "scenes").glob("*.toml"))]
    if not args.quick:
        rng = np.random.default_rng([args.seed, 0])
        for a, b in sample_pairs(shipped_icons(), args.pairs, rng, by_set=False):
            name = f"{a.parent.name}:{a.stem}>{b.parent.name}:{b.stem}"
            try:
                subjects.append((name, tr.load_scene([a, b]), a.stat().st_size + b.stat().st_size))
            except tr.TweenrenderError as error:
                print(f"{name}: not loaded ({error})", file=sys.stderr)
    print(f"load {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores; bound 0.25 px; the scene's own method")
    print(f"{'subject':44} {'keys':>5} {'frames':>6} {'lottie B':>9} {'.lottie':>8} {'svg B':>8} {'mp4 B':>8} "
          f"{'L/mp4':>6} {'S/mp4':>6} {'L/src':>6} {'worst px':>8}")
    over_video, svg_video, svg_sources, to_sources, worst = [], [], [], [], 0.0
    with tempfile.TemporaryDirectory() as scratch:
        folder = Path(scratch)
        for name, scene, sources in subjects:
            try:
                row = measure(scene, None, folder)
            except tr.TweenrenderError as error:
                print(f"{name:44} refused: {error}")
                continue
            by_video = row["lottie"] / row["mp4"]
            over_video.append(by_video)
            svg_video.append((name, row["svg"] / row["mp4"]))
            worst = max(worst, row["worst"])
            by_sources = f"{row['lottie'] / sources:6.2f}" if sources else f"{'-':>6}"
            if sources:
                to_sources.append(row["lottie"] / sources)
                svg_sources.append(row["svg"] / sources)
            print(f"{name[:44]:44} {row['keys']:5.0f} {row['frames']:6.0f} {row['lottie']:9.0f} "
                  f"{row['dotlottie']:8.0f} {row['svg']:8.0f} {row['mp4']:8.0f} {by_video:6.2f} "
                  f"{row['svg'] / row['mp4']:6.2f} {by_sources} {row['worst']:8.4f}")
        print()
        print(f"Lottie / MP4: max {max(over_video):.2f} (target ≤ 1 for every subject: "
              f"{'yes' if max(over_video) <= 1 else 'NO'}); worst replayed error {worst:.4f} px")
        over = [name for name, ratio in svg_video if ratio > 1]
        print(f"animated SVG / MP4: max {max(r for _, r in svg_video):.2f} (target ≤ 1 for every subject: "
              f"{'yes' if not over else 'NO, ' + ', '.join(over)})")
        if to_sources:
            median = float(np.median(to_sources))
            print(f"Lottie / the two sources over {len(to_sources)} pairs: median {median:.2f} "
                  f"(target ≤ 6: {'yes' if median <= 6 else 'NO'}), max {max(to_sources):.2f}; "
                  f"animated SVG: median {float(np.median(svg_sources)):.2f}")
        methods = [m for m in args.methods.split(",") if m]
        if methods:
            print()
            print(f"{'keyframes / frames drawn':44} " + " ".join(f"{m:>16}" for m in methods))
            for name, scene, _ in subjects:
                cells = []
                for method in methods:
                    try:
                        row = measure(scene, method, folder, video=False)
                        cells.append(f"{row['keys']:.0f}/{row['frames']:.0f}")
                    except tr.TweenrenderError:
                        cells.append("refused")
                print(f"{name[:44]:44} " + " ".join(f"{c:>16}" for c in cells))
    return 0 if over_video and max(over_video) <= 1 and (not to_sources or np.median(to_sources) <= 6) else 1


if __name__ == "__main__":
    raise SystemExit(main())
