"""Where an element's layers begin and end: its frames split into *runs*, each drawn alike.

A run is consecutive frames of one segment and one paint order on which the element is drawn with finite
contours, the same contours, stroke ends and kind of gradient fill and clip paths of the same make; its fill
rule and windings go on where the picture does not change: windings only relative to one another under
``nonzero``, and there only between contours that meet or nest; not at all under ``evenodd`` nor where nothing
is filled, and a solid fill may switch once between the two rules inside a run, drawn with the windings of its
``nonzero`` frames (under ``evenodd`` they change nothing), the files switching the rule at that frame. A run
under ``evenodd`` alone is wound by nesting, so that its picture is the same under either rule wherever its
contours do not cross. The paint order splits runs where it shows (:mod:`..core.stacking`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from numpy.typing import NDArray

from ..core.contours import inside, roles
from ..core.geometry import signed_area
from ..core.stacking import order_at, order_shows, swapped_pairs
from ..core.tangles import proper_crossings
from ..core.timing.timeline import ShapeAt, Track
from ..errors import OptionError
from ..model import Scene, Shape
from ..plan.job import stacking_of
from .paint_keys import clip_path_make, gradient_look

__all__ = ["Span", "stacking_phases", "runs_of", "style", "stroked"]

Array = NDArray[np.float64]


@dataclass(frozen=True)
class Span:
    """One run: frames ``first .. stop - 1`` filled by ``rule``, each contour drawn reversed where ``reversed`` says
    (empty: none); ``switch``, where the fill rule changes inside it: the frame and the rule from there on."""

    first: int
    stop: int
    rule: str
    reversed: tuple[bool, ...]
    switch: tuple[int, str] | None = None


def stacking_phases(scene: Scene, tracks: tuple[Track, ...], times: Array, drawn: list[list[ShapeAt]]
                    ) -> tuple[list[tuple[int, ...]], NDArray[np.intp]]:
    """The paint orders the clip passes through (shape indices, first painted first) and, per frame, which
    of them is in force: ``(F,)``. A layer is split where the order switches (docs/artwork.md;
    :mod:`..core.stacking`), unless no two shapes that change places look otherwise for it at any frame until
    the next split (``drawn``: each shape as drawn at each frame; :func:`..core.stacking.order_shows`)."""
    plan = stacking_of(scene, tracks)
    orders: list[tuple[int, ...]] = []
    phases = np.zeros(len(times), dtype=np.intp)
    for f, time in enumerate(times.tolist()):
        order = order_at(plan, scene.shapes, time)
        if not orders or (order != orders[-1] and any(order_shows(drawn[a][f], drawn[b][f])
                                                      for a, b in swapped_pairs(orders[-1], order))):
            orders.append(order)
        phases[f] = len(orders) - 1
    return orders, phases


def runs_of(shape: Shape, shapes: list[ShapeAt], segments: NDArray[np.intp], phases: NDArray[np.intp]) -> list[Span]:
    """The maximal runs of ``shape`` drawn as ``shapes`` at each frame (module docstring)."""
    drawn = []
    for at in shapes:
        _refuse_uncarried(shape, at)
        drawn.append(at.visible and all(np.all(np.isfinite(c)) for c in at.contours)
                     and all(at.clips))  # a clip region with no contours hides everything
    gradients = _gradient_looks(shapes, segments)

    def look(f: int) -> tuple[object, ...]:
        at = shapes[f]
        return int(segments[f]), int(phases[f]), len(at.contours), _stroke_ends(shape, at), gradients[f], \
            clip_path_make(at)

    out: list[Span] = []
    start: int | None = None
    filling: tuple[str, tuple[bool, ...], bool] | None = None
    rule, windings_at, switch, looks = "", 0, None, None
    for f in range(len(shapes) + 1):
        if start is not None:
            same = f < len(shapes) and drawn[f] and look(f) == looks
            now = _filling(shape, shapes[f]) if same else None
            if now is not None and filling is not None and now[0] == filling[0] == "nonzero" \
                    and not (now[2] or filling[2]) and _apart_where_they_differ(shapes[f], filling[1], now[1]):
                now = filling  # drawn with the run's windings, this frame looks the same
            if now is not None and now != filling:
                if filling is None:  # the first frame of the run that fills or dashes
                    rule = now[0]
                elif switch is None and now[0] != filling[0] and not (now[2] or filling[2]) and gradients[f] is None:
                    switch = f, now[0]
                else:
                    same = False
                if same:
                    if now[0] == "nonzero" and (filling is None or filling[0] != "nonzero"):
                        windings_at = f  # the windings of the nonzero frames (evenodd's change nothing)
                    filling = now
            if not same:
                dashed = any(at.paint.dash is not None for at in shapes[start:f])
                windings = _drawn_windings(shapes[start], rule, switch, shapes[windings_at], dashed)
                out.append(Span(start, f, rule, windings, switch))
                start = None
        if start is None and f < len(shapes) and drawn[f]:
            start, filling, switch, windings_at, looks = f, _filling(shape, shapes[f]), None, f, look(f)
            rule = filling[0] if filling is not None else style(shape, shapes[f])[0]
    return out


def _drawn_windings(first: ShapeAt, rule: str, switch: tuple[int, str] | None, nonzero: ShapeAt,
                    dashed: bool) -> tuple[bool, ...]:
    """Which contours a run draws reversed: under ``nonzero`` (throughout or in part) its nonzero frames' windings,
    and where dashed its first frame's (dashes run the way a contour winds); under ``evenodd`` alone, whichever make
    the two rules agree where no contours cross: each outline wound one way and each hole the other by their
    nesting at the run's first frame, so that a player that fills even-odd as nonzero (Skottie) draws the same
    picture."""
    if dashed:
        return first.reversed
    if rule == "nonzero" or switch is not None:
        return nonzero.reversed
    kinds = roles(list(first.contours), list(first.closed))
    return tuple(kind != "open" and len(c) >= 3 and (signed_area(c) > 0) != (kind == "outer")
                 for c, kind in zip(first.contours, kinds))


def _apart_where_they_differ(at: ShapeAt, ours: tuple[bool, ...], theirs: tuple[bool, ...]) -> bool:
    """Whether ``at`` fills nonzero the same with the relative windings ``ours`` as with ``theirs``
    (:func:`_windings`): every two contours wound alike by one and not by the other lie apart (no edges meet, as
    the exact test finds them, and neither holds the other), so that neither's winding adds to the other's."""
    count = len(at.contours)
    ours, theirs = ours or (False,) * count, theirs or (False,) * count  # none reversed
    if not len(ours) == len(theirs) == count:
        return False
    changed = {i for i, (a, b) in enumerate(zip(ours, theirs)) if a != b}
    pairs = [(i, j) for i in changed for j in range(count) if j not in changed]  # their relative winding changed
    if not pairs:
        return True
    shut = [len(c) >= 3 for c in at.contours]
    meeting = set(proper_crossings(list(at.contours), [True] * count, touching=True))
    return not any((min(i, j), max(i, j)) in meeting
                   or (shut[i] and len(at.contours[j]) and inside(at.contours[j][:1], at.contours[i])[0])
                   or (shut[j] and len(at.contours[i]) and inside(at.contours[i][:1], at.contours[j])[0])
                   for i, j in pairs)


def _filling(shape: Shape, at: ShapeAt) -> tuple[str, tuple[bool, ...], bool] | None:
    """What of the fill rule and windings shows at ``at``: the rule, the windings (:func:`_windings`) and whether
    the stroke is dashed (its dashes run the way the contour winds); None where nothing is filled nor dashed."""
    paint = at.paint
    fills = (paint.fill is not None and paint.fill[3] > 0) or paint.gradient is not None or paint.pattern is not None
    dashed = paint.dash is not None and stroked(at)
    if not (fills or dashed):
        return None
    return style(shape, at)[0], _windings(shape, at), dashed


def _stroke_ends(shape: Shape, at: ShapeAt) -> tuple[str, str, float] | None:
    """The caps, joins and miter limit ``at`` strokes with (None where it draws no stroke)."""
    return style(shape, at)[1:] if stroked(at) else None


def _windings(shape: Shape, at: ShapeAt) -> tuple[bool, ...]:
    """Which contours are drawn reversed, as far as the picture can tell: nothing under ``evenodd``, and under
    ``nonzero`` only relative to the first contour (every contour reversed fills the same), so a run goes on
    where a key's windings take over and the picture does not change."""
    if style(shape, at)[0] == "evenodd" or not at.reversed:
        return ()
    return tuple(flip != at.reversed[0] for flip in at.reversed)


