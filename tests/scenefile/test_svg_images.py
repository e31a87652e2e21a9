"""``<image>``: pictures and drawings drawn at keys as librsvg draws them, carried between keys with their
element, and what cannot be read drawn as nothing or refused in one line."""

from __future__ import annotations

import base64
import io
import shutil
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import tweenrender as tr
from tests.browser import svg_screenshots
from tests.helpers import run_main
from tests.scenefile.test_icons import needs_rsvg
from tests.scenefile.test_key_frames import SIZE, measures, reference

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
HEAD = '<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" viewBox="0 0 40 40">'


def _picture() -> np.ndarray:
    """A 12 × 8 picture: red rising to the right, green downwards, a transparent notch and a half-clear row."""
    pixels = np.zeros((8, 12, 4), np.uint8)
    pixels[..., 0] = np.arange(12) * 21
    pixels[..., 1] = np.arange(8)[:, None] * 32
    pixels[..., 2] = 180
    pixels[..., 3] = 255
    pixels[2:4, 3:6, 3] = 0
    pixels[6, :, 3] = 128
    return pixels


def _png(pixels: np.ndarray, kind: str = "PNG") -> bytes:
    out = io.BytesIO()
    Image.fromarray(pixels if kind == "PNG" else pixels[..., :3]).save(out, kind)
    return out.getvalue()


def _data_url(data: bytes, mime: str = "image/png") -> str:
    return f"data:{mime};base64," + base64.b64encode(data).decode()


def _write(folder: Path, name: str, body: str) -> Path:
    (folder / "pic.png").write_bytes(_png(_picture()))
    (folder / "pic.jpg").write_bytes(_png(np.repeat(np.repeat(_picture(), 4, 0), 4, 1), "JPEG"))
    (folder / "drawing.svg").write_text('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 20 10">'
                                        '<rect width="20" height="10" fill="#3366cc"/>'
                                        '<circle cx="10" cy="5" r="4" fill="#ffcc00"/></svg>')
    svg = folder / f"{name}.svg"
    svg.write_text(HEAD + body + "</svg>")
    return svg


EMBEDDED = _data_url(_png(_picture()))
CASES = {
    "embedded, meet": f'<image x="4" y="6" width="32" height="28" href="{EMBEDDED}"/>',
    "xlink:href, xMinYMax meet": f'<image x="4" y="4" width="20" height="32" preserveAspectRatio="xMinYMax meet" '
                                 f'xlink:href="{EMBEDDED}"/>',
    "xMaxYMid slice": f'<image x="4" y="4" width="20" height="32" preserveAspectRatio="xMaxYMid slice" '
                      f'href="{EMBEDDED}"/>',
    "none, turned, half opaque": f'<image x="6" y="8" width="28" height="20" preserveAspectRatio="none" '
                                 f'transform="rotate(20 20 20)" opacity="0.5" href="{EMBEDDED}"/>',
    "a file beside the drawing, in a group with a clip": '<clipPath id="c"><circle cx="20" cy="20" r="14"/>'
                                                         '</clipPath><g clip-path="url(#c)"><image x="2" y="2" '
                                                         'width="36" height="36" href="pic.png"/></g>',
    "a JPEG file": '<image x="2" y="8" width="36" height="24" href="pic.jpg"/>',
    # as Figma writes a picture fill: a pattern of the box, using a picture kept in <defs>
    "a pattern using a picture, as Figma writes it": '<rect x="4" y="6" width="32" height="24" rx="3" '
                                                     'fill="url(#p0)"/><defs><pattern id="p0" '
                                                     'patternContentUnits="objectBoundingBox" width="1" height="1">'
                                                     '<use xlink:href="#i0" transform="scale(0.0833333 0.125)"/>'
                                                     f'</pattern><image id="i0" width="12" height="8" '
                                                     f'xlink:href="{EMBEDDED}"/></defs>',
}
DRAWING = ('<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 20 10"><rect width="20" height="10" fill="#3366cc"/>'
           '<circle cx="10" cy="5" r="4" fill="#ffcc00"/><path d="M 2 8 L 18 2" stroke="#000" stroke-width="1"/></svg>')
