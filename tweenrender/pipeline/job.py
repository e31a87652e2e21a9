"""What to draw: a :class:`RenderJob` (scene, panels, size, frames, overlays) and :class:`Frames`,
which draws any frame of it.

Every frame is a pure function of (scene, methods, frame index), so any range of
frames can be rendered on its own, in any process.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ..core.stacking import Switch, layered, order_at, stacking_plan
from ..core.timeline import ShapeAt, Track, frame_count, tracks_of
from ..errors import OptionError
from ..model import Points, Scene
from ..raster.view import Box

if TYPE_CHECKING:
    from ..raster.panels import Composer

__all__ = ["RenderJob", "Frames", "Progress", "total_frames", "pick_frames", "tracks_of", "scene_view", "stacking_of"]

_BLOCK = 32  # frames whose polygons are evaluated in one vectorised call, at most ...
_BLOCK_POINTS = 1 << 20  # ... and vertices in a block (16 MiB of them): detailed scenes evaluate fewer frames at once
Progress = Callable[[int, int], None]
"""Called with ``(frames done, frames in all)`` as a render goes."""


def total_frames(scene: Scene, fps: float | None = None) -> int:
    """Frames of the whole scene at ``fps`` (default the scene's): the last key's frame included."""
    return frame_count(scene.duration, fps or scene.fps)


def pick_frames(spec: str | range | None, total: int) -> range:
    """The frames to render of a clip of ``total``: all (``None``), a ``range``, or ``"A:B"`` text
    (B exclusive, either side optional, like a Python slice, negative numbers counting from the end;
    ``"A"`` alone is one frame, ``"-1"`` the last)."""
    if spec is None:
        return range(total)
    if isinstance(spec, range):
        picked = range(total)[spec.start:spec.stop:spec.step]
        text = f"{spec.start}:{spec.stop}"
    else:
        text = str(spec)
        start_text, colon, stop_text = text.partition(":")
        try:
            start = int(start_text) if start_text.strip() else 0
            stop = int(stop_text) if stop_text.strip() else total
            if not colon:
                stop = (start + 1) or total  # "-1": the last frame, not the empty slice [-1:0]
        except ValueError:
            raise OptionError(f"frames {text!r}: expected A:B with whole numbers") from None
        picked = range(total)[start:stop]
    if not picked:
        raise OptionError(f"frames {text}: no frames selected; the scene has frames 0 to {total - 1}")
    return picked


def stacking_of(scene: Scene, tracks: Sequence[Track]) -> tuple[Switch, ...]:
    """Where the paint order of ``scene``'s drawings switches between keys (:mod:`..core.stacking`)."""
    if not layered(scene.shapes):
        return ()

    def shapes_at(index: int, times: NDArray[np.float64]) -> list[ShapeAt]:
        return tracks[index].at(times, scene.method_of(scene.shapes[index]))

    return stacking_plan(scene.shapes, shapes_at)


def scene_view(scene: Scene, tracks: Sequence[Track], methods: Sequence[str | None]) -> Box:
    """The scene's ``view``, or a box that fits every key and sampled inbetween of ``methods``."""
    from ..raster.view import fit_box

    if scene.view is not None:
        return scene.view
    outlines: list[Points] = [c.points for shape in scene.shapes for key in shape.keys if not key.hidden
                              for c in key.contours]
    samples = np.linspace(0.0, 1.0, 17)
    for track, shape in zip(tracks, scene.shapes):
        for segment in track.segments:
            times = segment.start + samples * (segment.end - segment.start)
            for method in methods:
                outlines.extend(c for at in track.at(times, method or scene.method_of(shape)) for c in at.contours)
    return fit_box(outlines)


@dataclass(frozen=True)
class RenderJob:
    """What to draw: one panel per entry of ``methods`` (``None``: each shape's own method)."""

    scene: Scene
    methods: tuple[str | None, ...] = (None,)
    labels: bool = False
    size: tuple[int, int] | None = None  # per panel; default the scene's
    fps: float | None = None
    frames: range | None = None  # default every frame
    paths: bool = False  # every vertex's path and the keys, behind the shapes
    onion: int = 0  # ghosted inbetweens before and after the frame (see raster.overlays)
    strip: bool = False  # the perimeter-ratio strip along each panel's bottom

    @property
    def panel_size(self) -> tuple[int, int]:
        return self.size or self.scene.size

    @property
    def frame_size(self) -> tuple[int, int]:
        width, height = self.panel_size
        return width * len(self.methods), height

    @property
    def rate(self) -> float:
        return self.fps or self.scene.fps

    @property
    def frame_range(self) -> range:
        return self.frames if self.frames is not None else range(total_frames(self.scene, self.rate))


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
            self._tracks = tracks_of(self.job.scene)
        return self._tracks

    @property
    def stacking(self) -> tuple[Switch, ...]:
        """Where the paint order switches between keys (each shape under its own method)."""
        if self._stacking is None:
            self._stacking = stacking_of(self.job.scene, self.tracks)
        return self._stacking

    def order_at(self, time: float) -> tuple[int, ...]:
        """The shapes' paint order at ``time`` seconds (indices into the scene's shapes)."""
        return order_at(self.stacking, self.job.scene.shapes, time)

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
            from .compiler_pages import page_out_compiler

            self._drawn = True
            page_out_compiler()
        return picture

    def at_time(self, time: float) -> NDArray[np.uint8]:
        """The picture at any ``time`` in seconds, on or between frames; reused like ``self(index)``."""
        return self._draw([self.shapes_at(method, time) for method in self.job.methods], time)

    def _draw(self, panels: list[list[ShapeAt]], time: float) -> NDArray[np.uint8]:
        return self.composer.draw(panels, time, self.layout)


