"""Comparison panels and their overlays (paths, onion ghosts, metric strip) against closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from tweenrender.core.ratios import scene_perimeter_ratio as perimeter_ratio
from tweenrender.model import Key, Paint, Scene, Shape
from tweenrender.pipeline.frames import Frames
from tweenrender.plan.job import RenderJob, tracks_of

K0 = np.array([[0, 0], [2, 0], [2, 2], [0, 2]], dtype=float)
K1 = np.array([[7, 1], [7, 3], [5, 3], [5, 1]], dtype=float)  # K0 turned 90° and moved
VIEW = (-2.0, -2.0, 10.0, 7.0)
SIZE = (360, 270)  # 30 px per world unit
WHITE = np.array([255, 255, 255])


def _scene(fill=(200, 40, 10, 255), fps: float = 24.0) -> Scene:
    shape = Shape("sq", (Key.outline(0.0, K0, paint=Paint(fill)), Key.outline(2.0, K1, paint=Paint(fill))))
    return Scene((shape,), size=SIZE, view=VIEW, fps=fps)


def _pixel(point: np.ndarray, panel: int = 0) -> tuple[int, int]:
    """(row, column) of a world point in panel ``panel``, computed from the view by hand: 30 px/unit."""
    x, y = point
    scale = 30.0
    ox = (SIZE[0] - scale * (VIEW[2] - VIEW[0])) / 2
    oy = (SIZE[1] - scale * (VIEW[3] - VIEW[1])) / 2
    column = (x - VIEW[0]) * scale + ox + panel * SIZE[0]
    row = SIZE[1] - ((y - VIEW[1]) * scale + oy)
    return int(np.floor(row)), int(np.floor(column))


def _inked(frame: np.ndarray, point: np.ndarray, panel: int = 0, radius: int = 1, by: int = 20) -> bool:
    """Whether any pixel within ``radius`` of the point differs from white by more than ``by``."""
    row, column = _pixel(point, panel)
    patch = frame[row - radius:row + radius + 1, column - radius:column + radius + 1, :3].astype(int)
    return bool(np.abs(patch - WHITE).max() > by)


@pytest.mark.parametrize("methods", [("linear",), ("linear", "nonlinear"), ("linear", "nonlinear", "rigid")])
@pytest.mark.parametrize("strip", [False, True])
def test_one_panel_per_method_at_the_asked_size(methods: tuple[str, ...], strip: bool) -> None:
    frame = Frames(RenderJob(_scene(), methods, labels=True, size=(200, 150), strip=strip))(0)
    assert frame.shape == (150, 200 * len(methods), 4)
    # every panel shows the first key (the same under every method) in the fill colour
    red = np.all(frame[..., :3] == (200, 40, 10), axis=-1)
    for panel in range(len(methods)):
        assert red[:, panel * 200:(panel + 1) * 200].sum() > 100


def _bezier_midpoints() -> np.ndarray:
    """maths §4 by hand: each vertex's nonlinear path at t = 0.5, ``Cm + (M - Cm)·d/|M - Cm|``."""
    c0, c1 = K0.mean(axis=0), K1.mean(axis=0)
    middle = (K0 + K1) / 2
    cm = (c0 + c1) / 2
    d = (np.linalg.norm(K0 - c0, axis=1) + np.linalg.norm(K1 - c1, axis=1)) / 2
    out = middle - cm
    return cm + out * (d / np.linalg.norm(out, axis=1))[:, None]


def _bezier(t: np.ndarray) -> np.ndarray:
    """Every vertex's nonlinear path at ``t (T,)``: ``(T, 4, 2)``, from the control point through B(0.5)."""
    p1 = 2 * _bezier_midpoints() - (K0 + K1) / 2
    t = t[:, None, None]
    return (1 - t) ** 2 * K0 + 2 * t * (1 - t) * p1 + t * t * K1


def _far_point(candidates: np.ndarray, away: np.ndarray) -> tuple[np.ndarray, float]:
    """The candidate ``(P, 2)`` farthest from every point of ``away (Q, 2)``, and that distance."""
    distance = np.linalg.norm(candidates[:, None] - away[None], axis=2).min(axis=1)
    return candidates[np.argmax(distance)], float(distance.max())


