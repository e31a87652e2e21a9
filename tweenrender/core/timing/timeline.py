"""Keys → segments → shapes at any time (maths §5.3, §5.7, §5.8).

A shape's keys split its life into segments, one per consecutive pair of keys.
In each segment the contours of the two keys are paired (:mod:`.contours`),
each pair is balanced to one vertex count (:mod:`.correspond`), and the pairs
move together under the segment's method: all the pairs' vertices are
interpolated as one point set, so a shape with holes or pieces turns about one
center of mass. A contour without a partner, and every contour of an element appearing from or
leaving for a hidden key, grows from (or shrinks to) its anchor over the whole segment, its area
linear in the eased parameter (:mod:`.appear`). Paint blends in OKLab (:mod:`.paint`).

Frame ``f`` is drawn at ``time = f / fps``; before the first key a shape holds
its first key, after its last key the last one. A *hidden* key (where an element
grows from or shrinks to) is reached, never shown. A segment's easing (:mod:`.easing`)
maps its time to how far along the way it is, and may overshoot; a key's ``delay``
(a stagger, a hold) starts its segment's motion later, still ending on time. Shape
hints (:mod:`.hints`) pair contours and fix the correspondence at their vertices.
"""

from __future__ import annotations

import hashlib
import math
from dataclasses import dataclass, replace
from typing import Callable, Sequence

import numpy as np
from numpy.typing import NDArray

from ...errors import GeometryError
from ...model import Contour, Key, Matching, Paint, Points, Scene, Shape
from ..contours import anchors, keep_nesting, pair_contours, roles
from ..tangles import contact_times, proper_crossings
from ..correspondence.correspond import Correspondence, correspond, correspond_open
from ..balance import spread
from .appear import scaled, width_share
from .bridges import join_alone
from .clearance import GRID, Growth, cached, growth_scale, place
from .easing import LINEAR, Easing, parse_easing
from ..geometry import best_fit_rotation, signed_area
from ..clip_motion import clips_at
from ..mask_motion import MaskBlend, carried, masks_at, masks_at_key
from ..gradient_blend import blend_gradient, blend_stroke_gradient, box_of, carry_pattern
from ..correspondence.hint_search import correspond_hinted, correspond_hinted_open
from ..correspondence.hints import Link, forced_contour_pairs, segment_links, vertex_links

from ..methods.qcurves import (BALLOON, QUALITY_T, STRAY_LIMIT, AutoChoice, auto_choice, auto_choice_contours, balloon,
                               candidate_paths, candidate_quality, drawn_choice, off_blend, straight, stroke_stray)
from ..methods.registry import interpolate, per_outline
from ..dashes import start_share
from ..memo import Remembered
from ..paint import blend_paints
from .steering import arc_corrections, bend, extra_turn, spin, unturned, whole_turns_to

__all__ = ["easing_of", "frame_count", "Pair", "Segment", "ShapeAt", "Track", "build_track", "segment_method",
           "evaluate_segment", "pair_paths", "method_paths", "make_breakdowns", "growths_of", "injective_fallback_of",
           "key_windings", "tracks_of", "view_side"]

Array = NDArray[np.float64]


def easing_of(key: Key) -> Easing:
    """The easing of the segment ``key`` starts: its parsed ``easing``, else its ``ease`` parsed."""
    if key.easing is not None:
        return key.easing  # type: ignore[return-value]
    try:
        return parse_easing(key.ease)
    except ValueError as error:
        raise GeometryError(str(error)) from None


def frame_count(duration: float, fps: float) -> int:
    """Frames from time 0 until one at or after ``duration``: ``ceil(duration · fps − 1e-9) + 1``.

    The last frame shows the last key: at its time, or just after it while the key holds (the
    1e-9 keeps a product that rounding put just above a whole number from adding a frame).
    """
    return math.ceil(duration * fps - 1e-9) + 1


@dataclass(frozen=True, slots=True)
class Pair:
    """One contour through a segment: ``k0``, ``k1`` are ``(L, 2)`` after balancing.

    ``source`` is the contour's index in each key (``None``: it has no partner there, or that key is
    hidden, and it grows from, or shrinks to, the point that key holds — or, when ``fades``, keeps its
    shape and fades);
    ``counts`` the two contours' vertex counts as drawn; ``correspondence`` the balancing
    path (``None`` where the drawn order is kept).
    """

    k0: Points
    k1: Points
    closed: bool
    counts: tuple[int, int]
    correspondence: Correspondence | None
    source: tuple[int | None, int | None]
    fades: bool = False
    # the two contours ``(N, 2)``, ``(M, 2)`` as paired where they are not the keys' own: a contour without
    # room was joined into one of them by a slit (:mod:`.bridges`); the correspondence indexes these
    joined: tuple[Points, Points] | None = None

    @property
    def moving(self) -> bool:
        """Whether the contour is in both keys (not growing or shrinking)."""
        return None not in self.source


@dataclass(frozen=True, slots=True)
class Segment:
    """Two consecutive keys in correspondence: their contour pairs, paints and easing.

    The motion runs from ``start + delay`` to ``end`` seconds; ``ease`` is the easing as written,
    ``easing`` the curve; ``links`` the shape hints both keys carry. With a ``stagger``, the pair of
    rank r in :meth:`stagger_order` starts ``r × stagger`` seconds later, still ending on time.
    """

    start: float
    end: float
    ease: str
    pairs: tuple[Pair, ...]
    joints: tuple[tuple[int, int], ...]  # in balanced vertex indices (one-contour shapes only)
    paints: tuple[Paint, Paint]
    shown: tuple[bool, bool]  # False for a hidden key
    ends: tuple[Key, Key] | None = None  # the two keys, whose fill rules and stroke ends are drawn at them
    # per pair and key: whether the pair's balanced contour runs against the key's own contour, so
    # that drawing it reversed gives the key's winding (see :func:`key_windings`)
    flips: tuple[tuple[bool, ...], tuple[bool, ...]] = ((), ())
    switch: float = 0.5  # the eased t from which in-betweens take the second key's fill rule and windings
    easing: Easing = LINEAR
    delay: float = 0.0
    links: tuple[Link, ...] = ()
    stagger: float = 0.0
    spin: float = 0.0  # radians (whole turns) added to the best-fit turn of the moving pairs (maths §5.13)
    # per pair, its hinted vertices: (letter, balanced vertex index); and the arcs, letter -> (x, y) at t = 0.5
    anchors: tuple[tuple[tuple[str, int], ...], ...] = ()
    arcs: tuple[tuple[str, tuple[float, float]], ...] = ()
    view: float = 0.0  # the larger side of the drawing's view: auto's stray reach is 12 % of it (maths §5.16)

    def time_fraction(self, times: Array, rank: int = 0) -> Array:
        """How much of the motion's time has passed at ``times (T,)`` seconds for the pair of stagger rank
        ``rank``: ``(T,)`` in [0, 1]."""
        begin = self.start + self.delay + rank * self.stagger
        span = self.end - begin
        return np.clip((times - begin) / span, 0.0, 1.0)

    def stagger_order(self) -> list[int]:
        """Pair indices in stagger order: the first key's contours in order, then those that appear."""
        present = sorted((p.source[0], k) for k, p in enumerate(self.pairs) if p.source[0] is not None)
        arriving = sorted((p.source[1], k) for k, p in enumerate(self.pairs) if p.source[0] is None)
        return [k for _, k in present] + [k for _, k in arriving]  # type: ignore[misc]

    def local_t(self, times: Array) -> Array:
        """Eased parameter of ``times (T,)`` seconds within this segment: 0 and 1 at the keys, and
        outside [0, 1] between them where the easing overshoots."""
        return self.easing(self.time_fraction(times))

    @property
    def k0(self) -> Points:
        """The balanced first key of a one-contour segment: ``(L, 2)``."""
        return self._only().k0

    @property
    def k1(self) -> Points:
        """The balanced second key of a one-contour segment: ``(L, 2)``."""
        return self._only().k1

    @property
    def counts(self) -> tuple[int, int]:
        return self._only().counts

    @property
    def correspondence(self) -> Correspondence | None:
        return self._only().correspondence

    def _only(self) -> Pair:
        if len(self.pairs) != 1:
            raise GeometryError(f"a segment of {len(self.pairs)} contours has no single pair of keys")
        return self.pairs[0]


@dataclass(frozen=True, slots=True)
class ShapeAt:
    """A shape as drawn at one time: its contours ``(N_i, 2)``, which are closed, its paint.

    While contours fade in or out, ``fade`` is the cross-fade's weight ``w`` in [0, 1] and
    ``sides`` says, per contour, where it belongs: 0 to both keys, -1 only to the first,
    +1 only to the second; the picture is then (1 - w) × the shape without the +1 contours
    plus w × the shape without the -1 ones. A contour growing from (shrinking to) a point is
    stroked with its share of the width (``widths``), so it leaves no dot.
    """

    contours: tuple[Points, ...]
    closed: tuple[bool, ...]
    paint: Paint
    visible: bool = True
    fade: float | None = None
    sides: tuple[int, ...] = ()
    reversed: tuple[bool, ...] = ()  # per contour: drawn in reverse, so its winding is its key's (empty: none)
    key: Key | None = None  # the key whose fill rule and stroke ends are in force (None: the shape's)
    widths: tuple[float, ...] = ()  # per contour, the share of the stroke width it is drawn with (empty: all)
    clips: tuple[tuple[Points, ...], ...] = ()  # clip regions (closed contours, nonzero), intersected
    masks: MaskBlend = ()  # the masks, each key's carried with the element (:mod:`..mask_motion`)
    # per contour, where a dashed stroke's pattern starts: a share of a closed contour's perimeter from its
    # vertex 0, before ``reversed`` (:func:`..dashes.start_share`); of an open one, 0 (its vertex 0) or 1
    # (its last vertex, drawn from there); empty: at vertex 0
    dash_starts: tuple[float, ...] = ()


