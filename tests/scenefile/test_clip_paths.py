"""Clip paths drawn at keys and carried with their element, against librsvg's pictures."""

from __future__ import annotations

from pathlib import Path

import pytest

import tweenrender as tr
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import measures, reference

HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40">'
CASES = {
    "on-the-element": '<defs><clipPath id="c"><circle cx="20" cy="20" r="12"/></clipPath></defs>'
                      '<rect x="4" y="4" width="32" height="20" fill="#cc3300" clip-path="url(#c)"/>',
    "on-a-group-with-transforms": '<defs><clipPath id="c" transform="rotate(20 20 20)"><rect x="8" y="8" width="20" '
                                  'height="14"/><circle cx="30" cy="30" r="6"/></clipPath></defs>'
                                  '<g clip-path="url(#c)" transform="translate(2 1)"><rect x="0" y="0" width="38" '
                                  'height="38" fill="#1166cc"/><circle cx="20" cy="20" r="9" fill="#ffcc00"/></g>',
    "bounding-box-units": '<defs><clipPath id="c" clipPathUnits="objectBoundingBox"><circle cx="0.5" cy="0.5" '
                          'r="0.5"/></clipPath></defs><rect x="6" y="10" width="28" height="20" fill="#228833" '
                          'clip-path="url(#c)"/>',
    "nested": '<defs><clipPath id="a"><rect x="5" y="5" width="22" height="30"/></clipPath>'
              '<clipPath id="b"><circle cx="22" cy="20" r="14"/></clipPath></defs>'
              '<g clip-path="url(#a)"><path d="M2 2H38V38H2Z" fill="#884499" clip-path="url(#b)"/></g>',
}


def _picture(svg: Path, time: float = 0.0, method: str | None = None):  # type: ignore[no-untyped-def]
    scene = tr.load_scene(svg)
    return tr.frame(scene, time, method=method, size=(256, 256), background="#ffffff")[..., :3].astype(float)


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_clip_paths_clip_as_librsvg_does(name: str, tmp_path: Path) -> None:
    svg = tmp_path / f"{name}.svg"
    svg.write_text(HEAD + CASES[name] + "</svg>")
    iou, error = measures(_picture(svg), reference(svg))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


@needs_rsvg
def test_a_clip_moves_and_grows_with_its_element(tmp_path: Path) -> None:
    """A square clipped by the circle inscribed in it moves from (2, 2), side 10 to (18, 14), side 20: halfway
    it is the square at (10, 8), side 15, clipped by its own inscribed circle."""
    def clipped(name: str, x: float, y: float, side: float) -> Path:
        svg = tmp_path / f"{name}.svg"
        svg.write_text(HEAD + f'<defs><clipPath id="c"><circle cx="{x + side / 2}" cy="{y + side / 2}" '
                       f'r="{side / 2}"/></clipPath></defs><rect id="box" x="{x}" y="{y}" width="{side}" '
                       f'height="{side}" fill="#dd5500" clip-path="url(#c)"/></svg>')
        return svg

    scene = tr.load_scene([clipped("a", 2, 2, 10), clipped("b", 18, 14, 20)])
    halfway = tr.frame(scene, 0.5, method="linear", size=(256, 256), background="#ffffff")[..., :3].astype(float)
    iou, error = measures(halfway, reference(clipped("middle", 10, 8, 15)))
    assert iou >= 0.99 and error <= 0.01, (iou, error)


def _clipped(tmp_path: Path, defs: str) -> np.ndarray:
    svg = tmp_path / "cc.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 100">' + defs +
                   '<rect width="100" height="100" fill="#008000" clip-path="url(#a)"/></svg>')
    return tr.frame(tr.load_scene(svg), 0.0, size=(100, 100), background="#ffffff")[..., :3]


def test_a_clip_path_on_a_clip_path_intersects_them(tmp_path: Path) -> None:
    # SVG 1.1 §14.3.5: the clip path's own clip-path clips its region: [0, 60] ∩ [40, 100] across
    picture = _clipped(tmp_path, '<clipPath id="b"><rect x="40" width="60" height="100"/></clipPath>'
                                 '<clipPath id="a" clip-path="url(#b)"><rect width="60" height="100"/></clipPath>')
    ink = (picture != 255).any(axis=-1)
    assert ink[50, 45:55].all() and not ink[50, :38].any() and not ink[50, 62:].any()


def test_a_clip_path_on_a_clip_path_that_loops_back_is_ignored(tmp_path: Path) -> None:
    # as Chromium and resvg draw it: b's clip-path leads back to a, so only a and b clip: x in [0, 60] ∩ [0, 80]
    picture = _clipped(tmp_path, '<clipPath id="b" clip-path="url(#a)"><rect width="80" height="100"/></clipPath>'
                                 '<clipPath id="a" clip-path="url(#b)"><rect width="60" height="100"/></clipPath>')
    ink = (picture != 255).any(axis=-1)
    assert ink[50, 2:58].all() and not ink[50, 62:].any()
