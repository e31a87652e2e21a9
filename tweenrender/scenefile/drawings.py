"""Whole SVG drawings as keys: their elements matched from drawing to drawing into shapes.

Elements of consecutive drawings are matched by id where both drawings have it,
else by a minimum-cost assignment on position (relative to the view), size and
colour. A chain of matched elements becomes one :class:`~tweenrender.model.Shape`.
An element drawn with a stroke alone matched with one drawn with a fill alone is outlined
(:mod:`.stroke_outline`): its stroke's band becomes the filled shape. An element with no partner
in the next (previous) drawing shrinks to (grows from)
its own centre of area over that segment, its area linear in time (maths §5.17) —
or fades, with ``unmatched = "fade"``: its shape gets a *hidden* key there.

Coordinates: the first drawing's view box (flipped so y is up) is the scene's
world; every later drawing's view box is fitted into it, centred, aspect kept
(``xMidYMid meet``), so a 16-unit and a 24-unit icon line up.
"""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Callable, Sequence

import numpy as np

from ..core.contours import apparent_area, centre_of_area, roles
from ..core.correspondence.assignment import min_cost_assignment
from ..core.timing.easing import Easing
from ..errors import SceneError
from ..model import Contour, Hint, Key, Shape, frozen_points
from .controls import check_hints, check_stagger, pinned
from .scene_limits import LIMITS
from .stroke_outline import fill_only, outlined, stroke_only
from .svg import Drawing, Element, read_drawing

__all__ = ["DrawingKey", "read_drawings", "drawing_shapes", "with_breakdowns"]

# Cost weights of pairing two elements: centre distance (in view diagonals), size ratio, colour
# (OKLab distance). Where an element sits is the strongest cue, then its colour.
_POSITION_WEIGHT = 2.0
_SIZE_WEIGHT = 0.5
_COLOR_WEIGHT = 1.0
_KIND_COST = 0.5  # a filled element with a stroke-only one; of two stroke-only ones, outlines with lines
_UNMATCHED_COST = 0.6  # leaving an element without a partner: beyond this, it goes and another comes
_ROWS = 256  # rows of the cost matrix computed at once
_SETTLING = 4  # passes placing the elements that come or go in the paint order


@dataclass(frozen=True, slots=True)
class DrawingKey:
    """A drawing at a time: its path, the time in seconds, the easing of the segment it starts (as written,
    and parsed: ``None`` parses ``ease``), its shape hints (letters to points in the SVG's user units),
    the stagger of its elements and how long it holds before moving (seconds)."""

    path: Path
    time: float
    ease: str = "linear"
    tolerance: float | None = None
    easing: Easing | None = None
    hints: dict[str, tuple[float, float]] = field(default_factory=dict)
    stagger: float = 0.0
    hold: float = 0.0
    turn: str | None = None  # the turn of the segment starting here (maths §5.13)
    turns: int = 0
    arcs: dict[str, tuple[float, float]] = field(default_factory=dict)  # in the SVG's user units


def read_drawings(keys: Sequence[DrawingKey]) -> tuple[list[Drawing], tuple[float, float, float, float]]:
    """Every drawing in world units, the later ones fitted into the first's view box; and that box."""
    first = read_drawing(keys[0].path, keys[0].tolerance)
    drawings = [first]
    for key in keys[1:]:
        drawings.append(read_drawing(key.path, key.tolerance, into=first.box))
    return drawings, first.box


Fail = Callable[[str, str], SceneError]


def _raise(where: str, message: str) -> SceneError:
    return SceneError(None, where, message)


