"""Which balance rule is the default: copies (the thesis) or spread (maths §5.6)?

For every shipped scene, every segment and every method, count the swept inbetweens
(101 t per segment) whose outline crosses itself, and take the worst edge-length error
over the sweep (edges whose reference length is 0 skipped: copies make such edges).
The default is the rule with fewer self-intersecting inbetweens, then the lower worst
edge error. Only segments whose keys differ in vertex count (where balancing makes
copies) can differ; the others are counted once, under both rules alike.

Run: ``python benchmarks/balance_rules.py``
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tweenrender.core.crossings import self_crossings  # noqa: E402
from tweenrender.core.measures import SWEEP, edge_error  # noqa: E402
from tweenrender.core.methods.registry import interpolate  # noqa: E402
from tweenrender.core.timing.timeline import build_track  # noqa: E402
from tweenrender.core.methods.registry import METHODS  # noqa: E402
from tweenrender.model import BALANCES  # noqa: E402
from tweenrender.scenefile import load_scene  # noqa: E402


def measure(balance: str) -> tuple[dict[str, tuple[int, float]], int, float]:
    """Per scene (crossing inbetweens, worst edge error over its balanced segments), and totals."""
    per_scene: dict[str, tuple[int, float]] = {}
    for path in sorted((ROOT / "scenes").glob("*.toml")):
        scene = load_scene(path)
        crossings, worst = 0, 0.0
        for shape in scene.shapes:
            for segment in build_track(shape, scene.matching, balance=balance).segments:
                if segment.correspondence is None:
                    continue  # equal counts in drawn order: nothing is balanced
                for method in METHODS:
                    if method == "jointed" and not segment.joints:
                        continue
                    frames = interpolate(segment.k0, segment.k1, SWEEP, method, segment.joints)
                    crossings += sum(c is not None for c in self_crossings(frames))
                    errors = edge_error(frames, segment.k0, segment.k1, SWEEP)
                    if np.isfinite(errors).any():
                        worst = max(worst, float(np.nanmax(errors)))
        if any(build_track(s, scene.matching).segments and any(
                g.correspondence is not None for g in build_track(s, scene.matching).segments)
               for s in scene.shapes):
            per_scene[path.stem] = (crossings, worst)
    return per_scene, sum(c for c, _ in per_scene.values()), max((w for _, w in per_scene.values()), default=0.0)


def main() -> None:
    results = {balance: measure(balance) for balance in BALANCES}
    scenes = sorted(results[BALANCES[0]][0])
    print(f"{'scene':22}" + "".join(f"{b + ' crossing':>18}{b + ' worst edge':>18}" for b in BALANCES))
    for name in scenes:
        print(f"{name:22}" + "".join(f"{results[b][0][name][0]:>18d}{results[b][0][name][1]:>18.3f}"
                                     for b in BALANCES))
    print(f"{'all':22}" + "".join(f"{results[b][1]:>18d}{results[b][2]:>18.3f}" for b in BALANCES))
    best = min(BALANCES, key=lambda b: (results[b][1], results[b][2]))
    print(f"\nfewer crossing inbetweens, then lower worst edge error: {best}")
    print(f"(methods {', '.join(METHODS)}; 101 t per segment; only segments whose keys differ in count)")


if __name__ == "__main__":
    main()
