"""tweenrender: inbetweening of 2-D shapes after Slinker (1992), and beyond.

Keyframe outlines from a scene file are put in correspondence, interpolated
along linear, nonlinear (quadratic Bézier), rigid or jointed vertex paths, and
rendered with skia to PNG frames or video::

    import tweenrender as tr
    scene = tr.load_scene("scenes/square.toml")
    img = tr.frame(scene, 1.0, size=(640, 360))      # (360, 640, 4) uint8, straight RGBA
    tr.write(scene, "output/square.mp4", compare=["linear", "nonlinear"])

Every public name is :mod:`tweenrender.api`'s (the front door); each function imports the stage it
needs when first called, so ``import tweenrender`` stays light.
"""

from __future__ import annotations

from .api import (
    Key, Matching, MatchSettings, RenderOptions, Scene, Shape, DrawnContour, __version__, contours, correspondence,
    describe, frame, frames, init_scene, interpolate, load_scene, outlines, parse_scene, qcurves, reel, report, sheet, stats,
    write,
)
from .errors import EncodeError, GeometryError, OptionError, RenderError, SceneError, TweenrenderError

__all__ = [
    "load_scene", "init_scene", "frame", "frames", "outlines", "contours", "write",
    "stats", "correspondence", "qcurves", "describe", "sheet", "report", "reel",
    "RenderOptions", "MatchSettings",
    "parse_scene", "interpolate", "Scene", "Shape", "Key", "Matching", "DrawnContour",
    "TweenrenderError", "SceneError", "OptionError", "GeometryError", "RenderError", "EncodeError",
]
