"""Read a scene file (TOML or JSON), one SVG drawing or several into the frozen model, refusing anything
malformed (:mod:`.scene_reader` reads the document, :mod:`.scene_limits` bounds it).

Every error names the file, the key path (and, for TOML, its line), what was
expected and what was found.
"""

from __future__ import annotations

import json
import math
import os
import re
import stat
import sys
import tomllib
from pathlib import Path
from typing import TYPE_CHECKING, Any, Sequence

from ..core.timing.easing import parse_easing
from ..errors import SceneError
from ..model import Scene, Shape
from .controls import Fail
from .scene_limits import LIMITS, check_counts, check_matching_effort
from .scene_reader import SceneReader, fitted_size

if TYPE_CHECKING:
    from .drawings import DrawingKey

__all__ = ["load_scene", "parse_scene", "drawings_scene", "LIMITS"]

_KINDS = ((stat.S_ISDIR, "a folder"), (stat.S_ISFIFO, "a pipe (FIFO)"), (stat.S_ISCHR, "a character device"),
          (stat.S_ISBLK, "a block device"), (stat.S_ISSOCK, "a socket"))


def load_scene(path: str | Path | Sequence[str | Path], step: float = 1.0, ease: str = "linear",
               hold: float = 0.0, stagger: float = 0.0) -> Scene:
    """Read and validate the scene at ``path`` (``.json`` is JSON — a scene, or a Lottie animation by its
    content —, ``.svg`` one drawing, anything else TOML), or build one from a list of SVG drawings: each shown ``hold`` seconds, then moving for
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
    shapes = tuple(drawing_shapes(drawings, keys, "grow", _drawing_fail(paths)))  # none: drawings of nothing
    scene = Scene(shapes=shapes, size=fitted_size(box), view=box, method="auto", path=paths[0],
                  sources=tuple(dict.fromkeys(paths)), end_hold=float(hold) if len(paths) > 1 else 0.0)

    def fail(where: str, message: str) -> SceneError:
        return SceneError(paths[0], where or None, message)

    check_counts(len(shapes), sum(len(shape.keys) for shape in shapes), fail)
    _check_contours(shapes, keys, paths)
    check_matching_effort(shapes, scene.matching, fail)
    return scene


def _check_contours(shapes: tuple[Shape, ...], keys: Sequence[DrawingKey], paths: Sequence[Path]) -> None:
    """Refuse an element of more contours than :data:`LIMITS` allows, naming its drawing and element."""
    for shape in shapes:
        for key in shape.keys:
            if len(key.contours) > LIMITS["contours"]:
                drawing = min(range(len(keys)), key=lambda k: abs(keys[k].time - key.time))
                raise SceneError(paths[drawing], None, f"element {shape.name!r}: expected at most {LIMITS['contours']} "
                                                       f"contours in a key, found {len(key.contours)}")


def _drawing_fail(paths: Sequence[Path]) -> Fail:
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


def _in_scene_words(error: ValueError) -> str:
    """A parser's ValueError as a scene's message: Python's refusal of a very long integer names the
    limit, not the interpreter setting that lifts it."""
    found = re.search(r"value has (\d+) digits", str(error))
    if found:
        return (f"expected integers of at most {sys.get_int_max_str_digits()} digits, "
                f"found one of {found.group(1)} digits")
    return str(error)


def parse_scene(text: str, path: str | Path, fmt: str = "toml") -> Scene:
    """Validate scene ``text`` (``fmt`` ``"toml"`` or ``"json"``; JSON whose top level has ``v``, ``fr``,
    ``ip``, ``op`` and ``layers`` is a Lottie animation, :mod:`.lottie_reader`); ``path`` names it in errors."""
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
            raise SceneError(path, None, f"not valid JSON: {_in_scene_words(error)}") from None
        from .lottie_reader import is_lottie

        if is_lottie(data):
            from .lottie_reader import lottie_scene

            return lottie_scene(data, path)
    else:
        from .point_arrays import lift_point_arrays

        lifted_text, arrays = lift_point_arrays(text, LIMITS["coordinate"])
        if arrays:
            try:
                reader = SceneReader(path, text, fmt, arrays)
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
            raise SceneError(path, None, f"not valid TOML: {_in_scene_words(error)}") from None
    return SceneReader(path, text, fmt).scene(data)
