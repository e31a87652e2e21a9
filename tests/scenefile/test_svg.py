"""SVG keyframes: transforms and the y flip, flattening within tolerance, clear refusals.

Expected values are computed here in closed form (hand-composed transforms,
Bernstein polynomials, circle and ellipse parametrisations), never by the code
under test.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tweenrender.errors import SceneError
from tweenrender.scenefile import svg, svg_document
from tweenrender.scenefile.svg import DEFAULT_TOLERANCE, SvgError, load_svg_points, read_drawing

SCENES = Path(__file__).resolve().parents[2] / "scenes" / "svg"


def drawing(tmp_path: Path, body: str, root: str = 'width="100" height="100"', name: str = "d.svg") -> Path:
    path = tmp_path / name
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" {root}>\n{body}\n</svg>\n', encoding="utf-8")
    return path


def distance_to_polygon(samples: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Distance from each sample ``(K, 2)`` to the closed polygon ``(N, 2)``: shape ``(K,)``."""
    a = polygon
    ab = np.roll(polygon, -1, axis=0) - a
    out = np.empty(len(samples))
    for start in range(0, len(samples), 2000):
        ap = samples[start:start + 2000, None, :] - a[None]
        t = np.clip((ap * ab).sum(-1) / np.maximum((ab * ab).sum(-1), 1e-300), 0.0, 1.0)
        out[start:start + 2000] = np.linalg.norm(ap - t[..., None] * ab, axis=-1).min(axis=1)
    return out


def distance_to_curve(points: np.ndarray, curve: np.ndarray) -> np.ndarray:
    """Distance from points to a densely sampled open curve ``(K, 2)`` (as a polyline)."""
    a, ab = curve[:-1], curve[1:] - curve[:-1]
    ap = points[:, None, :] - a[None]
    t = np.clip((ap * ab).sum(-1) / np.maximum((ab * ab).sum(-1), 1e-300), 0.0, 1.0)
    return np.linalg.norm(ap - t[..., None] * ab, axis=-1).min(axis=1)


def bernstein(nodes: list[tuple[float, float]], t: np.ndarray) -> np.ndarray:
    """The Bézier with these control points at parameters ``t``: ``(len(t), 2)``."""
    n = len(nodes) - 1
    p = np.asarray(nodes, dtype=float)
    return sum(math.comb(n, i) * ((1 - t) ** (n - i) * t**i)[:, None] * p[i] for i in range(n + 1))


def flip(points: np.ndarray) -> np.ndarray:
    return np.asarray(points, dtype=float) * [1.0, -1.0]


# --- exact polygons: transforms and the y flip ---------------------------------------


def test_nested_group_transforms_and_own_transform(tmp_path: Path) -> None:
    path = drawing(tmp_path, """
      <g transform="translate(5,7)"><g transform="rotate(90)"><g transform="scale(2,3)">
        <polygon id="tri" points="1,0 3,0 2,2" transform="matrix(1,0,0.5,1,1,2)"/>
      </g></g></g>""")
    # own (x + 0.5y + 1, y + 2) → scale (2x, 3y) → rotate 90° (−y, x) → translate (+5, +7) → flip y
    # (1,0) → (2,2) → (4,6) → (−6,4) → (−1,11) → (−1,−11)
    # (3,0) → (4,2) → (8,6) → (−6,8) → (−1,15) → (−1,−15)
    # (2,2) → (4,4) → (8,12) → (−12,8) → (−7,15) → (−7,−15)
    expected = [[-1, -11], [-1, -15], [-7, -15]]
    np.testing.assert_allclose(load_svg_points(path, "tri"), expected, atol=1e-12)


def test_rotation_about_a_point_and_skew(tmp_path: Path) -> None:
    path = drawing(tmp_path, """
      <g transform="rotate(30 10 20)"><g transform="skewX(45)">
        <polygon id="tri" points="0,0 4,0 0,2"/>
      </g></g>""")
    c, s = math.cos(math.radians(30)), math.sin(math.radians(30))

    def expected(x: float, y: float) -> tuple[float, float]:
        x, y = x + y * math.tan(math.radians(45)), y  # skewX(45)
        dx, dy = x - 10, y - 20  # rotate(30) about (10, 20)
        return 10 + c * dx - s * dy, -(20 + s * dx + c * dy)

    want = [expected(0, 0), expected(4, 0), expected(0, 2)]
    np.testing.assert_allclose(load_svg_points(path, "tri"), want, atol=1e-12)


