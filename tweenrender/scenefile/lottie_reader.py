"""A Lottie animation (bodymovin JSON) read as a scene: its top level has ``v``, ``fr``, ``ip``, ``op`` and
``layers``, which a scene file never has.

Each paint item of a shape layer (a fill, gradient fill or stroke, with the paths it draws) becomes a
shape, painted in Lottie's order. The world is the Lottie canvas with y up (``view`` 0, 0, w, h; the
scene's size is the canvas's), the scene's frame f is Lottie's frame ``ip + f`` and the clip ends on the
last frame before ``op``.

Keys: where only paths move (``sh`` keyframes of one timing for every path of the shape) and everything
else about the shape stays (transforms, paint, the layer shown throughout), its keys are the keyframes at
their own times with their own easing (a keyframe's ``o``/``i`` handles as ``cubic-bezier``, ``h`` as
``hold``); a span cut by the clip's ends keeps its timing. Anything else that moves — a keyframed
transform, colour or opacity, a rectangle or ellipse, a layer coming or going — makes the shape a key at
every frame, each exactly as lottie-web draws it there. Curves are flattened at equal parameter steps,
the same number per segment in every key, so every key has the designer's vertex correspondence
(``equal_counts = "drawn"``) and the ``linear`` method replays the file.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Callable

import numpy as np

from ..core.timing.easing import parse_easing
from ..errors import SceneError
from ..model import Contour, Key, Paint, Scene, Shape, frozen_points
from .lottie_geometry import Transform, check_structure, placed, sample_path, segment_counts
from .lottie_items import Element, gradient_at, layer_elements
from .lottie_props import Malformed, PathValue, Prop, ShapeProp, Unreadable, ease_text, number_list, sub_ease
from .scene_limits import LIMITS, check_counts, check_matching_effort

__all__ = ["is_lottie", "lottie_scene", "TOLERANCE"]

TOLERANCE = 0.02
"""How far (canvas pixels) a flattened curve may lie from the curve."""
_LAYER_KINDS = {2: "an image layer", 5: "a text layer", 6: "an audio layer", 7: "a video placeholder",
                8: "an image sequence", 9: "a video layer", 10: "an image placeholder", 11: "a guide layer",
                12: "an adjustment layer", 13: "a camera", 14: "a light", 15: "a data layer"}
_MOST_FRAMES = 100_000


def is_lottie(data: Any) -> bool:
    """Whether a parsed JSON document is a Lottie animation."""
    return isinstance(data, dict) and all(name in data for name in ("v", "fr", "ip", "op", "layers"))


@dataclass(frozen=True)
class Clock:
    """A composition's time: its frame is ``(root frame − offset) / scale``."""

    scale: float = 1.0
    offset: float = 0.0

    def local(self, frame: float) -> float:
        return (frame - self.offset) / self.scale

    def root(self, local: float) -> float:
        return local * self.scale + self.offset

    def inner(self, start: float, stretch: float) -> Clock:
        """The clock of a precomposition placed at ``start`` and stretched by ``stretch`` in this one."""
        return Clock(self.scale * stretch, self.offset + self.scale * start)


@dataclass
class Placement:
    """Where a composition's layers are drawn: its clock, and per root frame its matrix into the world, its
    opacity, whether it is shown, and the regions (precomposition boxes, world units) it is cut to."""

    clock: Clock
    matrix: Callable[[float], np.ndarray]
    opacity: Callable[[float], float]
    shown: Callable[[float], bool]
    clips: Callable[[float], list[np.ndarray]]
    where: str


@dataclass
class Drawn:
    """An element of a layer, placed: how to draw it at each root frame."""

    element: Element
    layer_matrix: Callable[[float], np.ndarray]
    layer_opacity: Callable[[float], float]
    shown: Callable[[float], bool]
    clips: Callable[[float], list[np.ndarray]]
    clock: Clock
    where: str


