"""The ``qcurves`` report: Q-curve control points, motion class and auto's choice, as data and text.

Built per shape and segment on the balanced keys of :func:`core.timeline.build_track`,
so vertex indices are those of the balanced polygon (equal to the drawn ones when
the two keys have the same vertex count).
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

from ..core.methods import qcurves
from ..core.geometry import edge_lengths
from ..core.methods.joints import bodies
from ..core.timing.timeline import Pair, Segment, segment_choice
from ..model import Scene
from .segments import entries, nothing_measured

if TYPE_CHECKING:
    from numpy.typing import NDArray

    from ..raster.plots.qcurve_plot import QPanel

__all__ = ["REL_TOL", "segment_dict", "qcurves_dict", "qcurves_text", "motion_words", "report_panels", "report_picture",
           "write_qcurve_plot"]

REL_TOL = 1e-3
"""Tolerance on Q values relative to the mean squared edge length, as :func:`qcurves.classify`."""


def _tolerance(k0: np.ndarray, k1: np.ndarray) -> float:
    # The same scale classify() uses, so per-vertex kinds agree with the shape's class.
    lengths = np.concatenate([edge_lengths(k0), edge_lengths(k1)])
    return REL_TOL * float((lengths * lengths).mean()) if lengths.size else 0.0


def _motion(k0: np.ndarray, k1: np.ndarray) -> dict[str, Any]:
    motion = qcurves.classify(k0, k1, REL_TOL)
    return {"motion": motion.kind, "rotation_deg": motion.rotation_deg, "why": motion.why}


def segment_dict(segment: Segment, pair: Pair | None = None) -> dict[str, Any]:
    """One segment's report (of ``pair``, default its only contour): motion, auto's choice,
    per-body motion and per-vertex Q-curves."""
    pair = pair or segment.pairs[0]
    k0, k1 = np.asarray(pair.k0), np.asarray(pair.k1)
    q = qcurves.control_points(k0, k1)
    kinds = qcurves.vertex_kinds(q, _tolerance(k0, k1))
    through = qcurves.passes_through_zero(q)
    turning_back = qcurves.non_monotonic(q)
    over = qcurves.sweeps_over_180(q)
    choice = segment_choice(segment) or qcurves.auto_choice(k0, k1, segment.joints)  # what render draws
    pairs = (pair.correspondence.pairs.tolist() if pair.correspondence is not None
             else [[i, i] for i in range(len(k0))])
    out: dict[str, Any] = {
        "times": [segment.start, segment.end],
        **_motion(k0, k1),
        "auto": {"method": choice.method, "balance": choice.balance, "why": choice.why},
        "joints": [list(j) for j in segment.joints],
    }
    if segment.joints:
        out["bodies"] = [{"vertices": b.tolist(), **_motion(k0[b], k1[b]), "auto": method}
                         for b, method in zip(bodies(len(k0), segment.joints), choice.bodies)]
    out["vertices"] = [{
        "index": i,
        "key_vertices": [int(a) for a in pairs[i]],
        "q0": q[i, 0].tolist(), "q1": q[i, 1].tolist(), "q2": q[i, 2].tolist(),
        "kind": kinds[i],
        "through_zero": bool(through[i]),
        "non_monotonic": bool(turning_back[i]),
        "sweeps_over_180": bool(over[i]),
    } for i in range(len(k0))]
    return out


def qcurves_dict(scene: Scene) -> dict[str, Any]:
    """The documented ``qcurves --json``: one entry per shape and segment (static shapes have none)."""
    shapes = []
    for entry in entries(scene, closed_only=True):
        shapes.append({**entry.head(), **segment_dict(entry.segment, entry.pair)})
    out: dict[str, Any] = {"scene": str(scene.path) if scene.path else None, "shapes": shapes}
    if not shapes:
        out["note"] = nothing_measured(scene)
    return out


def motion_words(entry: dict[str, Any]) -> str:
    """``"rigid rotation of 90.0 degrees → auto uses nonlinear"`` for one shape entry."""
    return f"{entry['why']} → auto uses {entry['auto']['method']}"


def _pair(p: list[float]) -> str:
    return f"({p[0]:.4g}, {p[1]:.4g})"


def qcurves_text(report: dict[str, Any]) -> str:
    """Per shape and segment: the motion in words, per-body motion, then a table of vertices."""
    lines = [f"{report['scene']}"]
    for entry in report["shapes"]:
        start, end = entry["times"]
        contour = f", contour {entry['contour']}" if "contour" in entry else ""
        lines += ["", f"{entry['name']}, segment {entry['segment']}{contour} ({start:g} s to {end:g} s): "
                      f"{motion_words(entry)}"]
        for k, body in enumerate(entry.get("bodies", [])):
            lines.append(f"  body {k} (vertices {', '.join(map(str, body['vertices']))}): "
                         f"{body['why']} → {body['auto']}")
        rows = [("vertex", "kind", "through zero", "Q0", "Q1", "Q2")]
        for v in entry["vertices"]:
            flags = "yes" if v["through_zero"] else "no"
            if v["non_monotonic"]:
                flags += ", turns back"
            if v["sweeps_over_180"]:
                flags += ", sweeps >180°"
            rows.append((str(v["index"]), v["kind"], flags, _pair(v["q0"]), _pair(v["q1"]), _pair(v["q2"])))
        widths = [max(len(r[c]) for r in rows) for c in range(len(rows[0]))]
        for r in rows:
            cells = [r[0].rjust(widths[0])] + [c.ljust(w) for c, w in zip(r[1:], widths[1:])]
            lines.append("  " + "  ".join(cells).rstrip())
    if not report["shapes"]:
        lines.append(report.get("note", "no shape has two keys: nothing moves"))
    return "\n".join(lines)


def report_panels(report: dict[str, Any]) -> list[QPanel]:
    """One plot panel per entry of :func:`qcurves_dict`'s ``shapes``."""
    from ..raster.plots.qcurve_plot import QPanel as _QPanel

    return [_QPanel(
        title=f"{e['name']}, segment {e['segment']} ({e['times'][0]:g}–{e['times'][1]:g} s)",
        subtitle="\n".join([motion_words(e)] + [
            f"body {k} ({', '.join(map(str, b['vertices']))}): {b['why']} → {b['auto']}"
            for k, b in enumerate(e.get("bodies", []))]),
        q=np.array([[v["q0"], v["q1"], v["q2"]] for v in e["vertices"]], dtype=np.float64).reshape(-1, 3, 2),
        through_zero=np.array([v["through_zero"] for v in e["vertices"]], dtype=bool),
    ) for e in report["shapes"]]


def report_picture(report: dict[str, Any]) -> NDArray[np.uint8]:
    """The ``qcurves`` plot of a report: straight RGBA ``(H, W, 4)``."""
    from ..raster.plots.qcurve_plot import qcurves_picture

    return qcurves_picture(report_panels(report), **({"note": report["note"]} if "note" in report else {}))


def write_qcurve_plot(report: dict[str, Any], target: Path) -> Path:
    """Draw the report's Q-curves (:func:`report_picture`) and write them to ``target`` as PNG, atomically."""
    from ..encode.images import write_png

    return write_png(report_picture(report), target, "the plot")
