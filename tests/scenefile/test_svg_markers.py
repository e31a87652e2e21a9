"""Markers expanded into shapes of their own at the vertices: drawn as librsvg draws them at keys, placed
after their element, and carried with the outline between keys."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import measures, reference

SIZE = 400  # pixels: at 2 per unit the outlines' antialiased edges weigh little in the measure
HEAD = '<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 200 200" width="200" height="200">'
ARROW = ('<marker id="arrow" refX="5" refY="5" markerWidth="10" markerHeight="10" orient="{orient}"{extra}>'
         '<path d="M 10 5 L 0 8 V 2 Z" fill="blue"/></marker>')
CASES = {
    "start-mid-end-auto": ARROW.format(orient="auto", extra="") +
    '<path d="M 30 160 L 100 40 L 170 160" fill="none" stroke="green" stroke-width="4" '
    'marker-start="url(#arrow)" marker-mid="url(#arrow)" marker-end="url(#arrow)"/>',
    "auto-start-reverse-on-a-curve": ARROW.format(orient="auto-start-reverse", extra="") +
    '<path d="M 30 150 C 60 20 140 20 170 150" fill="none" stroke="black" stroke-width="6" '
    'marker-start="url(#arrow)" marker-end="url(#arrow)"/>',
    "fixed-angle-user-space-units": '<marker id="arrow" refX="5" refY="5" markerWidth="30" markerHeight="30" '
    'orient="30deg" markerUnits="userSpaceOnUse" viewBox="0 0 10 10"><path d="M 10 5 L 0 8 V 2 Z" fill="blue"/>'
    '</marker>' +
    '<polyline points="30,50 170,50 100,160" fill="none" stroke="gray" stroke-width="6" '
    'marker-start="url(#arrow)" marker-mid="url(#arrow)" marker-end="url(#arrow)"/>',
    "view-box-and-overflow-clip": '<marker id="m" refX="5" refY="5" markerWidth="6" markerHeight="6" '
    'viewBox="0 0 10 10"><circle cx="5" cy="5" r="7" fill="crimson"/></marker>'
    '<line x1="40" y1="100" x2="160" y2="100" stroke="black" stroke-width="4" '
    'marker-start="url(#m)" marker-end="url(#m)"/>',
    "overflow-visible-and-the-marker-shorthand-in-css": '<style>#p { marker: url(#m) }</style>'
    '<marker id="m" refX="0" refY="0" markerWidth="4" markerHeight="4" overflow="visible">'
    '<rect x="-3" y="-3" width="6" height="6" fill="orange"/></marker>'
    '<polygon id="p" points="40,40 160,60 120,160 50,140" fill="#cde" stroke="navy" stroke-width="3"/>',
    "content-inherits-from-the-markers-ancestors": '<g fill="purple"><marker id="m" refX="2" refY="2" '
    'markerWidth="4" markerHeight="4"><rect width="4" height="4"/></marker></g>'
    '<path d="M 40 60 H 160 V 160" fill="none" stroke="black" stroke-width="5" marker-mid="url(#m)"/>',
}


def _svg(folder: Path, name: str, body: str) -> Path:
    svg = folder / f"{name}.svg"
    svg.write_text(HEAD + body + "</svg>")
    return svg


def _picture(scene: tr.Scene, time: float) -> np.ndarray:
    return tr.frame(scene, time, method="linear", size=(SIZE, SIZE), background="#ffffff")[..., :3].astype(float)


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_markers_draw_as_librsvg_draws_them(name: str, tmp_path: Path) -> None:
    svg = _svg(tmp_path, name, CASES[name])
    iou, error = measures(_picture(tr.load_scene(svg), 0.0), reference(svg, SIZE))
    assert iou >= 0.99 and error <= 0.02, (iou, error)


def test_marker_shapes_follow_their_element_start_mid_end(tmp_path: Path) -> None:
    from tweenrender.scenefile.svg import read_drawing

    body = CASES["start-mid-end-auto"] + '<rect id="after" x="0" y="0" width="5" height="5"/>'
    elements = read_drawing(_svg(tmp_path, "order", body)).elements
    assert [e.tag for e in elements] == ["path", "path", "path", "path", "rect"]
    for arrow, vertex in zip(elements[1:4], [(30, -160), (100, -40), (170, -160)]):  # each on its vertex
        points = arrow.contours[0].points
        assert np.all(points.min(axis=0) < vertex) and np.all(points.max(axis=0) > vertex)
    assert elements[-1].id == "after"


@needs_rsvg
def test_markers_move_with_their_outline(tmp_path: Path) -> None:
    """A marked path moved by 40 units: halfway (a pure translation, linear) its picture is librsvg's of the
    path moved by 20, markers included."""
    def drawing(name: str, dx: float) -> Path:
        return _svg(tmp_path, name, ARROW.format(orient="auto", extra="") +
                    f'<path d="M {30 + dx} 160 L {70 + dx} 40 L {110 + dx} 160" fill="none" stroke="green" '
                    'stroke-width="4" marker-start="url(#arrow)" marker-mid="url(#arrow)" marker-end="url(#arrow)"/>')

    scene = tr.load_scene([drawing("a", 0), drawing("b", 40)])
    halfway = _picture(scene, 0.5 * scene.duration)
    iou, error = measures(halfway, reference(drawing("middle", 20), SIZE))
    assert iou >= 0.99 and error <= 0.02, (iou, error)


def test_a_marker_inside_its_own_content_is_drawn_once(tmp_path: Path) -> None:
    from tweenrender.scenefile.svg import read_drawing

    body = ('<marker id="m" markerWidth="10" markerHeight="10" overflow="visible">'
            '<path d="M 0 0 L 5 5" stroke="red" marker-end="url(#m)"/></marker>'
            '<path d="M 20 20 L 100 100" stroke="black" marker-end="url(#m)"/>')
    assert len(read_drawing(_svg(tmp_path, "loop", body)).elements) == 2


def test_markers_copies_count_against_the_readers_limit(tmp_path: Path) -> None:
    from tweenrender.errors import TweenrenderError

    points = " ".join(f"{i % 100},{i // 100}" for i in range(1000))
    content = "".join('<rect width="0" height="0"/>' for _ in range(60))  # 60 × 1000 vertices: over 50 000
    body = f'<marker id="m">{content}</marker><polyline points="{points}" stroke="black" marker-mid="url(#m)"/>'
    with pytest.raises(TweenrenderError, match="once markers' copies are counted"):
        tr.load_scene(_svg(tmp_path, "many", body))