def _outlines(*polygons: np.ndarray) -> np.ndarray:
    """Dense samples of the polygons' edges: ``(Q, 2)``."""
    t = np.linspace(0, 1, 200)[:, None, None]
    return np.concatenate([(p + t * (np.roll(p, -1, axis=0) - p)).reshape(-1, 2) for p in polygons])


def test_paths_are_drawn_where_each_method_moves_the_vertices() -> None:
    scene = _scene()
    plain = Frames(RenderJob(scene, ("linear", "nonlinear"), size=SIZE))(0).copy()
    traced = Frames(RenderJob(scene, ("linear", "nonlinear"), size=SIZE, paths=True))(0).copy()
    assert np.allclose(_bezier_midpoints()[0], [3.5, 1.5 - np.sqrt(2)])  # maths §4 for vertex 0
    t = np.linspace(0.25, 0.75, 101)[:, None, None]
    straight = ((1 - t) * K0 + t * K1).reshape(-1, 2)  # points of the linear paths
    curved = _bezier(np.linspace(0.25, 0.75, 101)).reshape(-1, 2)  # points of the nonlinear paths
    keys = _outlines(K0, K1)
    on_line, gap = _far_point(straight, np.concatenate([_bezier(np.linspace(0, 1, 2001)).reshape(-1, 2), keys]))
    assert gap * 30 > 6  # 6 px from every nonlinear path and key outline
    on_arc, gap = _far_point(curved, np.concatenate([
        (np.linspace(0, 1, 2001)[:, None, None] * (K1 - K0) + K0).reshape(-1, 2), keys]))
    assert gap * 30 > 6
    assert _inked(traced, on_line, panel=0) and not _inked(plain, on_line, panel=0)
    assert _inked(traced, on_arc, panel=1) and not _inked(plain, on_arc, panel=1)
    assert not _inked(traced, on_line, panel=1)  # no straight path in the nonlinear panel
    assert not _inked(traced, on_arc, panel=0)  # no arc in the linear panel


