"""The quality measures over t of every shape segment and method, as chart panels and a PNG."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING, Sequence

import numpy as np

from ..core.measures import SWEEP, curves
from ..model import Scene
from .segments import SegmentPaths, entries, nothing_measured

if TYPE_CHECKING:
    from numpy.typing import NDArray

    from ..raster.plots.metric_plot import MPanel

__all__ = ["PANELS", "metric_panels", "metrics_png", "write_metric_plot"]


PANELS = 12
"""At most this many panels (contours) are charted; the stats table lists every one."""


def metric_panels(scene: Scene, methods: Sequence[str]) -> list[MPanel]:
    """One panel per moving closed contour of a shape segment (a drawing's element and contour), the
    first :data:`PANELS`: each method's measures over :data:`~tweenrender.core.measures.SWEEP`."""
    from ..raster.plots.metric_plot import MPanel as _MPanel

    panels = []
    paths = SegmentPaths()  # each contour of a segment is one of the same pairs' paths
    for entry in entries(scene, closed_only=True):
        if len(panels) == PANELS:
            break
        segment, pair = entry.segment, entry.pair
        series, crossing = {}, {}
        for method in methods:
            steered = bool(segment.spin or segment.arcs)
            drawn = None if entry.contour is None and not steered else \
                paths(segment, SWEEP, method)[entry.contour or 0]
            found = curves(pair.k0, pair.k1, method, SWEEP, segment.joints, drawn)
            series[method] = {"perimeter_ratio": found.perimeter_ratio, "area_ratio": found.area_ratio,
                              "edge_error": found.edge_error, "angle_error": found.angle_error}
            crossing[method] = np.array([c is not None for c in found.crossings])
        m, n = pair.counts
        contour = "" if entry.contour is None else f", contour {entry.contour}"
        panels.append(_MPanel(
            title=f"{entry.shape.name}{contour}, segment {entry.index} ({segment.start:g}–{segment.end:g} s)",
            subtitle=f"{m} and {n} vertices, {len(pair.k0)} after balancing "
                     f"({scene.balance_of(entry.shape)}); t within the segment, before easing",
            t=SWEEP, series=series, crossing=crossing))
    return panels


def metrics_png(scene: Scene, methods: Sequence[str]) -> NDArray[np.uint8]:
    """The charts of :func:`metric_panels`: straight RGBA ``(H, W, 4)``."""
    from ..raster.plots.metric_plot import metrics_picture

    return metrics_picture(metric_panels(scene, methods), note=nothing_measured(scene))


def write_metric_plot(scene: Scene, methods: Sequence[str], target: Path) -> Path:
    """Draw the charts and write them to ``target`` as PNG, atomically."""
    from ..encode.images import write_png

    return write_png(metrics_png(scene, methods), target, "the charts")
