"""tweenrender: inbetweening of 2-D shapes after Slinker (1992), and beyond.

Keyframe outlines from a scene file are put in correspondence, interpolated
along linear, nonlinear (quadratic Bézier), rigid or jointed vertex paths, and
rendered with skia to PNG frames or video::

    import tweenrender as tr
    scene = tr.load_scene("scenes/square.toml")
    img = tr.frame(scene, 1.0, size=(640, 360))      # (360, 640, 4) uint8, straight RGBA
    tr.write(scene, "output/square.mp4", compare=["linear", "nonlinear"])

Names are imported on first use, so ``import tweenrender`` (and the command
line's start-up) stays light. No module of the package is named like a public
name, so importing any submodule never changes what these names are.
"""

from __future__ import annotations

from importlib import import_module
from typing import Any

__all__ = [
    "load_scene", "frame", "frames", "outlines", "contours", "write",
    "stats", "correspondence", "qcurves", "describe", "sheet", "report", "reel",
    "RenderOptions",
    "parse_scene", "interpolate", "Scene", "Shape", "Key", "Matching", "DrawnContour",
    "TweenrenderError", "SceneError", "OptionError", "GeometryError", "RenderError", "EncodeError",
]
__version__ = "0.2.0"

_HOME = {
    "load_scene": "pipeline.library", "frame": "pipeline.library", "frames": "pipeline.library",
    "outlines": "pipeline.library", "contours": "pipeline.library", "write": "pipeline.library",
    "stats": "reports.analyses", "correspondence": "reports.analyses", "qcurves": "reports.analyses",
    "describe": "reports.analyses", "sheet": "reports.documents", "report": "reports.documents",
    "reel": "reports.documents", "RenderOptions": "plan.options", "DrawnContour": "model",
    "parse_scene": "scenefile", "interpolate": "core.methods.registry",
    "Scene": "model", "Shape": "model", "Key": "model", "Matching": "model",
    "TweenrenderError": "errors", "SceneError": "errors", "OptionError": "errors", "GeometryError": "errors",
    "RenderError": "errors", "EncodeError": "errors",
}


def __getattr__(name: str) -> Any:
    if name in _HOME:
        return getattr(import_module(f".{_HOME[name]}", __name__), name)
    raise AttributeError(f"module 'tweenrender' has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(__all__))
