"""SVG conformance against resvg's public test suite: frame 0 of each test drawing beside its reference PNG.

    python benchmarks/svg_conformance.py SUITE [--renderers tweenrender,rsvg,chromium] [--folders a/b,...]
                                               [--list-failing FILE] [-v]

``SUITE`` is a checkout of ``linebender/resvg-test-suite`` (MIT): ``SUITE/tests/<group>/<feature>/*.svg``
each beside its reference ``.png``, and ``SUITE/results.csv`` with the maintainers' verdicts, where a
Chrome verdict of 0 marks a test as not judged (undefined behaviour); only judged tests count.

Each renderer draws the test at the reference's size over white and is compared with the reference
over white by the key-frame measure of ``tests/scenefile/test_key_frames.py`` (ink is any channel more
than 32/255 from white; pass when coverage IoU ≥ 0.99 and colour error ≤ 0.02). tweenrender draws
``load_scene(X.svg)`` at time 0 (what ``tweenrender render X.svg X.svg`` shows first); a refusal is a
:class:`~tweenrender.errors.TweenrenderError`, a crash any other exception. Prints pass / wrong /
refused / crash per folder and per group of folders.
"""

from __future__ import annotations

import argparse
import csv
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import warnings
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

GROUPS: dict[str, list[str]] = {
    "claimed features": [
        "shapes/circle", "shapes/ellipse", "shapes/line", "shapes/path", "shapes/polygon", "shapes/polyline",
        "shapes/rect", "structure/a", "structure/defs", "structure/g", "structure/svg", "structure/use",
        "structure/symbol", "structure/style", "structure/style-attribute", "structure/transform",
        "painting/color", "painting/fill", "painting/fill-opacity", "painting/fill-rule", "painting/opacity",
        "painting/stroke", "painting/stroke-opacity", "painting/stroke-width", "painting/stroke-linecap",
        "painting/stroke-linejoin", "painting/stroke-miterlimit", "painting/display", "painting/visibility",
        "paint-servers/linearGradient", "paint-servers/radialGradient", "paint-servers/stop",
        "paint-servers/stop-color", "paint-servers/stop-opacity", "masking/clipPath", "masking/clip-rule",
        "masking/clip"],
    "masks": ["masking/mask"],
    "next to the claims": [
        "painting/stroke-dasharray", "painting/stroke-dashoffset", "painting/marker", "painting/paint-order",
        "structure/switch", "structure/transform-origin", "paint-servers/pattern", "painting/context",
        "structure/systemLanguage", "painting/overflow"],
    "pictures": ["structure/image"],
}
PASS_IOU, PASS_ERROR = 0.99, 0.02
SECONDS_PER_TEST = 20


def judged_tests(suite: Path, folders: list[str]) -> list[str]:
    """The suite's judged tests (``group/feature/name.svg``) in ``folders``, sorted."""
    with open(suite / "results.csv", newline="") as handle:
        rows = list(csv.reader(handle))
    wanted = tuple(f + "/" for f in folders)
    return sorted(row[0] for row in rows[1:] if row[0].startswith(wanted) and int(row[1]) != 0
                  and (suite / "tests" / row[0]).exists())


def over_white(rgba: np.ndarray) -> np.ndarray:
    """Straight RGBA uint8 ``(H, W, 4)`` (or RGB) composited over white: RGB floats ``(H, W, 3)`` in [0, 255]."""
    rgba = rgba.astype(float)
    if rgba.shape[-1] == 3:
        return rgba
    alpha = rgba[..., 3:4] / 255.0
    return rgba[..., :3] * alpha + 255.0 * (1.0 - alpha)


def measures(ours: np.ndarray, theirs: np.ndarray) -> tuple[float, float]:
    """(coverage IoU, colour error) of two RGB pictures over white (the key-frame measure)."""
    from tests.scenefile.test_key_frames import measures as key_frame_measures

    return key_frame_measures(ours, theirs)


class _Timeout(Exception):
    pass


def _alarm(*_: object) -> None:
    raise _Timeout()


def draw_tweenrender(svg: Path, width: int, height: int) -> np.ndarray:
    import tweenrender as tr

    scene = tr.load_scene(svg)
    return tr.frame(scene, 0.0, size=(width, height), background="#ffffff")


def draw_rsvg(svg: Path, width: int, height: int) -> np.ndarray:
    import imageio.v3 as iio

    done = subprocess.run(["rsvg-convert", "-w", str(width), "-h", str(height), "-b", "white", str(svg)],
                          capture_output=True, timeout=SECONDS_PER_TEST, cwd=svg.parent, check=False)
    if done.returncode != 0:
        raise RuntimeError(done.stderr.decode(errors="replace").strip()[:200])
    return iio.imread(done.stdout, mode="RGBA")


def draw_chromium(svg: Path, width: int, height: int) -> np.ndarray:
    import imageio.v3 as iio

    with tempfile.TemporaryDirectory() as scratch:
        page = Path(scratch) / "page.html"
        page.write_text(f"<html><body style='margin:0;background:white'><img src='{svg.as_uri()}' "
                        f"width='{width}' height='{height}' style='display:block'></body></html>")
        shot = Path(scratch) / "shot.png"
        subprocess.run(["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                        "--allow-file-access-from-files", f"--window-size={width},{height}",
                        f"--screenshot={shot}", page.as_uri()], capture_output=True, timeout=60, check=False)
        return iio.imread(shot, mode="RGBA")[:height, :width]


