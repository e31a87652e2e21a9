"""``tweenrender qcurves``: the JSON contract, motion classes, the plot, and the jointed scenes."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SCENES, SQUARE, write_scene

TRIANGLE = """[[shape]]
name = "tri"
[[shape.key]]
time = 0
points = [[0, 0], [3, 0], [1, 2]]
[[shape.key]]
time = 1
points = [[{}]]
"""


def _qcurves(cli, path: Path) -> dict:
    code, out, err = cli("qcurves", path, "--json")
    assert code == 0, err
    return json.loads(out)


def test_json_contract_and_the_turning_square(cli, tmp_path: Path) -> None:
    report = _qcurves(cli, write_scene(tmp_path, SQUARE))
    (shape,) = report["shapes"]
    assert {"name", "segment", "motion", "rotation_deg", "vertices"} <= shape.keys()
    assert shape["name"] == "sq" and shape["segment"] == 0
    assert shape["motion"] == "rotation"
    assert shape["rotation_deg"] == pytest.approx(90.0, abs=1e-6)
    assert shape["auto"]["method"] == "nonlinear"
    assert [v["index"] for v in shape["vertices"]] == [0, 1, 2, 3]
    for v in shape["vertices"]:
        assert {"index", "q0", "q1", "q2", "kind", "through_zero"} <= v.keys()
        # A 2x2 square turning 90 degrees: F·B = 0 and F×B = |F||B| = 4 at both keys,
        # and Q1 = cos(90°)·Q0 = 0 (maths §3).
        np.testing.assert_allclose([v["q0"], v["q1"], v["q2"]], [[0, 4], [0, 0], [0, 4]], atol=1e-12)
        assert v["kind"] == "rotation" and v["through_zero"] is False


@pytest.mark.parametrize(
    "second, motion, degrees",
    [
        ("5, 1], [8, 1], [6, 3", "translation", 0.0),  # moved only
        ("0, 0], [6, 0], [2, 4", "nonrigid", 0.0),  # scaled by 2
        ("0, 0], [3, 0], [2, 2", "nonrigid", None),  # the apex slides
        ("0, 0], [0, 3], [-2, 1", "rotation", 90.0),  # turned a quarter about the origin
    ],
)
def test_motion_classes(cli, tmp_path: Path, second: str, motion: str, degrees: float | None) -> None:
    (shape,) = _qcurves(cli, write_scene(tmp_path, TRIANGLE.format(second)))["shapes"]
    assert shape["motion"] == motion
    if degrees is not None:
        assert shape["rotation_deg"] == pytest.approx(degrees, abs=1e-6)
    q = np.array([[v["q0"], v["q1"], v["q2"]] for v in shape["vertices"]])
    if motion == "translation":
        assert all(v["kind"] == "translation" for v in shape["vertices"])
        np.testing.assert_allclose(q[:, 1], q[:, 0], atol=1e-12)
        np.testing.assert_allclose(q[:, 2], q[:, 0], atol=1e-12)
    # Triangles (thesis §4.3, G.-J. Wang): the Q0s are collinear, as are the Q1s and the Q2s.
    for k in range(3):
        a, b, c = q[:, k]
        assert abs((b - a)[0] * (c - a)[1] - (b - a)[1] * (c - a)[0]) < 1e-9


def test_text_names_the_motion_and_lists_the_vertices(cli, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    code, out, err = cli("qcurves", SCENES / "square.toml")
    assert code == 0, err
    assert "square, segment 0 (0 s to 2 s): rigid rotation of 90.0 degrees → auto uses nonlinear" in out
    header = next(line for line in out.splitlines() if "vertex" in line)
    assert header.split()[:4] == ["vertex", "kind", "through", "zero"]
    assert out.strip().splitlines()[-1] == str(Path("output") / "square-qcurves.png")
    assert (tmp_path / "output" / "square-qcurves.png").is_file()


def _picture(path: Path) -> np.ndarray:
    import imageio.v3 as iio

    return iio.imread(path)


def test_plot_is_drawn_around_the_origin(cli, tmp_path: Path) -> None:
    target = tmp_path / "plots" / "sq.png"
    code, out, err = cli("qcurves", write_scene(tmp_path, SQUARE), "--json", "-o", target)
    assert code == 0, err
    json.loads(out)  # stdout stays pure JSON
    rgba = _picture(target)
    assert rgba.ndim == 3 and rgba.shape[2] in (3, 4) and rgba.shape[0] > 300 and rgba.shape[1] > 300
    rgb = rgba[..., :3].astype(int)
    # The positive x-axis is drawn red: its row is the origin's height, and it starts at the
    # origin (behind the origin's dot and, for this square, the Q1 markers sitting on it).
    red = (rgb[..., 0] > 180) & (rgb[..., 1] < 150) & (rgb[..., 2] < 150)
    row = int(np.argmax(red.sum(axis=1)))
    assert red[row].sum() > 100
    column = int(np.flatnonzero(red[row]).min())
    assert rgb[row, column - 8: column].min() < 200  # something dark or coloured at the origin
    window = rgb[row - 12: row + 13, column - 12: column + 13].reshape(-1, 3)
    assert len({tuple(c) for c in window}) >= 5  # origin dot, axes, red axis, curve, background
    # The square's Q-curves run up the y-axis from Q1 = (0, 0) to Q0 = Q2 = (0, 4): a coloured
    # (neither grey nor red) stroke straight above the origin.
    above = rgb[: row - 20, column - 10: column].reshape(-1, 3)
    coloured = (above.max(axis=1) - above.min(axis=1) > 60) & ~((above[:, 0] > 180) & (above[:, 1] < 150))
    assert coloured.sum() > 50


def test_a_far_off_curve_gets_a_zoomed_inset(cli, tmp_path: Path) -> None:
    # A square that only moves: its four Q-curves are one point, (0, 4); the plot zooms on it.
    scene = write_scene(tmp_path, SQUARE.replace("[[7, 1], [7, 3], [5, 3], [5, 1]]",
                                                 "[[5, 1], [7, 1], [7, 3], [5, 3]]"))
    target = tmp_path / "t.png"
    assert cli("qcurves", scene, "-o", target)[0] == 0
    rgb = _picture(target)[..., :3].astype(int)
    # tab10 blue marks vertex 0; the zoomed copy draws its dot several times as wide.
    blue = (np.abs(rgb - [31, 119, 180]).sum(axis=-1) < 40)
    rows = np.flatnonzero(blue.any(axis=1))
    assert blue.sum() > 40 and rows.size > 0
    labels = np.unique(np.cumsum(np.diff(rows, prepend=rows[0]) > 3))
    assert len(labels) >= 2  # two separate blue places: the point and its zoomed copy


def test_a_failing_run_keeps_the_existing_png(cli, tmp_path: Path, monkeypatch) -> None:
    target = tmp_path / "keep.png"
    target.write_bytes(b"old picture")
    bad = write_scene(tmp_path, SQUARE.replace('name = "sq"', 'name = "sq"\njoints = [[0, 1]]'), "bad.toml")
    code, _, err = cli("qcurves", bad, "-o", target)
    assert code == 2 and "bad.toml" in err
    assert target.read_bytes() == b"old picture"

    import imageio.v3 as iio

    def broken(path, *args, **kwargs):
        Path(path).write_bytes(b"half")
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(iio, "imwrite", broken)
    code, _, err = cli("qcurves", write_scene(tmp_path, SQUARE), "-o", target)
    assert code == 1 and "No space left on device" in err and "keep.png" in err
    assert target.read_bytes() == b"old picture"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml", "keep.png", "scene.toml"]


def test_output_must_be_a_png(cli, tmp_path: Path) -> None:
    code, _, err = cli("qcurves", write_scene(tmp_path, SQUARE), "-o", tmp_path / "q.jpg")
    assert code == 2 and ".png" in err


# -- the jointed scenes (thesis ch. 7) ----------------------------------------------


def _stats(cli, name: str) -> dict:
    code, out, err = cli("stats", SCENES / f"{name}.toml", "--json")
    assert code == 0, err
    return json.loads(out)


@pytest.mark.parametrize("name", ["hinge", "roofbox", "walk"])
def test_jointed_keeps_edges_best_and_auto_chooses_it(cli, name: str) -> None:
    for shape in _stats(cli, name)["shapes"]:
        methods = shape["methods"]
        assert "jointed" in methods
        jointed = methods["jointed"]["edge_error_max"]
        assert jointed < methods["linear"]["edge_error_max"]
        assert jointed < methods["nonlinear"]["edge_error_max"]
        # Thesis §2.3 and ch. 7: a body that turns rigidly gets nonlinear paths, so a shape
        # whose joints cut off a turning body is jointed.
        assert shape["auto"]["method"] == "jointed"


def test_qcurves_reports_each_body_of_a_jointed_shape(cli) -> None:
    (shape,) = _qcurves(cli, SCENES / "hinge.toml")["shapes"]
    assert shape["joints"] == [[2, 4]]
    flap = next(b for b in shape["bodies"] if b["vertices"] == [2, 3, 4])
    assert flap["motion"] == "rotation" and flap["rotation_deg"] == pytest.approx(90.0, abs=1e-6)
    assert flap["auto"] == "nonlinear"
    assert shape["auto"]["method"] == "jointed"


def test_walk_keeps_the_foot_and_the_ankle_only_when_jointed() -> None:
    from tweenrender.core.methods.registry import interpolate
    from tweenrender.core.timing.timeline import build_track
    from tweenrender.scenefile import load_scene

    scene = load_scene(SCENES / "walk.toml")
    foot = [0, 1, 2, 3, 4, 5]  # the ankle's back, heel, sole, toe, instep, the ankle's front
    t = np.linspace(0, 1, 101)
    for segment in build_track(scene.shapes[0], scene.matching).segments:
        keys = np.stack([segment.k0[foot], segment.k1[foot]])
        # The foot is the same rigid shape in both keys (the ankle's width is its closing edge).
        lengths = np.linalg.norm(np.roll(keys, -1, axis=1) - keys, axis=-1)
        np.testing.assert_allclose(lengths[0], lengths[1], atol=2e-3)

        def worst(method: str) -> float:
            frames = interpolate(segment.k0, segment.k1, t, method, segment.joints)[:, foot]
            now = np.linalg.norm(np.roll(frames, -1, axis=1) - frames, axis=-1)
            return float(np.abs(now / lengths[0] - 1).max())

        assert worst("jointed") < 0.01
        assert worst("jointed") < worst("linear") / 2
        assert worst("jointed") < worst("nonlinear") / 2
