"""Lottie geometry: transforms (``ks`` of a layer, ``tr`` of a group), the path items (``sh``, ``rc``,
``el``) as cubic Bézier paths, and their flattening into vertex lists that keep the designer's vertex
correspondence: each cubic segment is cut into the same number of equal parameter steps in every key,
so vertex i of one key goes to vertex i of the next, and the in-between of two flattened keys is the
flattening of the in-between of their curves (a cubic is linear in its control points).
"""

from __future__ import annotations

import math
from typing import Any, Sequence

import numpy as np

from .lottie_props import Array, Malformed, PathValue, Prop, ShapeProp, Unreadable

__all__ = ["Transform", "PathItem", "segment_counts", "sample_path", "placed", "check_structure", "ROUND_CORNER"]

ROUND_CORNER = 0.5519150244935105707435627
"""The tangent length of a quarter circle of radius 1 that lottie-web draws ellipses and rounded corners with."""


class Transform:
    """A layer's or group's transform: anchor ``a``, position ``p`` (or ``px``/``py`` apart), scale ``s``
    (percent), rotation ``r`` (degrees, clockwise on screen), opacity ``o`` (percent); skew refused when
    not zero. :meth:`matrix` maps its content into its parent (y down): ``p + R(r)·S·(x − a)``."""

    def __init__(self, raw: Any) -> None:
        raw = raw if isinstance(raw, dict) else {}
        for name in ("sk",):
            if name in raw:
                skew = Prop(raw[name], "skew")
                if skew.animated or np.any(skew.value != 0):
                    raise Unreadable("a skewed transform")
        if "rx" in raw or "ry" in raw or "or" in raw:
            raise Unreadable("a 3-D transform")
        self.anchor = Prop(raw.get("a"), "an anchor point", [0, 0])
        position = raw.get("p")
        self.split: tuple[Prop, Prop] | None = None
        if isinstance(position, dict) and position.get("s") and "x" in position and "y" in position \
                and not isinstance(position.get("x"), str):
            self.split = (Prop(position["x"], "a position x"), Prop(position["y"], "a position y"))
            self.position = Prop(None, "a position", [0, 0])
        else:
            self.position = Prop(position, "a position", [0, 0])
        self.scale = Prop(raw.get("s"), "a scale", [100, 100])
        self.rotation = Prop(raw.get("r") if "r" in raw else raw.get("rz"), "a rotation", [0])
        self.opacity_prop = Prop(raw.get("o"), "an opacity", [100])
        moving = [self.anchor, self.position, self.scale, self.rotation]
        if self.split:
            moving += list(self.split)
        self.moves = any(p.animated for p in moving)
        self.fades = self.opacity_prop.animated
        self._matrices: dict[float, Array] = {}

    def matrix(self, frame: float) -> Array:
        """The 3 × 3 affine matrix at ``frame`` (read-only)."""
        key = frame if self.moves else 0.0
        found = self._matrices.get(key)
        if found is None:
            found = self._matrices[key] = self._matrix(frame)
            found.flags.writeable = False
        return found

    def _matrix(self, frame: float) -> Array:
        a = self.anchor.at(frame)
        if self.split:
            p = np.array([self.split[0].at(frame)[0], self.split[1].at(frame)[0]])
        else:
            p = self.position.at(frame)
        s = self.scale.at(frame)
        sx, sy = (s[0], s[1] if len(s) > 1 else s[0])
        angle = math.radians(float(self.rotation.at(frame)[0]))
        c, n = math.cos(angle), math.sin(angle)
        linear = np.array([[c, -n], [n, c]]) @ np.diag([sx / 100.0, sy / 100.0])
        out = np.eye(3)
        out[:2, :2] = linear
        out[:2, 2] = np.resize(p, 2) - linear @ np.resize(a, 2)
        return out

    def opacity(self, frame: float) -> float:
        return min(max(float(self.opacity_prop.at(frame)[0]) / 100.0, 0.0), 1.0)


class PathItem:
    """A path item of a group: ``sh`` (a path property), ``rc`` (rectangle) or ``el`` (ellipse), as
    lottie-web draws them; :meth:`at` its :class:`PathValue` at a frame."""

    def __init__(self, raw: dict[str, Any]) -> None:
        self.kind = raw["ty"]
        self.reversed = raw.get("d") == 3
        self.shape: ShapeProp | None = None
        if self.kind == "sh":
            self.shape = ShapeProp(raw.get("ks"))
            self.props: list[Prop] = []
        elif self.kind == "rc":
            self.centre = Prop(raw.get("p"), "a rectangle's position", [0, 0])
            self.size = Prop(raw.get("s"), "a rectangle's size", [0, 0])
            self.round = Prop(raw.get("r"), "a rectangle's roundness", [0])
            self.props = [self.centre, self.size, self.round]
        else:
            self.centre = Prop(raw.get("p"), "an ellipse's position", [0, 0])
            self.size = Prop(raw.get("s"), "an ellipse's size", [0, 0])
            self.props = [self.centre, self.size]

    @property
    def animated(self) -> bool:
        return self.shape.animated if self.shape else any(p.animated for p in self.props)

    def at(self, frame: float) -> PathValue:
        if self.shape is not None:
            return self.shape.at(frame)
        if self.kind == "rc":
            return self._rectangle(frame)
        return self._ellipse(frame)

    def _rectangle(self, frame: float) -> PathValue:
        x, y = np.resize(self.centre.at(frame), 2)
        w, h = np.resize(self.size.at(frame), 2) / 2.0
        rounded = self.round.animated or float(self.round.value[0]) != 0
        r = min(w, h, float(self.round.at(frame)[0]))
        k = r * ROUND_CORNER  # tangent length of a rounded corner
        if not rounded:
            v = np.array([[x + w, y - h], [x + w, y + h], [x - w, y + h], [x - w, y - h]])
            zero = np.zeros_like(v)
            out = PathValue(v, zero, zero.copy(), True)
        else:
            v = np.array([[x + w, y - h + r], [x + w, y + h - r], [x + w - r, y + h], [x - w + r, y + h],
                          [x - w, y + h - r], [x - w, y - h + r], [x - w + r, y - h], [x + w - r, y - h]])
            i = np.array([[0, -k], [0, 0], [k, 0], [0, 0], [0, k], [0, 0], [-k, 0], [0, 0]], dtype=float)
            o = np.array([[0, 0], [0, k], [0, 0], [-k, 0], [0, 0], [0, -k], [0, 0], [k, 0]], dtype=float)
            out = PathValue(v, i, o, True)
        return _reverse(out) if self.reversed else out

    def _ellipse(self, frame: float) -> PathValue:
        x, y = np.resize(self.centre.at(frame), 2)
        a, b = np.resize(self.size.at(frame), 2) / 2.0
        ka, kb = a * ROUND_CORNER, b * ROUND_CORNER
        v = np.array([[x, y - b], [x + a, y], [x, y + b], [x - a, y]])
        i = np.array([[-ka, 0], [0, -kb], [ka, 0], [0, kb]])
        out = PathValue(v, i, -i, True)
        return _reverse(out) if self.reversed else out


