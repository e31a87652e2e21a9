"""Pairing the elements of consecutive drawings: the least total cost over every partial pairing (brute
force on small drawings), the same for a thousand elements in bounded memory, and a refusal past the limit."""

from __future__ import annotations

import itertools
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from tweenrender.model import Contour, Paint
from tweenrender.scenefile import drawings
from tweenrender.scenefile.drawings import _costs, match_elements
from tweenrender.scenefile.svg import Element


def _element(x: float, y: float, side: float, fill: tuple[int, int, int, int] | None, ident: str | None = None
             ) -> Element:
    points = np.array([[x, y], [x + side, y], [x + side, y + side], [x, y + side]], dtype=np.float64)
    paint = Paint(fill=fill, stroke=None if fill else (0, 0, 0, 255))
    return Element(ident, "rect", 1, (Contour(points),), paint, "nonzero", "butt", "miter", 4.0)


def _random_drawing(rng: np.random.Generator, count: int) -> list[Element]:
    return [_element(*rng.uniform(0, 100, 2), rng.uniform(1, 30),
                     None if rng.random() < 0.2 else tuple(int(v) for v in rng.integers(0, 256, 3)) + (255,))
            for _ in range(count)]


def _least_total(cost: np.ndarray, unmatched: float) -> float:
    """Every partial pairing of rows with columns: pairs' costs plus ``unmatched`` per element left over."""
    m, n = cost.shape
    best = unmatched * (m + n)
    for size in range(1, min(m, n) + 1):
        for rows in itertools.combinations(range(m), size):
            for cols in itertools.permutations(range(n), size):
                total = sum(cost[r, c] for r, c in zip(rows, cols)) + unmatched * (m + n - 2 * size)
                best = min(best, total)
    return best


@pytest.mark.parametrize("seed", range(12))
def test_the_pairing_has_the_least_total_cost_of_every_partial_pairing(seed: int) -> None:
    rng = np.random.default_rng(seed)
    a, b = _random_drawing(rng, int(rng.integers(2, 5))), _random_drawing(rng, int(rng.integers(2, 5)))
    diagonal = float(np.hypot(100, 100))
    pairs = match_elements(a, b, diagonal)
    cost = _costs(a, b, diagonal)
    unmatched = drawings._UNMATCHED_COST
    assert sorted(i for i, _ in pairs if i is not None) == list(range(len(a)))
    assert sorted(j for _, j in pairs if j is not None) == list(range(len(b)))
    paired = [(i, j) for i, j in pairs if i is not None and j is not None]
    total = sum(cost[i, j] for i, j in paired) + unmatched * (len(a) + len(b) - 2 * len(paired))
    assert total == pytest.approx(_least_total(cost, unmatched), abs=1e-9)


def test_ids_pair_first_and_a_repeated_id_does_not() -> None:
    a = [_element(0, 0, 5, (255, 0, 0, 255), "x"), _element(50, 50, 5, (0, 0, 255, 255), "y"),
         _element(90, 0, 5, (0, 255, 0, 255), "y")]
    b = [_element(60, 60, 5, (0, 0, 255, 255), "y"), _element(0, 0, 5, (255, 0, 0, 255)),
         _element(52, 52, 5, (0, 0, 255, 255), "x")]
    pairs = match_elements(a, b, 141.0)
    assert (0, 2) in pairs  # "x" by its id, though (0, 0) sits where b's element 1 is
    assert (1, 0) in pairs  # "y" is twice in a: paired by cost (the nearer blue one), not by id


def _rects_svg(count: int, shift: int) -> str:
    rects = "".join(f'<rect x="{(i % 100) * 10 + shift}" y="{(i // 100) * 10}" width="6" height="6"/>'
                    for i in range(count))
    return f'<svg xmlns="http://www.w3.org/2000/svg" viewBox="0 0 1000 {10 * (count // 100 + 1)}">{rects}</svg>'


_MEASURED = """
import resource, subprocess, sys
done = subprocess.run([sys.executable, "-m", "tweenrender", *sys.argv[1:]])
print(resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss, done.returncode, file=sys.stderr)
"""


