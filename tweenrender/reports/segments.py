"""The (shape, segment, contour) entries the reports are made of."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterator

import numpy as np
from numpy.typing import NDArray

from ..core.timing.timeline import Pair, Segment, pair_paths, tracks_of
from ..model import Matching, Scene, Shape

__all__ = ["Entry", "entries", "nothing_measured", "SegmentPaths", "other_entries"]


@dataclass(frozen=True, slots=True)
class Entry:
    """One contour of one segment of one shape; ``contour`` is ``None`` when the segment has only one."""

    shape: Shape
    index: int
    segment: Segment
    contour: int | None
    pair: Pair

    def head(self) -> dict[str, object]:
        """The fields every report entry starts with: name, segment (and contour), times; a drawing's
        entries also name their ``element`` (the SVG id, else the loader's name) and always a ``contour``."""
        out: dict[str, object] = {"name": self.shape.name, "segment": self.index}
        drawn = any(key.layer is not None for key in self.shape.keys)
        if drawn:
            out["element"] = self.shape.name
        if self.contour is not None or drawn:
            out["contour"] = self.contour if self.contour is not None else self.pair.source[0]
        out["times"] = [self.segment.start, self.segment.end]
        return out


def entries(scene: Scene, matching: Matching | None = None, closed_only: bool = False) -> Iterator[Entry]:
    """Every contour that moves through a segment (in both keys), shape by shape, segment by segment.

    Growing, shrinking and fading contours are left out, and segments where a whole element
    appears or goes; with ``closed_only`` open strokes too, and contours of fewer than three
    vertices, which have no angles or area.
    """
    for shape, track in zip(scene.shapes, tracks_of(scene, matching)):
        for index, segment in enumerate(track.segments):
            if not all(segment.shown):
                continue
            several = len(segment.pairs) > 1
            for k, pair in enumerate(segment.pairs):
                if not pair.moving or (closed_only and (not pair.closed or len(pair.k0) < 3)):
                    continue
                yield Entry(shape, index, segment, k if several else None, pair)


def other_entries(scene: Scene) -> Iterator[Entry]:
    """One entry for each segment that draws contours through it but has no closed contour in both keys,
    which :func:`entries` with ``closed_only`` leaves out: open strokes, contours growing from or shrinking
    to a point. Its first moving contour (else its first drawn through) stands for the segment."""
    for shape, track in zip(scene.shapes, tracks_of(scene)):
        for index, segment in enumerate(track.segments):
            drawn = [k for k, pair in enumerate(segment.pairs) if not pair.fades]
            if not all(segment.shown) or not drawn or any(
                    pair.moving and pair.closed and len(pair.k0) >= 3 for pair in segment.pairs):
                continue
            k = next((k for k in drawn if segment.pairs[k].moving), drawn[0])
            yield Entry(shape, index, segment, k if len(segment.pairs) > 1 else None, segment.pairs[k])


def nothing_measured(scene: Scene, closed_only: bool = True) -> str:
    """Why a report has no entry: nothing moves, or what moves is not measured."""
    if not any(len(shape.keys) > 1 for shape in scene.shapes):
        return "no shape has two keys: nothing moves"
    if not closed_only:
        return ("no contour is in both keys of a segment: every contour that moves grows from, shrinks to "
                "or fades at a key, with no partner to put in correspondence")
    return ("no closed contour is in both keys of a segment, so there is nothing to compare: open strokes and "
            "contours that grow, shrink or fade move, but are not measured")


class SegmentPaths:
    """Every pair's inbetweens of a segment under a method at some ``t``, worked out once for a report:
    :func:`~tweenrender.core.timing.timeline.pair_paths`, remembered by segment, method and ``t`` (each
    contour of a segment, and its quality, asks for the same). The arrays are shared: read, never written."""

    def __init__(self) -> None:
        self._found: dict[tuple[int, str, bytes], tuple[Segment, list[NDArray[np.float64]]]] = {}

    def __call__(self, segment: Segment, t: NDArray[np.float64], method: str) -> list[NDArray[np.float64]]:
        """``pair_paths(segment, t (T,), method)``: one ``(T, L_i, 2)`` array per pair."""
        t = np.asarray(t, dtype=np.float64)
        key = (id(segment), method, t.tobytes())
        if key not in self._found:  # the segment is kept with its paths, so its id is not reused meanwhile
            self._found[key] = (segment, pair_paths(segment, t, method))
        return self._found[key][1]
