"""The animated SVG's own ids (its gradients' and clip paths') never collide with the ids the user's drawing gave
its elements, which name the file's groups: librsvg (an independent renderer) then draws the file's first frame
as the project draws it, clipped by the clip path, not by whatever element first took its id."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

import tweenrender as tr
from tests.vector_players import measures

RSVG = shutil.which("rsvg-convert")
needs_rsvg = pytest.mark.skipif(RSVG is None, reason="rsvg-convert (Debian package librsvg2-bin) is not installed; "
                                                       "`.ci/run` installs it")

_CLIP = '<clipPath id="c"><rect x="0" y="0" width="{w}" height="10"/></clipPath>'
_GRADIENT = '<linearGradient id="g"><stop offset="0" stop-color="#ff0000"/><stop offset="1" stop-color="#0000ff"/>' \
            '</linearGradient>'


def _drawing(folder: Path, name: str, body: str) -> Path:
    path = folder / name
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 20 10">{body}</svg>')
    return path


def _scene(folder: Path, names: tuple[str, str]) -> tr.Scene:
    """Two elements whose ids are what the file's own clip path and gradient ids would be without a prefix of
    their own: a clipped box and a box filled by a gradient."""
    clipped, filled = names
    first = _drawing(folder, "a.svg", f'<defs>{_CLIP.format(w=6)}{_GRADIENT}</defs>'
                                      f'<rect id="{clipped}" x="2" y="2" width="6" height="6" fill="#208040" '
                                      f'clip-path="url(#c)"/><rect id="{filled}" x="11" y="1" width="6" height="3" '
                                      f'fill="url(#g)"/>')
    second = _drawing(folder, "b.svg", f'<defs>{_CLIP.format(w=13)}{_GRADIENT}</defs>'
                                       f'<rect id="{clipped}" x="9" y="1" width="8" height="4" fill="#208040" '
                                       f'clip-path="url(#c)"/><rect id="{filled}" x="2" y="6" width="6" height="3" '
                                       f'fill="url(#g)"/>')
    return tr.load_scene([first, second])


def _ids(svg: str) -> list[str]:
    return re.findall(r'\bid="([^"]*)"', svg)


@pytest.mark.parametrize("names", [("run0-clip", "run1-fill-x"), ("tr-run0-clip", "tr-run1"),
                                   ("run1-clip", "run0")], ids=["plain", "prefixed", "crossed"])
def test_the_files_own_ids_are_unique_and_apart_from_the_drawings(tmp_path: Path, names: tuple[str, str]) -> None:
    scene = _scene(tmp_path, names)
    svg = tr.write(scene, tmp_path / "x.svg").read_text()
    ids = _ids(svg)
    assert len(ids) == len(set(ids)), f"ids used twice: {sorted(i for i in ids if ids.count(i) > 1)}"
    references = re.findall(r'url\(#([^)]*)\)', svg)
    assert references and all(ids.count(r) == 1 for r in references)
    for reference in references:  # each reference names a paint server or clip path, never a group
        assert re.search(rf'<(clipPath|linearGradient|radialGradient) id="{re.escape(reference)}"', svg)


@needs_rsvg
def test_librsvg_draws_the_first_frame_clipped_as_the_project_does(tmp_path: Path) -> None:
    scene = _scene(tmp_path, ("run0-clip", "run1-fill"))
    target = tr.write(scene, tmp_path / "x.svg")
    width, height = scene.size
    done = subprocess.run([RSVG, "-w", str(width), "-h", str(height), "-b", "white", str(target)],
                          capture_output=True, check=True)
    theirs = iio.imread(done.stdout)[..., :3]
    ours = tr.frame(scene, 0.0)
    alpha = ours[..., 3:4].astype(np.float64) / 255.0
    ours = np.rint(ours[..., :3] * alpha + 255 * (1 - alpha)).astype(np.uint8)
    iou, error = measures(ours, theirs, (255, 255, 255))
    assert iou >= 0.98 and error <= 0.03, f"IoU {iou:.4f}, colour error {error:.4f}"
