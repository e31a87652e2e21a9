"""The ``correspond`` report: per shape and segment, the vertex pairs the renderer uses and their work.

Built on :func:`core.timeline.build_track`, so the pairs are exactly those the
frames are drawn with: the least-work path where the two keys' vertex counts
differ, the drawn order (vertex i with vertex i) where they agree. For the
drawn order the optimum's work is reported too (``minimal_work``), so a user
can see how far the animator's own correspondence is from the least-work one.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np
from numpy.typing import NDArray

from ..core.correspondence.correspond import correspond, correspond_open, path_work
from ..core.correspondence.hints import segment_links
from ..model import Matching, Scene
from .segments import entries, nothing_measured

if TYPE_CHECKING:
    from ..raster.plots.match_picture import CPanel

__all__ = ["MINIMAL", "DRAWN", "inserted", "correspond_dict", "entry_line", "correspond_text",
           "matching_words", "report_panels", "report_picture",
           "write_match_picture"]

MINIMAL = "minimal work"
DRAWN = "drawn order"


def inserted(indices: NDArray[np.intp], count: int) -> list[int]:
    """Vertices of a ``count``-vertex key duplicated by a path column ``indices (L,)``.

    Each vertex appears once per extra copy, in index order, so the list has
    ``L - count`` entries: ``[3, 7, 7]`` is vertex 3 twice and vertex 7 three times.
    """
    copies = np.bincount(np.asarray(indices), minlength=count)
    return [int(i) for i in np.repeat(np.arange(count), np.maximum(copies - 1, 0))]


def correspond_dict(scene: Scene, matching: Matching | None = None) -> dict[str, Any]:
    """The documented ``correspond --json``: one entry per shape and segment (static shapes have none).

    ``matching`` defaults to the scene's ``[correspondence]``. ``work`` is the
    cost of the reported ``pairs`` under it (the sum of ``|A_i - B_j|`` after the
    alignment, or the S&G energy); ``minimal_work`` is the least cost any closed
    monotone path reaches. Where the drawn order is kept, ``minimal_pairs`` and
    ``minimal_reversed`` give that least-cost path too (the renderer does not use it). Where a contour
    without room was joined into the pair's by a slit (maths §5.17), ``joined_contours`` holds the two
    contours as paired (``a``, ``b``: scene units), which ``counts`` and ``pairs`` refer to.
    """
    matching = matching or scene.matching
    shapes = []
    for entry in entries(scene, matching):
        index, (i, j) = entry.index, entry.pair.source
        a = entry.shape.keys[index].contours[i].points  # type: ignore[index]
        b = entry.shape.keys[index + 1].contours[j].points  # type: ignore[index]
        if entry.pair.joined is not None:  # a contour without room joined into it: the pairs index these
            a, b = entry.pair.joined
        closed = entry.pair.closed
        found = entry.pair.correspondence
        if len(a) < 2 or len(b) < 2:  # a single point pairs with every vertex of the other
            continue
        if found is None:  # equal counts: the renderer keeps the animator's order
            pairs = np.column_stack([np.arange(len(a)), np.arange(len(b))]).astype(np.intp)
            work, reversed_, matched = path_work(a, b, pairs, matching, closed), False, DRAWN
            best = correspond(a, b, matching) if closed else correspond_open(a, b, matching)
            minimal, extra = best.work, {"minimal_pairs": best.pairs.tolist(),
                                         "minimal_reversed": best.reversed}
        else:
            pairs, work, reversed_, matched = found.pairs, found.work, found.reversed, MINIMAL
            minimal, extra = found.work, {}
        shapes.append({
            **entry.head(),
            "key_contours": [i, j],
            "closed": closed,
            "counts": [len(a), len(b)],
            "balanced": int(len(pairs)),
            "work": float(work),
            "minimal_work": float(minimal),
            "cost": matching.cost,
            "align": matching.align,
            "equal_counts": matching.equal_counts,
            "reversed": bool(reversed_),
            "matched": matched,
            "inserted": {"a": inserted(pairs[:, 0], len(a)), "b": inserted(pairs[:, 1], len(b))},
            "pairs": pairs.tolist(),
            **extra,
        })
        if entry.pair.joined is not None:
            shapes[-1]["joined_contours"] = {"a": np.asarray(a).tolist(), "b": np.asarray(b).tolist()}
        hints = [{"letter": link.letter, "a": link.a[1], "b": link.b[1]}
                 for link in segment_links(entry.shape.keys[index].hints, entry.shape.keys[index + 1].hints)
                 if (link.a[0], link.b[0]) == (i, j)]
        if hints:
            shapes[-1]["hints"] = hints
    out = {"scene": str(scene.path) if scene.path else None, "cost": matching.cost,
           "align": matching.align, "equal_counts": matching.equal_counts, "shapes": shapes}
    if not shapes:
        out["note"] = nothing_measured(scene, closed_only=False)
    return out


def matching_words(cost: str, align: str) -> str:
    """``"distance, centroid-aligned"`` or ``"sg, as placed"``."""
    return f"{cost}, {'centroid-aligned' if align == 'centroid' else 'as placed'}"


def _indices(values: list[int]) -> str:
    """``[3, 7, 7]`` → ``"3, 7 ×3"`` (a vertex listed k times has k + 1 copies)."""
    if not values:
        return "none"
    counts: dict[int, int] = {}
    for v in values:
        counts[v] = counts.get(v, 0) + 1
    return ", ".join(str(v) if k == 1 else f"{v} ×{k + 1}" for v, k in counts.items())


def entry_line(entry: dict[str, Any]) -> str:
    """One line per shape segment: counts, balance, work, and where vertices were inserted."""
    m, n = entry["counts"]
    how = matching_words(entry["cost"], entry["align"])
    line = f"{entry['name']}, segment {entry['segment']}: {m} → {n} vertices, "
    if entry["matched"] == DRAWN:
        line += (f"drawn order kept ({m} pairs), work {entry['work']:.4g} ({how}); "
                 f"least-work path would cost {entry['minimal_work']:.4g}")
        return line
    line += f"balanced to {entry['balanced']}, work {entry['work']:.4g} ({how})"
    if entry["reversed"]:
        line += ", second key walked backwards"
    ins = entry["inserted"]
    return line + f"; vertices inserted: a: {_indices(ins['a'])}; b: {_indices(ins['b'])}"


def correspond_text(report: dict[str, Any]) -> str:
    """The report as text: the scene, then one line per shape and segment."""
    lines = [f"{report['scene']}"]
    lines += [entry_line(entry) for entry in report["shapes"]]
    if not report["shapes"]:
        lines.append(report.get("note", "no shape has two keys: nothing to put in correspondence"))
    return "\n".join(lines)


def report_panels(scene: Scene, report: dict[str, Any]) -> list[CPanel]:
    """One picture panel per entry of :func:`correspond_dict`'s ``shapes``."""
    from ..raster.plots.match_picture import CPanel as _CPanel

    shapes = {shape.name: shape for shape in scene.shapes}
    panels = []
    for e in report["shapes"]:
        keys = shapes[e["name"]].keys
        m, n = e["counts"]
        how = matching_words(e["cost"], e["align"])
        if e["matched"] == DRAWN:
            title = f"{e['name']}, segment {e['segment']}: {m} → {n} vertices, drawn order kept"
            words = (f"work {e['work']:.4g} ({how}); the least-work path would cost "
                     f"{e['minimal_work']:.4g}")
        else:
            title = f"{e['name']}, segment {e['segment']}: {m} → {n} vertices, balanced to {e['balanced']}"
            words = f"minimal work {e['work']:.4g} ({how})"
            if e["reversed"]:
                words += "; b winds the other way and is walked backwards"
        i, j = e.get("key_contours", (0, 0))
        a = np.asarray(keys[e["segment"]].contours[i].points)
        b = np.asarray(keys[e["segment"] + 1].contours[j].points)
        if "joined_contours" in e:
            a, b = np.asarray(e["joined_contours"]["a"]), np.asarray(e["joined_contours"]["b"])
        hints = tuple((h["letter"], h["a"], h["b"]) for h in e.get("hints", ()))
        if hints:
            words += f"; hints {', '.join(h[0] for h in hints)} pin their points"
        panels.append(_CPanel(title, words, a, b, np.asarray(e["pairs"], dtype=np.intp).reshape(-1, 2), hints))
        if "minimal_pairs" in e:
            # Shown beside the drawn order so the two can be compared; rendering keeps the drawn order.
            best = np.asarray(e["minimal_pairs"], dtype=np.intp).reshape(-1, 2)
            words = (f"not used (equal counts keep the drawn order): work {e['minimal_work']:.4g} "
                     f"({how})" + ("; b walked backwards" if e.get("minimal_reversed") else ""))
            panels.append(_CPanel(f"{e['name']}, segment {e['segment']}: the least-work path, "
                                 f"balanced to {len(best)}", words, a, b, best))
    return panels


def report_picture(scene: Scene, report: dict[str, Any], width: int = 960) -> NDArray[np.uint8]:
    """The ``correspond`` picture of a report: straight RGBA ``(H, W, 4)``."""
    from ..raster.plots.match_picture import correspond_picture

    return correspond_picture(report_panels(scene, report), width)


def write_match_picture(scene: Scene, report: dict[str, Any], target: Path) -> Path:
    """Draw the report's pairs (:func:`report_picture`) and write them to ``target`` as PNG, atomically."""
    from ..encode.images import write_png

    return write_png(report_picture(scene, report), target, "the picture")
