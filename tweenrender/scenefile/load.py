"""Read a scene file (TOML or JSON) into the frozen model, refusing anything malformed.

Every error names the file, the key path (and, for TOML, its line), what was
expected and what was found.
"""

from __future__ import annotations

import json
import math
import os
import stat
import tomllib
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from ..core.timing.easing import LINEAR, Easing, parse_easing
from ..core.methods.registry import METHODS, REGISTRY
from ..errors import SceneError, did_you_mean
from ..model import (ALIGNS, BALANCES, CAPS, COSTS, DEFAULT_BALANCE, DEFAULT_FILL, EQUAL_COUNTS, FILL_RULES,
                     JOINS, UNMATCHED, Color, Contour, Key, Matching, Paint, Scene, Shape, frozen_points)
from .controls import check_hints, check_shape_stagger, pinned, read_easing, read_hints, read_stagger, read_timing
from .locate import json_line_of, line_of

__all__ = ["load_scene", "parse_scene", "LIMITS"]

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
    "shapes": 10_000,      # in the scene, drawings' elements included
}

_TOP = ("title", "size", "fps", "background", "view", "method", "compare", "balance", "correspondence", "unmatched",
        "ease", "stagger", "shape", "drawing")
_PAINT = ("fill", "stroke", "stroke_width", "opacity")
_SHAPE = ("name", *_PAINT, "method", "joints", "balance", "fill_rule", "closed", "cap", "join", "unmatched", "stagger",
          "key")
_KEY = ("time", "points", "contours", "ease", "spacing", "hints", *_PAINT)
_DRAWING = ("time", "svg", "ease", "spacing", "hints", "stagger", "tolerance")
_SVG = ("svg", "id", "tolerance")
_MATCHING = ("cost", "align", "equal_counts", "ks", "cs", "es", "kb", "eb", "mb", "pb")


_KINDS = ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a pipe (FIFO)"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"))


def load_scene(path: str | Path | Sequence[str | Path], step: float = 1.0, ease: str = "linear",
               hold: float = 0.0, stagger: float = 0.0) -> Scene:
    """Read and validate the scene at ``path`` (``.json`` is JSON, ``.svg`` one drawing, anything else
    TOML), or build one from a list of SVG drawings: each shown ``hold`` seconds, then moving for
    ``step`` seconds to the next under ``ease``, its elements ``stagger`` seconds apart."""
    if not isinstance(path, (str, Path)):
        return drawings_scene([Path(p) for p in path], step, ease, hold, stagger)
    if Path(path).suffix.lower() == ".svg":
        return drawings_scene([Path(path)], step, ease, hold, stagger)
    path = Path(path)
    limit = LIMITS["file_bytes"]
    try:
        mode = path.stat().st_mode
        # a pipe or a device would block or never end: only regular files are read
        for test, kind in _KINDS:
            if test(mode):
                raise SceneError(path, None, f"is {kind}, expected a scene file (.toml or .json)")
        # O_NONBLOCK: should the path turn into a FIFO after the check, open must not wait for a writer
        descriptor = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(descriptor, "rb") as file:
            raw = file.read(limit + 1)  # bounded even if the file grows while read
    except FileNotFoundError:
        raise SceneError(path, None, "no such file") from None
    except PermissionError:
        raise SceneError(path, None, "cannot be read (permission denied)") from None
    except OSError as error:
        raise SceneError(path, None, f"cannot be read ({error.strerror or error})") from None
    if len(raw) > limit:
        raise SceneError(path, None, f"expected a scene of at most {limit >> 20} MiB, found a larger file")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as error:
        line = raw[: error.start].count(b"\n") + 1
        raise SceneError(path, f"line {line}", f"expected UTF-8 text, found byte 0x{raw[error.start]:02x} "
                                               f"(at byte {error.start})") from None
    text = text.removeprefix("\ufeff")  # a byte order mark, as some editors write UTF-8
    return parse_scene(text, path, "json" if path.suffix.lower() == ".json" else "toml")