# librsvg 2.54 draws a drawing in an <image> as a picture of its own size scaled up (blurred); Chromium, as
# tweenrender, draws its shapes. (Chromium places it by its own preserveAspectRatio, not the <image>'s, where
# SVG 2 and resvg's suite take the <image>'s: that is left to the suite's tests, which tweenrender passes.)
DRAWINGS = {
    "an SVG drawing, met in a tall viewport": '<image x="4" y="4" width="20" height="30" '
                                              f'href="{_data_url(DRAWING.encode(), "image/svg+xml")}"/>'
                                              '<rect x="26" y="4" width="10" height="10" fill="green"/>',
    "an SVG drawing, stretched and turned": '<image x="4" y="10" width="32" height="20" preserveAspectRatio="none" '
                                            'transform="rotate(-15 20 20)" '
                                            f'href="{_data_url(DRAWING.encode(), "image/svg+xml")}"/>',
    "an SVG drawing of a given size, its own": '<image x="2" y="12" href="{}"/>'.format(_data_url(DRAWING.replace(
        'viewBox=', 'width="30" height="15" viewBox=').encode(), "image/svg+xml")),
}


@needs_rsvg
@pytest.mark.parametrize("name", sorted(CASES))
def test_drawn_as_librsvg_draws_it(name: str, tmp_path: Path) -> None:
    svg = _write(tmp_path, name.replace(" ", "-").replace(",", ""), CASES[name])
    ours = tr.frame(tr.load_scene(svg), 0.0, size=(SIZE, SIZE), background="#ffffff")[..., :3].astype(float)
    iou, error = measures(ours, reference(svg))
    assert iou >= 0.99 and error <= 0.02, (iou, error)


@pytest.mark.skipif(CHROMIUM is None, reason="chromium (Debian package chromium) is not installed; `.ci/run` installs it")
def test_drawings_drawn_as_chromium_draws_them(tmp_path: Path) -> None:
    svgs = [_write(tmp_path, f"drawing{k}", body) for k, body in enumerate(DRAWINGS.values())]
    theirs = svg_screenshots(svgs, [(SIZE, SIZE)] * len(svgs), SIZE, tmp_path)
    for name, svg, picture in zip(DRAWINGS, svgs, theirs):
        ours = tr.frame(tr.load_scene(svg), 0.0, size=(SIZE, SIZE), background="#ffffff")[..., :3].astype(float)
        iou, error = measures(ours, picture)
        assert iou >= 0.99 and error <= 0.02, (name, iou, error)


def test_pixelated_takes_the_nearest_pixel(tmp_path: Path) -> None:
    """A 2 × 2 picture (red, green / blue, clear) over 40 units at 200 px: each quadrant its pixel's colour
    alone, edges included, with ``image-rendering: pixelated``; blended (not the four colours alone) without."""
    pixels = np.array([[[255, 0, 0, 255], [0, 255, 0, 255]], [[0, 0, 255, 255], [0, 0, 0, 0]]], np.uint8)
    drawn = {}
    for rendering in ("pixelated", "auto"):
        svg = tmp_path / f"{rendering}.svg"
        svg.write_text(HEAD + f'<image width="40" height="40" style="image-rendering: {rendering}" '
                              f'href="{_data_url(_png(pixels))}"/></svg>')
        drawn[rendering] = tr.frame(tr.load_scene(svg), 0.0, size=(200, 200), background="#ffffff")[..., :3]
    near = drawn["pixelated"]
    for rows, columns, colour in ((slice(0, 100), slice(0, 100), (255, 0, 0)), (slice(0, 100), slice(100, 200),
                                  (0, 255, 0)), (slice(100, 200), slice(0, 100), (0, 0, 255)),
                                  (slice(100, 200), slice(100, 200), (255, 255, 255))):
        assert (near[rows, columns] == colour).all(), colour
    assert len(np.unique(drawn["auto"].reshape(-1, 3), axis=0)) > 4


