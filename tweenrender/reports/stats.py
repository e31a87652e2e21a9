"""The ``stats`` report: the thesis's ch. 6 perimeter measures per shape, segment and method."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ..core.coverage import Grid
from ..core.measures import SWEEP, report
from ..core.methods.intrinsic import closure_tweak
from ..core.methods.qcurves import AutoChoice, auto_choice
from ..core.methods.registry import REGISTRY, measured_methods
from ..core.pops import changes, frames_digest, pops
from ..core.stray import STRAY_REACH, Area, stray_shares, stroke_stray_shares
from ..core.tangles import contact_times
from ..core.timing.timeline import (ShapeAt, Track, evaluate_segment, injective_fallback_of, segment_choice,
                                    tracks_of)
from ..core.view import Viewport
from ..model import Scene, Shape
from ..plan.job import scene_view, total_frames
from .segments import Entry, SegmentPaths, entries, nothing_measured, other_entries

__all__ = ["stats_dict", "stats_text", "auto_words", "fallback_words", "others_words", "crossing_runs", "STATS_METHODS",
           "POP_CELLS"]

Array = NDArray[np.float64]

POP_CELLS = 128
"""Cells along the view's larger side of the grid ``pops`` compares frames on."""

_STRAY_ROWS = np.arange(0, len(SWEEP), 5)
STRAY_SWEEP = SWEEP[_STRAY_ROWS]
"""The t at which ``stray_max`` is measured (maths §5.16): k/20, every fifth t of :data:`SWEEP`."""

STATS_METHODS = measured_methods(jointed=False)
"""Every method measured on every segment (and those that need joints where the shape has them)."""



def stats_dict(scene: Scene, t: Sequence[float], methods: Sequence[str] | None = None) -> dict[str, Any]:
    """The thesis's ch. 6 report and the quality measures for every shape and segment (the documented
    ``stats --json``): for ``methods``, default every method (``jointed`` where a shape has joints)."""
    shapes = []
    quality: dict[tuple[int, int, str], _Quality] = {}
    paths = SegmentPaths()
    filled_in: list[tuple[dict[str, Any], _Quality]] = []
    every: dict[str, None] = dict.fromkeys(methods or ())
    for entry in entries(scene, closed_only=True):
        pair, joints = entry.pair, entry.segment.joints
        names = tuple(methods) if methods is not None else measured_methods(jointed=bool(joints))
        every.update(dict.fromkeys(names))
        choice = segment_choice(entry.segment) or auto_choice(pair.k0, pair.k1, joints)  # what render draws
        measured = {m: report(pair.k0, pair.k1, m, t, joints, _as_drawn(entry, m, paths)).as_dict()
                    for m in names}
        for method in measured:
            found = _quality(entry, method, quality, paths)
            measured[method].update(crossings=list(found.crossings), stroke_crossings=list(found.strokes))
            if method == "injective":  # where no injective morph exists, say why rigid paths were drawn
                measured[method]["fallback"] = injective_fallback_of(entry.segment)
            filled_in.append((measured[method], found))
            closure = REGISTRY[method].closure
            if closure is not None:  # how much the closing tweak changed the lengths, at worst
                measured[method]["closure_tweak_max"] = float(closure_tweak(pair.k0, pair.k1, SWEEP, closure).max())
        shapes.append({
            **entry.head(),
            "vertices": list(pair.counts),
            "balanced": len(pair.k0),
            "auto": _auto_of(choice, scene, entry.shape),
            "methods": measured,
        })
    others = [_other_entry(entry, scene, methods, every, quality, paths, filled_in) for entry in other_entries(scene)]
    # the view is worked out last: some methods keep what they worked out for the next call, so the
    # measures above see the calls in the order they always did
    tracks = tracks_of(scene)
    view = scene_view(scene, tracks, (None,))
    reach = STRAY_REACH * max(view[2] - view[0], view[3] - view[1])
    for measures, found in filled_in:
        if found.areas:
            measures["stray_max"] = found.stray_max(reach)
        if found.lines and found.lines[0]:
            measures["stroke_stray_max"] = found.stroke_stray_max(reach)
    out: dict[str, Any] = {"scene": str(scene.path) if scene.path else None, "shapes": shapes, "others": others}
    if not shapes:
        out["note"] = _OTHERS_ONLY if others else nothing_measured(scene)
    measured_changes: dict[tuple[int, bytes], Array] = {}
    out["pops"] = {m: _pops(scene, tracks, view, m, measured_changes) for m in (every or STATS_METHODS)}
    return out