def _refuse_uncarried(shape: Shape, at: ShapeAt) -> None:
    """A vector file cannot carry cross-fading contours, masks, group opacity nor pictures: refuse, naming the
    element."""
    if at.fade is not None:
        raise OptionError(f"element {shape.name!r}: its contours cross-fade (unmatched = \"fade\"), which the "
                          "vector formats do not carry; render a video or PNG frames", "format")
    if at.key is not None and at.key.groups:
        raise OptionError(f"element {shape.name!r}: it is drawn in a group with an opacity (an SVG <g opacity>) "
                          "composited as one, which the vector formats do not carry yet; render a video or PNG "
                          "frames, or put the opacity on each element in the drawing", "format")
    if at.masks:
        raise OptionError(f"element {shape.name!r}: it is masked (an SVG <mask>), which the vector formats do not "
                          "carry; render a video or PNG frames, or use a clip-path in the drawing", "format")
    if any(p is not None and p.image is not None for p in (at.paint.pattern, at.paint.stroke_pattern)):
        raise OptionError(f"element {shape.name!r}: it is a picture (an SVG <image>), which the vector formats do "
                          "not carry yet; render a video or PNG frames", "format")


def _gradient_looks(shapes: list[ShapeAt], segments: NDArray[np.intp]) -> list[tuple[str, str] | None]:
    """Per frame, the kind and spread of its gradient fill; a frame without one takes the nearest frame's of its
    segment, so a key filled plainly stays in the run of the gradient it blends with."""
    looks = [gradient_look(at.paint) for at in shapes]
    count = len(looks)
    nearest: list[list[int]] = [[] for _ in range(count)]  # the frames of the segment with a look, either side
    for order in (range(count), range(count - 1, -1, -1)):
        last, previous = None, None
        for f in order:
            if previous is not None and segments[f] != segments[previous]:
                last = None
            if looks[f] is not None:
                last = f
            if last is not None:
                nearest[f].append(last)
            previous = f
    return [looks[min(near, key=lambda i: abs(i - f))] if near else None for f, near in enumerate(nearest)]


def stroked(at: ShapeAt) -> bool:
    """Whether ``at`` draws a stroke (a colour not fully transparent, a width)."""
    stroke = at.paint.stroke
    return stroke is not None and stroke[3] > 0 and at.paint.stroke_width > 0


def style(shape: Shape, at: ShapeAt) -> tuple[str, str, str, float]:
    """The fill rule, caps, joins and miter limit ``shape`` is drawn with at one time: its key's own, else its own."""
    key = at.key
    if key is None:
        return shape.fill_rule, shape.cap, shape.join, shape.miter_limit
    return (key.fill_rule or shape.fill_rule, key.cap or shape.cap, key.join or shape.join,
            key.miter_limit or shape.miter_limit)


