"""The ``stats`` report: the thesis's ch. 6 perimeter measures per shape, segment and method."""

from __future__ import annotations

from typing import Any, Callable, Sequence

from ..core.methods.intrinsic import closure_tweak
from ..core.measures import SWEEP, report
from ..core.methods.qcurves import auto_choice
from ..core.tangles import tangled_times
from ..core.timing.timeline import pair_paths
from ..core.methods.registry import REGISTRY, measured_methods
from ..model import Scene
from .segments import Entry, entries, nothing_measured

__all__ = ["stats_dict", "stats_text", "crossing_runs", "STATS_METHODS"]

STATS_METHODS = measured_methods(jointed=False)
"""Every method measured on every segment (and those that need joints where the shape has them)."""



def stats_dict(scene: Scene, t: Sequence[float], methods: Sequence[str] | None = None) -> dict[str, Any]:
    """The thesis's ch. 6 report and the quality measures for every shape and segment (the documented
    ``stats --json``): for ``methods``, default every method (``jointed`` where a shape has joints)."""
    shapes = []
    tangled: dict[tuple[int, int, str], list[float]] = {}
    for entry in entries(scene, closed_only=True):
        pair, joints = entry.pair, entry.segment.joints
        names = tuple(methods) if methods is not None else measured_methods(jointed=bool(joints))
        choice = auto_choice(pair.k0, pair.k1, joints)
        measured = {m: report(pair.k0, pair.k1, m, t, joints, _as_drawn(entry, m)).as_dict()
                    for m in names}
        for method in measured:
            measured[method]["crossings"] = _crossings(entry, method, tangled)
            closure = REGISTRY[method].closure
            if closure is not None:  # how much the closing tweak changed the lengths, at worst
                measured[method]["closure_tweak_max"] = float(closure_tweak(pair.k0, pair.k1, SWEEP, closure).max())
        shapes.append({
            **entry.head(),
            "vertices": list(pair.counts),
            "balanced": len(pair.k0),
            "auto": {"method": choice.method, "why": choice.why},
            "methods": measured,
        })
    out: dict[str, Any] = {"scene": str(scene.path) if scene.path else None, "shapes": shapes}
    if not shapes:
        out["note"] = nothing_measured(scene)
    return out


def _crossings(entry: Entry, method: str, done: dict[tuple[int, int, str], list[float]]) -> list[float]:
    """The swept t at which the entry's shape tangles in its segment under ``method``: a contour
    crossing itself properly, or a hole leaving its outline (all the segment's moving contours)."""
    key = (id(entry.shape), entry.index, method)
    if key not in done:
        segment = entry.segment
        frames = pair_paths(segment, SWEEP, method)
        moving = [k for k, p in enumerate(segment.pairs) if p.moving]
        done[key] = tangled_times([frames[k] for k in moving], [segment.pairs[k].closed for k in moving], SWEEP)
    return done[key]


def _as_drawn(entry: Entry, method: str) -> Callable[[Any], Any] | None:
    """The contour's inbetweens as drawn, when its shape has other contours moving with it."""
    if entry.contour is None:
        return None
    segment, index = entry.segment, entry.contour
    return lambda t: pair_paths(segment, t, method)[index]


def stats_text(stats: dict[str, Any]) -> str:
    """The report in the thesis's words, five decimals."""
    lines = [f"{stats['scene']}"]
    for shape in stats["shapes"]:
        start, end = shape["times"]
        m, n = shape["vertices"]
        contour = f", contour {shape['contour']}" if "contour" in shape else ""
        lines += ["", f"SHAPE {shape['name']}, segment {shape['segment']}{contour} ({start:g} s to {end:g} s), "
                      f"{m} and {n} vertices, {shape['balanced']} after balancing",
                  f"auto chooses {shape['auto']['method']}: {shape['auto']['why']}"]
        for method, r in shape["methods"].items():
            lines += ["", f"{method.upper()} METHOD",
                      f"Perimeter of Left Polygon  = {r['perimeter_keys'][0]:.5f}",
                      f"Perimeter of Right Polygon = {r['perimeter_keys'][1]:.5f}"]
            single = len(r["t"]) == 1
            for t, p in zip(r["t"], r["perimeter"]):
                at = "" if single else f" at t = {t:g}"
                lines.append(f"Perimeter of Interpolated Polygon{at} = {p:.5f}")
            lines.append(f"Average of Keyframes = {r['perimeter_mean']:.5f}")
            for t, ratio in zip(r["t"], r["ratio"]):
                at = "" if single else f" at t = {t:g}"
                lines.append(f"Ratio of Inbetween to Average{at} = {ratio:.5f}")
            if single:
                lines.append(f"(at t = {r['t'][0]:g}; over the segment the ratio runs from "
                             f"{r['ratio_min']:.5f} to {r['ratio_max']:.5f}, worst edge-length error "
                             f"{r['edge_error_max']:.5f})")
            else:
                lines.append(f"(over the segment the ratio runs from {r['ratio_min']:.5f} to "
                             f"{r['ratio_max']:.5f}, worst edge-length error {r['edge_error_max']:.5f})")
            areas = ", ".join(f"{a:.5f}" for a in r["area_ratio"])
            lines.append(f"Area ratio to the interpolated keys = {areas}; worst turning-angle error "
                         f"{r['angle_error_max']:.3f} degrees")
            lines.append(_crossing_words(r["self_intersects"]))
            if "closure_tweak_max" in r:
                lines.append(f"Closing the walk changed the lengths by at most {100 * r['closure_tweak_max']:.2f} % "
                             "of the perimeter")
    if not stats["shapes"]:
        lines.append(stats.get("note", "no shape has two keys: nothing moves"))
    return "\n".join(lines)


def crossing_runs(at: Sequence[float]) -> list[tuple[float, float]]:
    """The swept t at which an outline crosses itself (steps of 0.01), as ``(first, last)`` runs."""
    runs: list[list[float]] = []
    for t in at:
        if runs and t - runs[-1][1] <= 0.0101:
            runs[-1][1] = t
        else:
            runs.append([t, t])
    return [(a, b) for a, b in runs]


def _crossing_words(at: list[float]) -> str:
    """``"The outline crosses itself at t = 0.51 to 1"`` or that it never does."""
    if not at:
        return "The outline never crosses itself"
    words = ", ".join(f"{a:g}" if a == b else f"{a:g} to {b:g}" for a, b in crossing_runs(at))
    return f"The outline crosses itself at t = {words}"