def lottie_scene(data: dict[str, Any], path: Path) -> Scene:
    """The scene of the Lottie document ``data`` read from ``path`` (see the module's docstring)."""
    def top(name: str, low: float, high: float, what: str) -> float:
        try:
            value = float(number_list(data.get(name), what)[0])
        except Malformed:
            value = math.nan
        if not low <= value <= high:
            raise SceneError(path, name, f"expected {what} from {low:g} to {high:g}, found {data.get(name)!r}")
        return value

    canvas = LIMITS["canvas"]
    width, height = top("w", 1, canvas, "a width in pixels"), top("h", 1, canvas, "a height in pixels")
    low, high = LIMITS["fps"]
    fps = top("fr", low, high, "frames per second")
    first = top("ip", -1e7, 1e7, "a first frame")
    end = top("op", first + 1e-9, first + _MOST_FRAMES, "an end frame after ip")
    last = first + math.ceil(end - first - 1e-9) - 1
    frames = np.arange(first, last + 0.5)
    assets = {str(a.get("id")): a for a in data.get("assets", []) if isinstance(a, dict)}
    flip = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, height], [0.0, 0.0, 1.0]])
    root = Placement(Clock(), lambda f: flip, lambda f: 1.0, lambda f: True, lambda f: [], "")
    drawn: list[Drawn] = []
    _composition(data.get("layers"), root, assets, drawn, path, 0)
    shapes: list[Shape] = []
    names: set[str] = set()
    view = np.array([[0.0, 0.0], [width, 0.0], [width, height], [0.0, height]])
    for item in drawn:
        try:
            shape = _shape(item, frames, fps, first, names, view)
        except Unreadable as error:
            raise SceneError(path, item.where, f"cannot read {error}") from None
        except Malformed as error:
            raise SceneError(path, item.where, str(error)) from None
        except (KeyError, TypeError, ValueError, IndexError, ZeroDivisionError) as error:
            raise SceneError(path, item.where, f"expected Lottie shape data, found malformed data ({error!r:.60})") \
                from None
        if shape is not None:
            shapes.append(shape)
    background: tuple[int, int, int, int] = (255, 255, 255, 255)
    if len(shapes) > 1 and _backdrop(shapes[0], view) is not None:
        background = _backdrop(shapes[0], view)  # type: ignore[assignment]
        shapes = shapes[1:]
    if not shapes:
        raise SceneError(path, "layers", "expected at least one shape layer that draws something, found none")

    def fail(where: str, message: str) -> SceneError:
        return SceneError(path, where, message)

    check_counts(len(shapes), sum(len(s.keys) for s in shapes), fail)
    duration = (last - first) / fps
    latest = max(s.keys[-1].time for s in shapes)
    scene = Scene(shapes=tuple(shapes), title=str(data.get("nm")) if data.get("nm") else None,
                  size=(int(round(width)), int(round(height))), fps=fps, background=background,
                  view=(0.0, 0.0, float(width), float(height)), method="linear", compare=("linear", "nonlinear"),
                  path=path, end_hold=max(0.0, duration - latest), sources=(path,))
    check_matching_effort(scene.shapes, scene.matching, fail)
    return scene


def _composition(layers: Any, outer: Placement, assets: dict[str, Any], out: list[Drawn], path: Path,
                 depth: int) -> None:
    """Every layer of a composition into ``out``, bottom first."""
    if depth > 16:
        raise SceneError(path, outer.where or "assets", "expected precompositions nested at most 16 deep")
    if not isinstance(layers, list):
        raise SceneError(path, f"{outer.where}layers".strip(), "expected a list of layers")
    by_index = {layer.get("ind"): layer for layer in layers if isinstance(layer, dict) and "ind" in layer}
    for number in range(len(layers) - 1, -1, -1):
        layer = layers[number]
        if not isinstance(layer, dict):
            raise SceneError(path, f"{outer.where}layers[{number}]", "expected a layer object")
        where = f"{outer.where}layer {layer.get('ind', number)} {str(layer.get('nm', ''))!r} (layers[{number}])"
        try:
            _layer(layer, outer, by_index, assets, out, path, depth, where)
        except Unreadable as error:
            raise SceneError(path, where, f"cannot read {error}") from None
        except Malformed as error:
            raise SceneError(path, where, str(error)) from None
        except (KeyError, TypeError, ValueError, IndexError, ZeroDivisionError) as error:
            raise SceneError(path, where, f"expected a Lottie layer, found malformed data ({error!r:.60})") from None


