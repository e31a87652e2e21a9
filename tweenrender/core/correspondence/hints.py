"""Shape hints (maths §5.10): points an animator pins on two keys so that one travels to the other.

A hint is a letter and a point of a key. The point snaps to the nearest point of the key's
outline — a vertex is inserted where it falls inside an edge — and the same letter on the next
key is its partner. Between two keys the letters both carry are *links*: each pairs a contour
and a vertex of the first key with a contour and a vertex of the second. Links make their
contours partners and fix the correspondence at their vertices (:mod:`.hint_search`).

A link is refused when it pairs an outer contour with a hole (or a closed contour with an open
one), when two letters pair one contour with two, or when the letters on a pair of closed
contours do not keep their cyclic order (both contours taken counter-clockwise).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

from ...errors import GeometryError
from ...model import Hint
from ..contours import roles
from ..geometry import signed_area

__all__ = ["HintError", "Snap", "SNAP_REACH", "snap_point", "insert_hints", "Link", "segment_links", "check_links",
           "forced_contour_pairs", "vertex_links"]

Array = NDArray[np.float64]

SNAP_REACH = 0.02
"""How far from an outline a hint may be: a fraction of its key's bounding-box diagonal."""


class HintError(GeometryError):
    """A hint that cannot be honoured; ``letters`` names the hints to blame (the caller adds where)."""

    def __init__(self, letters: tuple[str, ...], message: str) -> None:
        super().__init__(message)
        self.letters = letters
        self.message = message


@dataclass(frozen=True, slots=True)
class Snap:
    """Where a point lands on a key: on contour ``contour``'s edge ``edge`` (from vertex ``edge`` to the
    next) at ``fraction`` in [0, 1] of it, ``distance`` away (key units); ``at`` the point ``(2,)``."""

    contour: int
    edge: int
    fraction: float
    distance: float
    at: tuple[float, float]


def snap_point(contours: Sequence[Array], closed: Sequence[bool], point: Sequence[float]) -> Snap:
    """The nearest point to ``point (2,)`` on any of ``contours`` (each ``(N_i, 2)``; a closed one's last
    vertex joins its first). Ties go to the first contour, then the first edge."""
    p = np.asarray(point, dtype=np.float64)
    best: Snap | None = None
    for c, points in enumerate(contours):
        start = np.asarray(points, dtype=np.float64)
        end = np.roll(start, -1, axis=0)
        if not closed[c]:
            start, end = start[:-1], end[:-1]
        edge = end - start  # (E, 2)
        length2 = (edge * edge).sum(axis=1)
        with np.errstate(divide="ignore", invalid="ignore"):
            fraction = np.where(length2 > 0, ((p - start) * edge).sum(axis=1) / length2, 0.0)
        fraction = np.clip(fraction, 0.0, 1.0)
        foot = start + fraction[:, None] * edge
        distance = np.hypot(*(foot - p).T)
        k = int(np.argmin(distance))
        if best is None or distance[k] < best.distance:
            best = Snap(c, k, float(fraction[k]), float(distance[k]), (float(foot[k, 0]), float(foot[k, 1])))
    assert best is not None
    return best


def insert_hints(contours: Sequence[Array], closed: Sequence[bool], snaps: dict[str, Snap]
                 ) -> tuple[list[Array], tuple[Hint, ...], list[NDArray[np.intp]]]:
    """The contours with a vertex inserted where a hint falls inside an edge, the hints on their vertices,
    and for each contour where its old vertices went ``(N_i,)``.

    A hint within a billionth of the key's size of a vertex takes that vertex. Two letters on one
    point are a :class:`HintError`.
    """
    every = np.concatenate([np.asarray(c, dtype=np.float64) for c in contours])
    size = float(np.hypot(*np.ptp(every, axis=0))) or 1.0
    near = 1e-9 * size
    out, moved, hints = [], [], []
    for c, points in enumerate(contours):
        points = np.asarray(points, dtype=np.float64)
        n = len(points)
        # per edge, the new vertices in order along it: (fraction, letter)
        inserts: dict[int, list[tuple[float, str]]] = {}
        on_vertex: dict[str, int] = {}
        for letter, snap in snaps.items():
            if snap.contour != c:
                continue
            start, end = points[snap.edge], points[(snap.edge + 1) % n]
            at = np.array(snap.at)
            if np.hypot(*(at - start)) <= near:
                on_vertex[letter] = snap.edge
            elif np.hypot(*(at - end)) <= near:
                on_vertex[letter] = (snap.edge + 1) % n
            else:
                inserts.setdefault(snap.edge, []).append((snap.fraction, letter))
        new_points: list[Array] = []
        where = np.empty(n, dtype=np.intp)
        placed: dict[str, int] = {}
        for v in range(n):
            where[v] = len(new_points)
            new_points.append(points[v])
            for fraction, letter in sorted(inserts.get(v, [])):
                placed[letter] = len(new_points)
                new_points.append(np.array(snaps[letter].at))
        placed.update({letter: int(where[v]) for letter, v in on_vertex.items()})
        seen: dict[tuple[float, float], str] = {}
        for letter in sorted(placed):
            spot = tuple(float(v) for v in new_points[placed[letter]])
            if spot in seen:
                raise HintError((seen[spot], letter), f"expected each hint on its own point, found "
                                                      f"{seen[spot]} and {letter} on one point")
            seen[spot] = letter  # type: ignore[index]
            hints.append(Hint(letter, c, placed[letter]))
        array = np.array(new_points)
        array.flags.writeable = False
        out.append(array)
        moved.append(where)
    return out, tuple(sorted(hints, key=lambda h: h.letter)), moved


