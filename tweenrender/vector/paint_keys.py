"""A run's gradient fill and clip paths as a vector file carries them: sampled at every frame in output
pixels, then picked at keyframes.

A gradient is what the raster draws (:mod:`..raster.gradients`): its geometry placed through its matrix
and the viewport, a linear one as the points where offsets 0 and 1 fall (an affine map keeps a linear
gradient linear), a radial one as a centre, a turned and stretched frame (an ellipse: singular values
of the placed matrix) and a focal point in it. Its stops are resampled to one list for the whole run:
every offset some frame has, as often as a frame repeats it (a hard edge); a stop inserted where a frame
has none takes that frame's colour there, which changes nothing drawn. A plain fill is a gradient of
its one colour, no fill the nearest gradient at alpha 0, a gradient the raster cannot place its plain
colour. Clip paths are each frame's clip regions in pixels.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np
from numpy.typing import NDArray

from .keyframes import greedy_keyframes
from ..core.timing.timeline import ShapeAt
from ..encode.vector_data import ClipPathKeys, GradientKeys, Handles, VectorRun, into_gradient_frame
from ..model import Gradient, Paint
from ..core.view import Viewport, pixel_affine

__all__ = ["GradientSamples", "gradient_samples", "gradient_look", "clip_path_make", "clip_path_keys"]

Array = NDArray[np.float64]
_DIGITS = 9  # offsets equal to this many decimals are one offset
_HALF_STEP = 0.5 / 255.0


@dataclass(frozen=True)
class _Frame:
    """One frame's fill as a gradient: its stops ``[(offset, RGBA (4,) in [0, 1])]`` and, unless it is one
    plain colour (``placed`` None), its geometry and its matrix ``(3, 3)``, gradient space → pixels."""

    stops: list[tuple[float, Array]]
    placed: Array | None = None
    geometry: tuple[float, ...] = ()


@dataclass(frozen=True)
class GradientSamples:
    """A run's gradient at every frame: as :class:`GradientKeys` with ``F`` frames in place of ``P`` keys."""

    kind: str
    spread: str
    offsets: Array
    colours: Array  # (F, S, 4)
    start: Array  # (F, 2)
    end: Array  # (F, 2)
    angle: Array  # (F,) degrees
    ratio: Array  # (F,)
    focal: Array  # (F, 2)
    tolerance: float

    def channels(self) -> Array:
        """``(F, N, 2)`` values for :func:`greedy_keyframes` with tolerance 1: stop colours in 1/255, and the
        geometry in the tolerance's pixels, as each player moves it between keyframes (points on straight
        lines; a Lottie ellipse's turn, axes and highlight length and angle each on its own line)."""
        frames = len(self.colours)
        colour = np.zeros((frames, self.colours.shape[1] * 4, 2))
        colour[:, :, 0] = self.colours.reshape(frames, -1) * 255.0
        points = [self.start, self.end]
        if self.kind == "radial":
            radius = np.linalg.norm(self.end - self.start, axis=1)
            reach = max(float(radius.max()), 1.0)
            length = np.linalg.norm(self.focal, axis=1)
            turn = np.unwrap(np.arctan2(self.focal[:, 1], self.focal[:, 0]))
            scalars = [np.radians(self.angle) * reach,  # the turn of the first axis, at its end
                       radius, self.ratio * reach,  # the two axes
                       length / np.maximum(radius, 1e-12) * reach,  # Lottie's highlight length
                       turn * float(length.max())]  # and angle, at the focal point
            points += [self.focal, *(np.stack([v, np.zeros(frames)], axis=1) for v in scalars)]
        geometry = np.stack(points, axis=1) / self.tolerance
        return np.concatenate([colour, geometry], axis=1)

    def keys(self, picked: NDArray[np.intp]) -> GradientKeys:
        """The gradient at frames ``picked (P,)``."""
        circular = bool(np.all(np.abs(1.0 - self.ratio) * np.linalg.norm(self.end - self.start, axis=1)
                               <= self.tolerance))
        return GradientKeys(self.kind, self.spread, self.offsets, self.colours[picked], self.start[picked],
                            self.end[picked], self.angle[picked], self.ratio[picked], self.focal[picked], circular)


def gradient_look(paint: Paint) -> tuple[str, str] | None:
    """What splits a run where it changes: the kind and spread of the gradient a frame is filled with."""
    gradient = paint.gradient
    return None if gradient is None or paint.fill is None else (gradient.kind, gradient.spread)