@dataclass(frozen=True, slots=True)
class Track:
    """A shape's segments, ready to be sampled at any time."""

    name: str
    segments: tuple[Segment, ...]
    still: ShapeAt  # the only key of a static shape (unused when there are segments)

    def segment_index(self, times: Array) -> NDArray[np.intp]:
        """The segment each of ``times (F,)`` seconds falls in: ``(F,)`` (the first before, the last after)."""
        starts = np.array([s.start for s in self.segments])
        return np.clip(np.searchsorted(starts, times, side="right") - 1, 0, len(self.segments) - 1)

    def at(self, times: Array, method: str) -> list[ShapeAt]:
        """The shape at each of ``times (F,)`` seconds under ``method``: one :class:`ShapeAt` each.

        Frames are grouped by segment so each segment's paths are evaluated in one vectorised call.
        """
        times = np.atleast_1d(np.asarray(times, dtype=np.float64))
        if not self.segments:
            return [self.still] * len(times)
        index = self.segment_index(times)
        out: list[ShapeAt] = [self.still] * len(times)
        for s in sorted(set(index.tolist())):  # not np.unique: it loads numpy.ma (10 ms of start-up)
            segment = self.segments[s]
            picked = np.flatnonzero(index == s)
            frames = staggered_paths(segment, times[picked], method) if segment.stagger > 0 else None
            for slot, shape in zip(picked, evaluate_segment(segment, segment.local_t(times[picked]), method, frames)):
                out[slot] = shape
        return out

    def outlines(self, times: Array, method: str) -> list[tuple[Points, ...]]:
        """Only the contours of :meth:`at`: a tuple of ``(N_i, 2)`` arrays per time."""
        return [shape.contours for shape in self.at(times, method)]


def segment_choice(segment: Segment, hold: bool = True) -> AutoChoice | None:
    """What ``auto`` draws for a segment's moving pairs, and why (None where nothing moves): one closed
    outline decides per body; one open stroke takes straight or injective paths where auto would (its
    crossings read as a stroke's), else what auto does with it as an outline; several contours are
    chosen over together (maths §5.16), their area measured where no contour comes or goes beside them; with
    ``hold``, measured again with the contours without a partner (:func:`_with_alone`)."""
    moving = [p for p in segment.pairs if p.moving]
    if not moving:
        return None
    whole = not _alone(segment)  # the moving contours' area is the shape's only where none comes or goes
    if len(moving) == 1:
        pair = moving[0]
        if not pair.closed:
            choice = auto_choice(pair.k0, pair.k1, segment.joints, closed=False, view=segment.view, weigh_area=whole)
            if choice.method in ("linear", "injective"):
                return _held_choice(segment, hold, choice)
        return _held_choice(segment, hold, auto_choice(pair.k0, pair.k1, segment.joints, view=segment.view,
                                                       weigh_area=whole))
    return _held_choice(segment, hold, auto_choice_contours(
        [p.k0 for p in moving if p.closed], [p.k1 for p in moving if p.closed],
        [p.k0 for p in moving if not p.closed], [p.k1 for p in moving if not p.closed], view=segment.view,
        weigh_area=whole))


def _held_choice(segment: Segment, hold: bool, choice: AutoChoice) -> AutoChoice:
    return _with_alone(segment, choice) if hold else choice


def _with_alone(segment: Segment, choice: AutoChoice) -> AutoChoice:
    """``choice`` (made over the moving contours) measured again with the contours without a partner, as
    drawn (maths §5.16): where they tangle with the moving ones, the other way of straight and injective
    paths, measured with them too (placed clear of its own paths), is taken when it tangles at fewer t and
    strays and swells no further; where they still tangle, the injective paths holding them in one
    mesh (:func:`_meshed_alone`) are taken instead when they tangle at fewer t, stray at most
    :data:`.qcurves.STRAY_LIMIT` more, by area and by the open strokes' length (a mesh that holds
    everything may carry a piece far: a tangle for a sweep is no gain) and change the area evenly (no
    step over :data:`EVEN` × the median: a mesh grows a contour by its triangles' stretch, not its area)."""
    return _alone_measures(segment, choice)[0]


def _alone_measures(segment: Segment, choice: AutoChoice) -> tuple[AutoChoice, tuple[int, float] | None]:
    """:func:`_with_alone`'s choice, and how what it draws measured with the contours without a partner (tangled t,
    stray), where they were measured."""
    if segment.joints or choice.method == "jointed" or not _holdable(segment):
        return choice, None
    return _alone_choices.get(_digest(segment, "choice") + repr(choice).encode(),
                              lambda: _alone_measured(segment, choice))


_alone_choices: Remembered[tuple[AutoChoice, tuple[int, float] | None]] = Remembered(256)


def _clean_unjoined(segment: Segment) -> bool:
    """Whether ``auto``, measuring the segment's contours without a partner with the moving ones (:func:`_with_alone`),
    takes another way than over the moving ones alone — their injective mesh, or the other paths — whose
    in-betweens tangle at no t and stray at most :data:`.qcurves.STRAY_LIMIT`."""
    base = segment_choice(segment, hold=False)
    if base is None:
        return False
    choice, found = _alone_measures(segment, base)
    return (choice.holds or choice.method != base.method) and found is not None and found[0] == 0 \
        and found[1] <= STRAY_LIMIT


def _alone_measured(segment: Segment, choice: AutoChoice) -> tuple[AutoChoice, tuple[int, float] | None]:
    pairs = segment.pairs
    moving = [i for i, p in enumerate(pairs) if p.moving]
    k0s, k1s = [pairs[i].k0 for i in moving], [pairs[i].k1 for i in moving]
    shut = [pairs[i].closed for i in moving]
    as_grown = _grown_with(segment, choice)
    first = candidate_quality(*as_grown, view=segment.view)
    swell = balloon(*as_grown, grown=True)
    if first[0]:
        # the choice was made over the moving contours alone: where it tangles with those without a partner, the
        # other ways are measured with them too (each placed clear of its own paths), and the least tangled kept
        # that strays, by area and by the strokes' length, and swells no further
        stroked = stroke_stray(*as_grown, view=segment.view)
        ways, switched = [], False
        for other in ("linear", "injective"):
            if other == choice.method:
                continue
            way = AutoChoice(other, choice.why, (other,))
            grown_way = _grown_with(segment, way)
            found = candidate_quality(*grown_way, view=segment.view)
            ways.append(f"{other} with them tangled at {found[0]}, stray {found[1]:.3f}")
            if found[0] < first[0] and found[1] <= first[1] + STRAY_LIMIT \
                    and stroke_stray(*grown_way, view=segment.view) <= stroked + STRAY_LIMIT \
                    and balloon(*grown_way, grown=True) <= max(swell, BALLOON):
                taken = f"{choice.method} with them tangled at {first[0]} of {len(QUALITY_T)} t, stray {first[1]:.3f}"
                choice = replace(way, why=f"{choice.why}; {taken}; {ways[-1]}: {other} the less tangled")
                as_grown, first, switched = grown_way, found, True
                swell = balloon(*as_grown, grown=True)
                stroked = stroke_stray(*as_grown, view=segment.view)
        if not switched and ways:
            choice = replace(choice, why=f"{choice.why}; {'; '.join(ways)}")
    # the mesh only where they tangle as they grow, or grow and shrink when the area they leave swells the shape
    held = _meshed_alone(segment) if first[0] or swell > BALLOON else []
    grown_words = (f"with the contours without a partner: {choice.method} tangled at {first[0]} of {len(QUALITY_T)} t, "
                   f"stray {first[1]:.3f}" + (f", area {swell:.3f} off the keys' blend" if swell > BALLOON else ""))
    if not held:  # where they tangle as drawn and no mesh holds them, say so
        return (replace(choice, why=f"{choice.why}; {grown_words}; no mesh holds them") if first[0] else choice), first
    from ..methods.injective import injective_contours

    every0 = k0s + [k0 for _, k0, _ in held]
    every1 = k1s + [k1 for _, _, k1 in held]
    closed = shut + [pairs[i].closed for i, _, _ in held]

    held_frames = injective_contours(every0, every1, closed, QUALITY_T, paced=False)  # as auto measures paths
    second = candidate_quality(held_frames, every0, every1, closed, view=segment.view)
    held_swell = balloon(held_frames, every0, every1, closed, grown=True)
    rings = [k for k, c in enumerate(closed) if c]
    uneven = _uneven([held_frames[k] for k in rings], [every0[k] for k in rings], [every1[k] for k in rings])
    # open strokes by their length: a mesh may carry one far where no area shows it
    strokes = stroke_stray(*as_grown, view=segment.view), stroke_stray(held_frames, every0, every1, closed,
                                                                      view=segment.view)
    measures = (f"{grown_words}; injective holding them tangled at {second[0]}, stray {second[1]:.3f}, "
                f"largest area step {uneven:.1f} × the median" + (f", area {held_swell:.3f} off the keys' blend"
                                                                   if swell > BALLOON else ""))
    if strokes != (0.0, 0.0):
        measures += f"; strokes' stray {strokes[0]:.3f} and {strokes[1]:.3f} holding them"
    # fewer tangles, or as few where growing apart swells the shape and holding them does not swell it as much
    better = second[0] < first[0] or (second[0] == first[0] and swell > BALLOON and held_swell < swell - BALLOON)
    if better and second[1] <= first[1] + STRAY_LIMIT and uneven <= EVEN and strokes[1] <= strokes[0] + STRAY_LIMIT:
        return AutoChoice("injective", f"{choice.why}; {measures}", ("injective",), holds=True), second
    return replace(choice, why=f"{choice.why}; {measures}"), first


def _grown_with(segment: Segment, choice: AutoChoice) -> tuple[list[Array], list[Array], list[Array], list[bool]]:
    """The moving contours' paths at :data:`QUALITY_T` under auto's ``choice`` (``(T, L_i, 2)`` each) followed by
    those without a partner grown and shrunk clear of them, as auto draws them without a mesh (and as joins weigh
    them), with their keys (``(L_i, 2)`` each) and whether each is closed."""
    pairs = segment.pairs
    moving = [i for i, p in enumerate(pairs) if p.moving]
    k0s, k1s = [pairs[i].k0 for i in moving], [pairs[i].k1 for i in moving]
    shut = [pairs[i].closed for i in moving]
    own = candidate_paths(choice.method if choice.method in ("linear", "nonlinear", "injective") else "linear",
                          k0s, k1s, shut, QUALITY_T)
    growths = growths_of(segment, "auto", hold=False, choice=choice)
    alone = _alone(segment)
    grown = [scaled(growths[i].point, pairs[i].k1 if growths[i].grows else pairs[i].k0,  # type: ignore[union-attr]
                    growth_scale(growths[i], QUALITY_T)) for i in alone]  # type: ignore[arg-type]
    return (own + grown, k0s + [pairs[i].k0 for i in alone], k1s + [pairs[i].k1 for i in alone],
            shut + [pairs[i].closed for i in alone])


