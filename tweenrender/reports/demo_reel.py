"""Demo reels: for each scene a title card, then its comparison, all at one size and fps in one video.

Each comparison (one labelled panel per method) is scaled to fit under a title
band of the reel's frame, aspect kept, and letterboxed: side by side, or in a
grid of rows when that shows the panels larger (three 16:9 panels in a 16:9
reel: two over one). The panels are drawn as one side-by-side frame, so their
metric strips share one scale, and cut apart into their cells. Frames
are drawn and sent to a single sink one at a time, so memory does not grow
with the reel's length.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Iterator, Sequence

import numpy as np
from numpy.typing import NDArray

from ..errors import RenderError
from ..model import Scene
from ..pipeline.frames import Frames
from ..plan.job import Progress, RenderJob
from ..plan.options import own_method_first
from ..pipeline.stream import stream_into
from ..pipeline.workers import draw_frame

__all__ = ["CARD_SECONDS", "ReelPart", "plan_reel", "reel_frames", "write_reel", "panel_fit", "grid_cells",
           "band_height"]

CARD_SECONDS = 1.5
"""How long each title card shows."""

GAP = 4
"""Pixels of the reel's dark background between panels."""


@dataclass(frozen=True)
class ReelPart:
    """One scene of a reel: its card's frame count and the job of its comparison."""

    scene: Scene
    name: str
    card_frames: int
    job: RenderJob
    cells: tuple[tuple[int, int], ...]  # top-left pixel of each panel in the reel's frame

    @property
    def frames(self) -> int:
        return self.card_frames + len(self.job.frame_range)


def band_height(height: int) -> int:
    """Pixels of the title band above each comparison (1/14 of the height, at least 16)."""
    return max(16, round(height / 14))


def panel_fit(panel: tuple[int, int], panels: int, box: tuple[int, int],
              strip: bool = False) -> tuple[tuple[int, int], int]:
    """Panel size and column count that show ``panels`` panels largest inside ``box``.

    The drawing keeps ``panel``'s aspect; with ``strip`` each panel is made
    taller by the strip below its drawing. Rows are filled left to right.
    """
    from ..raster.overlays import height_with_strip

    pw, ph = panel
    grow = (lambda h: height_with_strip(h)) if strip else (lambda h: h)
    best: tuple[float, int, tuple[int, int]] | None = None
    for columns in range(1, panels + 1):
        rows = -(-panels // columns)
        room = (box[0] - (columns - 1) * GAP, box[1] - (rows - 1) * GAP)
        scale = min(room[0] / (columns * pw), room[1] / (rows * ph))
        while scale > 0 and rows * grow(max(1, int(ph * scale))) > room[1]:
            scale *= 0.99
        size = (max(1, int(pw * scale)), grow(max(1, int(ph * scale))))
        if best is None or scale > best[0] + 1e-9:
            best = (scale, columns, size)
    assert best is not None
    return best[2], best[1]


def grid_cells(size: tuple[int, int], count: int, columns: int, box: tuple[int, int],
               top: int) -> tuple[tuple[int, int], ...]:
    """Top-left pixels of ``count`` panels of ``size`` in rows of ``columns``, centred in ``box`` below ``top``."""
    pw, ph = size
    rows = -(-count // columns)
    y0 = top + (box[1] - rows * ph - (rows - 1) * GAP) // 2
    cells = []
    for index in range(count):
        row, column = divmod(index, columns)
        in_row = min(columns, count - row * columns)
        x0 = (box[0] - in_row * pw - (in_row - 1) * GAP) // 2
        cells.append((x0 + column * (pw + GAP), y0 + row * (ph + GAP)))
    return tuple(cells)


def plan_reel(scenes: Sequence[Scene], names: Sequence[str], size: tuple[int, int], fps: float,
              methods: Sequence[str] | None = None, card_seconds: float = CARD_SECONDS,
              paths: bool = True, onion: int = 0, strip: bool = True) -> list[ReelPart]:
    """Lay out every scene's card and comparison in a ``size`` reel at ``fps``."""
    width, height = size
    band = band_height(height)
    parts = []
    for scene, name in zip(scenes, names):
        panels = tuple(methods) if methods else own_method_first(scene)
        box = (width, height - band)
        panel, columns = panel_fit(scene.size, len(panels), box, strip)
        job = RenderJob(scene, panels, labels=True, size=panel, fps=fps, paths=paths, onion=onion,
                        strip=strip)
        cells = grid_cells(panel, len(panels), columns, box, band)
        parts.append(ReelPart(scene, name, round(card_seconds * fps), job, cells))
    return parts


def _title(part: ReelPart) -> str:
    return part.scene.title or part.name


def reel_frames(parts: Sequence[ReelPart], size: tuple[int, int]) -> Iterator[NDArray[np.uint8]]:
    """Every frame of the reel in order, straight RGBA ``(height, width, 4)`` (buffers are reused)."""
    from ..raster.title_cards import draw_band, draw_card

    width, height = size
    for number, part in enumerate(parts, start=1):
        corner = f"{number} / {len(parts)}"
        job = part.job
        notes = [f"{part.name}  ·  {part.scene.duration:g} s, {len(job.frame_range)} frames at {job.rate:g} fps"]
        if job.strip:
            notes.append("strip below each panel: perimeter ÷ the keys' mean perimeter (1.0 keeps the size)")
        if job.paths:
            notes.append("thin lines: the path each vertex follows; dashed: the keys")
        card = draw_card(width, height, _title(part), job.methods, notes, corner)  # type: ignore[arg-type]
        for _ in range(part.card_frames):
            yield card
        picture = draw_band(width, height, band_height(height), _title(part), corner)
        frames = Frames(job)
        pw, ph = job.panel_size
        for index in job.frame_range:
            try:
                comparison = draw_frame(frames, index)
            except RenderError as error:
                raise RenderError(f"{part.name}: {error}") from error
            for panel, (x, y) in enumerate(part.cells):
                picture[y:y + ph, x:x + pw, :3] = comparison[:, panel * pw:(panel + 1) * pw, :3]
                picture[y:y + ph, x:x + pw, 3] = 255
            yield picture


def write_reel(parts: Sequence[ReelPart], fmt: str, target: Path, size: tuple[int, int], fps: float,
               progress: Progress | None = None) -> Path:
    """Stream the whole reel into one sink; the target changes only if everything succeeded."""
    from ..encode import open_sink

    total = sum(part.frames for part in parts)
    sink = open_sink(fmt, target, size[0], size[1], fps, total)
    return stream_into(sink, reel_frames(parts, size), total, progress)
