"""The library's front door, in the style of imageio's v3 API: a few functions that return fresh data.

::

    scene = load_scene("scenes/square.toml")
    img = frame(scene, 1.0, method="rigid", size=(640, 360))   # (360, 640, 4) uint8, straight RGBA
    for img in frames(scene): ...                               # one fresh array per frame
    contours = outlines(scene, 1.0)                              # (N, 2) arrays, scene units, y up
    write(scene, "output/square.mp4", compare=["linear", "nonlinear"])

Times are in seconds. Every refusal is a :class:`~tweenrender.errors.TweenrenderError`
whose message is the line the command line prints.
"""

from __future__ import annotations

import os
from collections import OrderedDict
from dataclasses import replace
from pathlib import Path
from typing import Iterator, Sequence

import numpy as np
from numpy.typing import NDArray

from ..errors import OptionError
from ..model import BALANCES, EQUAL_COUNTS, METHODS, Color, Points, Scene
from .job import Frames, Progress, RenderJob, pick_frames, total_frames

__all__ = ["load_scene", "frame", "frames", "outlines", "write", "output_format", "with_matching",
           "with_balance", "CANVAS_LIMIT"]

CANVAS_LIMIT = 16384
"""The largest frame side, in pixels (a comparison's panels together)."""

_CACHE_SIZE = 4
# Frames objects of recent (scene, method, size, background) calls: building one costs the
# correspondence of every segment, which repeated frame() calls on one scene should pay once.
_recent: OrderedDict[tuple[int, str | None, tuple[int, int] | None, Color | None], tuple[Scene, Frames]] = \
    OrderedDict()


def load_scene(path: str | os.PathLike[str] | Sequence[str | os.PathLike[str]], step: float = 1.0,
               ease: str = "linear", hold: float = 0.0, stagger: float = 0.0) -> Scene:
    """The scene at ``path`` (TOML; JSON by its ``.json`` suffix; one SVG drawing by ``.svg``), validated;
    or, for a list of SVG files, their drawings morphing one into the next (what ``tweenrender render
    a.svg b.svg`` renders): each shown ``hold`` seconds, then moving for ``step`` seconds under ``ease``,
    element i of a drawing starting ``i × stagger`` seconds later and arriving on time."""
    from ..scenefile import load_scene as load

    if isinstance(path, (str, os.PathLike)):
        return load(Path(path), step, ease, hold, stagger)
    return load([Path(p) for p in path], step, ease, hold, stagger)


def frame(scene: Scene, time: float, *, method: str | None = None, size: tuple[int, int] | None = None,
          background: str | Color | None = None) -> NDArray[np.uint8]:
    """The picture at ``time`` seconds: a fresh ``(height, width, 4)`` uint8 array, straight RGBA.

    ``method`` overrides every shape's own; ``size`` is ``(width, height)`` in pixels (default the
    scene's); ``background`` a colour (``"#rrggbbaa"``, ``"none"``, or an RGBA tuple). Before the
    first key the first key is drawn, after the last the last.
    """
    drawer = _frames_for(scene, method, size, background)
    return drawer.at_time(_finite_time(time)).copy()


def frames(scene: Scene, *, method: str | None = None, size: tuple[int, int] | None = None,
           background: str | Color | None = None, fps: float | None = None) -> Iterator[NDArray[np.uint8]]:
    """Every frame of the clip at ``fps`` (default the scene's), frame ``f`` at ``f / fps`` seconds:
    ``round(last time · fps) + 1`` fresh ``(height, width, 4)`` uint8 arrays, straight RGBA."""
    rate = _fps(fps, scene)
    job = _job(scene, method, size, background, fps=rate)
    drawer = Frames(job)
    for index in job.frame_range:
        yield drawer(index).copy()


def outlines(scene: Scene, time: float, *, method: str | None = None) -> list[Points]:
    """Every drawn contour at ``time`` seconds under ``method`` (default each shape's own): a list of
    fresh ``(N, 2)`` float64 arrays in scene units, y up — shapes in paint order, a shape's contours
    in order, at the balanced vertex count. A closed contour does not repeat its first point; an
    open one is not closed. Shapes not drawn at that time (before they appear, after they go,
    fully transparent) are left out; contours that are growing or shrinking are in while they have size."""
    drawer = _frames_for(scene, method, None, None)
    out = []
    for at in drawer.shapes_at(method, _finite_time(time)):
        if not at.visible:
            continue
        out += [np.array(c, dtype=np.float64) for c in at.contours if np.ptp(c, axis=0).max(initial=0.0) > 0]
    return out


