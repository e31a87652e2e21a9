"""Contours that stay apart are drawn as paths of their own in the animated SVG: the pieces are checked against
shapely's distances and containment on random moving polygons, and a real export is split where its contours come
and go apart (Chromium plays it against the project's own frames in tests/encode/test_vector_players.py:
mdi weather-night → bootstrap sun-fill)."""

from __future__ import annotations

import re
from dataclasses import replace

import numpy as np
import pytest

shapely = pytest.importorskip("shapely", reason="shapely (the test extra) measures the distances independently")
from shapely.geometry import LinearRing, Polygon  # noqa: E402

import tweenrender as tr  # noqa: E402
from tests.helpers import DATA, count_calls  # noqa: E402
from tweenrender.encode.animated_svg import svg_document  # noqa: E402
from tweenrender.pipeline.library import render_job  # noqa: E402
from tweenrender.plan.options import RenderOptions  # noqa: E402
from tweenrender.vector.export import vector_clip  # noqa: E402
from tweenrender.vector.pieces import apart_pieces  # noqa: E402

APART = 2.0


def _moving_polygons(rng: np.random.Generator, count: int, frames: int) -> list[np.ndarray]:
    """``count`` regular polygons, each moving and growing straight over ``frames``: ``(F, n, 2)`` each."""
    out = []
    for _ in range(count):
        sides = int(rng.integers(3, 9))
        angles = np.arange(sides) * 2 * np.pi / sides + rng.uniform(0, np.pi)
        unit = np.stack([np.cos(angles), np.sin(angles)], axis=1)
        start, end = rng.uniform(0, 200, 2), rng.uniform(0, 200, 2)
        r0, r1 = rng.uniform(2, 40, 2)
        s = np.linspace(0, 1, frames)[:, None, None]
        out.append((1 - s) * start + s * end + ((1 - s) * r0 + s * r1) * unit[None])
    return out


def _meets(a: np.ndarray, b: np.ndarray, reach: float) -> bool:
    """Whether two moving polygons come within ``reach`` or lie one inside the other at some frame (shapely)."""
    for pa, pb in zip(a, b):
        if LinearRing(pa).distance(LinearRing(pb)) <= reach or Polygon(pa).contains(Polygon(pb)) \
                or Polygon(pb).contains(Polygon(pa)):
            return True
    return False


@pytest.mark.parametrize("seed", range(12))
def test_pieces_are_the_groups_of_contours_that_meet(seed: int) -> None:
    """Two contours of different pieces are farther apart than ``apart`` at every frame and neither holds the
    other; two of one piece are joined by a chain of contours that come within half a step more (the densified
    edges' spacing) or hold one another at some frame."""
    rng = np.random.default_rng(seed)
    contours = _moving_polygons(rng, int(rng.integers(3, 9)), 6)
    pieces = apart_pieces(contours, APART)
    assert pieces is not None and sorted(i for p in pieces for i in p) == list(range(len(contours)))
    piece_of = {i: k for k, p in enumerate(pieces) for i in p}
    for i in range(len(contours)):
        for j in range(i + 1, len(contours)):
            if piece_of[i] != piece_of[j]:
                assert not _meets(contours[i], contours[j], APART), (i, j)
    linked = {(i, j) for i in range(len(contours)) for j in range(len(contours))
              if i != j and _meets(contours[i], contours[j], 1.5 * APART + 1e-9)}
    for members in pieces:
        reached, todo = {members[0]}, [members[0]]
        while todo:
            i = todo.pop()
            for j in members:
                if j not in reached and (i, j) in linked:
                    reached.add(j)
                    todo.append(j)
        assert reached == set(members), members


def test_one_contour_and_non_finite_points() -> None:
    square = np.array([[[0.0, 0.0], [1, 0], [1, 1], [0, 1]]])
    assert apart_pieces([square], APART) == ((0,),)
    assert apart_pieces([square, square + np.nan], APART) is None


