"""Whole SVG drawings as keys: their elements matched from drawing to drawing into shapes.

Elements of consecutive drawings are matched by id where both drawings have it,
else by a minimum-cost assignment on position (relative to the view), size and
colour. A chain of matched elements becomes one :class:`~tweenrender.model.Shape`.
An element with no partner in the next (previous) drawing shrinks to (grows from)
its own centre during that segment — or fades, with ``unmatched = "fade"``: its
shape gets a *hidden* key there.

Coordinates: the first drawing's view box (flipped so y is up) is the scene's
world; every later drawing's view box is fitted into it, centred, aspect kept
(``xMidYMid meet``), so a 16-unit and a 24-unit icon line up.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import Sequence

import numpy as np

from ..model import Contour, Key, Shape, frozen_points
from .svg import Drawing, Element, read_drawing

__all__ = ["DrawingKey", "read_drawings", "drawing_shapes"]

# Cost weights of pairing two elements: centre distance (in view diagonals), size ratio, colour
# (OKLab distance). Where an element sits is the strongest cue, then its colour.
_POSITION_WEIGHT = 2.0
_SIZE_WEIGHT = 0.5
_COLOR_WEIGHT = 1.0
_KIND_COST = 0.5  # a filled element with a stroke-only one
_UNMATCHED_COST = 0.6  # leaving an element without a partner: beyond this, it goes and another comes


@dataclass(frozen=True, slots=True)
class DrawingKey:
    """A drawing at a time: its path, the time in seconds, the easing of the segment it starts."""

    path: Path
    time: float
    ease: str = "linear"
    tolerance: float | None = None


def read_drawings(keys: Sequence[DrawingKey]) -> tuple[list[Drawing], tuple[float, float, float, float]]:
    """Every drawing in world units, the later ones fitted into the first's view box; and that box."""
    first = read_drawing(keys[0].path, keys[0].tolerance)
    drawings = [first]
    for key in keys[1:]:
        drawings.append(read_drawing(key.path, key.tolerance, into=first.box))
    return drawings, first.box


def drawing_shapes(drawings: Sequence[Drawing], keys: Sequence[DrawingKey], unmatched: str) -> list[Shape]:
    """The shapes the drawings make, in paint order (see the module's docstring)."""
    box = drawings[0].box
    diagonal = float(np.hypot(box[2] - box[0], box[3] - box[1])) or 1.0
    chains: list[list[tuple[int, int]]] = [[(0, e)] for e in range(len(drawings[0].elements))]
    last_of = {e: e for e in range(len(drawings[0].elements))}  # element of the latest drawing → its chain
    order = list(range(len(chains)))
    for k in range(1, len(drawings)):
        links = match_elements(drawings[k - 1].elements, drawings[k].elements, diagonal)
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
    names = _names([[drawings[k].elements[e] for k, e in chain] for chain in chains])
    return [_shape(chains[c], names[c], drawings, keys, unmatched) for c in order]


def match_elements(a: Sequence[Element], b: Sequence[Element], diagonal: float) -> list[tuple[int | None, int | None]]:
    """Pairs ``(i, j)`` of elements of consecutive drawings (``None``: no partner)."""
    from scipy.optimize import linear_sum_assignment

    pairs: list[tuple[int | None, int | None]] = []
    ids_a = {e.id: i for i, e in enumerate(a) if e.id and sum(x.id == e.id for x in a) == 1}
    ids_b = {e.id: j for j, e in enumerate(b) if e.id and sum(x.id == e.id for x in b) == 1}
    for ident, i in ids_a.items():
        if ident in ids_b:
            pairs.append((i, ids_b[ident]))
    left = [i for i in range(len(a)) if i not in {p[0] for p in pairs}]
    right = [j for j in range(len(b)) if j not in {p[1] for p in pairs}]
    if left and right:
        if len(left) == len(right) == 1 and not pairs:
            pairs.append((left[0], right[0]))  # one element each: always the same one
            left, right = [], []
        else:
            cost = _costs([a[i] for i in left], [b[j] for j in right], diagonal)
            m, n = cost.shape
            big = 1e9
            full = np.full((m + n, n + m), big)
            full[:m, :n] = cost
            full[:m, n:] = np.where(np.eye(m, dtype=bool), _UNMATCHED_COST, big)
            full[m:, :n] = np.where(np.eye(n, dtype=bool), _UNMATCHED_COST, big)
            full[m:, n:] = 0.0
            rows, cols = linear_sum_assignment(full)
            paired = [(left[r], right[c]) for r, c in zip(rows, cols) if r < m and c < n]
            pairs += paired
            left = [i for i in left if i not in {p[0] for p in paired}]
            right = [j for j in right if j not in {p[1] for p in paired}]
    pairs += [(i, None) for i in left] + [(None, j) for j in right]
    return pairs


