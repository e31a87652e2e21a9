"""Play every frame of every shipped scene's Lottie export in rlottie and compare with the project's frames.

The test suite samples frames (ten evenly, and both sides of every key); this draws them all, at each
scene's own size and method, and prints the worst coverage IoU and colour error per scene (DESIGN,
"Measures used in acceptance": IoU at least 0.98, colour error at most 0.03). Needs the test extra
(``rlottie-python``). Run from anywhere:

    python scripts/check_vector_players.py [SCENE_STEM ...]
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))

import tweenrender as tr  # noqa: E402
from tests.vector_players import measures, over, rlottie_frames  # noqa: E402
from tweenrender.plan.job import total_frames  # noqa: E402

_BATCH = 16


def main(stems: list[str]) -> int:
    paths = [p for p in sorted((ROOT / "scenes").glob("*.toml")) if not stems or p.stem in stems]
    failed = False
    with tempfile.TemporaryDirectory() as folder:
        for path in paths:
            scene = tr.load_scene(path)
            target = tr.write(scene, Path(folder) / f"{path.stem}.json")
            count, background = total_frames(scene), scene.background[:3]
            worst_iou, worst_error = 1.0, 0.0
            for start in range(0, count, _BATCH):
                frames = list(range(start, min(count, start + _BATCH)))
                for frame, picture in zip(frames, rlottie_frames(target, frames, scene.size)):
                    iou, error = measures(over(tr.frame(scene, frame / scene.fps), background),
                                          over(picture, background), background)
                    worst_iou, worst_error = min(worst_iou, iou), max(worst_error, error)
            ok = worst_iou >= 0.98 and worst_error <= 0.03
            failed |= not ok
            print(f"{path.stem:22} {count:4d} frames  worst IoU {worst_iou:.4f}  worst colour error {worst_error:.4f}"
                  f"  {'ok' if ok else 'FAILS'}", flush=True)
    return 1 if failed else 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