def segment_method(segment: Segment, method: str, hold: bool = True) -> str:
    """The method a segment's moving pairs take for ``method``: ``auto`` chosen over all its contours
    (:func:`segment_choice`) when it has several or one open stroke that auto draws straight or
    injective; a one-outline segment keeps ``auto``, which decides per body."""
    if method != "auto" or not any(p.moving for p in segment.pairs):
        return method
    return _choice_method(segment, segment_choice(segment, hold))


def _choice_method(segment: Segment, choice: AutoChoice | None) -> str:
    """The method ``auto``'s ``choice`` draws the segment's moving pairs by (:func:`segment_method`): ``"auto"``
    where one outline moves (auto decides per body, unless it holds contours without a partner) or one open
    stroke that auto draws neither straight nor injective, else the choice's."""
    moving = [p for p in segment.pairs if p.moving]
    if choice is None:
        return "auto"
    if len(moving) == 1 and moving[0].closed:
        return "injective" if choice.holds else "auto"
    if len(moving) == 1 and choice.method not in ("linear", "injective"):
        return "auto"
    return choice.method


def pair_paths(segment: Segment, t: Array, method: str) -> list[Array]:
    """Every pair's inbetweens at parameters ``t (T,)``: one ``(T, L_i, 2)`` array per pair, steered as
    the segment says (its turn and arcs, :mod:`.steering`); see :func:`method_paths`."""
    t = np.asarray(t, dtype=np.float64)
    frames = _turned(segment, t, method)
    if not segment.arcs:
        return frames
    at = dict(segment.arcs)
    middle = _turned(segment, np.array([0.5]), method)
    for i, pair in enumerate(segment.pairs):
        hinted = segment.anchors[i] if i < len(segment.anchors) else ()
        if not any(letter in at for letter, _ in hinted):
            continue
        anchors = [(v, (np.asarray(at[letter]) - middle[i][0, v]) if letter in at else None) for letter, v in hinted]
        frames[i] = bend(frames[i], t, arc_corrections(pair.k0, pair.closed, anchors))
    return frames


def _turned(segment: Segment, t: Array, method: str) -> list[Array]:
    """Every pair's inbetweens by ``method``, the moving pairs' rigid frame turning by the segment's total turn
    where it adds whole turns (maths §5.13; ``linear`` has no rigid frame and goes straight)."""
    moving = [i for i, p in enumerate(segment.pairs) if p.moving]
    if segment.spin == 0.0 or method == "linear" or not moving:
        return method_paths(segment, t, method)
    k0 = np.concatenate([segment.pairs[i].k0 for i in moving])
    k1 = np.concatenate([segment.pairs[i].k1 for i in moving])
    total = float(best_fit_rotation(k0, k1)) + segment.spin
    c1 = k1.mean(axis=0)
    pairs = list(segment.pairs)
    for i in moving:
        pairs[i] = replace(pairs[i], k1=_frozen(unturned(pairs[i].k1, c1, total)))
    frames = method_paths(replace(segment, pairs=tuple(pairs)), t, method)
    for i, turned in zip(moving, spin([frames[i] for i in moving], k0, k1, t, total)):
        turned[t == 0.0] = segment.pairs[i].k0
        turned[t == 1.0] = segment.pairs[i].k1
        frames[i] = turned
    return frames


def method_paths(segment: Segment, t: Array, method: str, hold: bool = True) -> list[Array]:
    """Every pair's inbetweens at parameters ``t (T,)`` by ``method`` alone: one ``(T, L_i, 2)`` array per pair.

    The moving pairs are interpolated as one point set (one center of mass, one turn), except by
    the methods that work on one closed outline (:func:`.methods.per_outline`), which take each closed contour on its own and place it
    where the whole shape's rigid paths put it; the growing and shrinking pairs are scaled about their
    point, clear of the moving ones (:mod:`.clearance`, :mod:`.appear`), unless an injective mesh holds
    them (:func:`held_in_mesh`; never without ``hold``); the fading ones keep their shape.
    """
    frames = _moving_paths(segment, t, method, hold)
    pending = any(f is None and not p.fades for f, p in zip(frames, segment.pairs))
    growths = growths_of(segment, method, hold) if pending else []
    for i, pair in enumerate(segment.pairs):
        if frames[i] is None and pair.fades:
            frames[i] = interpolate(pair.k0, pair.k1, t, "linear")
        elif frames[i] is None:  # its area grows (shrinks) linearly in t, from its start to its stop
            growth = growths[i]
            assert growth is not None
            frames[i] = scaled(growth.point, pair.k1 if growth.grows else pair.k0, growth_scale(growth, t))
    return frames  # type: ignore[return-value]


def injective_fallback_of(segment: Segment) -> str | None:
    """Why ``injective`` draws a segment's moving contours on rigid paths (no injective morph of its
    keys: they cross, nest differently, wind apart; a contour joined by a slit passes points twice), or None."""
    from ..methods.compatible import COINCIDENT
    from ..methods.injective import injective_fallback

    moving = [p for p in segment.pairs if p.moving]
    if not moving:
        return None
    reason = injective_fallback([p.k0 for p in moving], [p.k1 for p in moving], [p.closed for p in moving])
    if reason == COINCIDENT and any(p.joined is not None and p.closed for p in moving):
        return f"{reason} (contours joined by a slit, whose two sides pass the same points)"
    return reason


def growths_of(segment: Segment, method: str, hold: bool = True, choice: AutoChoice | None = None
               ) -> list[Growth | None]:
    """How each pair without a partner comes or goes under ``method`` (None for the others, and for those
    its injective mesh holds, :func:`held_in_mesh`): placed clear of the other pairs
    (:func:`.clearance.place`) when there are others and no stagger, else about its anchor over the whole
    segment; in an element drawn by its stroke alone (:func:`_filled`), only closed contours keep clear
    of the closed ones. Without ``hold``, as if the mesh held none. With ``choice``, clear of the paths
    ``auto`` draws for it (a choice measured before it is taken); else, under ``auto``, of those it takes."""
    pairs = segment.pairs
    held = held_in_mesh(segment, method) if hold else frozenset()
    alone = [i for i in _alone(segment) if i not in held]
    out: list[Growth | None] = [None] * len(pairs)
    if not alone:
        return out
    for i in alone:
        grows = pairs[i].source[0] is None
        out[i] = Growth(np.asarray((pairs[i].k0 if grows else pairs[i].k1)[0], dtype=np.float64), grows)
    filled = _filled(segment)
    if not filled:  # lines crossing lines are no tangle: only closed outlines keep clear of one another
        alone = [i for i in alone if pairs[i].closed]
    moving = [i for i, p in enumerate(pairs) if p.moving and (filled or p.closed)]
    if len(alone) + len(moving) < 2 or segment.stagger > 0:
        return out

    def search() -> list[Growth]:
        frames = _moving_paths(segment, GRID, method, hold, choice)
        # the moving ones, and those a mesh holds
        around = [i for i, f in enumerate(frames) if f is not None and (filled or pairs[i].closed)]
        shapes = [pairs[i].k1 if pairs[i].source[0] is None else pairs[i].k0 for i in alone]
        return place(shapes, [pairs[i].closed for i in alone], [pairs[i].source[0] is None for i in alone],
                     [out[i].point for i in alone],  # type: ignore[union-attr]
                     [frames[i] for i in around], [pairs[i].closed for i in around])

    drawn = choice if choice is not None else segment_choice(segment, hold) if method == "auto" else None
    taken = "" if drawn is None else f"{drawn.method}{drawn.holds}"  # what auto draws the moving pairs by
    for i, growth in zip(alone, cached(_digest(segment, f"{method}{sorted(held)}{filled}{taken}"), search)):
        out[i] = growth
    return out


def _filled(segment: Segment) -> bool:
    """Whether either key of the segment fills its contours (a colour, gradient or pattern): else only its
    stroke is drawn, and an open stroke crossing another contour is no tangle."""
    return any((p.fill is not None and p.fill[3] > 0) or p.gradient is not None or p.pattern is not None
               for p in segment.paints)


def _digest(segment: Segment, method: str) -> bytes:
    """What a segment's placement of contours without a partner depends on, as a short digest: its
    pairs (keys, closed, sources), joints and the method (the segment itself is made anew for every
    render job, library call and test)."""
    h = hashlib.blake2b(method.encode(), digest_size=20)
    for pair in segment.pairs:
        h.update(np.ascontiguousarray(pair.k0).tobytes())
        h.update(np.ascontiguousarray(pair.k1).tobytes())
        h.update(repr((pair.closed, pair.source, pair.fades)).encode())
    h.update(repr((segment.joints, segment.view)).encode())
    return h.digest()