def gradient_samples(paints: list[Paint], viewport: Viewport, tolerance: float) -> GradientSamples | None:
    """The gradient of each of ``paints`` (one a frame, one kind and spread) as drawn through ``viewport``;
    ``None`` when none of them fills with a gradient."""
    looks = [gradient_look(p) for p in paints]
    kind, spread = next((look for look in looks if look is not None), (None, None))
    if kind is None:
        return None
    filled = [_frame(p, viewport) for p in paints]
    every = [frame if frame is not None else _clear(filled, f) for f, frame in enumerate(filled)]
    offsets = _common_offsets([frame.stops for frame in every])
    offsets, colours = _refined(offsets, np.stack([_resampled(frame.stops, offsets) for frame in every]))
    geometry = _geometry(every, kind)
    return GradientSamples(kind, spread, offsets, colours, *geometry, tolerance=tolerance)


def _frame(paint: Paint, viewport: Viewport) -> _Frame | None:
    """One frame's fill as the raster paints it; ``None`` where it has none."""
    if paint.fill is None:
        return None
    plain = _Frame([(0.0, np.array(paint.fill, dtype=np.float64) / 255.0)])
    gradient = paint.gradient
    if gradient is None:
        return plain
    stops = [(float(o), np.array(c, dtype=np.float64) / 255.0) for o, c in gradient.stops]
    placed = pixel_affine(gradient, viewport)
    linear = placed[:2, :2]
    if not (np.all(np.isfinite(placed)) and all(np.isfinite(gradient.geometry))) \
            or abs(float(np.linalg.det(linear))) <= 1e-12 * max(float(np.abs(linear).max()), 1e-300) ** 2:
        return plain  # the raster cannot place it: the plain colour
    if _flat(gradient):
        return _Frame([stops[-1]])  # SVG: the last stop's colour over the whole area
    return _Frame(stops, placed, tuple(float(v) for v in gradient.geometry))


def _clear(filled: list[_Frame | None], f: int) -> _Frame:
    """Frame ``f``, which has no fill, as the nearest fill's stops at alpha 0 (one gradient fades in or out)."""
    present = [(abs(i - f), frame) for i, frame in enumerate(filled) if frame is not None]
    near = min(present, key=lambda item: item[0])[1] if present else _Frame([(0.0, np.zeros(4))])
    return _Frame([(o, np.array([*c[:3], 0.0])) for o, c in near.stops])


def _flat(gradient: Gradient) -> bool:
    if gradient.kind == "linear":
        x1, y1, x2, y2 = gradient.geometry
        return (x1, y1) == (x2, y2)
    return gradient.geometry[2] <= 0


def _common_offsets(stop_lists: list[list[tuple[float, Array]]]) -> Array:
    """Every offset some list has, as many times as the list that repeats it most: ``(S,)``, sorted."""
    most: Counter[float] = Counter()
    for stops in stop_lists:
        most |= Counter(round(o, _DIGITS) for o, _ in stops)
    return np.array(sorted(most.elements()), dtype=np.float64)


def _resampled(stops: list[tuple[float, Array]], offsets: Array) -> Array:
    """``stops`` at ``offsets (S,)``: ``(S, 4)``. An offset the stops have keeps their colours (the first
    repeated where ``offsets`` holds it more often); any other takes the colour drawn there."""
    own = np.array([round(o, _DIGITS) for o, _ in stops])
    colours = np.stack([c for _, c in stops])
    out = np.empty((len(offsets), 4))
    index = 0
    while index < len(offsets):
        offset = offsets[index]
        count = int(np.count_nonzero(offsets == offset))
        mine = colours[own == offset]
        if len(mine):
            out[index:index + count] = np.concatenate([np.repeat(mine[:1], count - len(mine), axis=0), mine])
        else:
            out[index:index + count] = [np.interp(offset, own, colours[:, k]) for k in range(4)]
        index += count
    return out