def test_a_morph_whose_pieces_come_and_go_apart_draws_each_as_a_path_of_its_own(tmp_path) -> None:
    """The moon and stars of weather-night become the sun's disc and rays: rays that grow clear of everything are
    paths of their own, each keyed by its own keyframes, and the file is shorter than one path keyed together."""
    scene = tr.load_scene([DATA / "icons" / "mdi" / "weather-night.svg", DATA / "icons" / "bootstrap" / "sun-fill.svg"])
    written = tr.write(scene, tmp_path / "night.svg")
    text = written.read_text()
    group = text[text.index("<g id="):text.rindex("</g>")]
    assert len(re.findall(r"<path ", group)) >= 4
    assert 'attributeName="transform"' in group  # a ray growing from a point: a still path, scaled
    clip = vector_clip(render_job(scene, RenderOptions.create()))
    together = replace(clip, runs=tuple(replace(run, pieces=None) for run in clip.runs))
    assert len(svg_document(clip)) < len(svg_document(together))


def test_a_contour_growing_over_the_others_of_one_opaque_fill_is_a_path_of_its_own_under_its_move(tmp_path) -> None:
    """feather's check becoming simple-icons' apple: the leaf grows from a point on the check's outline, so it comes
    near the check and is no piece apart by distance; drawn in that one path, every contour was keyed at every frame
    the growth needs (31 KB). Under the nonzero rule, one opaque colour, no stroke and every contour wound one way,
    paths painted one over another cover what one path fills (overlaps add to the winding), so the leaf is a still
    path of its own under a keyed scale and position, and the file is less than a quarter the size. Chromium draws
    it as the frames are drawn (``tests/encode/test_vector_players.py``, ``svg-move-check-apple``). Under the
    even-odd rule the overlap would cancel, and the leaf stays in the check's path."""
    icons = DATA / "icons"
    scene = tr.load_scene([icons / "feather" / "check.svg", icons / "simple-icons" / "apple.svg"])
    clip = vector_clip(render_job(scene, RenderOptions.create()))
    (run,) = [r for r in clip.runs if r.contour_moves is not None and any(m is not None for m in r.contour_moves)]
    leaf = next(i for i, m in enumerate(run.contour_moves) if m is not None)
    assert run.pieces is not None and (leaf,) in run.pieces
    text = tr.write(scene, tmp_path / "apple.svg").read_text()
    assert 'attributeName="transform"' in text
    together = replace(clip, runs=tuple(replace(r, pieces=None) for r in clip.runs))
    assert 4 * len(svg_document(clip)) < len(svg_document(together))

    evenodd = replace(scene, shapes=tuple(replace(shape, fill_rule="evenodd", keys=tuple(
        replace(key, fill_rule="evenodd") for key in shape.keys)) for shape in scene.shapes))
    clip = vector_clip(render_job(evenodd, RenderOptions.create()))
    (run,) = [r for r in clip.runs if r.contour_moves is not None and any(m is not None for m in r.contour_moves)]
    assert run.fill_rule == "evenodd"
    assert run.pieces is None or all(len(p) > 1 or run.contour_moves[p[0]] is None for p in run.pieces)


def _winding(point: np.ndarray, ring: np.ndarray) -> int:
    """The winding number of the closed polygon ``ring (L, 2)`` about ``point``, by summing the angles it turns
    through (an independent brute force: no crossing rule)."""
    v = ring - point
    w = np.roll(v, -1, axis=0)
    angles = np.arctan2(v[:, 0] * w[:, 1] - v[:, 1] * w[:, 0], np.sum(v * w, axis=1))
    return int(round(float(angles.sum()) / (2 * np.pi)))


def _filled(point: np.ndarray, rings: list[np.ndarray], rule: str) -> bool:
    total = sum(_winding(point, r) for r in rings)
    return total % 2 == 1 if rule == "evenodd" else total != 0


def _hole_everywhere(contours: list[np.ndarray], h: int, rule: str, apart: float = APART) -> bool:
    """Whether contour ``h`` is, at every frame, more than ``apart`` from the others, holds none, and the fill
    leaves its inside empty and the band just outside it filled (shapely and the brute-force winding number)."""
    for f in range(len(contours[0])):
        rings = [c[f] for c in contours]
        hole = Polygon(rings[h])
        if hole.area <= 1e-9:
            continue
        for j, ring in enumerate(rings):
            if j != h and (LinearRing(rings[h]).distance(LinearRing(ring)) <= apart or hole.contains(Polygon(ring))):
                return False
        inner = np.array(hole.representative_point().coords[0])
        band = hole.buffer(APART / 2).difference(hole)
        outer = np.array(band.representative_point().coords[0])
        if _filled(inner, rings, rule) or not _filled(outer, rings, rule):
            return False
    return True