def _reverse(path: PathValue) -> PathValue:
    """The same path drawn the other way round, from the same first vertex."""
    order = np.r_[0, np.arange(len(path.v) - 1, 0, -1)]
    return PathValue(path.v[order], path.o[order], path.i[order], path.closed)


def placed(path: PathValue, matrix: Array) -> PathValue:
    """``path`` mapped by the affine ``matrix (3, 3)`` (tangents by its linear part)."""
    linear, offset = matrix[:2, :2], matrix[:2, 2]
    return PathValue(path.v @ linear.T + offset, path.i @ linear.T, path.o @ linear.T, path.closed)


def _segments(path: PathValue) -> Array:
    """The path's cubic segments ``(S, 4, 2)`` (the closing one too when closed)."""
    n = len(path.v)
    ends = range(n if path.closed else n - 1)
    return np.array([[path.v[j], path.v[j] + path.o[j], path.v[(j + 1) % n] + path.i[(j + 1) % n],
                      path.v[(j + 1) % n]] for j in ends]).reshape(-1, 4, 2)


def segment_counts(paths: Sequence[PathValue], tolerance: float, most: int = 4096) -> Array:
    """Equal parameter steps per segment ``(S,)`` so that every one of ``paths`` (one structure, in world
    units) is within ``tolerance`` of its flattening: a cubic cut into n equal steps is within
    ``(3/4)·max|second differences of its control points| / n²`` of its chords, and within the farthest
    inner control point's distance from its chord of that one chord (a straight segment: one step)."""
    counts = np.ones(0, dtype=np.int64)
    for path in paths:
        nodes = _segments(path)
        second = np.maximum(np.linalg.norm(nodes[:, 0] - 2 * nodes[:, 1] + nodes[:, 2], axis=1),
                            np.linalg.norm(nodes[:, 1] - 2 * nodes[:, 2] + nodes[:, 3], axis=1))
        need = np.ceil(np.sqrt(0.75 * second / tolerance) - 1e-9).astype(np.int64)
        need = np.where(_hull_distance(nodes) <= tolerance, 1, np.clip(need, 1, most))
        counts = need if len(counts) == 0 else np.maximum(counts, need)
    return counts


def _hull_distance(nodes: Array) -> Array:
    """The farthest distance of each cubic's inner control points from its chord segment: ``(S,)``."""
    first, last = nodes[:, 0], nodes[:, 3]
    chord = last - first
    length2 = np.einsum("ij,ij->i", chord, chord)
    out = np.zeros(len(nodes))
    for q in (1, 2):
        offset = nodes[:, q] - first
        s = np.clip(np.einsum("ij,ij->i", offset, chord) / np.where(length2 > 0, length2, 1.0), 0.0, 1.0)
        out = np.maximum(out, np.linalg.norm(offset - s[:, None] * chord, axis=1))
    return out


def sample_path(path: PathValue, counts: Array) -> Array:
    """The flattened ``path``: each segment ``j`` at ``counts[j]`` equal parameter steps, ``(M, 2)`` (an open
    path ends on its last vertex)."""
    nodes = _segments(path)
    if len(nodes) == 0:
        return path.v[:1].copy()
    pieces = []
    for segment, n in zip(nodes, counts):
        s = (np.arange(int(n)) / int(n))[:, None]
        pieces.append((1 - s) ** 3 * segment[0] + 3 * (1 - s) ** 2 * s * segment[1]
                      + 3 * (1 - s) * s ** 2 * segment[2] + s ** 3 * segment[3])
    if not path.closed:
        pieces.append(path.v[-1:])
    return np.concatenate(pieces)


def check_structure(paths: Sequence[PathValue]) -> None:
    """Refuse keyframes of one path with different vertex counts or closedness."""
    first = paths[0]
    for other in paths[1:]:
        if len(other.v) != len(first.v) or other.closed != first.closed:
            raise Malformed(f"expected every keyframe of a path to have {len(first.v)} vertices "
                            f"({'closed' if first.closed else 'open'}), found {len(other.v)}")
