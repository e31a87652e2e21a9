"""Cubic Bézier paths read back from written Lottie and animated SVG files and played as a player does, written
independently of the exporter: a path's vertices and tangents move straight between keyframes through the
span's cubic-bezier timing (bisection), each span is drawn from the closed form of the cubic, and the
distance to the exact in-between polyline is shapely's discrete Hausdorff distance over densified lines.
"""

from __future__ import annotations

import re

import numpy as np
import shapely

_POINTS = 48  # points of each drawn cubic, at least
_STEP = 2.0
"""Pixels at most between a drawn cubic's points (by its control polygon's length, which bounds the cubic's): the
drawing strays from the cubic by at most the sagitta of such a chord (0.01 px on a 50 px radius), so the
measure is of the cubic, not of a coarse drawing of a long one."""
_DENSIFY = 0.1  # shapely splits each segment into 10 for the Hausdorff distance


def timing(x: float, handles: tuple[float, ...]) -> float:
    """CSS ``cubic-bezier(x1, y1, x2, y2)`` at ``x``: y(u) where x(u) = x, u by bisection."""
    x1, y1, x2, y2 = handles

    def curve(u: float, p1: float, p2: float) -> float:
        return 3 * (1 - u) ** 2 * u * p1 + 3 * (1 - u) * u ** 2 * p2 + u ** 3

    low, high = 0.0, 1.0
    for _ in range(60):
        mid = (low + high) / 2
        low, high = (mid, high) if curve(mid, x1, x2) < x else (low, mid)
    return curve(low, y1, y2)


def cubic(p0: np.ndarray, p1: np.ndarray, p2: np.ndarray, p3: np.ndarray, count: int = _POINTS) -> np.ndarray:
    """The cubic Bézier through control points ``(2,)`` each at ``count`` even parameters, or more where its control
    polygon is longer than ``count`` steps of :data:`_STEP` pixels: ``(count', 2)``."""
    polygon = float(np.linalg.norm(np.diff(np.array([p0, p1, p2, p3], dtype=np.float64), axis=0), axis=1).sum())
    count = max(count, int(np.ceil(polygon / _STEP)) + 1) if np.isfinite(polygon) else count
    u = np.linspace(0.0, 1.0, count)[:, None]
    return (1 - u) ** 3 * p0 + 3 * (1 - u) ** 2 * u * p1 + 3 * (1 - u) * u ** 2 * p2 + u ** 3 * p3


def drawn(vertices: np.ndarray, ins: np.ndarray, outs: np.ndarray, closed: bool) -> np.ndarray:
    """The points a Lottie path (``v``, ``i``, ``o`` as ``(M, 2)``; tangents relative to their vertex) draws:
    ``(P, 2)``, one cubic per span."""
    count = len(vertices)
    spans = [(k, k + 1) for k in range(count - 1)] + ([(count - 1, 0)] if closed and count > 1 else [])
    if not spans:
        return vertices.copy()
    return np.concatenate([cubic(vertices[a], vertices[a] + outs[a], vertices[b] + ins[b], vertices[b])
                           for a, b in spans])


def lottie_path_at(prop: dict, frame: float) -> tuple[np.ndarray, np.ndarray, np.ndarray, bool]:
    """A Lottie path property (``ks``) at ``frame``: vertices, in and out tangents ``(M, 2)`` and closed, each
    moved straight between keyframes through the span's ``o``/``i`` timing, held before the first and after
    the last."""
    if prop["a"] == 0:
        value = prop["k"]
        return (np.array(value["v"], float), np.array(value["i"], float), np.array(value["o"], float),
                bool(value["c"]))
    values = [k["s"][0] for k in prop["k"]]
    arrays = [np.array([[v[name] for v in values]], float)[0] for name in ("v", "i", "o")]  # (K, M, 2) each
    index, s = _span_at(prop["k"], frame)
    v, i, o = (_between(a, index, s) for a in arrays)
    return v, i, o, bool(values[0]["c"])


