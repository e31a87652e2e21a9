"""``stats``' quality measures (DESIGN turn 4): ``crossings``, ``stroke_crossings`` and ``stray_max`` per entry and
method, ``pops`` per method, on real icon pairs with holes and pieces, against shapely and by construction."""

from __future__ import annotations

from collections import defaultdict

import numpy as np
import pytest

import tweenrender as tr
from tests.core.shapely_areas import drawn_area, stray_share
from tests.core.shapely_tangles import tangled
from tests.helpers import DATA, SCENES
from tweenrender.core.tangles import SWEEP, tangled_times
from tweenrender.core.timing.timeline import pair_paths, tracks_of
from tweenrender.reports.stats import stats_dict, stats_text

ICONS = DATA / "icons"


def _pair(a: str, b: str, **timing: object) -> tr.Scene:
    return tr.load_scene([ICONS / f"{a}.svg", ICONS / f"{b}.svg"], step=1.0, **timing)


def _shapely_crossings(scene: tr.Scene, method: str) -> set[tuple[str, float]]:
    """(element, t) at which shapely finds the element's contours in both keys tangled, the in-betweens
    as ``tr.contours`` draws them (a one-segment morph of 1 s: t is the time)."""
    at_t = []
    for t in SWEEP:
        drawn: dict[str, list[np.ndarray]] = defaultdict(list)
        for c in tr.contours(scene, float(t), method=method, points=True):
            drawn[c.element].append(c.points)
        at_t.append(drawn)
    out = set()
    for shape, track in zip(scene.shapes, tracks_of(scene)):
        pairs = track.segments[0].pairs
        kept = [k for k, p in enumerate(pairs) if not p.fades]  # growing and shrinking ones too
        if not all(track.segments[0].shown) or not any(pairs[k].moving for k in kept):
            continue
        closed = [pairs[k].closed for k in kept]
        assert all(len(d[shape.name]) == len(pairs) for d in at_t)  # every contour drawn, in pair order
        frames = [[d[shape.name][k] for k in kept] for d in at_t]
        keys0, keys1 = frames[0], frames[-1]  # as drawn at the keys: a growing contour is its point there
        out |= {(shape.name, float(t)) for t, f in zip(SWEEP, frames) if tangled(f, keys0, keys1, closed)[0]}
    return out


@pytest.mark.parametrize("a, b, method", [
    ("simple-icons/apple", "simple-icons/python", "linear"),  # two pieces that overlap on the way
    ("mdi/alpha-o-box", "mdi/alpha-o", "nonlinear"),  # a hole leaving its outline through its corners
    ("mdi/weather-night", "mdi/weather-sunny", "rigid"),  # four contours: pieces and holes
    ("twemoji/1f4c4", "mdi/weather-sunny", "linear"),  # seven pieces
])
def test_crossings_of_real_pairs_are_what_shapely_sees(a: str, b: str, method: str) -> None:
    scene = _pair(a, b)
    found = {(s["name"], t) for s in stats_dict(scene, [0.5], [method])["shapes"]
             for t in s["methods"][method]["crossings"]}
    assert found and found == _shapely_crossings(scene, method)


def test_the_pieces_meeting_were_left_out_before() -> None:
    """The apple and python pair's pieces overlap at 82 t (the t shapely sees: the test above) that a contour
    crossing itself or a hole leaving its outline does not show (the measure as it was)."""
    scene = _pair("simple-icons/apple", "simple-icons/python")
    segment = next(segment for track in tracks_of(scene) for segment in track.segments
                   if sum(p.moving for p in segment.pairs) > 1)
    frames = pair_paths(segment, SWEEP, "linear")
    assert tangled_times(frames, [p.closed for p in segment.pairs], SWEEP) == []
    entry = next(s for s in stats_dict(scene, [0.5], ["linear"])["shapes"] if s["methods"]["linear"]["crossings"])
    assert len(entry["methods"]["linear"]["crossings"]) == 82