def _costs(a: Sequence[Element], b: Sequence[Element], diagonal: float) -> np.ndarray:
    """The cost of pairing each element of ``a`` with each of ``b``: ``(len(a), len(b))``."""
    from ..core.paint import srgb_to_oklab

    def features(elements: Sequence[Element]) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        centres = np.array([_centre(e) for e in elements])
        sizes = np.log([_size(e) for e in elements])
        colours = [e.paint.fill or e.paint.stroke for e in elements]
        lab = srgb_to_oklab(np.array([c[:3] if c is not None else (0, 0, 0) for c in colours], float) / 255.0)
        lab[[c is None for c in colours]] = np.nan
        filled = np.array([e.paint.fill is not None for e in elements])
        return centres, sizes, lab, filled

    ca, sa, la, fa = features(a)
    cb, sb, lb, fb = features(b)
    cost = (_POSITION_WEIGHT * np.linalg.norm(ca[:, None] - cb[None], axis=-1) / diagonal
            + _SIZE_WEIGHT * np.abs(sa[:, None] - sb[None]))
    colour = np.linalg.norm(la[:, None] - lb[None], axis=-1)
    cost += _COLOR_WEIGHT * np.nan_to_num(colour, nan=0.0)  # an element without colour matches any
    cost += _KIND_COST * (fa[:, None] != fb[None])
    return cost


def _centre(element: Element) -> np.ndarray:
    """The centre of the element's bounding box."""
    every = np.concatenate([c.points for c in element.contours])
    return 0.5 * (every.min(axis=0) + every.max(axis=0))


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
           unmatched: str) -> Shape:
    first_k, last_k = chain[0][0], chain[-1][0]
    elements = [drawings[k].elements[e] for k, e in chain]
    out = [Key(keys[k].time, e.contours, keys[k].ease, e.paint, fill_rule=e.fill_rule, cap=e.cap, join=e.join,
               miter_limit=e.miter_limit, layer=index, clips=e.clips) for (k, index), e in zip(chain, elements)]
    if first_k > 0:  # it appears: it comes from the key before
        out.insert(0, _hidden(elements[0], keys[first_k - 1], unmatched))
    if last_k < len(drawings) - 1:  # it goes: it leaves by the key after
        out.append(_hidden(elements[-1], keys[last_k + 1], unmatched))
    style = elements[0]
    return Shape(name=name, keys=tuple(out), fill_rule=style.fill_rule, cap=style.cap, join=style.join,
                 miter_limit=style.miter_limit, stroke_scales=True, unmatched=unmatched, equal_counts="match")


def _hidden(element: Element, at: DrawingKey, unmatched: str) -> Key:
    """Where an element comes from or goes to: its centre (``grow``) or itself at opacity 0 (``fade``)."""
    if unmatched == "fade":
        return Key(at.time, element.contours, at.ease, replace(element.paint, opacity=0.0), hidden=True,
                   fill_rule=element.fill_rule, cap=element.cap, join=element.join, miter_limit=element.miter_limit,
                   clips=element.clips)
    centre = _centre(element)
    contours = tuple(Contour(frozen_points(np.broadcast_to(centre, c.points.shape)), c.closed)
                     for c in element.contours)
    return Key(at.time, contours, at.ease, replace(element.paint, stroke_width=0.0), hidden=True,
               fill_rule=element.fill_rule, cap=element.cap, join=element.join, miter_limit=element.miter_limit,
               clips=element.clips)