def drawing_shapes(drawings: Sequence[Drawing], keys: Sequence[DrawingKey], unmatched: str,
                   fail: Fail = _raise) -> list[Shape]:
    """The shapes the drawings make, in paint order (see the module's docstring). ``fail(where, message)``
    builds the error for a bad hint or stagger, ``where`` a path such as ``drawing[1].hints.a``."""
    box = drawings[0].box
    diagonal = float(np.hypot(box[2] - box[0], box[3] - box[1])) or 1.0
    elements = sum(len(drawing.elements) for drawing in drawings)  # each one key of a shape: refused before
    if elements > LIMITS["keys"]:                                   # they are paired, not after
        raise fail("drawing", f"expected at most {LIMITS['keys']} keys in the scene, found {elements} "
                            f"(one for each element of each drawing)")
    drawings, hints = _pinned_drawings(drawings, keys, fail)
    arcs = [_world(drawing, key.arcs) for drawing, key in zip(drawings, keys)]
    chains: list[list[tuple[int, int]]] = [[(0, e)] for e in range(len(drawings[0].elements))]
    last_of = {e: e for e in range(len(drawings[0].elements))}  # element of the latest drawing → its chain
    order = list(range(len(chains)))
    for k in range(1, len(drawings)):
        forced = _hinted_partners(hints[k - 1], hints[k], f"drawing[{k}].hints", fail)
        links = match_elements(drawings[k - 1].elements, drawings[k].elements, diagonal, forced)
        now: dict[int, int] = {}
        for a, b in links:
            if a is not None and b is not None:
                chain = last_of[a]
                chains[chain].append((k, b))
                now[b] = chain
        for b in range(len(drawings[k].elements)):
            if b not in now:
                now[b] = len(chains)
                chains.append([(k, b)])
        order = _merge_order(order, [now[b] for b in range(len(drawings[k].elements))])
        last_of = now
    order = _settled(order, chains, len(drawings))
    names = _names([[drawings[k].elements[e] for k, e in chain] for chain in chains])
    delays = _delays(chains, drawings, keys, fail)
    shapes = [_shape(chains[c], names[c], drawings, keys, unmatched, hints, delays[c], arcs) for c in order]
    times = [key.time for key in keys]
    for shape in shapes:
        check_hints(shape.keys, lambda q, s=shape: f"drawing[{times.index(s.keys[q].time)}]", fail)
    return shapes


def _pinned_drawings(drawings: Sequence[Drawing], keys: Sequence[DrawingKey], fail: Fail
                     ) -> tuple[list[Drawing], list[dict[int, tuple[Hint, ...]]]]:
    """The drawings with their hints snapped onto their elements (vertices inserted), and per drawing the
    hints of each element (by element index; a hint's contour indexes its element's contours)."""
    out, hints = [], []
    for k, (drawing, key) in enumerate(zip(drawings, keys)):
        if not key.hints or not drawing.elements:
            out.append(drawing)
            hints.append({})
            continue
        flat = [(e, c) for e, element in enumerate(drawing.elements) for c in range(len(element.contours))]
        to_world = drawing.to_world if drawing.to_world is not None else np.eye(3)
        world = {letter: tuple((to_world @ np.array([x, y, 1.0]))[:2]) for letter, (x, y) in key.hints.items()}
        scale = float(np.sqrt(abs(np.linalg.det(to_world[:2, :2])))) or 1.0
        contours = [drawing.elements[e].contours[c] for e, c in flat]
        new, placed, _ = pinned(contours, world, f"drawing[{k}].hints", fail, scale)  # type: ignore[arg-type]
        elements = list(drawing.elements)
        for e in range(len(elements)):
            mine = tuple(new[q] for q, (owner, _) in enumerate(flat) if owner == e)
            elements[e] = replace(elements[e], contours=mine)
        per: dict[int, list[Hint]] = {}
        for hint in placed:
            e, c = flat[hint.contour]
            per.setdefault(e, []).append(Hint(hint.letter, c, hint.vertex))
        out.append(replace(drawing, elements=tuple(elements)))
        hints.append({e: tuple(h) for e, h in per.items()})
    for k, key in enumerate(keys):
        letters = {h.letter for found in hints[k].values() for h in found}
        for letter in sorted(letters):
            near = [q for q in (k - 1, k + 1) if 0 <= q < len(keys)]
            if not any(letter in {h.letter for found in hints[q].values() for h in found} for q in near):
                raise fail(f"drawing[{k}].hints.{letter}",
                           f"expected hint {letter} on the drawing before or after too, found it on neither")
    return out, hints


