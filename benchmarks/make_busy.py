"""Write ``busy.toml``: two dozen 40-vertex shapes that turn and travel for ``--seconds`` at 1080p24.

``--stroked`` writes the detailed, stroked scene instead: 100 shapes of 500
vertices with a 2 px outline (each vertex's radius drawn at random, so the
outlines are spiky at the pixel scale). Deterministic (a seeded generator), so
every run benchmarks the same scene.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path

import numpy as np

__all__ = ["busy_scene", "stroked_scene"]


def _polygon(rng: np.random.Generator, cx: float, cy: float, radius: float, vertices: int) -> list[list[float]]:
    """A wobbly star-ish ring of ``vertices`` points around ``(cx, cy)``."""
    angles = np.linspace(0.0, 2 * math.pi, vertices, endpoint=False)
    radii = radius * (1.0 + 0.25 * np.sin(5 * angles + rng.uniform(0, 6.3)) + 0.1 * rng.uniform(-1, 1, vertices))
    return [[round(float(cx + r * math.cos(a)), 4), round(float(cy + r * math.sin(a)), 4)]
            for r, a in zip(radii, angles)]


def busy_scene(seconds: float = 5.0, shapes: int = 24, vertices: int = 40, size: tuple[int, int] = (1920, 1080),
               seed: int = 1992) -> str:
    """The scene's TOML text: each shape has a key at 0, seconds/2 and seconds, turning by up to 180°."""
    rng = np.random.default_rng(seed)
    colours = ["#3b6fd8", "#d84b3b", "#f1c40f", "#27ae60", "#8e44ad", "#e67e22", "#16a085", "#2c3e50"]
    lines = [f'title = "Busy: {shapes} shapes of {vertices} vertices"', f"size = [{size[0]}, {size[1]}]",
             "fps = 24", 'background = "#fdfdf8"', "view = [0, 0, 32, 18]", 'method = "nonlinear"', ""]
    for s in range(shapes):
        lines += ["[[shape]]", f'name = "s{s:02d}"', f'fill = "{colours[s % len(colours)]}"',
                  'stroke = "#1d2b50"', "stroke_width = 2.0", ""]
        base = _polygon(rng, 0.0, 0.0, rng.uniform(1.0, 2.2), vertices)
        for k, time in enumerate((0.0, seconds / 2, seconds)):
            turn = math.radians(rng.uniform(-180, 180)) * k / 2
            cx, cy = rng.uniform(3, 29), rng.uniform(3, 15)
            c, s_ = math.cos(turn), math.sin(turn)
            points = [[round(cx + c * x - s_ * y, 4), round(cy + s_ * x + c * y, 4)] for x, y in base]
            lines += ["[[shape.key]]", f"time = {time:g}", f"points = {points}", ""]
    return "\n".join(lines)


def stroked_scene(seconds: float = 5.0) -> str:
    """The detailed, stroked scene's TOML text: 100 shapes x 500 vertices, 2 px outline, 1080p24."""
    return busy_scene(seconds, shapes=100, vertices=500)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("-o", "--output", default=str(Path(__file__).with_name("busy.toml")))
    parser.add_argument("--seconds", type=float, default=5.0)
    parser.add_argument("--stroked", action="store_true", help="100 shapes x 500 vertices, 2 px outline")
    args = parser.parse_args()
    Path(args.output).write_text(stroked_scene(args.seconds) if args.stroked else busy_scene(args.seconds))
    print(args.output)


if __name__ == "__main__":
    main()