def _refined(offsets: Array, colours: Array) -> tuple[Array, Array]:
    """Stops ``offsets (S,)``, ``colours (F, S, 4)`` with stops added between neighbours whose alpha and colour
    both change, so that a player blending stops premultiplied by alpha (rlottie does) draws what the raster
    draws, blending them straight, within half a 1/255 step. Between stops ``(c0, a0)`` and ``(c1, a1)``
    the two blends differ, premultiplied, by ``s(1 - s)(a1 - a0)(c1 - c0)``, at most a quarter of
    ``|Δa| |Δc|``; ``n`` equal pieces divide that by ``n²``."""
    out_offsets, out_colours = [offsets[:1]], [colours[:, :1]]
    for i in range(len(offsets) - 1):
        a, b = colours[:, i], colours[:, i + 1]  # (F, 4)
        worst = float(np.max(np.abs(b[:, 3] - a[:, 3]) * np.abs(b[:, :3] - a[:, :3]).max(axis=1), initial=0.0))
        pieces = 1 if offsets[i + 1] == offsets[i] else int(np.ceil(np.sqrt(worst / 4.0 / _HALF_STEP)))
        s = np.arange(1, max(pieces, 1) + 1) / max(pieces, 1)  # (n,), the last 1
        out_offsets.append(offsets[i] + s * (offsets[i + 1] - offsets[i]))
        out_colours.append(a[:, None] + s[None, :, None] * (b - a)[:, None])
        out_offsets[-1][-1], out_colours[-1][:, -1] = offsets[i + 1], b
    return np.concatenate(out_offsets), np.concatenate(out_colours, axis=1)


def _geometry(frames: list[_Frame], kind: str) -> tuple[Array, Array, Array, Array, Array]:
    """Per frame ``start``, ``end (F, 2)``, ``angle``, ``ratio (F,)`` and ``focal (F, 2)`` (see
    :class:`GradientKeys`); a plain frame takes the nearest placed frame's (or a unit one)."""
    count = len(frames)
    start, end, focal = np.zeros((count, 2)), np.tile([1.0, 0.0], (count, 1)), np.zeros((count, 2))
    angle, ratio = np.zeros(count), np.ones(count)
    placed = [f for f, frame in enumerate(frames) if frame.placed is not None]
    previous: tuple[float, float, float] | None = None
    for f in placed:
        matrix, geometry = frames[f].placed, frames[f].geometry
        assert matrix is not None
        if kind == "linear":
            start[f], end[f] = _linear(matrix, geometry)
        else:
            start[f], theta, radii, focal[f] = _radial(matrix, geometry, previous)
            previous = (theta, *radii)
            angle[f], ratio[f] = np.degrees(theta), radii[1] / radii[0]
            end[f] = start[f] + radii[0] * np.array([np.cos(theta), np.sin(theta)])
    for f in range(count):
        if frames[f].placed is None and placed:
            near = min(placed, key=lambda i: abs(i - f))
            for values in (start, end, angle, ratio, focal):
                values[f] = values[near]
    return start, end, angle, ratio, focal


def _linear(placed: Array, geometry: tuple[float, ...]) -> tuple[Array, Array]:
    """A linear gradient's points at offsets 0 and 1 in pixels: the offset at a pixel ``x`` is
    ``(x - start)·(end - start) / |end - start|²``, as the placed gradient's."""
    x1, y1, x2, y2 = geometry
    d = np.array([x2 - x1, y2 - y1])
    inverse = np.linalg.inv(placed[:2, :2])
    g = inverse.T @ d / float(d @ d)  # the offset's gradient in pixel space: (2,)
    start = placed[:2, :2] @ np.array([x1, y1]) + placed[:2, 2]
    return start, start + g / float(g @ g)


def _radial(placed: Array, geometry: tuple[float, ...], previous: tuple[float, float, float] | None
            ) -> tuple[Array, float, tuple[float, float], Array]:
    """A radial gradient's centre ``(2,)``, the angle (radians) of its first axis, its two radii and its focal
    point in its own frame ``(2,)``; of the equivalent frames, the one nearest ``previous``
    ``(angle, radius, radius)``, so the values move smoothly from frame to frame."""
    cx, cy, r, fx, fy = geometry[:5]  # a focal radius (a sixth value) is not written
    centre = placed[:2, :2] @ np.array([cx, cy]) + placed[:2, 2]
    u, sigma, _ = np.linalg.svd(placed[:2, :2] * r)
    theta = float(np.arctan2(u[1, 0], u[0, 0]))
    a, b = float(sigma[0]), float(sigma[1])
    if previous is not None:
        last, first_radius, second_radius = previous
        if a - b <= 1e-9 * a:  # a circle: any angle will do; keep the last one
            theta = last
        else:  # the same ellipse turned by a quarter (axes swapped), a half, three quarters: the nearest
            reach = max(a, first_radius, second_radius)
            options = [(theta + k * np.pi / 2, (a, b) if k % 2 == 0 else (b, a)) for k in range(4)]
            theta, (a, b) = min(options, key=lambda o: _wrapped(o[0] - last) * reach + abs(o[1][0] - first_radius)
                                + abs(o[1][1] - second_radius))
        theta = last + (theta - last + np.pi) % (2 * np.pi) - np.pi
    c, s = np.cos(theta), np.sin(theta)
    offset = placed[:2, :2] @ np.array([fx, fy]) + placed[:2, 2] - centre
    focal = np.array([c * offset[0] + s * offset[1], (-s * offset[0] + c * offset[1]) * a / b])
    return centre, theta, (a, b), focal