def _span_at(keys: list[dict], frame: float) -> tuple[int, float]:
    """Where ``frame`` falls among Lottie keyframes ``keys``: the keyframe before it and the share of the way to the
    next through the span's ``o``/``i`` timing (0 before the first keyframe; at the last, share 0 from it)."""
    times = [k["t"] for k in keys]
    if frame <= times[0] or frame >= times[-1]:
        return (0 if frame <= times[0] else len(keys) - 1), 0.0
    index = int(np.searchsorted(times, frame, side="right")) - 1
    key = keys[index]
    return index, timing((frame - times[index]) / (times[index + 1] - times[index]),
                         (key["o"]["x"][0], key["o"]["y"][0], key["i"]["x"][0], key["i"]["y"][0]))


def _between(values: np.ndarray, index: int, s: float) -> np.ndarray:
    """``values (K, …)`` the share ``s`` of the way from keyframe ``index`` to the next (itself when ``s`` is 0)."""
    return values[index] if s == 0.0 else values[index] + s * (values[index + 1] - values[index])


def svg_path_points(d: str) -> list[tuple[np.ndarray, bool]]:
    """The subpaths an SVG ``d`` of ``M``, ``L``, ``C`` and ``Z`` (``l``, ``c`` relative to the pen; ``z``) draws:
    ``[(points (P, 2), closed)]``."""
    out: list[tuple[np.ndarray, bool]] = []
    for sub in re.findall(r"M[^M]*", d):
        tokens = re.findall(r"[MLCZlcz]|-?(?:\d+\.?\d*|\.\d+)(?:e-?\d+)?", sub)
        pen, start, pieces, closed = np.zeros(2), np.zeros(2), [], False
        command, numbers = "", []
        for token in tokens + ["M"]:
            if token in "MLCZlcz":
                if command == "M":
                    pen = start = np.array(numbers[:2])
                    pieces.append(pen[None])
                elif command in "Ll":
                    for k in range(0, len(numbers), 2):
                        end = np.array(numbers[k:k + 2]) + (pen if command == "l" else 0.0)
                        pieces.append(np.stack([pen, end]))
                        pen = end
                elif command in "Cc":
                    for k in range(0, len(numbers), 6):
                        c = np.array(numbers[k:k + 6]).reshape(3, 2) + (pen if command == "c" else 0.0)
                        pieces.append(cubic(pen, c[0], c[1], c[2]))
                        pen = c[2]
                elif command in "Zz":
                    pieces.append(np.stack([pen, start]))
                    closed = True
                command, numbers = token, []
            else:
                numbers.append(float(token))
        out.append((np.concatenate(pieces), closed))
    return out


def distance(points: np.ndarray, exact: np.ndarray, closed: bool) -> float:
    """The Hausdorff distance (both ways, shapely's discrete one over densified lines) between drawn points
    ``(P, 2)`` (a closed path's back at its start) and the exact polyline ``(L, 2)``, closed or not."""
    exact = np.concatenate([exact, exact[:1]]) if closed else exact
    lines = [shapely.Point(p[0]) if len(p) == 1 else shapely.LineString(p) for p in (points, exact)]
    return float(shapely.hausdorff_distance(*lines, densify=_DENSIFY))


def lottie_error(prop: dict, frame: float, exact: np.ndarray) -> float:
    """How far the Lottie path ``prop`` played at ``frame`` is from the exact polyline ``(L, 2)``."""
    v, i, o, closed = lottie_path_at(prop, frame)
    return distance(drawn(v, i, o, closed), exact, closed)


def lottie_value_at(prop: dict, frame: float) -> np.ndarray:
    """A keyed (or still) Lottie property of numbers (a position, a scale) at ``frame``, moved straight between
    keyframes through the span's ``o``/``i`` timing, held before the first and after the last."""
    if prop["a"] == 0:
        return np.atleast_1d(np.array(prop["k"], float))
    index, s = _span_at(prop["k"], frame)
    return _between(np.array([k["s"] for k in prop["k"]], float), index, s)


def lottie_placed(transform: dict, frame: float, points: np.ndarray) -> np.ndarray:
    """``points (P, 2)`` placed by a Lottie group's transform (``tr``: anchor, position, scale in percent; no
    turn) at ``frame``: ``position + scale · (points - anchor)``."""
    assert transform["r"] == {"a": 0, "k": 0}
    anchor = lottie_value_at(transform["a"], frame)[:2]
    position = lottie_value_at(transform["p"], frame)[:2]
    scale = lottie_value_at(transform["s"], frame)[:2] / 100.0
    return position + scale * (points - anchor)
