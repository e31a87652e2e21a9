"""Colour values as CSS Color 3/4 define them (values worked out by hand from the specification's formulas),
and drawn: a fill written each way paints the same pixels."""

from __future__ import annotations

from pathlib import Path

import pytest

import tweenrender as tr
from tweenrender.scenefile.svg_color import parse_color


@pytest.mark.parametrize(("text", "rgba"), [
    ("#0a0", (0, 170, 0, 255)),
    ("#00aa0080", (0, 170, 0, 128)),
    ("green", (0, 128, 0, 255)),
    ("rgb(0.8, 127.5, 14.2)", (1, 128, 14, 255)),   # decimals round (Chrome draws 1, 128, 14)
    ("RGB(0, 128, 0)", (0, 128, 0, 255)),          # function names are case-insensitive
    ("rgba(0, 127, 0, 50%)", (0, 127, 0, 128)),     # a percentage alpha
    ("rgb(0%, 50%, 0%)", (0, 128, 0, 255)),
    ("rgb(300, -5, 0)", (255, 0, 0, 255)),          # clamped
    ("hsl(120, 100%, 25%)", (0, 128, 0, 255)),
    ("hsl(999, 100%, 25%)", (83, 0, 128, 255)),     # hue 999 ≡ 279°: (0.325, 0, 0.5) × 255
    ("hsla(120, 100%, 25%, 0.5)", (0, 128, 0, 128)),
    ("hsl(120, 200%, 25%)", (0, 128, 0, 255)),      # saturation clamped to 100 %
])
def test_colours_read_as_css_defines_them(text: str, rgba: tuple[int, int, int, int]) -> None:
    got = parse_color(text)
    assert got is not None and max(abs(a - b) for a, b in zip(got, rgba)) <= 1, got


@pytest.mark.parametrize("text", ["rgb(1, 2)", "#12345", "nonsense", "rgb(a, b, c)", "hsl(1, 2, 3)",
                                  "rgba(0, 50%, 0, 0.5)"])  # numbers and percentages mixed
def test_what_is_no_colour_is_none(text: str) -> None:
    assert parse_color(text) is None


@pytest.mark.parametrize("fill", ["RGB(0, 128, 0)", "rgb(0.2, 127.8, 0.1)", "hsl(480, 100%, 25%)"])
def test_a_fill_written_any_way_paints_its_colour(tmp_path: Path, fill: str) -> None:
    svg = tmp_path / "c.svg"
    svg.write_text(f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><rect width="10" height="10" '
                   f'fill="{fill}"/></svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(10, 10), background="#ffffff")
    assert tuple(picture[5, 5, :3]) == (0, 128, 0)


def test_current_color_in_a_stop_is_the_gradient_s_colour(tmp_path: Path) -> None:
    svg = tmp_path / "s.svg"
    svg.write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 10 10"><g color="#008000"><defs>'
                   '<linearGradient id="g"><stop offset="0" stop-color="currentColor"/>'
                   '<stop offset="1" stop-color="currentColor" stop-opacity="50%"/></linearGradient></defs></g>'
                   '<rect width="10" height="10" fill="url(#g)"/></svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(10, 10), background="#ffffff")
    assert max(abs(int(v) - w) for v, w in zip(picture[5, 0, :3], (0, 128, 0))) <= 12  # was black
    assert abs(int(picture[5, 9, 1]) - (128 + 255) // 2) <= 12  # towards half opacity on the right