def _peak_kib(*args: object) -> tuple[subprocess.CompletedProcess[str], int]:
    """Run ``python -m tweenrender ARGS`` as the only child of a fresh process; with its largest resident
    size (KiB). (This process's own count of its children's peak holds every child it ever had.)"""
    done = subprocess.run([sys.executable, "-c", _MEASURED, *map(str, args)], capture_output=True, text=True,
                          timeout=600)
    *said, last = done.stderr.splitlines() or [""]
    peak, code = (int(v) for v in last.split())
    return subprocess.CompletedProcess(done.args, code, done.stdout, "\n".join(said)), peak


def test_checking_3000_elements_a_drawing_stays_within_400_mb(tmp_path: Path) -> None:
    # the pairing's costs, one (m, n) matrix: 72 MB here, where three-dimensional differences and a
    # (m + n)² assignment took about ten times that (1.8 GB for 5000 rects)
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(_rects_svg(3000, 0))
    b.write_text(_rects_svg(3000, 1))
    done, peak = _peak_kib("check", a, b)
    assert done.returncode == 0 and done.stderr == "", done.stderr
    assert "3000 shapes" in done.stdout  # each rect paired with its shifted self
    assert peak < 400 * 1024, f"{peak / 1024:.0f} MB"


def test_drawings_with_too_many_elements_are_refused_before_pairing(tmp_path: Path, monkeypatch) -> None:
    # every element of every drawing is a key of some shape: 5001 + 5001 are over the scene's 10000 keys,
    # which is said before any pairing is tried (the pairing here would fail the test)
    import tweenrender as tr
    from tweenrender.errors import SceneError

    def no_pairing(*args: object, **kwargs: object) -> None:
        raise AssertionError("paired before the count was checked")

    monkeypatch.setattr(drawings, "match_elements", no_pairing)
    a, b = tmp_path / "a.svg", tmp_path / "b.svg"
    a.write_text(_rects_svg(5001, 0))
    b.write_text(_rects_svg(5001, 1))
    with pytest.raises(SceneError) as caught:
        tr.load_scene([a, b])
    assert str(caught.value) == (f"{a}: expected at most 10000 keys in the scene, found 10002 "
                                 "(one for each element of each drawing)")



def test_of_drawings_drawn_by_strokes_alone_an_outline_pairs_with_an_outline_not_with_lines() -> None:
    """lucide's circle-check becoming its sun (both drawn by their strokes): the tick is nearer the sun's
    ring in size and place than the big ring is, but a tick's line and a ring's outline cannot morph one into
    the other (one would only shrink away as the other grows), so the ring becomes the ring."""
    import tweenrender as tr
    from tweenrender.core.timing.timeline import tracks_of

    def radius(points: np.ndarray) -> float:  # of a circle's polygon, from its shoelace area
        x, y = points[:, 0], points[:, 1]
        return float(np.sqrt(abs(0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)) / np.pi))

    icons = Path(__file__).resolve().parents[1] / "data" / "icons" / "lucide"
    for circle in ('<circle cx="12" cy="12" r="10"', '<circle cx="12" cy="12" r="4"'):
        assert circle in ((icons / "circle-check.svg").read_text() + (icons / "sun.svg").read_text())
    scene = tr.load_scene([icons / "circle-check.svg", icons / "sun.svg"])
    rings = [(radius(p.k0), radius(p.k1)) for track in tracks_of(scene) for segment in track.segments
             for p in segment.pairs if p.moving and p.closed]
    assert len(rings) == 1 and rings[0] == (pytest.approx(10.0, rel=0.01), pytest.approx(4.0, rel=0.01))


def _disc(cx: float, cy: float, r: float, count: int = 48) -> np.ndarray:
    angles = np.linspace(0.0, 2.0 * np.pi, count, endpoint=False)
    return np.stack([cx + r * np.cos(angles), cy + r * np.sin(angles)], axis=1)


def test_a_solid_shape_pairs_with_the_solid_shape_of_its_area_not_with_pieces_spread_over_its_box() -> None:
    """A heart becoming a sun drawn as a disc and, as one element, eight small rays around it (twemoji's
    2600): the rays' box is the heart's, but their ink is a fifth of it; the disc, in a smaller box, holds
    nearly the heart's area. The heart becomes the disc and the rays grow (were it the rays, the heart would
    shrink into one ray while the disc grew out of it)."""
    orange = (255, 172, 51, 255)
    heart = Element(None, "path", 1, (Contour(_disc(18, 18, 15, 64)),), Paint(fill=(0, 0, 0, 255)),
                    "nonzero", "butt", "miter", 4.0)
    rays = tuple(Contour(_disc(18 + 16 * np.cos(a), 18 + 16 * np.sin(a), 2, 16))
                 for a in np.linspace(0.0, 2.0 * np.pi, 8, endpoint=False))
    sun = [Element(None, "path", 1, rays, Paint(fill=orange), "nonzero", "butt", "miter", 4.0),
           Element(None, "circle", 2, (Contour(_disc(18, 18, 10)),), Paint(fill=orange), "nonzero", "butt",
                   "miter", 4.0)]
    assert (0, 1) in match_elements([heart], sun, float(np.hypot(36, 36)))


