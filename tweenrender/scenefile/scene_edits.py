"""The preview's edits applied to a scene file's TOML text, keeping every comment and the layout (tomlkit).

An edit is a list of ops (DESIGN, "The preview edits"), each naming a key by ``shape`` (a ``[[shape]]``'s
name; in a scene of ``[[drawing]]`` s, any element id: hints, arcs and the rest belong to the drawing)
and ``key`` (its index). Only the tables an op names are touched; what the ops write is checked by
the loader afterwards, not here: this module checks only that each op is one.
"""

from __future__ import annotations

import math
import re
from pathlib import Path
from typing import Any, Callable, Sequence

import numpy as np

from ..core.contours import nearest_point
from ..errors import SceneError
from .scene_writer import drawings_toml

__all__ = ["OPS", "apply_edits", "breakdown_segment", "drawings_scene_text", "written_tables"]

OPS = ("hint", "unhint", "arc", "turn", "ease", "breakdown", "bake")
TURNS = ("cw", "ccw", "shortest")
_LETTER = re.compile(r"[a-z]")
_DIGITS = 9  # significant digits written for a coordinate a click gave

Contours = list[list[list[float]]]
Bake = Callable[[str, int], Contours]
"""``bake(shape, key)``: the breakdown key's contours (lists of [x, y]) as the loader would make them."""


def apply_edits(text: str, path: Path, ops: object, bake: Bake | None = None) -> str:
    """``text`` (a TOML scene) with ``ops`` applied; a :class:`SceneError` naming ``ops[i]`` for an op
    that is not one (an unknown shape, a key out of range, a letter that is not a–z)."""
    import tomlkit
    from tomlkit.exceptions import TOMLKitError

    if not isinstance(ops, list) or not ops:
        raise SceneError(path, "ops", "expected a list of edits, e.g. [{\"op\": \"hint\", ...}]")
    try:
        document = tomlkit.parse(text)
    except TOMLKitError as error:
        raise SceneError(path, None, f"not valid TOML: {error}") from None
    for index, op in enumerate(ops):
        _Op(document, path, f"ops[{index}]", op, bake).apply()
    return tomlkit.dumps(document)


def written_tables(path: Path | None) -> dict[str, Any]:
    """The TOML scene file ``path`` as written (plain tables), or {} (no file, not TOML, unreadable)."""
    import tomllib

    if path is None or path.suffix.lower() not in (".toml", ""):
        return {}
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        return {}


def breakdown_segment(text: str, path: Path, shape: str, key: int) -> tuple[str, float, float, float]:
    """For the breakdown key ``key`` of ``shape``: the scene without it, and its segment made plain (no
    ease, spacing or arcs on the key before it), the favour and the times of the keys around it."""
    import tomlkit

    document = tomlkit.parse(text)
    keys = _Op(document, path, "bake", {"op": "bake", "shape": shape, "key": key}, None).keys()
    table = keys[key]
    if "breakdown" not in table:
        raise SceneError(path, f"{_where(document, shape, key)}", "expected a breakdown key (breakdown = f) to bake")
    if not 0 < key < len(keys) - 1:
        raise SceneError(path, _where(document, shape, key), "expected a breakdown between two keys")
    favour = float(table["breakdown"])
    before, after = keys[key - 1], keys[key + 1]
    for name in ("ease", "spacing", "arcs"):
        if name in before:
            del before[name]
    t0, t1 = float(before["time"]), float(after["time"])
    del keys[key]
    return tomlkit.dumps(document), favour, t0, t1


def drawings_scene_text(svgs: Sequence[Path], folder: Path, step: float = 1.0, ease: str = "linear",
                        hold: float = 0.0, stagger: float = 0.0) -> str:
    """The ``[[drawing]]`` scene (TOML) of ``svgs`` that ``init`` writes (:func:`.scene_writer.drawings_toml`),
    file names relative to ``folder``, where the scene is saved."""
    return drawings_toml(svgs, folder, step, ease, hold, stagger)