def write(scene: Scene, path: str | os.PathLike[str], *, method: str | None = None,
          compare: Sequence[str] | bool | None = None, format: str | None = None,
          size: tuple[int, int] | None = None, fps: float | None = None, frames: str | range | None = None,
          background: str | Color | None = None, balance: str | None = None, paths: bool = False,
          onion: int = 0, strip: bool = False, cost: str | None = None, align: str | None = None,
          equal_counts: str | None = None, workers: int | None = None, cluster: str | None = None,
          progress: Progress | None = None) -> Path:
    """Write the clip to ``path`` exactly as ``tweenrender render`` does; returns the path written.

    The format is ``format`` or ``path``'s extension (``.mp4``, ``.webm``, ``.mov``, ``.gif``; a name
    without one is a folder of PNG frames). ``background`` overrides the scene's (``"none"``:
    transparent, kept by WebM, MOV, GIF and PNG; refused for MP4). ``compare`` lists the methods of side-by-side labelled panels
    (``True``: the scene's ``compare`` list); ``size`` is each panel's. ``frames`` picks part of the
    clip (``"A:B"`` or a ``range``). ``cost``, ``align`` and ``equal_counts`` override the scene's
    ``[correspondence]``; ``balance`` (``"copies"`` or ``"spread"``) overrides every shape's.
    ``workers`` is the number of drawing processes (default: chosen from the measured cost of a
    frame against the encoder's). ``cluster`` renders on a dask.distributed cluster instead: a
    scheduler's address, or ``"local:N"`` for a local cluster of N processes (needs the ``cluster``
    extra). ``progress`` is called with ``(done, total)`` frames. The target changes only when the
    whole output was written and checked.
    """
    from ..encode.limits import check_frame_size
    from ..encode.targets import check_frames_folder, check_output_name
    from .chunks import render_in_processes
    from .workers import default_workers

    if method is not None and compare not in (None, False):
        raise OptionError("method and compare do not go together: list the methods in compare")
    target = check_output_name(path)
    fmt = output_format(target, format)
    _not_the_scene(target, scene)
    if fmt == "png":
        check_frames_folder(target)
    scene = with_balance(with_matching(scene, cost, align, equal_counts), balance)
    panels: tuple[str | None, ...]
    if compare is True:
        panels = scene.compare
    elif compare:
        panels = tuple(_method(m) for m in compare)
    else:
        panels = (_method(method),)
    rate = _fps(fps, scene)
    picked = pick_frames(frames, total_frames(scene, rate))
    job = _job(scene, None, size, background, fps=rate, panels=panels, labels=bool(compare), frames=picked,
               paths=paths, onion=onion, strip=strip)
    from ..encode.sinks import check_alpha

    check_alpha(fmt, job.scene.background[3] < 255)
    check_frame_size(fmt, *job.frame_size)  # before drawing a frame or starting ffmpeg
    if cluster is not None:
        if workers is not None:
            raise OptionError("workers and cluster do not go together: the cluster's workers draw the frames")
        from .cluster import render_on_cluster

        return render_on_cluster(job, fmt, target, cluster, progress)
    if workers is None:
        workers = default_workers(job, fmt)
    elif workers < 1:
        raise OptionError(f"workers: expected 1 or more processes, found {workers}")
    return render_in_processes(job, fmt, target, workers, progress)


def output_format(target: Path, fmt: str | None = None) -> str:
    """The format to write ``target`` in: ``fmt``, else its extension; a name without one is PNG frames."""
    from ..encode import FORMATS

    suffix = target.suffix.lower().lstrip(".")
    if fmt is not None:
        if fmt not in FORMATS:
            raise OptionError(f"unknown format {fmt!r}; expected one of {', '.join(FORMATS)}")
        if suffix in FORMATS and suffix != fmt and fmt != "png":
            raise OptionError(f"{target} ends in .{suffix} but the format asked for is {fmt}")
        return fmt
    if suffix in FORMATS and suffix != "png":
        return suffix
    if suffix == "":
        return "png"
    videos = ", ".join(f".{f}" for f in FORMATS if f != "png")
    raise OptionError(f"{target}: cannot tell the format from .{suffix}; expected a name ending in {videos}, "
                      "or one without extension for a folder of PNG frames")


# -- helpers -------------------------------------------------------------------------------------


def _frames_for(scene: Scene, method: str | None, size: tuple[int, int] | None,
                background: str | Color | None) -> Frames:
    """A :class:`Frames` for one panel, reused across calls with the same arguments."""
    color = None if background is None else _color(background)
    key = (id(scene), _method(method), None if size is None else tuple(size), color)
    found = _recent.get(key)
    if found is not None and found[0] is scene:
        _recent.move_to_end(key)
        return found[1]
    drawer = Frames(_job(scene, method, size, background))
    _recent[key] = (scene, drawer)  # the scene is held too, so its id cannot be reused meanwhile
    while len(_recent) > _CACHE_SIZE:
        _recent.popitem(last=False)
    return drawer


