"""Lottie files read as scenes: closed-form in-betweens of a hand-written file, real files (rlottie's
examples) drawn by ``--method linear`` against rlottie and ThorVG, export → import → export, and the
one-line refusals of what the reader does not draw."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.api import frame_count
from tests.helpers import run_main
from tests.vector_players import IOU, COLOUR, measures, over, rlottie_frames, thorvg_frames
from tweenrender.errors import SceneError

DATA = Path(__file__).resolve().parent.parent / "data" / "lottie"
MORPH = DATA / "morph.json"
SQUARE = np.array([[50, 50], [150, 50], [150, 150], [50, 150]], float)
DIAMOND = np.array([[100, 30], [170, 100], [100, 170], [30, 100]], float)
WHITE = (255, 255, 255)
DARK = (24, 40, 72)  # a file drawing white strokes is compared over a dark blue


def _morph() -> dict:
    return json.loads(MORPH.read_text())


def _write(folder: Path, document: dict, name: str = "anim.json") -> Path:
    target = folder / name
    target.write_text(json.dumps(document))
    return target


def _smoothstep(u: np.ndarray) -> np.ndarray:
    return u * u * (3 - 2 * u)  # cubic-bezier(1/3, 0, 2/3, 1) exactly: x(s) = s


def test_keyframes_are_keys_with_their_times_and_easing() -> None:
    scene = tr.load_scene(MORPH)
    assert (scene.size, scene.fps, scene.view) == ((200, 200), 10.0, (0.0, 0.0, 200.0, 200.0))
    assert frame_count(scene) == 21  # frames 0..20: op = 21 is not drawn
    (shape,) = scene.shapes
    assert [key.time for key in shape.keys] == [0.0, 2.0]
    assert shape.keys[0].easing.handles == pytest.approx((1 / 3, 0, 2 / 3, 1), abs=1e-15)
    assert shape.keys[0].paint.fill == (204, 26, 26, 255)
    assert shape.equal_counts == "drawn"


@pytest.mark.parametrize("frame", range(21))
def test_linear_replays_the_closed_form(frame: int) -> None:
    """Vertex i at frame f: square_i + (diamond_i − square_i)·smoothstep(f / 20), y flipped (y up)."""
    scene = tr.load_scene(MORPH)
    (points,) = tr.outlines(scene, frame / 10, method="linear")
    expected = SQUARE + (DIAMOND - SQUARE) * _smoothstep(np.array(frame / 20))
    expected[:, 1] = 200 - expected[:, 1]
    np.testing.assert_allclose(points, expected, atol=1e-9)


def _coverage(picture: np.ndarray) -> np.ndarray:
    """How much of each pixel the red fill (204, 26, 26) covers, from the green channel over white."""
    return (255.0 - picture[..., 1].astype(float)) / (255.0 - 26.0)


@pytest.mark.parametrize("player", ["rlottie", "thorvg"])
def test_edges_within_a_quarter_pixel_of_the_players(player: str) -> None:
    """The area between our edge and the player's (Σ|coverage difference|) over the outline's length is
    the mean distance between the two edges: at most 0.25 px at every frame."""
    scene = tr.load_scene(MORPH)
    frames = list(range(21))
    draw = rlottie_frames if player == "rlottie" else thorvg_frames
    theirs = draw(MORPH, frames, scene.size)
    for frame, picture in zip(frames, theirs):
        ours = over(tr.frame(scene, frame / 10, method="linear", background="none"), WHITE)
        expected = SQUARE + (DIAMOND - SQUARE) * _smoothstep(np.array(frame / 20))
        perimeter = np.linalg.norm(np.roll(expected, -1, axis=0) - expected, axis=1).sum()
        apart = np.abs(_coverage(ours) - _coverage(over(picture, WHITE))).sum() / perimeter
        assert apart <= 0.25, f"{player}, frame {frame}: edges {apart:.3f} px apart"


@pytest.mark.parametrize("name, backdrop", [("emoji_wink.json", WHITE), ("gradient_sleepy_loader.json", WHITE),
                                            ("StickAndBall.json", DARK), ("ondas.json", WHITE)])
def test_real_files_drawn_as_the_players_draw_them(name: str, backdrop: tuple[int, int, int]) -> None:
    path = DATA / name
    scene = tr.load_scene(path)
    count = frame_count(scene)
    frames = sorted(set(np.linspace(0, count - 1, 12).round().astype(int).tolist()))
    for player, pictures in (("rlottie", rlottie_frames(path, frames, scene.size)),
                             ("ThorVG", thorvg_frames(path, frames[::3], scene.size))):
        for frame, picture in zip(frames if player == "rlottie" else frames[::3], pictures):
            ours = over(tr.frame(scene, frame / scene.fps, method="linear", background="none"), backdrop)
            iou, error = measures(ours, over(picture, backdrop), backdrop)
            assert iou >= IOU and error <= COLOUR, f"{name}, {player}, frame {frame}: IoU {iou:.4f}, colour {error:.4f}"


def test_a_real_files_path_keyframes_are_its_keys() -> None:
    """ondas.json moves only its paths: each shape's keys are the keyframes of one of the file's keyframed paths,
    at their frames, with their handles (read from the file here)."""
    document = json.loads((DATA / "ondas.json").read_text())
    found = []

    def walk(value: object) -> None:
        if isinstance(value, dict):
            if value.get("ty") == "sh" and value["ks"].get("a") == 1:
                keys = value["ks"]["k"]
                found.append(([k["t"] / document["fr"] for k in keys],
                              [tuple(np.ravel([k["o"]["x"], k["o"]["y"], k["i"]["x"], k["i"]["y"]]).tolist())
                               for k in keys[:-1]]))
            for item in value.values():
                walk(item)
        elif isinstance(value, list):
            for item in value:
                walk(item)

    walk(document["layers"])
    scene = tr.load_scene(DATA / "ondas.json")
    assert len(scene.shapes) == len(found) == 4
    for shape in scene.shapes:
        times = [k.time for k in shape.keys]
        handles = np.array([k.easing.handles for k in shape.keys[:-1]])
        assert any(len(t) == len(times) and np.allclose(times, t, rtol=0, atol=1e-12)
                   and np.allclose(handles, h, rtol=0, atol=1e-15) for t, h in found)


def test_export_import_export_is_stable(tmp_path: Path) -> None:
    scene = tr.load_scene(MORPH)
    first = tr.write(scene, tmp_path / "a.json", method="linear")
    again = tr.load_scene(first)
    second = tr.write(again, tmp_path / "b.json", method="linear")
    a, b = json.loads(first.read_text()), json.loads(second.read_text())
    a.pop("nm"), b.pop("nm")
    assert a == b
    last = tr.load_scene(second)
    assert [s.name for s in last.shapes] == [s.name for s in again.shapes]
    for one, other in zip(again.shapes, last.shapes):
        assert [k.time for k in one.keys] == [k.time for k in other.keys]
        assert [k.ease for k in one.keys] == [k.ease for k in other.keys]
        for x, y in zip(one.keys, other.keys):
            np.testing.assert_array_equal(x.points, y.points)
    # and the exported file still plays the closed form
    for frame in range(21):
        (points,) = tr.outlines(last, frame / 10, method="linear")
        expected = SQUARE + (DIAMOND - SQUARE) * _smoothstep(np.array(frame / 20))
        expected[:, 1] = 200 - expected[:, 1]
        np.testing.assert_allclose(points, expected, atol=2e-3)  # the writer rounds to a thousandth


def _keyframes(document: dict) -> list[dict]:
    return document["layers"][0]["shapes"][0]["it"][0]["ks"]["k"]


def test_hold_keyframe_and_a_span_cut_by_the_end(tmp_path: Path) -> None:
    """A hold keyframe stays until the next; a span running past the last frame is cut there, keeping its
    timing: the last frame shows the in-between at its share of the whole span."""
    document = _morph()
    keys = _keyframes(document)
    keys[1]["t"] = 40  # the span now runs from frame 0 to 40; the clip ends at frame 20
    scene = tr.load_scene(_write(tmp_path, document))
    for frame in (0, 5, 13, 20):
        (points,) = tr.outlines(scene, frame / 10, method="linear")
        expected = SQUARE + (DIAMOND - SQUARE) * _smoothstep(np.array(frame / 40))
        expected[:, 1] = 200 - expected[:, 1]
        np.testing.assert_allclose(points, expected, atol=1e-9)
    keys[0]["h"] = 1
    keys[1]["t"] = 10
    scene = tr.load_scene(_write(tmp_path, document))
    for frame, shape in ((0, SQUARE), (9, SQUARE), (10, DIAMOND), (20, DIAMOND)):
        (points,) = tr.outlines(scene, frame / 10, method="linear")
        np.testing.assert_allclose(points, np.c_[shape[:, 0], 200 - shape[:, 1]], atol=1e-9)


def test_keyframed_transform_is_sampled_at_every_frame(tmp_path: Path) -> None:
    """A layer moving 100 px right over frames 0..20 (linear): each frame's outline is the path moved by 5 px a
    frame."""
    document = _morph()
    layer = document["layers"][0]
    layer["shapes"][0]["it"][0]["ks"] = {"a": 0, "k": _keyframes(document)[0]["s"][0]}
    layer["ks"]["p"] = {"a": 1, "k": [{"t": 0, "s": [0, 0, 0], "o": {"x": [0], "y": [0]}, "i": {"x": [1], "y": [1]}},
                                      {"t": 20, "s": [100, 0, 0]}]}
    scene = tr.load_scene(_write(tmp_path, document))
    assert len(scene.shapes[0].keys) == 21
    for frame in (0, 7, 20):
        (points,) = tr.outlines(scene, frame / 10, method="linear")
        np.testing.assert_allclose(points, np.c_[SQUARE[:, 0] + 5 * frame, 200 - SQUARE[:, 1]], atol=1e-9)


def _refusal(document: dict, folder: Path) -> tuple[int, str, str]:
    path = _write(folder, document)
    done = run_main("render", path, "-o", folder / "out.mp4", "-q")
    return done.returncode, done.stdout, done.stderr


def _text_layer(document: dict) -> dict:
    document["layers"].insert(0, {"ddd": 0, "ind": 7, "ty": 5, "nm": "Title", "ip": 0, "op": 21, "st": 0, "ks": {},
                                  "t": {"d": {"k": []}}})
    return document


def _expression(document: dict) -> dict:
    document["layers"][0]["ks"]["r"] = {"a": 0, "k": 0, "x": "time * 36"}
    return document


def _image_layer(document: dict) -> dict:
    document["layers"].append({"ddd": 0, "ind": 9, "ty": 2, "nm": "Photo", "refId": "image_0", "ip": 0, "op": 21,
                               "st": 0, "ks": {}})
    return document


@pytest.mark.parametrize("change, place, what", [
    (_text_layer, "layer 7 'Title' (layers[0])", "a text layer"),
    (_expression, "layer 1 'square' (layers[0])", "an expression"),
    (_image_layer, "layer 9 'Photo' (layers[1])", "an image layer"),
])
def test_what_is_not_read_is_one_line_naming_the_layer(tmp_path: Path, change, place: str, what: str) -> None:
    code, _, err = _refusal(change(_morph()), tmp_path)
    assert code == 2
    assert err.strip() == f"tweenrender: error: {tmp_path / 'anim.json'}: {place}: cannot read {what}", err
    assert "Traceback" not in err and "Warning" not in err
    assert not (tmp_path / "out.mp4").exists()


def test_library_refusal_is_a_scene_error(tmp_path: Path) -> None:
    with pytest.raises(SceneError, match=r"layer 7 'Title' \(layers\[0\]\): cannot read a text layer"):
        tr.load_scene(_write(tmp_path, _text_layer(_morph())))


def test_scene_json_is_still_a_scene(tmp_path: Path) -> None:
    """A scene file in JSON (no v, fr, ip, op, layers at its top) is read as before."""
    path = tmp_path / "scene.json"
    path.write_text(json.dumps({"shape": [{"name": "a", "key": [{"time": 0, "points": [[0, 0], [1, 0], [0, 1]]}]}]}))
    assert tr.load_scene(path).shapes[0].name == "a"


def test_precomposition_shifts_its_keys_and_the_end_cuts_them(tmp_path: Path) -> None:
    """The morph in a precomposition starting at frame 5: its keyframes at 0 and 20 fall on root frames 5 and
    25; the clip ends at 20, so the last span is cut there, keeping its timing."""
    document = _morph()
    layer = document["layers"][0]
    layer["ip"] = -100  # shown from before the precomposition starts (its frames are the precomposition's)
    document["assets"] = [{"id": "inner", "layers": [layer]}]
    document["layers"] = [{"ddd": 0, "ind": 1, "ty": 0, "nm": "comp", "refId": "inner", "sr": 1, "st": 5, "ip": 0,
                           "op": 21, "w": 200, "h": 200, "bm": 0, "ks": {}}]
    scene = tr.load_scene(_write(tmp_path, document))
    (shape,) = scene.shapes
    assert [key.time for key in shape.keys] == [0.5, 2.0]
    for frame in (0, 4, 5, 9, 17, 20):
        (points,) = tr.outlines(scene, frame / 10, method="linear")
        expected = SQUARE + (DIAMOND - SQUARE) * _smoothstep(np.clip(np.array((frame - 5) / 20), 0, 1))
        expected[:, 1] = 200 - expected[:, 1]
        np.testing.assert_allclose(points, expected, atol=1e-9)


def test_a_mask_clips_as_the_players_clip(tmp_path: Path) -> None:
    """A mask over the left half of the canvas: drawn as rlottie draws it."""
    document = _morph()
    box = {"c": True, "v": [[0, 0], [100, 0], [100, 200], [0, 200]], "i": [[0, 0]] * 4, "o": [[0, 0]] * 4}
    document["layers"][0].update(hasMask=True, masksProperties=[{"mode": "a", "inv": False, "o": {"a": 0, "k": 100},
                                                                 "x": {"a": 0, "k": 0}, "pt": {"a": 0, "k": box}}])
    path = _write(tmp_path, document)
    scene = tr.load_scene(path)
    frames = [0, 10, 20]
    for frame, picture in zip(frames, rlottie_frames(path, frames, scene.size)):
        ours = over(tr.frame(scene, frame / 10, method="linear", background="none"), WHITE)
        assert (ours[:, 101:] == 255).all() and (ours[:, :99] != 255).any()  # nothing right of the mask
        iou, error = measures(ours, over(picture, WHITE), WHITE)
        assert iou >= 0.99 and error <= COLOUR, f"frame {frame}: IoU {iou:.4f}"


def _shape_items(document: dict) -> list:
    return document["layers"][0]["shapes"][0]["it"]


@pytest.mark.parametrize("change, message", [
    (lambda d: _keyframes(d)[0]["s"][0]["v"].__setitem__(0, ["x", 1]),
     "layer 1 'square' (layers[0]): expected path points as numbers"),
    (lambda d: _keyframes(d)[0]["s"][0]["v"].__setitem__(0, [1e300, 1]),
     "layer 1 'square' (layers[0]): expected path points as finite numbers within ±1e9"),
    (lambda d: d["layers"][0].update(parent=1),
     "layer 1 'square' (layers[0]): expected parents without a loop"),
    (lambda d: _shape_items(d).insert(1, {"ty": "tm", "nm": "Trim Paths 1"}),
     "layer 1 'square' (layers[0]): cannot read trim paths ('Trim Paths 1')"),
    (lambda d: d.update(fr=0), "fr: expected frames per second from 1 to 240, found 0"),
    (lambda d: d.update(layers=[]), "layers: expected at least one shape layer that draws something, found none"),
])
@pytest.mark.lottie_input
def test_malformed_files_are_refused_in_one_line(tmp_path: Path, change, message: str) -> None:
    document = _morph()
    change(document)
    path = _write(tmp_path, document)
    with pytest.raises(SceneError) as caught:
        tr.load_scene(path)
    assert str(caught.value).startswith(f"{path}: {message}")
    assert "\n" not in str(caught.value)


def test_writers_background_layer_is_the_scenes_background(tmp_path: Path) -> None:
    """A still, opaque rectangle filling the canvas at the bottom (as the vector writers draw a background)
    is read as the background; anything smaller stays a shape."""
    document = _morph()
    backdrop = {"ddd": 0, "ind": 2, "ty": 4, "nm": "background", "ip": 0, "op": 21, "st": 0, "ks": {}, "shapes": [
        {"ty": "gr", "it": [{"ty": "rc", "d": 1, "s": {"a": 0, "k": [200, 200]}, "p": {"a": 0, "k": [100, 100]},
                             "r": {"a": 0, "k": 0}},
                            {"ty": "fl", "c": {"a": 0, "k": [0, 0.5, 1, 1]}, "o": {"a": 0, "k": 100}, "r": 1}]}]}
    document["layers"].append(backdrop)
    scene = tr.load_scene(_write(tmp_path, document))
    assert scene.background == (0, 128, 255, 255) and [s.name for s in scene.shapes] == ["square"]
    backdrop["shapes"][0]["it"][0]["s"]["k"] = [150, 200]
    scene = tr.load_scene(_write(tmp_path, document))
    assert scene.background == (255, 255, 255, 255) and [s.name for s in scene.shapes] == ["background", "square"]


@pytest.mark.parametrize("item, perimeter", [
    ({"ty": "el", "p": {"a": 0, "k": [100, 90]}, "s": {"a": 0, "k": [120, 120]}}, 2 * np.pi * 60),
    ({"ty": "rc", "p": {"a": 0, "k": [100, 90]}, "s": {"a": 0, "k": [120, 60]}, "r": {"a": 0, "k": 0}}, 360.0),
    ({"ty": "rc", "p": {"a": 0, "k": [100, 90]}, "s": {"a": 0, "k": [120, 60]}, "r": {"a": 0, "k": 20}},
     360.0 - 8 * 20 + 2 * np.pi * 20),
])
def test_ellipses_and_rectangles_as_the_players_draw_them(tmp_path: Path, item: dict, perimeter: float) -> None:
    """A circle, a rectangle and a rounded one: edges within 0.25 px of rlottie's (the area between the two
    edges over the outline's length)."""
    document = _morph()
    _shape_items(document)[0] = {**item, "nm": "outline"}
    path = _write(tmp_path, document)
    scene = tr.load_scene(path)
    (picture,) = rlottie_frames(path, [0], scene.size)
    ours = over(tr.frame(scene, 0.0, method="linear", background="none"), WHITE)
    apart = np.abs(_coverage(ours) - _coverage(over(picture, WHITE))).sum() / perimeter
    assert apart <= 0.25, f"edges {apart:.3f} px apart"
