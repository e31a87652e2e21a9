"""The scene file formats: the only code that knows TOML, JSON and SVG."""

from .load import LIMITS, load_scene, parse_color, parse_scene

__all__ = ["LIMITS", "load_scene", "parse_scene", "parse_color"]