def _moving_paths(segment: Segment, t: Array, method: str, hold: bool = True, choice: AutoChoice | None = None
                  ) -> list[Array | None]:
    """The moving pairs' inbetweens at ``t (T,)`` (``(T, L_i, 2)`` each), and those of the pairs without a
    partner that an injective mesh holds (:func:`held_in_mesh`; none without ``hold``); None for the others.
    ``choice``: under ``auto``, draw that choice (one measured before it is taken, holding nothing)."""
    pairs = segment.pairs
    frames: list[Array | None] = [None] * len(pairs)
    moving = [i for i, p in enumerate(pairs) if p.moving]
    if not moving:
        return frames
    k0 = np.concatenate([pairs[i].k0 for i in moving])
    k1 = np.concatenate([pairs[i].k1 for i in moving])
    cuts = np.cumsum([len(pairs[i].k0) for i in moving])[:-1]
    single = len(moving) == 1 and pairs[moving[0]].closed
    chosen = segment_method(segment, method, hold) if choice is None else _choice_method(segment, choice)
    if per_outline(method) and not single:
        # these methods need one closed outline: each contour takes them on its own (open ones the
        # rigid paths), and its centre follows the rigid paths of the whole shape
        placed = np.split(interpolate(k0, k1, t, "rigid"), cuts, axis=1)
        for i, where in zip(moving, placed):
            pair = pairs[i]
            own = interpolate(pair.k0, pair.k1, t, method if pair.closed and len(pair.k0) >= 3 else "rigid")
            frames[i] = own - own.mean(axis=1, keepdims=True) + where.mean(axis=1, keepdims=True)
    elif chosen == "injective" and (not single or (hold and held_in_mesh(segment, method))):
        # one mesh for every moving contour, so holes stay inside their outlines, and for those
        # without a partner where they have room in it
        from ..methods.injective import injective_contours

        holding = held_in_mesh(segment, method) if hold else frozenset()
        held = [h for h in _meshed_alone(segment) if h[0] in holding]
        found = injective_contours([pairs[i].k0 for i in moving] + [k0 for _, k0, _ in held],
                                   [pairs[i].k1 for i in moving] + [k1 for _, _, k1 in held],
                                   [pairs[i].closed for i in moving] + [pairs[i].closed for i, _, _ in held], t)
        for i, part in zip(moving, found):
            frames[i] = part
        for (i, k0, k1), part in zip(held, found[len(moving):]):
            grows = pairs[i].source[0] is None
            middle = (k0 if grows else k1).mean(axis=0)
            part[t <= 0.0 if grows else t >= 1.0] = middle  # a point at the key that lacks it
            frames[i] = part
    elif method == "auto" and chosen == "linear" and not single:
        # auto's straight paths: each closed contour's copies spread along its edges first
        for i in moving:
            pair = pairs[i]
            path = straight(pair.k0, pair.k1, t) if pair.closed else interpolate(pair.k0, pair.k1, t, "linear")
            path[t == 0.0], path[t == 1.0] = pair.k0, pair.k1
            frames[i] = path
    elif chosen == "auto" and single and not segment.joints:
        # one outline: auto's choice for it, measured within the drawing's view (not its own size)
        choice = choice if choice is not None else segment_choice(segment, hold)
        assert choice is not None
        path = drawn_choice(choice, k0, k1, t)
        path[t == 0.0], path[t == 1.0] = k0, k1
        frames[moving[0]] = path
    else:
        together = interpolate(k0, k1, t, chosen, segment.joints)
        for i, part in zip(moving, np.split(together, cuts, axis=1)):
            frames[i] = part
    return frames


def _alone(segment: Segment) -> list[int]:
    """The pairs that grow or shrink (not fading)."""
    return [i for i, p in enumerate(segment.pairs) if not p.moving and not p.fades]


def held_in_mesh(segment: Segment, method: str) -> frozenset[int]:
    """The growing and shrinking pairs that take ``method``'s paths with the moving ones: under injective
    paths, those the mesh holds (:func:`_meshed_alone`); else none. ``auto`` holds them where it chose
    injective paths for them (:func:`_with_alone`)."""
    if not _alone(segment) or segment_method(segment, method) != "injective":
        return frozenset()
    if method == "auto" and not getattr(segment_choice(segment), "holds", False):
        return frozenset()
    return frozenset(i for i, _, _ in _meshed_alone(segment))


HOLD_MAX = 64
"""Most pairs without a partner a mesh holds in one segment (the shipped icons' segments have at most 36; held, at
most 10): past it they grow and shrink clear of the mesh, as the stand-ins' search and the mesh grow faster than
the pairs."""


def _holdable(segment: Segment) -> bool:
    """Whether a mesh could hold the segment's pairs without a partner (:func:`_meshed_alone`): it has some, at
    most :data:`HOLD_MAX`, and moving pairs, on one timing and turn."""
    alone = _alone(segment)
    return bool(alone) and len(alone) <= HOLD_MAX and segment.stagger == 0 and segment.spin == 0.0 \
        and any(p.moving for p in segment.pairs)


def _meshed_alone(segment: Segment) -> list[tuple[int, Array, Array]]:
    """The growing and shrinking pairs the injective mesh holds, as (pair index, key 0, key 1) with
    their stand-ins (:mod:`.methods.stand_ins`) in the key that lacks them: all of them where none meets
    another contour in its own key, each has room and the mesh with them exists, else none (they grow
    and shrink clear of the mesh, :func:`growths_of`, where a contour touching another in its key can
    be carried out of it); none in a staggered or turned segment (each pair on its own timing, or the
    moving ones turned apart), nor where nothing moves (a whole element comes from its centre)."""
    if not _holdable(segment):
        return []
    return _held.get(_digest(segment, "held"), lambda: _stand_ins_held(segment))


_held: Remembered[list[tuple[int, Array, Array]]] = Remembered(64)


def _stand_ins_held(segment: Segment) -> list[tuple[int, Array, Array]]:
    from ..methods.injective import carried_points, injective_fallback
    from ..methods.stand_ins import stand_ins

    pairs = segment.pairs
    moving = [i for i, p in enumerate(pairs) if p.moving]
    k0s, k1s, shut = [pairs[i].k0 for i in moving], [pairs[i].k1 for i in moving], [pairs[i].closed for i in moving]
    alone = _alone(segment)
    for side, keys in ((0, k0s), (1, k1s)):  # a mesh holds contours apart: none may meet another in its key
        here = [i for i in alone if pairs[i].source[side] is not None]
        drawn_here = [pairs[i].k0 if side == 0 else pairs[i].k1 for i in here]
        every = keys + drawn_here, shut + [pairs[i].closed for i in here]
        met = proper_crossings(*every, touching=True) + proper_crossings(*every)
        if any(c >= len(keys) or d >= len(keys) for c, d in met):
            return []
    grows = [pairs[i].source[0] is None for i in alone]
    drawn = [pairs[i].k1 if g else pairs[i].k0 for i, g in zip(alone, grows)]
    found = stand_ins(list(zip(k0s, k1s)), shut, drawn, [pairs[i].closed for i in alone], grows,
                      lambda points, key: carried_points(k0s, k1s, shut, points, key, build=True))
    if found is None:
        return []
    held = [(i, s if g else d, d if g else s) for i, g, d, s in zip(alone, grows, drawn, found)]
    every0, every1 = k0s + [k0 for _, k0, _ in held], k1s + [k1 for _, _, k1 in held]
    if injective_fallback(every0, every1, shut + [pairs[i].closed for i, _, _ in held]):
        return []
    return held


def staggered_paths(segment: Segment, times: Array, method: str) -> list[Array]:
    """Every pair's inbetweens at ``times (T,)`` seconds, each on its own staggered timing: one
    ``(T, L_i, 2)`` array per pair. A pair's positions come from the whole shape's paths (one
    centre, one turn) at its own eased parameter."""
    out: list[Array] = [np.empty(0)] * len(segment.pairs)
    for rank, k in enumerate(segment.stagger_order()):
        out[k] = pair_paths(segment, segment.easing(segment.time_fraction(times, rank)), method)[k]
    return out


def evaluate_segment(segment: Segment, t: Array, method: str, frames: list[Array] | None = None) -> list[ShapeAt]:
    """The segment at eased parameters ``t (T,)``: one :class:`ShapeAt` per t (``frames``: the pairs'
    inbetweens already computed, e.g. staggered; the paint follows ``t``).

    At a key only that key's contours are drawn (one that grows from or shrinks to a point there is
    kept, as that point with no stroke width), with the key's own fill rule and windings; in-betweens
    take the first key's until ``segment.switch``, the second's from it. A growing (shrinking)
    contour's stroke width scales with it (:func:`.appear.width_share`): its share of the width, or,
    for a whole element coming from (going to) a hidden key, its paint's width.
    """
    pairs = segment.pairs
    frames = pair_paths(segment, t, method) if frames is None else frames
    closed = tuple(p.closed for p in pairs)
    t = np.clip(t, 0.0, 1.0)  # paint, fades and visibility do not overshoot
    paints = blend_paints(*segment.paints, t)
    fading = any(p.fades for p in pairs)
    sides = tuple((-1 if p.source[1] is None else 1) if p.fades else 0 for p in pairs) if fading else ()
    growing = [i for i, p in enumerate(pairs) if not p.moving and not p.fades]
    held = held_in_mesh(segment, method) if growing else frozenset()
    growths = growths_of(segment, method) if set(growing) - held else [None] * len(pairs)
    whole = bool(growing) and not all(segment.shown)  # an element growing from (shrinking to) a hidden key
    p0, p1 = segment.paints
    c0, c1 = (segment.ends[0].clips, segment.ends[1].clips) if segment.ends is not None else ((), ())
    m0, m1 = (segment.ends[0].masks, segment.ends[1].masks) if segment.ends is not None else ((), ())
    boxes = None
    strokes = p0.stroke_gradient is not None or p1.stroke_gradient is not None
    patterns = any(p is not None for p in (p0.pattern, p1.pattern, p0.stroke_pattern, p1.stroke_pattern))
    if (p0.gradient is not None or p1.gradient is not None or strokes or patterns or c0 or c1 or m0 or m1) and pairs:
        boxes = box_of([p.k0 for p in pairs]), box_of([p.k1 for p in pairs])
    out = []
    for k, (x, paint) in enumerate(zip(t.tolist(), paints)):
        visible = segment.shown[0] if x == 0.0 else segment.shown[1] if x == 1.0 else True
        contours = tuple(f[k] for f in frames)  # type: ignore[index]
        clips: tuple[tuple[Points, ...], ...] = ()
        masks: MaskBlend = ()
        if x in (0.0, 1.0):
            clips = tuple(tuple(c.points for c in region) for region in (c0 if x == 0.0 else c1))
            masks = masks_at_key(m0 if x == 0.0 else m1)
        elif boxes is not None:  # gradient, clips and masks move with the element (an overshoot too)
            box = box_of(list(contours))
            if p0.gradient is not None or p1.gradient is not None:
                paint = replace(paint, gradient=blend_gradient(p0, p1, *boxes, box, x))
            if strokes:
                paint = replace(paint, stroke_gradient=blend_stroke_gradient(p0, p1, *boxes, box, x))
            if patterns:
                paint = replace(paint, pattern=carry_pattern(p0.pattern, p1.pattern, *boxes, box, x),
                                stroke_pattern=carry_pattern(p0.stroke_pattern, p1.stroke_pattern, *boxes, box, x))
            clips = clips_at(c0, c1, *boxes, box, x)
            if m0 or m1:
                now = np.concatenate(contours)
                masks = masks_at(m0, m1, carried(np.concatenate([p.k0 for p in pairs]), now),
                                 carried(np.concatenate([p.k1 for p in pairs]), now), x)
        phase = 0 if x < segment.switch else 1
        flips = segment.flips[phase] or (False,) * len(pairs)
        drawn_as = segment.ends[phase] if segment.ends is not None else None
        if fading and x in (0.0, 1.0):  # a key of a cross-fade: only its own contours
            end = 0 if x == 0.0 else 1
            own = [i for i, p in enumerate(pairs) if p.source[end] is not None]
            out.append(ShapeAt(tuple(contours[i] for i in own), tuple(closed[i] for i in own), paint,
                               visible and paint.visible, reversed=tuple(flips[i] for i in own), key=drawn_as,
                               clips=clips, masks=masks))
            continue
        # every pair is kept (a constant count, for players that interpolate vertices): at a key, one that
        # grows from or shrinks to a point there is that point, stroked with no width, so nothing of it shows
        widths: tuple[float, ...] = ()
        if whole:
            paint = replace(paint, stroke_width=paint.stroke_width * width_share(x, segment.shown[1]))
        elif growing:
            share = [1.0] * len(pairs)
            for i in growing:
                if i in held:  # its size in the mesh against its size as drawn
                    share[i] = _size_share(contours[i], pairs[i], closed[i])
                else:
                    share[i] = float(growth_scale(growths[i], np.array([x]))[0])  # type: ignore[arg-type]
            widths = tuple(share)
        starts = _dash_starts(segment, contours, x) if paint.dash is not None else ()
        out.append(ShapeAt(contours, closed, paint, visible and paint.visible, x if fading else None, sides,
                           flips, drawn_as, widths, clips, masks, starts))
    return out