def drawings_scene(paths: Sequence[Path], step: float = 1.0, ease: str = "linear", hold: float = 0.0,
                   stagger: float = 0.0) -> Scene:
    """A scene of whole drawings, one key every ``hold + step`` seconds: what ``tweenrender render a.svg
    b.svg`` renders (see :func:`load_scene`). The view is the first drawing's view box, the size fitted to
    it within 1280 × 720."""
    from .drawings import DrawingKey, drawing_shapes, read_drawings

    if not paths:
        raise SceneError(None, None, "expected at least one SVG drawing, found none")
    if not (isinstance(step, (int, float)) and math.isfinite(step) and 0 < step <= LIMITS["time"] / len(paths)):
        raise SceneError(None, None, f"expected a step of seconds between drawings above 0, found {step!r}")
    for name, value in (("hold", hold), ("stagger", stagger)):
        if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value) \
                or not 0 <= value <= LIMITS["time"] / len(paths):
            raise SceneError(None, None, f"expected a {name} of seconds from 0, found {value!r}")
    try:
        easing = parse_easing(ease) if isinstance(ease, str) else None
    except ValueError as error:
        raise SceneError(None, None, str(error)) from None
    if easing is None:
        raise SceneError(None, None, f"expected an easing name or curve, found {ease!r}")
    for path in paths:
        if path.suffix.lower() != ".svg":
            raise SceneError(path, None, "expected an SVG drawing (.svg) among several drawings")
    period = float(step) + float(hold)
    keys = [DrawingKey(path, i * period, easing.text, easing=easing, stagger=float(stagger), hold=float(hold))
            for i, path in enumerate(paths)]
    drawings, box = read_drawings(keys)
    shapes = tuple(drawing_shapes(drawings, keys, "grow", _drawing_fail(paths)))
    if not shapes:
        raise SceneError(paths[0], None, "expected at least one visible shape in the drawings, found none")
    scene = Scene(shapes=shapes, size=fitted_size(box), view=box, method="auto", path=paths[0],
                  sources=tuple(dict.fromkeys(paths)), end_hold=float(hold) if len(paths) > 1 else 0.0)
    reader = _Reader(paths[0], "", "toml")
    reader.counts(len(shapes), sum(len(shape.keys) for shape in shapes))
    reader.matching_effort(shapes, scene.matching)
    return scene


def _drawing_fail(paths: Sequence[Path]) -> Callable[[str, str], SceneError]:
    """Errors of drawings given as files: ``drawing[k]...`` is told as drawing k's own file."""
    def fail(where: str, message: str) -> SceneError:
        head, _, rest = where.partition("]")
        index = int(head.removeprefix("drawing[")) if head.startswith("drawing[") else 0
        return SceneError(paths[index], rest.lstrip(".") or None, message)
    return fail