def _hinted_partners(first: dict[int, tuple[Hint, ...]], second: dict[int, tuple[Hint, ...]], where: str,
                     fail: Fail) -> list[tuple[int, int]]:
    """The element pairs ``(i, j)`` that letters on both drawings make partners."""
    owner_a = {h.letter: e for e, found in first.items() for h in found}
    owner_b = {h.letter: e for e, found in second.items() for h in found}
    to: dict[int, tuple[int, str]] = {}
    back: dict[int, tuple[int, str]] = {}
    for letter in sorted(set(owner_a) & set(owner_b)):
        i, j = owner_a[letter], owner_b[letter]
        if (i in to and to[i][0] != j) or (j in back and back[j][0] != i):
            other = to[i][1] if i in to and to[i][0] != j else back[j][1]
            raise fail(f"{where}.{letter}", f"expected hints {other} and {letter} to pair one element with one "
                                            f"element, found them pairing it with two")
        to[i], back[j] = (j, letter), (i, letter)
    return sorted((i, j) for i, (j, _) in to.items())


def _delays(chains: list[list[tuple[int, int]]], drawings: Sequence[Drawing], keys: Sequence[DrawingKey],
            fail: Fail) -> list[dict[int, float]]:
    """Per chain, the delay of the segment starting at each drawing k: the drawing's hold, plus
    ``i × stagger`` for element i in the order of drawing k's paint, then the elements appearing in
    drawing k + 1 in its order."""
    out: list[dict[int, float]] = [{} for _ in chains]
    at = {node: c for c, chain in enumerate(chains) for node in chain}
    for k in range(len(keys) - 1):
        key = keys[k]
        present = [at[(k, e)] for e in range(len(drawings[k].elements))]
        arriving = [at[(k + 1, e)] for e in range(len(drawings[k + 1].elements))
                    if chains[at[(k + 1, e)]][0][0] == k + 1]
        order = present + arriving
        if key.stagger > 0:
            check_stagger(key.stagger, len(order), key.time + key.hold, keys[k + 1].time,
                          f"drawing[{k}].stagger", fail)
        for i, c in enumerate(order):
            out[c][k] = key.hold + i * key.stagger
    return out


def match_elements(a: Sequence[Element], b: Sequence[Element], diagonal: float,
                   forced: Sequence[tuple[int, int]] = ()) -> list[tuple[int | None, int | None]]:
    """Pairs ``(i, j)`` of elements of consecutive drawings (``None``: no partner); ``forced`` pairs
    (shape hints make them) come first, then ids, then the assignment."""
    pairs: list[tuple[int | None, int | None]] = [(i, j) for i, j in forced]
    taken_a, taken_b = {i for i, _ in forced}, {j for _, j in forced}
    ids_a, ids_b = _unique_ids(a, taken_a), _unique_ids(b, taken_b)
    for ident, i in ids_a.items():
        if ident in ids_b:
            pairs.append((i, ids_b[ident]))
    paired_a, paired_b = {p[0] for p in pairs}, {p[1] for p in pairs}
    left = [i for i in range(len(a)) if i not in paired_a]
    right = [j for j in range(len(b)) if j not in paired_b]
    if left and right:
        if len(left) == len(right) == 1 and not pairs:
            pairs.append((left[0], right[0]))  # one element each: always the same one
            left, right = [], []
        else:
            # leaving an element unpaired costs _UNMATCHED_COST, so a pair is worth what it saves,
            # 2·_UNMATCHED_COST - cost, and one that saves nothing is not made: a rectangular assignment
            # of the savings finds the least total (an (m + n)² matrix of "unpaired" slots would too,
            # at four times the memory)
            saving = _costs([a[i] for i in left], [b[j] for j in right], diagonal)
            saving -= 2.0 * _UNMATCHED_COST
            np.minimum(saving, 0.0, out=saving)
            rows, cols = min_cost_assignment(saving)
            paired = [(left[r], right[c]) for r, c in zip(rows, cols) if saving[r, c] < 0.0]
            pairs += paired
            paired_a, paired_b = {p[0] for p in paired}, {p[1] for p in paired}
            left = [i for i in left if i not in paired_a]
            right = [j for j in right if j not in paired_b]
    pairs += [(i, None) for i in left] + [(None, j) for j in right]
    return pairs


def _unique_ids(elements: Sequence[Element], taken: set[int]) -> dict[str, int]:
    """Each id written on exactly one of ``elements`` → that element's index (unless ``taken``)."""
    counts = Counter(e.id for e in elements if e.id)
    return {e.id: i for i, e in enumerate(elements) if e.id and counts[e.id] == 1 and i not in taken}