def _wrapped(turn: float) -> float:
    """The size of a turn (radians) taken the short way round: in [0, π]."""
    return abs((turn + np.pi) % (2 * np.pi) - np.pi)


def clip_path_make(at: ShapeAt) -> tuple[tuple[int, ...], ...]:
    """What splits a run where it changes: how many regions, contours and vertices a frame's clip paths have."""
    return tuple(tuple(len(c) for c in region) for region in at.clips)


def clip_path_keys(shapes: list[ShapeAt], first: int, viewport: Viewport, tolerance: float) -> ClipPathKeys | None:
    """The clip paths of a run's frames ``shapes`` (the run starts at clip frame ``first``; a last frame
    clipped otherwise than the first, the next key, is left out), keyframed within ``tolerance`` pixels;
    ``None`` when unclipped."""
    make = clip_path_make(shapes[0])
    if not make:
        return None
    shapes = [at for at in shapes if clip_path_make(at) == make]
    regions = [[np.stack([viewport.to_pixels(at.clips[r][c]) for at in shapes]) for c in range(len(region))]
               for r, region in enumerate(make)]  # (F, N, 2) each
    keys = greedy_keyframes(np.concatenate([c for region in regions for c in region], axis=1), tolerance)
    return ClipPathKeys(tuple(first + k for k in keys), tuple(tuple(c[keys] for c in region) for region in regions))


def gradient_frame_paths(run: VectorRun, tolerance: float, keyed: Callable[..., tuple[Any, ...]]
                         ) -> tuple[tuple[int, ...], tuple[Array, ...], tuple[Handles, ...]] | None:
    """The run's contours in its elliptical radial gradient's own frame, as the player places that frame at
    each frame: ``(frames, (one path per contour, as ``VectorRun.paths``), eases (K - 1,))``; ``None`` for a
    linear or circular gradient (or none), and for a run that is neither stroked nor clipped, whose Lottie
    draws the gradient through a matte of its own paths (:func:`..encode.lottie_paint.stretched_cover`). Where the frame never moves, the run's own keyframes mapped into it
    (an affine map keeps a cubic a cubic of its mapped control points); else the exact paths at every frame of
    the run mapped through the player's transform there and keyed as curves by ``keyed`` (``(samples, closed,
    tolerance) -> (frames from 0, paths, eases, ...)``) so that, mapped back, they stay within ``tolerance``
    pixels."""
    gradient = run.gradient
    if gradient is None or gradient.kind == "linear" or gradient.circular or run.gradient_matted():
        return None
    still = all(np.array_equal(a[:1].repeat(len(a), 0), a) for a in (gradient.start, gradient.angle, gradient.ratio))
    if still:
        local = tuple(into_gradient_frame(p, gradient.start[0], gradient.angle[0], gradient.ratio[0])
                      for p in run.paths)
        return run.path_frames, local, run.eases
    frames = np.arange(run.first, run.stop, dtype=np.float64)
    centre, angle, ratio = run.gradient_placed(frames)
    exact = run.exact_frames  # (F, sum L_i, 2)
    placed = np.stack([into_gradient_frame(exact[f], centre[f], angle[f], ratio[f]) for f in range(len(frames))])
    stretch = max(1.0, float(ratio.max()))  # the transform lengthens no distance more than this
    bounds = np.cumsum([0] + [c.shape[1] for c in run.exact_contours()])
    picked, paths, eases = keyed([placed[:, a:b] for a, b in zip(bounds, bounds[1:])], run.closed,
                                 tolerance / stretch)[:3]
    return tuple(run.first + k for k in picked), paths, eases


