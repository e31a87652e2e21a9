"""Storyboard sheets (pictures, golden image) and demo reels (decoded: size, fps, frame count)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import SCENES, SQUARE, assert_close_to_golden, decode, write_scene


def _read(path: Path) -> np.ndarray:
    import imageio.v3 as iio

    return iio.imread(path)


def test_sheet_of_the_square_matches_golden(cli, tmp_path: Path, update_golden: bool) -> None:
    target = tmp_path / "sheet.png"
    code, out, err = cli("sheet", SCENES / "square.toml", "-o", target, "--size", "640x520")
    assert code == 0, err
    assert out.strip() == str(target)
    picture = _read(target)
    assert picture.shape == (520, 640, 3)  # an opaque sheet is written as RGB
    assert_close_to_golden(picture, "square-sheet.png", update_golden)


def test_sheet_shows_linear_shrinking_and_nonlinear_keeping_size(cli, tmp_path: Path) -> None:
    """With one inbetween (t = 0.5), the mid square is √2 tall as a diamond in the nonlinear row, 1 in the linear."""
    from tweenrender.raster.plots.storyboard import SheetLayout

    target = tmp_path / "mid.png"
    assert cli("sheet", SCENES / "square.toml", "-o", target, "--count", "1", "--size", "1000x800")[0] == 0
    picture = _read(target)[..., :3].astype(int)
    layout = SheetLayout(1000, 800, 2)
    # the scene's view is [-1.5, -1.5, 8.5, 4.5]: the keys span world x 0..2 and 5..7, the mid frame lies
    # between (linear: x 2.5..4.5, nonlinear: a diamond 2.09..4.91); look only at columns of world x 2.2..4.8
    extents = []
    for row in range(2):
        left, top, width, height = layout.drawing(row)
        scale = min(width / 10, height / 6)
        x0 = left + (width - 10 * scale) / 2
        columns = slice(int(x0 + 3.7 * scale), int(x0 + 6.3 * scale))
        area = picture[int(top):int(top + height), columns]
        inked = np.flatnonzero((np.abs(area - 255).max(axis=-1) > 40).any(axis=1))
        extents.append((inked.max() - inked.min() + 1) / scale)
    nonlinear, linear = extents  # the scene's own method (nonlinear) is the first row
    # linear: the mid square's corners at (3.5, 0.5) and (3.5, 2.5): 2 tall; nonlinear 2√2 tall (±1 px of stroke)
    assert linear == pytest.approx(2.0, abs=0.1)
    assert nonlinear == pytest.approx(2 * np.sqrt(2), abs=0.1)


def test_sheet_default_output_rows_and_errors(cli, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    scene = write_scene(tmp_path, SQUARE, "box.toml")
    monkeypatch.chdir(tmp_path)
    code, out, err = cli("sheet", scene)
    assert code == 0, err
    written = Path(out.strip())
    assert written == Path("output/box-sheet.png") and written.exists()
    assert sorted(p.name for p in written.parent.iterdir()) == ["box-sheet.png"]  # no temporary left
    two = _read(written)
    assert cli("sheet", scene, "--methods", "linear,nonlinear,rigid", "-o", "three.png")[0] == 0
    three = _read(Path("three.png"))
    assert two.shape[1] == three.shape[1] == 1280 and three.shape[0] > two.shape[0] * 1.3
    assert cli("sheet", scene, "-o", "sheet.jpg")[0] == 2
    assert cli("sheet", scene, "--methods", "linaer")[0] == 2
    assert cli("sheet", scene, "--count", "-3")[0] == 2


def test_reel_has_every_card_and_comparison_frame(cli, tmp_path: Path) -> None:
    short = write_scene(tmp_path, SQUARE.replace("time = 2\n", "time = 1\n"), "short.toml")
    long = write_scene(tmp_path, 'title = "Long one"\ncompare = ["linear", "nonlinear", "rigid"]\n' + SQUARE,
                       "long.toml")
    target = tmp_path / "reel.mp4"
    code, out, err = cli("reel", short, long, "-o", target, "--size", "320x180", "--fps", "12", "-q")
    assert code == 0, err
    assert out.strip() == str(target)
    meta, frames = decode(target)
    assert meta["size"] == (320, 180) and meta["fps"] == pytest.approx(12.0)
    card = round(1.5 * 12)  # a title card of 1.5 s per scene
    assert len(frames) == card + (1 * 12 + 1) + card + (2 * 12 + 1)
    # cards are dark all over; a comparison is light panels under a dark title band
    first_card, first_clip = frames[0], frames[card]
    assert first_card.mean() < 60
    assert first_clip[:5].mean() < 60 and first_clip[90].mean() > 150
    second_clip = frames[2 * card + 13 + 5]
    assert second_clip.mean() > first_card.mean() + 50


def test_reel_grid_and_letterbox_keep_the_aspect() -> None:
    from tweenrender.reports.demo_reel import GAP, grid_cells, panel_fit

    # three 16:9 panels in a 1280x669 box: two rows (two over one) show them larger than one row of three
    (width, height), columns = panel_fit((1280, 720), 3, (1280, 669))
    assert columns == 2
    assert abs(width / height - 16 / 9) < 0.01 and 2 * height + GAP <= 669 and 2 * width + GAP <= 1280
    assert width > 1280 / 3
    cells = grid_cells((width, height), 3, 2, (1280, 669), 51)
    assert cells[0][1] == cells[1][1] < cells[2][1]  # two over one
    assert cells[2][0] == (1280 - width) // 2  # the lone panel is centred
    # two panels stay side by side, at exactly half the width
    assert panel_fit((1280, 720), 2, (1280, 669)) == ((638, 358), 2)


def test_reel_refuses_bad_outputs(cli, tmp_path: Path) -> None:
    scene = write_scene(tmp_path, SQUARE)
    assert cli("reel", scene, "-o", tmp_path / "r.avi", "-q")[0] == 2
    assert cli("reel", scene, "-o", tmp_path / "r.mp4", "--size", "321x181", "-q")[0] == 2
    assert cli("reel", tmp_path / "missing.toml", "-o", tmp_path / "r.mp4", "-q")[0] == 2
    assert not (tmp_path / "r.mp4").exists()