def _layer(layer: dict[str, Any], outer: Placement, by_index: dict[Any, dict[str, Any]], assets: dict[str, Any],
           out: list[Drawn], path: Path, depth: int, where: str) -> None:
    kind = layer.get("ty")
    if layer.get("hd") or kind == 3 and not layer.get("ef"):
        return  # hidden, or a null layer (it only moves its children)
    if kind in _LAYER_KINDS:
        raise Unreadable(_LAYER_KINDS[kind])
    if kind not in (0, 1, 4):
        raise Unreadable(f"a layer of type {kind!r}")
    if layer.get("ef"):
        raise Unreadable("effects")
    if layer.get("tt") or layer.get("td"):
        raise Unreadable("a track matte")
    if layer.get("ddd"):
        raise Unreadable("a 3-D layer")
    if layer.get("bm"):
        raise Unreadable(f"a blend mode ({layer.get('bm')})")
    if "tm" in layer:
        raise Unreadable("time remapping")
    chain = _parents(layer, by_index)
    if layer.get("ao") and chain[-1].moves:
        raise Unreadable("an auto-oriented layer that moves")
    clock = outer.clock
    start_frame, stop_frame = float(layer.get("ip", -math.inf)), float(layer.get("op", math.inf))

    made: dict[float, np.ndarray] = {}

    def matrix(frame: float) -> np.ndarray:
        if frame not in made:
            local = clock.local(frame)
            out_matrix = outer.matrix(frame)
            for transform in chain:
                out_matrix = out_matrix @ transform.matrix(local)
            made[frame] = out_matrix
        return made[frame]

    own = chain[-1]

    def opacity(frame: float) -> float:
        return outer.opacity(frame) * own.opacity(clock.local(frame))

    def shown(frame: float) -> bool:
        return outer.shown(frame) and start_frame <= clock.local(frame) < stop_frame

    if kind == 0:
        asset = assets.get(str(layer.get("refId")))
        if asset is None or "layers" not in asset:
            raise Malformed(f"expected a precomposition asset {layer.get('refId')!r}, found none")
        stretch = float(layer.get("sr", 1) or 1)
        if stretch <= 0:
            raise Malformed(f"expected a positive time stretch, found {stretch!r}")
        box = np.array([[0, 0], [layer.get("w", 0), 0], [layer.get("w", 0), layer.get("h", 0)],
                        [0, layer.get("h", 0)]], dtype=float)

        def clips(frame: float) -> list[np.ndarray]:
            if not ("w" in layer and "h" in layer):
                return outer.clips(frame)
            m = matrix(frame)
            return [*outer.clips(frame), box @ m[:2, :2].T + m[:2, 2]]

        inner = Placement(clock.inner(float(layer.get("st", 0)), stretch), matrix, opacity, shown, clips,
                          f"{where} > ")
        _composition(asset["layers"], inner, assets, out, path, depth + 1)
        return
    masks = _masks(layer.get("masksProperties") or [])

    def masked(frame: float) -> list[np.ndarray]:
        if not masks:
            return outer.clips(frame)
        m, local = matrix(frame), clock.local(frame)
        return [*outer.clips(frame), *(sample_path(placed(mask.at(local), m), counts) for mask, counts in masks)]

    if kind == 1:
        items = _solid(layer)
    else:
        items = layer.get("shapes", [])
    name = str(layer.get("nm", f"layer {layer.get('ind', '')}")).strip() or "layer"
    elements = layer_elements(items, name)
    if len(elements) == 1:
        elements[0].name = name
    for element in elements:
        out.append(Drawn(element, matrix, opacity, shown, masked, clock, where))


_MASK_STEPS = 16  # equal parameter steps a curved mask segment is cut into, in every frame alike