def _costs(a: Sequence[Element], b: Sequence[Element], diagonal: float) -> np.ndarray:
    """The cost of pairing each element of ``a`` with each of ``b``: ``(len(a), len(b))``."""
    from ..core.paint import srgb_to_oklab

    def features(elements: Sequence[Element]) -> tuple[np.ndarray, ...]:
        centres = np.array([_centre(e) for e in elements])
        extents = [_size(e) for e in elements]
        sizes = np.log([_enclosed_size(e, extent) for e, extent in zip(elements, extents)])
        colours = [e.paint.fill or e.paint.stroke for e in elements]
        lab = srgb_to_oklab(np.array([c[:3] if c is not None else (0, 0, 0) for c in colours], float) / 255.0)
        lab[[c is None for c in colours]] = np.nan
        filled = np.array([e.paint.fill is not None for e in elements])
        looped = np.array([_looped(e, extent) for e, extent in zip(elements, extents)])
        return centres, sizes, lab, filled, looped

    ca, sa, la, fa, oa = features(a)
    cb, sb, lb, fb, ob = features(b)
    cost = np.empty((len(a), len(b)))
    for start in range(0, len(a), _ROWS):  # a block of rows at a time: no (m, n, 3) differences in memory
        rows = slice(start, start + _ROWS)
        apart = np.hypot(ca[rows, None, 0] - cb[None, :, 0], ca[rows, None, 1] - cb[None, :, 1])
        block = _POSITION_WEIGHT / diagonal * apart
        block += _SIZE_WEIGHT * np.abs(sa[rows, None] - sb[None])
        colour = np.sqrt(sum((la[rows, None, q] - lb[None, :, q]) ** 2 for q in range(3)))
        block += _COLOR_WEIGHT * np.nan_to_num(colour, nan=0.0)  # an element without colour matches any
        block += _KIND_COST * (fa[rows, None] != fb[None])
        # two elements drawn by their strokes alone, an outline and lines: their contours cannot pair, so
        # one would only shrink away while the other grows
        block += _KIND_COST * (~fa[rows, None] & ~fb[None] & (oa[rows, None] != ob[None]))
        cost[rows] = block
    return cost


def _centre(element: Element) -> np.ndarray:
    """The centre of the element's bounding box."""
    every = np.concatenate([c.points for c in element.contours])
    return 0.5 * (every.min(axis=0) + every.max(axis=0))


def _looped(element: Element, size: float) -> bool:
    """Whether any of the element's contours is closed, or a stroke whose ends meet (an outline); ``size`` is
    the element's (:func:`_size`)."""
    return any(c.closed or (len(c.points) > 2 and float(np.hypot(*(c.points[0] - c.points[-1]))) <= 1e-6 * size)
               for c in element.contours)


def _enclosed_size(element: Element, extent: float) -> float:
    """The element's size for pairing: for a filled element, √(2 × the area its outer contours look to cover,
    :func:`..core.contours.apparent_area`), holes not taken away (a square's is its diagonal); else, or where
    that area is nil, its ``extent`` (:func:`_size`). Pieces spread over a box are as small as their area (a
    sun's rays are not its disc), and a ring, drawn as an outline with a hole or as one contour out round
    and back, is nearly as big as the disc it rings."""
    if element.paint.fill is None:
        return extent
    points = [c.points for c in element.contours]
    kinds = roles(points, [c.closed and len(p) >= 3 for c, p in zip(element.contours, points)])
    enclosed = sum(apparent_area(p) for p, kind in zip(points, kinds) if kind == "outer")
    return float(np.sqrt(2.0 * enclosed)) if enclosed > 1e-6 * extent * extent else extent


def _size(element: Element) -> float:
    every = np.concatenate([c.points for c in element.contours])
    return max(float(np.hypot(*np.ptp(every, axis=0))), 1e-9)


def _merge_order(order: list[int], drawn: list[int]) -> list[int]:
    """``order`` with the chains of a drawing's paint order ``drawn`` that it lacks, each put right
    after the chain drawn before it (or first)."""
    out = list(order)
    cursor = -1
    for chain in drawn:
        if chain in out:
            cursor = out.index(chain)
        else:
            out.insert(cursor + 1, chain)
            cursor += 1
    return out


