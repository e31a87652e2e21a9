"""Edits of a scene file checked by the loader before anything is written, and what an editor shows of
a scene: every key's outlines, hints, arcs and timing, and where scene units fall on the picture.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import SceneError
from ..model import Scene

__all__ = ["edited_scene_text", "save_scene_text", "editing_state"]

_FIELDS = ("time", "ease", "spacing", "hints", "arcs", "turn", "turns", "breakdown")


def edited_scene_text(text: str, path: Path, ops: object) -> str:
    """``text`` with ``ops`` applied, once the loader accepts the result; else the loader's
    :class:`SceneError` (its one line), and nothing is written anywhere."""
    from ..scenefile import parse_scene
    from ..scenefile.scene_edits import apply_edits

    if path.suffix.lower() == ".json":
        raise SceneError(path, None, "the preview edits TOML scenes; this one is JSON")

    def bake(shape: str, key: int) -> list[list[list[float]]]:
        return _baked(text, path, shape, key)

    edited = apply_edits(text, path, ops, bake)
    parse_scene(edited, path, "toml")
    return edited


def save_scene_text(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` atomically: a hidden sibling first, moved over ``path`` when complete."""
    from ..encode.atomic import sibling

    part = sibling(path)
    try:
        with open(part, "x", encoding="utf-8", newline="") as file:
            file.write(text)
            file.flush()
            os.fsync(file.fileno())
        os.replace(part, path)
    except OSError as error:
        part.unlink(missing_ok=True)
        raise SceneError(path, None, f"cannot be written ({error.strerror or error})") from None


def _baked(text: str, path: Path, shape: str, key: int) -> list[list[list[float]]]:
    """The contours of breakdown key ``key`` of ``shape``: its segment's in-between at its favour, under
    the shape's method, correspondence and hints, with no easing (SPEC §5.15)."""
    from ..scenefile import parse_scene
    from ..scenefile.scene_edits import breakdown_segment
    from .library import contours

    plain, favour, t0, t1 = breakdown_segment(text, path, shape, key)
    if not 0 <= favour <= 1:
        raise SceneError(path, None, f"a breakdown of favour {favour:g} lies outside its segment; only favours "
                                     "from 0 to 1 can be baked into points")
    scene = parse_scene(plain, path, "toml")
    drawn = [c for c in contours(scene, t0 + favour * (t1 - t0)) if c.element == shape]
    return [_distinct(c.points).tolist() for c in drawn]


def _distinct(points: np.ndarray) -> np.ndarray:
    """``points (N, 2)`` without a vertex equal to the one before it (balancing's copies), cyclically."""
    keep = np.any(points != np.roll(points, 1, axis=0), axis=1)
    keep[0] = True
    return points[keep] if keep.sum() >= 3 else points


def editing_state(scene: Scene, size: tuple[int, int] | None = None, method: str | None = None) -> dict[str, Any]:
    """What the page edits: ``shapes``, each with its ``keys`` (``time``, ``ease``, ``hints``, ``arcs``,
    ``turn``, ``turns``, ``breakdown`` as the scene file writes them, in the key's units; ``outlines`` in
    scene units, one list of [x, y] per contour; ``elements``, whose each outline is; ``to_scene``, the
    affine map from the key's units to scene units), and ``to_page``, scene units to the picture's
    pixels: ``[a, b, c, d, e, f]`` with ``x' = a·x + c·y + e``, ``y' = b·x + d·y + f``; ``easings``, each named
    curve's Bézier handles ``[x1, y1, x2, y2]``."""
    from ..core.view import Viewport
    from ..plan.job import scene_view
    from .library import _frames_for

    width, height = size or scene.size
    drawer = _frames_for(scene, method, (width, height), None)
    matrix = Viewport(scene_view(scene, drawer.tracks, (method,)), width, height).matrix
    written = _written(scene)
    if written.get("shape") or "drawing" not in written and not _drawn(scene):
        shapes = [_shape_entry(scene, index, written) for index in range(len(scene.shapes))]
    else:
        shapes = [_drawing_entry(scene, written)]
    from ..core.timing.easing import NAMED

    easings = {"linear": [0.0, 0.0, 1.0, 1.0], **{name: list(handles) for name, handles in NAMED.items()}}
    return {"to_page": _affine(matrix), "shapes": shapes, "easings": easings}


def _written(scene: Scene) -> dict[str, Any]:
    """The scene file as written (TOML), or {} (drawings from the command line, JSON)."""
    from ..scenefile.scene_edits import written_tables

    return written_tables(scene.path)


def _drawn(scene: Scene) -> bool:
    return any(shape.stroke_scales for shape in scene.shapes)


def _shape_entry(scene: Scene, index: int, written: dict[str, Any]) -> dict[str, Any]:
    shape = scene.shapes[index]
    tables = next((s.get("key", []) for s in written.get("shape", []) if s.get("name") == shape.name), [])
    keys = []
    for k, key in enumerate(shape.keys):
        table = tables[k] if k < len(tables) else {}
        keys.append({**_timing(table, key.time, key.ease), "to_scene": [1.0, 0.0, 0.0, 1.0, 0.0, 0.0],
                     "outlines": [c.points.tolist() for c in key.contours], "elements": [shape.name] * len(key.contours)})
    return {"name": shape.name, "drawing": False, "keys": keys}


def _drawing_entry(scene: Scene, written: dict[str, Any]) -> dict[str, Any]:
    """Every drawing as one key of one entry: its elements' outlines at its time."""
    times = sorted({key.time for shape in scene.shapes for key in shape.keys if not key.hidden})
    tables = written.get("drawing", [])
    files = [scene.path.parent / t["svg"] for t in tables if "svg" in t] if tables and scene.path else \
        list(scene.sources)
    maps = _drawing_maps(files)
    keys = []
    for k, time in enumerate(times):
        outlines, elements = [], []
        for shape in scene.shapes:
            for key in shape.keys:
                if key.time == time and not key.hidden:
                    outlines.extend(c.points.tolist() for c in key.contours)
                    elements.extend([shape.name] * len(key.contours))
        table = tables[k] if k < len(tables) else {}
        keys.append({**_timing(table, time, table.get("ease", "linear")),
                     "to_scene": maps[k] if k < len(maps) else [1.0, 0.0, 0.0, 1.0, 0.0, 0.0],
                     "outlines": outlines, "elements": elements})
    return {"name": scene.shapes[0].name if scene.shapes else "", "drawing": True, "keys": keys}


def _drawing_maps(files: list[Path]) -> list[list[float]]:
    """Each drawing's map from its SVG's user units to scene units (``[a, b, c, d, e, f]``)."""
    from ..scenefile.drawings import DrawingKey, read_drawings

    try:
        drawings, _ = read_drawings([DrawingKey(file, float(i)) for i, file in enumerate(files)])
    except (SceneError, OSError, ValueError):
        return []
    return [_affine(d.to_world if d.to_world is not None else np.eye(3)) for d in drawings]


def _timing(table: dict[str, Any], time: float, ease: str) -> dict[str, Any]:
    entry = {name: table[name] for name in _FIELDS if name in table}
    entry["time"] = float(time)
    entry.setdefault("ease", ease)
    entry.setdefault("hints", {})
    entry.setdefault("arcs", {})
    return entry


def _affine(matrix: np.ndarray) -> list[float]:
    return [float(matrix[0, 0]), float(matrix[1, 0]), float(matrix[0, 1]), float(matrix[1, 1]),
            float(matrix[0, 2]), float(matrix[1, 2])]
