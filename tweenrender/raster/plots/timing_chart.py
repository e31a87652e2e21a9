"""The animator's marks on a storyboard: timing charts between keys, and shape hints as lettered dots.

A *timing chart* is drawn as an animator draws one on a key drawing: a line from the first
key's centre to the second's, with a tick where each frame of the segment falls along the way
(the fraction of the way its easing gives at that frame's time), long ticks at the keys. Evenly
spaced ticks are linear timing; bunched ticks at an end are a slow in or out; ticks past an end
are an overshoot; ticks piled on one spot are a hold or a step.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ...core.timing.timeline import Segment, Track, pair_paths
from ...model import Color, Scene, Shape
from ..painter import Painter
from ...core.view import Viewport

__all__ = ["chart_ticks", "draw_timing_charts", "draw_hint_marks", "hint_paths"]

_CHART: Color = (200, 60, 40, 255)
_HINT: Color = (120, 40, 170, 255)
_WHITE: Color = (255, 255, 255, 255)


def chart_ticks(segment: Segment, fps: float) -> NDArray[np.float64]:
    """The fraction of the way at each frame time inside ``segment`` (keys included): ``(F,)``."""
    first = int(np.ceil(segment.start * fps - 1e-9))
    last = int(np.floor(segment.end * fps + 1e-9))
    times = np.arange(first, last + 1) / fps
    return segment.local_t(times)


def _centre(shape: Shape, index: int) -> NDArray[np.float64]:
    return np.concatenate([c.points for c in shape.keys[index].contours]).mean(axis=0)


def draw_timing_charts(painter: Painter, port: Viewport, offset: tuple[float, float], scene: Scene,
                       tracks: Sequence[Track], fps: float) -> None:
    """Each segment of each moving shape: its chart between the keys' centres (pixels of ``port`` moved by
    ``offset``). A segment whose keys share a centre gets its chart under the first key, 60 px long."""
    s = painter.scale
    shift = np.array(offset)
    for shape, track in zip(scene.shapes, tracks):
        for k, segment in enumerate(track.segments):
            a = port.to_pixels(_centre(shape, k)[None])[0] + shift
            b = port.to_pixels(_centre(shape, k + 1)[None])[0] + shift
            if np.hypot(*(b - a)) < 8 * s:
                a = a + np.array([-30.0, 30.0]) * s
                b = a + np.array([60.0, 0.0]) * s
            along = (b - a) / max(float(np.hypot(*(b - a))), 1e-9)
            across = np.array([-along[1], along[0]])
            painter.line(a, b, _CHART, 1.0, 0.7)
            ticks = chart_ticks(segment, fps)
            for t in ticks.tolist():
                at = a + t * (b - a)
                key = t in (0.0, 1.0)
                half = (6.0 if key else 3.0) * s
                painter.line(at - half * across, at + half * across, _CHART, 1.3 if key else 0.8, 1.0 if key else 0.8)


def hint_paths(segment: Segment, method: str, samples: int = 65) -> list[NDArray[np.float64]]:
    """The path each hinted point travels through ``segment`` under ``method``: one ``(samples, 2)`` array
    per hint (world units), from its point on the first key to its partner on the second."""
    t = np.linspace(0.0, 1.0, samples)
    out = []
    frames: list[NDArray[np.float64]] | None = None
    for link in segment.links:
        for k, pair in enumerate(segment.pairs):
            found = pair.correspondence
            if pair.source != (link.a[0], link.b[0]) or found is None:
                continue
            rows = np.flatnonzero((found.pairs[:, 0] == link.a[1]) & (found.pairs[:, 1] == link.b[1]))
            if len(rows):
                frames = frames if frames is not None else pair_paths(segment, t, method)
                out.append(frames[k][:, int(rows[0])])
    return out


def draw_hint_marks(painter: Painter, port: Viewport, offset: tuple[float, float], shapes: Sequence[Shape],
                    tracks: Sequence[Track] = (), method: str = "linear") -> None:
    """Every shown key's hints as lettered dots on their vertices, and (given ``tracks``) the paths the
    hinted points travel under ``method``."""
    s = painter.scale
    shift = np.array(offset)
    for track in tracks:
        for segment in track.segments:
            for path in hint_paths(segment, method):
                pixels = port.to_pixels(path) + shift
                for a, b in zip(pixels[:-1], pixels[1:]):
                    painter.line(a, b, _HINT, 1.2, 0.6)
    for shape in shapes:
        for key in shape.keys:
            if key.hidden:
                continue
            for hint in key.hints:
                point = port.to_pixels(key.contours[hint.contour].points[hint.vertex][None])[0] + shift
                painter.dot(point, 7.0, _HINT)
                painter.text(hint.letter, float(point[0]), float(point[1]) + 3.5 * s, 10, _WHITE, bold=True,
                             anchor="middle")
