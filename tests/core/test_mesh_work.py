"""Work the compatible mesh does on many contours, counted: bridging a face's boundaries into one must stop at
a stated size, not grow without bound (a grid of small squares becoming a grid of
larger ones once took 98 s and gigabytes in one mesh that then failed)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.core.methods import compatible, mesh_overlay


def _grid(count: int, side: float, pitch: float, columns: int, box: int) -> str:
    squares = " ".join(f"M{(i % columns) * pitch:g} {(i // columns) * pitch:g}h{side:g}v{side:g}h-{side:g}z"
                       for i in range(count))
    return f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 {box} {box}"><path d="{squares}"/></svg>'


def test_a_grid_of_squares_becoming_fewer_larger_ones_meshes_in_bounded_work(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(_grid(32, 2.0, 4.0, 6, 34))  # 24 of them shrink away: held in the mesh by stand-ins, or not
    b.write_text(_grid(8, 6.0, 8.0, 3, 22))
    counted = {"points": 0, "crossing counts": 0}
    new_point, crossing_count = compatible._Triangulation.new_point, mesh_overlay._crossing_count

    def counting_point(self, *args):  # noqa: ANN001, ANN202
        counted["points"] += 1
        return new_point(self, *args)

    def counting_crossings(*args):  # noqa: ANN002, ANN202
        counted["crossing counts"] += 1
        return crossing_count(*args)

    monkeypatch.setattr(compatible._Triangulation, "new_point", counting_point)
    monkeypatch.setattr(mesh_overlay, "_crossing_count", counting_crossings)
    scene = tr.load_scene([a, b])
    drawn = tr.contours(scene, 0.5)
    assert all(np.isfinite(c.points).all() for c in drawn) and len(drawn) >= 8
    # before: 16 800 bridge points in one face of 16 922 corners, 1.3 million crossing counts
    assert counted["points"] <= 2 * compatible.BRIDGE_CAP, counted
    assert counted["crossing counts"] <= 100_000, counted




def test_stand_ins_are_not_searched_for_more_contours_than_a_mesh_holds(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    # 100 small squares becoming 25 larger ones: 75 shrink away, more than a mesh holds (the shipped icons'
    # segments have at most 36 without a partner), so they shrink clear of the mesh without a stand-in search
    # (whose pairwise work took 137 of 230 s for 1 000 squares becoming 250)
    from tweenrender.core.methods import stand_ins
    from tweenrender.core.timing import timeline

    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(_grid(100, 2.0, 4.0, 10, 50))
    b.write_text(_grid(25, 6.0, 8.0, 5, 30))
    searched = []
    search = stand_ins.stand_ins

    def counting(*args, **kwargs):  # noqa: ANN002, ANN003, ANN202
        searched.append(len(args[2]))
        return search(*args, **kwargs)

    monkeypatch.setattr(stand_ins, "stand_ins", counting)
    drawn = tr.contours(tr.load_scene([a, b]), 0.5)
    assert all(np.isfinite(c.points).all() for c in drawn) and len(drawn) >= 25
    assert all(count <= timeline.HOLD_MAX for count in searched), searched


def _ears(points: list[tuple[float, float]], rng: np.random.Generator) -> list[tuple[int, int, int]]:
    """A triangulation of the simple polygon ``points`` (counter-clockwise) by clipping ears picked at random."""
    left, found = list(range(len(points))), []
    while len(left) > 3:
        ears = []
        for k in range(len(left)):
            a, b, c = left[k - 1], left[k], left[(k + 1) % len(left)]
            if mesh_overlay.orient(points[a], points[b], points[c]) > 0 and not any(
                    min(mesh_overlay.orient(points[a], points[b], points[p]),
                        mesh_overlay.orient(points[b], points[c], points[p]),
                        mesh_overlay.orient(points[c], points[a], points[p])) >= 0
                    for p in left if p not in (a, b, c)):
                ears.append(k)
        k = int(rng.choice(ears))
        found.append((left[k - 1], left[k], left[(k + 1) % len(left)]))
        del left[k]
    return found + [tuple(left)]  # type: ignore[list-item]


def _fewer_crossings_afresh(m: int, tris0: list, tris1: list, pos0: list, pos1: list) -> tuple[list, list]:
    """The flips tried as the module's notes state them, every chord on every pass, counted and tested afresh."""
    meshes = (mesh_overlay._Polygon(m, tris0), mesh_overlay._Polygon(m, tris1))
    fat = mesh_overlay.fat
    for _ in range(mesh_overlay._FLIP_ROUNDS):
        changed = False
        for side in (0, 1):
            mesh, other, pos = meshes[side], meshes[1 - side], (pos0, pos1)[side]
            theirs = np.array(sorted(other.chords), dtype=np.intp).reshape(-1, 2)
            for a, b in sorted(mesh.chords - other.chords):
                if (a, b) not in mesh.he:
                    continue
                x, y = mesh.he[(a, b)], mesh.he[(b, a)]
                if (fat(pos[a], pos[y], pos[x]) and fat(pos[y], pos[b], pos[x]) and fat(pos[x], pos[a], pos[y])
                        and fat(pos[b], pos[x], pos[y])
                        and mesh_overlay._crossing_count(x, y, theirs[:, 0], theirs[:, 1])
                        < mesh_overlay._crossing_count(a, b, theirs[:, 0], theirs[:, 1])):
                    mesh.flip(a, b)
                    changed = True
        if not changed:
            break
    return meshes[0].triangles(), meshes[1].triangles()


@pytest.mark.parametrize("seed", range(6))
def test_fewer_crossings_flips_as_trying_every_chord_afresh_in_less_work(
        seed: int, monkeypatch: pytest.MonkeyPatch) -> None:
    # star-shaped polygons (corners alternately far and near: many flips would make a thin or turned triangle)
    rng = np.random.default_rng(seed)
    m = 48
    keys = []
    for _ in range(2):
        angle = np.sort(rng.uniform(0.0, 2.0 * np.pi, m))
        radius = np.where(np.arange(m) % 2 == 0, 1.0, rng.uniform(0.3, 0.8, m))
        keys.append([(float(r * np.cos(a)), float(r * np.sin(a))) for a, r in zip(angle, radius)])
    tris0, tris1 = _ears(keys[0], rng), _ears(keys[1], rng)
    expected = _fewer_crossings_afresh(m, tris0, tris1, keys[0], keys[1])
    counted = {"crossing counts": 0, "fat": 0}
    crossing_count, fat = mesh_overlay._crossing_count, mesh_overlay.fat

    def counting_crossings(*args):  # noqa: ANN002, ANN202
        counted["crossing counts"] += 1
        return crossing_count(*args)

    def counting_fat(*args):  # noqa: ANN002, ANN202
        counted["fat"] += 1
        return fat(*args)

    monkeypatch.setattr(mesh_overlay, "_crossing_count", counting_crossings)
    monkeypatch.setattr(mesh_overlay, "fat", counting_fat)
    assert mesh_overlay.fewer_crossings(m, tris0, tris1, keys[0], keys[1]) == expected
    afresh = dict(counted)
    counted.update({"crossing counts": 0, "fat": 0})
    _fewer_crossings_afresh(m, tris0, tris1, keys[0], keys[1])
    # each chord counted once, each quadrilateral tested once (afresh: on every pass)
    assert afresh["crossing counts"] < counted["crossing counts"] and afresh["fat"] < counted["fat"], (afresh, counted)