def test_stray_max_is_shapely_s_largest_stray_over_twenty_steps() -> None:
    scene = tr.load_scene(SCENES / "square.toml")  # a square of side 2 moving 5.5 in a view 10 wide
    x0, y0, x1, y1 = scene.view
    reach = 0.12 * max(x1 - x0, y1 - y0)
    measured = stats_dict(scene, [0.5], ["linear", "nonlinear"])["shapes"][0]["methods"]
    start, end = 0.0, 2.0
    for method in ("linear", "nonlinear"):
        areas = [drawn_area([c.points for c in tr.contours(scene, start + t * (end - start), method) if c.closed],
                            "nonzero") for t in np.arange(21) / 20]
        exact = max(stray_share(area, areas[0], areas[-1], reach) for area in areas)
        assert exact > 0.3 and measured[method]["stray_max"] == pytest.approx(exact, abs=0.02), method


@pytest.mark.parametrize("a, b", [("bootstrap/emoji-smile", "twemoji/1f319"), ("twemoji/1f319", "octicons/heart-24")])
def test_stray_max_of_real_elements_drawn_with_a_hole_is_shapely_s(a: str, b: str) -> None:
    """The smile's face is a ring (a hole wound against its outline, nonzero) whose hole shrinks away
    while the moon's crescent comes; the moon's two contours become the heart's one, one of them drawn
    reversed: the in-betweens' stray as drawn, windings and fill rule included."""
    scene = _pair(a, b)
    x0, y0, x1, y1 = scene.view
    reach = 0.12 * max(x1 - x0, y1 - y0)
    stats = stats_dict(scene, [0.5], ["linear"])
    measured = {s["methods"]["linear"]["stray_max"] for s in stats["shapes"] if s["name"] == "path1"}

    def area(t: float) -> object:
        drawn = [c for c in tr.contours(scene, t, "linear") if c.element == "path1" and c.closed]
        return drawn_area([c.points[::-1] if c.reversed else c.points for c in drawn], drawn[0].fill_rule)

    exact = max(stray_share(area(t), area(0.0), area(1.0), reach) for t in np.arange(21) / 20)
    assert len(measured) == 1 and exact > 0.05
    assert measured.pop() == pytest.approx(exact, abs=0.01)


def test_a_drawing_jumping_in_steps_pops_at_each_step_and_a_smooth_one_never() -> None:
    # steps(2): frames 0-11 show the first key, 12-23 the half-way in-between, 24 the second key
    stepped = stats_dict(_pair("mdi/weather-night", "mdi/weather-sunny", ease="steps(2)"), [0.5], ["linear", "rigid"])
    assert stepped["pops"] == {"linear": [12, 24], "rigid": [12, 24]}
    smooth = stats_dict(_pair("mdi/weather-night", "mdi/weather-sunny"), [0.5], ["linear", "rigid"])
    assert smooth["pops"] == {"linear": [], "rigid": []}


def test_the_text_says_where_a_shape_tangles_how_far_it_strays_and_what_pops() -> None:
    stats = stats_dict(_pair("simple-icons/apple", "simple-icons/python", ease="steps(2)"), [0.5], ["linear"])
    words = stats_text(stats)
    assert "The shape tangles at t = 0.12 to 0.93" in words  # the first and last t shapely sees (above)
    assert "of an inbetween strays from both keys" in words
    assert "POPS" in words and "linear: frames 12, 24" in words
    for shape in stats["shapes"]:
        assert shape["methods"]["linear"]["stroke_crossings"] == []
        assert 0.0 <= shape["methods"]["linear"]["stray_max"] <= 1.0


