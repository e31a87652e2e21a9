"""What the picture-making commands write: a storyboard sheet, the HTML report, a demo reel — each one
call here (``tr.sheet``, ``tr.report``, ``tr.reel``), written atomically.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Callable, Sequence

from ..errors import OptionError
from ..model import Scene
from .analyses import picture_target
from ..pipeline.library import not_an_input, output_format
from ..plan.options import (DEFAULT_MAX_FRAMES, MAX_ONION, REEL_FPS, REEL_SIZE, SHEET_COUNT, SHEET_PIXELS,
                            MatchSettings, Progress, check_fps, check_methods, check_size, own_method_first)

__all__ = ["sheet", "report", "reel"]


def sheet(scene: Scene, path: str | os.PathLike[str], *, methods: Sequence[str] | None = None,
          count: int = SHEET_COUNT, size: tuple[int, int] | None = None, paths: bool = False,
          match: MatchSettings = MatchSettings()) -> Path:
    """A storyboard PNG like the thesis's figures: one row per method (default the scene's compare list),
    ``count`` inbetweens evenly spaced over the clip; returns the path written."""
    from ..core.timing.timeline import tracks_of
    from ..plan.job import scene_view
    from .pictures import write_sheet

    target = picture_target(path, "a sheet")
    scene = match.over(scene)
    not_an_input(target, [scene])
    rows = own_method_first(scene) if methods is None else check_methods(methods, "methods")
    if isinstance(count, bool) or not isinstance(count, int) or not 0 <= count <= 200:
        raise OptionError(f"expected a whole number from 0 to 200, found {count!r}", "count")
    checked = None if size is None else check_size(size)
    if checked is not None and checked[0] * checked[1] > SHEET_PIXELS:
        raise OptionError(f"expected a sheet of at most {SHEET_PIXELS} pixels (4096x4096, or as many in another "
                          f"shape), found {checked[0]}x{checked[1]} = {checked[0] * checked[1]}", "size")
    tracks = tracks_of(scene)
    view = scene_view(scene, tracks, rows)
    return write_sheet(scene, tracks, rows, view, target, count, checked, bool(paths))


def report(scene: Scene, path: str | os.PathLike[str], *, compare: Sequence[str] | None = None,
           match: MatchSettings = MatchSettings(),
           progress: Callable[[str], Progress | None] | None = None) -> Path:
    """The HTML report folder ``path``: every method's animation in sync, sheet, correspondence,
    metric charts and table; returns its ``index.html``. ``progress(name)`` may give a callback per video."""
    from .html_report import write_report

    if not isinstance(path, (str, os.PathLike)):
        raise OptionError(f"expected a folder name, found {path!r}", "path")
    methods = None if compare is None else check_methods(compare, "compare")
    return write_report(match.over(scene), Path(path), methods, progress)


def reel(scenes: Sequence[Scene], path: str | os.PathLike[str], *, names: Sequence[str] | None = None,
         size: tuple[int, int] = REEL_SIZE, fps: float = REEL_FPS, methods: Sequence[str] | None = None,
         onion: int = 0, plain: bool = False, match: MatchSettings = MatchSettings(),
         max_frames: int = DEFAULT_MAX_FRAMES,
         progress: Progress | None = None) -> Path:
    """A demo reel: a title card and a comparison of ``methods`` (default each scene's compare list) for
    each scene, in one video or folder of frames; returns the path written. ``names`` label the scenes
    (default their files' stems); ``plain`` leaves out vertex paths and the perimeter strip."""
    from ..encode.targets import check_output_name
    from .demo_reel import plan_reel, write_reel

    if isinstance(scenes, Scene) or not isinstance(scenes, Sequence) or not scenes:
        raise OptionError(f"expected a list of scenes, found {scenes!r}", "scenes")
    if not isinstance(path, (str, os.PathLike)):
        raise OptionError(f"expected a file or folder name, found {path!r}", "path")
    target = check_output_name(path)
    fmt = output_format(target)
    from ..encode.formats import is_vector, outputs_text

    if is_vector(fmt):
        raise OptionError(f"{target}: a reel is a video of title cards and labelled comparisons, which a {fmt} "
                          f"file cannot hold; write {outputs_text(vector=False)}", "path")
    chosen = [match.over(s) for s in scenes]
    from ..encode.formats import TABLE

    not_an_input(target, chosen, folder=TABLE[fmt].folder)
    labels = list(names) if names is not None else [Path(s.path).stem if s.path else f"scene {i + 1}"
                                                    for i, s in enumerate(chosen)]
    if isinstance(onion, bool) or not isinstance(onion, int) or not 0 <= onion <= MAX_ONION:
        raise OptionError(f"expected a whole number from 0 to {MAX_ONION}, found {onion!r}", "onion")
    parts = plan_reel(chosen, labels, check_size(size), check_fps(fps),
                      None if methods is None else check_methods(methods, "methods"),
                      paths=not plain, onion=onion, strip=not plain)
    frames = sum(part.frames for part in parts)
    if frames > max_frames:
        raise OptionError(f"the reel: {frames} frames is more than {max_frames}; "
                          "raise it to render them anyway", "max_frames")
    return write_reel(parts, fmt, target, check_size(size), check_fps(fps), progress)