def _size_share(contour: Points, pair: Pair, closed: bool) -> float:
    """How large ``contour (L, 2)`` of a growing or shrinking ``pair`` is against its drawn key: the square
    root of their areas' ratio (closed), their lengths' (open), within [0, 1]."""
    drawn = np.asarray(pair.k1 if pair.source[0] is None else pair.k0)
    if closed and len(drawn) >= 3:
        whole, now = abs(float(signed_area(drawn))), abs(float(signed_area(np.asarray(contour))))
        ratio = math.sqrt(now / whole) if whole > 0 else 0.0
    else:
        whole, now = float(np.hypot(*np.diff(drawn, axis=0).T).sum()), float(np.hypot(*np.diff(contour, axis=0).T).sum())
        ratio = now / whole if whole > 0 else 0.0
    return min(max(ratio, 0.0), 1.0)


def _dash_starts(segment: Segment, contours: tuple[Points, ...], t: float) -> tuple[float, ...]:
    """Per contour, where its dash pattern starts at ``t`` (:func:`..dashes.start_share`): each closed contour
    in both keys from its keys' first vertices; an open one from the end that is its key's first vertex (the
    first key's until halfway, then the second's); others at vertex 0."""
    if segment.ends is None:
        return ()
    out = []
    for pair, now in zip(segment.pairs, contours):
        i, j = pair.source
        if i is None or j is None or len(now) != len(pair.k0):
            out.append(0.0)
            continue
        first0, first1 = segment.ends[0].contours[i].points[0], segment.ends[1].contours[j].points[0]
        if pair.closed:
            out.append(start_share(pair.k0, pair.k1, first0, first1, now, t))
        else:
            k, first = (pair.k0, first0) if t < 0.5 else (pair.k1, first1)
            out.append(1.0 if np.hypot(*(k[-1] - first)) < np.hypot(*(k[0] - first)) else 0.0)
    return tuple(out)


def key_windings(pairs: Sequence[Pair], before: Sequence[Contour], after: Sequence[Contour],
                 rules: tuple[str, str] = ("nonzero", "nonzero")) -> tuple[tuple[bool, ...], tuple[bool, ...]]:
    """Per pair, whether its balanced contour must be drawn reversed to wind as in the first key, and
    as in the second: the correspondence may walk a partner backwards, and under ``nonzero`` a hole
    is a hole only while it winds against its outer.

    A contour that only one key has takes the other key's windings through the largest moving pair:
    if that pair's two keys wind oppositely, so is it drawn in the key it is not part of. Where its own
    key is ``evenodd`` and the other ``nonzero`` (``rules``: the two keys' fill rules), its winding said
    nothing: under the other key's rule it winds as that key's largest contour at an even depth of nesting
    in its own key and against it at an odd one, so a hole stays a hole.
    """
    def sign(points: Array) -> float:
        return float(np.sign(signed_area(points))) if len(points) >= 3 else 0.0

    first, second, biggest, outer = [], [], -1.0, (0.0, 0.0)
    for pair in pairs:
        i, j = pair.source
        flip0 = i is not None and sign(pair.k0) * sign(before[i].points) < 0
        flip1 = j is not None and sign(pair.k1) * sign(after[j].points) < 0
        first.append(flip0)
        second.append(flip1)
        if pair.moving and pair.closed and len(pair.k0) >= 3:
            size = abs(signed_area(pair.k0)) + abs(signed_area(pair.k1))
            if size > biggest:
                biggest, outer = size, (sign(before[i].points), sign(after[j].points))  # type: ignore[index]
    relation = outer[0] * outer[1] < 0  # the largest moving pair's two keys wind oppositely
    depths = [_depth_signs(keyed) if rules[end] == "evenodd" and rules[1 - end] == "nonzero" else None
              for end, keyed in enumerate((before, after))]
    for n, pair in enumerate(pairs):
        if pair.source[0] is None:
            first[n] = relation
            if depths[1] is not None and pair.closed and outer[0]:
                first[n] = sign(pair.k1) != outer[0] * depths[1][pair.source[1]]  # type: ignore[index]
        elif pair.source[1] is None:
            second[n] = relation
            if depths[0] is not None and pair.closed and outer[1]:
                second[n] = sign(pair.k0) != outer[1] * depths[0][pair.source[0]]
    return tuple(first), tuple(second)


def _depth_signs(contours: Sequence[Contour]) -> list[float]:
    """Per contour of one key, 1.0 at an even depth of nesting (an outer, an open stroke), -1.0 at an odd one."""
    return [-1.0 if role == "hole" else 1.0 for role in roles([c.points for c in contours], [c.closed for c in contours])]


def _still(key: Key) -> ShapeAt:
    return ShapeAt(tuple(c.points for c in key.contours), tuple(c.closed for c in key.contours), key.paint,
                   not key.hidden and key.paint.visible, key=key,
                   clips=tuple(tuple(c.points for c in region) for region in key.clips),
                   masks=masks_at_key(key.masks))


def tracks_of(scene: Scene, matching: Matching | None = None) -> tuple[Track, ...]:
    """Every shape's track, in paint order, under the scene's matching (or ``matching``) and rules.

    A shape's breakdowns are made again here under the matching and balance in force (a command may
    put its own over the scene's), by the shape's own method: they are in-betweens of that correspondence."""
    matching = scene.matching if matching is None else matching
    rules = tuple((scene.unmatched, scene.balance_of(shape), scene.method_of(shape)) for shape in scene.shapes)
    for shapes, known, tracks in _BUILT:
        if shapes is scene.shapes and known == (matching, rules):
            return tracks
    tracks = _build_tracks(scene, matching)
    _BUILT.insert(0, (scene.shapes, (matching, rules), tracks))
    del _BUILT[_TRACKS_KEPT:]
    return tracks


_TRACKS_KEPT = 4
"""Scenes whose tracks :func:`tracks_of` keeps (a report asks for the same scene's a dozen times: its
videos, sheet, pictures and table), by their shapes (frozen: the same tuple is the same drawing),
matching and rules."""
_BUILT: list[tuple[tuple[Shape, ...], tuple[object, ...], tuple[Track, ...]]] = []


def _build_tracks(scene: Scene, matching: Matching) -> tuple[Track, ...]:
    """:func:`tracks_of`, worked out."""
    tracks = []
    view = view_side(scene)
    for shape in scene.shapes:
        rules = {"unmatched": scene.unmatched, "balance": scene.balance_of(shape), "view": view}
        if any(key.breakdown is not None for key in shape.keys):
            unmade = replace(shape, keys=tuple(replace(key, contours=()) if key.breakdown is not None else key
                                               for key in shape.keys))
            shape = make_breakdowns(unmade, matching, scene.method_of(shape), **rules)
        tracks.append(build_track(shape, matching, method=scene.method_of(shape), **rules))
    return tuple(tracks)


def view_side(scene: Scene) -> float:
    """The larger side of ``scene``'s view, or of the box of all its keys where it sets none: what ``auto``'s
    stray reach is a share of (maths §5.16); 0 for a scene without points."""
    if scene.view is not None:
        x0, y0, x1, y1 = scene.view
        return float(max(x1 - x0, y1 - y0))
    points = [c.points for shape in scene.shapes for key in shape.keys for c in key.contours if len(c.points)]
    return float(np.ptp(np.concatenate(points), axis=0).max()) if points else 0.0