def test_keys_that_already_cross_do_not_tangle_and_injective_says_why_it_draws_rigid_paths(tmp_path) -> None:
    """Two squares that overlap in both keys (shapely: their outlines cross) and slide: no morph keeps them
    apart, and none has to. Neither is a hole of the other, so nothing tangles; `injective`, which needs
    keys whose contours do not cross, says so instead of drawing rigid paths silently."""
    import shapely

    from tests.helpers import write_scene

    k0 = [[[0, 0], [10, 0], [10, 10], [0, 10]], [[5, 2], [15, 2], [15, 8], [5, 8]]]
    k1 = [[[0, 0], [10, 0], [10, 10], [0, 10]], [[6, 2], [16, 2], [16, 8], [6, 8]]]
    for key in (k0, k1):
        assert shapely.LinearRing(key[0]).crosses(shapely.LinearRing(key[1]))
    scene = tr.load_scene(write_scene(tmp_path, f'[[shape]]\nname = "s"\n[[shape.key]]\ntime = 0\ncontours = {k0}\n'
                                                f'[[shape.key]]\ntime = 1\ncontours = {k1}\n'))
    stats = stats_dict(scene, [0.5], ["linear", "injective"])
    assert stats["shapes"]
    for entry in stats["shapes"]:
        assert entry["methods"]["linear"]["crossings"] == [] == entry["methods"]["injective"]["crossings"]
        assert "cross" in entry["methods"]["injective"]["fallback"]
    assert _shapely_crossings(scene, "linear") == set()
    assert "No injective morph: " in stats_text(stats)
    square = stats_dict(tr.load_scene(SCENES / "square.toml"), [0.5], ["injective"])
    assert square["shapes"][0]["methods"]["injective"]["fallback"] is None


def test_injective_names_the_slit_that_keeps_it_from_a_mesh() -> None:
    """The check of bootstrap's check-circle has no partner in the python logo and no room to grow: it is joined
    to the ring by a slit, whose two sides pass the same points. The sources have no such points (shapely:
    each of their rings is simple), so it is the slit `injective` cannot mesh, and stats says so."""
    import shapely

    for name in ("bootstrap/check-circle", "simple-icons/python"):
        scene = tr.load_scene(ICONS / f"{name}.svg")
        for shape in scene.shapes:
            for contour in shape.keys[0].contours:
                if contour.closed and len(contour.points) >= 3:
                    assert shapely.LinearRing(contour.points).is_simple, name
    stats = stats_dict(_pair("bootstrap/check-circle", "simple-icons/python"), [0.5], ["injective"])
    reasons = [s["methods"]["injective"]["fallback"] for s in stats["shapes"] if s["methods"]["injective"]["fallback"]]
    assert reasons and all("slit" in reason for reason in reasons), reasons
    assert "joined by a slit" in stats_text(stats)


def test_pops_measure_each_shapes_frames_once_for_the_methods_that_draw_them_alike(monkeypatch: pytest.MonkeyPatch) -> None:
    # a face becoming a circled check: most of the face's elements have no partner and grow or shrink alike under
    # every method; each distinct run of frames of a shape is measured once (counted), and the pops are those of
    # measuring every method apart
    import tweenrender.reports.stats as stats_module
    from tweenrender.core.coverage import Grid
    from tweenrender.core.pops import changes, pops
    from tweenrender.core.view import Viewport
    from tweenrender.plan.job import scene_view, total_frames
    from tweenrender.reports.stats import POP_CELLS, STATS_METHODS

    scene = _pair("twemoji/1f600", "tabler/circle-check")
    tracks = tracks_of(scene)
    view = scene_view(scene, tracks, (None,))
    grid = Grid.over(view, max(view[2] - view[0], view[3] - view[1]) / POP_CELLS)
    pixel = 1.0 / Viewport(view, *scene.size).scale
    times = np.arange(total_frames(scene)) / scene.fps
    apart: dict[str, list[int]] = {}
    distinct: set[tuple[int, bytes]] = set()
    for method in STATS_METHODS:
        change = np.zeros(len(times))
        for k, (track, shape) in enumerate(zip(tracks, scene.shapes)):
            drawn = track.at(times, method)
            rules = [(at.key.fill_rule if at.key is not None else None) or shape.fill_rule for at in drawn]
            change += changes(grid, drawn, rules, 1.0 if shape.stroke_scales else pixel)
            distinct.add((k, b"".join(np.ascontiguousarray(c).tobytes() for at in drawn for c in at.contours)
                          + repr([(at.visible, at.fade, at.sides, at.paint, at.widths, at.reversed) for at in drawn]).encode()))
        apart[method] = pops(change)
    measured = []
    monkeypatch.setattr(stats_module, "changes", lambda *a, **k: measured.append(1) or changes(*a, **k))
    found = stats_dict(scene, [0.5])
    assert found["pops"] == apart
    assert len(measured) == len(distinct) < len(STATS_METHODS) * len(scene.shapes)