def _refuse_duplicates(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """JSON object hook: a repeated key would silently drop a value, so it is an error."""
    table: dict[str, Any] = {}
    for key, value in pairs:
        if key in table:
            raise _DuplicateKey(key)
        table[key] = value
    return table


class _DuplicateKey(ValueError):
    def __init__(self, key: str) -> None:
        super().__init__(key)
        self.key = key


def parse_scene(text: str, path: str | Path, fmt: str = "toml") -> Scene:
    """Validate scene ``text`` (``fmt`` ``"toml"`` or ``"json"``); ``path`` names it in errors."""
    path = Path(path)
    # a cheap count before parsing: each [x, y] pair opens one bracket (so do a few headers)
    pairs, most = text.count("["), LIMITS["vertices_total"] + 1000
    if pairs > most:
        raise SceneError(path, None, f"expected at most {LIMITS['vertices_total']} [x, y] pairs in one scene, "
                                     f"found about {pairs} (count of '[')")
    if fmt == "json":
        try:
            data = json.loads(text, object_pairs_hook=_refuse_duplicates)
        except json.JSONDecodeError as error:
            raise SceneError(path, f"line {error.lineno}", f"not valid JSON: {error.msg}") from None
        except _DuplicateKey as error:
            raise SceneError(path, None, f"not valid JSON: expected each key once per object, "
                                         f"found {error.key!r} twice") from None
        except RecursionError:
            raise SceneError(path, None, "not valid JSON: nested too deeply") from None
        except ValueError as error:  # e.g. an integer of more than 4300 digits
            raise SceneError(path, None, f"not valid JSON: {error}") from None
    else:
        from .point_arrays import lift_point_arrays

        lifted_text, arrays = lift_point_arrays(text, LIMITS["coordinate"])
        if arrays:
            try:
                reader = _Reader(path, text, fmt, arrays)
                scene = reader.scene(tomllib.loads(lifted_text))
                if not arrays.keys() - reader.read_arrays:
                    return scene
            except (tomllib.TOMLDecodeError, SceneError, RecursionError, ValueError):
                pass  # read again as written: the lifting never changes what a scene means or how it fails
        try:
            data = tomllib.loads(text)
        except tomllib.TOMLDecodeError as error:
            message = str(error)
            where = None
            if "(at line " in message:
                message, _, rest = message.rpartition(" (at line ")
                where = "line " + rest.split(",")[0].rstrip(")")
            elif "(at end of document)" in message:
                message, where = message.replace(" (at end of document)", ""), "end of file"
            raise SceneError(path, where, f"not valid TOML: {message}") from None
        except RecursionError:
            raise SceneError(path, None, "not valid TOML: nested too deeply") from None
        except ValueError as error:  # e.g. an integer of more than 4300 digits
            raise SceneError(path, None, f"not valid TOML: {error}") from None
    return _Reader(path, text, fmt).scene(data)


def _short(value: Any) -> str:
    """A repr short enough for a one-line message (huge integers included)."""
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 10**30:
        return f"an integer of {len(str(abs(value))) if abs(value).bit_length() < 14000 else 'over 4000'} digits"
    shown = repr(value)
    return shown if len(shown) <= 40 else shown[:37] + "..."


def _describe(value: Any) -> str:
    """How a found value reads in a message: its kind and a short repr."""
    kinds = {bool: "a boolean", int: "a number", float: "a number", str: "a string", type(None): "null"}
    if isinstance(value, dict):
        return f"a table of {len(value)} key{'s' * (len(value) != 1)}"
    if isinstance(value, list):
        if value and all(isinstance(v, dict) for v in value):
            return f"an array of {len(value)} table{'s' * (len(value) != 1)}"
        return f"a list of {len(value)} item{'s' * (len(value) != 1)}"
    kind = kinds.get(type(value), type(value).__name__)
    return f"{kind} {_short(value)}"


class _Reader:
    """Validates one parsed document; knows where it came from for messages."""

    def __init__(self, path: Path, text: str, fmt: str, arrays: dict[str, np.ndarray] | None = None) -> None:
        self.path = path
        self.text = text
        self.arrays = arrays or {}  # points arrays read ahead by numpy (point_arrays), by the string standing for each
        self.read_arrays: set[str] = set()
        self.locate = json_line_of if fmt == "json" else line_of
        self.timing: tuple[str, Easing] = ("linear", LINEAR)  # the scene's ease: every key's default
        self.stagger = 0.0
        self.moved: dict[str, list[np.ndarray]] = {}  # key path -> where hints moved its contours' vertices
        self.sources: list[Path] = []  # files the scene refers to, in the order they are read

    def fail(self, where: str, message: str) -> SceneError:
        line = self.locate(self.text, where) if where else None
        place = f"{where} (line {line})" if line else where
        return SceneError(self.path, place or None, message)

    # -- typed readers -------------------------------------------------------
    def table(self, value: Any, where: str, allowed: tuple[str, ...]) -> dict[str, Any]:
        if not isinstance(value, dict):
            raise self.fail(where, f"expected a table, found {_describe(value)}")
        for key in value:
            if key not in allowed:
                at = f"{where}.{key}" if where else str(key)
                raise self.fail(at, f"unknown key {_short(key)}{did_you_mean(str(key), allowed)}; "
                                    f"expected one of {', '.join(allowed)}")
        return value

    def number(self, value: Any, where: str, low: float = -math.inf, high: float = math.inf,
               what: str = "a number") -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise self.fail(where, f"expected {what}, found {_describe(value)}")
        try:
            number = float(value)
        except OverflowError:  # an integer beyond float range
            number = math.inf
        if not math.isfinite(number):
            raise self.fail(where, f"expected {what} (finite), found {_short(value)}")
        if not low <= number <= high:
            raise self.fail(where, f"expected {what} from {low:g} to {high:g}, found {_short(value)}")
        return number

    def integer(self, value: Any, where: str, low: int, high: int, what: str) -> int:
        if isinstance(value, bool) or not isinstance(value, int):
            if isinstance(value, float) and value.is_integer():
                value = int(value)
            else:
                raise self.fail(where, f"expected {what}, found {_describe(value)}")
        if not low <= value <= high:
            raise self.fail(where, f"expected {what} from {low} to {high}, found {_short(value)}")
        return value

    def string(self, value: Any, where: str) -> str:
        if not isinstance(value, str):
            raise self.fail(where, f"expected a string, found {_describe(value)}")
        return value

    def choice(self, value: Any, where: str, choices: tuple[str, ...], what: str) -> str:
        word = self.string(value, where)
        if word not in choices:
            raise self.fail(where, f"unknown {what} {_short(word)}{did_you_mean(word, choices)}; "
                                   f"expected one of {', '.join(choices)}")
        return word

    def listing(self, value: Any, where: str, what: str) -> list[Any]:
        if not isinstance(value, list):
            raise self.fail(where, f"expected {what}, found {_describe(value)}")
        return value

    def color(self, value: Any, where: str) -> Color:
        return parse_color(self.string(value, where), lambda msg: self.fail(where, msg))

    # -- the document ----------------------------------------------------------
    def scene(self, data: Any) -> Scene:
        top = self.table(data, "", _TOP)
        canvas = LIMITS["canvas"]
        size: tuple[int, int] = (1280, 720)
        if "size" in top:
            pair = self.listing(top["size"], "size", "[width, height] in pixels")
            if len(pair) != 2:
                raise self.fail("size", f"expected [width, height] in pixels, found {_describe(pair)}")
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
        keys_raw = sum(len(raw["key"]) for raw in shapes_raw if isinstance(raw, dict) and isinstance(raw.get("key"), list))
        self.counts(len(shapes_raw), keys_raw + len(drawings_raw))
        shapes = tuple(self.shape(raw, f"shape[{i}]", i) for i, raw in enumerate(shapes_raw))
        names: dict[str, int] = {}
        for i, shape in enumerate(shapes):
            if shape.name in names:
                raise self.fail(f"shape[{i}].name", f"expected a unique name, found {_short(shape.name)} "
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
        self.counts(len(shapes), sum(len(shape.keys) for shape in shapes))
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
        self.matching_effort(shapes, matching)
        balance = self.choice(top.get("balance", DEFAULT_BALANCE), "balance", BALANCES, "balance")
        return Scene(shapes=shapes, title=title, size=size, fps=fps, background=background, view=view,
                     method=method, compare=compare, matching=matching, path=self.path, unmatched=unmatched,
                     balance=balance, sources=tuple(dict.fromkeys((self.path, *self.sources))))

    def counts(self, shapes: int, keys: int) -> None:
        """Refuse more shapes or keys than :data:`LIMITS` allows, before they are matched or drawn."""
        for count, what, where in ((shapes, "shapes", "shape"), (keys, "keys", "shape")):
            if count > LIMITS[what]:
                raise self.fail(where, f"expected at most {LIMITS[what]} {what} in the scene, found {count}")

    def drawings(self, items: list[Any], unmatched: str) -> tuple[tuple[Shape, ...], tuple[float, float, float, float]]:
        """``[[drawing]]`` keys: whole SVG files at times; their shapes and the first drawing's view box."""
        from .drawings import DrawingKey, drawing_shapes, read_drawings
        from .svg import SvgError

        keys = []
        for i, raw in enumerate(items):
            where = f"drawing[{i}]"
            table = self.table(raw, where, _DRAWING)
            if "time" not in table or "svg" not in table:
                raise self.fail(where, "expected time = seconds and svg = \"file.svg\", found "
                                       f"{', '.join(table) or 'no keys'}")
            time = self.number(table["time"], f"{where}.time", 0.0, LIMITS["time"], "a time in seconds")
            if keys and time <= keys[-1].time:
                raise self.fail(f"{where}.time", f"expected a time after {keys[-1].time:.15g} "
                                                 f"(times strictly increase), found {time:.15g}")
            file = self.path.parent / self.string(table["svg"], f"{where}.svg")
            text, easing = read_timing(table, where, self.fail, self.timing)
            tolerance = None
            if "tolerance" in table:
                tolerance = self.number(table["tolerance"], f"{where}.tolerance", 1e-9, 1e6,
                                        "a tolerance in world units")
            hints = read_hints(table["hints"], f"{where}.hints", self.fail, LIMITS["coordinate"]) \
                if "hints" in table else {}
            stagger = read_stagger(table["stagger"], f"{where}.stagger", self.fail) \
                if "stagger" in table else self.stagger
            keys.append(DrawingKey(file, time, text, tolerance, easing=easing, hints=hints, stagger=stagger))
            self.sources.append(file)
        try:
            drawings, box = read_drawings(keys)
        except SvgError as error:
            index = next(i for i, key in enumerate(keys) if str(key.path) == error.path)
            raise self.fail(f"drawing[{index}].svg", str(error)) from None
        return tuple(drawing_shapes(drawings, keys, unmatched, self.fail)), box

    def background(self, value: Any, where: str) -> Color:
        """A colour, or ``none`` for a transparent background."""
        if isinstance(value, str) and value.strip().lower() == "none":
            return (0, 0, 0, 0)
        return self.color(value, where)

    def matching_effort(self, shapes: tuple[Shape, ...], matching: Matching) -> None:
        """Refuse key pairs whose correspondence search would run for minutes (see ``LIMITS``)."""
        cost = matching.cost
        for i, shape in enumerate(shapes):
            for k in range(1, len(shape.keys)):
                counts_a = [len(c.points) for c in shape.keys[k - 1].contours]
                counts_b = [len(c.points) for c in shape.keys[k].contours]
                m, n = max(counts_a), max(counts_b)
                equal = shape.equal_counts or matching.equal_counts
                hinted = bool(shape.keys[k - 1].hints and shape.keys[k].hints)
                if len(counts_a) == len(counts_b) == 1 and m == n and equal == "drawn" and not hinted:
                    continue  # equal counts keep the drawn order: no search
                effort, limit = (m * n * max(m, n), LIMITS["match_sg"]) if cost == "sg" else \
                                (m * n, LIMITS["match_cells"])
                if effort > limit:
                    raise self.fail(f"shape[{i}].key[{k}].points",
                                    f"expected keys the {cost!r} correspondence can match in seconds "
                                    f"(a size of at most {limit:.0e}), found {m} vertices then {n} "
                                    f"(size {effort:.1e}); use fewer vertices, equal counts"
                                    + (", or cost = \"distance\"" if cost == "sg" else ""))

    def view(self, value: Any) -> tuple[float, float, float, float]:
        box = self.listing(value, "view", "[xmin, ymin, xmax, ymax]")
        if len(box) != 4:
            raise self.fail("view", f"expected [xmin, ymin, xmax, ymax], found {_describe(box)}")
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
        check_hints(keys, lambda k: f"{where}.key[{k}]", self.fail)
        if not closed and not any(key.paint.stroke is not None for key in keys):
            raise self.fail(where, "expected a stroke on an open shape (closed = false), found none: "
                                   "add stroke = \"#rrggbb\"")
        method = None
        if "method" in table:
            method = self.choice(table["method"], f"{where}.method", METHODS, "method")
        joints: tuple[tuple[int, int], ...] = ()
        if "joints" in table:
            several = [k for k, key in enumerate(keys) if len(key.contours) != 1 or not key.contours[0].closed]
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
        check_shape_stagger(keys, stagger, place, lambda k: f"{where}.key[{k}]", self.fail)
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
                raise self.fail(f"{where}[{i}]", f"expected an [a, b] vertex index pair, found {_describe(pair)}")
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
                   easing=easing, hints=placed)

    def outline(self, value: Any, where: str, closed: bool) -> tuple[Contour, ...]:
        """``points``: a list of [x, y] (one contour) or ``{ svg, id }`` (every contour of that element)."""
        if isinstance(value, dict):
            return tuple(Contour(p, closed and shut) for p, shut in self.svg_contours(value, where))
        return (Contour(self.points(value, where, closed), closed),)

    def boolean(self, value: Any, where: str) -> bool:
        if not isinstance(value, bool):
            raise self.fail(where, f"expected true or false, found {_describe(value)}")
        return value

    def color_or_none(self, value: Any, where: str) -> Color | None:
        if isinstance(value, str) and value.strip().lower() == "none":
            return None
        return self.color(value, where)

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
                raise self.fail(f"{where}[{i}]", f"expected an [x, y] pair, found {_describe(item)}")
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
    scale = min(most[0] / width, most[1] / height)
    return (max(2, 2 * round(width * scale / 2)), max(2, 2 * round(height * scale / 2)))


def parse_color(text: str, fail: Callable[[str], Exception]) -> Color:
    """``#rgb``, ``#rgba``, ``#rrggbb`` or ``#rrggbbaa`` → straight RGBA 0..255."""
    digits = text[1:] if text.startswith("#") else None
    if digits is None or len(digits) not in (3, 4, 6, 8) or any(c not in "0123456789abcdefABCDEF" for c in digits):
        raise fail(f"expected a colour #rgb, #rgba, #rrggbb or #rrggbbaa, found {_short(text)}")
    if len(digits) in (3, 4):
        digits = "".join(c * 2 for c in digits)
    if len(digits) == 6:
        digits += "ff"
    r, g, b, a = (int(digits[i:i + 2], 16) for i in range(0, 8, 2))
    return (r, g, b, a)
