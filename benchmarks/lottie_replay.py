"""How far lottie-web's outlines lie from ``--method linear``'s replay of the same Lottie file, per frame.

lottie-web (its SVG renderer, in headless chromium) is stopped at every frame; each visible path of its
picture is sampled every half pixel along its length (``getPointAtLength``, placed by ``getCTM``), and
the farthest of those points from the outlines tweenrender draws at that frame (stroke centre lines
included) is the frame's distance. Prints the worst frame per file.

Run: ``python benchmarks/lottie_replay.py NODE_MODULES FILE.json..`` where NODE_MODULES holds the npm
package ``lottie-web`` (``npm install lottie-web`` in a folder of your choice).
"""

from __future__ import annotations

import json
import sys
import tempfile
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import tweenrender as tr  # noqa: E402
from tests.browser import live_page  # noqa: E402
from tweenrender.api import frame_count  # noqa: E402

_VISIBLE_PATHS = """
(() => { const out = [];
  for (const el of document.querySelectorAll('svg path')) {
    if (el.closest('defs, clipPath, mask')) continue;
    let hidden = false;
    for (let n = el; n && n.tagName !== 'svg'; n = n.parentNode) {
      const style = getComputedStyle(n); if (style.display === 'none' || style.opacity === '0') hidden = true; }
    const d = el.getAttribute('d'); if (hidden || !d || d.length < 4) continue;
    const style = getComputedStyle(el);
    if ((style.fill === 'none' || style.fillOpacity === '0') && (style.stroke === 'none' || style.strokeOpacity === '0'))
      continue;
    const length = el.getTotalLength(), m = el.getCTM(), points = [];
    const n = Math.max(8, Math.min(2000, Math.ceil(length / 0.5)));
    for (let i = 0; i < n; i++) { const p = el.getPointAtLength(length * i / n);
      points.push([m.a * p.x + m.c * p.y + m.e, m.b * p.x + m.d * p.y + m.f]); }
    out.push(points); }
  return out; })()
"""


def distances(points: np.ndarray, contours: list[np.ndarray]) -> np.ndarray:
    """The distance of each of ``points (P, 2)`` from the nearest edge of ``contours`` (closed): ``(P,)``."""
    best = np.full(len(points), np.inf)
    for start in contours:
        edge = np.roll(start, -1, axis=0) - start
        length2 = np.maximum((edge ** 2).sum(1), 1e-300)
        for s in range(0, len(points), 256):
            p = points[s:s + 256, None, :]
            t = np.clip(((p - start) * edge).sum(-1) / length2, 0, 1)
            near = np.linalg.norm(p - (start + t[..., None] * edge), axis=-1).min(1)
            best[s:s + 256] = np.minimum(best[s:s + 256], near)
    return best


def worst_distance(modules: Path, path: Path) -> tuple[int, float]:
    scene = tr.load_scene(path)
    width, height = scene.size
    player = (modules / "lottie-web" / "build" / "player" / "lottie.min.js").resolve()
    worst = 0.0
    with tempfile.TemporaryDirectory() as folder:
        page = Path(folder) / "page.html"
        page.write_text(f"""<html><body style="margin:0"><div id=a style="width:{width}px;height:{height}px"></div>
<script src="{player.as_uri()}"></script><script>window.anim = lottie.loadAnimation({{
container: document.getElementById('a'), renderer: 'svg', loop: false, autoplay: false,
animationData: {json.dumps(json.loads(path.read_text()))}}});</script></body></html>""")
        with live_page(page.as_uri(), (width + 20, height + 20)) as live:
            live.wait_for("window.anim && window.anim.isLoaded")
            for frame in range(frame_count(scene)):
                live.evaluate(f"window.anim.goToAndStop({frame}, true)")
                theirs = [np.array(p) for p in live.evaluate(_VISIBLE_PATHS) if p]
                ours = [c.points * [1, -1] + [0, height] for c in tr.contours(scene, frame / scene.fps, method="linear")]
                if theirs and ours:
                    worst = max(worst, float(distances(np.concatenate(theirs), ours).max()))
    return frame_count(scene), worst


if __name__ == "__main__":
    modules = Path(sys.argv[1])
    for name in sys.argv[2:]:
        count, worst = worst_distance(modules, Path(name))
        print(f"{Path(name).name}: {count} frames, lottie-web's outlines at most {worst:.4f} px from ours")
