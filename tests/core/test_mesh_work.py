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
