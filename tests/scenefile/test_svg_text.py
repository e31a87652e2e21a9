"""``<text>`` drawn as its glyphs: positions, anchors, white space and spans held to facts of the font itself.

The font is Noto Sans (``tests/data/resvg/fonts``), found through ``TWEENRENDER_FONT_PATH``. Expected places
come from skia's own metrics of the glyphs (advances, outline bounds), read here without the layout code,
or from the SVG rules stated as equalities between drawings.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.helpers import DATA, run_module
from tweenrender.scenefile.svg import SvgError, read_drawing

FONTS = DATA / "resvg" / "fonts"
SIZE = 100.0


@pytest.fixture(autouse=True)
def _fonts(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("TWEENRENDER_FONT_PATH", str(FONTS))


def _metrics(char: str) -> tuple[float, float, float]:
    """(advance, left of the ink, right of the ink) of ``char`` at :data:`SIZE`, from skia alone."""
    import skia

    face = skia.Typeface.MakeFromFile(str(FONTS / "NotoSans-Regular.ttf"))
    font = skia.Font(face, SIZE)
    font.setHinting(skia.FontHinting.kNone)  # the font's own advances, not rounded to pixels
    font.setLinearMetrics(True)
    font.setSubpixel(True)
    glyph = font.textToGlyphs(char)[0]
    bounds = font.getPath(glyph).getBounds()
    return font.getWidths([glyph])[0], bounds.left(), bounds.right()


def _drawn(tmp_path: Path, body: str) -> dict[str, np.ndarray]:
    """Each element's points (x right, as in the file), by id, of a 1000 × 200 drawing of ``body``."""
    path = tmp_path / "t.svg"
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
                    f'viewBox="0 0 1000 200" font-family="Noto Sans" font-size="{SIZE}">{body}</svg>',
                    encoding="utf-8")
    drawing = read_drawing(path)
    return {e.id or f"{e.tag}@{e.line}": np.concatenate([c.points for c in e.contours]) for e in drawing.elements}


def test_a_glyph_sits_at_its_x_and_on_its_baseline(tmp_path: Path) -> None:
    _, left, right = _metrics("H")
    points = _drawn(tmp_path, '<text id="t" x="100" y="150">H</text>')["t"]
    assert points[:, 0].min() == pytest.approx(100 + left, abs=0.05)
    assert points[:, 0].max() == pytest.approx(100 + right, abs=0.05)
    assert -points[:, 1].min() == pytest.approx(150, abs=0.05)  # the baseline (world y is up)


@pytest.mark.parametrize(("anchor", "shift"), [("start", 0.0), ("middle", -0.5), ("end", -1.0)])
def test_the_anchor_moves_the_chunk_by_its_advance(tmp_path: Path, anchor: str, shift: float) -> None:
    advance, left, _ = _metrics("H")
    points = _drawn(tmp_path, f'<text id="t" x="500" y="150" text-anchor="{anchor}">HH</text>')["t"]
    assert points[:, 0].min() == pytest.approx(500 + left + shift * 2 * advance, abs=0.05)


def test_a_list_of_x_places_each_character(tmp_path: Path) -> None:
    _, left, right = _metrics("H")
    points = _drawn(tmp_path, '<text id="t" x="100 400 700" y="150">HHH</text>')["t"]
    for x in (100, 400, 700):
        inside = points[(points[:, 0] > x - 20) & (points[:, 0] < x + 150)]
        assert inside[:, 0].min() == pytest.approx(x + left, abs=0.05)
        assert inside[:, 0].max() == pytest.approx(x + right, abs=0.05)


def test_kerning_pulls_a_pair_closer_than_the_advances_alone(tmp_path: Path) -> None:
    advance, _, _ = _metrics("A")
    _, v_left, _ = _metrics("V")
    points = _drawn(tmp_path, '<text id="t" x="0" y="150">AV</text>')["t"]
    unkerned = advance + v_left  # where V's ink would start without the font's kerning
    right_half = points[points[:, 0] > advance * 0.8]
    assert right_half[:, 0].min() < unkerned - 0.02 * SIZE


def test_white_space_collapses_and_preserve_keeps_it(tmp_path: Path) -> None:
    drawn = _drawn(tmp_path, '<text id="a" x="0" y="100">A B</text>'
                             '<text id="b" x="0" y="100">  A \n\t   B  </text>'
                             '<text id="c" x="0" y="100" xml:space="preserve">A   B</text>')
    np.testing.assert_allclose(drawn["a"], drawn["b"])
    space, _, _ = _metrics(" ")
    assert drawn["c"][:, 0].max() == pytest.approx(drawn["a"][:, 0].max() + 2 * space, abs=0.05)


