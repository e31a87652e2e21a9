"""Group opacity drawn with skia: the shapes of one group go into one layer, drawn down at the group's opacity.

Shapes are drawn in paint order; each names the groups it is in, outermost first (``(number, opacity)``).
Moving from one shape to the next closes the layers of the groups the next is not in and opens those it
enters, so the shapes of a group drawn one after another are composited together first (SVG 1.1 §14.5).
"""

from __future__ import annotations

from collections.abc import Sequence

import skia

__all__ = ["GroupLayers"]


class GroupLayers:
    """The group layers open on ``canvas``; :meth:`enter` before each shape, ``enter(())`` at the end."""

    def __init__(self, canvas: skia.Canvas) -> None:
        self.canvas = canvas
        self.open: list[tuple[int, float]] = []

    def enter(self, groups: Sequence[tuple[int, float]]) -> None:
        """Make ``groups`` (outermost first) the open layers: close the others, open the missing ones."""
        common = 0
        while common < min(len(self.open), len(groups)) and self.open[common] == tuple(groups[common]):
            common += 1
        while len(self.open) > common:
            self.canvas.restore()
            self.open.pop()
        for number, opacity in groups[common:]:
            self.canvas.saveLayerAlpha(None, max(0, min(255, int(round(255 * float(opacity))))))
            self.open.append((int(number), float(opacity)))