class _Op:
    """One op, checked and applied to the parsed ``document``."""

    def __init__(self, document: Any, path: Path, where: str, op: object, bake: Bake | None) -> None:
        self.document, self.path, self.where, self.bake = document, path, where, bake
        if not isinstance(op, dict):
            raise self.fail("", "expected an edit as an object, e.g. {\"op\": \"hint\", ...}")
        self.op = op
        self.kind = op.get("op")
        if self.kind not in OPS:
            raise self.fail(".op", f"expected one of {', '.join(OPS)}, found {str(self.kind)[:40]!r}")
        self.shape = op.get("shape")
        if not isinstance(self.shape, str):
            raise self.fail(".shape", "expected a shape's name or an element's id")
        self.index = op.get("key")
        if isinstance(self.index, bool) or not isinstance(self.index, int):
            raise self.fail(".key", "expected a key's index")

    def fail(self, field: str, message: str) -> SceneError:
        return SceneError(self.path, f"{self.where}{field}", message)

    def keys(self) -> Any:
        """The array of key tables the op's ``shape`` names: its ``[[shape.key]]`` s or the ``[[drawing]]`` s."""
        for shape in self.document.get("shape", []):
            if shape.get("name") == self.shape:
                if "key" not in shape:
                    raise self.fail(".shape", f"shape {self.shape!r} has no [[shape.key]] tables")
                self.table_path = f"shape[{self.document['shape'].index(shape)}].key"
                return shape["key"]
        if "drawing" in self.document:
            self.table_path = "drawing"
            return self.document["drawing"]
        raise self.fail(".shape", f"no shape named {self.shape[:40]!r} in the scene")

    def apply(self) -> None:
        keys = self.keys()
        if not 0 <= self.index < len(keys):
            raise self.fail(".key", f"expected a key index from 0 to {len(keys) - 1}, found {self.index}")
        getattr(self, f"_{self.kind}")(keys, keys[self.index])

    # -- the ops ---------------------------------------------------------------------------------

    def _hint(self, keys: Any, table: Any) -> None:
        self._set_letter(table, "hints", self._letter(), self._point())

    def _unhint(self, keys: Any, table: Any) -> None:
        letter = self._letter()
        hints = table.get("hints")
        if hints is None or letter not in hints:
            raise self.fail(".letter", f"this key has no hint {letter}")
        del hints[letter]
        if not hints:
            del table["hints"]
        arcs = table.get("arcs")
        if arcs is not None and letter in arcs:  # an arc belongs to its hint
            del arcs[letter]
            if not arcs:
                del table["arcs"]

    def _arc(self, keys: Any, table: Any) -> None:
        letter = self._letter()
        if self.op.get("point") is None:
            arcs = table.get("arcs")
            if arcs is not None and letter in arcs:
                del arcs[letter]
                if not arcs:
                    del table["arcs"]
            return
        self._set_letter(table, "arcs", letter, self._point())

    def _turn(self, keys: Any, table: Any) -> None:
        turn = self.op.get("turn")
        if turn not in TURNS:
            raise self.fail(".turn", f"expected one of {', '.join(TURNS)}, found {str(turn)[:20]!r}")
        turns = self.op.get("turns", 0)
        if isinstance(turns, bool) or not isinstance(turns, int) or turns < 0:
            raise self.fail(".turns", f"expected a whole number of extra turns ≥ 0, found {str(turns)[:20]!r}")
        if turn == "shortest" and turns == 0:
            for name in ("turn", "turns"):
                if name in table:
                    del table[name]
            return
        table["turn"] = turn
        if turns:
            table["turns"] = turns
        elif "turns" in table:
            del table["turns"]

    def _ease(self, keys: Any, table: Any) -> None:
        ease = self.op.get("ease")
        if not isinstance(ease, str) or not ease.strip() or len(ease) > 200:
            raise self.fail(".ease", "expected an easing such as \"in-out\" or \"cubic-bezier(0.2, 0, 0.2, 1)\"")
        if "spacing" in table:  # a key has an ease or a spacing chart, never both
            del table["spacing"]
        table["ease"] = ease

    def _breakdown(self, keys: Any, table: Any) -> None:
        import tomlkit

        favour = self.op.get("breakdown")
        if isinstance(favour, bool) or not isinstance(favour, (int, float)) or not math.isfinite(favour):
            raise self.fail(".breakdown", "expected a favour as a number (0 the key before, 1 the key after)")
        if "time" not in self.op:
            if "breakdown" not in table:
                raise self.fail(".key", "expected a breakdown key to change its favour, or a time to insert one")
            table["breakdown"] = _number(favour)
            return
        time = self.op.get("time")
        if isinstance(time, bool) or not isinstance(time, (int, float)) or not math.isfinite(time):
            raise self.fail(".time", "expected the breakdown's time in seconds")
        entry = tomlkit.table()
        entry["time"] = _number(time)
        entry["breakdown"] = _number(favour)
        keys.insert(self.index + 1, entry)

    def _bake(self, keys: Any, table: Any) -> None:
        import tomlkit

        if "breakdown" not in table:
            raise self.fail(".key", "expected a breakdown key (breakdown = f) to bake into points")
        if self.table_path == "drawing":
            raise self.fail(".shape", "a drawing's breakdown has no points to bake into; bake a [[shape]]'s")
        if self.bake is None:
            raise self.fail("", "baking needs the scene's in-betweens")
        contours = self.bake(self.shape, self.index)
        f = float(table["breakdown"])
        del table["breakdown"]
        if len(contours) == 1:
            table["points"] = _points_array(contours[0])
        else:
            table["contours"] = tomlkit.array([_points_array(c) for c in contours])
        # a letter on both keys around it stays hinted through the baked key: where the baked outline
        # comes nearest the point between its two places at the favour
        before, after = keys[self.index - 1], keys[self.index + 1]
        shared = sorted(set(before.get("hints", {})) & set(after.get("hints", {})))
        if shared:
            hints = tomlkit.inline_table()
            for letter in shared:
                a, b = (np.asarray(k["hints"][letter], dtype=np.float64) for k in (before, after))
                hints[letter] = [_number(v) for v in nearest_point((1.0 - f) * a + f * b, [np.asarray(c, dtype=np.float64) for c in contours], [True] * len(contours))]
            table["hints"] = hints

    # -- values -----------------------------------------------------------------------------------

    def _letter(self) -> str:
        letter = self.op.get("letter")
        if not isinstance(letter, str) or not _LETTER.fullmatch(letter):
            raise self.fail(".letter", f"expected a hint letter a–z, found {str(letter)[:20]!r}")
        return letter

    def _point(self) -> list[float]:
        point = self.op.get("point")
        if not isinstance(point, list) or len(point) != 2 or not all(
                isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v) for v in point):
            raise self.fail(".point", "expected [x, y] in the key's units")
        return [_number(v) for v in point]

    def _set_letter(self, table: Any, name: str, letter: str, point: list[float]) -> None:
        import tomlkit

        letters = table.get(name)
        if letters is None:
            letters = tomlkit.inline_table()
            table[name] = letters
        letters[letter] = point


def _number(value: float) -> float | int:
    """``value`` as few digits as a click means: integers stay integers."""
    if float(value).is_integer() and abs(value) < 2**53:
        return int(value)
    return float(f"{value:.{_DIGITS}g}")


def _points_array(points: list[list[float]]) -> Any:
    import tomlkit

    array = tomlkit.array()
    for x, y in points:
        array.append([_number(x), _number(y)])
    return array


def _where(document: Any, shape: str, key: int) -> str:
    for index, table in enumerate(document.get("shape", [])):
        if table.get("name") == shape:
            return f"shape[{index}].key[{key}]"
    return f"drawing[{key}]"