def chromium_batch(svgs: list[Path], sizes: list[tuple[int, int]]) -> dict[Path, np.ndarray]:
    """Chromium's pictures of many drawings from one screenshot: each ``<img>`` at its size, stacked."""
    import imageio.v3 as iio

    pictures: dict[Path, np.ndarray] = {}
    for start in range(0, len(svgs), 30):
        chunk, dims = svgs[start:start + 30], sizes[start:start + 30]
        tops = np.cumsum([0] + [h for _, h in dims])
        width = max(w for w, _ in dims)
        images = "".join(f"<img src='{svg.as_uri()}' width='{w}' height='{h}' "
                         f"style='position:absolute;left:0;top:{top}px'>"
                         for svg, (w, h), top in zip(chunk, dims, tops))
        with tempfile.TemporaryDirectory() as scratch:
            page, shot = Path(scratch) / "page.html", Path(scratch) / "shot.png"
            page.write_text(f"<html><body style='margin:0;background:white'>{images}</body></html>")
            subprocess.run(["chromium", "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                            "--allow-file-access-from-files", f"--window-size={width},{int(tops[-1])}",
                            f"--screenshot={shot}", page.as_uri()], capture_output=True, timeout=300,
                           check=False)
            whole = iio.imread(shot, mode="RGBA")
        for svg, (w, h), top in zip(chunk, dims, tops):
            pictures[svg] = whole[top:top + h, :w]
    return pictures


RENDERERS = {"tweenrender": draw_tweenrender, "rsvg": draw_rsvg, "chromium": draw_chromium}


def verdict(draw, svg: Path) -> tuple[str, str]:
    """("pass" | "wrong" | "refused" | "crash", detail) for one test drawn by ``draw``."""
    import imageio.v3 as iio

    from tweenrender.errors import TweenrenderError

    reference = over_white(iio.imread(svg.with_suffix(".png"), mode="RGBA"))
    height, width = reference.shape[:2]
    signal.signal(signal.SIGALRM, _alarm)
    signal.alarm(SECONDS_PER_TEST)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            picture = draw(svg, width, height)
    except TweenrenderError as refusal:
        return "refused", str(refusal).replace(str(svg.parent) + "/", "")[:160]
    except _Timeout:
        return "crash", "timed out"
    except Exception as error:  # noqa: BLE001 - a crash is what is counted here
        return "crash", f"{type(error).__name__}: {error}"[:160]
    finally:
        signal.alarm(0)
    iou, error = measures(over_white(picture), reference)
    ok = iou >= PASS_IOU and error <= PASS_ERROR
    return ("pass" if ok else "wrong"), f"IoU {iou:.3f} error {error:.3f}"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("suite", type=Path)
    parser.add_argument("--renderers", default="tweenrender")
    parser.add_argument("--folders", default="", help="comma-separated group/feature folders (default: all groups)")
    parser.add_argument("--list-failing", type=Path, help="write every judged test that does not pass here")
    parser.add_argument("-v", "--verbose", action="store_true", help="print each test that does not pass")
    args = parser.parse_args()
    warnings.simplefilter("ignore")  # the reference PNGs' palettes
    renderers = [r for r in args.renderers.split(",") if r]
    for name in renderers:
        if name != "tweenrender" and shutil.which({"rsvg": "rsvg-convert"}.get(name, name)) is None:
            sys.exit(f"{name} is not installed")
    groups = ({"chosen": args.folders.split(",")} if args.folders else GROUPS)
    failing: list[str] = []
    header = "folder".ljust(32) + "".join(f"{r + ' p/w/r/c':>24}" for r in renderers)
    print(header)
    for group, folders in groups.items():
        totals = {r: Counter() for r in renderers}
        for folder in folders:
            tests = judged_tests(args.suite, [folder])
            counts = {r: Counter() for r in renderers}
            if "chromium" in renderers:
                import imageio.v3 as iio

                svgs = [args.suite / "tests" / t for t in tests]
                shots = chromium_batch(svgs, [iio.imread(p.with_suffix(".png")).shape[1::-1] for p in svgs])
                RENDERERS["chromium"] = lambda svg, w, h, shots=shots: shots[svg]
            for test in tests:
                for r in renderers:
                    result, detail = verdict(RENDERERS[r], args.suite / "tests" / test)
                    counts[r][result] += 1
                    if result != "pass":
                        if r == "tweenrender":
                            failing.append(test)
                        if args.verbose:
                            print(f"  {r} {result}: {test}: {detail}", flush=True)
            line = f"{folder} ({len(tests)})".ljust(32)
            for r in renderers:
                c = counts[r]
                totals[r].update(c)
                line += f"{c['pass']:>9}/{c['wrong']}/{c['refused']}/{c['crash']}".rjust(24)
            print(line, flush=True)
        line = f"== {group} ({sum(totals[renderers[0]].values())})".ljust(32)
        for r in renderers:
            c = totals[r]
            line += f"{c['pass']:>9}/{c['wrong']}/{c['refused']}/{c['crash']}".rjust(24)
        print(line, flush=True)
    if args.list_failing:
        args.list_failing.write_text("".join(t + "\n" for t in failing))


if __name__ == "__main__":
    os.environ.setdefault("OMP_NUM_THREADS", "1")
    main()