def test_a_picture_is_carried_with_its_element_between_keys(tmp_path: Path) -> None:
    """Left half red, right half blue, in a 20 × 10 viewport moving from x = 2 to x = 18 and growing to twice
    its width: half-way it covers x = 10 … 40 (the rectangle's vertices on straight paths), its left quarter
    still red and its right quarter blue."""
    pixels = np.zeros((4, 8, 4), np.uint8)
    pixels[:, :4] = (255, 0, 0, 255)
    pixels[:, 4:] = (0, 0, 255, 255)
    url = _data_url(_png(pixels))
    first = tmp_path / "a.svg"
    first.write_text(HEAD.replace("0 0 40 40", "0 0 60 40") + f'<image id="p" x="2" y="10" width="20" height="10" '
                                                                f'preserveAspectRatio="none" href="{url}"/></svg>')
    second = tmp_path / "b.svg"
    second.write_text(HEAD.replace("0 0 40 40", "0 0 60 40") + f'<image id="p" x="18" y="10" width="40" height="10" '
                                                                 f'preserveAspectRatio="none" href="{url}"/></svg>')
    scene = tr.load_scene([first, second])
    picture = tr.frame(scene, 0.5, method="linear", size=(300, 200), background="#ffffff")[..., :3]
    row = 75  # y = 15 at 5 px a unit
    assert tuple(picture[row, 5 * 14]) == (255, 0, 0) and tuple(picture[row, 5 * 36]) == (0, 0, 255)
    assert tuple(picture[row, 5 * 8]) == (255, 255, 255) and tuple(picture[row, 5 * 42]) == (255, 255, 255)


BROKEN_SVGZ = _data_url(b"\x1f\x8b broken", "image/svg+xml")


