"""``tweenrender correspond``: the JSON contract, optimality against brute force, the picture,
and ``render`` of the thesis's ch. 3 scenes under every method and matching flag."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SCENES, SQUARE, write_scene

FIG3 = ("e-to-f", "twelve-to-six", "eight-to-three", "pentagon-to-triangle", "c-spike", "braces",
        "bird-feet", "bird-tail")


def _two_keys(a: list[list[float]], b: list[list[float]], extra: str = "") -> str:
    return (f"{extra}\n[[shape]]\nname = \"p\"\n[[shape.key]]\ntime = 0\npoints = {a}\n"
            f"[[shape.key]]\ntime = 1\npoints = {b}\n")


def _report(cli, path: Path, *flags: str) -> dict:
    code, out, err = cli("correspond", path, "--json", *flags)
    assert code == 0, err
    return json.loads(out)


def _closed_paths(m: int, n: int):
    """Every closed monotone path of the cyclic m × n grid through a node of row 0, as node lists.

    Written out directly: from (0, s) take steps (0, 1), (1, 0) or (1, 1) on the
    unrolled grid until (m, s + n), the start again; its nodes mod (m, n), the end dropped.
    """
    def walk(i: int, c: int, s: int, nodes: list[tuple[int, int]]):
        if (i, c) == (m, s + n):
            yield nodes
            return
        for di, dc in ((0, 1), (1, 0), (1, 1)):
            if i + di <= m and c + dc <= s + n:
                yield from walk(i + di, c + dc, s, nodes + [(i, c)])

    for s in range(n):
        for nodes in walk(0, s, s, []):
            yield [(i % m, c % n) for i, c in nodes]


def _brute_minimum(a: np.ndarray, b: np.ndarray) -> float:
    return min(sum(math.dist(a[i], b[j]) for i, j in nodes) for nodes in _closed_paths(len(a), len(b)))


def _valid(pairs: list[list[int]], m: int, n: int, backwards: bool = False) -> bool:
    """Closed, each step advancing i and/or j by one (j by -1 walking backwards), once round each."""
    steps = list(zip(pairs, pairs[1:] + pairs[:1]))
    di = [(q[0] - p[0]) % m for p, q in steps]
    dj = [((p[1] - q[1]) if backwards else (q[1] - p[1])) % n for p, q in steps]
    return (all(x in (0, 1) and y in (0, 1) and x + y >= 1 for x, y in zip(di, dj))
            and sum(di) == m and sum(dj) == n
            and {p[0] for p in pairs} == set(range(m)) and {p[1] for p in pairs} == set(range(n)))


def _star(rng: np.random.Generator, count: int, centre: tuple[float, float]) -> np.ndarray:
    """A counter-clockwise star-shaped polygon: sorted angles, random radii."""
    angles = np.sort(rng.uniform(0, 2 * np.pi, count))
    radii = rng.uniform(0.5, 2.0, count)
    return np.column_stack([centre[0] + radii * np.cos(angles), centre[1] + radii * np.sin(angles)]).round(3)


def test_json_contract(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, _two_keys([[0, 0], [2, 0], [2, 2], [0, 2]], [[5, 0], [7, 0], [6, 2]]))
    report = _report(cli, scene)
    (entry,) = report["shapes"]
    assert {"name", "segment", "counts", "balanced", "work", "pairs", "cost", "align", "reversed",
            "matched", "minimal_work"} <= entry.keys()
    assert entry["name"] == "p" and entry["segment"] == 0 and entry["counts"] == [4, 3]
    assert entry["balanced"] == len(entry["pairs"]) and 4 <= entry["balanced"] <= 7
    assert entry["matched"] == "minimal work" and entry["reversed"] is False
    assert (entry["cost"], entry["align"]) == ("distance", "centroid")  # the scene's defaults
    # both are the least work, found by brute force over every closed monotone path of the keys centred
    # on their vertex means (the scene's alignment); the pairs reported cost exactly the work reported
    a = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], float)
    b = np.array([[5, 0], [7, 0], [6, 2]], float)
    a, b = a - a.mean(axis=0), b - b.mean(axis=0)
    least = _brute_minimum(a, b)
    assert entry["work"] == pytest.approx(least, rel=1e-9)
    assert entry["minimal_work"] == pytest.approx(least, rel=1e-9)
    assert entry["work"] == pytest.approx(sum(math.dist(a[i], b[j]) for i, j in entry["pairs"]), rel=1e-9)
    inserted = entry["inserted"]
    assert len(inserted["a"]) == entry["balanced"] - 4 and len(inserted["b"]) == entry["balanced"] - 3


@pytest.mark.parametrize("seed, m, n", [(0, 4, 3), (1, 5, 3), (2, 3, 6), (3, 6, 4), (4, 5, 7)])
def test_distance_as_placed_is_the_true_minimum(cli, tmp_path: Path, seed: int, m: int, n: int) -> None:
    rng = np.random.default_rng(seed)
    a, b = _star(rng, m, (0.0, 0.0)), _star(rng, n, (3.0, 1.0))
    scene = write_scene(tmp_path, _two_keys(a.tolist(), b.tolist()))
    (entry,) = _report(cli, scene, "--cost", "distance", "--align", "none")["shapes"]
    assert (entry["cost"], entry["align"], entry["reversed"]) == ("distance", "none", False)
    assert _valid(entry["pairs"], m, n)
    assert entry["work"] == pytest.approx(_brute_minimum(a, b), rel=1e-9)
    # the work is the sum of the distances of the pairs reported
    assert entry["work"] == pytest.approx(sum(math.dist(a[i], b[j]) for i, j in entry["pairs"]), rel=1e-9)


def test_centroid_alignment_measures_shapes_not_places(cli, tmp_path: Path) -> None:
    # b is a copy of a moved by (10, 4), listed from another vertex, with one extra vertex
    # halfway along an edge: centred, every pair is short; as placed, every pair spans the move.
    a = [[0, 0], [3, 0], [3, 1], [1, 2], [0, 1]]
    moved = [[x + 10, y + 4] for x, y in a[2:] + a[:2]]
    b = moved[:1] + [[(moved[0][0] + moved[1][0]) / 2, (moved[0][1] + moved[1][1]) / 2]] + moved[1:]
    scene = write_scene(tmp_path, _two_keys(a, b))
    (centred,) = _report(cli, scene, "--align", "centroid", "--cost", "distance")["shapes"]
    (placed,) = _report(cli, scene, "--align", "none")["shapes"]
    assert _valid(centred["pairs"], 5, 6) and _valid(placed["pairs"], 5, 6)
    move = math.hypot(10, 4)
    assert placed["work"] > 6 * (move - 3.2)  # no vertex is more than ~3.2 from the others
    # the only offsets left: the extra vertex pulls b's vertex mean by at most 1.6/6 per axis
    assert centred["work"] < 6 * 0.4 + 1.6


def test_sg_cost_gives_a_valid_path(cli, tmp_path: Path) -> None:
    rng = np.random.default_rng(7)
    a, b = _star(rng, 7, (0, 0)), _star(rng, 4, (0, 0))
    scene = write_scene(tmp_path, _two_keys(a.tolist(), b.tolist()))
    (entry,) = _report(cli, scene, "--cost", "sg")["shapes"]
    assert entry["cost"] == "sg" and entry["work"] > 0
    assert _valid(entry["pairs"], 7, 4)


def test_opposite_winding_walks_backwards(cli, tmp_path: Path) -> None:
    a = [[0, 0], [2, 0], [2, 2], [0, 2]]
    b = [[5, 0], [5, 2], [7, 1]]  # clockwise
    (entry,) = _report(cli, write_scene(tmp_path, _two_keys(a, b)))["shapes"]
    assert entry["reversed"] is True
    assert _valid(entry["pairs"], 4, 3, backwards=True)


def test_equal_counts_keep_the_drawn_order(cli, tmp_path: Path) -> None:
    (entry,) = _report(cli, write_scene(tmp_path, SQUARE))["shapes"]
    assert entry["matched"] == "drawn order"
    assert entry["pairs"] == [[0, 0], [1, 1], [2, 2], [3, 3]] and entry["balanced"] == 4
    # Centred, each vertex of the 2×2 square is √2 from its centre, and vertex i of the turned
    # square is vertex i turned by 90°: √2·√2 = 2 apart. The turned square's vertex i-1 is
    # exactly where vertex i of the first one is, so the optimum costs nothing.
    assert entry["work"] == pytest.approx(8.0, abs=1e-9)
    assert entry["minimal_work"] == pytest.approx(0.0, abs=1e-9)
    assert entry["minimal_work"] <= entry["work"]
    assert _valid(entry["minimal_pairs"], 4, 4, backwards=entry["minimal_reversed"])


def test_text_output_and_picture(cli, tmp_path: Path) -> None:
    import imageio.v3 as iio

    target = tmp_path / "pic.png"
    code, out, err = cli("correspond", SCENES / "bird-feet.toml", "-o", target, "--align", "none")
    assert code == 0, err
    first, line, written = out.strip().splitlines()
    assert line.startswith("bird, segment 0: 22 → 20 vertices, balanced to 22, work ")
    assert "(distance, as placed)" in line and "vertices inserted" in line
    assert written == str(target)
    picture = iio.imread(target)
    assert picture.shape[1] == 960 and 200 < picture.shape[0] < 2000
    rgb = picture[..., :3].astype(int)
    inked = np.any(rgb < 200, axis=2).mean()
    assert 0.005 < inked < 0.5  # outlines, lines and text, on a mostly white picture
    # both key colours are there: a bluish outline and an orange one
    assert np.any((rgb[..., 2] > rgb[..., 0] + 80))
    assert np.any((rgb[..., 0] > rgb[..., 2] + 120))


def test_json_writes_a_picture_only_when_asked(cli, tmp_path: Path, monkeypatch) -> None:
    monkeypatch.chdir(tmp_path)
    scene = write_scene(tmp_path, SQUARE)
    code, out, _ = cli("correspond", scene, "--json")
    assert code == 0 and json.loads(out)["shapes"]
    assert not (tmp_path / "output").exists()
    code, _, err = cli("correspond", scene)
    assert code == 0, err
    assert (tmp_path / "output" / "scene-correspond.png").is_file()


def test_bad_scene_leaves_the_picture_untouched(cli, tmp_path: Path) -> None:
    target = tmp_path / "keep.png"
    target.write_bytes(b"an earlier picture")
    bad = write_scene(tmp_path, SQUARE.replace('name = "sq"', 'name = "sq"\ncolour = "#fff"'))
    code, out, err = cli("correspond", bad, "-o", target)
    assert code == 2 and "colour" in err and out == ""
    assert target.read_bytes() == b"an earlier picture"
    code, _, err = cli("correspond", write_scene(tmp_path, SQUARE, "ok.toml"), "-o", tmp_path / "x.jpg")
    assert code == 2 and ".png" in err
    code, _, err = cli("correspond", write_scene(tmp_path, SQUARE, "ok.toml"), "--cost", "energy")
    assert code == 2 and "--cost: expected one of distance, sg, found 'energy'" in err and err.count("\n") == 1


def test_overlapping_keys_are_drawn_apart() -> None:
    from tweenrender.raster.plots.match_picture import placed_apart

    a = np.array([[0.0, 0], [2, 0], [2, 2], [0, 2]])
    moved, shift = placed_apart(a, a + [1.0, 0.5])
    assert shift > 0 and moved[:, 0].min() > a[:, 0].max()
    far = a + [5.0, 0]
    same, none = placed_apart(a, far)
    assert none == 0 and np.array_equal(same, far)


def _blank(frame: np.ndarray) -> bool:
    return bool(np.all(frame[..., :3] == frame[0, 0, :3]))


@pytest.mark.parametrize("stem", FIG3)
def test_fig3_scenes_render_with_every_method(cli, tmp_path: Path, stem: str) -> None:
    import imageio.v3 as iio

    from tweenrender.core.timing.timeline import build_track
    from tweenrender.scenefile import load_scene

    scene = load_scene(SCENES / f"{stem}.toml")
    for method in ("linear", "nonlinear", "rigid", "auto"):
        for shape in scene.shapes:
            polygons = [c for at in build_track(shape, scene.matching).at(np.array([0.0, 0.5, 1.0, 1.5, 2.0]), method)
                            for c in at.contours]
            assert all(np.all(np.isfinite(p)) for p in polygons), (stem, method)
        folder = tmp_path / method
        code, out, err = cli("render", SCENES / f"{stem}.toml", "--method", method, "--format", "png",
                             "--frames", "23:26", "--size", "160x96", "-o", folder, "-q")
        assert code == 0, err
        frames = sorted(folder.glob("frame_*.png"))
        assert len(frames) == 3
        for path in frames:
            picture = iio.imread(path)
            assert picture.shape[:2] == (96, 160) and not _blank(picture), (stem, method, path.name)


def test_render_flags_change_the_blend(cli, tmp_path: Path) -> None:
    import imageio.v3 as iio

    seen = {}
    for align in ("none", "centroid"):
        folder = tmp_path / align
        code, _, err = cli("render", SCENES / "eight-to-three.toml", "--method", "linear", "--format", "png",
                           "--frames", "24:25", "--size", "160x96", "--align", align, "-o", folder, "-q")
        assert code == 0, err
        seen[align] = iio.imread(folder / "frame_0000.png")
    assert np.abs(seen["none"].astype(int) - seen["centroid"].astype(int)).max() > 100
    code, _, err = cli("render", SCENES / "eight-to-three.toml", "--cost", "work")
    assert code == 2 and "--cost: expected one of distance, sg, found 'work'" in err and err.count("\n") == 1


def test_sheet_takes_the_matching_flags(cli, tmp_path: Path) -> None:
    target = tmp_path / "sheet.png"
    code, out, err = cli("sheet", SCENES / "pentagon-to-triangle.toml", "--cost", "sg", "--align", "none",
                         "--count", "1", "-o", target)
    assert code == 0, err
    assert target.is_file()


def test_flat_keys_still_draw(cli, tmp_path: Path) -> None:
    import imageio.v3 as iio

    flat = write_scene(tmp_path, _two_keys([[0, 0], [1, 0], [2, 0], [3, 0]], [[5, 0], [6, 0], [7, 0]]))
    target = tmp_path / "flat.png"
    code, _, err = cli("correspond", flat, "-o", target)
    assert code == 0, err
    assert not _blank(iio.imread(target))