_OTHERS_ONLY = ("no closed contour is in both keys of a segment: the thesis's measures need closed outlines; "
                "the open strokes and the contours that grow or shrink are measured for tangles (OTHERS)")


def _other_entry(entry: Entry, scene: Scene, methods: Sequence[str] | None, every: dict[str, None],
                 quality: dict[tuple[int, int, str], "_Quality"], paths: SegmentPaths,
                 filled_in: list[tuple[dict[str, Any], "_Quality"]]) -> dict[str, Any]:
    """A segment with no closed contour in both keys (``others`` in ``stats --json``): its open strokes and
    its contours growing or shrinking, what auto draws (None where no contour is in both keys), and per
    method where the element tangles and its strokes cross (and why ``injective`` drew rigid paths). No
    ``stray_max`` (no outline in both keys encloses an area); its strokes' stray is filled in later, with
    the view (``filled_in``)."""
    segment = entry.segment
    names = tuple(methods) if methods is not None else measured_methods(jointed=bool(segment.joints))
    every.update(dict.fromkeys(names))
    choice = segment_choice(segment)
    measured: dict[str, dict[str, Any]] = {}
    for method in names:
        found = _quality(entry, method, quality, paths, areas=False)
        measured[method] = {"crossings": list(found.crossings), "stroke_crossings": list(found.strokes)}
        filled_in.append((measured[method], found))
        if method == "injective":
            measured[method]["fallback"] = injective_fallback_of(segment)
    head = entry.head()
    head.pop("contour", None)
    drawn = [pair for pair in segment.pairs if not pair.fades]
    return {**head, "strokes": sum(1 for pair in drawn if not pair.closed),
            "growing": sum(1 for pair in drawn if not pair.moving),
            "auto": None if choice is None else _auto_of(choice, scene, entry.shape),
            "methods": measured}


def _auto_of(choice: AutoChoice, scene: Scene, shape: Shape) -> dict[str, Any]:
    """An entry's ``auto``: what render draws (the method, its balance: the choice's, else the shape's) and why."""
    return {"method": choice.method, "balance": choice.balance or scene.balance_of(shape), "why": choice.why}


@dataclass(slots=True)
class _Quality:
    """One shape's quality in one segment under one method: its tangled t over :data:`SWEEP`, and its
    drawn areas and open strokes (``lines``, ``(L_i, 2)`` each) over :data:`STRAY_SWEEP`, whose stray waits for
    the view, with every contour of both keys (``keys``: points, closed) the strokes' stray is measured from."""

    crossings: list[float]
    strokes: list[float]
    areas: list[Area]
    lines: list[list[Array]]
    keys: list[tuple[Array, bool]]
    stray: float | None = None
    stroke_stray: float | None = None

    def stray_max(self, reach: float) -> float:
        """The largest :func:`~tweenrender.core.stray.stray_shares` of the areas (``reach`` in scene units,
        the same every time it is asked)."""
        if self.stray is None:
            self.stray = float(stray_shares(self.areas, self.areas[0], self.areas[-1], reach).max())
        return self.stray

    def stroke_stray_max(self, reach: float) -> float:
        """The largest share of the open strokes' length farther than ``reach`` from both keys, their areas and
        their contours (:func:`~tweenrender.core.stray.stroke_stray_shares`: what a viewer sees of a stroke
        swinging out, which encloses no area)."""
        if self.stroke_stray is None:
            areas = (self.areas[0], self.areas[-1]) if self.areas else (([], "nonzero"), ([], "nonzero"))
            self.stroke_stray = float(stroke_stray_shares(self.lines, *areas, self.keys, reach).max(initial=0.0))
        return self.stroke_stray