def build_track(shape: Shape, matching: Matching, *, unmatched: str = "grow", balance: str = "copies",
                method: str | None = None, view: float = 0.0) -> Track:
    """Pair and balance every consecutive pair of ``shape``'s keys; carry its joints through.

    ``unmatched`` is the rule for contours without a partner (``shape.unmatched`` overrides it);
    ``balance`` places the copies balancing makes: ``"copies"`` stacks them on their vertex (the
    thesis), ``"spread"`` spreads them along its edges (maths §5.6). Breakdown keys (made by
    :func:`make_breakdowns`) split the segment of the keys around them into halves that share its
    pairs, correspondence and hints (maths §5.15); the halves share its total turn as the breakdowns
    share its way; the first key's arcs are in the breakdowns (made with them), not bent in again.
    Given the ``method`` it is drawn with, a contour without a partner that has no room to grow over
    the whole segment (:func:`growths_of`) is joined to a neighbour instead (:mod:`.bridges`), unless
    ``method`` is injective and its mesh holds it (:func:`held_in_mesh`). ``view``: the larger side of the
    drawing's view (:func:`view_side`), which ``auto`` measures stray within.
    """
    keys = shape.keys
    if shape.equal_counts is not None and shape.equal_counts != matching.equal_counts:
        matching = replace(matching, equal_counts=shape.equal_counts)
    rule = shape.unmatched or unmatched
    joints = tuple(shape.joints)  # indices into the current key's vertices
    segments: list[Segment] = []
    k = 0
    while k < len(keys) - 1:
        end = next(e for e in range(k + 1, len(keys)) if keys[e].breakdown is None or e == len(keys) - 1)
        first, last = keys[k], keys[end]
        links = tuple(segment_links(first.hints, last.hints))
        pairs = _pairs(first, last, shape.fill_rule, matching, rule, balance, links, (shape.cap, shape.join))
        crowded = None
        if method is not None and not joints and _joinable(first, last, rule, links) \
                and not easing_of(first).overshoots:  # a slit would turn inside out
            crowded = _crowded(pairs, first, last, method, shape.stagger, view)
        if crowded:
            # joined where that tangles no more than growing late, the area changes no less evenly and
            # balloons no more (:func:`_best_join`)
            plain = _join_measures(pairs, first, last, method, shape.stagger, view)
            # injective paths that hold them in their mesh need no slit (which has no mesh)
            probe = _probe(pairs, first, last, shape.stagger, view)
            held = method == "injective" and bool(held_in_mesh(probe, method))

            def joining(part: frozenset[tuple[int, int]], toward: tuple[float, float] | None) -> tuple[Pair, ...]:
                return _pairs(first, last, shape.fill_rule, matching, rule, balance, links, (shape.cap, shape.join),
                              part, toward)

            def measures(joined: tuple[Pair, ...], way: str) -> JoinMeasures:
                return _join_measures(joined, first, last, way, shape.stagger, view)

            role = _roles_of(first, last)
            holes = frozenset(c for c, kind in role.items() if kind == "hole")
            best = None if held else _best_join(_join_choices(crowded, role), plain, method, joining, measures, holes)
            # auto keeps them unjoined where, measured with them, it draws them without a tangle or a stray (its
            # mesh holding them, or the other paths) and no join is as clean (a mesh that holds everything may
            # carry shapes far: elsewhere joins are weighed against growing clear of the moving contours, as if
            # none were held)
            if (best is None or best[0][0] > 0) and method == "auto" and _clean_unjoined(probe):
                best = None
            if best is not None:
                pairs = best[1]
        anchors = _anchors(pairs, links)
        balanced_joints: tuple[tuple[int, int], ...] = ()
        if joints and len(pairs) == 1:
            found = pairs[0].correspondence
            if found is None:
                balanced_joints = carried = joints
            else:
                first_of = _first_occurrence(found.pairs[:, 0], pairs[0].counts[0])
                balanced_joints = tuple((int(first_of[i]), int(first_of[j])) for i, j in joints)
                carried = tuple((int(found.pairs[p, 1]), int(found.pairs[q, 1])) for p, q in balanced_joints)
            joints = carried
        windings = key_windings(pairs, first.contours, last.contours,
                                (first.fill_rule or shape.fill_rule, last.fill_rule or shape.fill_rule))
        moving = [p for p in pairs if p.moving]
        m0 = np.concatenate([p.k0 for p in moving]) if moving else np.zeros((0, 2))
        m1 = np.concatenate([p.k1 for p in moving]) if moving else np.zeros((0, 2))
        delta = extra_turn(m0, m1, first.turn, first.turns)
        remaining = (float(best_fit_rotation(m0, m1)) if moving else 0.0) + delta
        for q in range(k, end):
            before, after = keys[q], keys[q + 1]
            part = pairs
            if end > k + 1:  # a half: the breakdowns' contours in place of the run's keys
                part = _half(pairs, before if q > k else None, after if q + 1 < end else None)
                h0 = np.concatenate([p.k0 for p in part if p.moving]) if moving else np.zeros((0, 2))
                h1 = np.concatenate([p.k1 for p in part if p.moving]) if moving else np.zeros((0, 2))
                target = remaining * (after.breakdown if q + 1 < end else 1.0)  # type: ignore[operator]
                remaining -= target
                if q > k and (before.turn is not None or before.turns):
                    delta = extra_turn(h0, h1, before.turn, before.turns)
                else:
                    delta = whole_turns_to(target, h0, h1)
            # a breakdown is drawn with the windings of the run's key it is nearer
            flips = (_windings_at(before, windings[0], windings), _windings_at(after, windings[1], windings))
            segments.append(Segment(before.time, after.time, before.ease, part, balanced_joints,
                                    _paints(before, after, rule), (not before.hidden, not after.hidden),
                                    (before, after), flips, easing=easing_of(before), delay=before.delay,
                                    links=links if end == k + 1 else (), stagger=shape.stagger, spin=delta,
                                    anchors=anchors, arcs=() if q == k < end - 1 else before.arcs, view=view))
        k = end
    return Track(shape.name, tuple(segments), _still(keys[0]))


EVEN = 3.0
"""A segment's area changes evenly where no step is over this many times the median (as pops are told)."""
SLIT_WAYS = tuple((float(np.cos(a)), float(np.sin(a))) for a in np.linspace(0.0, 2.0 * np.pi, 8, endpoint=False))
"""The directions a slit is tried leaving the contour it joins, every 45°, where growing late balloons
(:data:`BALLOON`) and the shortest slits are not clean (:func:`_best_join`)."""
SCREENED = 4
"""How many of the slits leaving each way, ranked under straight paths, are measured under the method."""
JoinMeasures = tuple[int, float, float]
"""How in-betweens fare at :data:`JOIN_CHECKS` (:func:`_join_measures`): tangled checks, the largest area step
over the median, how far the area balloons."""
JOIN_CHECKS = np.concatenate([[1e-6], np.linspace(0.0, 1.0, 13)[1:-1], [1.0 - 1e-6]])
"""The parameters at which a segment's in-betweens with contours joined (:mod:`.bridges`) are measured
against those without: the keys as the first and last are approached, and 11 between. Which contours are
apart is read from the keys themselves, where a contour that is one point is drawn nowhere (as ``stats``
reads them): a speck shrinking inside an outline near the last key would be nested there and never counted."""


def _probe(pairs: tuple[Pair, ...], first: Key, last: Key, stagger: float, view: float = 0.0) -> Segment:
    """A segment of ``pairs`` from ``first`` to ``last`` for looking at how its contours move (``view``: the
    larger side of the drawing's view)."""
    return Segment(first.time, last.time, first.ease, pairs, (), (first.paint, last.paint), (True, True),
                   stagger=stagger, view=view)


def _join_measures(pairs: tuple[Pair, ...], first: Key, last: Key, method: str, stagger: float, view: float = 0.0
                   ) -> JoinMeasures:
    """How the in-betweens of ``pairs`` under ``method``, growing and shrinking clear of the moving ones (as
    if no mesh held them: joins are weighed against that, and holding is for the pairs kept), fare at
    :data:`JOIN_CHECKS`: at how many of the
    inner ones their contours tangle (:func:`.tangles.contact_times`, crossings and stroke crossings,
    among the contours that are more than a point then), the largest change of their closed
    contours' signed area from one check to the next over the median change (the pops rule), and how far
    the area they fill (holes taken away, :func:`_hole_signs`) leaves the straight blend of the first and last checks', over
    the larger of those (:data:`BALLOON`)."""
    frames = method_paths(_probe(pairs, first, last, stagger, view), JOIN_CHECKS, method, hold=False)
    inner = slice(1, len(JOIN_CHECKS) - 1)
    there = np.array([[bool(np.any(f[k] != f[k][:1])) for f in frames] for k in range(len(JOIN_CHECKS))])[inner]
    tangled: set[float] = set()
    for pattern in np.unique(there, axis=0):
        when = np.flatnonzero((there == pattern).all(axis=1))
        which = np.flatnonzero(pattern)
        crossed, stroked = contact_times([frames[i][inner][when] for i in which], [pairs[i].closed for i in which],
                                         JOIN_CHECKS[inner][when], [pairs[i].k0 for i in which],
                                         [pairs[i].k1 for i in which])
        tangled |= set(crossed) | set(stroked)
    closed = [i for i, p in enumerate(pairs) if p.closed]
    signed = [_signed_areas(frames[i]) for i in closed]  # (T,) each
    area = sum(signed, np.zeros(len(JOIN_CHECKS)))
    steps = np.abs(np.diff(area))
    middle = float(np.median(steps))
    uneven = float(steps.max()) / middle if middle > 0 else (0.0 if steps.max() == 0 else np.inf)
    # the area filled: each contour counted whatever way it winds, holes taken away
    filled = sum((sign * np.abs(a) for sign, a in zip(_hole_signs([pairs[i] for i in closed]), signed)),
                 np.zeros(len(JOIN_CHECKS)))
    return len(tangled), uneven, off_blend(filled, JOIN_CHECKS, float(filled[0]), float(filled[-1]))


def _hole_signs(pairs: Sequence[Pair]) -> list[float]:
    """Per closed pair, -1 where it is a hole (by its nesting in the key where it is drawn: the last for one
    growing from a point), else 1."""
    kinds = [roles([p.k0 for p in pairs], [True] * len(pairs)), roles([p.k1 for p in pairs], [True] * len(pairs))]
    return [-1.0 if kinds[p.source[0] is None][n] == "hole" else 1.0 for n, p in enumerate(pairs)]


def _best_join(choices: Sequence[frozenset[tuple[int, int]]], plain: JoinMeasures, method: str,
               joining: Callable[[frozenset[tuple[int, int]], tuple[float, float] | None], tuple[Pair, ...]],
               measures: Callable[[tuple[Pair, ...], str], JoinMeasures], holes: frozenset[tuple[int, int]]
               ) -> tuple[JoinMeasures, tuple[Pair, ...]] | None:
    """The join to keep, with its measures, of the contours of each of ``choices`` in turn (all, the pieces,
    the holes: :func:`_join_choices`), or None: one that under ``method`` tangles at no more checks than
    growing late (``plain``, :func:`_join_measures`), changes the area no less evenly and balloons no more,
    ranked by :func:`_join_rank`; the first clean one (no tangle, even, not ballooned) ends the search. Each
    choice is joined by its shortest slits; where those are not clean, growing late balloons and the choice
    holds one of ``holes`` (what balloons), by slits leaving the contours each way of :data:`SLIT_WAYS` too,
    ranked by the moving contours alone under straight paths (the way a slit leaves shows in them, at a
    fraction of the cost) and the best :data:`SCREENED` measured in full under ``method``.
    ``joining(part, toward)`` makes the pairs, ``measures(pairs, method)`` measures them."""
    best: tuple[JoinMeasures, tuple[Pair, ...]] | None = None

    def weigh(found: JoinMeasures, joined: tuple[Pair, ...]) -> bool:
        nonlocal best
        if found[0] <= plain[0] and found[1] <= max(plain[1], EVEN) and found[2] <= max(plain[2], BALLOON) \
                and (best is None or _join_rank(found) < _join_rank(best[0])):
            best = found, joined
        return found[0] == 0 and found[1] <= EVEN and found[2] <= BALLOON and best is not None and best[1] is joined

    for part in choices:
        joined = joining(part, None)
        if weigh(measures(joined, method), joined):
            break
        if plain[2] <= BALLOON or not part & holes:
            continue
        ways = [found for found in (joining(part, toward) for toward in SLIT_WAYS) if any(p.joined for p in found)]
        ranked = sorted(ways, key=lambda found: _join_rank(measures(tuple(p for p in found if p.moving) or found,
                                                                    "linear")))
        if any(weigh(measures(found, method), found) for found in ranked[:SCREENED]):
            break
    return best


