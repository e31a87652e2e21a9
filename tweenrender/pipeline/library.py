"""What the front door (:mod:`tweenrender.api`) calls to load, draw and write: functions that return fresh data.

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

import math
import os
from collections import OrderedDict
from dataclasses import replace
from pathlib import Path
from numbers import Real
from typing import Any, Iterator, Sequence

import numpy as np
from numpy.typing import NDArray

from ..errors import OptionError, printable
from ..model import Color, DrawnContour, Points, Scene
from ..plan.job import RenderJob, pick_frames, total_frames
from .frames import Frames
from ..plan.options import RenderOptions, canvas_limit, check_color, check_fps, check_method, check_scene, check_size

__all__ = ["load_scene", "frame", "frames", "outlines", "contours", "write", "render_job", "output_format",
           "not_an_input"]

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
        given = [n for n, v, d in (("ease", ease, "linear"), ("hold", hold, 0.0), ("stagger", stagger, 0.0)) if v != d]
        if given and Path(path).suffix.lower() != ".svg":
            raise OptionError("applies to SVG drawings morphing into each other; a scene file sets ease and "
                              "stagger itself", given[0])
        _check_timing(ease, hold, stagger)
        return load(Path(path), _step(step), ease, float(hold), float(stagger))
    if isinstance(path, (bytes, bytearray)) or not isinstance(path, Sequence) or \
            not all(isinstance(p, (str, os.PathLike)) for p in path):
        raise OptionError(f"path: expected a scene file's name or a list of SVG files, found {path!r}")
    step = _step(step)
    _check_timing(ease, hold, stagger)
    return load([Path(p) for p in path], step, ease, float(hold), float(stagger))


MAX_STEP = 1e6
"""The most seconds between two drawings :func:`load_scene` takes (a scene's last key is at most 1e7 s)."""


def _step(step: object) -> float:
    """Seconds between drawings: a number above 0 and at most :data:`MAX_STEP` (``10**400`` is refused, not
    overflowed)."""
    if isinstance(step, bool) or not isinstance(step, Real) or not 0 < step <= MAX_STEP:
        shown = repr(step) if len(repr(step)) <= 40 else f"{repr(step)[:20]}…"
        raise OptionError(f"expected seconds between drawings above 0 and at most {MAX_STEP:g}, found {shown}",
                          "step")
    return float(step)


def init_scene(drawings: Sequence[str | os.PathLike[str]], step: float = 1.0, ease: str = "linear",
               hold: float = 0.0, stagger: float = 0.0, path: str | os.PathLike[str] | None = None) -> str:
    """The TOML text of the ``[[drawing]]`` scene that renders as ``drawings`` with this timing do (see
    :func:`load_scene`), its file names relative to ``path``'s folder (the current one without ``path``);
    with ``path``, also written there as a new file (never replacing one)."""
    from ..encode.atomic import create_new
    from ..encode.targets import check_name_fits
    from ..scenefile.scene_writer import drawings_toml

    if isinstance(drawings, (str, bytes, os.PathLike)) or not isinstance(drawings, Sequence) or not drawings:
        raise OptionError(f"expected a list of SVG drawings, found {drawings!r}"[:200], "drawings")
    target = None if path is None else Path(path)
    if target is not None:
        if target.suffix.lower() != ".toml":
            raise OptionError(f"{printable(str(target))}: expected a scene file name ending in .toml")
        check_name_fits(target)
    load_scene(drawings, step, ease, hold, stagger)  # refused as the command line would refuse it
    text = drawings_toml([Path(p) for p in drawings], target.parent if target is not None else Path.cwd(),
                         float(step), ease, float(hold), float(stagger))
    if target is not None:
        create_new(target, text, "the scene")
    return text


def _check_timing(ease: object, hold: object, stagger: object) -> None:
    """Refuse a timing of drawings that is not one: an unknown curve, a negative or non-numeric hold."""
    from ..core.timing.easing import parse_easing

    if not isinstance(ease, str):
        raise OptionError(f"expected an easing name or curve, found {ease!r}", "ease")
    try:
        parse_easing(ease)
    except ValueError as error:
        raise OptionError(str(error), "ease") from None
    for name, value in (("hold", hold), ("stagger", stagger)):
        if isinstance(value, bool) or not isinstance(value, Real) or not 0 <= float(value) <= 1e6:
            raise OptionError(f"expected seconds from 0 to 1000000, found {value!r}", name)


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
    ``ceil(last time · fps − 1e-9) + 1`` fresh ``(height, width, 4)`` uint8 arrays, straight RGBA."""
    scene = check_scene(scene)
    rate = scene.fps if fps is None else check_fps(fps)
    job = _job(scene, None if method is None else check_method(method), None if size is None else check_size(size),
               None if background is None else check_color(background), fps=rate)
    drawer = Frames(job)
    for index in job.frame_range:
        yield drawer(index).copy()


def outlines(scene: Scene, time: float, *, method: str | None = None) -> list[Points]:
    """Every drawn contour at ``time`` seconds under ``method`` (default each shape's own): a list of
    fresh ``(N, 2)`` float64 arrays in scene units, y up — shapes in paint order, a shape's contours
    in order, at the balanced vertex count. A closed contour does not repeat its first point; an
    open one is not closed. Shapes not drawn at that time (before they appear, after they go,
    fully transparent) are left out; contours that are growing or shrinking are in while they have size."""
    return [drawn.points for drawn in contours(scene, time, method=method)]


def contours(scene: Scene, time: float, method: str | None = None, points: bool = False) -> list[DrawnContour]:
    """Every drawn contour at ``time`` seconds as :class:`~tweenrender.model.DrawnContour` s, in the
    order of :func:`outlines`: which are open strokes, which holes, their element and paint (``points``:
    those that are one point at that time too)."""
    from ..core.contours import roles
    from ..core.view import Viewport

    points_too = points
    drawer = _frames_for(scene, method, None, None)
    at_time = _finite_time(time)
    shapes = drawer.shapes_at(method, at_time)
    pixel = 1.0
    if any(not shape.stroke_scales and shape.paint.stroke is not None for shape in scene.shapes):
        from ..plan.job import scene_view

        pixel = 1.0 / Viewport(scene_view(scene, drawer.tracks, (method,)), *scene.size).scale
    out = []
    for index in drawer.order_at(at_time):
        shape, at = scene.shapes[index], shapes[index]
        if not at.visible:
            continue
        key = at.key
        rule = (key.fill_rule if key is not None else None) or shape.fill_rule
        paint = at.paint
        width = paint.stroke_width * (1.0 if shape.stroke_scales else pixel)
        kinds = roles(list(at.contours), list(at.closed))
        for i, points in enumerate(at.contours):
            if not points_too and np.ptp(points, axis=0).max(initial=0.0) <= 0:
                continue
            out.append(DrawnContour(np.array(points, dtype=np.float64), at.closed[i], kinds[i] == "hole", shape.name,
                                    rule, _unit(paint.fill), _unit(paint.stroke), float(width), float(paint.opacity),
                                    bool(at.reversed and at.reversed[i]), paint.gradient))
    return out


def _unit(color: Color | None) -> tuple[float, float, float, float] | None:
    return None if color is None else tuple(c / 255.0 for c in color)  # type: ignore[return-value]


def write(scene: Scene, path: str | os.PathLike[str], *, options: RenderOptions | None = None,
          **named: Any) -> Path:
    """Write the clip to ``path`` exactly as ``tweenrender render`` does; returns the path written.

    Options come by their long names (``method, compare, format, size, fps, frames, background, balance,
    paths, onion, strip, cost, align, equal_counts, workers, cluster, max_frames, progress, max_error, loop,
    draft``; see
    :class:`~.options.RenderOptions`) or as one ``options`` object. The format is ``format`` or
    ``path``'s extension (any of ``encode.formats.suffixes()``; a name without one is a folder of PNG
    frames). ``background`` overrides the scene's (``"none"``: transparent, kept by every format but MP4).
    ``compare`` lists the methods of side-by-side labelled panels (``True``: the scene's ``compare``
    list); ``size`` is each panel's. ``frames`` picks part of the clip (``"A:B"`` or a ``range``).
    ``cost``, ``align`` and ``equal_counts`` override the scene's ``[correspondence]``; ``balance``
    (``"copies"`` or ``"spread"``) overrides every shape's. ``workers`` is the number of drawing
    processes (default: chosen from the measured cost of a frame against the encoder's). ``cluster``
    renders on a dask.distributed cluster instead: a scheduler's address, or ``"local:N"`` (needs the
    ``cluster`` extra). ``progress`` is called with ``(done, total)`` frames. The target changes only
    when the whole output was written and checked.

    ``.json`` (format ``lottie``) writes Lottie, ``.lottie`` (``dotlottie``) the same in a dotLottie
    archive, ``.svg`` (``svg``) an animated SVG: the paths themselves as cubic Bézier curves, keyframed
    within ``max_error`` output pixels (default 0.25) of every frame; they take no ``compare``, ``paths``,
    ``onion``, ``strip``, ``workers``, ``cluster`` or ``draft``. ``loop`` makes the animated SVG repeat and the
    dotLottie's manifest say it loops (a Lottie JSON cannot say: its player decides). ``draft`` encodes an
    MP4 or WebM at the encoder's quickest settings: the same quality asked for, in a larger file.
    """
    from ..encode.formats import TABLE, check_alpha, check_draft, check_frame_size, check_loop
    from ..encode.targets import check_frames_folder, check_output_name
    from .chunks import render_in_processes
    from .workers import default_workers

    scene = check_scene(scene)
    if options is not None and named:
        raise OptionError(f"give the options either as options= or by name, not both ({', '.join(named)})")
    if options is not None and not isinstance(options, RenderOptions):
        raise OptionError(f"expected a RenderOptions (or the options by name), found {type(options).__name__}",
                          "options")
    # an object built directly skipped create()'s checks: every value is checked again here
    opts = RenderOptions.create(**(options.given() if options is not None else named))
    if path is None or not isinstance(path, (str, os.PathLike)):
        raise OptionError(f"path: expected a file or folder name, found {path!r}")
    target = check_output_name(path)
    fmt = output_format(target, opts.format)
    not_an_input(target, [scene], folder=TABLE[fmt].folder)
    check_loop(fmt, opts.loop)
    if TABLE[fmt].folder:
        check_frames_folder(target)
    if TABLE[fmt].vector:
        from ..vector.export import refuse_raster_options

        refuse_raster_options(fmt, opts)
    elif opts.max_error is not None:
        from ..encode.formats import names

        raise OptionError(f"applies to the vector formats ({', '.join(names(vector=True))}) only, not {fmt}",
                          "max_error")
    job = render_job(scene, opts)
    if len(job.frame_range) > opts.max_frames:
        raise OptionError(f"{len(job.frame_range)} frames is more than {opts.max_frames}; "
                          "raise it to render them anyway", "max_frames")
    if TABLE[fmt].vector:
        from ..vector.export import write_vector

        return write_vector(job, fmt, target, opts.max_error, opts.loop)
    check_alpha(fmt, job.scene.background[3] < 255)
    check_draft(fmt, opts.draft)
    check_frame_size(fmt, *job.frame_size)  # before drawing a frame or starting ffmpeg
    if opts.cluster is not None:
        from .cluster import render_on_cluster

        return render_on_cluster(job, fmt, target, opts.cluster, opts.progress)
    workers = opts.workers or default_workers(job, fmt)
    return render_in_processes(job, fmt, target, workers, opts.progress)


def render_job(scene: Scene, options: RenderOptions) -> RenderJob:
    """The job ``write`` renders: the scene with the options' matching and balance put over its own,
    the panels, size, rate, frames and overlays."""
    scene = options.match.over(scene)
    panels: tuple[str | None, ...]
    if options.compare is True:
        panels = scene.compare
    elif options.compare:
        panels = tuple(options.compare)
    else:
        panels = (options.method,)
        if options.method == "linear":
            _refuse_turns(scene)
    rate = options.fps or scene.fps
    picked = pick_frames(options.frames, total_frames(scene, rate))
    return _job(scene, None, options.size, options.background, fps=rate, panels=panels,
                labels=bool(options.compare), frames=picked, paths=options.paths, onion=options.onion,
                strip=options.strip, draft=options.draft)


def output_format(target: Path, fmt: str | None = None) -> str:
    """The format to write ``target`` in: ``fmt``, else its extension; a name without one is PNG frames."""
    from ..encode.formats import by_suffix, lookup, suffixes

    suffix = target.suffix.lower()
    named = by_suffix(suffix)
    if fmt is not None:
        wanted = lookup(fmt)
        if named is not None and not named.folder and named is not wanted and not wanted.folder:
            raise OptionError(f"{target} ends in {suffix} but the format asked for is {fmt}", "format")
        return fmt
    if named is not None:
        return named.name
    files = ", ".join(suffixes())
    raise OptionError(f"{target}: cannot tell the format from {suffix}; expected a name ending in {files}, "
                      "or one without extension for a folder of PNG frames")


# -- helpers -------------------------------------------------------------------------------------


def _refuse_turns(scene: Scene) -> None:
    """Straight paths have no rigid frame: a scene whose keys choose a turn is not drawn by ``linear`` alone
    (a comparison's ``linear`` panel goes straight)."""
    for shape in scene.shapes:
        for k, key in enumerate(shape.keys):
            if key.turn is not None or key.turns:
                field = "turn" if key.turn is not None else "turns"
                raise OptionError(f'"linear" has no rigid frame to turn, but shape {shape.name!r} key {k} '
                                  f"sets {field}; choose rigid, nonlinear or another method", "method")


def _frames_for(scene: Scene, method: str | None, size: tuple[int, int] | None,
                background: str | Color | None) -> Frames:
    """A :class:`Frames` for one panel, reused across calls with the same arguments."""
    scene = check_scene(scene)
    method = None if method is None else check_method(method)
    size = None if size is None else check_size(size)
    color = None if background is None else check_color(background)
    key = (id(scene), method, size, color)
    found = _recent.get(key)
    if found is not None and found[0] is scene:
        _recent.move_to_end(key)
        return found[1]
    drawer = Frames(_job(scene, method, size, color))
    _recent[key] = (scene, drawer)  # the scene is held too, so its id cannot be reused meanwhile
    while len(_recent) > _CACHE_SIZE:
        _recent.popitem(last=False)
    return drawer


def _job(scene: Scene, method: str | None, size: tuple[int, int] | None, background: Color | None,
         panels: tuple[str | None, ...] | None = None, **options: object) -> RenderJob:
    if background is not None:
        scene = replace(scene, background=background)
    if panels is None:
        panels = (method,)
    width, height = scene.size if size is None else size
    limit = canvas_limit()
    if width * len(panels) > limit:
        raise OptionError(f"{len(panels)} panels of {width} px make a {width * len(panels)} px wide frame, "
                          f"more than {limit}", "size")
    return RenderJob(scene, panels, size=(width, height), **options)  # type: ignore[arg-type]


def _finite_time(time: object) -> float:
    if isinstance(time, bool) or not isinstance(time, Real):
        raise OptionError(f"expected seconds as a number, found {time!r}", "time")
    try:
        value = float(time)
    except OverflowError:
        value = math.inf
    if not math.isfinite(value):
        raise OptionError(f"expected a finite number of seconds, found {time!r}", "time")
    # far before the first key or after the last draws that key: held within reach of the timeline's arithmetic
    return min(max(value, -_FAR), _FAR)


_FAR = 1e12
"""Seconds past which a time draws what it would at ±1e12 (every key is within 1e7 s)."""


def not_an_input(target: Path, scenes: Sequence[Scene], folder: bool = False, files: Sequence[str] = ()) -> None:
    """Refuse to write ``target`` over a file ``scenes`` were read from (the scene file, its SVG keys and
    drawings), through links; a ``folder`` target also when it holds one, or one of ``files`` (the names
    it will hold) already is one (see :func:`~tweenrender.encode.targets.check_not_an_input`)."""
    from ..encode.targets import check_not_an_input

    sources = [p for scene in scenes for p in (scene.sources or ((scene.path,) if scene.path else ()))]
    scene_files = [scene.path for scene in scenes if scene.path is not None and scene.path.suffix.lower() != ".svg"]
    check_not_an_input(target, sources, folder, files, scene_files)
