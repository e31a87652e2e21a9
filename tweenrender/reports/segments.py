"""The (shape, segment, contour) entries the reports are made of."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Iterator

from ..core.timeline import Pair, Segment, tracks_of
from ..model import Matching, Scene, Shape

__all__ = ["Entry", "entries"]


@dataclass(frozen=True, slots=True)
class Entry:
    """One contour of one segment of one shape; ``contour`` is ``None`` when the segment has only one."""

    shape: Shape
    index: int
    segment: Segment
    contour: int | None
    pair: Pair

    def head(self) -> dict[str, object]:
        """The fields every report entry starts with: name, segment (and contour), times."""
        out: dict[str, object] = {"name": self.shape.name, "segment": self.index}
        if self.contour is not None:
            out["contour"] = self.contour
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