def _join_rank(found: JoinMeasures) -> tuple[int, float, float]:
    """Joins are ranked by tangles, then by how far they balloon past :data:`BALLOON`, then by evenness."""
    return found[0], max(found[2], BALLOON), found[1]


def _uneven(frames: Sequence[Array], k0s: Sequence[Array], k1s: Sequence[Array]) -> float:
    """The largest change of the area closed contours enclose (holes taken away, however each winds) from one
    t to the next, the keys included (``frames`` ``(T, L_i, 2)`` at :data:`.qcurves.QUALITY_T`), over the
    median change (the pops rule)."""
    signs = np.array([-1.0 if kind == "hole" else 1.0 for kind in roles(list(k0s), [True] * len(k0s))])
    inner = sum((sign * np.abs(_signed_areas(f)) for sign, f in zip(signs, frames)), np.zeros(len(frames[0]) if frames else 0))
    ends = [sum(sign * abs(float(_signed_areas(np.asarray(k)[None])[0])) for sign, k in zip(signs, keys))
            for keys in (k0s, k1s)]
    steps = np.abs(np.diff(np.concatenate([[ends[0]], inner, [ends[1]]])))
    middle = float(np.median(steps)) if len(steps) else 0.0
    return float(steps.max()) / middle if middle > 0 else (0.0 if not len(steps) or steps.max() == 0 else np.inf)


def _signed_areas(frames: Array) -> Array:
    """Shoelace areas of ``frames (T, L, 2)``: ``(T,)``."""
    x, y = frames[..., 0], frames[..., 1]
    return 0.5 * np.sum(x * np.roll(y, -1, axis=1) - np.roll(x, -1, axis=1) * y, axis=1)


def _join_choices(crowded: frozenset[tuple[int, int]], role: dict[tuple[int, int], str]
                  ) -> list[frozenset[tuple[int, int]]]:
    """The sets of ``crowded`` contours to try joining, best first: all, the pieces only, the holes only
    (``role``: each contour's, :func:`_roles_of`)."""
    out = [crowded]
    for kind in ("outer", "hole"):
        part = frozenset(c for c in crowded if role.get(c) == kind)
        if part and part not in out:
            out.append(part)
    return out


def _roles_of(first: Key, last: Key) -> dict[tuple[int, int], str]:
    """Each contour's role (:func:`.contours.roles`) in its key, by (key 0 or 1, index)."""
    role = {(0, i): r for i, r in enumerate(roles([c.points for c in first.contours], [c.closed for c in first.contours]))}
    role.update({(1, j): r for j, r in enumerate(roles([c.points for c in last.contours],
                                                       [c.closed for c in last.contours]))})
    return role


def _crowded(pairs: tuple[Pair, ...], first: Key, last: Key, method: str, stagger: float, view: float = 0.0
             ) -> frozenset[tuple[int, int]]:
    """The contours without a partner that :func:`growths_of` finds no room to grow (shrink) over the
    whole segment from ``first`` to ``last`` under ``method`` (or no room at all), as (key 0 or 1, index)."""
    if all(p.moving or p.fades for p in pairs):
        return frozenset()
    out = set()
    for pair, growth in zip(pairs, growths_of(_probe(pairs, first, last, stagger, view), method, hold=False)):
        if growth is not None and (growth.start > 0.0 or growth.stop < 1.0 or growth.stuck):
            out.add((1, pair.source[1]) if growth.grows else (0, pair.source[0]))
    return frozenset(out)  # type: ignore[arg-type]


def _windings_at(key: Key, own: tuple[bool, ...], run: tuple[tuple[bool, ...], tuple[bool, ...]]
                 ) -> tuple[bool, ...]:
    """The windings a half draws at ``key``: its run key's own, or at a breakdown those of the run's key
    it is nearer (``run``: the run's first and last keys' windings)."""
    if key.breakdown is None:
        return own
    return run[0] if key.breakdown < 0.5 else run[1]


def _anchors(pairs: Sequence[Pair], links: Sequence[Link]) -> tuple[tuple[tuple[str, int], ...], ...]:
    """Per pair, its hinted vertices as ``(letter, balanced vertex index)``."""
    out = []
    for pair in pairs:
        found: list[tuple[str, int]] = []
        for link in links:
            if (link.a[0], link.b[0]) != pair.source:
                continue
            if pair.correspondence is None:
                found.append((link.letter, link.a[1]))
                continue
            hits = np.flatnonzero((pair.correspondence.pairs[:, 0] == link.a[1])
                                  & (pair.correspondence.pairs[:, 1] == link.b[1]))
            if len(hits):
                found.append((link.letter, int(hits[0])))
        out.append(tuple(found))
    return tuple(out)


def _half(pairs: Sequence[Pair], start: Key | None, end: Key | None) -> tuple[Pair, ...]:
    """The pairs of a run of keys split by breakdowns, from breakdown ``start`` (``None``: the run's first
    key) to breakdown ``end`` (``None``: its last); a breakdown's contour n is pair n's in-between. A
    contour part way grown (or shrunk) at a breakdown moves from (to) there with the others."""
    out = []
    for n, pair in enumerate(pairs):
        s0, s1 = pair.source
        k0, k1 = pair.k0, pair.k1
        if start is not None:
            k0 = start.contours[n].points
            s0 = n if s0 is None and not pair.fades else s0
        if end is not None:
            k1 = end.contours[n].points
            s1 = n if s1 is None and not pair.fades else s1
        out.append(replace(pair, k0=k0, k1=k1, source=(s0, s1)))
    return tuple(out)


def make_breakdowns(shape: Shape, matching: Matching, method: str, *, unmatched: str = "grow",
                    balance: str = "copies", view: float = 0.0) -> Shape:
    """``shape`` with each breakdown key's contours and paint made (maths §5.15): the in-between at its
    favour ``f`` of the segment it splits, by ``method`` (its correspondence, hints, turn and arcs; no
    easing). Several breakdowns in one segment are made in time order, each splitting what is left."""
    if all(key.breakdown is None or key.contours for key in shape.keys):
        return shape
    keys = list(shape.keys)
    for k, key in enumerate(keys):
        if key.breakdown is None or key.contours:
            continue
        end = next(e for e in range(k + 1, len(keys)) if keys[e].breakdown is None)
        partial = replace(shape, keys=tuple(keys[:k]) + tuple(keys[end:]))
        segment = build_track(partial, matching, unmatched=unmatched, balance=balance, method=method,
                              view=view).segments[k - 1]
        f = np.array([float(key.breakdown)])
        frames = pair_paths(segment, f, method)
        paint = blend_paints(*segment.paints, np.clip(f, 0.0, 1.0))[0]
        near = segment.ends[0] if key.breakdown < 0.5 or segment.ends is None else segment.ends[1]
        contours = tuple(Contour(_frozen(frame[0]), pair.closed) for frame, pair in zip(frames, segment.pairs))
        keys[k] = replace(key, contours=contours, paint=paint, fill_rule=near.fill_rule, cap=near.cap,
                          join=near.join, miter_limit=near.miter_limit, layer=near.layer, hints=())
    return replace(shape, keys=tuple(keys))


