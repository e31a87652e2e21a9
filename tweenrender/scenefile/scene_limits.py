"""How much a scene may hold: sizes, times, vertices, keys and shapes, and the correspondence effort of
its keys, each refused before anything is matched or drawn."""

from __future__ import annotations

from ..model import Matching, Shape
from .controls import Fail

__all__ = ["LIMITS", "check_counts", "check_matching_effort"]

LIMITS = {
    "canvas": 16384,       # pixels a side
    "fps": (1, 240),
    "coordinate": 1e9,     # |x|, |y| in world units
    "time": 1e7,           # seconds, the latest a key may be
    # tomllib parses ~2.5 MB/s into ~16x its size in objects: these two bound a refusal to seconds
    "file_bytes": 16 << 20,
    "vertices_total": 1_000_000,  # [x, y] pairs in one file, every key together
    "vertices": 200_000,   # per key
    # keys of different vertex counts m, n are matched in O(mn log n) (distance) or, at worst,
    # O(27 m n²) (sg) steps: these caps keep one segment's correspondence to seconds (about 1.5 s;
    # for sg, 7 s to solve every start here, which its branch and bound spares drawn outlines but
    # may exceed about 2.7 times where nothing can be pruned)
    "match_cells": 25_000_000,    # m·n, cost "distance"
    "match_sg": 100_000_000,      # m·n·max(m, n), cost "sg"
    # every key is a segment to match and every shape a track drawn each frame: 8 000 keys took 6.6 s
    # to the first frame here, 8 000 shapes 1.9 s and 69 MB (100 000 took minutes, or 2 GB)
    "keys": 10_000,        # in the scene, every shape's and drawing's together
    # a key's contours are paired, nested and placed clear of each other: one path of 5 000 small squares
    # renders in about 30 s here, to 1 250 larger ones in about 3 minutes
    "contours": 5_000,     # per key (a drawing's element: one path's subpaths)
    "shapes": 10_000,      # in the scene, drawings' elements included
    # every in-between blends each stop of both keys' gradients: 100 000 stops took minutes a frame
    "gradient_stops": 1_000,  # per gradient (SVG <stop>s, a Lottie gradient's p)
}


def check_counts(shapes: int, keys: int, fail: Fail) -> None:
    """Refuse more shapes or keys than :data:`LIMITS` allows, before they are matched or drawn; ``fail``
    makes the error of a key path and a message."""
    for count, what, where in ((shapes, "shapes", "shape"), (keys, "keys", "shape")):
        if count > LIMITS[what]:
            raise fail(where, f"expected at most {LIMITS[what]} {what} in the scene, found {count}")


def check_matching_effort(shapes: tuple[Shape, ...], matching: Matching, fail: Fail) -> None:
    """Refuse keys of more contours, and key pairs whose correspondence search would run for minutes, than
    :data:`LIMITS` allows."""
    cost = matching.cost
    for i, shape in enumerate(shapes):
        for k, key in enumerate(shape.keys):
            if len(key.contours) > LIMITS["contours"]:
                raise fail(f"shape[{i}].key[{k}].contours",
                           f"expected at most {LIMITS['contours']} contours in a key, found {len(key.contours)}")
        keys = [key for key in shape.keys if key.breakdown is None]  # breakdowns take their segment's matching
        for k in range(1, len(keys)):
            counts_a = [len(c.points) for c in keys[k - 1].contours]
            counts_b = [len(c.points) for c in keys[k].contours]
            m, n = max(counts_a), max(counts_b)
            equal = shape.equal_counts or matching.equal_counts
            hinted = bool(keys[k - 1].hints and keys[k].hints)
            if len(counts_a) == len(counts_b) == 1 and m == n and equal == "drawn" and not hinted:
                continue  # equal counts keep the drawn order: no search
            effort, limit = (m * n * max(m, n), LIMITS["match_sg"]) if cost == "sg" else \
                            (m * n, LIMITS["match_cells"])
            if effort > limit:
                raise fail(f"shape[{i}].key[{k}].points",
                           f"expected keys the {cost!r} correspondence can match in seconds "
                           f"(a size of at most {limit:.0e}), found {m} vertices then {n} "
                           f"(size {effort:.1e}); use fewer vertices, equal counts"
                           + (", or cost = \"distance\"" if cost == "sg" else ""))
