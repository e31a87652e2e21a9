"""manim's morph of the two feather icons the render benchmark morphs (heart -> star, 1 s).

Run by ``bench_render.py --only icons`` with a manim executable (``--manim PATH``, or ``manim`` on
the PATH): ``manim render -r 1280,720 --frame_rate 24 benchmarks/manim_morph.py IconMorph``.
manim's ``Transform`` is its default shape morph; the icons are drawn as the SVG says (stroked).
"""

from pathlib import Path

from manim import WHITE, Scene, SVGMobject, Transform

ICONS = Path(__file__).resolve().parents[1] / "tests" / "data" / "icons" / "feather"


class IconMorph(Scene):
    def construct(self) -> None:
        self.camera.background_color = WHITE
        heart = SVGMobject(str(ICONS / "heart.svg"), height=6)
        star = SVGMobject(str(ICONS / "star.svg"), height=6)
        self.add(heart)
        self.play(Transform(heart, star), run_time=1.0)