def _inside(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    """Even-odd point-in-polygon for ``points (P, 2)``."""
    x, y = points[:, 0:1], points[:, 1:2]
    a, b = polygon, np.roll(polygon, -1, axis=0)
    crosses = (a[:, 1] > y) != (b[:, 1] > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        at = a[:, 0] + (y - a[:, 1]) * (b[:, 0] - a[:, 0]) / (b[:, 1] - a[:, 1])
    return np.sum(crosses & (x < at), axis=1) % 2 == 1


def _edge_distance(points: np.ndarray, polygon: np.ndarray) -> np.ndarray:
    a, b = polygon, np.roll(polygon, -1, axis=0)
    ab = b - a
    t = np.clip(np.einsum("pki,ki->pk", points[:, None] - a, ab) / np.einsum("ki,ki->k", ab, ab), 0, 1)
    nearest = a + t[..., None] * ab
    return np.linalg.norm(points[:, None] - nearest, axis=2).min(axis=1)


def test_onion_ghosts_sit_where_earlier_and_later_frames_were() -> None:
    scene = _scene()
    frame, step = 24, 4  # 24 fps: a ghost every 24 / 6 = 4 frames
    linear = lambda f: (1 - f / 48) * K0 + (f / 48) * K1  # noqa: E731 - the linear inbetween of frame f
    shown = [linear(frame + k * step) for k in (-2, -1, 0, 1, 2)]
    grid = np.stack(np.meshgrid(np.linspace(-1, 8, 181), np.linspace(-1, 4, 101)), -1).reshape(-1, 2)
    plain = Frames(RenderJob(scene, ("linear",), size=SIZE))(frame).copy()
    ghosted = Frames(RenderJob(scene, ("linear",), size=SIZE, onion=2))(frame).copy()
    for k in (-2, 2):  # the farthest ghost before and after, where no other frame is drawn
        ghost = linear(frame + k * step)
        others = [p for p in shown if p is not shown[k + 2]]
        alone = _inside(grid, ghost) & ~np.any([_inside(grid, p) for p in others], axis=0)
        margin = np.min([_edge_distance(grid, p) for p in shown], axis=0)
        assert alone.any()
        point = grid[alone][np.argmax(margin[alone])]
        assert np.min(margin[alone]) >= 0 and margin[alone].max() * 30 > 3
        assert _inked(ghosted, point, radius=0, by=10) and not _inked(plain, point, radius=0, by=2)
    # no ghost before the clip's start: at frame 0 only the later frames 4 and 8 add ink
    first = Frames(RenderJob(scene, ("linear",), size=SIZE, onion=2))(0).copy()
    bare = Frames(RenderJob(scene, ("linear",), size=SIZE))(0)
    rows, columns = np.nonzero(np.abs(first[..., :3].astype(int) - bare[..., :3]).max(axis=-1) > 2)
    assert len(rows) > 100
    row0, column0 = _pixel(np.array([0.0, 0.0]))
    world = np.stack([(columns + 0.5 - column0) / 30, (row0 - rows - 0.5) / 30], -1)
    later = [linear(4), linear(8)]
    near = np.any([_inside(world, p) | (_edge_distance(world, p) * 30 < 2.5) for p in later], axis=0)
    assert near.all()


def test_the_strip_marks_the_current_time_from_left_to_right() -> None:
    scene = _scene()
    frames = Frames(RenderJob(scene, ("linear",), size=SIZE, strip=True))
    columns = []
    for index in (0, 12, 24, 36, 48):
        picture = frames(index)[int(SIZE[1] * 0.8):, :, :3].astype(int)
        red = (picture[..., 0] > 180) & (picture[..., 1] < 120) & (picture[..., 2] < 120)
        assert red.any()
        columns.append(np.flatnonzero(red.any(axis=0)).mean())
    assert np.all(np.diff(columns) > 20)  # the marker walks right, evenly
    gaps = np.diff(columns)
    assert gaps.max() - gaps.min() < 3


def test_perimeter_ratio_closed_forms() -> None:
    scene = _scene()
    tracks = tracks_of(scene)
    times = np.array([0.0, 1.0, 2.0])
    assert np.allclose(perimeter_ratio(tracks, ["linear"], times), [1.0, np.cos(np.pi / 4), 1.0])
    assert np.allclose(perimeter_ratio(tracks, ["rigid"], np.linspace(0, 2, 9)), 1.0)
    assert perimeter_ratio(tracks, ["nonlinear"], [1.0])[0] == pytest.approx(1.0)
    # a still shape adds nothing; two moving shapes add perimeters: a 2x2 (8) and a 4x4 (16) square
    still = Shape("still", (Key.outline(0.0, K0 * 3),))
    big = Shape("big", (Key.outline(0.0, K0 * 2), Key.outline(2.0, K1 * 2)))
    both = Scene((scene.shapes[0], still, big), view=VIEW)
    mid = perimeter_ratio(tracks_of(both), ["linear", "linear", "rigid"], [1.0])[0]
    assert mid == pytest.approx((8 * np.cos(np.pi / 4) + 16) / 24)


def test_render_flags_reach_the_frames(cli, tmp_path) -> None:
    import imageio.v3 as iio

    from tests.helpers import SQUARE, write_scene

    scene = write_scene(tmp_path, SQUARE)
    pictures = {}
    for flags in ((), ("--paths",), ("--onion", "2"), ("--strip",)):
        target = tmp_path / ("x" + "".join(flags).replace("-", ""))
        code, out, err = cli("render", scene, "--compare", "-o", target, "--frames", "24", "-q", *flags)
        assert code == 0, err
        pictures[flags] = iio.imread(target / "frame_0000.png")
    assert pictures[()].shape == (240, 640, 4)
    for flags, picture in pictures.items():
        assert flags == () or np.abs(picture.astype(int) - pictures[()].astype(int)).max() > 50
    assert cli("render", scene, "--onion", "-1", "-q")[0] == 2
