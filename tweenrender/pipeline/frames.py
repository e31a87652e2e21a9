"""Draws the frames of a :class:`~tweenrender.plan.job.RenderJob` on the raster panels.

Every frame is a pure function of (scene, methods, frame index), so any range of
frames can be rendered on its own, in any process.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

from ..core.stacking import Switch, layered, order_at, order_at_key
from ..core.timing.timeline import ShapeAt, Track, tracks_of
from ..plan.job import RenderJob, scene_view, stacking_of

if TYPE_CHECKING:
    from ..raster.panels import Composer

__all__ = ["Frames"]

_BLOCK = 32  # frames whose polygons are evaluated in one vectorised call, at most ...
_BLOCK_POINTS = 1 << 20  # ... and vertices in a block (16 MiB of them): detailed scenes evaluate fewer frames at once


@dataclass
class Frames:
    """Draws the frames of a job; built lazily so it can be shipped to a worker process."""

    job: RenderJob
    layout: str = "rgba"  # "bgra": the surface's own premultiplied pixels (opaque backgrounds only)
    _tracks: tuple[Track, ...] | None = field(default=None, init=False, repr=False)
    _stacking: tuple[Switch, ...] | None = field(default=None, init=False, repr=False)
    _composer: Composer | None = field(default=None, init=False, repr=False)
    _blocks: dict[str | None, tuple[int, list[list[ShapeAt]]]] = field(default_factory=dict, init=False,
                                                                       repr=False)
    _block_frames: int = field(default=0, init=False, repr=False)
    _drawn: bool = field(default=False, init=False, repr=False)

    @property
    def tracks(self) -> tuple[Track, ...]:
        if self._tracks is None:
            self._tracks = self.job.tracks if self.job.tracks is not None else tracks_of(self.job.scene)
        return self._tracks

    @property
    def stacking(self) -> tuple[Switch, ...]:
        """Where the paint order switches between keys (each shape under its own method)."""
        if self._stacking is None:
            self._stacking = stacking_of(self.job.scene, self.tracks)
        return self._stacking

    def order_at(self, time: float) -> tuple[int, ...]:
        """The shapes' paint order at ``time`` seconds (indices into the scene's shapes); at a key time, the
        keys' own, with no plan worked out (a still of a key draws no in-between)."""
        at_key = order_at_key(self.job.scene.shapes, time) if self._stacking is None else None
        return at_key if at_key is not None else order_at(self.stacking, self.job.scene.shapes, time)

    def shapes_at(self, method: str | None, time: float) -> list[ShapeAt]:
        """Every shape as it is at ``time`` seconds under ``method`` (``None``: the shape's own)."""
        scene = self.job.scene
        return [track.at(np.array([time]), method or scene.method_of(shape))[0]
                for track, shape in zip(self.tracks, scene.shapes)]

    def frame_shapes(self, method: str | None, index: int) -> list[ShapeAt]:
        """Every shape at frame ``index``: ``shapes_at(method, index / fps)``, but evaluated for a block of
        frames at once (:meth:`block_frames`), so the per-call cost of numpy is paid once a block."""
        size = self.block_frames()
        block = index // size
        if self._blocks.get(method, (None,))[0] != block:
            self._blocks.pop(method, None)  # the previous block's outlines go before the next one's are made
            scene, times = self.job.scene, np.arange(block * size, (block + 1) * size) / self.job.rate
            self._blocks[method] = (block, [track.at(times, method or scene.method_of(shape))
                                            for track, shape in zip(self.tracks, scene.shapes)])
        return [per_time[index - block * size] for per_time in self._blocks[method][1]]

    def block_frames(self) -> int:
        """Frames evaluated in one block: ``_BLOCK``, fewer where a frame has so many vertices that a block
        would hold more than ``_BLOCK_POINTS`` (each shape counted at its most detailed key)."""
        if not self._block_frames:
            points = sum(max((sum(len(c.points) for c in key.contours) for key in shape.keys), default=0)
                         for shape in self.job.scene.shapes)
            self._block_frames = max(1, min(_BLOCK, _BLOCK_POINTS // max(points, 1)))
        return self._block_frames

    @property
    def composer(self) -> Composer:
        """The panels' drawing surface with the job's overlays, built on first use."""
        from ..raster.panels import Composer

        job = self.job
        if self._composer is None:
            labels = [m if job.labels else None for m in job.methods]
            width, height = job.panel_size
            view = scene_view(job.scene, self.tracks, job.methods)
            self._composer = Composer(job.scene, labels, width, height, view)
            if layered(job.scene.shapes):
                self._composer.stacking = self.order_at
            if job.paths or job.onion or job.strip:
                from ..raster.overlays import PanelOverlays, above_strip

                if job.strip:
                    self._composer.viewport = above_strip(self._composer.viewport)
                self._composer.layers.append(PanelOverlays(
                    job.scene, self.tracks, job.methods, self._composer.viewport, job.rate, self.shapes_at,
                    paths=job.paths, onion=job.onion, strip=job.strip))
        return self._composer

    def __call__(self, index: int) -> NDArray[np.uint8]:
        """Frame ``index`` as straight RGBA ``(height, width, 4)`` (a buffer reused by the next call),
        or as the surface's premultiplied BGRA when ``layout`` is ``"bgra"``."""
        panels = [self.frame_shapes(method, index) for method in self.job.methods]
        picture = self._draw(panels, index / self.job.rate)
        if not self._drawn:  # every kernel a frame needs is linked now: the compiler's code can go
            from ..pipeline.compiler_pages import page_out_compiler

            self._drawn = True
            page_out_compiler()
        return picture

    def at_time(self, time: float) -> NDArray[np.uint8]:
        """The picture at any ``time`` in seconds, on or between frames; reused like ``self(index)``."""
        return self._draw([self.shapes_at(method, time) for method in self.job.methods], time)

    def _draw(self, panels: list[list[ShapeAt]], time: float) -> NDArray[np.uint8]:
        return self.composer.draw(panels, time, self.layout)