def _quality(entry: Entry, method: str, done: dict[tuple[int, int, str], _Quality],
             paths: SegmentPaths, areas: bool = True) -> _Quality:
    """The entry's shape's quality in its segment under ``method`` (docs/methods.md): ``crossings`` and
    ``stroke_crossings`` (:func:`~tweenrender.core.tangles.contact_times`, over every contour drawn
    through the segment, growing and shrinking ones too), and (with ``areas``) the areas ``stray_max`` is measured on."""
    key = (id(entry.shape), entry.index, method)
    if key not in done:
        segment = entry.segment
        frames = paths(segment, SWEEP, method)
        # every contour drawn through the segment: those growing from (shrinking to) a point too, whose
        # key there is that point
        drawn_through = [k for k, p in enumerate(segment.pairs) if not p.fades]
        crossings, strokes = contact_times([frames[k] for k in drawn_through],
                                           [segment.pairs[k].closed for k in drawn_through], SWEEP,
                                           [frames[k][0] for k in drawn_through],
                                           [frames[k][-1] for k in drawn_through])
        few = [f[_STRAY_ROWS] for f in frames]
        drawn = [_area(at, entry.shape) for at in evaluate_segment(segment, STRAY_SWEEP, method, few)] if areas else []
        stroked = [k for k in drawn_through if not segment.pairs[k].closed]
        lines = [[frames[k][row] for k in stroked] for row in _STRAY_ROWS]
        keys = [(frames[k][end], segment.pairs[k].closed) for k in drawn_through for end in (0, -1)]
        done[key] = _Quality(crossings, strokes, drawn, lines, keys)
    return done[key]


def _rule(at: ShapeAt, shape: Shape) -> str:
    """The fill rule ``at`` is drawn with: its key's, else its shape's."""
    return (at.key.fill_rule if at.key is not None else None) or shape.fill_rule


def _area(at: ShapeAt, shape: Shape) -> Area:
    """The area the closed contours of ``at`` enclose as drawn (windings, fill rule)."""
    turned = at.reversed or (False,) * len(at.contours)
    return ([c[::-1] if back else c for c, shut, back in zip(at.contours, at.closed, turned) if shut and len(c) >= 3],
            _rule(at, shape))


def _pops(scene: Scene, tracks: Sequence[Track], view: tuple[float, float, float, float], method: str,
          measured: dict[tuple[int, bytes], Array]) -> list[int]:
    """The frames of the clip that pop under ``method`` (:mod:`~tweenrender.core.pops`), on a grid of
    :data:`POP_CELLS` cells along the view's larger side. A shape's change is worked out once for frames drawn
    alike (``measured``, by shape and :func:`~tweenrender.core.pops.frames_digest`, shared by the methods: a
    shape that has no partner grows, shrinks or fades alike under every method)."""
    grid = Grid.over(view, max(view[2] - view[0], view[3] - view[1]) / POP_CELLS)
    pixel = 1.0 / Viewport(view, *scene.size).scale  # a stroke width in pixels, in scene units
    times = np.arange(total_frames(scene)) / scene.fps
    change = np.zeros(len(times))
    for k, (track, shape) in enumerate(zip(tracks, scene.shapes)):
        drawn = track.at(times, method)
        rules = [_rule(at, shape) for at in drawn]
        key = (k, frames_digest(drawn, rules))
        if key not in measured:
            measured[key] = changes(grid, drawn, rules, 1.0 if shape.stroke_scales else pixel)
        change += measured[key]
    return pops(change)


def _as_drawn(entry: Entry, method: str, paths: SegmentPaths) -> Callable[[Any], Any]:
    """The contour's inbetweens as drawn: the segment's paths, shared with its other contours and its quality
    (a lone outline's, unsteered, are the method's own paths, the very same call)."""
    segment = entry.segment
    index = entry.contour or 0
    return lambda t: paths(segment, t, method)[index]