def _job(scene: Scene, method: str | None, size: tuple[int, int] | None, background: str | Color | None,
         panels: tuple[str | None, ...] | None = None, **options: object) -> RenderJob:
    if background is not None:
        scene = replace(scene, background=_color(background))
    if panels is None:
        panels = (_method(method),)
    width, height = _size(size, scene)
    if width * len(panels) > CANVAS_LIMIT:
        raise OptionError(f"{len(panels)} panels of {width} px make a {width * len(panels)} px wide frame, "
                          f"more than {CANVAS_LIMIT}")
    return RenderJob(scene, panels, size=(width, height), **options)  # type: ignore[arg-type]


def _method(name: str | None) -> str | None:
    if name is None or name in METHODS:
        return name
    import difflib

    close = difflib.get_close_matches(str(name), METHODS, n=1)
    hint = f" (did you mean {close[0]!r}?)" if close else ""
    raise OptionError(f"unknown method {name!r}{hint}; expected one of {', '.join(METHODS)}")


def _size(size: tuple[int, int] | None, scene: Scene) -> tuple[int, int]:
    if size is None:
        return scene.size
    try:
        width, height = (int(v) for v in size)
    except (TypeError, ValueError):
        raise OptionError(f"size: expected (width, height) in pixels, found {size!r}") from None
    if not (1 <= width <= CANVAS_LIMIT and 1 <= height <= CANVAS_LIMIT):
        raise OptionError(f"size: expected (width, height) from 1 to {CANVAS_LIMIT} pixels each, "
                          f"found {width}x{height}")
    return width, height


def _fps(fps: float | None, scene: Scene) -> float:
    if fps is None:
        return scene.fps
    from ..scenefile import LIMITS

    low, high = LIMITS["fps"]
    if not (isinstance(fps, (int, float)) and low <= fps <= high):
        raise OptionError(f"fps: expected {low} to {high} frames per second, found {fps!r}")
    return float(fps)


def _color(value: str | Color) -> Color:
    from ..scenefile import parse_color

    if isinstance(value, str):
        if value.strip().lower() == "none":
            return (0, 0, 0, 0)
        return parse_color(value, lambda message: OptionError(f"background: {message}"))
    try:
        r, g, b, a = (int(v) for v in value)
    except (TypeError, ValueError):
        raise OptionError(f"background: expected a colour text or an (r, g, b, a) tuple, found {value!r}") from None
    if not all(0 <= v <= 255 for v in (r, g, b, a)):
        raise OptionError(f"background: expected (r, g, b, a) from 0 to 255 each, found {value!r}")
    return (r, g, b, a)


def _finite_time(time: float) -> float:
    try:
        value = float(time)
    except (TypeError, ValueError):
        raise OptionError(f"time: expected seconds as a number, found {time!r}") from None
    if not np.isfinite(value):
        raise OptionError(f"time: expected a finite number of seconds, found {time!r}")
    return value


def with_matching(scene: Scene, cost: str | None = None, align: str | None = None,
                  equal_counts: str | None = None) -> Scene:
    """``scene`` with the given ``[correspondence]`` settings put over its own (itself when none is given)."""
    from ..model import ALIGNS, COSTS

    changes = {}
    for name, value, choices in (("cost", cost, COSTS), ("align", align, ALIGNS),
                                 ("equal_counts", equal_counts, EQUAL_COUNTS)):
        if value is None:
            continue
        if value not in choices:
            raise OptionError(f"{name}: expected one of {', '.join(choices)}, found {value!r}")
        changes[name] = value
    return replace(scene, matching=replace(scene.matching, **changes)) if changes else scene


def with_balance(scene: Scene, balance: str | None) -> Scene:
    """``scene`` with every shape balanced by ``balance`` (``"copies"`` or ``"spread"``; None: as it is)."""
    if balance is None:
        return scene
    if balance not in BALANCES:
        raise OptionError(f"balance: expected one of {', '.join(BALANCES)}, found {balance!r}")
    return replace(scene, balance=balance, shapes=tuple(replace(shape, balance=None) for shape in scene.shapes))


def _not_the_scene(target: Path, scene: Scene) -> None:
    """Refuse to write over the scene file itself."""
    if scene.path is None:
        return
    try:
        same = os.path.samefile(target, scene.path)
    except OSError:  # either does not exist (yet): they cannot be the same file
        return
    if same:
        raise OptionError(f"{target}: is the scene file itself; choose another output")
