"""Lottie property values at a frame, as lottie-web computes them: static values and keyframes, their
Bézier easing (``o``/``i`` handles, one per dimension or one for all), hold keyframes (``h``) and motion
paths (``to``/``ti``: the value moves along the cubic at the eased share of its length).

Keyframe times are frames of the property's composition. Before the first keyframe the first value
holds, from the last keyframe on the last.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from ..core.timing.easing import CubicBezier

__all__ = ["Unreadable", "Malformed", "Keyframe", "Prop", "ShapeProp", "PathValue", "read_path", "number_list",
           "ease_text", "sub_ease"]

Array = NDArray[np.float64]
_MOTION_STEPS = 150  # lottie-web measures a motion path on 150 chords


class Unreadable(Exception):
    """A feature the reader does not draw (an expression, a text layer...): the message says which."""


class Malformed(Exception):
    """Data that is not Lottie where it is read: the message says what was expected."""


def number_list(value: Any, what: str) -> Array:
    """``value`` (a number or a list of numbers) as a finite float64 array ``(D,)``."""
    try:
        array = np.atleast_1d(np.asarray(value, dtype=np.float64)).ravel()
    except (TypeError, ValueError):
        raise Malformed(f"expected {what} as numbers, found {str(value)[:40]!r}") from None
    if not np.all(np.isfinite(array)) or np.any(np.abs(array) > 1e9):
        raise Malformed(f"expected {what} as finite numbers within ±1e9, found {str(value)[:40]!r}")
    return array


def _handle(side: Any, axis: str) -> Array:
    if not isinstance(side, dict) or axis not in side:
        raise Malformed(f"expected an easing handle {{x, y}}, found {str(side)[:40]!r}")
    return number_list(side[axis], "an easing handle")


@dataclass(frozen=True)
class Keyframe:
    """One keyframe: its frame ``t``, its value ``start``, the value it moves to (``end``: its ``e`` or
    the next keyframe's ``s``), its easing handles per dimension ``(D, 4)`` (x1, y1, x2, y2), whether it
    holds, and its motion path's tangents (``None``: straight)."""

    t: float
    start: Any
    end: Any
    handles: Array | None
    hold: bool
    tangents: tuple[Array, Array] | None = None


def _expression(raw: dict[str, Any]) -> None:
    if isinstance(raw.get("x"), str) and raw["x"].strip():
        raise Unreadable("an expression")


def _keyframes(items: list[Any], read: Any) -> list[Keyframe]:
    """Keyframes of ``items`` with values made by ``read``."""
    if not all(isinstance(k, dict) and "t" in k for k in items):
        raise Malformed("expected keyframes {t, s, ...}")
    out: list[Keyframe] = []
    for n, item in enumerate(items):
        t = float(number_list(item["t"], "a keyframe time")[0])
        if out and t < out[-1].t:
            raise Malformed(f"expected keyframe times in order, found {t:g} after {out[-1].t:g}")
        start = read(item["s"]) if "s" in item else None
        end = read(item["e"]) if "e" in item else None
        hold = bool(item.get("h", 0))
        handles = None
        if not hold and n < len(items) - 1 and "o" in item and "i" in item:
            x1, y1 = _handle(item["o"], "x"), _handle(item["o"], "y")
            x2, y2 = _handle(item["i"], "x"), _handle(item["i"], "y")
            size = max(len(x1), len(y1), len(x2), len(y2))
            handles = np.stack([np.resize(v, size) for v in (x1, y1, x2, y2)], axis=1)
        tangents = None
        if "to" in item and "ti" in item and item["to"] is not None and item["ti"] is not None:
            out_t, in_t = number_list(item["to"], "a motion tangent"), number_list(item["ti"], "a motion tangent")
            if np.any(out_t != 0) or np.any(in_t != 0):
                tangents = (out_t, in_t)
        out.append(Keyframe(t, start, end, handles, hold, tangents))
    fixed: list[Keyframe] = []
    for n, key in enumerate(out):
        start = key.start if key.start is not None else (out[n - 1].end if n else None)
        if start is None:
            raise Malformed("expected a value (s) on the first keyframe")
        end = key.end
        if end is None and n + 1 < len(out):
            end = out[n + 1].start if out[n + 1].start is not None else start
        fixed.append(Keyframe(key.t, start, end if end is not None else start, key.handles, key.hold, key.tangents))
    return fixed


def _eased(handles: Array | None, u: float) -> Array:
    """The eased share of each dimension at time share ``u`` in [0, 1]: ``(D,)`` (one for all when ``(1,)``)."""
    if handles is None:
        return np.array([u])
    return np.array([_bezier_ease(min(max(float(x1), 0.0), 1.0), float(y1), min(max(float(x2), 0.0), 1.0),
                                  float(y2), u) for x1, y1, x2, y2 in handles])


def _bezier_ease(x1: float, y1: float, x2: float, y2: float, u: float) -> float:
    """CSS ``cubic-bezier(x1, y1, x2, y2)`` at ``u`` in [0, 1]: ``y(s)`` where ``x(s) = u``, s found by Newton's
    method from ``s = u``, then by bisection if it did not settle (to 1e-13 in x), as the scene's easing does."""
    if u <= 0.0 or u >= 1.0:
        return 0.0 if u <= 0.0 else 1.0

    def cubic(s: float, p1: float, p2: float) -> float:
        r = 1.0 - s
        return 3.0 * r * r * s * p1 + 3.0 * r * s * s * p2 + s * s * s

    s = u
    for _ in range(8):
        r = 1.0 - s
        slope = 3.0 * r * r * x1 + 6.0 * r * s * (x2 - x1) + 3.0 * s * s * (1.0 - x2)
        if abs(slope) <= 1e-6:
            break
        s = min(max(s - (cubic(s, x1, x2) - u) / slope, 0.0), 1.0)
    if abs(cubic(s, x1, x2) - u) > 1e-13:
        low, high = 0.0, 1.0
        for _ in range(60):
            middle = 0.5 * (low + high)
            low, high = (middle, high) if cubic(middle, x1, x2) < u else (low, middle)
        s = 0.5 * (low + high)
    return cubic(s, y1, y2)


class Prop:
    """A numeric property (``{"a": 0|1, "k": ...}``): :meth:`at` its value ``(D,)`` at a frame."""

    def __init__(self, raw: Any, what: str, default: Any = None) -> None:
        if raw is None and default is not None:
            raw = {"a": 0, "k": default}
        if not isinstance(raw, dict) or "k" not in raw:
            raise Malformed(f"expected {what} as a property {{a, k}}, found {str(raw)[:40]!r}")
        _expression(raw)
        self.what = what
        value = raw["k"]
        if isinstance(value, list) and value and isinstance(value[0], dict):
            self.keys: list[Keyframe] | None = _keyframes(value, lambda v: number_list(v, what))
            if len(self.keys) == 1:
                self.value, self.keys = self.keys[0].start, None
        else:
            self.keys, self.value = None, number_list(value, what)

    @property
    def animated(self) -> bool:
        return self.keys is not None

    def times(self) -> list[float]:
        """The keyframes' frames (none when static)."""
        return [k.t for k in self.keys] if self.keys else []

    def at(self, frame: float) -> Array:
        """The value at ``frame``: ``(D,)``."""
        if self.keys is None:
            return self.value
        key, u = _segment(self.keys, frame)
        if u is None:
            return key.start
        a, b = key.start, key.end
        if len(a) != len(b):
            raise Malformed(f"expected keyframes of {self.what} of one size, found {len(a)} and {len(b)} values")
        if key.tangents is not None and len(a) in (2, 3):
            share = float(_eased(key.handles[:1] if key.handles is not None else None, u)[0])
            return _along(a, b, key.tangents, share)
        share = _eased(key.handles, u)
        if len(share) > 1:
            share = np.resize(share, len(a))
        return a + (b - a) * share


def _segment(keys: list[Keyframe], frame: float) -> tuple[Keyframe, float | None]:
    """The keyframe whose span holds ``frame`` and the share of the span (``None``: its value holds)."""
    if frame < keys[0].t:
        return keys[0], None
    if frame >= keys[-1].t:
        last = keys[-1]
        return Keyframe(last.t, last.start, last.start, None, True), None
    index = max(i for i in range(len(keys) - 1) if keys[i].t <= frame)
    key, after = keys[index], keys[index + 1]
    if key.hold or after.t <= key.t:
        return key, None
    return key, (frame - key.t) / (after.t - key.t)


def _along(a: Array, b: Array, tangents: tuple[Array, Array], share: float) -> Array:
    """The point at ``share`` of the length of the cubic from ``a`` to ``b`` (tangents relative), measured on
    :data:`_MOTION_STEPS` chords as lottie-web does."""
    out_t, in_t = (np.resize(t, len(a)) for t in tangents)
    s = np.linspace(0.0, 1.0, _MOTION_STEPS + 1)[:, None]
    nodes = (a, a + out_t, b + in_t, b)
    points = ((1 - s) ** 3 * nodes[0] + 3 * (1 - s) ** 2 * s * nodes[1] + 3 * (1 - s) * s ** 2 * nodes[2]
              + s ** 3 * nodes[3])
    lengths = np.concatenate([[0.0], np.cumsum(np.linalg.norm(np.diff(points, axis=0), axis=1))])
    if lengths[-1] <= 0:
        return a.copy()
    target = share * lengths[-1]
    if target <= 0:
        return points[0] + (points[1] - points[0]) * (target / max(lengths[1], 1e-300))
    if target >= lengths[-1]:
        return points[-1] + (points[-1] - points[-2]) * ((target - lengths[-1]) / max(lengths[-1] - lengths[-2], 1e-300))
    j = int(np.searchsorted(lengths, target, side="right")) - 1
    j = min(j, _MOTION_STEPS - 1)
    part = (target - lengths[j]) / max(lengths[j + 1] - lengths[j], 1e-300)
    return points[j] + (points[j + 1] - points[j]) * part


@dataclass(frozen=True)
class PathValue:
    """A Lottie path: vertices ``v (N, 2)``, in and out tangents relative to them ``(N, 2)``, closed."""

    v: Array
    i: Array
    o: Array
    closed: bool

    def lerp(self, other: PathValue, share: float) -> PathValue:
        return PathValue(self.v + (other.v - self.v) * share, self.i + (other.i - self.i) * share,
                         self.o + (other.o - self.o) * share, self.closed)


def read_path(value: Any) -> PathValue:
    """A path value (``{"v", "i", "o", "c"}``, or a list holding one, as keyframes write it)."""
    if isinstance(value, list) and len(value) == 1:
        value = value[0]
    if not isinstance(value, dict) or "v" not in value:
        raise Malformed(f"expected a path {{v, i, o, c}}, found {str(value)[:40]!r}")
    arrays = []
    for name in ("v", "i", "o"):
        raw = value.get(name, [[0, 0]] * len(value["v"]) if isinstance(value["v"], list) else None)
        flat = number_list(raw if raw != [] else np.zeros((0, 2)), "path points")
        if len(flat) % 2:
            flat = number_list([p[:2] for p in raw], "path points")
        arrays.append(flat.reshape(-1, 2))
    v, i, o = arrays
    if not len(v) == len(i) == len(o):
        raise Malformed(f"expected as many tangents as vertices, found {len(v)} vertices, {len(i)} and {len(o)} tangents")
    return PathValue(v, i, o, bool(value.get("c", False)))


class ShapeProp:
    """A path property (``ks`` of a ``sh`` item): :meth:`at` its :class:`PathValue` at a frame."""

    def __init__(self, raw: Any) -> None:
        if not isinstance(raw, dict) or "k" not in raw:
            raise Malformed(f"expected a path property {{a, k}}, found {str(raw)[:40]!r}")
        _expression(raw)
        value = raw["k"]
        if isinstance(value, list) and value and isinstance(value[0], dict) and "t" in value[0]:
            self.keys: list[Keyframe] | None = _keyframes(value, read_path)
            if len(self.keys) == 1:
                self.value, self.keys = self.keys[0].start, None
        else:
            self.keys, self.value = None, read_path(value)

    @property
    def animated(self) -> bool:
        return self.keys is not None

    def at(self, frame: float) -> PathValue:
        if self.keys is None:
            return self.value
        key, u = _segment(self.keys, frame)
        if u is None:
            return key.start
        share = float(_eased(key.handles[:1] if key.handles is not None else None, u)[0])
        if len(key.start.v) != len(key.end.v):
            return key.start if share < 1 else key.end
        return key.start.lerp(key.end, share)

    def continuous(self) -> bool:
        """Whether each keyframe's end value is the next one's start (no jump at a keyframe)."""
        if not self.keys:
            return True
        for key, after in zip(self.keys, self.keys[1:]):
            a, b = key.end, after.start
            if key.hold:
                continue
            if a.v.shape != b.v.shape or not (np.allclose(a.v, b.v) and np.allclose(a.i, b.i)
                                               and np.allclose(a.o, b.o)):
                return False
        return True


def ease_text(handles: Array | None, hold: bool) -> str | None:
    """A scene's ``ease`` for a keyframe's span: ``hold``, ``linear`` or ``cubic-bezier(...)``; ``None`` when
    the dimensions ease differently or the handles are no CSS curve."""
    if hold:
        return "hold"
    if handles is None:
        return "linear"
    if not np.allclose(handles, handles[0]):
        return None
    x1, y1, x2, y2 = (float(v) for v in handles[0])
    x1, x2 = min(max(x1, 0.0), 1.0), min(max(x2, 0.0), 1.0)
    if max(abs(y1), abs(y2)) > 1e3:
        return None
    if math.isclose(x1, y1, abs_tol=1e-12) and math.isclose(x2, y2, abs_tol=1e-12):
        return "linear"
    return f"cubic-bezier({x1!r}, {y1!r}, {x2!r}, {y2!r})"


def sub_ease(text: str, u0: float, u1: float) -> str | None:
    """The ``ease`` of the part ``[u0, u1]`` of a span eased by ``text`` (so that the part, from its own
    values at ``u0`` and ``u1``, moves as the whole did); ``None`` when no scene ease says it."""
    if (u0, u1) == (0.0, 1.0) or text in ("linear", "hold"):
        return text
    from ..core.timing.easing import parse_easing

    curve = parse_easing(text)
    assert isinstance(curve, CubicBezier)
    s0, s1 = (float(curve.solve(np.array([u]))[0]) for u in (u0, u1))
    nodes = np.array([[0.0, 0.0], [curve.x1, curve.y1], [curve.x2, curve.y2], [1.0, 1.0]])
    part = _sub_bezier(nodes, s0, s1)
    dx, dy = part[3] - part[0]
    if dx <= 1e-12 or abs(dy) <= 1e-12:
        return None
    x1, y1 = (part[1] - part[0]) / (dx, dy)
    x2, y2 = (part[2] - part[0]) / (dx, dy)
    if not (-1e-9 <= x1 <= 1 + 1e-9 and -1e-9 <= x2 <= 1 + 1e-9) or max(abs(y1), abs(y2)) > 1e3:
        return None
    return ease_text(np.array([[x1, y1, x2, y2]]), False)


def _sub_bezier(nodes: Array, s0: float, s1: float) -> Array:
    """The control points ``(4, 2)`` of the part ``[s0, s1]`` of the cubic ``nodes (4, 2)``."""
    def split(points: Array, s: float) -> tuple[Array, Array]:
        left, right, level = [points[0]], [points[-1]], points
        while len(level) > 1:
            level = (1 - s) * level[:-1] + s * level[1:]
            left.append(level[0])
            right.append(level[-1])
        return np.array(left), np.array(right[::-1])

    _, tail = split(nodes, s0)
    if s1 >= 1.0:
        return tail
    inner = (s1 - s0) / (1.0 - s0) if s0 < 1.0 else 1.0
    head, _ = split(tail, inner)
    return head
