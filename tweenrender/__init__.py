"""tweenrender: inbetweening of 2-D shapes after Slinker (1992).

Keyframe polygons from a scene file are put in correspondence, interpolated
along linear, nonlinear (quadratic Bézier), rigid or jointed vertex paths, and
rendered with skia to PNG frames or video.

Names are imported on first use, so ``import tweenrender`` (and the command
line's start-up) stays light.
"""

from __future__ import annotations

from importlib import import_module
from typing import Any

__all__ = [
    "load_scene", "parse_scene", "interpolate", "render", "RenderJob", "Frames",
    "Scene", "Shape", "Key", "Matching",
    "TweenrenderError", "SceneError", "UsageError", "RenderError", "EncodeError",
]
__version__ = "0.1.0"

_HOME = {
    "load_scene": "scenefile", "parse_scene": "scenefile", "interpolate": "core.methods",
    "render": "pipeline", "RenderJob": "pipeline", "Frames": "pipeline",
    "Scene": "model", "Shape": "model", "Key": "model", "Matching": "model",
    "TweenrenderError": "errors", "SceneError": "errors", "UsageError": "errors",
    "RenderError": "errors", "EncodeError": "errors",
}


def __getattr__(name: str) -> Any:
    if name in _HOME:
        return getattr(import_module(f".{_HOME[name]}", __name__), name)
    raise AttributeError(f"module 'tweenrender' has no attribute {name!r}")