def stats_text(stats: dict[str, Any]) -> str:
    """The report in the thesis's words, five decimals."""
    lines = [f"{stats['scene']}"]
    for shape in stats["shapes"]:
        start, end = shape["times"]
        m, n = shape["vertices"]
        contour = f", contour {shape['contour']}" if "contour" in shape else ""
        lines += ["", f"SHAPE {shape['name']}, segment {shape['segment']}{contour} ({start:g} s to {end:g} s), "
                      f"{m} and {n} vertices, {shape['balanced']} after balancing",
                  auto_words(shape["auto"])]
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
            if r.get("fallback"):
                lines.append(fallback_words(r["fallback"]))
            if "crossings" in r:
                lines += _quality_words(r)
            if "closure_tweak_max" in r:
                lines.append(f"Closing the walk changed the lengths by at most {100 * r['closure_tweak_max']:.2f} % "
                             "of the perimeter")
    for entry in stats.get("others", []):
        start, end = entry["times"]
        lines += ["", f"OTHERS {entry['name']}, segment {entry['segment']} ({start:g} s to {end:g} s): "
                      f"{others_words(entry)}", auto_words(entry["auto"])]
        for method, r in entry["methods"].items():
            lines += [f"{method.upper()} METHOD"] + _quality_words(r)
            if r.get("fallback"):
                lines.append(fallback_words(r["fallback"]))
    if not stats["shapes"]:
        lines += ["", stats.get("note", "no shape has two keys: nothing moves")]
    if stats.get("pops"):
        lines += ["", "POPS (frames changing over 3x the clip's median change)"]
        lines += [f"{method}: " + (f"frames {', '.join(map(str, at))}" if at else "none")
                  for method, at in stats["pops"].items()]
    return "\n".join(lines)


def _quality_words(r: dict[str, Any]) -> list[str]:
    """Where the shape tangles, where its strokes cross, and how far it strays, in a few words."""
    def runs(at: Sequence[float]) -> str:
        return ", ".join(f"{a:g}" if a == b else f"{a:g} to {b:g}" for a, b in crossing_runs(at))

    lines = [f"The shape tangles at t = {runs(r['crossings'])}" if r["crossings"] else
             "The shape never tangles (no crossing, no hole leaving, no contours meeting)"]
    if r.get("stroke_crossings"):
        lines.append(f"Its strokes cross at t = {runs(r['stroke_crossings'])}")
    if "stray_max" in r:
        lines.append(f"At most {100 * r['stray_max']:.1f} % of an inbetween strays from both keys")
    if "stroke_stray_max" in r:
        lines.append(f"At most {100 * r['stroke_stray_max']:.1f} % of its strokes' length strays from both keys")
    return lines


def auto_words(auto: dict[str, Any] | None) -> str:
    """What ``auto`` draws and why, from an entry's ``auto`` (method, balance, why; None where no contour is in
    both keys): one sentence."""
    if auto is None:
        return "auto has no contour in both keys to choose over: each grows from or shrinks to a point"
    return f"auto draws {auto['method']} (balance {auto['balance']}): {auto['why']}"


def others_words(entry: dict[str, Any]) -> str:
    """What an entry of ``others`` draws through its segment: ``"2 open strokes, 1 contour growing or
    shrinking"``."""
    def counted(n: int, what: str) -> str:
        return f"{n} {what}{'' if n == 1 else 's'}"

    parts = [counted(entry["strokes"], "open stroke")] if entry["strokes"] else []
    if entry["growing"]:
        parts.append(counted(entry["growing"], "contour") + " growing or shrinking")
    return ", ".join(parts) or "nothing drawn through"


def fallback_words(reason: str) -> str:
    """Why ``injective`` drew rigid paths (an entry's ``fallback``): one sentence."""
    return f"No injective morph: {reason}; the rigid paths are drawn"


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
