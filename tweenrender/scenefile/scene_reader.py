"""A parsed scene document (TOML or JSON) read into the frozen model, refusing anything malformed:
every error names the file, the key path (and, for TOML, its line), what was expected and what was
found (:class:`.values.ValueReader`)."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np

from ..core.methods.registry import METHODS, REGISTRY
from ..core.timing.easing import LINEAR, Easing
from ..errors import GeometryError
from ..model import (ALIGNS, BALANCES, CAPS, COSTS, DEFAULT_BALANCE, DEFAULT_FILL, EQUAL_COUNTS, FILL_RULES,
                     JOINS, UNMATCHED, Color, Contour, Key, Matching, Paint, Scene, Shape, frozen_points)
from .controls import (check_hints, check_shape_stagger, check_steering, pinned, read_easing, read_hints,
                       read_stagger, read_steering, read_timing)
from .scene_limits import LIMITS, check_counts, check_matching_effort
from .values import ValueReader, describe, short

__all__ = ["SceneReader", "fitted_size"]

_TOP = ("title", "size", "fps", "background", "view", "method", "compare", "balance", "correspondence", "unmatched",
        "ease", "stagger", "shape", "drawing")
_PAINT = ("fill", "stroke", "stroke_width", "opacity")
_SHAPE = ("name", *_PAINT, "method", "joints", "balance", "fill_rule", "closed", "cap", "join", "unmatched", "stagger",
          "key")
_STEER = ("turn", "turns", "arcs", "breakdown")
_KEY = ("time", "points", "contours", "ease", "spacing", "hints", *_STEER, *_PAINT)
_DRAWING = ("time", "svg", "ease", "spacing", "hints", "stagger", "hold", "tolerance", *_STEER)
_SVG = ("svg", "id", "tolerance")
_MATCHING = ("cost", "align", "equal_counts", "ks", "cs", "es", "kb", "eb", "mb", "pb")


class SceneReader(ValueReader):
    """Reads one parsed scene document into a :class:`Scene`; ``arrays`` are the points arrays numpy read
    ahead (:mod:`.point_arrays`), by the string standing for each in the document."""

    def __init__(self, path: Path, text: str, fmt: str, arrays: dict[str, np.ndarray] | None = None) -> None:
        super().__init__(path, text, fmt)
        self.arrays = arrays or {}
        self.read_arrays: set[str] = set()
        self.timing: tuple[str, Easing] = ("linear", LINEAR)  # the scene's ease: every key's default
        self.stagger = 0.0
        self.moved: dict[str, list[np.ndarray]] = {}  # key path -> where hints moved its contours' vertices
        self.sources: list[Path] = []  # files the scene refers to, in the order they are read
        self.drawing_times: list[float] = []  # each [[drawing]] entry's time, in order
        self.end_hold = 0.0  # the last drawing's hold

    def scene(self, data: Any) -> Scene:
        top = self.table(data, "", _TOP)
        canvas = LIMITS["canvas"]
        size: tuple[int, int] = (1280, 720)
        if "size" in top:
            pair = self.listing(top["size"], "size", "[width, height] in pixels")
            if len(pair) != 2:
                raise self.fail("size", f"expected [width, height] in pixels, found {describe(pair)}")
            size = (self.integer(pair[0], "size[0]", 1, canvas, "a width in pixels"),
                    self.integer(pair[1], "size[1]", 1, canvas, "a height in pixels"))
        low, high = LIMITS["fps"]
        fps = self.number(top.get("fps", 24), "fps", low, high, "frames per second")
        view = None
        if "view" in top:
            view = self.view(top["view"])
        unmatched = self.choice(top.get("unmatched", "grow"), "unmatched", UNMATCHED, "rule for unmatched contours")
        if "ease" in top:
            easing = read_easing(top["ease"], "ease", self.fail)
            self.timing = (easing.text, easing)
        if "stagger" in top:
            self.stagger = read_stagger(top["stagger"], "stagger", self.fail)
        shapes_raw = self.listing(top.get("shape", []), "shape", "a list of [[shape]] tables")
        drawings_raw = self.listing(top.get("drawing", []), "drawing", "a list of [[drawing]] tables")
        if not shapes_raw and not drawings_raw:
            raise self.fail("shape", "expected at least one [[shape]] or [[drawing]], found none")
        keys_raw = sum(len(raw["key"]) for raw in shapes_raw
                       if isinstance(raw, dict) and isinstance(raw.get("key"), list))
        check_counts(len(shapes_raw), keys_raw + len(drawings_raw), self.fail)
        shapes = tuple(self.shape(raw, f"shape[{i}]", i) for i, raw in enumerate(shapes_raw))
        names: dict[str, int] = {}
        for i, shape in enumerate(shapes):
            if shape.name in names:
                raise self.fail(f"shape[{i}].name", f"expected a unique name, found {short(shape.name)} "
                                                    f"again (also shape[{names[shape.name]}])")
            names[shape.name] = i
        drawn: tuple[Shape, ...] = ()
        if drawings_raw:
            drawn, box = self.drawings(drawings_raw, unmatched)
            drawn = tuple(_renamed(shape, names) for shape in drawn)
            if view is None:
                view = box
            if "size" not in top:
                size = fitted_size(box)
        shapes = drawn + shapes
        check_counts(len(shapes), sum(len(shape.keys) for shape in shapes), self.fail)
        method = self.choice(top.get("method", "auto" if drawings_raw else "nonlinear"), "method", METHODS, "method")
        compare = ("linear", "nonlinear")
        if "compare" in top:
            items = self.listing(top["compare"], "compare", "a list of method names")
            if not items:
                raise self.fail("compare", "expected at least one method name, found an empty list")
            compare = tuple(self.choice(m, f"compare[{i}]", METHODS, "method") for i, m in enumerate(items))
        for i, shape in enumerate(shapes):
            chosen = shape.method or method
            if REGISTRY[chosen].needs_joints and not shape.joints:
                raise self.fail(f"shape[{i}].method", f"method {chosen!r} needs joints = [[a, b], ...], found none")
        title = self.string(top["title"], "title") if "title" in top else None
        background = self.background(top.get("background", "#ffffff"), "background")
        matching = self.matching(top.get("correspondence", {}))
        check_matching_effort(shapes, matching, self.fail)
        balance = self.choice(top.get("balance", DEFAULT_BALANCE), "balance", BALANCES, "balance")
        shapes = self.steered(shapes, method, len(drawn), matching, unmatched, balance)
        return Scene(shapes=shapes, title=title, size=size, fps=fps, background=background, view=view,
                     method=method, compare=compare, matching=matching, path=self.path, unmatched=unmatched,
                     balance=balance, sources=tuple(dict.fromkeys((self.path, *self.sources))),
                     end_hold=self.end_hold)

    def drawings(self, items: list[Any], unmatched: str) -> tuple[tuple[Shape, ...], tuple[float, float, float, float]]:
        """``[[drawing]]`` keys: whole SVG files at times; their shapes and the first drawing's view box."""
        from .drawings import DrawingKey, drawing_shapes, read_drawings, with_breakdowns
        from .svg import SvgError

        keys = []
        breakdowns: list[Key] = []  # breakdown drawings, as keys without contours yet
        last = -1.0
        for i, raw in enumerate(items):
            where = f"drawing[{i}]"
            table = self.table(raw, where, _DRAWING)
            steering = read_steering(table, where, self.fail, LIMITS["coordinate"])
            if "time" not in table or ("svg" not in table and "breakdown" not in steering):
                raise self.fail(where, "expected time = seconds and svg = \"file.svg\" (or breakdown = favour), "
                                       f"found {', '.join(table) or 'no keys'}")
            time = self.number(table["time"], f"{where}.time", 0.0, LIMITS["time"], "a time in seconds")
            if time <= last:
                raise self.fail(f"{where}.time", f"expected a time after {last:.15g} "
                                                 f"(times strictly increase), found {time:.15g}")
            last = time
            self.drawing_times.append(time)
            text, easing = read_timing(table, where, self.fail, self.timing)
            if "breakdown" in steering:
                for name in ("svg", "hints", "arcs", "hold", "stagger", "tolerance"):
                    if name in table:
                        raise self.fail(f"{where}.{name}", f"expected no {name} on a breakdown drawing (its "
                                                           "elements are the in-betweens of the drawings around it)")
                if not keys or i == len(items) - 1:
                    raise self.fail(f"{where}.breakdown", "expected a drawing before and a drawing after a "
                                                          f"breakdown, found it {'first' if not keys else 'last'}")
                breakdowns.append(Key(time, (), text, easing=easing, **steering))
                continue
            file = self.path.parent / self.string(table["svg"], f"{where}.svg")
            tolerance = None
            if "tolerance" in table:
                tolerance = self.number(table["tolerance"], f"{where}.tolerance", 1e-9, 1e6,
                                        "a tolerance in world units")
            hints = read_hints(table["hints"], f"{where}.hints", self.fail, LIMITS["coordinate"]) \
                if "hints" in table else {}
            for letter, _ in steering.get("arcs", ()):
                if letter not in hints:
                    raise self.fail(f"{where}.arcs.{letter}", f"expected hint {letter} on this drawing (and the "
                                                              "next), found none on this one")
            stagger = read_stagger(table["stagger"], f"{where}.stagger", self.fail) \
                if "stagger" in table else self.stagger
            hold = read_stagger(table["hold"], f"{where}.hold", self.fail, "a hold") if "hold" in table else 0.0
            keys.append(DrawingKey(file, time, text, tolerance, easing=easing, hints=hints, stagger=stagger,
                                   hold=hold, turn=steering.get("turn"), turns=steering.get("turns", 0),
                                   arcs=dict(steering.get("arcs", ()))))
            self.sources.append(file)
        self.end_hold = keys[-1].hold if len(keys) > 1 else 0.0
        try:
            drawings, box = read_drawings(keys)
        except SvgError as error:
            index = next(i for i, key in enumerate(keys) if str(key.path) == error.path)
            raise self.fail(f"drawing[{index}].svg", str(error)) from None
        shapes = drawing_shapes(drawings, keys, unmatched, self.fail)
        return tuple(with_breakdowns(shape, breakdowns) for shape in shapes), box

    def steered(self, shapes: tuple[Shape, ...], method: str, drawn: int, matching: Matching, unmatched: str,
                balance: str) -> tuple[Shape, ...]:
        """``shapes`` with their steering checked and their breakdown keys made (maths §5.13–5.15); the
        first ``drawn`` are the drawings' elements, whose keys are ``drawing[k]`` entries."""
        from ..core.timing.timeline import make_breakdowns

        times = self.drawing_times
        out = []
        for i, shape in enumerate(shapes):
            if i < drawn:
                def where_of(k: int, s: Shape = shape) -> str:
                    return f"drawing[{times.index(s.keys[k].time)}]"
            else:
                def where_of(k: int, i: int = i) -> str:
                    return f"shape[{i - drawn}].key[{k}]"
            chosen = shape.method or method
            check_steering(shape.keys, chosen, where_of, self.fail)
            try:
                out.append(make_breakdowns(shape, matching, chosen, unmatched=unmatched,
                                           balance=shape.balance or balance))
            except GeometryError as error:
                at = next(k for k, key in enumerate(shape.keys) if key.breakdown is not None)
                raise self.fail(f"{where_of(at)}.breakdown", str(error)) from None
        return tuple(out)

    def background(self, value: Any, where: str) -> Color:
        """A colour, or ``none`` for a transparent background."""
        if isinstance(value, str) and value.strip().lower() == "none":
            return (0, 0, 0, 0)
        return self.color(value, where)

    def view(self, value: Any) -> tuple[float, float, float, float]:
        box = self.listing(value, "view", "[xmin, ymin, xmax, ymax]")
        if len(box) != 4:
            raise self.fail("view", f"expected [xmin, ymin, xmax, ymax], found {describe(box)}")
        limit = LIMITS["coordinate"]
        x0, y0, x1, y1 = (self.number(v, f"view[{i}]", -limit, limit, "a coordinate") for i, v in enumerate(box))
        if not (x1 > x0 and y1 > y0):
            raise self.fail("view", f"expected xmax > xmin and ymax > ymin, found {box}")
        return (x0, y0, x1, y1)

    def matching(self, value: Any) -> Matching:
        table = self.table(value, "correspondence", _MATCHING)
        fields: dict[str, Any] = {}
        if "cost" in table:
            fields["cost"] = self.choice(table["cost"], "correspondence.cost", COSTS, "cost")
        if "align" in table:
            fields["align"] = self.choice(table["align"], "correspondence.align", ALIGNS, "alignment")
        if "equal_counts" in table:
            fields["equal_counts"] = self.choice(table["equal_counts"], "correspondence.equal_counts",
                                                 EQUAL_COUNTS, "rule for equal counts")
        for name in _MATCHING[3:]:
            if name in table:
                fields[name] = self.number(table[name], f"correspondence.{name}", 0.0, 1e6, "a constant")
        return Matching(**fields)

    def shape(self, value: Any, where: str, index: int) -> Shape:
        table = self.table(value, where, _SHAPE)
        name = self.string(table["name"], f"{where}.name") if "name" in table else f"shape{index + 1}"
        closed = self.boolean(table.get("closed", True), f"{where}.closed")
        defaults = self.paint(table, where, Paint(DEFAULT_FILL if closed else None, None, 2.0, 1.0))
        if not closed and "fill" in table:
            raise self.fail(f"{where}.fill", "expected no fill on an open shape (closed = false): "
                                             "open strokes are drawn with stroke, never filled")
        if "key" not in table:
            raise self.fail(where, "expected at least one [[shape.key]], found none")
        keys_raw = self.listing(table["key"], f"{where}.key", "a list of [[shape.key]] tables")
        if not keys_raw:
            raise self.fail(f"{where}.key", "expected at least one [[shape.key]], found none")
        keys = tuple(self.key(raw, f"{where}.key[{k}]", closed, defaults) for k, raw in enumerate(keys_raw))
        for k in range(1, len(keys)):
            if keys[k].time <= keys[k - 1].time:
                raise self.fail(f"{where}.key[{k}].time", f"expected a time after {keys[k - 1].time:.15g} "
                                                          f"(times strictly increase), found {keys[k].time:.15g}")
        for k in (0, len(keys) - 1):
            if keys[k].breakdown is not None:
                raise self.fail(f"{where}.key[{k}].breakdown", "expected a key before and a key after a breakdown, "
                                                               f"found it {'first' if k == 0 else 'last'}")
        real = [k for k, key in enumerate(keys) if key.breakdown is None]
        check_hints([keys[k] for k in real], lambda k: f"{where}.key[{real[k]}]", self.fail)
        if not closed and not any(key.paint.stroke is not None for key in keys):
            raise self.fail(where, "expected a stroke on an open shape (closed = false), found none: "
                                   "add stroke = \"#rrggbb\"")
        method = None
        if "method" in table:
            method = self.choice(table["method"], f"{where}.method", METHODS, "method")
        joints: tuple[tuple[int, int], ...] = ()
        if "joints" in table:
            several = [k for k, key in enumerate(keys) if key.breakdown is None
                       and (len(key.contours) != 1 or not key.contours[0].closed)]
            if several:
                raise self.fail(f"{where}.joints", f"expected keys of one closed outline for joints, found "
                                                   f"{len(keys[several[0]].contours)} contours in key {several[0]}")
            moved = self.moved[f"{where}.key[0]"][0]  # joints name the vertices as drawn, before hints
            joints = tuple((int(moved[i]), int(moved[j]))
                           for i, j in self.joints(table["joints"], f"{where}.joints", len(moved)))
        fill_rule = self.choice(table.get("fill_rule", "nonzero"), f"{where}.fill_rule", FILL_RULES, "fill rule")
        cap = self.choice(table.get("cap", "round"), f"{where}.cap", CAPS, "line cap")
        join = self.choice(table.get("join", "round"), f"{where}.join", JOINS, "line join")
        unmatched = None
        if "unmatched" in table:
            unmatched = self.choice(table["unmatched"], f"{where}.unmatched", UNMATCHED, "rule for unmatched contours")
        balance = self.choice(table["balance"], f"{where}.balance", BALANCES, "balance") \
            if "balance" in table else None
        stagger = read_stagger(table["stagger"], f"{where}.stagger", self.fail) if "stagger" in table \
            else self.stagger
        place = f"{where}.stagger" if "stagger" in table else "stagger"
        check_shape_stagger([keys[k] for k in real], stagger, place, lambda k: f"{where}.key[{real[k]}]", self.fail)
        return Shape(name=name, keys=keys, method=method, joints=joints, fill_rule=fill_rule, cap=cap, join=join,
                     unmatched=unmatched, balance=balance, stagger=stagger)

    def paint(self, table: dict[str, Any], where: str, base: Paint) -> Paint:
        """``base`` with the ``fill``, ``stroke``, ``stroke_width`` and ``opacity`` that ``table`` gives."""
        fill, stroke = base.fill, base.stroke
        if "fill" in table:
            fill = self.color_or_none(table["fill"], f"{where}.fill")
        if "stroke" in table:
            stroke = self.color_or_none(table["stroke"], f"{where}.stroke")
        width = base.stroke_width
        if "stroke_width" in table:
            width = self.number(table["stroke_width"], f"{where}.stroke_width", 0.0, 1000.0, "a width in pixels")
        opacity = base.opacity
        if "opacity" in table:
            opacity = self.number(table["opacity"], f"{where}.opacity", 0.0, 1.0, "an opacity")
        return Paint(fill, stroke, width, opacity)

    def joints(self, value: Any, where: str, vertices: int) -> tuple[tuple[int, int], ...]:
        from ..core.methods.joints import JointError, validate_joints

        items = self.listing(value, where, "a list of [a, b] vertex index pairs")
        joints = []
        for i, item in enumerate(items):
            pair = self.listing(item, f"{where}[{i}]", "an [a, b] vertex index pair")
            if len(pair) != 2:
                raise self.fail(f"{where}[{i}]", f"expected an [a, b] vertex index pair, found {describe(pair)}")
            joints.append(tuple(self.integer(v, f"{where}[{i}][{j}]", 0, vertices - 1,
                                             "a vertex index of the first key") for j, v in enumerate(pair)))
        try:
            validate_joints(vertices, joints)
        except JointError as error:
            raise self.fail(f"{where}[{error.index}]", str(error)) from None
        return tuple(joints)  # type: ignore[arg-type]

    def key(self, value: Any, where: str, closed: bool = True, defaults: Paint = Paint()) -> Key:
        table = self.table(value, where, _KEY)
        if "time" not in table:
            raise self.fail(where, "expected a time (seconds), found none")
        time = self.number(table["time"], f"{where}.time", 0.0, LIMITS["time"], "a time in seconds")
        steering = read_steering(table, where, self.fail, LIMITS["coordinate"])
        if "breakdown" in steering:
            for name in ("points", "contours", "hints", *_PAINT):
                if name in table:
                    raise self.fail(f"{where}.{name}", f"expected no {name} on a breakdown key (its shape is the "
                                                       "in-between of the keys around it), found some")
            text, easing = read_timing(table, where, self.fail, self.timing)
            return Key(time=time, contours=(), ease=text, paint=defaults, easing=easing, **steering)
        if "points" in table and "contours" in table:
            raise self.fail(f"{where}.contours", "expected either points or contours in a key, found both")
        if "points" in table:
            contours = self.outline(table["points"], f"{where}.points", closed)
        elif "contours" in table:
            items = self.listing(table["contours"], f"{where}.contours", "a list of contours, each a list of [x, y]")
            if not items:
                raise self.fail(f"{where}.contours", "expected at least one contour, found an empty list")
            contours = tuple(Contour(self.points(c, f"{where}.contours[{i}]", closed), closed)
                             for i, c in enumerate(items))
        else:
            raise self.fail(where, "expected points = [[x, y], ...] or contours = [[[x, y], ...], ...], found neither")
        text, easing = read_timing(table, where, self.fail, self.timing)
        if not closed and "fill" in table:
            raise self.fail(f"{where}.fill", "expected no fill on an open shape (closed = false)")
        hints = read_hints(table["hints"], f"{where}.hints", self.fail, LIMITS["coordinate"]) \
            if "hints" in table else {}
        contours, placed, self.moved[where] = pinned(contours, hints, f"{where}.hints", self.fail)
        return Key(time=time, contours=contours, ease=text, paint=self.paint(table, where, defaults),
                   easing=easing, hints=placed, **steering)

    def outline(self, value: Any, where: str, closed: bool) -> tuple[Contour, ...]:
        """``points``: a list of [x, y] (one contour) or ``{ svg, id }`` (every contour of that element)."""
        if isinstance(value, dict):
            return tuple(Contour(p, closed and shut) for p, shut in self.svg_contours(value, where))
        return (Contour(self.points(value, where, closed), closed),)


    def points(self, value: Any, where: str, closed: bool = True) -> np.ndarray:
        least = 3 if closed else 2
        what = f"a list of at least {least} [x, y] pairs"
        if isinstance(value, str) and value in self.arrays:  # finite pairs within range, as lifted
            array = self.arrays[value]
            if len(array) > LIMITS["vertices"]:
                raise self.fail(where, f"expected at most {LIMITS['vertices']} vertices, found {len(array)}")
            self.read_arrays.add(value)
            return frozen_points(array)
        items = self.listing(value, where, what + " or { svg = ..., id = ... }")
        if len(items) > LIMITS["vertices"]:
            raise self.fail(where, f"expected at most {LIMITS['vertices']} vertices, found {len(items)}")
        limit = LIMITS["coordinate"]
        coords = []
        for i, item in enumerate(items):
            if not isinstance(item, list) or len(item) != 2:
                raise self.fail(f"{where}[{i}]", f"expected an [x, y] pair, found {describe(item)}")
            coords.append([self.number(v, f"{where}[{i}][{j}]", -limit, limit, "a coordinate")
                           for j, v in enumerate(item)])
        if len(coords) < least:
            raise self.fail(where, f"expected {what}, found {len(coords)}")
        return frozen_points(coords)

    def svg_contours(self, value: dict[str, Any], where: str) -> list[tuple[np.ndarray, bool]]:
        from .svg import DEFAULT_TOLERANCE, SvgError, load_svg_contours

        table = self.table(value, where, _SVG)
        if "svg" not in table or "id" not in table:
            raise self.fail(where, "expected { svg = \"file.svg\", id = \"element\" }, "
                                   f"found keys {', '.join(table) or 'none'}")
        file = self.string(table["svg"], f"{where}.svg")
        element = self.string(table["id"], f"{where}.id")
        tolerance = self.number(table.get("tolerance", DEFAULT_TOLERANCE), f"{where}.tolerance",
                                1e-9, 1e6, "a tolerance in world units")
        self.sources.append(self.path.parent / file)
        try:
            contours = load_svg_contours(self.path.parent / file, element, tolerance)
        except SvgError as error:
            raise self.fail(where, str(error)) from None
        count = sum(len(points) for points, _ in contours)
        limit = LIMITS["coordinate"]
        if count > LIMITS["vertices"] or not all(np.all(np.abs(points) <= limit) for points, _ in contours):
            raise self.fail(where, f"the drawing gives {count} vertices; expected at most "
                                   f"{LIMITS['vertices']} within ±{limit:g}")
        return [(frozen_points(points), closed) for points, closed in contours]


def _renamed(shape: Shape, taken: dict[str, int]) -> Shape:
    """``shape`` under a name no ``[[shape]]`` has (a drawing's element named like one gets a suffix)."""
    from dataclasses import replace

    name, n = shape.name, 1
    while name in taken:
        n += 1
        name = f"{shape.name}-{n}"
    return shape if name == shape.name else replace(shape, name=name)


def fitted_size(box: tuple[float, float, float, float], most: tuple[int, int] = (1280, 720)) -> tuple[int, int]:
    """The largest even size within ``most`` with the aspect of world ``box`` (a drawing's default size)."""
    width, height = box[2] - box[0], box[3] - box[1]
    # by the aspect, never by most / width, which overflows for a subnormal box
    if width * most[1] >= height * most[0]:
        fit_width, fit_height = most[0], most[0] * (height / width)
    else:
        fit_width, fit_height = most[1] * (width / height), most[1]
    return (max(2, 2 * round(fit_width / 2)), max(2, 2 * round(fit_height / 2)))