def test_a_ring_drawn_as_an_outline_with_a_hole_pairs_by_the_area_it_encloses() -> None:
    """A page (a filled rectangle) becoming a thin ring (a disc with a hole, one element) with a bar across
    it: the ring's ink is nearer the bar's than the page's, but it encloses the page's area; the page becomes
    the ring."""
    page = Element(None, "rect", 1, (Contour(np.array([[4, 2], [32, 2], [32, 34], [4, 34]], float)),),
                   Paint(fill=(0, 0, 0, 255)), "nonzero", "butt", "miter", 4.0)
    ring = Element(None, "path", 1, (Contour(_disc(18, 18, 15)), Contour(_disc(18, 18, 14.5)[::-1])),
                   Paint(fill=(0, 0, 0, 255)), "nonzero", "butt", "miter", 4.0)
    bar = Element(None, "rect", 2, (Contour(np.array([[8, 16.5], [28, 16.5], [28, 19.5], [8, 19.5]], float)),),
                  Paint(fill=(0, 0, 0, 255)), "nonzero", "butt", "miter", 4.0)
    assert (0, 0) in match_elements([page], [ring, bar], float(np.hypot(36, 36)))


def test_a_ring_drawn_as_one_contour_pairs_by_the_area_it_looks_to_cover() -> None:
    """The same page becoming the same thin ring, here drawn as one contour as some icon sets draw outlines
    (out round the outside, back round the inside through a notch), beside a bar: the ring's own area
    (about 46) is less than the bar's (60), but it looks to cover the disc it rings; the page becomes the ring."""
    page = Element(None, "rect", 1, (Contour(np.array([[4, 2], [32, 2], [32, 34], [4, 34]], float)),),
                   Paint(fill=(0, 0, 0, 255)), "nonzero", "butt", "miter", 4.0)
    turn = np.linspace(0.02, 2.0 * np.pi - 0.02, 64)
    band = np.vstack([np.c_[18 + 15 * np.cos(turn), 18 + 15 * np.sin(turn)],
                      np.c_[18 + 14.5 * np.cos(turn[::-1]), 18 + 14.5 * np.sin(turn[::-1])]])
    ring = Element(None, "path", 1, (Contour(band),), Paint(fill=(0, 0, 0, 255)), "nonzero", "butt", "miter", 4.0)
    bar = Element(None, "rect", 2, (Contour(np.array([[8, 16.5], [28, 16.5], [28, 19.5], [8, 19.5]], float)),),
                  Paint(fill=(0, 0, 0, 255)), "nonzero", "butt", "miter", 4.0)
    assert (0, 0) in match_elements([page], [ring, bar], float(np.hypot(36, 36)))


def test_bootstraps_heart_becomes_twemojis_sun_disc_not_a_ray() -> None:
    """The real pair behind the test above: twemoji's 2600 draws its rays as one path of eight pieces and its
    disc as ``<circle r="10">`` in a 36-unit view; fitted into the heart's 16-unit view the disc's radius is
    10 × 16 / 36. The heart's key at 1 s is that disc (its area π r²), and every ray grows."""
    import tweenrender as tr

    icons = Path(__file__).resolve().parents[1] / "data" / "icons"
    assert '<circle cx="18" cy="18" r="10"' in (icons / "twemoji" / "2600.svg").read_text()
    scene = tr.load_scene([icons / "bootstrap" / "heart-fill.svg", icons / "twemoji" / "2600.svg"])
    shown = [shape for shape in scene.shapes if not shape.keys[0].hidden and not shape.keys[-1].hidden]
    assert len(shown) == 1
    (disc,) = shown[0].keys[-1].contours
    x, y = disc.points[:, 0], disc.points[:, 1]
    area = abs(0.5 * float(np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y)))
    assert area == pytest.approx(np.pi * (10 * 16 / 36) ** 2, rel=0.01)