def test_what_cannot_be_read_draws_nothing_and_is_said_with_v(tmp_path: Path) -> None:
    svg = tmp_path / "broken.svg"
    svg.write_text(HEAD + '<image width="20" height="20" href="https://example.com/a.png"/>'
                          '<image y="20" width="20" height="20" href="missing.png"/>'
                          '<image x="20" width="20" height="20" href="data:image/png;base64,AAAA"/>'
                          '<image x="20" y="20" width="10" height="10" href="data:image/svg+xml,&lt;svg"/>'
                          f'<image x="20" y="30" width="10" height="10" href="{BROKEN_SVGZ}"/>'
                          '<rect x="30" y="30" width="10" height="10" fill="green"/></svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(40, 40), background="#ffffff")[..., :3]
    assert (picture[:30, :30] == 255).all()
    good = tmp_path / "good.svg"
    good.write_text(HEAD + '<rect width="10" height="10"/></svg>')
    said = run_main("-v", "render", str(svg), str(good), "-o", str(tmp_path / "frames"), "--frames", "0:1")
    assert said.returncode == 0, said.stderr
    lines = [line for line in said.stderr.splitlines() if "<image>" in line]  # a line a drawing
    assert len(lines) == 1 and all(what in lines[0] for what in ("'https://example.com/a.png', which is not "
                                                                  "fetched", "'missing.png', a file that cannot be "
                                                                  "read", "not a PNG", "a drawing that cannot be "
                                                                  "read")), said.stderr
    quiet = run_main("render", str(svg), str(good), "-o", str(tmp_path / "frames2"), "--frames", "0:1")
    assert quiet.returncode == 0 and quiet.stderr == ""


def test_a_picture_too_large_is_refused_in_one_line(tmp_path: Path) -> None:
    """A 1-bit PNG of 8 000 × 6 000 pixels (48 million, a few kilobytes of file) would take 192 MB as RGBA."""
    out = io.BytesIO()
    Image.new("1", (8000, 6000)).save(out, "PNG")
    svg = tmp_path / "huge.svg"
    svg.write_text(HEAD + f'<image width="40" height="40" href="{_data_url(out.getvalue())}"/></svg>')
    done = run_main("render", str(svg), str(svg), "-o", str(tmp_path / "frames"))
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "huge.svg" in done.stderr and "8000 × 6000" in done.stderr and "line 1" in done.stderr
    assert not (tmp_path / "frames").exists()


def test_a_drawing_that_shows_itself_is_drawn_once_inside_itself(tmp_path: Path) -> None:
    """As browsers do: the ``<image>`` inside the drawing it shows draws nothing."""
    svg = tmp_path / "self.svg"
    svg.write_text(HEAD + '<rect width="40" height="40" fill="none" stroke="black" stroke-width="2"/>'
                          '<image x="10" y="10" width="20" height="20" href="self.svg"/></svg>')
    picture = tr.frame(tr.load_scene(svg), 0.0, size=(200, 200), background="#ffffff")[..., :3]
    ink = (picture < 128).any(axis=-1)
    assert ink[100, 52] and ink[100, 148]  # the inner frame inside x = 10 … 30 (the drawing at half size)
    assert not ink[100, 76] and not ink[100, 124]  # no third frame about x = 15 and 25


def test_vector_formats_refuse_a_picture_in_one_line(tmp_path: Path) -> None:
    svg = tmp_path / "pic.svg"
    svg.write_text(HEAD + f'<image id="photo" width="40" height="40" href="{EMBEDDED}"/></svg>')
    done = run_main("render", str(svg), str(svg), "--format", "lottie", "-o", str(tmp_path / "out.json"))
    assert done.returncode == 2 and len(done.stderr.strip().splitlines()) == 1, done.stderr
    assert "'photo'" in done.stderr and "<image>" in done.stderr
    assert not (tmp_path / "out.json").exists()


def test_two_pictures_cross_fade_between_keys(tmp_path: Path) -> None:
    """A red picture at one key and a blue one at the other, in the same place: between the keys each pixel
    is a blend of the two, red ebbing and blue growing with t (before, the nearer key's picture alone: all red,
    then all blue from t = 0.5, a pop)."""
    keys = []
    for name, colour in (("red", (255, 0, 0, 255)), ("blue", (0, 0, 255, 255))):
        pixels = np.zeros((4, 4, 4), np.uint8)
        pixels[:] = colour
        svg = tmp_path / f"{name}.svg"
        svg.write_text(HEAD + f'<image id="p" x="10" y="10" width="20" height="20" href="{_data_url(_png(pixels))}"/>'
                              '</svg>')
        keys.append(svg)
    scene = tr.load_scene(keys)
    middle = [tr.frame(scene, t, method="linear", size=(40, 40), background="#ffffff")[20, 20, :3].astype(int)
              for t in (0.25, 0.5, 0.75)]
    reds, blues = [int(p[0]) for p in middle], [int(p[2]) for p in middle]
    assert reds[0] > reds[1] > reds[2] and blues[0] < blues[1] < blues[2], middle
    assert all(20 < value < 235 for value in reds + blues), middle


def test_a_picture_used_again_is_decoded_once(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Three ``<use>`` copies of one ``<image>``: one decoding, the three shapes sharing its pixels."""
    from tweenrender.scenefile import svg_image

    calls = []
    decode = svg_image._decode
    monkeypatch.setattr(svg_image, "_decode", lambda data, line: calls.append(line) or decode(data, line))
    svg = tmp_path / "copies.svg"
    svg.write_text(HEAD + f'<defs><image id="p" width="10" height="10" href="{EMBEDDED}"/></defs>'
                          '<use href="#p"/><use href="#p" x="15"/><use href="#p" y="15"/></svg>')
    drawing = tr.load_scene(svg)
    pictures = [shape.keys[0].paint.pattern.image for shape in drawing.shapes]
    assert len(calls) == 1 and len(pictures) == 3 and all(p is pictures[0] for p in pictures)
