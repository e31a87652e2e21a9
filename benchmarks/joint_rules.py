"""Compare rules for the paths of jointed bodies (run by hand, not in CI).

    PYTHONPATH=. /tmp/probe/bin/python benchmarks/joint_rules.py

For a limb swinging about a hinge and for the hinge, roof-box and walk scenes,
prints the worst edge-length error (the documented ``edge_error``, over 101 t) of
every edge, and of each local body's outline (its edges and its joint chords,
i.e. the width of each joint), under these rules:

* ``mean``: each body's nonlinear paths about its own center of mass; a joint
  vertex follows the mean of its bodies' paths (the first rule of maths §5.1).
* ``mean-joint``: as ``mean``, but each body turns about the midpoint of its
  joint chords instead of its center of mass.
* ``chain``: ``joints.jointed``'s default. The body with most vertices (the
  thesis's "larger masses controlling the movement of the other segments")
  gets the nonlinear paths about its center of mass; every other body turns
  about the midpoint of the chord joining it to its parent, which moves with
  the parent; the chord turns with the more nearly rigid of its two bodies.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

from tweenrender.core import joints, paths  # noqa: E402
from tweenrender.core.geometry import rotate  # noqa: E402
from tweenrender.core.measures import SWEEP, edge_error  # noqa: E402
from tweenrender.core.timing.timeline import build_track  # noqa: E402
from tweenrender.scenefile import load_scene  # noqa: E402


def mean_about_joints(k0: np.ndarray, k1: np.ndarray, t: np.ndarray, chords) -> np.ndarray:
    """Every body turns about the mean of its joint vertices (moving straight); joints on the mean."""
    n = len(k0)
    total = np.zeros((len(t), n, 2))
    count = np.zeros(n)
    for b in joints.bodies(n, chords):
        ends = sorted({v for c in chords for v in c} & set(b.tolist()))
        j0, j1 = k0[ends].mean(axis=0), k1[ends].mean(axis=0)
        total[:, b] += paths.linear(j0[None], j1[None], t) + joints.pivoted(k0[b] - j0, k1[b] - j1, t)
        count[b] += 1
    return total / count[None, :, None]


RULES = {
    "linear": lambda k0, k1, t, c: paths.linear(k0, k1, t),
    "nonlinear": lambda k0, k1, t, c: paths.nonlinear(k0, k1, t),
    "mean": lambda k0, k1, t, c: joints.jointed(k0, k1, t, c, rule="mean"),
    "chain": lambda k0, k1, t, c: joints.jointed(k0, k1, t, c),
    "mean-joint": mean_about_joints,
}


def limb(deg: float):
    k0 = np.array([[-2, -2], [2, -2], [2, 1.5], [8, 1.5], [8, 2], [2, 2], [-2, 2]], dtype=float)
    k1 = k0.copy()
    idx = [2, 3, 4, 5]
    k1[idx] = k0[2] + rotate(k0[idx] - k0[2], np.radians(deg))
    return k0, k1, ((2, 5),)


def cases():
    for deg in (45.0, 90.0, -90.0, 135.0):
        yield f"limb {deg:+.0f}", *limb(deg)
    for name in ("hinge", "roofbox", "walk"):
        scene = load_scene(ROOT / "scenes" / f"{name}.toml")
        for shape in scene.shapes:
            for i, seg in enumerate(build_track(shape, scene.matching).segments):
                yield f"{name} {i}", np.asarray(seg.k0), np.asarray(seg.k1), seg.joints


def main() -> None:
    t = SWEEP
    print(f"{'case':<12} {'rule':<12} {'all edges':>9}  per body (its outline, joint chords included)")
    for name, k0, k1, chords in cases():
        n = len(k0)
        parts = joints.bodies(n, chords)
        for rule, f in RULES.items():
            frames = f(k0, k1, t, chords)
            err = edge_error(frames, k0, k1, t)
            per = [np.nanmax(edge_error(frames[:, b], k0[b], k1[b], t)) for b in parts]
            print(f"{name:<12} {rule:<12} {np.nanmax(err):9.4f}  " + "  ".join(f"{p:.4f}" for p in per))
        print()


if __name__ == "__main__":
    main()