def _two_strokes(folder, x: float):  # noqa: ANN001, ANN202
    """A drawing of one element, two open strokes: a long upright one at ``x`` and a short level one at
    x = 18.5 … 21.5, y = 20."""
    path = folder / f"strokes-{x:g}.svg"
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40">'
                    f'<path id="strokes" fill="none" stroke="#000" d="M{x} 10 L{x} 30 M18.5 20 L21.5 20"/></svg>')
    return path


def test_an_element_of_open_strokes_alone_is_measured_for_crossings(tmp_path) -> None:
    """An element whose contours are all open strokes has no closed contour for the thesis's measures, but its
    strokes can still cross: an upright stroke slides from x = 10 to 30 through a short level one at
    x = 18.5 … 21.5. They are apart in both keys, and on the straight paths meet from t = 0.425 to 0.575.
    `stats` reports the element under ``others``, with what auto draws and, per method, the t at which
    shapely finds the drawn strokes crossing; no ``stray_max``, which is measured on closed outlines' area
    (the strokes stray by their length)."""
    import shapely

    scene = tr.load_scene([_two_strokes(tmp_path, 10), _two_strokes(tmp_path, 30)], step=1.0)
    stats = stats_dict(scene, [0.5], ["linear"])
    assert stats["shapes"] == []
    (entry,) = stats["others"]
    assert entry["element"] == "strokes" and entry["times"] == [0.0, 1.0] and (entry["strokes"], entry["growing"]) == (2, 0)
    assert set(entry["auto"]) == {"method", "balance", "why"}
    seen = []
    for t in SWEEP:
        upright, level = (shapely.LineString(c.points) for c in tr.contours(scene, float(t), method="linear"))
        if upright.intersects(level):
            seen.append(float(t))
    assert seen and seen[0] == pytest.approx(0.43) and seen[-1] == pytest.approx(0.57)
    assert entry["methods"]["linear"]["stroke_crossings"] == seen and "stray_max" not in entry["methods"]["linear"]
    words = stats_text(stats)
    assert "OTHERS strokes, segment 0 (0 s to 1 s): 2 open strokes" in words
    assert "Its strokes cross at t = 0.43 to 0.57" in words and "the thesis's measures need closed outlines" in words


def test_an_open_stroke_strays_by_its_length_the_closed_form(tmp_path) -> None:
    """``stroke_stray_max``: the largest share of the strokes' length (t = k/20) farther than 12 % of the view
    (4.8 of 40) from both keys' contours. Sliding at x = 10 + 20 t, the upright stroke (y = 10 … 30) is near the
    keys' uprights while within 4.8 of x = 10 or 30, and elsewhere only where within 4.8 of the level stroke
    (x = 18.5 … 21.5, y = 20, near in every frame): |y − 20| ≤ √(4.8² − dx²), dx its gap to the level stroke
    in x. Of both strokes' 23 units, the far share peaks at t = 0.25 and 0.75: (20 − 2√(4.8² − 3.5²)) / 23."""
    import math

    scene = tr.load_scene([_two_strokes(tmp_path, 10), _two_strokes(tmp_path, 30)], step=1.0)
    entry = stats_dict(scene, [0.5], ["linear"])["others"][0]

    def far_share(t: float) -> float:
        x = 10.0 + 20.0 * t
        if min(x - 10.0, 30.0 - x) <= 4.8:
            return 0.0
        dx = max(0.0, 18.5 - x, x - 21.5)
        near = 2.0 * math.sqrt(4.8 ** 2 - dx ** 2) if dx < 4.8 else 0.0
        return (20.0 - near) / 23.0

    exact = max(far_share(k / 20) for k in range(21))
    assert exact == pytest.approx((20 - 2 * math.sqrt(4.8 ** 2 - 3.5 ** 2)) / 23)
    assert entry["methods"]["linear"]["stroke_stray_max"] == pytest.approx(exact, abs=0.01)
    assert f"At most {100 * entry['methods']['linear']['stroke_stray_max']:.1f} % of its strokes' length" in (
        stats_text(stats_dict(scene, [0.5], ["linear"])))