def test_a_hidden_span_keeps_its_room_and_an_undisplayed_one_does_not(tmp_path: Path) -> None:
    w_advance, _, _ = _metrics("W")
    drawn = _drawn(tmp_path, '<text id="plain" x="0" y="100">AB</text>'
                             '<text id="gone" x="0" y="100">A<tspan display="none">WW</tspan>B</text>'
                             '<text id="hidden" x="0" y="100">A<tspan visibility="hidden">WW</tspan>B</text>')
    np.testing.assert_allclose(drawn["gone"], drawn["plain"])
    assert drawn["hidden"][:, 0].max() == pytest.approx(drawn["plain"][:, 0].max() + 2 * w_advance, abs=0.5)


def test_a_span_takes_its_own_paint_and_a_tref_its_target_s_characters(tmp_path: Path) -> None:
    path = tmp_path / "t.svg"
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" '
                    'viewBox="0 0 1000 200" font-family="Noto Sans" font-size="100"><defs><text id="src">HI</text>'
                    '</defs><text x="0" y="100" fill="#00ff00">A<tspan id="s" fill="#0000ff">B</tspan>'
                    '<tref id="r" xlink:href="#src" fill="#ff0000"/></text></svg>', encoding="utf-8")
    elements = {e.id: e for e in read_drawing(path).elements}
    assert elements["s"].paint.fill[:3] == (0, 0, 255) and elements["r"].paint.fill[:3] == (255, 0, 0)
    _, h_left, _ = _metrics("H")
    a, _, _ = _metrics("A")
    b, _, _ = _metrics("B")
    tref = np.concatenate([c.points for c in elements["r"].contours])
    assert tref[:, 0].min() == pytest.approx(a + b + h_left, abs=1.0)  # after "AB" (kerning aside)


def test_the_font_shorthand_and_a_postscript_name_name_the_same_face(tmp_path: Path) -> None:
    drawn = _drawn(tmp_path, '<text id="longhands" x="0" y="100" font-weight="bold" font-size="50">Ab</text>'
                             '<text id="shorthand" x="0" y="100" style="font: bold 50px/2 \'Noto Sans\', serif">Ab</text>'
                             '<text id="postscript" x="0" y="100" font-family="NotoSans-Bold" font-size="50">Ab</text>'
                             '<text id="regular" x="0" y="100" font-size="50">Ab</text>')
    np.testing.assert_allclose(drawn["shorthand"], drawn["longhands"])
    np.testing.assert_allclose(drawn["postscript"], drawn["longhands"])
    assert drawn["regular"].shape != drawn["longhands"].shape or not np.allclose(drawn["regular"], drawn["longhands"])


def test_an_unknown_family_still_draws(tmp_path: Path) -> None:
    drawn = _drawn(tmp_path, '<text id="t" x="0" y="100" font-family="No Such Family, fantasy">Hi</text>')
    assert len(drawn["t"]) > 10


@pytest.mark.parametrize(("body", "said"), [
    ('<text x="0" y="100"><textPath href="#p">along</textPath></text>', "expected text without <textPath>"),
    ('<text x="0" y="100">' + "x" * 100_001 + "</text>", "at most 100000 characters"),
])
def test_what_is_not_drawn_is_refused_in_one_line(tmp_path: Path, body: str, said: str) -> None:
    path = tmp_path / "t.svg"
    path.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10">{body}</svg>', encoding="utf-8")
    with pytest.raises(SvgError, match=said):
        read_drawing(path)
    done = run_module("render", path, path, "-o", tmp_path / "out.mp4")
    assert done.returncode == 2 and said.split()[0] in done.stderr and len(done.stderr.strip().splitlines()) == 1
    assert str(path.name) in done.stderr and "line 1" in done.stderr
    assert not (tmp_path / "out.mp4").exists()


def test_text_from_the_system_fonts_leaves_stderr_clean(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("TWEENRENDER_FONT_PATH")
    path = tmp_path / "t.svg"
    path.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 100 40">'
                    '<text x="5" y="30" font-family="sans-serif" font-size="20">Words</text></svg>', encoding="utf-8")
    done = run_module("render", path, path, "-o", tmp_path / "frames", "--frames", "0:1")
    assert done.returncode == 0 and done.stderr == "", done.stderr
    assert (tmp_path / "frames" / "frame_0000.png").exists()
