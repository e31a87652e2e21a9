"""What to draw: a :class:`RenderJob` (scene, panels, size, frames, overlays), below both renderers
(``pipeline.frames`` draws its frames, ``vector.export`` writes it as a vector file).

Every frame is a pure function of (scene, methods, frame index), so any range of
frames can be rendered on its own, in any process.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ..core.stacking import Switch, layered, stacking_plan
from ..core.timing.timeline import ShapeAt, Track, frame_count, tracks_of
from ..errors import OptionError
from ..model import Points, Scene
from ..core.view import Box

__all__ = ["RenderJob", "Progress", "total_frames", "pick_frames", "tracks_of", "scene_view", "stacking_of"]

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
    from ..core.view import fit_box

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
    draft: bool = False  # encoded at the encoder's quickest settings (encode.formats.Format.draft)
    # the scene's tracks where they were already built (shipped to worker processes, which then need not
    # build them again); None: built where the frames are drawn
    tracks: tuple[Track, ...] | None = field(default=None, compare=False, repr=False)

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