@pytest.mark.parametrize("root", [
    'width="100mm" height="50mm" viewBox="0 0 100 50"',
    'width="4in" height="7cm" viewBox="-10 20 300 150"',
    'width="100mm" height="100mm" viewBox="0 0 100 50" preserveAspectRatio="none"',
    'width="100mm" height="50mm"',
    'viewBox="0 0 10 10"',
    'width="100mm" height="50mm" viewBox="0 0 100 50" transform="translate(9 9) scale(2)"',
])
def test_coordinates_are_user_units_whatever_the_viewport(tmp_path: Path, root: str) -> None:
    path = drawing(tmp_path, '<g transform="translate(1 2)"><polygon id="p" points="1,2 7,2 7,5"/></g>', root)
    np.testing.assert_allclose(load_svg_points(path, "p"), [[2, -4], [8, -4], [8, -7]], atol=1e-9)


def test_units_inside_the_drawing_convert_at_96_per_inch(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<rect id="r" x="0" y="0" width="1in" height="25.4mm"/>',
                   'width="100mm" height="100mm" viewBox="0 0 100 100"')
    # svgelements takes an inch as 1 / 0.0393701 mm: 25.4 mm comes out 5e-7 too long
    np.testing.assert_allclose(load_svg_points(path, "r"), [[0, 0], [96, 0], [96, -96], [0, -96]], rtol=1e-6)


def test_rect_gives_its_four_corners_in_order(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<rect id="r" x="1" y="2" width="4" height="3"/>'
                             '<rect id="moved" x="1" y="2" width="4" height="3" transform="translate(10 0)"/>')
    np.testing.assert_array_equal(load_svg_points(path, "r"), [[1, -2], [5, -2], [5, -5], [1, -5]])
    np.testing.assert_array_equal(load_svg_points(path, "moved"), [[11, -2], [15, -2], [15, -5], [11, -5]])