def _masks(raw: Any) -> list[tuple[ShapeProp, np.ndarray]]:
    """A layer's masks as clip paths (each with its segments' step counts): masks that intersect what the
    layer draws (the first adding, the others intersecting), opaque, not inverted nor expanded."""
    out = []
    if not isinstance(raw, list):
        raise Malformed("expected masksProperties as a list of masks")
    for n, mask in enumerate(raw):
        if not isinstance(mask, dict):
            raise Malformed("expected a mask object")
        mode = mask.get("mode", "a")
        if mode == "n":
            continue
        expected = "a" if not out else "i"
        if mode != expected or mask.get("inv"):
            raise Unreadable(f"mask {n} (mode {mode!r}{', inverted' if mask.get('inv') else ''}): masks are read "
                             "when the first adds and the others intersect, none inverted")
        fade, grow = Prop(mask.get("o"), "a mask's opacity", [100]), Prop(mask.get("x"), "a mask's expansion", [0])
        if fade.animated or float(fade.value[0]) != 100 or grow.animated or float(grow.value[0]) != 0:
            raise Unreadable(f"mask {n} (not opaque, or expanded)")
        shape = ShapeProp(mask.get("pt"))
        values = [k.start for k in shape.keys] if shape.keys else [shape.value]
        check_structure(values)
        if len(values[0].v) < 2:
            continue
        straight = [segment_counts([v], 1e-9, 2) for v in values]
        counts = np.where(np.max(straight, axis=0) > 1, _MASK_STEPS, 1)
        out.append((shape, counts))
    return out


def _parents(layer: dict[str, Any], by_index: dict[Any, dict[str, Any]]) -> list[Transform]:
    """The transforms from the outermost parent down to the layer's own."""
    chain = [Transform(layer.get("ks"))]
    seen = {id(layer)}
    current = layer
    while "parent" in current:
        parent = by_index.get(current["parent"])
        if parent is None:
            raise Malformed(f"expected a parent layer with ind {current['parent']!r}, found none")
        if id(parent) in seen:
            raise Malformed("expected parents without a loop, found a layer its own ancestor")
        seen.add(id(parent))
        chain.insert(0, Transform(parent.get("ks")))
        current = parent
    return chain


def _solid(layer: dict[str, Any]) -> list[dict[str, Any]]:
    """A solid layer's rectangle as shape items."""
    colour = str(layer.get("sc", "#000000")).lstrip("#")
    try:
        rgb = [int(colour[i:i + 2], 16) / 255 for i in (0, 2, 4)]
    except ValueError:
        raise Malformed(f"expected a solid colour #rrggbb, found {layer.get('sc')!r}") from None
    w, h = float(layer.get("sw", 0)), float(layer.get("sh", 0))
    box = {"c": True, "v": [[0, 0], [w, 0], [w, h], [0, h]], "i": [[0, 0]] * 4, "o": [[0, 0]] * 4}
    return [{"ty": "sh", "ks": {"a": 0, "k": box}}, {"ty": "fl", "c": {"a": 0, "k": [*rgb, 1]},
                                                    "o": {"a": 0, "k": 100}, "r": 1}]


def _chain_matrix(transforms: list[Transform], local: float) -> np.ndarray:
    """Group transforms (innermost first) as one matrix from the innermost group into the layer."""
    out = np.eye(3)
    for transform in transforms:
        out = transform.matrix(local) @ out
    return out


def _chain_opacity(transforms: list[Transform], local: float) -> float:
    return float(np.prod([t.opacity(local) for t in transforms]))


def _paths_at(item: Drawn, frame: float, local: float | None = None) -> list[PathValue]:
    """The element's paths at root ``frame`` in world units (``local``: its composition's frame, when known
    exactly)."""
    local = item.clock.local(frame) if local is None else local
    layer = item.layer_matrix(frame)
    return [placed(path.at(local), layer @ _chain_matrix(groups, local)) for path, groups in item.element.paths]


def _paint_at(item: Drawn, frame: float) -> Paint:
    """The element's paint at root ``frame`` (world units; opacity 0 where the layer is not shown)."""
    local = item.clock.local(frame)
    element = item.element
    matrix = item.layer_matrix(frame) @ _chain_matrix(element.transforms, local)
    opacity = item.layer_opacity(frame) * _chain_opacity(element.transforms, local) if item.shown(frame) else 0.0
    fill = stroke = gradient = None
    width = 0.0
    if element.fill is not None:
        if element.fill.kind == "gf":
            gradient, fill = gradient_at(element.fill, local, matrix)
        else:
            fill = element.fill.colour_at(local)
    if element.stroke is not None:
        stroke = element.stroke.colour_at(local)
        width = float(element.stroke.width.at(local)[0]) * math.sqrt(abs(np.linalg.det(matrix[:2, :2])))
    return Paint(fill=fill, stroke=stroke, stroke_width=max(width, 0.0), opacity=min(max(opacity, 0.0), 1.0),
                 gradient=gradient)