def _settled(order: list[int], chains: list[list[tuple[int, int]]], count: int) -> list[int]:
    """``order`` with each chain that comes after the first drawing or goes before the last put where it
    changes places with the fewest others between its hidden key and the key beside it, and then, of
    those places, where it is over the most elements that go as it comes (under those that come as it goes).

    At its hidden key an element is painted right after the chain before it in ``order`` that is drawn
    there (:func:`..core.stacking.key_order`). Were it on the other side of a chain there than beside,
    the paint order's one switch between the keys (which other elements may put late) would keep it
    under that chain for part of its growth (or put it there for part of its shrinking), and it would
    pop into (out of) view at the switch; and under an element that shrinks away as it grows, it would
    show only as that one goes (maths §5.17). Ties keep its place.
    """
    layers: list[dict[int, int]] = [{} for _ in range(count)]  # per drawing: chain -> its place in the paint
    for c, chain in enumerate(chains):
        for k, e in chain:
            layers[k][c] = e
    out = list(order)
    moving = [c for c in order if chains[c][0][0] > 0 or chains[c][-1][0] < count - 1]
    for _ in range(_SETTLING):  # where one goes may change where another is best: a few passes
        before = list(out)
        for c in moving:
            out = _settle(c, out, chains[c], layers)
        if out == before:
            break
    return out


def _settle(c: int, out: list[int], chain: list[tuple[int, int]], layers: list[dict[int, int]]) -> list[int]:
    """``out`` with chain ``c`` (drawn in ``chain``, its drawings and places) moved where it changes places
    with the fewest others, then is under the fewest that go as it comes (see :func:`_settled`)."""
    first, last = chain[0][0], chain[-1][0]
    ends = ([(first - 1, first)] if first > 0 else []) + ([(last + 1, last)] if last < len(layers) - 1 else [])
    rest = [x for x in out if x != c]
    size = len(rest) + 1
    swaps = np.zeros(size, dtype=np.int64)
    unders = np.zeros(size, dtype=np.int64)
    for hidden, shown in ends:
        there = np.array([layers[hidden].get(x, -1) for x in rest], dtype=np.int64)  # -1: not drawn there
        beside = np.array([layers[shown].get(x, -1) for x in rest], dtype=np.int64)
        # put before rest[j], c is painted right after the last chain before it drawn at ``hidden``: above
        # the chains whose places there are < slots[j]
        prior = np.maximum.accumulate(np.where(there >= 0, np.arange(len(rest)), -1))
        slots = np.concatenate([[0], np.where(prior >= 0, there[prior] + 1, 0)])
        below = (beside >= 0) & (beside < layers[shown][c])  # under c beside
        both = (there >= 0) & (beside >= 0)
        swaps += _misplaced(there[both], below[both], slots)
        # hidden there too: after the same chain, the later in ``out`` is above
        alone = np.flatnonzero((there < 0) & (beside >= 0))
        swaps += _misplaced(slots[alone] * size + alone, below[alone], slots * size + np.arange(size))
        going = (there >= 0) & (beside < 0)  # goes as c comes (comes as c goes): c over (under) it
        unders += _misplaced(there[going], np.full(int(going.sum()), hidden < shown), slots)
    cost = swaps * size + unders
    now = out.index(c)
    best = now if cost[now] == cost.min() else int(np.argmin(cost))
    return rest[:best] + [c] + rest[best:]


def _misplaced(keys: np.ndarray, below: np.ndarray, at: np.ndarray) -> np.ndarray:
    """For each place ``at (P,)``: how many chains (their ``keys (D,)``; below the place where key < at) are
    not below it though they should be (``below (D,)``), plus how many are below it though they should
    not be: ``(P,)``."""
    should, should_not = np.sort(keys[below]), np.sort(keys[~below])
    return (len(should) - np.searchsorted(should, at)) + np.searchsorted(should_not, at)


def _names(chains: list[list[Element]]) -> list[str]:
    """A unique name per chain: the element's id where it has one, else its tag and a number."""
    names: list[str] = []
    taken: set[str] = set()
    counts: dict[str, int] = {}
    for chain in chains:
        ident = next((e.id for e in chain if e.id), None)
        name = ident if ident and ident not in taken else None
        while name is None or name in taken:
            tag = chain[0].tag
            counts[tag] = counts.get(tag, 0) + 1
            name = f"{tag}{counts[tag]}"
        taken.add(name)
        names.append(name)
    return names


