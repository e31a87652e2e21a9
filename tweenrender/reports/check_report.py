"""The ``check --json`` report: the scene as loaded, in world units."""

from __future__ import annotations

from typing import Any, Sequence

from ..model import Scene

__all__ = ["scene_dict"]


def scene_dict(scene: Scene, view: Sequence[float]) -> dict[str, Any]:
    """The scene as loaded, for ``check --json``: points in world units."""
    return {
        "scene": str(scene.path) if scene.path else None,
        "title": scene.title,
        "size": list(scene.size),
        "fps": scene.fps,
        "view": list(view),
        "method": scene.method,
        "compare": list(scene.compare),
        "shapes": [{
            "name": shape.name,
            "method": scene.method_of(shape),
            "joints": [list(j) for j in shape.joints],
            "keys": [{"time": key.time, "ease": key.ease, "points": key.points.tolist()} for key in shape.keys],
        } for shape in scene.shapes],
    }