def test_polyline_gives_its_points(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<polyline id="zig" points="0,0 10,0 10,10 5,12.5 0,10" fill="none"/>')
    expected = flip([[0, 0], [10, 0], [10, 10], [5, 12.5], [0, 10]])
    np.testing.assert_array_equal(load_svg_points(path, "zig"), expected)


def test_closing_and_consecutive_duplicates_are_dropped(tmp_path: Path) -> None:
    path = drawing(tmp_path, """
      <polygon id="poly" points="0,0 4,0 4,0 4,3 0,3 0,0"/>
      <path id="rel" d="m 0,0 l 0.1,0 l 0.2,1 l -0.3,-1 z m 0,0"/>""")
    np.testing.assert_array_equal(load_svg_points(path, "poly"), flip([[0, 0], [4, 0], [4, 3], [0, 3]]))
    # 0.1 + 0.2 - 0.3 is not 0.0 in floating point: the near-duplicate closing point goes too
    np.testing.assert_allclose(load_svg_points(path, "rel"), flip([[0, 0], [0.1, 0], [0.3, 1]]), atol=1e-15)


def test_straight_segments_stay_single_edges(tmp_path: Path) -> None:
    path = drawing(tmp_path, """
      <path id="hv" d="M 1 1 h 10 v 5 H 1 Z"/>
      <path id="straight" d="M 0 0 C 0 0 10 0 10 0 C 10 2 10 8 10 10 Q 5 10 0 10 Z"/>""")
    np.testing.assert_array_equal(load_svg_points(path, "hv"), flip([[1, 1], [11, 1], [11, 6], [1, 6]]))
    np.testing.assert_array_equal(load_svg_points(path, "straight"), flip([[0, 0], [10, 0], [10, 10], [0, 10]]))


def test_hidden_layers_still_load(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<g style="display:none"><polygon id="p" points="0,0 1,0 1,1"/></g>')
    np.testing.assert_array_equal(load_svg_points(path, "p"), flip([[0, 0], [1, 0], [1, 1]]))


# --- curves: within tolerance, not over-refined ----------------------------------------


@pytest.mark.parametrize(("radius", "tolerance"), [(2.0, 0.01), (50.0, 0.01), (5.0, 0.2), (1.0, 1e-4)])
def test_circle_is_within_tolerance_and_not_over_refined(tmp_path: Path, radius: float, tolerance: float) -> None:
    path = drawing(tmp_path, f'<circle id="c" cx="3" cy="-4" r="{radius}"/>')
    polygon = load_svg_points(path, "c", tolerance)
    centre = np.array([3.0, 4.0])
    assert np.max(np.abs(np.hypot(*(polygon - centre).T) - radius)) < 1e-9 * radius
    t = np.linspace(0, 2 * np.pi, 20_000, endpoint=False)
    circle = centre + radius * np.column_stack([np.cos(t), np.sin(t)])
    error = distance_to_polygon(circle, polygon).max()
    assert error <= tolerance * (1 + 1e-9)
    ideal = math.pi / math.acos(1 - tolerance / radius)
    assert ideal <= len(polygon) <= 1.25 * ideal + 4


def test_error_is_measured_after_transforms(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<g transform="scale(3)"><circle id="c" cx="0" cy="0" r="2"/></g>')
    polygon = load_svg_points(path, "c", 0.01)
    t = np.linspace(0, 2 * np.pi, 20_000, endpoint=False)
    circle = 6.0 * np.column_stack([np.cos(t), np.sin(t)])
    assert distance_to_polygon(circle, polygon).max() <= 0.01 * (1 + 1e-9)
    assert len(polygon) >= math.pi / math.acos(1 - 0.01 / 6.0)


def test_skewed_ellipse_is_within_tolerance(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<g transform="matrix(1 0.3 -0.8 1.2 10 5)">'
                             '<ellipse id="e" cx="4" cy="2" rx="20" ry="6"/></g>')
    polygon = load_svg_points(path, "e", 0.02)
    t = np.linspace(0, 2 * np.pi, 20_000, endpoint=False)
    x, y = 4 + 20 * np.cos(t), 2 + 6 * np.sin(t)
    exact = np.column_stack([x - 0.8 * y + 10, -(0.3 * x + 1.2 * y + 5)])
    assert distance_to_polygon(exact, polygon).max() <= 0.02 * (1 + 1e-9)
    assert distance_to_polygon(polygon, exact).max() < 1e-3  # vertices lie on the ellipse


def test_rounded_rect_is_within_tolerance(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<rect id="r" x="0" y="0" width="20" height="10" rx="3"/>')
    polygon = load_svg_points(path, "r", 0.01)
    t = np.linspace(0, np.pi / 2, 2000)
    corner = 3 * np.column_stack([np.cos(t), np.sin(t)])
    # the four corner arcs (SVG coordinates) and the straight sides' ends
    arcs = [np.array([17, 7]) + corner, np.array([3, 7]) + corner * [-1, 1],
            np.array([3, 3]) - corner, np.array([17, 3]) + corner * [1, -1]]
    exact = flip(np.concatenate(arcs))
    assert distance_to_polygon(exact, polygon).max() <= 0.01 * (1 + 1e-9)
    assert distance_to_polygon(polygon, exact).max() < 1e-3
    assert len(polygon) < 60


def test_cubic_path_is_within_tolerance(tmp_path: Path) -> None:
    nodes = [(0, 0), (10, 30), (40, -20), (50, 10)]
    path = drawing(tmp_path, '<path id="s" d="M 0 0 C 10 30 40 -20 50 10 L 50 -10 Z"/>')
    for tolerance in (0.5, 0.01, 0.001):
        polygon = load_svg_points(path, "s", tolerance)
        exact = flip(bernstein(nodes, np.linspace(0, 1, 20_000)))
        assert distance_to_polygon(exact, polygon).max() <= tolerance * (1 + 1e-9)
        assert distance_to_curve(polygon[:-1], exact).max() < 1e-6  # all but (50, -10) lie on it


def test_smooth_and_relative_curves(tmp_path: Path) -> None:
    # S reflects the previous second control point: (10,0)·2 − (10,10) = (10,−10);
    # T reflects the previous quadratic control point: (30,0)·2 − (25,10) = (35,−10).
    path = drawing(tmp_path, '<path id="s" d="M 0 0 c 0 10 10 10 10 0 s 10 -10 10 0 q 5 10 10 0 t 10 0 Z"/>')
    pieces = [[(0, 0), (0, 10), (10, 10), (10, 0)], [(10, 0), (10, -10), (20, -10), (20, 0)],
              [(20, 0), (25, 10), (30, 0)], [(30, 0), (35, -10), (40, 0)]]
    t = np.linspace(0, 1, 5000)
    exact = flip(np.concatenate([bernstein(piece, t) for piece in pieces]))
    polygon = load_svg_points(path, "s", 0.01)
    assert distance_to_polygon(exact, polygon).max() <= 0.01 * (1 + 1e-9)
    assert distance_to_curve(polygon, exact).max() < 1e-6


@pytest.mark.parametrize(("d", "centre", "radius", "start", "sweep"), [
    ("M 10 0 A 10 10 0 0 1 0 10 L 0 0 Z", (0, 0), 10, 0.0, 90.0),        # quarter, centre (0, 0)
    ("M 10 0 A 10 10 0 1 1 0 10 L 10 10 Z", (10, 10), 10, -90.0, 270.0),  # large arc, centre (10, 10)
    ("M 10 0 a 10 10 0 0 0 -20 0 Z", (0, 0), 10, 0.0, -180.0),           # relative half turn
    ("M 0 0 A 1 1 0 0 1 10 0 Z", (5, 0), 5, 180.0, 180.0),               # radii too small: scaled up
])
def test_arc_is_within_tolerance(
    tmp_path: Path, d: str, centre: tuple[float, float], radius: float, start: float, sweep: float
) -> None:
    path = drawing(tmp_path, f'<path id="a" d="{d}"/>')
    polygon = load_svg_points(path, "a", 0.01)
    t = np.radians(start + sweep * np.linspace(0, 1, 20_000))
    exact = flip(np.array(centre) + radius * np.column_stack([np.cos(t), np.sin(t)]))
    assert distance_to_polygon(exact, polygon).max() <= 0.01 * (1 + 1e-9)
    on_circle = np.abs(np.hypot(*(polygon - flip(centre)).T) - radius) < 1e-9
    assert on_circle.sum() >= len(polygon) - 1  # all but a pie's other corner
    ideal = math.radians(abs(sweep)) / (2 * math.acos(1 - 0.01 / radius))
    assert on_circle.sum() <= 1.25 * ideal + 3


def test_rotated_elliptical_arc_under_a_transform(tmp_path: Path) -> None:
    # an ellipse about the origin, rx 20, ry 10, turned 30°, from parameter 10° to 150°
    phi = math.radians(30)
    rotation = np.array([[math.cos(phi), -math.sin(phi)], [math.sin(phi), math.cos(phi)]])

    def on_ellipse(u: np.ndarray) -> np.ndarray:
        return np.column_stack([20 * np.cos(u), 10 * np.sin(u)]) @ rotation.T

    (x0, y0), (x1, y1) = on_ellipse(np.radians([10.0, 150.0])).tolist()
    path = drawing(tmp_path, f'<g transform="matrix(2 0.5 0 0.7 3 1)">'
                             f'<path id="a" d="M {x0!r} {y0!r} A 20 10 30 0 1 {x1!r} {y1!r} Z"/></g>')
    polygon = load_svg_points(path, "a", 0.01)
    local = on_ellipse(np.radians(np.linspace(10.0, 150.0, 20_000)))
    exact = np.column_stack([2 * local[:, 0] + 3, -(0.5 * local[:, 0] + 0.7 * local[:, 1] + 1)])
    assert distance_to_polygon(exact, polygon).max() <= 0.01 * (1 + 1e-9)
    assert distance_to_curve(polygon, exact).max() < 1e-6


finite = st.floats(-100, 100, allow_nan=False)


@settings(max_examples=60, deadline=None)
@given(
    nodes=st.lists(st.tuples(finite, finite), min_size=4, max_size=4),
    linear=st.tuples(st.floats(-3, 3), st.floats(-3, 3), st.floats(-3, 3), st.floats(-3, 3)),
    tolerance=st.sampled_from([1.0, 0.1, 0.01]),
)
def test_any_transformed_cubic_is_within_tolerance(
    tmp_path_factory: pytest.TempPathFactory, nodes: list[tuple[float, float]],
    linear: tuple[float, float, float, float], tolerance: float,
) -> None:
    a, b, c, d = linear
    coordinates = " ".join(f"{x!r} {y!r}" for x, y in nodes[1:])
    path = drawing(tmp_path_factory.mktemp("cubic"),
                   f'<path id="s" transform="matrix({a!r} {b!r} {c!r} {d!r} 7 -3)" '
                   f'd="M {nodes[0][0]!r} {nodes[0][1]!r} C {coordinates} L -500 -500 Z"/>')
    try:
        polygon = load_svg_points(path, "s", tolerance)
    except SvgError as error:  # a transform that collapses the outline
        assert "distinct vertices" in str(error)
        return
    local = bernstein(nodes, np.linspace(0, 1, 4000))
    exact = np.column_stack([a * local[:, 0] + c * local[:, 1] + 7, -(b * local[:, 0] + d * local[:, 1] - 3)])
    assert distance_to_polygon(exact, polygon).max() <= tolerance * (1 + 1e-9) + 1e-9


# --- refusals ------------------------------------------------------------------------


def test_error_is_a_scene_error_on_one_line(tmp_path: Path) -> None:
    with pytest.raises(SvgError) as caught:
        load_svg_points(tmp_path / "nowhere.svg", "body")
    assert isinstance(caught.value, SceneError) and isinstance(caught.value, ValueError)
    message = str(caught.value)
    assert "\n" not in message
    assert message.startswith(f"{tmp_path / 'nowhere.svg'}#body: ")
    assert "no file" in message


def test_missing_id_names_it_and_suggests_a_close_one(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<polygon id="body" points="0,0 1,0 1,1"/><rect id="tail" width="1" height="1"/>')
    with pytest.raises(SvgError, match=r'#bdy: .*did you mean \'body\'\?.*"body", "tail"'):
        load_svg_points(path, "bdy")


@pytest.mark.parametrize(("d", "found"), [
    ("M 0 0 L 10 X 10 10 Z", "X 10 10 Z"),
    ("M 0 0 L 10 10 L 20 0 e", "'e'"),
    ("M 0 0 L 10", "right count"),
    ("L 0 0 L 10 10 L 0 10 Z", "starts with M"),
    ("", "empty"),
])
def test_malformed_path_data(tmp_path: Path, d: str, found: str) -> None:
    path = drawing(tmp_path, f'<path id="bad" d="{d}"/>')
    with pytest.raises(SvgError, match="#bad: ") as caught:
        load_svg_points(path, "bad")
    assert found in str(caught.value)


def test_malformed_points(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<polygon id="odd" points="0,0 1,0 1"/><polygon id="junk" points="0,0 1,0 1,a"/>')
    with pytest.raises(SvgError, match="#odd: .*odd count"):
        load_svg_points(path, "odd")
    with pytest.raises(SvgError, match="#junk: .*'a'"):
        load_svg_points(path, "junk")


@pytest.mark.parametrize("d", [
    "M 0 0 L 10 0 L 10 10 Z M 2 2 L 8 2 L 8 8 Z",   # a hole
    "M 0 0 L 10 0 L 10 10 Z L -5 -5 L -5 0",       # drawing on after Z
])
def test_several_subpaths_are_refused(tmp_path: Path, d: str) -> None:
    path = drawing(tmp_path, f'<path id="holed" d="{d}"/>')
    with pytest.raises(SvgError, match="#holed: .*2 subpaths"):
        load_svg_points(path, "holed")


def test_a_move_that_draws_nothing_is_not_a_subpath(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<path id="p" d="M 5 5 M 0 0 L 10 0 L 10 10 Z m 3 3"/>')
    np.testing.assert_array_equal(load_svg_points(path, "p"), flip([[0, 0], [10, 0], [10, 10]]))


@pytest.mark.parametrize("body", [
    '<polygon id="p" points="0,0 1,1 0,0"/>',
    '<path id="p" d="M 0 0 L 5 0 Z"/>',
    '<rect id="p" width="0" height="3"/>',
    '<polygon id="p" points=""/>',
])
def test_fewer_than_three_vertices(tmp_path: Path, body: str) -> None:
    with pytest.raises(SvgError, match="#p: .*(3 distinct vertices|positive size)"):
        load_svg_points(drawing(tmp_path, body), "p")


@pytest.mark.parametrize(("body", "kind"), [
    ('<text id="x" x="0" y="0">hi</text>', "<text>"),
    ('<g id="x"><rect width="1" height="1"/></g>', "<g>"),
    ('<image id="x" width="1" height="1" href="a.png"/>', "<image>"),
])
def test_unsupported_elements(tmp_path: Path, body: str, kind: str) -> None:
    with pytest.raises(SvgError, match=f"#x: expected one of <path>.*found {kind}"):
        load_svg_points(drawing(tmp_path, body), "x")


LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE svg [
  <!ENTITY a "ha">
  <!ENTITY b "&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;">
  <!ENTITY c "&b;&b;&b;&b;&b;&b;&b;&b;&b;&b;">
]>
<svg xmlns="http://www.w3.org/2000/svg"><text id="t">&c;</text><polygon id="p" points="0,0 1,0 1,1"/></svg>
"""


@pytest.mark.parametrize("encoding", ["utf-8", "utf-16"])
def test_entity_declarations_are_refused(tmp_path: Path, encoding: str) -> None:
    path = tmp_path / "laughs.svg"
    path.write_bytes(LAUGHS.replace("1.0\"?>", f"1.0\" encoding=\"{encoding}\"?>").encode(encoding))
    with pytest.raises(SvgError, match="#p: .*entity"):
        load_svg_points(path, "p")


@pytest.mark.parametrize(("declaration", "refused"), [
    ('<!ENTITY e SYSTEM "/etc/hostname">', "SYSTEM"),
    ('<!ENTITY % p "x">', "p"),
    ('<!ENTITY big "' + "x" * 5000 + '">', "more than"),
])
def test_unsafe_entities_are_refused(tmp_path: Path, declaration: str, refused: str) -> None:
    path = tmp_path / "unsafe.svg"
    path.write_text(f'<!DOCTYPE svg [ {declaration} ]>\n<svg xmlns="http://www.w3.org/2000/svg">'
                    + '<polygon id="p" points="0,0 1,0 1,1" fill="&big;"/>' * (1000 if "big" in declaration else 1)
                    + "</svg>")
    with pytest.raises(SvgError, match=f"expected plain SVG or internal entities.*{refused}"):
        read_drawing(path)


def test_plain_internal_entities_are_expanded_as_illustrator_writes_them(tmp_path: Path) -> None:
    """Illustrator's namespaces and styles as entities: the triangle is drawn in the entity's colour."""
    path = tmp_path / "illustrator.svg"
    path.write_text('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" '
                    '"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd" [\n'
                    '  <!ENTITY ns_svg "http://www.w3.org/2000/svg">\n  <!ENTITY st0 "fill:#FF0000;stroke:none;">\n]>\n'
                    '<svg xmlns="&ns_svg;" viewBox="0 0 10 10"><polygon style="&st0;" points="0,0 10,0 10,10"/></svg>')
    (element,) = read_drawing(path).elements
    assert element.paint.fill == (255, 0, 0, 255) and element.paint.stroke is None


def test_internal_dtd_subset_is_refused_but_a_plain_doctype_is_not(tmp_path: Path) -> None:
    subset = tmp_path / "subset.svg"
    subset.write_text('<!DOCTYPE svg [ <!ATTLIST svg foo CDATA "x"> ]>\n'
                      '<svg xmlns="http://www.w3.org/2000/svg"><polygon id="p" points="0,0 1,0 1,1"/></svg>')
    with pytest.raises(SvgError, match="#p: .*DOCTYPE"):
        load_svg_points(subset, "p")
    plain = tmp_path / "plain.svg"
    plain.write_text('<!DOCTYPE svg PUBLIC "-//W3C//DTD SVG 1.1//EN" '
                     '"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd">\n'
                     '<svg xmlns="http://www.w3.org/2000/svg"><polygon id="p" points="0,0 1,0 1,1"/></svg>')
    assert load_svg_points(plain, "p").shape == (3, 2)


def test_oversized_file_is_refused_before_parsing(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = drawing(tmp_path, '<polygon id="p" points="0,0 1,0 1,1"/>' + " " * 500)
    monkeypatch.setattr(svg_document, "MAX_FILE_BYTES", 256)
    with pytest.raises(SvgError, match="#p: expected a drawing of at most 256 bytes, found"):
        load_svg_points(path, "p")


@pytest.mark.parametrize(("text", "found"), [
    ('<svg xmlns="http://www.w3.org/2000/svg"><polygon id="p" points="0,0 1,0 1,1"></svg>', "mismatched tag"),
    ("not xml at all", "syntax error"),
    ('<html><polygon id="p" points="0,0 1,0 1,1"/></html>', "<svg> root"),
])
def test_unreadable_xml(tmp_path: Path, text: str, found: str) -> None:
    path = tmp_path / "broken.svg"
    path.write_text(text)
    with pytest.raises(SvgError, match="#p: expected") as caught:
        load_svg_points(path, "p")
    assert found in str(caught.value)


def test_duplicate_ids_are_refused(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<polygon id="p" points="0,0 1,0 1,1"/>\n<polygon id="p" points="0,0 2,0 2,2"/>')
    with pytest.raises(SvgError, match=r"#p: expected a unique id, found 2 .*lines 2, 3"):
        load_svg_points(path, "p")


@pytest.mark.parametrize("tolerance", [0, -0.01, float("nan"), float("inf"), True, "small"])
def test_tolerance_must_be_finite_and_positive(tmp_path: Path, tolerance: object) -> None:
    path = drawing(tmp_path, '<circle id="c" r="1"/>')
    with pytest.raises(SvgError, match="#c: expected .*tolerance"):
        load_svg_points(path, "c", tolerance)  # type: ignore[arg-type]


def test_absurdly_small_tolerance_is_refused(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<circle id="c" r="1000"/>')
    with pytest.raises(SvgError, match="#c: expected at most"):
        load_svg_points(path, "c", 1e-9)


# --- the example drawings --------------------------------------------------------------

KEYS = [("bird0.svg", "body"), ("bird0.svg", "wing"), ("bird1.svg", "body"), ("bird1.svg", "wing"),
        ("letter0.svg", "letter"), ("letter1.svg", "letter"), ("foot0.svg", "leg"), ("foot1.svg", "leg")]


@pytest.mark.parametrize(("name", "element_id"), KEYS)
def test_example_drawings_load(name: str, element_id: str) -> None:
    polygon = load_svg_points(SCENES / name, element_id)
    assert polygon.ndim == 2 and polygon.shape[1] == 2 and len(polygon) >= 3
    assert np.all(np.isfinite(polygon))
    assert DEFAULT_TOLERANCE > 0


def test_letter_keys_are_an_l_and_a_seven() -> None:
    # the 7 is drawn upside down inside rotate(180 50 50): (x, y) → (100 − x, 100 − y), then y flipped
    np.testing.assert_allclose(load_svg_points(SCENES / "letter0.svg", "letter"),
                               flip([[30, 20], [42, 20], [42, 68], [72, 68], [72, 80], [30, 80]]), atol=1e-12)
    np.testing.assert_allclose(load_svg_points(SCENES / "letter1.svg", "letter"),
                               flip([[28, 20], [72, 20], [50, 80], [38, 80], [58, 32], [28, 32]]), atol=1e-12)


@pytest.mark.parametrize(("body", "found"), [
    ('<circle id="p" r="-3"/>', "r ≥ 0"),
    ('<rect id="p" width="-3" height="2"/>', "width ≥ 0"),
    ('<path id="p" d="M 0 0 L 1e400 0 L 5 5 Z"/>', "finite coordinates"),
])
def test_negative_sizes_and_infinite_coordinates(tmp_path: Path, body: str, found: str) -> None:
    with pytest.raises(SvgError, match=f"#p: expected {found}"):
        load_svg_points(drawing(tmp_path, body), "p")


def test_error_survives_pickling(tmp_path: Path) -> None:
    import pickle

    with pytest.raises(SvgError) as caught:
        load_svg_points(tmp_path / "nowhere.svg", "body")
    copy = pickle.loads(pickle.dumps(caught.value))
    assert str(copy) == str(caught.value) and copy.element_id == "body"


def test_a_line_is_an_open_contour(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<line id="x" x1="1" y1="2" x2="7" y2="5"/>')
    ((points, closed),) = svg.load_svg_contours(path, "x")
    assert not closed
    np.testing.assert_array_equal(points, flip([[1, 2], [7, 5]]))
    with pytest.raises(SvgError, match="#x: .*3 distinct vertices"):
        load_svg_points(path, "x")


def test_holes_and_pieces_are_contours(tmp_path: Path) -> None:
    path = drawing(tmp_path, '<path id="o" d="M 0 0 H 10 V 10 H 0 Z M 2 2 V 8 H 8 V 2 Z M 20 0 L 30 0"/>')
    contours = svg.load_svg_contours(path, "o")
    assert [closed for _, closed in contours] == [True, True, False]
    np.testing.assert_array_equal(contours[0][0], flip([[0, 0], [10, 0], [10, 10], [0, 10]]))
    np.testing.assert_array_equal(contours[1][0], flip([[2, 2], [2, 8], [8, 8], [8, 2]]))
    np.testing.assert_array_equal(contours[2][0], flip([[20, 0], [30, 0]]))


def test_a_huge_circle_at_a_tiny_tolerance_is_refused_for_its_vertices(tmp_path: Path) -> None:
    """1 - tol/r rounds to 1 here: the step must not come out 0 (it once divided by zero)."""
    path = drawing(tmp_path, '<circle id="c" r="1e8"/>')
    with pytest.raises(SvgError, match="#c: expected at most .* vertices"):
        load_svg_points(path, "c", 1e-9)


def test_use_expansion_is_counted_and_stops_early(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    levels = ['<rect id="l0" width="1" height="1"/>']
    for k in range(1, 9):
        levels.append(f'<g id="l{k}">' + "".join(f'<use href="#l{k - 1}" x="{i}"/>' for i in range(10)) + "</g>")
    path = drawing(tmp_path, "<defs>" + "".join(levels) + '</defs><use href="#l8"/>', 'viewBox="0 0 24 24"')
    visits = []
    visit = svg_document._Walk.visit

    def counted(self, *args, **kwargs):  # type: ignore[no-untyped-def]
        visits.append(1)
        return visit(self, *args, **kwargs)

    monkeypatch.setattr(svg_document._Walk, "visit", counted)
    with pytest.raises(SvgError, match="at most 50000 elements once <use> copies are counted"):
        svg.read_drawing(path)
    # 10⁸ copies in the file; the walk stops at the limit instead of visiting them
    assert svg_document.MAX_EXPANDED < len(visits) <= svg_document.MAX_EXPANDED + 1


def test_use_loops_are_left_out(tmp_path: Path) -> None:
    # SVG 2 §5.6: a <use> in a loop of references is in error and not rendered; the rest is drawn
    path = drawing(tmp_path, '<g id="a"><use href="#b"/></g><g id="b"><use href="#a"/></g>'
                   '<rect id="r" width="1" height="1"/>', 'viewBox="0 0 1 1"')
    assert [e.id for e in svg.read_drawing(path).elements] == ["r"]


def test_huge_path_data_is_refused_before_it_is_parsed(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    import svgelements

    rng = np.random.default_rng(0)
    numbers = " ".join(f"L{x:.6f} {y:.6f}" for x, y in rng.random((1_000_000, 2)))
    path = drawing(tmp_path, f'<path d="M0 0 {numbers}"/>', 'viewBox="0 0 1 1"')
    assert path.stat().st_size < svg_document.MAX_FILE_BYTES
    parsed = []

    class Counted(svgelements.Path):  # type: ignore[misc]
        def __init__(self, *args, **kwargs):  # type: ignore[no-untyped-def]
            parsed.append(args)
            super().__init__(*args, **kwargs)

    monkeypatch.setattr(svgelements, "Path", Counted)
    with pytest.raises(SvgError, match="at most 200000 vertices, found data for more"):
        svg.read_drawing(path)
    assert parsed == []  # refused from a count of its numbers: parsing it would take tens of seconds


# -- smooth curves after a curve of the other kind (SVG 1.1 §8.3.6, §8.3.7) ---------------------------

def _second_piece(tmp_path: Path, d: str) -> np.ndarray:
    """The flattened points of path ``d`` right of x = 10 (its second segment), in SVG's y-down units."""
    path = tmp_path / "s.svg"
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40"><path id="x" d="{d}" '
                    'fill="none" stroke="black"/></svg>')
    ((points, _),) = svg.load_svg_contours(path, "x", tolerance=1e-4)
    points = points * [1.0, -1.0]
    return points[points[:, 0] > 10.0 + 1e-9]


def test_s_after_a_quadratic_starts_from_the_current_point(tmp_path: Path) -> None:
    # S's first control point is the current point (10, 0): y(t) = 60 (1 - t) t², highest 80/9 at t = 2/3
    piece = _second_piece(tmp_path, "M0 0 Q 5 5 10 0 S 20 20 30 0")
    assert abs(piece[:, 1].max() - 80 / 9) < 1e-3


def test_t_after_a_cubic_is_a_straight_line(tmp_path: Path) -> None:
    # T's control point is the current point (10, 0): the quadratic to (20, 0) is the segment between them
    piece = _second_piece(tmp_path, "M0 0 C 0 10 10 10 10 0 T 20 0")
    assert np.abs(piece[:, 1]).max() < 1e-9 and piece[:, 0].max() == pytest.approx(20.0)
