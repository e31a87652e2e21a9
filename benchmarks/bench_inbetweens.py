"""In-betweens of real drawing pairs, measured with shapely (not with the package's own measures).

    python benchmarks/bench_inbetweens.py [--pairs 120] [--seed 1] [--methods default,linear,...]
                                          [--jobs 1] [--sheets] [--holdout] [--timeout 180]

Draws ``--pairs`` seeded random ordered pairs of different icons from ``tests/data/icons/<set>/*.svg``
(``--holdout``: from icon packages fetched with ``npm pack`` into ``~/.cache/tweenrender-bench/``, the
shipped icons left out, sampled in a seed space of their own), loads each pair as
``tweenrender.load_scene([a, b], step=1.0)`` (what ``tweenrender render a.svg b.svg`` draws) and, per
method (``default`` is the scene's own, what ``render`` draws without ``--method``), takes
``tweenrender.contours`` at t = 0.05, 0.10, ... 0.95 and measures:

* **tangles** (closed): within one element, a closed contour self-crossing though simple in both
  keys; a hole (inside an odd number of the element's other closed contours in both keys, with the
  same innermost parent in both) with a vertex outside its parent; two contours of the element whose
  boundaries are apart in both keys but intersect at t. Crossings that involve an open stroke (its own
  or with another contour) are counted apart, as **stroke tangles**. Keys are read at t = 1e-6 and
  1 - 1e-6, so elements growing from or shrinking to nothing keep their contours.
* **stray**: the share of the drawn area at t (fills by their fill rule, from winding numbers of the
  faces of the noded contours, united with stroke bands of half the stroke width) lying farther than
  12 % of the view's larger side from both keys' drawn areas; p95 and max over every frame. Paint counts
  as drawn from alpha x opacity 0.1 (unmatched elements fade in and out).
* **area deviation**: ``|area(t) - lerp(area0, area1, t)| / max(area0, area1)`` of the whole drawing; p90.
* **pops**: the rendered frames of the clip (0..24 at 24 fps, 200 px on the longer side, transparent
  background); a frame's change is the mean over the pixels of ``|alpha(f) - alpha(f - 1)|`` (the share of
  the view whose coverage changed, alpha-weighted so fades are gradual); a pop is a change over 3x the
  clip's median change and over 0.002 of the view's area. A smooth but uneven change (fast early shrinking,
  a U-shaped curve) passes that test on many frames, so **spikes** are counted too: changes over 3x both
  neighbouring changes and over 0.002 of the view. **net pops** apply the same test to the change of the
  whole drawing's coverage (``|mean alpha(f) - mean alpha(f - 1)|``), the measure of earlier versions of
  this benchmark: there a shape shrinking where another grows cancels, so the median is small and steady
  frames where the two do not overlap count as pops. **colour pops** apply the pop test to the change of the
  picture as seen over white (the mean over the pixels and channels of ``|RGB(f) - RGB(f - 1)| / 255``): a
  colour that jumps between two frames (a gradient stop turning transparent), which coverage cannot see.
* **distortion**: per element and frame, with ``r`` = ``log(l_t / l_lerp)`` for each edge of its contours
  (``l_t`` its length at t, ``l_lerp`` the linear blend of its lengths in the two keys; edges whose blend
  is under 1e-4 of the view are left out), the length-weighted mean of ``|r - mean r|``: the element's
  change of size (growing with area linear in t, a linear turn's shrinking) is taken out, so any
  similarity motion scores 0 and uneven stretching, kinks and crumpling score above 0 (0.1 is an edge
  about 10 % longer or shorter than the rest); p90 over every element-frame.

The table's ``seconds`` are each method's time to give the contours measured (keys and 19 in-betweens),
summed over pairs; "tangled pairs/frames" are pairs with at least one tangled in-between / tangled
in-betweens in all. Pairs the loader refuses are counted and listed. Prints one table (per method), the worst 8 pairs per
method by stray and by tangled frames, and writes per-pair results to
``output/bench_inbetweens/results.json`` (``results_holdout.json`` for ``--holdout``). ``--sheets`` writes
contact sheets (``sheet_*.png``, at most 20 pairs each): a row per pair, columns t = 0, .25, .5, .75, 1 per
method. ``--jobs J`` measures pairs in J processes. The shapely measures are in ``inbetween_geometry.py``.
A few pairs with intricate paths (``simple-icons/github``) take most of the time: 120 pairs with the default
methods and ``--sheets`` take about 10 minutes of CPU (11 minutes with ``--jobs 2`` on a busy 2-core machine).
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import signal
import subprocess
import sys
import tarfile
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from contextlib import contextmanager
from multiprocessing import get_context
from pathlib import Path
from typing import Any, Iterator, Sequence

import numpy as np
import shapely
from shapely.geometry.base import BaseGeometry

sys.path.insert(0, str(Path(__file__).resolve().parent))
from inbetween_geometry import drawn_area, element_distortion, element_structure, element_tangles, group  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
ICONS = ROOT / "tests" / "data" / "icons"
OUT = ROOT / "output" / "bench_inbetweens"
CACHE = Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache")) / "tweenrender-bench"

TIMES = tuple(round(0.05 * k, 2) for k in range(1, 20))
SHEET_TIMES = (0.0, 0.25, 0.5, 0.75, 1.0)
KEY_EPS = 1e-6
STRAY_SHARE = 0.12
POP_RATIO, POP_FLOOR = 3.0, 0.002
POP_SIDE = 200  # pixels of the longer side of the frames whose coverage is compared for pops
TILE = 160
ROWS_PER_SHEET = 20
DEFAULT_METHODS = ("default", "linear", "nonlinear", "injective", "arap")

# npm package -> (folders of its SVGs inside the tarball, the shipped set made from it)
HOLDOUT_PACKAGES: dict[str, tuple[tuple[str, ...], str]] = {
    "@tabler/icons": (("icons/outline", "icons/filled"), "tabler"),
    "bootstrap-icons": (("icons",), "bootstrap"),
    "lucide-static": (("icons",), "lucide"),
    "@mdi/svg": (("svg",), "mdi"),
    "simple-icons": (("icons",), "simple-icons"),
    "heroicons": (("24/solid", "24/outline"), "heroicons"),
    "feather-icons": (("dist/icons",), "feather"),
    "@primer/octicons": (("build/svg",), "octicons"),
    "@twemoji/svg": (("",), "twemoji"),
}


# -- one pair --------------------------------------------------------------------------------------


class Timeout(Exception):
    pass


@contextmanager
def deadline(seconds: float) -> Iterator[None]:
    """Raise :class:`Timeout` after ``seconds`` (SIGALRM; checked when Python code runs)."""
    if seconds <= 0 or not hasattr(signal, "SIGALRM"):
        yield
        return

    def ring(signum: int, frame: Any) -> None:
        raise Timeout(f"over {seconds:g} s")

    previous = signal.signal(signal.SIGALRM, ring)
    signal.setitimer(signal.ITIMER_REAL, seconds)
    try:
        yield
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)


def _view(scene: Any, keys: Sequence[Sequence[Any]]) -> tuple[float, float]:
    """The view's width and height in scene units (the keys' bounds when the scene has no view)."""
    if scene.view is not None:
        x0, y0, x1, y1 = scene.view
        return abs(x1 - x0), abs(y1 - y0)
    pts = np.vstack([c.points for key in keys for c in key])
    w, h = np.ptp(pts, axis=0)
    return float(w), float(h)


def pop_frames(tr: Any, scene: Any, method: str | None, view: tuple[float, float]) -> np.ndarray:
    """Every frame of the clip at the scene's rate on a transparent background, straight RGBA in [0, 1]:
    ``(F, height, width, 4)``."""
    scale = POP_SIDE / max(view)
    size = (max(8, round(view[0] * scale)), max(8, round(view[1] * scale)))
    return np.stack([img.astype(np.float32) / 255.0
                     for img in tr.frames(scene, method=method, size=size, background="none")])


def over_white(frames: np.ndarray) -> np.ndarray:
    """Straight RGBA frames ``(F, H, W, 4)`` as seen over white: ``(F, H, W, 3)``."""
    alpha = frames[..., 3:]
    return alpha * frames[..., :3] + (1.0 - alpha)


def jumps(change: np.ndarray) -> tuple[list[int], list[int]]:
    """Pops and spikes (frame indices >= 1) of the frame-to-frame ``change (F - 1,)``."""
    median = float(np.median(change)) if len(change) else 0.0
    pops = [int(k + 1) for k in np.flatnonzero((change > POP_RATIO * median) & (change > POP_FLOOR))]
    before = np.concatenate([[0.0], change[:-1]])
    after = np.concatenate([change[1:], [0.0]])
    spikes = [int(k + 1) for k in np.flatnonzero((change > POP_RATIO * np.maximum(before, after))
                                                 & (change > POP_FLOOR))]
    return pops, spikes


def every_contour(tr: Any, scene: Any, t: float, method: str | None) -> list[Any]:
    """``tr.contours`` at ``t``, contours that are one point then included (a version without the
    ``points`` keyword never returned such contours within a segment: its growing ones start at once)."""
    try:
        return tr.contours(scene, t, method=method, points=True)
    except TypeError:
        return tr.contours(scene, t, method=method)


def measure_method(tr: Any, scene: Any, method: str | None, key_areas: tuple[BaseGeometry, BaseGeometry],
                   near: BaseGeometry, view: tuple[float, float]) -> dict[str, Any]:
    """Every measure of one method on one loaded pair."""
    side = max(view)
    started = time.perf_counter()
    k0 = group(every_contour(tr, scene, KEY_EPS, method))
    k1 = group(every_contour(tr, scene, 1 - KEY_EPS, method))
    at0, at1 = group(every_contour(tr, scene, 0.0, method)), group(every_contour(tr, scene, 1.0, method))
    at = {t: every_contour(tr, scene, t, method) for t in TIMES}
    seconds = time.perf_counter() - started

    elements = {name: element_structure(name, k0[name], k1.get(name, []), at0.get(name), at1.get(name))
                for name in k0}
    a0, a1 = key_areas[0].area, key_areas[1].area
    amax = max(a0, a1, 1e-12)
    frames = []
    distortions: list[float] = []
    unaligned = 0
    for t in TIMES:
        groups = group(at[t])
        closed = stroke = 0
        kinds = [0, 0, 0]
        worst = 0.0
        for name, cs in groups.items():
            element = elements.get(name)
            found = element_tangles(element, cs) if element is not None else None
            if found is None:
                unaligned += 1
                continue
            closed += found.closed
            stroke += found.stroke
            kinds = [kinds[0] + found.self_cross, kinds[1] + found.hole_out, kinds[2] + found.pair_cross]
            d = element_distortion(element, cs, t, 1e-4 * side)
            if d is not None:
                distortions.append(d)
                worst = max(worst, d)
        area = drawn_area(at[t])
        a = area.area
        if a <= 0 or shapely.contains(near, area):
            stray = 0.0
        else:
            stray = shapely.difference(area, near).area / a
        frames.append({"t": t, "closed": closed, "stroke": stroke, "kinds": kinds, "stray": stray,
                       "area_dev": abs(a - ((1 - t) * a0 + t * a1)) / amax, "distortion": worst})
    pictures = pop_frames(tr, scene, method, view)
    alphas = pictures[..., 3]
    coverage = alphas.mean(axis=(1, 2), dtype=np.float64)
    change = np.abs(np.diff(alphas, axis=0)).mean(axis=(1, 2), dtype=np.float64)
    pops, spikes = jumps(change)
    net_pops, _ = jumps(np.abs(np.diff(coverage)))
    seen_change = np.abs(np.diff(over_white(pictures), axis=0)).mean(axis=(1, 2, 3), dtype=np.float64)
    colour_pops, _ = jumps(seen_change)
    return {
        "seconds": seconds,
        "measure_seconds": time.perf_counter() - started - seconds,
        "tangled_frames": sum(f["closed"] > 0 for f in frames),
        "stroke_tangled_frames": sum(f["stroke"] > 0 for f in frames),
        "tangle_kinds": [sum(f["kinds"][k] for f in frames) for k in range(3)],
        "stray_max": max(f["stray"] for f in frames),
        "pops": pops,
        "pop_changes": [float(change[p - 1]) for p in pops],
        "spikes": spikes,
        "net_pops": net_pops,
        "colour_pops": colour_pops,
        "colour_pop_changes": [float(seen_change[p - 1]) for p in colour_pops],
        "coverage": [round(float(c), 5) for c in coverage],
        "unaligned_element_frames": unaligned,
        "frames": frames,
        "distortions": distortions,  # every element-frame's value; dropped from the JSON
    }


def measure_pair(job: tuple[int, str, str, list[str], bool, float]) -> dict[str, Any]:
    """Load pair ``(a, b)`` and measure each method (and draw its sheet tiles when asked)."""
    index, a, b, methods, sheets, timeout = job
    import tweenrender as tr

    result: dict[str, Any] = {"index": index, "a": a, "b": b, "methods": {}, "tiles": {}}
    started = time.perf_counter()
    try:
        with deadline(timeout):
            scene = tr.load_scene([a, b], step=1.0)
            keys = (tr.contours(scene, 0.0), tr.contours(scene, 1.0))
            tr.contours(scene, 0.5, method="linear")  # the correspondence, shared by every method
    except Timeout as error:
        result["error"] = f"load timed out ({error})"
        return result
    except Exception as error:  # noqa: BLE001 - every refusal is reported, none hidden
        result["error"] = f"{type(error).__name__}: {error}".splitlines()[0][:300]
        return result
    result["load_seconds"] = time.perf_counter() - started
    result["scene_method"] = scene.method
    view = _view(scene, keys)
    key_areas = (drawn_area(keys[0]), drawn_area(keys[1]))
    reach = STRAY_SHARE * max(view)
    near = shapely.union_all([shapely.buffer(k, reach, quad_segs=4) for k in key_areas])
    shapely.prepare(near)
    result["view"] = view
    result["key_areas"] = [key_areas[0].area, key_areas[1].area]
    for name in methods:
        method = None if name == "default" else name
        try:
            with deadline(timeout):
                result["methods"][name] = measure_method(tr, scene, method, key_areas, near, view)
                if sheets:
                    result["tiles"][name] = [tr.frame(scene, s, method=method, size=(TILE, TILE)) for s in SHEET_TIMES]
        except Timeout as error:
            result["methods"][name] = {"error": f"timed out ({error})"}
        except Exception as error:  # noqa: BLE001
            result["methods"][name] = {"error": f"{type(error).__name__}: {error}".splitlines()[0][:300]}
    result["seconds"] = time.perf_counter() - started
    return result


# -- icons -----------------------------------------------------------------------------------------


def shipped_icons() -> dict[str, list[Path]]:
    """The shipped sets: set name -> its SVGs."""
    return {d.name: sorted(d.glob("*.svg")) for d in sorted(ICONS.iterdir()) if d.is_dir() and any(d.glob("*.svg"))}


def holdout_icons() -> dict[str, list[Path]] | None:
    """Icons of the npm packages (fetched once into the cache), less the shipped ones; None when there is
    neither npm nor a fetched package."""
    npm = shutil.which("npm")
    packs = CACHE / "packs"
    packs.mkdir(parents=True, exist_ok=True)
    shipped = shipped_icons()
    out: dict[str, list[Path]] = {}
    for package, (folders, set_name) in HOLDOUT_PACKAGES.items():
        stem = package.lstrip("@").replace("/", "-")
        tarballs = sorted(packs.glob(f"{stem}-[0-9]*.tgz"))
        if not tarballs and npm is not None:
            try:
                subprocess.run([npm, "pack", package, "--silent"], cwd=packs, check=True, timeout=300,
                               capture_output=True, text=True)
            except (subprocess.SubprocessError, OSError) as error:
                print(f"  npm pack {package} failed: {str(error).splitlines()[0]}", file=sys.stderr)
                continue
            tarballs = sorted(packs.glob(f"{stem}-[0-9]*.tgz"))
        if not tarballs:
            continue
        tarball = tarballs[-1]
        target = CACHE / tarball.name.removesuffix(".tgz")
        done = target / ".unpacked"
        if not done.exists():
            with tarfile.open(tarball) as tar:
                members = [m for m in tar.getmembers() if m.isfile() and m.name.endswith(".svg")
                           and any(str(Path(m.name).parent) == str(Path("package") / f) for f in folders)]
                tar.extractall(target, members=members, filter="data")
            done.touch()
        known = {p.name for p in shipped.get(set_name, [])}
        files = sorted(p for f in folders for p in (target / "package" / f).glob("*.svg") if p.name not in known)
        if files:
            out[package] = files
    return out if out else None


def sample_pairs(sets: dict[str, list[Path]], count: int, rng: np.random.Generator,
                 by_set: bool) -> list[tuple[Path, Path]]:
    """``count`` distinct ordered pairs of different icons: uniform over all icons, or (``by_set``) a set
    drawn uniformly, then an icon of it, for each side."""
    if not by_set:
        icons = [p for files in sets.values() for p in files]
        n = len(icons)
        picks = rng.permutation(n * (n - 1))[:count]  # a larger count extends a smaller one
        pairs = []
        for k in picks:
            i, j = divmod(int(k), n - 1)
            pairs.append((icons[i], icons[j + (j >= i)]))
        return pairs
    names = sorted(sets)
    seen: set[tuple[Path, Path]] = set()
    pairs = []
    while len(pairs) < count:
        a, b = (sets[names[s]][int(rng.integers(len(sets[names[s]])))]
                for s in rng.integers(len(names), size=2))
        if a != b and (a, b) not in seen:
            seen.add((a, b))
            pairs.append((a, b))
    return pairs


def short(path: str) -> str:
    """``set/name`` of an icon path."""
    p = Path(path)
    if not p.is_relative_to(CACHE):
        return f"{p.parent.name}/{p.stem}"
    unpacked = p.relative_to(CACHE).parts[0]  # e.g. heroicons-2.2.0
    for package, (_, set_name) in HOLDOUT_PACKAGES.items():
        if unpacked.startswith(package.lstrip("@").replace("/", "-") + "-"):
            if set_name == "heroicons":
                return f"heroicons{p.parent.parent.name}{p.parent.name}/{p.stem}"  # e.g. heroicons24solid/x
            if set_name == "tabler":
                return f"tabler-{p.parent.name}/{p.stem}"
            return f"{set_name}/{p.stem}"
    return f"{p.parent.name}/{p.stem}"


# -- report ----------------------------------------------------------------------------------------


def _pct(values: Sequence[float], q: float) -> float:
    return float(np.percentile(values, q)) if len(values) else float("nan")


def summarise(results: list[dict[str, Any]], methods: list[str]) -> list[dict[str, Any]]:
    rows = []
    for name in methods:
        done = [r["methods"][name] for r in results if "error" not in r and "error" not in r["methods"].get(name, {"error": 1})]
        failed = sum(1 for r in results if "error" not in r and "error" in r["methods"].get(name, {"error": 1}))
        frames = [f for m in done for f in m["frames"]]
        rows.append({
            "method": name,
            "pairs": len(done),
            "failed": failed,
            "tangled_pairs": sum(m["tangled_frames"] > 0 for m in done),
            "tangled_frames": sum(m["tangled_frames"] for m in done),
            "stroke_pairs": sum(m["stroke_tangled_frames"] > 0 for m in done),
            "stroke_frames": sum(m["stroke_tangled_frames"] for m in done),
            "frames": len(frames),
            "stray_p95": _pct([f["stray"] for f in frames], 95),
            "stray_max": max((f["stray"] for f in frames), default=float("nan")),
            "area_dev_p90": _pct([f["area_dev"] for f in frames], 90),
            "pop_pairs": sum(bool(m["pops"]) for m in done),
            "spike_pairs": sum(bool(m["spikes"]) for m in done),
            "net_pop_pairs": sum(bool(m.get("net_pops")) for m in done),
            "colour_pop_pairs": sum(bool(m.get("colour_pops")) for m in done),
            "distortion_p90": _pct([d for m in done for d in m["distortions"]], 90),
            "seconds": sum(m["seconds"] for m in done),
            "unaligned": sum(m["unaligned_element_frames"] for m in done),
        })
    return rows


def print_report(results: list[dict[str, Any]], methods: list[str], scene_method: str) -> list[dict[str, Any]]:
    rows = summarise(results, methods)
    loaded = [r for r in results if "error" not in r]
    print(f"\n{len(results)} pairs, {len(loaded)} loaded, {len(results) - len(loaded)} refused; "
          f"{len(TIMES)} in-betweens each (t = 0.05 ... 0.95); default = the scene's own method ({scene_method})")
    head = (f"{'method':<18}{'tangled pairs/frames':>21}{'stroke x pairs/frames':>22}{'stray p95':>11}{'stray max':>11}"
            f"{'area dev p90':>13}{'pop pairs':>10}{'spike pairs':>12}{'net pops':>9}{'colour pops':>12}{'distort p90':>12}"
            f"{'seconds':>9}")
    print(head)
    print("-" * len(head))
    for row in rows:
        name = f"default ({scene_method})" if row["method"] == "default" else row["method"]
        print(f"{name:<18}{row['tangled_pairs']:>11}/{row['tangled_frames']:<9}{row['stroke_pairs']:>12}/"
              f"{row['stroke_frames']:<9}{row['stray_p95']:>11.4f}{row['stray_max']:>11.4f}{row['area_dev_p90']:>13.4f}"
              f"{row['pop_pairs']:>10}{row['spike_pairs']:>12}{row['net_pop_pairs']:>9}{row['colour_pop_pairs']:>12}"
              f"{row['distortion_p90']:>12.4f}"
              f"{row['seconds']:>9.1f}")
    for row in rows:
        notes = []
        if row["failed"]:
            notes.append(f"{row['failed']} pairs failed")
        if row["unaligned"]:
            notes.append(f"{row['unaligned']} element-frames not aligned with the keys (tangles not checked there)")
        if notes:
            print(f"  {row['method']}: " + "; ".join(notes))
    refused = [r for r in results if "error" in r]
    if refused:
        print(f"\nrefused by the loader ({len(refused)}):")
        for r in refused:
            print(f"  {short(r['a'])} -> {short(r['b'])}: {r['error']}")
    for name in methods:
        done = [(r, r["methods"][name]) for r in loaded if "error" not in r["methods"].get(name, {"error": 1})]
        errors = [(r, r["methods"][name]["error"]) for r in loaded if "error" in r["methods"].get(name, {})]
        print(f"\n[{name}] worst by stray (max share):    " + (", ".join(
            f"{short(r['a'])}->{short(r['b'])} {m['stray_max']:.3f}"
            for r, m in sorted(done, key=lambda x: -x[1]["stray_max"])[:8] if m["stray_max"] > 0) or "-"))
        print(f"[{name}] worst by tangled frames (of {len(TIMES)}): " + (", ".join(
            f"{short(r['a'])}->{short(r['b'])} {m['tangled_frames']}"
            for r, m in sorted(done, key=lambda x: -x[1]["tangled_frames"])[:8] if m["tangled_frames"] > 0) or "-"))
        popped = [(r, m) for r, m in done if m["spikes"]]
        if popped:
            print(f"[{name}] spikes (frames): " + ", ".join(
                f"{short(r['a'])}->{short(r['b'])} " + " ".join(map(str, m["spikes"])) for r, m in popped))
        coloured = [(r, m) for r, m in done if m.get("colour_pops")]
        if coloured:
            print(f"[{name}] colour pops (frames): " + ", ".join(
                f"{short(r['a'])}->{short(r['b'])} " + " ".join(map(str, m["colour_pops"])) for r, m in coloured))
        for r, error in errors:
            print(f"[{name}] failed {short(r['a'])}->{short(r['b'])}: {error}")
    return rows


# -- sheets ----------------------------------------------------------------------------------------


def write_sheets(results: list[dict[str, Any]], methods: list[str], stem: str) -> list[Path]:
    """Contact sheets: a row per pair, columns t = 0, .25, .5, .75, 1 per method; at most 20 rows each."""
    import imageio.v3 as iio
    from PIL import Image, ImageDraw, ImageFont

    font = ImageFont.load_default(size=13)
    label_w, head_h, gap = 170, 22, 6
    group_w = len(SHEET_TIMES) * TILE
    width = label_w + len(methods) * (group_w + gap)
    for stale in OUT.glob(f"{stem}_*.png"):  # sheets of an earlier, longer run
        stale.unlink()
    written = []
    for start in range(0, len(results), ROWS_PER_SHEET):
        chunk = results[start:start + ROWS_PER_SHEET]
        sheet = Image.new("RGBA", (width, head_h + len(chunk) * TILE), (235, 235, 235, 255))
        draw = ImageDraw.Draw(sheet)
        for m, name in enumerate(methods):
            x = label_w + m * (group_w + gap)
            draw.text((x + 4, 4), f"{name}   t = 0, .25, .5, .75, 1", fill=(0, 0, 0, 255), font=font)
        for row, r in enumerate(chunk):
            y = head_h + row * TILE
            draw.text((4, y + 8), f"#{r['index']}", fill=(0, 0, 0, 255), font=font)
            draw.text((4, y + 30), short(r["a"])[:22], fill=(0, 0, 0, 255), font=font)
            draw.text((4, y + 48), "-> " + short(r["b"])[:19], fill=(0, 0, 0, 255), font=font)
            if "error" in r:
                draw.text((4, y + 70), "refused:", fill=(180, 0, 0, 255), font=font)
                draw.text((4, y + 88), r["error"][:24], fill=(180, 0, 0, 255), font=font)
                continue
            for m, name in enumerate(methods):
                tiles = r.get("tiles", {}).get(name)
                x = label_w + m * (group_w + gap)
                if not tiles:
                    draw.text((x + 4, y + 8), "failed: " + r["methods"].get(name, {}).get("error", "?")[:40],
                              fill=(180, 0, 0, 255), font=font)
                    continue
                for k, tile in enumerate(tiles):
                    sheet.paste(Image.fromarray(np.ascontiguousarray(tile), "RGBA"), (x + k * TILE, y))
                    draw.rectangle((x + k * TILE, y, x + (k + 1) * TILE - 1, y + TILE - 1), outline=(200, 200, 200, 255))
        path = OUT / f"{stem}_{start // ROWS_PER_SHEET + 1:02d}.png"
        iio.imwrite(path, np.asarray(sheet))
        written.append(path)
    return written


# -- main ------------------------------------------------------------------------------------------


def _json_ready(results: list[dict[str, Any]]) -> list[dict[str, Any]]:
    out = []
    for r in results:
        r = {k: v for k, v in r.items() if k != "tiles"}
        r["a"], r["b"] = short(r["a"]), short(r["b"])
        methods = {}
        for name, m in r.get("methods", {}).items():
            m = dict(m)
            if "distortions" in m:
                d = m.pop("distortions")
                m["distortion_p90"] = _pct(d, 90) if d else None
                m["distortion_max"] = max(d) if d else None
            methods[name] = m
        r["methods"] = methods
        out.append(r)
    return out


def source_state() -> str:
    """The package's version, the working tree's commit (``+dirty`` with uncommitted changes) and a digest
    of the package's sources as they are (runs on a changing tree are told apart by it)."""
    import hashlib

    import tweenrender

    package = Path(tweenrender.__file__).resolve().parent  # the tree measured (PYTHONPATH may point elsewhere)
    try:
        head = subprocess.run(["git", "-C", str(package), "describe", "--always", "--dirty=+dirty"], check=True,
                              capture_output=True, text=True, timeout=30).stdout.strip()
    except (subprocess.SubprocessError, OSError):
        head = "unknown commit"
    digest = hashlib.sha1()
    for path in sorted(package.rglob("*.py")):
        digest.update(path.relative_to(package.parent).as_posix().encode() + b"\0" + path.read_bytes())
    return f"{tweenrender.__version__} at {head} ({package.parent}), sources {digest.hexdigest()[:12]}"


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--pairs", type=int, default=120)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--methods", default=",".join(DEFAULT_METHODS),
                        help="comma-separated; 'default' is the scene's own method")
    parser.add_argument("--jobs", type=int, default=1)
    parser.add_argument("--sheets", action="store_true")
    parser.add_argument("--holdout", action="store_true", help="icons of npm packages the project has not seen")
    parser.add_argument("--timeout", type=float, default=180.0, help="seconds per pair and method (0: none)")
    parser.add_argument("--tag", default="", help="results_<tag>.json instead of results.json (runs side by side)")
    args = parser.parse_args()
    try:
        from tweenrender.api import method_names

        METHODS = method_names()
    except ImportError:  # a version before the front door, measured for comparison
        from tweenrender.core.methods import METHODS  # type: ignore[no-redef]

    methods = [m.strip() for m in args.methods.split(",") if m.strip()]
    unknown = [m for m in methods if m != "default" and m not in METHODS]
    if unknown:
        parser.error(f"unknown methods {unknown}; expected 'default' or one of {', '.join(METHODS)}")
    print(f"load average at start: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    tree = source_state()
    print(f"tweenrender {tree}")
    if args.holdout:
        sets = holdout_icons()
        if sets is None:
            print("npm is not available (or fetched nothing) and no icon package is cached: nothing held out to measure")
            return 2
        rng = np.random.default_rng([args.seed, 0x401D])
        pairs = sample_pairs(sets, args.pairs, rng, by_set=True)
        stem = "holdout"
        print("held-out icons: " + ", ".join(f"{k} {len(v)}" for k, v in sets.items()))
    else:
        sets = shipped_icons()
        rng = np.random.default_rng([args.seed, 0])
        pairs = sample_pairs(sets, args.pairs, rng, by_set=False)
        stem = "tuning"
        print(f"shipped icons: {sum(len(v) for v in sets.values())} in {len(sets)} sets")
    OUT.mkdir(parents=True, exist_ok=True)
    jobs = [(k, str(a), str(b), methods, args.sheets, args.timeout) for k, (a, b) in enumerate(pairs)]
    started = time.perf_counter()
    results: list[dict[str, Any]] = []

    def progress(r: dict[str, Any]) -> None:
        state = r.get("error", "") or " ".join(
            f"{n}:{'ERR' if 'error' in m else m['tangled_frames']}" for n, m in r["methods"].items())
        print(f"  [{len(results):>3}/{len(jobs)}] {short(r['a'])} -> {short(r['b'])} "
              f"{r.get('seconds', 0):.1f}s {state}", file=sys.stderr, flush=True)

    if args.jobs <= 1:
        for job in jobs:
            results.append(measure_pair(job))
            progress(results[-1])
    else:
        with ProcessPoolExecutor(args.jobs, mp_context=get_context("spawn")) as pool:
            for future in as_completed([pool.submit(measure_pair, job) for job in jobs]):
                results.append(future.result())
                progress(results[-1])
    results.sort(key=lambda r: r["index"])
    wall = time.perf_counter() - started
    scene_method = next((r["scene_method"] for r in results if "scene_method" in r), "?")
    rows = print_report(results, methods, scene_method)
    target = OUT / (("results_holdout" if args.holdout else "results") + (f"_{args.tag}" if args.tag else "") + ".json")
    target.write_text(json.dumps({"seed": args.seed, "holdout": args.holdout, "source": tree, "methods": methods,
                                  "wall_seconds": wall, "jobs": args.jobs, "summary": rows,
                                  "pairs": _json_ready(results)}, indent=1))
    print(f"\nwrote {target.relative_to(ROOT)}")
    if args.sheets:
        for path in write_sheets(results, methods, f"sheet_{stem}"):
            print(f"wrote {path.relative_to(ROOT)}")
    print(f"wall time {wall:.0f} s with {args.jobs} job(s); "
          f"load average at end: {' '.join(f'{x:.2f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