@dataclass(frozen=True, slots=True)
class Link:
    """A letter both keys carry: contour and vertex in the first key, contour and vertex in the second."""

    letter: str
    a: tuple[int, int]
    b: tuple[int, int]


def segment_links(first: Sequence[Hint], second: Sequence[Hint]) -> list[Link]:
    """The letters both keys carry, in alphabetical order."""
    later = {h.letter: h for h in second}
    return [Link(h.letter, (h.contour, h.vertex), (later[h.letter].contour, later[h.letter].vertex))
            for h in sorted(first, key=lambda h: h.letter) if h.letter in later]


def check_links(a: Sequence[Array], a_closed: Sequence[bool], b: Sequence[Array], b_closed: Sequence[bool],
                links: Sequence[Link]) -> None:
    """Refuse links that cannot all be honoured (see the module's docstring): a :class:`HintError`."""
    role_a, role_b = roles(a, a_closed), roles(b, b_closed)
    partner: dict[int, tuple[int, str]] = {}
    back: dict[int, tuple[int, str]] = {}
    for link in links:
        (ca, _), (cb, _) = link.a, link.b
        if role_a[ca] != role_b[cb]:
            raise HintError((link.letter,), f"expected hint {link.letter} to pair like contours, found "
                                            f"{_role(role_a[ca])} with {_role(role_b[cb])}")
        if ca in partner and partner[ca][0] != cb:
            raise HintError((partner[ca][1], link.letter),
                            f"expected hints {partner[ca][1]} and {link.letter}, on one contour of the first key, "
                            f"on one contour of the next, found them on two")
        if cb in back and back[cb][0] != ca:
            raise HintError((back[cb][1], link.letter),
                            f"expected hints {back[cb][1]} and {link.letter}, on one contour of the next key, "
                            f"on one contour of the first, found them on two")
        partner[ca], back[cb] = (cb, link.letter), (ca, link.letter)
    for ca, (cb, _) in partner.items():
        on = [link for link in links if link.a[0] == ca]
        if len(on) < 2:
            continue
        if role_a[ca] == "open":
            order_a = sorted(on, key=lambda link: link.a[1])
            forward = [link.letter for link in sorted(on, key=lambda link: link.b[1])]
            if [link.letter for link in order_a] not in (forward, forward[::-1]):
                x, y = _first_misplaced([link.letter for link in order_a], forward)
                raise HintError((x, y), f"expected hints {x} and {y} in the same order along both keys' "
                                        f"strokes, found them swapped")
            continue
        sequence_a = _ccw_order(a[ca], [(link.letter, link.a[1]) for link in on])
        sequence_b = _ccw_order(b[cb], [(link.letter, link.b[1]) for link in on])
        turn = sequence_b.index(sequence_a[0])
        sequence_b = sequence_b[turn:] + sequence_b[:turn]
        if sequence_a != sequence_b:
            x, y = _first_misplaced(sequence_a, sequence_b)
            raise HintError((x, y), f"expected hints {x} and {y} in the same cyclic order on both keys' "
                                    f"outlines (counter-clockwise), found them swapped")


def forced_contour_pairs(links: Sequence[Link]) -> list[tuple[int, int]]:
    """The contour pairs ``(i, j)`` the links make partners, each once."""
    return sorted({(link.a[0], link.b[0]) for link in links})


def vertex_links(links: Sequence[Link], pair: tuple[int, int]) -> list[tuple[int, int]]:
    """The hinted vertex pairs ``(i, j)`` of the contour pair ``pair``."""
    return [(link.a[1], link.b[1]) for link in links if (link.a[0], link.b[0]) == pair]


def _role(role: str) -> str:
    return {"outer": "an outer contour", "hole": "a hole", "open": "an open stroke"}[role]


def _ccw_order(points: Array, hinted: list[tuple[str, int]]) -> list[str]:
    """Letters in the order a counter-clockwise walk of ``points (N, 2)`` from vertex 0 meets them."""
    clockwise = signed_area(np.asarray(points)) < 0
    order = sorted(hinted, key=lambda h: h[1], reverse=bool(clockwise))
    return [letter for letter, _ in order]


def _first_misplaced(one: list[str], other: list[str]) -> tuple[str, str]:
    """Two letters whose order differs between ``one`` and ``other`` (the same letters)."""
    rank = {letter: k for k, letter in enumerate(other)}
    for k in range(len(one) - 1):
        for q in range(k + 1, len(one)):
            if rank[one[k]] > rank[one[q]]:
                return one[k], one[q]
    return one[0], one[-1]