def test_an_element_whose_contours_all_grow_or_shrink_is_measured_for_tangles(tmp_path) -> None:
    """A level stroke 36 long with no partner shrinks to its middle while a square 20 wide, with none either,
    grows from the same point: the stroke pokes through the square's sides until its half-length falls
    below the square's half-side (each scaled by the square root of its share of area, 18·√(1 − t) = 10·√t at
    t = 0.764). No contour is in both keys, so auto has nothing to choose over (``None``);
    ``others`` still gives where the stroke crosses, at the t where shapely finds the drawn stroke and square
    boundary meeting (a contour one point at a key meets nothing there)."""
    import shapely

    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40"><path id="e" fill="none" '
                 'stroke="#000" d="M2 20 L38 20"/></svg>')
    b.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 40 40"><path id="e" fill="none" '
                 'stroke="#000" d="M10 30 L30 30 L30 10 L10 10 Z"/></svg>')
    scene = tr.load_scene([a, b], step=1.0)
    stats = stats_dict(scene, [0.5], ["linear"])
    (entry,) = stats["others"]
    assert (entry["strokes"], entry["growing"], entry["auto"]) == (1, 2, None)
    seen = []
    for t in SWEEP[1:-1]:
        stroke, square = tr.contours(scene, float(t), method="linear")
        assert not stroke.closed and square.closed
        if shapely.LineString(stroke.points).intersects(shapely.LinearRing(square.points)):
            seen.append(float(t))
    assert seen[-1] == pytest.approx(0.76) and seen == [float(t) for t in SWEEP[1:len(seen) + 1]]
    assert entry["methods"]["linear"]["stroke_crossings"] == seen
    assert entry["methods"]["linear"]["crossings"] == []
    assert "1 open stroke, 2 contours growing or shrinking" in stats_text(stats)
    assert "auto has no contour in both keys to choose over" in stats_text(stats)


def test_auto_says_when_contours_without_a_partner_tangle_and_no_mesh_holds_them() -> None:
    """mdi's moped becoming its docker whale (``tests/data/pairs``): the containers have no partner, a wheel passes
    through the body on its way to one, and no mesh can hold them. What render draws tangles, as shapely sees it, and
    auto's reason says so, with the count of t, rather than only the moving contours' count."""
    folder = DATA / "pairs"
    scene = tr.load_scene([folder / "mdi-moped-outline.svg", folder / "mdi-docker.svg"], step=1.0)
    seen = _shapely_crossings(scene, scene.method_of(scene.shapes[0]))
    assert seen, "shapely finds the drawn in-betweens tangled"
    shapes = stats_dict(scene, [0.5], ["auto"])["shapes"]
    tangled_shapes = {name for name, _ in seen}
    for shape in shapes:
        if shape["name"] in tangled_shapes:
            why = shape["auto"]["why"]
            assert "with the contours without a partner:" in why and "no mesh holds them" in why, why
            count = int(why.split("with the contours without a partner:")[1].split("tangled at ")[1].split(" of")[0])
            assert count >= 1