def _still(item: Drawn, frames: np.ndarray) -> bool:
    """Whether everything but the ``sh`` paths stays over ``frames``: transforms, paint, shown, clips."""
    element = item.element
    if any(path.kind != "sh" and path.animated for path, _ in element.paths):
        return False
    first = frames[0]
    signature = _signature(item, first)
    return all(_same(signature, _signature(item, f)) for f in frames[1:])


def _signature(item: Drawn, frame: float) -> list[Any]:
    local = item.clock.local(frame)
    out: list[Any] = [item.layer_matrix(frame), item.shown(frame), _paint_at(item, frame), item.clips(frame)]
    out += [_chain_matrix(groups, local) for _, groups in item.element.paths]
    return out


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.shape(a) == np.shape(b) and bool(np.allclose(a, b, rtol=0, atol=1e-9))
    if isinstance(a, (list, tuple)):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return bool(a == b)


def _key_plan(item: Drawn, low: float, high: float) -> list[tuple[float, float | None, str]] | None:
    """Keys at the ``sh`` keyframes, clipped to root frames ``[low, high]``: ``(root frame, exact local frame or
    None, ease)``; ``None`` when the paths' keyframes differ in time or timing or jump."""
    shaped = [path.shape for path, _ in item.element.paths if path.shape is not None and path.shape.animated]
    if not shaped:
        return [(low, None, "linear")]
    keys = shaped[0].keys
    assert keys is not None
    times = [k.t for k in keys]
    eases = [ease_text(k.handles[:1] if k.handles is not None else None, k.hold) for k in keys[:-1]]
    for prop in shaped:
        other = prop.keys
        assert other is not None
        if [k.t for k in other] != times or not prop.continuous():
            return None
        if [ease_text(k.handles[:1] if k.handles is not None else None, k.hold) for k in other[:-1]] != eases:
            return None
    if any(e is None for e in eases) or len(set(times)) != len(times):
        return None
    roots = [item.clock.root(t) for t in times]
    at = sorted({min(max(r, low), high) for r in roots})
    plan: list[tuple[float, float | None, str]] = []
    for n, frame in enumerate(at):
        exact = times[roots.index(frame)] if frame in roots else None
        if n == len(at) - 1:
            plan.append((frame, exact, "linear"))
            continue
        after = at[n + 1]
        k = max((j for j in range(len(roots) - 1) if roots[j] <= frame), default=None)
        if k is None or after > roots[k + 1] + 1e-9:
            return None
        span = roots[k + 1] - roots[k]
        ease = sub_ease(eases[k], (frame - roots[k]) / span, (after - roots[k]) / span)  # type: ignore[arg-type]
        if ease is None:
            return None
        plan.append((frame, exact, ease))
    return plan


def _backdrop(shape: Shape, view: np.ndarray) -> tuple[int, int, int, int] | None:
    """The colour of a bottom shape that is an opaque fill of the whole canvas, still (the scene's
    background, as the vector writers draw it); ``None`` for any other shape."""
    first = shape.keys[0]
    paint = first.paint
    if paint.fill is None or paint.fill[3] != 255 or paint.opacity != 1 or paint.gradient is not None \
            or (paint.stroke is not None and paint.stroke_width > 0) or first.clips or len(first.contours) != 1:
        return None
    points = first.contours[0].points
    if len(points) != 4 or not _covers(points, view):
        return None
    if any(k.paint != paint or len(k.contours) != 1 or not np.array_equal(k.contours[0].points, points)
           for k in shape.keys[1:]):
        return None
    return paint.fill


_COVERING: dict[bytes, bool] = {}


