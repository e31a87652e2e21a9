"""A contour that only grows, shrinks and moves is written once, still, under a keyed scale and position: found by
closed form on made-up frames, and in a real export replayed from the file by an independent reader
(tests/vector_curves.py: the group's transform applied to the still path, timings by bisection) and compared with
``tr.outlines`` by shapely at every frame. The players (rlottie, ThorVG, Skottie, lottie-web) draw such groups in
tests/encode/test_vector_players.py (bootstrap emoji-smile → sun-fill, heroicons check-circle → octicons sun-24)."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

import tweenrender as tr
from tweenrender.core.view import Viewport
from tweenrender.pipeline.library import render_job
from tweenrender.plan.job import scene_view, tracks_of
from tweenrender.plan.options import RenderOptions
from tweenrender.vector.scaled_keys import homothety
from tests.helpers import DATA
from tests.vector_curves import distance, drawn, lottie_path_at, lottie_placed


def _star(points: int = 5) -> np.ndarray:
    angles = np.arange(2 * points) * np.pi / points
    radii = np.where(np.arange(2 * points) % 2 == 0, 40.0, 17.0)
    return np.stack([100 + radii * np.cos(angles), 80 + radii * np.sin(angles)], axis=1)  # (10, 2)


def test_a_shape_grown_from_a_moving_point_is_found_with_its_scales() -> None:
    star = _star()
    t = np.linspace(0.0, 1.0, 13)
    scales = np.sqrt(t)  # area linear in t
    points = np.stack([300 - 200 * t, 50 + 10 * t], axis=1)  # where it grows from, moving
    frames = points[:, None] + scales[:, None, None] * (star - star.mean(axis=0))  # (13, 10, 2)
    found = homothety(frames)
    assert found is not None
    r, anchor, centres, got = found
    assert r == 12
    np.testing.assert_allclose(anchor, points[-1], atol=1e-9)  # the largest frame's centre
    np.testing.assert_allclose(got, scales, atol=1e-12)
    np.testing.assert_allclose(centres, points, atol=1e-9)


def _replayed(move: object, count: int) -> np.ndarray:
    """Where a :class:`ContourMove` puts its centre and scale at frames ``0 .. count - 1`` as a player does: held
    before the first keyframe and after the last, between them through each span's CSS cubic-bezier found by
    bisection (tests/vector_players.py): ``(count, 3)``."""
    from tests.vector_players import bezier_timing

    frames = np.asarray(move.frames)  # type: ignore[attr-defined]
    values = np.concatenate([move.centres, move.scales[:, None]], axis=1)  # type: ignore[attr-defined]
    out = np.empty((count, 3))
    for f in range(count):
        k = int(np.clip(np.searchsorted(frames, f, side="right") - 1, 0, len(frames) - 1))
        if k == len(frames) - 1 or f <= frames[0]:
            out[f] = values[k]
            continue
        x = (f - frames[k]) / (frames[k + 1] - frames[k])
        y = bezier_timing(np.array([x]), move.eases[k])[0]  # type: ignore[attr-defined]
        out[f] = values[k] + y * (values[k + 1] - values[k])
    return out


def test_a_shape_growing_with_its_area_linear_in_t_takes_one_span_of_its_own_timing() -> None:
    """Its scale is √t. A timing whose handles sit a third and two thirds of the way in time is a cubic in t, which
    cannot follow √t's upright start within the bound in one span (the keys took four); a CSS cubic-bezier free in
    both handles can (x1 = 0 leaves the first keyframe upright). Replayed by bisection at every frame: each point of
    the path within the bound of the exact frame, in two keyframes."""
    from tweenrender.vector.scaled_keys import scaled_contour

    star = _star()
    t = np.linspace(0.0, 1.0, 25)
    frames = star.mean(axis=0) + np.sqrt(t)[:, None, None] * (star - star.mean(axis=0))  # (25, 10, 2)
    found = scaled_contour(frames, True, 0.05, lambda fitted: 0.25 - fitted, 6)
    assert found is not None
    move = found.move
    assert len(move.frames) == 2, move.frames
    played = _replayed(move, len(t))
    path = found.curve[0, :, 1]  # the still path's vertices, (M, 2)
    for f in range(len(t)):
        at = played[f, :2] + played[f, 2] * (path - move.anchor)
        exact = star.mean(axis=0) + np.sqrt(t[f]) * (path - star.mean(axis=0))
        assert float(np.linalg.norm(at - exact, axis=1).max()) <= 0.25, f


def test_a_turn_a_stretch_or_a_still_shape_is_not_a_homothety() -> None:
    star = _star()
    centred = star - star.mean(axis=0)
    turned = np.stack([star, star.mean(axis=0) + centred @ np.array([[0.0, 1.0], [-1.0, 0.0]])])
    stretched = np.stack([star, star.mean(axis=0) + centred * [1.0, 0.5]])
    nudged = np.stack([star, star + np.where(np.arange(10) == 3, 1e-3, 0.0)[:, None]])
    assert homothety(turned) is None
    assert homothety(stretched) is None
    assert homothety(nudged) is None  # one vertex a thousandth of a pixel off
    assert homothety(np.stack([star, star])) is None  # nothing to place


def _contours(item: dict) -> list[tuple[dict, dict | None]]:
    """The paths of a Lottie group's items, each with the transform of the group placing it alone (or None)."""
    out: list[tuple[dict, dict | None]] = []
    for child in item.get("it", []):
        if child["ty"] == "sh":
            out.append((child, None))
        elif child["ty"] == "gr" and child["nm"].startswith("contour"):
            (path,) = [c for c in child["it"] if c["ty"] == "sh"]
            (place,) = [c for c in child["it"] if c["ty"] == "tr"]
            out.append((path, place))
        elif child["ty"] == "gr":
            out.extend(_contours(child))
    return out


def test_pieces_that_appear_are_still_paths_under_a_keyed_scale_within_the_bound(tmp_path: Path) -> None:
    icons = DATA / "icons"
    scene = tr.load_scene([icons / "bootstrap/emoji-smile.svg", icons / "bootstrap/sun-fill.svg"])
    document = json.loads(tr.write(scene, tmp_path / "clip.json").read_text())
    job = render_job(scene, RenderOptions.create())
    viewport = Viewport(scene_view(scene, tracks_of(scene), job.methods), *job.panel_size)
    placed = [(layer, path, place) for layer in document["layers"] if layer["nm"] != "background"
              for group in layer["shapes"] for path, place in _contours(group)]
    moved = [(layer, path, place) for layer, path, place in placed if place is not None]
    assert len(moved) >= 7  # the rays
    for _, path, place in moved:
        assert path["ks"]["a"] == 0  # one still path
        assert place["s"]["a"] == 1 and len(place["s"]["k"]) < document["op"]
    worst = 0.0
    for frame in range(document["op"]):
        exact = [viewport.to_pixels(c) for c in tr.outlines(scene, frame / document["fr"])]
        for layer, path, place in moved:
            if not layer["ip"] <= frame < layer["op"]:
                continue
            v, i, o, closed = lottie_path_at(path["ks"], frame)
            points = lottie_placed(place, frame, drawn(v, i, o, closed))
            if np.ptp(points, axis=0).max() == 0.0:  # at scale 0: a point, nothing drawn (nor outlined)
                continue
            # the contour it draws: the exact one it is nearest to (tiny at the first frames, but there too)
            worst = max(worst, min(distance(points, c, closed) for c in exact if len(c) >= 2))
    assert worst <= 0.25
