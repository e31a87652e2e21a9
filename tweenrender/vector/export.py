"""What a vector file holds: every element's contours and paint at every frame, reduced to keyframes.

:func:`vector_clip` samples each shape once per frame of the clip (exactly what the raster draws), maps
scene units to output pixels, and splits each shape's frames into *runs* (:mod:`.runs`): consecutive
frames of one segment on which it is drawn alike. A run keeps one list of contours (the segment's pairs,
so every contour keeps one vertex count) and becomes a layer (Lottie, with ``ip``/``op``) or a path
element shown over those frames (SVG). Paths are cubic Bézier contours (:mod:`.curves`) keyed by
:mod:`.keyframes`: a contour that moves straight between its segment's keys (``linear``, ``auto``'s
straight paths with their copies spread) whose keys fall on whole frames is those two keys, timed by the
segment's easing (in the Lottie, even where its element's other contours need more); every other run's
paths are fitted within ``max_error`` pixels (keyframe values free within it, each span with its own
timing; the run's first and last keyframes exact); paint within 1/255 (width, a gradient's geometry and
clip paths within ``max_error``; see :mod:`.paint_keys`).
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import numpy as np
from numpy.typing import NDArray

from .curves import Blend, RIDGE, STRAIGHT_RIDGE, distance_to_polyline, fit_curves, free_points, with_fixed_points
from .dash_keys import contour_dashes, dash_rows
from .keyframes import fit_keyframes, greedy_keyframes, paint_channels
from .pieces import pieces_and_holes
from .runs import Span, runs_of, stacking_phases, stroked, style
from .scaled_keys import scaled_contour
from ..core.timing.timeline import Segment, ShapeAt, Track, evaluate_segment, pair_paths, segment_method
from ..encode.formats import is_vector, listing, names, writer
from ..encode.vector_data import PIXEL_DIGITS, STRAIGHT, ContourMove, Handles, VectorClip, VectorRun
from ..errors import OptionError
from ..model import Color, Paint, Shape
from ..core.geometry import signed_area
from ..core.view import Viewport
from ..plan.job import RenderJob, scene_view, tracks_of
from ..plan.options import RenderOptions
from .paint_keys import clip_path_keys, gradient_frame_paths, gradient_samples

__all__ = ["vector_clip", "write_vector", "refuse_raster_options", "RASTER_ONLY", "DEFAULT_MAX_ERROR", "VECTOR_SAMPLES"]

Array = NDArray[np.float64]
DEFAULT_MAX_ERROR = 0.25
"""Output pixels a baked path may stray from the exact inbetween at a frame time."""

CURVE_SHARE = 0.8
"""The share of ``max_error`` the cubic fit at each frame may take; the keyframes between take the rest
(measured on icon pairs, ``benchmarks/vector_size.py``: the Lottie is 35× the sources at the median with
half, 26× with 0.8: a path's vertices weigh more than its keyframes)."""

_SAME = 1e-6
"""Pixels within which two polylines count as drawing the same line (rounding of a straight continuation)."""
EXACT_SHARE = 0.95
"""The share of ``max_error`` the cubic fit of a contour that moves straight between two keys may take (its two
keyframes play the fitted curves exactly, up to the files' rounding and the arithmetic's)."""

APART = 1.0
"""Pixels beyond the bound (and a stroke's reach) two contours stay apart at every frame to be drawn as paths of
their own: the antialiasing of one never touches a pixel of the other."""

_ON_FRAME = 1e-6  # a key time this close to a whole frame (in frames) is on it
_ROUNDING = 0.5 * 10.0 ** -PIXEL_DIGITS * np.sqrt(2.0)
"""How far a vertex moves when the files round its pixels to :data:`PIXEL_DIGITS` decimals (a control point, written as
an offset from its vertex, moves twice that at most): kept out of the bound."""


VECTOR_SAMPLES = 10_000_000
"""Most vertex samples a vector file may take (frames × the vertices drawn at once, every shape's together):
each is kept until the frames are reduced to keyframes (some 160 MB of coordinates at the limit, more as
Python objects), so a clip past it is refused before any is taken."""


RASTER_ONLY = ("compare", "paths", "onion", "strip", "workers", "cluster", "draft")
"""Render options a vector file cannot carry: it holds the scene's own animated paths, drawn by its player."""


def refuse_raster_options(fmt: str, options: RenderOptions) -> None:
    """Refuse each of :data:`RASTER_ONLY` that ``options`` sets, naming it."""
    for name in RASTER_ONLY:
        if getattr(options, name) not in (None, False, 0):
            raise OptionError(f"cannot be used with a {fmt} file, which holds the scene's own animated paths, "
                              "drawn by its player; render a video or PNG frames for that", name)


def write_vector(job: RenderJob, fmt: str, target: Path, max_error: float | None = None, loop: bool = False) -> Path:
    """Write ``job`` (one panel, nothing drawn over it) as the vector format ``fmt`` (``lottie``, ``dotlottie``
    or ``svg``: :func:`~..encode.formats.is_vector`) to ``target``, atomically, by the format's writer;
    ``loop``: the file says it plays over and over."""
    if not is_vector(fmt):
        raise OptionError(f"expected a vector format, {listing(names(vector=True), 'or')}, found {fmt!r}", "format")
    clip = replace(vector_clip(job, DEFAULT_MAX_ERROR if max_error is None else max_error, pieces=fmt == "svg"),
                   loop=loop)
    written: Path = writer(fmt)(clip, target)
    return written


def vector_clip(job: RenderJob, max_error: float = DEFAULT_MAX_ERROR, pieces: bool = True) -> VectorClip:
    """Sample ``job`` (one panel) at every frame of its range and reduce each run to keyframes; with ``pieces``,
    each run's contours grouped into pieces that an animated SVG may draw apart (:attr:`VectorRun.pieces`: work
    that only the SVG writer uses)."""
    if isinstance(max_error, bool) or not (isinstance(max_error, (int, float)) and np.isfinite(max_error)
                                           and max_error > 0):
        raise OptionError(f"expected a positive number of output pixels, found {max_error!r}", "max_error")
    scene = job.scene
    tracks = tracks_of(scene)
    width, height = job.panel_size
    viewport = Viewport(scene_view(scene, tracks, job.methods), width, height)
    picked = job.frame_range
    offset, count = picked.start, len(picked)
    _check_samples(tracks, count)
    times = np.arange(offset, offset + count) / job.rate
    methods = [job.methods[0] or scene.method_of(shape) for shape in scene.shapes]
    drawn = [track.at(times, method) for track, method in zip(tracks, methods)]
    orders, phases = stacking_phases(scene, tracks, times, drawn)
    placed: list[tuple[int, int, VectorRun]] = []  # (stacking phase, place in its order, run)
    for index, (shape, track, method, shapes) in enumerate(zip(scene.shapes, tracks, methods, drawn)):
        segments = track.segment_index(times) if track.segments else np.zeros(count, dtype=np.intp)
        for span in runs_of(shape, shapes, segments, phases):
            first, stop = span.first, span.stop
            whole = int(phases[first]) == int(phases[stop - 1]) and (stop == count or phases[stop] == phases[first])
            exact = _exact_keys(track, int(segments[first]), method, job.rate, offset, count)
            ending = _ending(track, int(segments[first]), method, stop, job.rate, offset, count) \
                if exact is None and whole else None
            run = _run(shape, shapes[first:stop], span, viewport, exact, method, max_error, times[first:stop],
                       ending, pieces)
            placed.append((int(phases[first]), orders[int(phases[first])].index(index), run))
        drawn[index] = []  # its samples are keyframed: let them go
    runs = tuple(run for _, _, run in sorted(placed, key=lambda item: item[:2]))
    return VectorClip((width, height), job.rate, count, scene.background, runs, max_error)


def _check_samples(tracks: tuple[Track, ...], frames: int) -> None:
    """Refuse a clip whose ``frames`` × the vertices its shapes draw at once (each shape's largest segment)
    pass :data:`VECTOR_SAMPLES`."""
    vertices = sum(max((sum(len(pair.k0) for pair in segment.pairs) for segment in track.segments),
                       default=sum(len(points) for points in track.still.contours)) for track in tracks)
    if frames * vertices > VECTOR_SAMPLES:
        raise OptionError(f"expected a vector file of at most {VECTOR_SAMPLES:,} vertex samples (frames × vertices "
                          f"drawn at once), found {frames:,} frames × {vertices:,} vertices = {frames * vertices:,}; "
                          "render fewer frames (a lower --fps or a shorter range) or a video", "format")


def _exact_keys(track: Track, segment: int, method: str, fps: float, offset: int,
                count: int) -> tuple[int, int, Segment] | None:
    """The clip frames where a ``linear`` segment's motion starts (its first key, or after the key's hold)
    and ends (its second key), and the segment, when both are whole frames of the clip, every pair moves
    together (no stagger) and its easing has exact handles."""
    if not track.segments:
        return None
    seg = track.segments[segment]
    if segment_method(seg, method) != "linear" or _timing(seg) is None or seg.stagger > 0:
        return None
    ends = []
    for time in (seg.start + seg.delay, seg.end):
        at = time * fps - offset
        if abs(at - round(at)) > _ON_FRAME or not 0 <= round(at) < count:
            return None
        ends.append(int(round(at)))
    return ends[0], ends[1], seg


def _timing(segment: Segment) -> Handles | None:
    """The cubic-bezier handles of a segment's easing, if a Bézier draws it exactly (``linear``, or a curve
    such as ``in-out`` or ``cubic-bezier(…)``: :data:`..core.timing.easing.NAMED`) and both files can
    carry it: SMIL's ``keySplines`` take values in [0, 1] only, so a curve that overshoots is baked."""
    easing = segment.easing
    handles = STRAIGHT if easing.text == "linear" else getattr(easing, "handles", None)
    if handles is None or not all(0.0 <= h <= 1.0 for h in handles):
        return None
    return tuple(float(h) for h in handles)  # type: ignore[return-value]


def _ending(track: Track, segment: int, method: str, stop: int, fps: float, offset: int,
            count: int) -> tuple[ShapeAt, list[Array]] | None:
    """The segment's second key, when the run ends because that key is drawn at clip frame ``stop`` by
    the next segment's run: then the run's keyframes go on to it, so a player moving between frames
    ``stop - 1`` and ``stop`` moves towards the key rather than holding still."""
    if not track.segments or stop >= count:
        return None
    seg = track.segments[segment]
    at = seg.end * fps - offset
    if abs(at - stop) > _ON_FRAME or segment + 1 >= len(track.segments):
        return None
    end = evaluate_segment(seg, np.array([1.0]), method)[0]
    points = [p[0] for p in pair_paths(seg, np.array([1.0]), method)]  # every pair's, growing ones too
    shares = tuple(0.0 if p.source[1] is None else 1.0 for p in seg.pairs)  # one shrunk to a point: no stroke
    end = replace(end, widths=shares)
    return (end, points) if end.fade is None and all(np.all(np.isfinite(p)) for p in points) else None


def _run(shape: Shape, shapes: list[ShapeAt], span: Span, viewport: Viewport,
         exact: tuple[int, int, Segment] | None, method: str, max_error: float, run_times: Array,
         ending: tuple[ShapeAt, list[Array]] | None = None, pieces: bool = True) -> VectorRun:
    """The run ``span`` of ``shape``, drawn as ``shapes`` at its frames, as keyframes (with ``pieces``, its
    contours grouped into pieces: :func:`_with_pieces`)."""
    first, stop = span.first, span.stop
    keep = [i for i, c in enumerate(shapes[0].contours) if len(c) >= 2]
    flips = span.reversed or (False,) * len(shapes[0].contours)
    samples = [_drawn(viewport, np.stack([at.contours[i] for at in shapes]), flips[i]) for i in keep]  # (F, L_i, 2)
    joined = np.concatenate(samples, axis=1) if samples else np.zeros((len(shapes), 0, 2))
    every_pair = exact is not None and len(shapes[0].contours) == len(exact[2].pairs)
    if ending is not None and len(shapes[0].contours) == len(ending[1]):
        # the key at frame ``stop`` closes the run's keyframes (not drawn by it)
        end_shape, end_points = ending
        samples = [np.concatenate([s, _drawn(viewport, end_points[i], flips[i])[None]])
                   for s, i in zip(samples, keep)]
        shapes = [*shapes, end_shape]
    closed = tuple(shapes[0].closed[i] for i in keep)
    samples = [_opened(s, shut) for s, shut in zip(samples, closed)]
    paths: tuple[Array, ...] = ()
    contour_keys: tuple[tuple[tuple[int, ...], Array, tuple[Handles, ...]], ...] | None = None
    exact_own: dict[int, tuple[tuple[int, ...], Array, tuple[Handles, ...]]] = {}
    if exact is not None and every_pair:
        a, b, segment = exact
        t = segment.local_t(run_times)
        opened = _segment_ends(segment, method)
        ends = [_drawn(viewport, opened[i], flips[i]) for i in keep]  # (2, L_i, 2) each
        samples = [_with_ends(s, t, e, shut) for s, e, shut in zip(samples, ends, closed)]
        path_frames: tuple[int, ...] = (a, b)
        exact_tolerance = max_error * EXACT_SHARE - 2 * _ROUNDING  # the keyframes add nothing but rounding
        # every frame's cubics are the keys' blended by the segment's eased progress, as a player draws them,
        # and are measured against every frame's exact in-between
        blend = Blend(len(t), len(t) + 1, np.concatenate([t, [0.0, 1.0]]))
        ease = _timing(segment) or STRAIGHT
        eases: tuple[Handles, ...] = (ease,)
        # the fit measures each blended cubic against every frame; a span that is one edge is the blend of its two
        # vertices, so each contour's vertices moved along the eased chord must be within what the fit left of
        # the bound (less the files' rounding) of their own at every frame (a contour may grow otherwise than
        # straight); those that are keep their two keyframes. A contour whose vertices leave the chord by the
        # whole bound cannot be one of them, whatever its fit: it is not fitted
        for index, (s, e, shut) in enumerate(zip(samples, ends, closed)):
            chord = e[0] + t[:, None, None] * (e[1] - e[0])
            off = float(np.linalg.norm(chord - s[:len(t)], axis=-1).max())
            if off > max_error - 2 * _ROUNDING:
                continue
            _, curve, error = _fewest_cubics(np.concatenate([s, e]), shut, exact_tolerance, blend)  # (F + 2, M, 3, 2)
            if off <= max_error - error - 2 * _ROUNDING:
                exact_own[index] = (path_frames, curve[-2:], eases)
        if len(exact_own) < len(samples):
            exact = None
        else:
            paths = tuple(path for _, path, _ in exact_own.values())
    fits: tuple[list[Array], list[NDArray[np.bool_]], list[float]] | None = None  # each contour's, keyed apart
    if exact is None or not every_pair:
        path_frames, paths, eases = (first,), (), ()
        if samples:
            frames_in, paths, eases, (curves, free, errors) = keyed_curves(samples, closed, max_error)
            path_frames = tuple(first + k for k in frames_in)
            if len(curves) > 1:  # each contour keyed on its own too, for the files that animate them apart
                own = []
                for index, (c, f, error) in enumerate(zip(curves, free, errors)):
                    if index in exact_own:  # straight between the keys: exact with its two keyframes
                        own.append(exact_own[index])
                        continue
                    alone = fit_keyframes(c[:, f], _key_tolerance(max_error, error))
                    own.append((tuple(first + k for k in alone.frames), with_fixed_points(alone.values, f),
                                alone.handles()))
                contour_keys = tuple(own)
                fits = (curves, free, errors)
    scale = viewport.scale if shape.stroke_scales else 1.0
    paints = [at.paint for at in shapes]
    fill, stroke, width, opacity = _paint_arrays(paints, scale)
    gradient = gradient_samples(paints, viewport, max_error)
    if gradient is not None:
        fill = None  # filled by the gradient, a plain key as a gradient of its one colour
    channels = paint_channels(_or_clear(fill, len(shapes)), _or_clear(stroke, len(shapes)), width, opacity,
                              max_error)
    shares = np.array([[at.widths[i] if at.widths else 1.0 for i in keep] for at in shapes]).reshape(len(shapes), -1)
    contour_widths = None
    if stroke is not None and np.any(shares != 1.0):
        contour_widths = width[:, None] * shares  # (F, C)
        channels = np.concatenate([channels, contour_widths[:, :, None] / max_error], axis=1)
    dash = dash_rows(paints, scale, shape.name) if stroke is not None else None
    dashes = None if dash is None else _contour_dashes(dash, samples, shapes, keep, flips, closed)
    if dashes is not None:
        channels = np.concatenate([channels, *(d[:, :, None] / max_error for d in dashes)], axis=1)
    channels = np.pad(channels, ((0, 0), (0, 0), (0, 1)))  # (F, C, 2), beside the gradient's points
    if gradient is not None:
        channels = np.concatenate([channels, gradient.channels()], axis=1)
    paint_keys = greedy_keyframes(channels, 1.0)
    pick = np.array(paint_keys)
    _, cap, join, miter = style(shape, next((at for at in shapes if stroked(at)), shapes[0]))
    run = VectorRun(shape.name, first, stop, path_frames, paths, closed, eases, tuple(first + k for k in paint_keys),
                    None if fill is None else fill[pick], None if stroke is None else stroke[pick], width[pick],
                    opacity[pick], span.rule, cap, join, miter, joined,
                    None if contour_widths is None else contour_widths[pick],
                    None if gradient is None else gradient.keys(pick),
                    clip_path_keys(shapes, first, viewport, max_error),
                    exact_lengths=tuple(s.shape[1] for s in samples),
                    contour_keys=contour_keys,
                    dash=None if dashes is None else tuple(d[pick] for d in dashes), rule_switch=span.switch)
    run = replace(run, gradient_paths=gradient_frame_paths(run, max_error, keyed_curves))
    run = _with_moves(run, samples, max_error)
    return _with_pieces(run, samples, fits, max_error) if pieces else run


def _with_pieces(run: VectorRun, samples: list[Array], fits: tuple[list[Array], list[NDArray[np.bool_]], list[float]]
                 | None, max_error: float) -> VectorRun:
    """``run`` with its contours (``samples (F, L_i, 2)``, fitted apart as ``fits``: each contour's curves at every
    frame, their free points, the distance each fit reached) grouped into pieces apart by :data:`APART` pixels
    beyond the bound and the stroke's reach at every frame (:func:`.pieces.apart_pieces`), where its contours
    have keyframes of their own and one dash pattern. In a plain fill (no stroke) a piece's holes
    that stay as far from its other contours are cut out of it (:func:`.pieces.cut_holes`); the rest of a piece
    of several contours is keyed on its own (as :func:`keyed_curves` keys a run)."""
    if fits is None or run.dash is not None or len(run.paths) < 2:  # fits: its contours keyed apart
        return run
    reach = 0.0 if run.stroke is None else 0.5 * float(np.max(run.width, initial=0.0)) * max(run.miter_limit,
                                                                                              np.sqrt(2.0))
    apart = max_error + APART + reach
    cutting = run.stroke is None and (run.fill is not None or run.gradient is not None)
    rules = [run.fill_rule if run.rule_switch is None or run.first + f < run.rule_switch[0] else run.rule_switch[1]
             for f in range(len(samples[0]))]  # the rule at each frame sampled, the run's closing key too
    found = pieces_and_holes(samples, rules, apart, cutting)  # the key closing the run too, if any
    if found is None:
        return run
    pieces, cuts = _moves_apart(run, samples, rules, *found)
    if len(pieces) < 2 and not any(cuts):
        return run
    curves, free, errors = fits
    keys: list[tuple[tuple[int, ...], tuple[Array, ...], tuple[Handles, ...]] | None] = []
    for members, cut in zip(pieces, cuts):
        drawn = [i for i in members if i not in cut]
        if len(drawn) == 1:
            keys.append(None)  # its own keys (and move)
            continue
        frames, paths, handles = _keyed_together([curves[i] for i in drawn], [free[i] for i in drawn],
                                                 [errors[i] for i in drawn], max_error)
        keys.append((tuple(run.first + k for k in frames), paths, handles))
    return replace(run, pieces=pieces, piece_keys=tuple(keys), piece_cuts=cuts if any(cuts) else None)


def _moves_apart(run: VectorRun, samples: list[Array], rules: list[str], pieces: tuple[tuple[int, ...], ...],
                 cuts: tuple[tuple[int, ...], ...]) -> tuple[tuple[tuple[int, ...], ...], tuple[tuple[int, ...], ...]]:
    """``pieces`` and their ``cuts`` with each contour that only grows, shrinks and moves (:attr:`VectorRun.contour_moves`)
    made a piece of its own even where it comes near or over the others of its piece, so that it keeps one still
    path under its move instead of its piece keying every contour at every frame. Paths painted one over another
    cover what one path of them all fills where the fill is one opaque colour under the nonzero rule, nothing is
    stroked and every contour of the piece winds one way at every frame (``samples (F, L_i, 2)``): overlaps add to
    the winding and never cancel it. Not in a piece with holes cut out."""
    moves = run.contour_moves
    if moves is None or run.stroke is not None or run.fill is None or run.gradient is not None \
            or run.clip_paths is not None or any(rule != "nonzero" for rule in rules) \
            or float(np.min(run.fill[:, 3])) < 1.0:
        return pieces, cuts
    out_pieces: list[tuple[int, ...]] = []
    out_cuts: list[tuple[int, ...]] = []
    for members, cut in zip(pieces, cuts):
        moving = [i for i in members if moves[i] is not None]
        if cut or len(members) < 2 or not moving or not _one_winding([samples[i] for i in members]):
            out_pieces.append(members)
            out_cuts.append(cut)
            continue
        rest = tuple(i for i in members if moves[i] is None)
        if rest:
            out_pieces.append(rest)
            out_cuts.append(())
        out_pieces += [(i,) for i in moving]
        out_cuts += [() for _ in moving]
    return tuple(out_pieces), tuple(out_cuts)


def _one_winding(contours: list[Array]) -> bool:
    """Whether every contour ``(F, L_i, 2)`` that has an area winds the same way at every frame."""
    signs = np.concatenate([np.sign(signed_area(c)) for c in contours])  # (F,) each
    signs = signs[signs != 0]
    return bool(len(signs) == 0 or np.all(signs == signs[0]))


def _with_moves(run: VectorRun, samples: list[Array], max_error: float) -> VectorRun:
    """``run`` with each contour that only grows, shrinks and moves (``samples (F, L_i, 2)`` from the run's first
    frame) keyed as a still path under a keyed scale and position (:mod:`.scaled_keys`) where that is shorter; not
    where the stroke's width or dashes are the contour's own, or the fill is drawn in a gradient's frame."""
    if run.contour_widths is not None or run.dash is not None or run.gradient_paths is not None:
        return run
    keys = [run.keys_of(i) for i in range(len(samples))]
    moves: list[ContourMove | None] = []
    for index, (s, shut) in enumerate(zip(samples, run.closed)):
        frames, path, eases = keys[index]
        scaled = scaled_contour(s, shut, max_error * CURVE_SHARE,
                                # less the rounding of the written position and anchor (the path's is in the rest)
                                lambda fitted: _key_tolerance(max_error, fitted) - 2 * _ROUNDING, len(frames))
        if scaled is None:
            moves.append(None)
            continue
        moves.append(scaled.move.shifted(run.first))
        keys[index] = ((run.first,), scaled.curve, ())
    if all(m is None for m in moves):
        return run
    return replace(run, contour_keys=tuple(keys), contour_moves=tuple(moves))


def keyed_curves(samples: list[Array], closed: tuple[bool, ...], max_error: float
                 ) -> tuple[tuple[int, ...], tuple[Array, ...], tuple[Handles, ...], tuple[list[Array], list[NDArray[np.bool_]], list[float]]]:
    """Contours ``samples`` (``(F, L_i, 2)`` each, pixels) as cubic Bézier paths keyed together within ``max_error``
    of them at every frame: the keyframes' frames (from 0), the paths ``(K, M_i, 3, 2)``, each span's timing, and
    the curves fitted at every frame, their free points and the distance each fit reached."""
    fitted_curves = [fit_curves(s, shut, max_error * CURVE_SHARE) for s, shut in zip(samples, closed)]
    curves = [c for _, c, _ in fitted_curves]
    errors = [e for _, _, e in fitted_curves]
    free = [free_points(c) for c in curves]  # only these are keyframed; the rest sit on their vertex
    frames, paths, handles = _keyed_together(curves, free, errors, max_error)
    return frames, paths, handles, (curves, free, errors)


def _keyed_together(curves: list[Array], free: list[NDArray[np.bool_]], errors: list[float], max_error: float
                    ) -> tuple[tuple[int, ...], tuple[Array, ...], tuple[Handles, ...]]:
    """Contours fitted at every frame (``curves (F, M_i, 3, 2)``, their ``free (M_i, 3)`` points, each fit ``errors``
    pixels from its in-between) keyed together within ``max_error``: the keyframes' frames (from 0), the paths
    ``(K, M_i, 3, 2)`` and each span's timing."""
    keyed = fit_keyframes(np.concatenate([c[:, f] for c, f in zip(curves, free)], axis=1),
                          _key_tolerance(max_error, max(errors)))
    cuts = np.cumsum([int(f.sum()) for f in free])[:-1]
    paths = tuple(with_fixed_points(v, f) for v, f in zip(np.split(keyed.values, cuts, axis=1), free))
    return keyed.frames, paths, keyed.handles()


def _fewest_cubics(samples: Array, closed: bool, tolerance: float,
                   blend: Blend | None = None) -> tuple[NDArray[np.intp], Array, float]:
    """:func:`~.curves.fit_curves` of ``samples (F, L, 2)`` with the ridge that takes fewer cubics: the steady
    one, or the close one (a contour keyed only at its two keys needs no steadiness, and the close fit follows
    the keys' own curves where their in-betweens are curves too); with a ``blend``, every frame's cubics are
    its two frames' blended (:class:`~.curves.Blend`)."""
    fits = [fit_curves(samples, closed, tolerance, ridge, blend) for ridge in (RIDGE, STRAIGHT_RIDGE)]
    return min(fits, key=lambda fit: len(fit[0]))


def _same_drawing(a: Array, b: Array, closed: bool) -> bool:
    """Whether the polylines ``a`` and ``b`` ``(L, 2)`` (pixels) draw the same line: every vertex of each, and
    the quarter points of ``a``'s edges, on the other (within :data:`_SAME`)."""
    if a.shape != b.shape or not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
        return False
    ring_a = np.concatenate([a, a[:1]]) if closed else a
    ring_b = np.concatenate([b, b[:1]]) if closed else b
    edges = ring_a[:-1, None] + np.array([0.25, 0.5, 0.75])[:, None] * (ring_a[1:] - ring_a[:-1])[:, None]
    on_b = np.concatenate([a, edges.reshape(-1, 2)])
    return bool(distance_to_polyline(on_b[None], ring_b[None]).max() <= _SAME
                and distance_to_polyline(b[None], ring_a[None]).max() <= _SAME)


def _opened(samples: Array, closed: bool) -> Array:
    """``samples (F, L, 2)`` whose first (last) frame is replaced by the straight continuation of the two
    frames after (before) it where that draws the same line: a method that spreads a key's coincident
    copies along its edges in between (``auto``'s straight paths) moves them straight from there, so the
    keyframes need not break at the key."""
    if len(samples) < 3:
        return samples
    out = samples
    for at, near, far in ((0, 1, 2), (-1, -2, -3)):
        opened = 2 * samples[near] - samples[far]
        if not np.array_equal(opened, samples[at]) and _same_drawing(opened, samples[at], closed):
            out = out.copy() if out is samples else out
            out[at] = opened
    return out


def _segment_ends(segment: Segment, method: str) -> list[Array]:
    """Every pair's keys ``(2, L_i, 2)`` as the straight continuation of its in-betweens (at t = 1/3 and
    2/3) where that draws the same as the key (copies of a vertex spread along its edges), else the key."""
    keys = pair_paths(segment, np.array([0.0, 1.0]), method)
    inner = pair_paths(segment, np.array([1 / 3, 2 / 3]), method)
    out = []
    for key, path, pair in zip(keys, inner, segment.pairs):
        opened = np.stack([2 * path[0] - path[1], 2 * path[1] - path[0]])
        scale = max(float(np.abs(key).max()), 1.0)
        same = [_same_drawing(opened[k] / scale, key[k] / scale, pair.closed) for k in (0, 1)]
        out.append(np.stack([opened[k] if same[k] else key[k] for k in (0, 1)]))
    return out


def _with_ends(samples: Array, t: Array, ends: Array, closed: bool) -> Array:
    """``samples (F', L, 2)`` (the run's frames first, at segment times ``t (F,)``) with the frames at t = 0
    and 1 replaced by ``ends (2, L, 2)`` where those draw the same line."""
    out = samples.copy()
    for k, at in ((0, 0.0), (1, 1.0)):
        for f in np.flatnonzero(t == at):
            if _same_drawing(ends[k], samples[f], closed):
                out[f] = ends[k]
    return out


def _contour_dashes(dash: Array, samples: list[Array], shapes: list[ShapeAt], keep: list[int],
                    flips: tuple[bool, ...], closed: tuple[bool, ...]) -> tuple[Array, ...]:
    """Each kept contour's dash rows ``(F, C + 1)`` (:func:`.dash_keys.contour_dashes`)."""
    starts = np.array([[at.dash_starts[i] if at.dash_starts else 0.0 for i in keep] for at in shapes])
    return contour_dashes(dash, samples, starts.reshape(len(shapes), len(keep)), tuple(flips[i] for i in keep),
                          closed)


def _key_tolerance(max_error: float, fitted: float) -> float:
    """How far keyframed control points may stray from the curves fitted at each frame, when those are
    ``fitted`` pixels from the exact in-between: the rest of ``max_error``, less the files' rounding (a
    point of a cubic is a convex combination of its control points, so it strays no farther)."""
    return max(max_error - fitted - 2 * _ROUNDING, max_error * (1 - CURVE_SHARE) / 2)


def _drawn(viewport: Viewport, points: Array, flip: bool) -> Array:
    """A contour ``(N, 2)`` (or one per frame, ``(F, N, 2)``) in output pixels, in the order it is drawn
    (reversed where its key winds so)."""
    pixels = viewport.to_pixels(points)
    return pixels[..., ::-1, :] if flip else pixels


def _paint_arrays(paints: list[Paint], scale: float) -> tuple[Array | None, Array | None, Array, Array]:
    """Fill and stroke ``(F, 4)`` straight RGBA in [0, 1] (``None`` where never drawn), stroke width
    ``(F,)`` pixels and opacity ``(F,)`` of each frame's paint."""
    return (_colours([p.fill for p in paints]), _colours([p.stroke for p in paints]),
            np.array([p.stroke_width * scale for p in paints], dtype=np.float64),
            np.array([p.opacity for p in paints], dtype=np.float64))


def _colours(colours: list[Color | None]) -> Array | None:
    """``(F, 4)`` in [0, 1]; a missing colour is the nearest present one at alpha 0; ``None`` if none is."""
    present = [i for i, c in enumerate(colours) if c is not None]
    if not present:
        return None
    out = np.empty((len(colours), 4))
    for f, colour in enumerate(colours):
        if colour is None:
            near = colours[min(present, key=lambda i: abs(i - f))]
            out[f] = (*(np.array(near[:3]) / 255.0), 0.0)  # type: ignore[index]
        else:
            out[f] = np.array(colour, dtype=np.float64) / 255.0
    return out


def _or_clear(colours: Array | None, frames: int) -> Array:
    return np.zeros((frames, 4)) if colours is None else colours
