"""The front door: every public function of tweenrender, each a thin check-and-call.

::

    import tweenrender as tr
    scene = tr.load_scene("scenes/square.toml")
    img = tr.frame(scene, 1.0, method="rigid", size=(640, 360))   # (360, 640, 4) uint8, straight RGBA
    tr.write(scene, "output/square.mp4", compare=["linear", "nonlinear"])

Times are in seconds. Every refusal is a :class:`~tweenrender.errors.TweenrenderError` whose message is
the line the command line prints. The command line and the preview use this module (and
:mod:`tweenrender.errors`) only; the stages below it do the work. Each function imports its stage when
first called, so ``import tweenrender`` stays light.

Five settings of the correspondence come by name wherever keys are matched (``sheet``, ``report``,
``reel``, ``correspondence``; ``write`` takes them among its options): ``cost`` (``distance`` or
``sg``), ``align`` (``centroid`` or ``none``), ``equal_counts`` (``drawn`` or ``match``), put over the
scene's ``[correspondence]``, ``max_memory`` (bytes, or a text such as ``512M`` or ``2G``: what the
exact ``sg`` search's tables may take, about 120 bytes a pair of vertices; a larger search is refused
before it starts; default 2 GiB), and ``balance`` (``copies`` or ``spread``), put over every shape's.
They travel as one :class:`MatchSettings`.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Callable, Iterator, Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ._version import __version__
from .model import ALIGNS, BALANCES, COSTS, EQUAL_COUNTS, Color, DrawnContour, Key, Matching, Points, Scene, Shape
from .plan.options import DEFAULT_MAX_FRAMES, REEL_FPS, REEL_SIZE, SHEET_COUNT, MatchSettings, Progress, RenderOptions

__all__ = [
    "load_scene", "init_scene", "parse_scene", "frame", "frames", "outlines", "contours", "write", "interpolate",
    "stats", "correspondence", "qcurves", "describe", "sheet", "report", "reel",
    "stats_text", "correspondence_text", "qcurves_text", "frame_count", "png_bytes",
    "method_names", "format_names", "format_loop", "output_kinds", "listing", "output_format", "default_suffix",
    "check_preview_settings", "edit_scene_text", "save_scene_text", "editing_state", "drawings_scene_text",
    "start_encoder_search", "encoder_search_done", "sweep_temporaries",
    "RenderOptions", "MatchSettings", "Scene", "Shape", "Key", "Matching", "DrawnContour",
    "COSTS", "ALIGNS", "EQUAL_COUNTS", "BALANCES", "DEFAULT_MAX_FRAMES", "SHEET_COUNT", "REEL_SIZE", "REEL_FPS",
    "__version__",
]

# -- scenes ----------------------------------------------------------------------------------------


def load_scene(path: str | os.PathLike[str] | Sequence[str | os.PathLike[str]], step: float = 1.0,
               ease: str = "linear", hold: float = 0.0, stagger: float = 0.0) -> Scene:
    """The scene at ``path`` (TOML; JSON by its ``.json`` suffix — a Lottie animation when its top level has
    ``v``, ``fr``, ``ip``, ``op`` and ``layers``, see docs/lottie.md; one SVG drawing by ``.svg``), validated;
    or, for a list of SVG files, their drawings morphing one into the next (what ``tweenrender render
    a.svg b.svg`` renders): each shown ``hold`` seconds, then moving for ``step`` seconds under ``ease``,
    element i of a drawing starting ``i × stagger`` seconds later and arriving on time."""
    from .pipeline.library import load_scene as load

    return load(path, step, ease, hold, stagger)


def init_scene(drawings: Sequence[str | os.PathLike[str]], step: float = 1.0, ease: str = "linear",
               hold: float = 0.0, stagger: float = 0.0, path: str | os.PathLike[str] | None = None) -> str:
    """The TOML text of a ``[[drawing]]`` scene that renders exactly as ``load_scene(drawings, step, ease,
    hold, stagger)`` does (what ``tweenrender init`` writes), file names relative to ``path``'s folder;
    with ``path`` it is also written there, never replacing a file (an :class:`OptionError`)."""
    from .pipeline.library import init_scene as init

    return init(drawings, step, ease, hold, stagger, path)


def parse_scene(text: str, path: str | os.PathLike[str], fmt: str = "toml") -> Scene:
    """The scene written in ``text`` (``fmt`` ``"toml"`` or ``"json"``); ``path`` names it in errors and
    places its relative file names."""
    from .errors import OptionError
    from .scenefile import parse_scene as parse

    if not isinstance(text, str):
        raise OptionError(f"expected the scene's text as a str, found {type(text).__name__}", "text")
    if not isinstance(path, (str, os.PathLike)):
        raise OptionError(f"expected a file name to name the scene by, found {type(path).__name__}", "path")
    if fmt not in ("toml", "json"):
        raise OptionError(f"expected 'toml' or 'json', found {fmt!r}", "fmt")
    return parse(text, Path(path), fmt)


def describe(scene: Scene) -> dict[str, Any]:
    """The scene as loaded, in world units (what ``check --json`` prints)."""
    from .reports.analyses import describe as described

    return described(scene)


# -- pictures and outlines -------------------------------------------------------------------------


def frame(scene: Scene, time: float, *, method: str | None = None, size: tuple[int, int] | None = None,
          background: str | Color | None = None) -> NDArray[np.uint8]:
    """The picture at ``time`` seconds: a fresh ``(height, width, 4)`` uint8 array, straight RGBA.

    ``method`` overrides every shape's own; ``size`` is ``(width, height)`` in pixels (default the
    scene's); ``background`` a colour (``"#rrggbbaa"``, ``"none"``, or an RGBA tuple). Before the
    first key the first key is drawn, after the last the last."""
    from .pipeline.library import frame as drawn

    return drawn(scene, time, method=method, size=size, background=background)


def frames(scene: Scene, *, method: str | None = None, size: tuple[int, int] | None = None,
           background: str | Color | None = None, fps: float | None = None) -> Iterator[NDArray[np.uint8]]:
    """Every frame of the clip at ``fps`` (default the scene's), frame ``f`` at ``f / fps`` seconds:
    ``frame_count(scene, fps)`` fresh ``(height, width, 4)`` uint8 arrays, straight RGBA."""
    from .pipeline.library import frames as drawn

    return drawn(scene, method=method, size=size, background=background, fps=fps)


def frame_count(scene: Scene, fps: float | None = None) -> int:
    """How many frames :func:`frames` yields at ``fps`` (default the scene's): ``ceil(last time · fps −
    1e-9) + 1``."""
    from .plan.job import total_frames
    from .plan.options import check_fps, check_scene

    return total_frames(check_scene(scene), None if fps is None else check_fps(fps))


def outlines(scene: Scene, time: float, *, method: str | None = None) -> list[Points]:
    """Every drawn contour at ``time`` seconds under ``method`` (default each shape's own): fresh ``(N, 2)``
    float64 arrays in scene units, y up, in paint order (see :func:`contours`)."""
    from .pipeline.library import outlines as drawn

    return drawn(scene, time, method=method)


def contours(scene: Scene, time: float, method: str | None = None, *, points: bool = False) -> list[DrawnContour]:
    """Every drawn contour at ``time`` seconds as :class:`~tweenrender.model.DrawnContour` s, in the order
    of :func:`outlines`: which are open strokes, which holes, their element and paint. With ``points``,
    contours that are one point at that time (growing from it, shrinking to it, or not started yet) are
    kept too, so an element has the same contours at every time of a segment."""
    from .pipeline.library import contours as drawn

    return drawn(scene, time, method=method, points=bool(points))


def interpolate(k0: ArrayLike, k1: ArrayLike, t: ArrayLike, method: str, joints: Sequence[Any] = ()) -> NDArray:
    """Two corresponding keys ``(N, 2)`` at times ``t`` (``(T,)``) under ``method``: ``(T, N, 2)``."""
    from .core.methods.registry import interpolate as moved

    return moved(k0, k1, t, method, tuple(joints))  # type: ignore[arg-type]


def png_bytes(picture: NDArray[np.uint8]) -> bytes:
    """A straight-RGBA picture ``(height, width, 4)`` as the bytes of a PNG file (quick to compress)."""
    from .encode.images import png_bytes as encoded

    return encoded(picture)


# -- writing ---------------------------------------------------------------------------------------


def write(scene: Scene, path: str | os.PathLike[str], *, options: RenderOptions | None = None,
          **named: Any) -> Path:
    """Write the clip to ``path`` exactly as ``tweenrender render`` does; returns the path written.

    Options come by their long names (``RenderOptions.names()``: ``method, compare, format, size, fps,
    frames, background, balance, cost, align, equal_counts, max_memory, paths, onion, strip, workers,
    cluster, max_frames, progress, max_error, loop``) or as one ``options`` object. The format is ``format`` or
    ``path``'s extension (:func:`format_names`); a name without one is a folder of PNG frames. The
    target changes only when the whole output was written and checked."""
    from .pipeline.library import write as written

    return written(scene, path, options=options, **named)


def sheet(scene: Scene, path: str | os.PathLike[str], *, methods: Sequence[str] | None = None,
          count: int = SHEET_COUNT, size: tuple[int, int] | None = None, paths: bool = False,
          **match: str | None) -> Path:
    """A storyboard PNG like the thesis's figures: one row per method (default the scene's compare list),
    ``count`` inbetweens evenly spaced over the clip; ``match`` the correspondence settings (module
    docstring); returns the path written."""
    from .reports.documents import sheet as drawn

    return drawn(scene, path, methods=methods, count=count, size=size, paths=paths,
                 match=MatchSettings.create(**match))


def report(scene: Scene, path: str | os.PathLike[str], *, compare: Sequence[str] | None = None,
           progress: Callable[[str], Progress | None] | None = None, **match: str | None) -> Path:
    """The HTML report folder ``path``: every method's animation in sync, sheet, correspondence, metric
    charts and table; returns its ``index.html``. ``progress(name)`` may give a callback per video."""
    from .reports.documents import report as written

    return written(scene, path, compare=compare, match=MatchSettings.create(**match), progress=progress)


def reel(scenes: Sequence[Scene], path: str | os.PathLike[str], *, names: Sequence[str] | None = None,
         size: tuple[int, int] = REEL_SIZE, fps: float = REEL_FPS, methods: Sequence[str] | None = None,
         onion: int = 0, plain: bool = False, max_frames: int = DEFAULT_MAX_FRAMES,
         progress: Progress | None = None, **match: str | None) -> Path:
    """A demo reel: a title card and a comparison of ``methods`` (default each scene's compare list) for
    each scene, in one video or folder of frames; returns the path written. ``names`` label the scenes
    (default their files' stems); ``plain`` leaves out vertex paths and the perimeter strip."""
    from .reports.documents import reel as written

    return written(scenes, path, names=names, size=size, fps=fps, methods=methods, onion=onion, plain=plain,
                   match=MatchSettings.create(**match), max_frames=max_frames, progress=progress)


def output_format(path: str | os.PathLike[str], fmt: str | None = None) -> str:
    """The format ``path`` is written in: ``fmt``, else its extension; a name without one is PNG frames."""
    from .pipeline.library import output_format as chosen

    return chosen(Path(path), fmt)


def default_suffix(fmt: str | None = None) -> str:
    """The ending of a default output name in ``fmt`` (default the default format; ``""`` for a folder)."""
    from .encode.formats import DEFAULT, TABLE, lookup

    return (lookup(fmt) if fmt else TABLE[DEFAULT]).suffix


def format_names(*, vector: bool | None = None, alpha: bool | None = None,
                 loop: bool | None = None, draft: bool | None = None) -> tuple[str, ...]:
    """The output formats a user may ask for, in the format table's order: ``vector`` keeps those of paths
    (True) or of pictures (False), ``alpha`` those that keep a transparent background (True) or not,
    ``loop`` those whose file can say it loops (True) or not, ``draft`` those with quicker encoder
    settings (True) or not."""
    from .encode.formats import names

    return names(vector=vector, alpha=alpha, loop=loop, draft=draft)


def format_loop(fmt: str) -> str | None:
    """What ``loop`` makes of a ``fmt`` file, in words (``None``: it cannot say whether it loops)."""
    from .encode.formats import lookup

    return lookup(fmt).loop


def output_kinds(*, vector: bool | None = None) -> str:
    """What an output may be, in words made from the format table (``.mp4, .webm, … or a folder of PNG
    frames``)."""
    from .encode.formats import outputs_text

    return outputs_text(vector=vector)


def listing(items: Sequence[str], last: str = "and") -> str:
    """``items`` as a sentence lists them: ``a``, ``a and b``, ``a, b and c``."""
    from .encode.formats import listing as listed

    return listed(items, last)


def method_names() -> tuple[str, ...]:
    """Every interpolation method's name, in the registry's order."""
    from .core.methods.registry import METHODS

    return tuple(METHODS)


def start_encoder_search(path: str | os.PathLike[str], fmt: str | None = None) -> None:
    """Begin looking for ffmpeg on a thread while the scene loads, where ``path`` is a video it encodes (a
    format that cannot be told is left for :func:`write` to refuse)."""
    from .encode.formats import TABLE
    from .errors import OptionError

    try:
        chosen = TABLE[output_format(path, fmt)]
    except OptionError:
        return
    if chosen.ffmpeg:
        from .encode.sinks import find_ffmpeg_early

        find_ffmpeg_early()


def encoder_search_done() -> None:
    """Wait for the search :func:`start_encoder_search` began, so that no child process outlives a command."""
    from .encode.sinks import ffmpeg_search_done

    ffmpeg_search_done()


def sweep_temporaries() -> None:
    """Remove what runs that were killed left in ``$TMPDIR/tweenrender-<uid>/`` (parts, scratch folders):
    the folders of processes that no longer run, never one whose process still runs."""
    from .encode.scratch import sweep_scratch

    sweep_scratch()


def check_preview_settings(method: str | None, size: tuple[int, int] | None,
                           fps: float | None) -> tuple[str | None, tuple[int, int] | None, float | None]:
    """The preview's ``method``, ``size`` and ``fps``, each checked as :func:`write` checks it (None: the
    scene's)."""
    from .plan.options import check_fps, check_method, check_size

    return (None if method is None else check_method(method), None if size is None else check_size(size),
            None if fps is None else check_fps(fps))


# -- editing (the preview's edits) ----------------------------------------------------------------


def edit_scene_text(text: str, path: str | os.PathLike[str], ops: object) -> str:
    """The TOML scene ``text`` (of the file ``path``) with the preview's edit ``ops`` applied (DESIGN, "The
    preview edits"), comments and layout kept; a :class:`~tweenrender.errors.SceneError` (the loader's
    one line) when an op is not one or the result does not load."""
    from .pipeline.scene_editing import edited_scene_text

    return edited_scene_text(text, Path(path), ops)


def save_scene_text(path: str | os.PathLike[str], text: str) -> None:
    """Write a scene's ``text`` to ``path`` atomically (a sibling file moved over it when complete)."""
    from .pipeline.scene_editing import save_scene_text as save

    save(Path(path), text)


def editing_state(scene: Scene, size: tuple[int, int] | None = None, method: str | None = None) -> dict[str, Any]:
    """Every key's outlines, hints, arcs and timing, and ``to_page`` (scene units to the picture's pixels
    at ``size``, as drawn with ``method``): what the preview's page edits."""
    from .pipeline.scene_editing import editing_state as state

    return state(scene, size, method)


def drawings_scene_text(svgs: Sequence[str | os.PathLike[str]], folder: str | os.PathLike[str], step: float = 1.0,
                        ease: str = "linear", hold: float = 0.0, stagger: float = 0.0) -> str:
    """A ``[[drawing]]`` scene (TOML) of ``svgs`` as the command line morphs them, its file names relative
    to ``folder``."""
    from .scenefile.scene_edits import drawings_scene_text as text

    return text([Path(p) for p in svgs], Path(folder), step, ease, hold, stagger)


# -- reports ---------------------------------------------------------------------------------------


def stats(scene: Scene, t: Sequence[float] = (0.5,), methods: Sequence[str] | None = None) -> dict[str, Any]:
    """The thesis's ch. 6 perimeter report and the quality measures per shape, segment and method, at
    ``t`` within each segment (what ``stats --json`` prints)."""
    from .reports.analyses import stats as measured

    return measured(scene, t, methods)


def correspondence(scene: Scene, picture: str | os.PathLike[str] | None = None,
                   **match: str | None) -> dict[str, Any]:
    """The vertex correspondence of every segment: pairs, balanced count, work (what ``correspond --json``
    prints); ``picture`` names a PNG to draw it in; ``match`` the correspondence settings."""
    from .reports.analyses import correspondence as matched

    return matched(scene, picture, MatchSettings.create(**match))


def qcurves(scene: Scene, picture: str | os.PathLike[str] | None = None) -> dict[str, Any]:
    """Every vertex's Q-curve, the motion it shows and auto's choice (what ``qcurves --json`` prints);
    ``picture`` names a PNG to plot them in."""
    from .reports.analyses import qcurves as curves

    return curves(scene, picture)


def stats_text(report: dict[str, Any]) -> str:
    """:func:`stats`' report as the lines ``tweenrender stats`` prints."""
    from .reports.stats import stats_text as text

    return text(report)


def correspondence_text(report: dict[str, Any]) -> str:
    """:func:`correspondence`'s report as the lines ``tweenrender correspond`` prints."""
    from .reports.match_report import correspond_text

    return correspond_text(report)


def qcurves_text(report: dict[str, Any]) -> str:
    """:func:`qcurves`' report as the lines ``tweenrender qcurves`` prints."""
    from .reports.qcurve_report import qcurves_text as text

    return text(report)
