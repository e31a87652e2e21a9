"""The numbers of docs/arap.md and docs/intrinsic.md: how well each method keeps a shape.

    python benchmarks/method_quality.py

1. The articulated scenes (walk, hinge, roofbox) without their joints — except the
   ``jointed`` column, which uses them — at t = 0.25, 0.5, 0.75 of every segment:
   the worst edge-length error ``|L(t) / ((1-t)·L0 + t·L1) - 1|`` and the range of
   the perimeter ratio ``P(t) / ((1-t)·P0 + t·P1)``. ``arap (paper)`` is the plain
   formulation of Alexa et al. on the same triangulation as ``arap``.
2. Every shipped scene: how many of the 101 swept inbetweens of its segments
   cross themselves, per method, for segments whose keys are simple and wind
   the same way (keys of opposite winding cannot be blended without a crossing:
   the signed area must pass through zero).
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tweenrender.core.methods.arap import arap  # noqa: E402
from tweenrender.core.crossings import self_crossing, self_crossings  # noqa: E402
from tweenrender.core.geometry import signed_area  # noqa: E402
from tweenrender.core.methods.intrinsic import closure_tweak  # noqa: E402
from tweenrender.core.measures import SWEEP, edge_error, perimeter_ratio  # noqa: E402
from tweenrender.core.methods.registry import interpolate  # noqa: E402
from tweenrender.core.timing.timeline import build_track  # noqa: E402
from tweenrender.scenefile import load_scene  # noqa: E402

AT = np.array([0.25, 0.5, 0.75])
COLUMNS = ("linear", "nonlinear", "rigid", "jointed", "arap", "arap (paper)", "intrinsic", "intrinsic-length")
ARTICULATED = ("walk", "hinge", "roofbox", "foot-svg")
CROSSING = ("linear", "nonlinear", "rigid", "arap", "intrinsic", "intrinsic-length", "auto")


def frames(column: str, segment, t: np.ndarray) -> np.ndarray:
    if column == "arap (paper)":
        return arap(segment.k0, segment.k1, t, variant="paper")
    joints = segment.joints if column == "jointed" else ()
    return interpolate(segment.k0, segment.k1, t, column, joints)


def segments(name: str):
    scene = load_scene(ROOT / "scenes" / f"{name}.toml")
    for shape in scene.shapes:
        yield from build_track(shape, scene.matching, unmatched=scene.unmatched, balance=scene.balance_of(shape)).segments


def articulated() -> None:
    print("worst edge error, and perimeter ratio range, at t = 0.25, 0.5, 0.75 (no joints but in 'jointed')")
    print(f"{'scene':10}" + "".join(f"{c:>22}" for c in COLUMNS))
    for name in ARTICULATED:
        cells = []
        for column in COLUMNS:
            worst, low, high = 0.0, np.inf, -np.inf
            for segment in segments(name):
                f = frames(column, segment, AT)
                worst = max(worst, float(np.nanmax(edge_error(f, segment.k0, segment.k1, AT))))
                ratio = perimeter_ratio(f, segment.k0, segment.k1, AT)
                low, high = min(low, float(ratio.min())), max(high, float(ratio.max()))
            cells.append(f"{worst:.3f} {low:.3f}-{high:.3f}")
        print(f"{name:10}" + "".join(f"{c:>22}" for c in cells))
    print("\nclosing tweak of the intrinsic walk, worst over the sweep (share of the perimeter):")
    for name in ARTICULATED:
        for closure in ("paper", "length"):
            worst = max(float(closure_tweak(s.k0, s.k1, SWEEP, closure).max()) for s in segments(name))
            print(f"  {name:8} {closure:7} {100 * worst:6.2f} %")


def crossings() -> None:
    print("\ninbetweens (of 101 per segment) whose outline crosses itself, where the keys are simple")
    print(f"{'scene':22}" + "".join(f"{c:>17}" for c in CROSSING))
    totals = dict.fromkeys(CROSSING, 0)
    for path in sorted((ROOT / "scenes").glob("*.toml")):
        counts = dict.fromkeys(CROSSING, 0)
        note = ""
        for segment in segments(path.stem):
            k0, k1 = np.asarray(segment.k0), np.asarray(segment.k1)
            if self_crossing(k0) is not None or self_crossing(k1) is not None:
                note = " (a key crosses itself: skipped)"
                continue
            if np.sign(signed_area(k0)) != np.sign(signed_area(k1)):
                note = " (keys wind opposite ways: skipped)"
                continue
            for method in CROSSING:
                f = interpolate(k0, k1, SWEEP, method, segment.joints)
                counts[method] += sum(c is not None for c in self_crossings(f))
        for method in CROSSING:
            totals[method] += counts[method]
        print(f"{path.stem:22}" + "".join(f"{counts[c]:>17d}" for c in CROSSING) + note)
    print(f"{'all':22}" + "".join(f"{totals[c]:>17d}" for c in CROSSING))


if __name__ == "__main__":
    articulated()
    crossings()
