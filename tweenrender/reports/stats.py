"""The ``stats`` report: the thesis's ch. 6 perimeter measures per shape, segment and method."""

from __future__ import annotations

from typing import Any, Sequence

from ..core.measures import report
from ..core.qcurves import auto_choice
from ..model import Scene
from .segments import entries

__all__ = ["stats_dict", "stats_text", "STATS_METHODS"]

STATS_METHODS = ("linear", "nonlinear", "rigid")


def stats_dict(scene: Scene, t: Sequence[float]) -> dict[str, Any]:
    """The thesis's ch. 6 report for every shape and segment (the documented ``stats --json``)."""
    shapes = []
    for entry in entries(scene, closed_only=True):
        pair, joints = entry.pair, entry.segment.joints
        methods = STATS_METHODS + (("jointed",) if joints else ())
        choice = auto_choice(pair.k0, pair.k1, joints)
        shapes.append({
            **entry.head(),
            "vertices": list(pair.counts),
            "balanced": len(pair.k0),
            "auto": {"method": choice.method, "why": choice.why},
            "methods": {m: report(pair.k0, pair.k1, m, t, joints).as_dict() for m in methods},
        })
    return {"scene": str(scene.path) if scene.path else None, "shapes": shapes}


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
    if not stats["shapes"]:
        lines.append("no shape has two keys: nothing moves")
    return "\n".join(lines)