def _covers(region: np.ndarray, view: np.ndarray) -> bool:
    """Whether the convex ``region (4, 2)`` holds every corner of the ``view (4, 2)``: it cuts nothing away."""
    key = region.tobytes() + view.tobytes()
    if key not in _COVERING:
        if len(_COVERING) > 4096:
            _COVERING.clear()
        _COVERING[key] = _convex_holds(region, view)
    return _COVERING[key]


def _convex_holds(region: np.ndarray, view: np.ndarray) -> bool:
    edges = np.roll(region, -1, axis=0) - region
    cross = edges[:, None, 0] * (view[None, :, 1] - region[:, None, 1]) \
        - edges[:, None, 1] * (view[None, :, 0] - region[:, None, 0])
    return bool(np.all(cross >= -1e-9) or np.all(cross <= 1e-9))


def _shape(item: Drawn, frames: np.ndarray, fps: float, first: float, names: set[str],
           view: np.ndarray) -> Shape | None:
    """The shape of one placed element: exact keys where only its paths move, else a key a frame."""
    plan = _key_plan(item, float(frames[0]), float(frames[-1])) if _still(item, frames) else None
    for attempt in ("exact", "frames"):
        if attempt == "frames" or plan is None:
            plan = [(float(f), None, "linear") for f in frames]
        paths = [_paths_at(item, frame, exact) for frame, exact, _ in plan]
        keep = [j for j, p in enumerate(paths[0]) if len(p.v) > 0]
        if not keep:
            return None
        for j in keep:
            check_structure([p[j] for p in paths])
        counts = [segment_counts([p[j] for p in paths], TOLERANCE) for j in keep]
        contours_per_key = []
        for p in paths:
            contours = []
            for j, count in zip(keep, counts):
                points = sample_path(p[j], count)
                if len(points) >= (3 if p[j].closed else 2):
                    contours.append(Contour(frozen_points(points), p[j].closed))
            contours_per_key.append(tuple(contours))
        if not contours_per_key[0]:
            return None
        if attempt == "exact" and len(contours_per_key[0]) > 1 and not _paired_in_order(contours_per_key):
            continue
        break
    paints = [_paint_at(item, frame) for frame, _, _ in plan]
    keys = []
    for (frame, _, ease), contours, paint in zip(plan, contours_per_key, paints):
        clips = tuple((Contour(frozen_points(region), True),) for region in item.clips(frame)
                      if not _covers(region, view))
        keys.append(Key(time=(frame - first) / fps, contours=contours, ease=ease, paint=paint, clips=clips,
                        easing=parse_easing(ease)))
    keys = _without_repeats(keys)
    element = item.element
    fill_rule = element.fill.fill_rule if element.fill is not None else "nonzero"
    stroke = element.stroke
    name = element.name
    n = 1
    while name in names:
        n += 1
        name = f"{element.name} {n}"
    names.add(name)
    return Shape(name=name, keys=tuple(keys), fill_rule=fill_rule, cap=stroke.cap if stroke else "round",
                 join=stroke.join if stroke else "round", miter_limit=stroke.miter if stroke else 4.0,
                 stroke_scales=True, equal_counts="drawn")


def _paired_in_order(keys: list[tuple[Contour, ...]]) -> bool:
    """Whether the scene pairs contour i of each key with contour i of the next (as the file does)."""
    from ..core.contours import pair_contours

    for a, b in zip(keys, keys[1:]):
        pairs = pair_contours([c.points for c in a], [c.closed for c in a], [c.points for c in b],
                              [c.closed for c in b])
        if pairs != [(i, i) for i in range(len(a))]:
            return False
    return True


def _without_repeats(keys: list[Key]) -> list[Key]:
    """The keys without those inside a run of equal keys (nothing moves there)."""
    def same(a: Key, b: Key) -> bool:
        return a.paint == b.paint and _same([[c.points for c in r] for r in a.clips],
                                            [[c.points for c in r] for r in b.clips]) \
            and len(a.contours) == len(b.contours) and all(
            np.array_equal(x.points, y.points) for x, y in zip(a.contours, b.contours))

    out = [keys[0]]
    for n in range(1, len(keys)):
        if n + 1 < len(keys) and same(keys[n - 1], keys[n]) and same(keys[n], keys[n + 1]):
            continue
        out.append(keys[n])
    return out