def _ring_with_holes(rng: np.random.Generator, frames: int) -> list[np.ndarray]:
    """A square outline and two to four small polygons moving inside and about it, each wound either way."""
    s = np.linspace(0, 1, frames)[:, None, None]
    square = np.array([[0.0, 0.0], [200, 0], [200, 200], [0, 200]])
    if rng.random() < 0.5:
        square = square[::-1]
    out = [np.broadcast_to(square, (frames, 4, 2)).copy()]
    for _ in range(int(rng.integers(2, 5))):
        sides = int(rng.integers(3, 7))
        angles = np.arange(sides) * 2 * np.pi / sides
        unit = np.stack([np.cos(angles), np.sin(angles)], axis=1)
        if rng.random() < 0.5:
            unit = unit[::-1]
        start, end = rng.uniform(20, 180, 2), rng.uniform(-20, 220, 2)
        r0, r1 = rng.uniform(3, 30, 2)
        out.append((1 - s) * start + s * end + ((1 - s) * r0 + s * r1) * unit[None])
    return out


@pytest.mark.parametrize("seed", range(16))
def test_the_holes_cut_out_are_exactly_those_the_fill_leaves_empty_apart_from_the_rest(seed: int) -> None:
    """Against shapely's distances and containment and a brute-force winding number: every hole :func:`cut_holes`
    names is one at every frame, and every contour it leaves is not one at some frame."""
    from tweenrender.vector.pieces import cut_holes

    rng = np.random.default_rng(seed)
    contours = _ring_with_holes(rng, 5)
    rule = "evenodd" if rng.random() < 0.5 else "nonzero"
    named = set(cut_holes(contours, rule, APART))
    for h in range(len(contours)):
        if h in named:
            assert _hole_everywhere(contours, h, rule), (h, rule)
        else:  # cut_holes looks as far as ``APART`` and half a step (its edges' points ``APART`` apart)
            assert not _hole_everywhere(contours, h, rule, 1.5 * APART + 1e-9), (h, rule)


def test_a_hole_is_cut_only_where_each_frame_s_own_rule_leaves_it_empty() -> None:
    """A square and a square inside it wound the same way: even-odd leaves the inner one empty, nonzero fills it.
    Cut out while the rule is even-odd throughout; not where it switches to nonzero at some frame."""
    from tweenrender.vector.pieces import cut_holes

    outer = np.broadcast_to(np.array([[0.0, 0.0], [100, 0], [100, 100], [0, 100]]), (4, 4, 2))
    inner = np.broadcast_to(np.array([[40.0, 40.0], [60, 40], [60, 60], [40, 60]]), (4, 4, 2))
    assert cut_holes([outer, inner], "evenodd", APART) == (1,)
    assert cut_holes([outer, inner], "nonzero", APART) == ()
    assert cut_holes([outer, inner], ["evenodd", "evenodd", "nonzero", "nonzero"], APART) == ()
    assert cut_holes([outer, inner[:, ::-1]], ["evenodd", "evenodd", "nonzero", "nonzero"], APART) == (1,)


def test_pieces_are_looked_for_only_for_an_animated_svg(tmp_path, monkeypatch) -> None:
    """Counted work: writing a Lottie or dotLottie file measures no distances between contours; an SVG does."""
    from tweenrender.vector import export

    calls = count_calls(monkeypatch, export, "pieces_and_holes")
    scene = tr.load_scene([DATA / "icons" / "mdi" / "weather-night.svg", DATA / "icons" / "bootstrap" / "sun-fill.svg"])
    tr.write(scene, tmp_path / "night.json")
    tr.write(scene, tmp_path / "night.lottie")
    assert calls == []
    tr.write(scene, tmp_path / "night.svg")
    assert calls