def _pairs(before: Key, after: Key, fill_rule: str, matching: Matching, unmatched: str,
           balance: str = "copies", links: tuple[Link, ...] = (), caps: tuple[str, str] = ("round", "round"),
           join: frozenset[tuple[int, int]] = frozenset(), toward: tuple[float, float] | None = None
           ) -> tuple[Pair, ...]:
    """The contour pairs of the segment from ``before`` to ``after`` (``caps``: the shape's cap and join,
    where its keys do not set their own; ``join``: the contours without a partner, as (key 0 or 1,
    index), to join to a neighbour where they can be, :mod:`.bridges`, their slits leaving them
    ``toward`` a direction where one is given)."""
    a, b = before.contours, after.contours
    if before.hidden or after.hidden:
        # a hidden key is made contour by contour, vertex by vertex, from its neighbour: pair them in order;
        # unless it fades, the element grows from (shrinks to) the point the hidden key holds
        grows = unmatched != "fade" and before.hidden != after.hidden
        return tuple(Pair(x.points, y.points, x.closed, (len(x.points), len(y.points)), None,
                          (None if grows and before.hidden else i, None if grows and after.hidden else i))
                     for i, (x, y) in enumerate(zip(a, b)))
    forced = forced_contour_pairs(links)
    partners = pair_contours([c.points for c in a], [c.closed for c in a], [c.points for c in b],
                             [c.closed for c in b], forced=forced)
    shut_a, shut_b = _shut_strokes(before, caps), _shut_strokes(after, caps)
    changed = any(x is not y for x, y in zip(shut_a + shut_b, a + b))
    if changed and any(i is None or j is None for i, j in partners):
        # a stroke whose ends meet is a closed outline to the eye: paired as one, if that leaves fewer alone
        closing = pair_contours([c.points for c in shut_a], [c.closed for c in shut_a], [c.points for c in shut_b],
                                [c.closed for c in shut_b], forced=forced)
        if len(closing) < len(partners):
            partners, a, b = closing, shut_a, shut_b
    if any(i is None for i, _ in partners) and any(j is None for _, j in partners):
        # an outline drawn as a stroke alone is an open stroke whose ends meet: paired with a stroke of the
        # other key that has no partner either, if that leaves fewer alone, rather than one shrinking while
        # the other grows across it
        opened_a, opened_b = (_opened_alone(key, mine, theirs, partners, side, caps)
                              for key, mine, theirs, side in ((before, a, b, 0), (after, b, a, 1)))
        if opened_a is not a or opened_b is not b:
            opening = pair_contours([c.points for c in opened_a], [c.closed for c in opened_a],
                                    [c.points for c in opened_b], [c.closed for c in opened_b], forced=forced)
            if len(opening) < len(partners):
                partners, a, b = opening, opened_a, opened_b
    partners = keep_nesting(partners, [c.points for c in a], [c.closed for c in a], [c.points for c in b],
                            [c.closed for c in b], forced)
    if join and _joinable(before, after, unmatched, links):
        # a piece or hole without room to grow joins a neighbour by a slit and morphs with it (§5.17)
        a, b, partners = _joined(a, b, partners, before.fill_rule or fill_rule, after.fill_rule or fill_rule, join,
                                 toward)
    anchored = {} if unmatched == "fade" else \
        _anchor_points(a, b, partners, before.fill_rule or fill_rule, after.fill_rule or fill_rule)
    pairs = []
    for i, j in partners:
        if i is not None and j is not None:
            pair = _balanced(a[i], b[j], (i, j), matching, balance, vertex_links(links, (i, j)))
            if a[i] is not before.contours[i] or b[j] is not after.contours[j]:  # joined (or a stroke shut)
                pair = replace(pair, joined=(a[i].points, b[j].points))
            pairs.append(pair)
            continue
        # a contour without a partner: it fades, or shrinks to (i) or grows from (j) a point of the other key
        alone = a[i] if i is not None else b[j]  # type: ignore[index]
        n = len(alone.points)
        if unmatched == "fade":
            pairs.append(Pair(alone.points, alone.points, alone.closed, (n, n), None, (i, j), fades=True))
            continue
        collapsed = np.broadcast_to(anchored[i, j], alone.points.shape)
        k0, k1 = (alone.points, collapsed) if i is not None else (collapsed, alone.points)
        pairs.append(Pair(_frozen(k0), _frozen(k1), alone.closed, (n, n), None, (i, j)))
    return tuple(pairs)


def _anchor_points(a: Sequence[Contour], b: Sequence[Contour], partners: Sequence[tuple[int | None, int | None]],
                   rule_a: str, rule_b: str) -> dict[tuple[int | None, int | None], Array]:
    """Where each contour without a partner shrinks to (in key b) or grows from (in key a), by its pair:
    ``(2,)`` each (:func:`.contours.anchors`, each key's own fill rule)."""
    out: dict[tuple[int | None, int | None], Array] = {}
    for lonely, others, rule in (([p for p in partners if p[1] is None], b, rule_b),
                                 ([p for p in partners if p[0] is None], a, rule_a)):
        alone = [a[i] if i is not None else b[j] for i, j in lonely]  # type: ignore[index]
        found = anchors([c.points for c in alone], [c.closed for c in alone], [c.points for c in others],
                        [c.closed for c in others], rule)
        out.update(zip(lonely, found))
    return out


def _joinable(before: Key, after: Key, unmatched: str, links: tuple[Link, ...]) -> bool:
    """Whether contours without a partner may be joined to a neighbour between these keys (:mod:`.bridges`):
    they grow (not fade), no shape hint numbers the vertices, and neither key is stroked (a slit would show)."""
    return unmatched != "fade" and not links and not _stroked(before) and not _stroked(after)


def _stroked(key: Key) -> bool:
    """Whether ``key`` draws a stroke (a slit in its outline would show)."""
    paint = key.paint
    return paint.stroke is not None and paint.stroke[3] > 0 and paint.stroke_width > 0


def _joined(a: Sequence[Contour], b: Sequence[Contour], partners: Sequence[tuple[int | None, int | None]],
            rule_a: str, rule_b: str, join: frozenset[tuple[int, int]], toward: tuple[float, float] | None = None
            ) -> tuple[list[Contour], list[Contour], list[tuple[int | None, int | None]]]:
    """The two keys' contours with those of ``join`` (key 0 or 1, index) joined into neighbours
    (:func:`.bridges.join_alone`, slits leaving them ``toward`` a direction where given), and the partners
    left."""
    out = []
    gone: list[set[int]] = []
    for side, contours, rule in ((0, a, rule_a), (1, b, rule_b)):
        has = {p[side] for p in partners if None not in p}
        points, joined = join_alone([c.points for c in contours], [c.closed for c in contours],
                                    [k in has for k in range(len(contours))],
                                    [k for s, k in join if s == side], rule == "evenodd", toward)
        out.append([Contour(_frozen(p), c.closed) if p is not c.points else c for p, c in zip(points, contours)])
        gone.append({k for k, j in enumerate(joined) if j})
    kept = [(i, j) for i, j in partners if not (i in gone[0] and j is None) and not (j in gone[1] and i is None)]
    return out[0], out[1], kept


SHUT_GAP = 1e-3
"""An open contour whose ends are closer than this share of its box's diagonal ..."""


def _shut_strokes(key: Key, caps: tuple[str, str]) -> tuple[Contour, ...]:
    """``key``'s contours with each open one whose ends meet (within :data:`SHUT_GAP`) closed — where
    that draws the same: round caps and joins, or no stroke (a fill closes it anyway)."""
    if _stroked(key) and ((key.cap or caps[0]) != "round" or (key.join or caps[1]) != "round"):
        return key.contours
    out = []
    for contour in key.contours:
        points = contour.points
        if not contour.closed and len(points) >= 4:
            gap = float(np.hypot(*(points[-1] - points[0])))
            if gap <= SHUT_GAP * float(np.hypot(*np.ptp(points, axis=0))):
                contour = Contour(points[:-1] if gap == 0.0 else points, True)
        out.append(contour)
    return tuple(out)


def _opened_alone(key: Key, mine: Sequence[Contour], theirs: Sequence[Contour],
                  partners: Sequence[tuple[int | None, int | None]], side: int, caps: tuple[str, str]
                  ) -> Sequence[Contour]:
    """``mine`` (the contours of ``key``, key ``side`` of the segment) with each closed contour that has no
    partner opened into a stroke whose ends meet, where the other key (``theirs``) has an open stroke without
    a partner, and where that draws the same: a solid stroke with round caps and joins, nothing filled. It is
    cut at its vertex nearest the middle of that stroke's ends, where they come together."""
    paint = key.paint
    if (not _stroked(key) or (paint.fill is not None and paint.fill[3] > 0) or paint.gradient is not None
            or paint.pattern is not None or paint.dash is not None
            or (key.cap or caps[0]) != "round" or (key.join or caps[1]) != "round"):
        return mine
    alone = {pair[side] for pair in partners if pair[1 - side] is None} - {None}
    strokes = [theirs[pair[1 - side]] for pair in partners
               if pair[side] is None and pair[1 - side] is not None and not theirs[pair[1 - side]].closed]
    strokes = [c for c in strokes if len(c.points) >= 2]
    if not strokes:
        return mine
    out = list(mine)
    for k in sorted(alone):
        contour = mine[k]
        if not contour.closed or len(contour.points) < 3:
            continue
        middle = contour.points.mean(axis=0)
        nearest = min(strokes, key=lambda c: float(np.hypot(*(c.points.mean(axis=0) - middle))))
        ends = 0.5 * (nearest.points[0] + nearest.points[-1])
        cut = int(np.argmin(np.hypot(*(contour.points - ends).T)))
        turned = np.roll(contour.points, -cut, axis=0)
        out[k] = Contour(_frozen(np.vstack([turned, turned[:1]])), False)
    return out if any(x is not y for x, y in zip(out, mine)) else mine


def _paints(before: Key, after: Key, unmatched: str) -> tuple[Paint, Paint]:
    """The paints a segment blends: the keys' own, but an element growing from (shrinking to) a hidden
    key keeps its stroke width there: :func:`evaluate_segment` scales the width with the element."""
    if unmatched == "fade" or before.hidden == after.hidden:
        return before.paint, after.paint
    if before.hidden:
        return replace(before.paint, stroke_width=after.paint.stroke_width), after.paint
    return before.paint, replace(after.paint, stroke_width=before.paint.stroke_width)


def _balanced(a: Contour, b: Contour, source: tuple[int, int], matching: Matching,
              balance: str = "copies", hinted: list[tuple[int, int]] | None = None) -> Pair:
    closed = a.closed and b.closed
    m, n = len(a.points), len(b.points)
    if hinted and m >= 2 and n >= 2:
        search = correspond_hinted if closed else correspond_hinted_open
        found = search(a.points, b.points, hinted, matching)
        k0, k1 = found.apply(a.points, b.points)
        if balance == "spread" and closed:
            pinned = [p for p, (i, j) in enumerate(found.pairs.tolist()) if (i, j) in set(hinted)]
            k0, k1 = spread(k0, k1, fixed=pinned)
        return Pair(_frozen(k0), _frozen(k1), closed, (m, n), found, source)
    if m == n and matching.equal_counts == "drawn":
        return Pair(a.points, b.points, closed, (m, n), None, source)
    if m < 2 or n < 2:  # a single point: every vertex of the other pairs with it
        k0 = np.broadcast_to(a.points[0], (max(m, n), 2)) if m == 1 else a.points
        k1 = np.broadcast_to(b.points[0], (max(m, n), 2)) if n == 1 else b.points
        return Pair(_frozen(k0), _frozen(k1), closed, (m, n), None, source)
    found = correspond(a.points, b.points, matching) if closed else correspond_open(a.points, b.points, matching)
    k0, k1 = found.apply(a.points, b.points)
    if balance == "spread" and closed:
        k0, k1 = spread(k0, k1)
    return Pair(_frozen(k0), _frozen(k1), closed, (m, n), found, source)


def _frozen(points: Array) -> Points:
    array = np.array(points, dtype=np.float64)
    array.flags.writeable = False
    return array


def _first_occurrence(indices: NDArray[np.intp], count: int) -> NDArray[np.intp]:
    """For each value 0..count-1, the first position where it occurs in ``indices``."""
    first = np.full(count, -1, dtype=np.intp)
    values, positions = np.unique(indices, return_index=True)
    first[values] = positions
    return first

