"""The scene file formats: the only code that knows TOML, JSON and SVG."""

from .load import load_scene, parse_scene
from .scene_limits import LIMITS
from .values import parse_color

__all__ = ["LIMITS", "load_scene", "parse_scene", "parse_color"]