def _shape(chain: list[tuple[int, int]], name: str, drawings: Sequence[Drawing], keys: Sequence[DrawingKey],
           unmatched: str, hints: Sequence[dict[int, tuple[Hint, ...]]], delays: dict[int, float],
           arcs: Sequence[dict[str, tuple[float, float]]] = ()) -> Shape:
    first_k, last_k = chain[0][0], chain[-1][0]
    elements = [drawings[k].elements[e] for k, e in chain]
    if any(fill_only(e.paint) for e in elements) and any(stroke_only(e.paint) for e in elements):
        # a stroke becoming a fill: its band of ink is what becomes the filled shape
        elements = [outlined(e) if stroke_only(e.paint) else e for e in elements]
    out = [Key(keys[k].time, e.contours, keys[k].ease, e.paint, fill_rule=e.fill_rule, cap=e.cap, join=e.join,
               miter_limit=e.miter_limit, layer=index, clips=e.clips, masks=e.masks, groups=e.groups,
               easing=keys[k].easing,
               hints=hints[k].get(index, ()), delay=delays.get(k, 0.0), turn=keys[k].turn, turns=keys[k].turns,
               arcs=tuple((h.letter, arcs[k][h.letter]) for h in hints[k].get(index, ())
                          if arcs and h.letter in arcs[k]))
           for (k, index), e in zip(chain, elements)]
    if first_k > 0:  # it appears: it comes from the key before
        out.insert(0, replace(_hidden(elements[0], keys[first_k - 1], unmatched), delay=delays.get(first_k - 1, 0.0)))
    if last_k < len(drawings) - 1:  # it goes: it leaves by the key after
        out.append(_hidden(elements[-1], keys[last_k + 1], unmatched))
    style = elements[0]
    return Shape(name=name, keys=tuple(out), fill_rule=style.fill_rule, cap=style.cap, join=style.join,
                 miter_limit=style.miter_limit, stroke_scales=True, unmatched=unmatched, equal_counts="match")


def _hidden(element: Element, at: DrawingKey, unmatched: str) -> Key:
    """Where an element comes from or goes to: its centre of area (``grow``) or itself at opacity 0 (``fade``)."""
    if unmatched == "fade":
        return Key(at.time, element.contours, at.ease, replace(element.paint, opacity=0.0), hidden=True,
                   fill_rule=element.fill_rule, cap=element.cap, join=element.join, miter_limit=element.miter_limit,
                   clips=element.clips, masks=element.masks, groups=element.groups, easing=at.easing)
    centre = centre_of_area([c.points for c in element.contours], [c.closed for c in element.contours])
    contours = tuple(Contour(frozen_points(np.broadcast_to(centre, c.points.shape)), c.closed)
                     for c in element.contours)
    return Key(at.time, contours, at.ease, replace(element.paint, stroke_width=0.0), hidden=True,
               fill_rule=element.fill_rule, cap=element.cap, join=element.join, miter_limit=element.miter_limit,
               clips=element.clips, masks=element.masks, groups=element.groups, easing=at.easing)


def _world(drawing: Drawing, points: dict[str, tuple[float, float]]) -> dict[str, tuple[float, float]]:
    """``points`` in a drawing's user units, in world units."""
    to_world = drawing.to_world if drawing.to_world is not None else np.eye(3)
    out = {}
    for letter, (x, y) in points.items():
        world = to_world @ np.array([x, y, 1.0])
        out[letter] = (float(world[0]), float(world[1]))
    return out


def with_breakdowns(shape: Shape, breakdowns: Sequence[Key]) -> Shape:
    """``shape`` with each breakdown key (no contours yet) whose time falls between two of its keys put
    among them, keeping the element's drawing rules."""
    keys = list(shape.keys)
    for key in breakdowns:
        if not keys[0].time < key.time < keys[-1].time:
            continue
        at = next(k for k, other in enumerate(keys) if other.time > key.time)
        keys.insert(at, key)
    return replace(shape, keys=tuple(keys))
