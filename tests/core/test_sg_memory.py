"""The ``sg`` search's memory guard: the estimate against what the search allocates (tracemalloc, which
numpy reports its arrays to), a search over the limit refused before it allocates anything, one under it
run as without the limit, and the limit taken from the library's options."""

from __future__ import annotations

import tracemalloc
from dataclasses import replace
from pathlib import Path

import numpy as np
import pytest

from tweenrender.core.correspondence.correspond import (
    SearchTooLarge, correspond, naive_correspond, sg_memory,
)
from tweenrender.core.correspondence.hint_search import correspond_hinted
from tweenrender.errors import GeometryError, OptionError
from tweenrender.model import DEFAULT_MAX_MEMORY, Matching
from tweenrender.plan.options import MatchSettings, RenderOptions, check_memory

SG = Matching(cost="sg")


def blob(count: int, seed: int) -> np.ndarray:
    """A smooth star-shaped outline of ``count`` vertices, counter-clockwise: ``(count, 2)``."""
    rng = np.random.default_rng(seed)
    angles = np.linspace(0.0, 2 * np.pi, count, endpoint=False)
    radius = 1.0 + 0.3 * np.sin(3 * angles + rng.uniform(0, 6)) + 0.1 * np.cos(5 * angles)
    return np.column_stack([radius * np.cos(angles), radius * np.sin(angles)])


def peak_bytes(call, *args) -> tuple[int, object]:  # type: ignore[no-untyped-def]
    """The most memory traced at once while ``call(*args)`` runs, and what it returned (or raised)."""
    tracemalloc.start()
    try:
        try:
            result: object = call(*args)
        except GeometryError as error:
            result = error
        return tracemalloc.get_traced_memory()[1], result
    finally:
        tracemalloc.stop()


@pytest.fixture(scope="module", autouse=True)
def compiled() -> None:
    """The kernels compiled (or loaded from their cache) before anything is measured."""
    correspond(blob(30, 1), blob(33, 2), SG)
    naive_correspond(blob(12, 1), blob(13, 2), SG)
    correspond_hinted(blob(12, 1), blob(13, 2), [(0, 0), (6, 6)], SG)


@pytest.mark.parametrize("m, n", [(120, 90), (200, 230)])
def test_the_estimate_is_what_the_search_takes(m: int, n: int) -> None:
    a, b = blob(m, 3), blob(n, 4)
    peak, found = peak_bytes(correspond, a, b, SG)
    assert not isinstance(found, Exception)
    assert 0.97 * peak <= sg_memory(m, n) <= 1.05 * peak  # within a few per cent, from above
    for search, args in ((naive_correspond, (a, b, SG)), (correspond_hinted, (a, b, [(0, 0), (m // 2, n // 2)], SG))):
        assert peak_bytes(search, *args)[0] <= sg_memory(m, n)  # the other searches hold less


def test_a_search_over_the_limit_is_refused_before_it_allocates() -> None:
    a, b = blob(200, 5), blob(230, 6)
    needed, _ = peak_bytes(correspond, a, b, SG)
    limit = needed // 2
    for search, args in ((correspond, (a, b)), (naive_correspond, (a, b)),
                         (correspond_hinted, (a, b, [(0, 0), (100, 115)]))):
        peak, refusal = peak_bytes(search, *args, replace(SG, max_memory=limit))
        assert isinstance(refusal, SearchTooLarge) and isinstance(refusal, GeometryError)
        assert peak < 64 << 10  # no table was made: the two keys' copies and the message only
        message = str(refusal)
        assert "\n" not in message and "200 × 230" in message and "--cost distance" in message
        assert f"{limit / (1 << 20):.3g} MiB" in message  # the limit, and the estimate beside it
        assert f"{sg_memory(200, 230) / (1 << 20):.3g} MiB" in message


def test_a_search_under_the_limit_is_the_search_without_one() -> None:
    a, b = blob(200, 7), blob(230, 8)
    needed, free = peak_bytes(correspond, a, b, SG)
    _, limited = peak_bytes(correspond, a, b, replace(SG, max_memory=int(needed * 1.06)))
    assert not isinstance(limited, Exception)
    assert np.array_equal(limited.pairs, free.pairs) and limited.work == free.work  # type: ignore[union-attr]
    assert SG.max_memory == DEFAULT_MAX_MEMORY == 2 * 1024 ** 3


def test_the_distance_cost_has_no_such_limit() -> None:
    a, b = blob(200, 9), blob(230, 10)
    found = correspond(a, b, Matching(cost="distance", max_memory=1024))
    assert len(found.pairs) >= 230


@pytest.mark.parametrize("text, expected", [
    ("512M", 512 * 1024 ** 2), ("2G", 2 * 1024 ** 3), ("1.5GiB", 3 * 1024 ** 3 // 2), ("100k", 102_400),
    ("64 MB", 64 * 1024 ** 2), ("4096", 4096), (4096, 4096), ("1T", 1024 ** 4),
])
def test_sizes_are_read_in_binary_units(text: object, expected: int) -> None:
    assert check_memory(text) == expected


@pytest.mark.parametrize("text", ["2X", "-1", "", "G", "1e9", True, 0, 512, "0.5K", 1.5, None, "2 G B"])
def test_sizes_that_are_no_size_are_refused(text: object) -> None:
    with pytest.raises(OptionError, match=r"^max_memory=: expected a size"):
        check_memory(text)


def test_the_library_takes_the_limit_in_its_options(tmp_path: Path) -> None:
    from tweenrender import api

    scene = api.load_scene(Path(__file__).parents[2] / "scenes" / "bird-feet.toml")  # 22 → 20 vertices
    assert MatchSettings(max_memory="1K").over(scene).matching.max_memory == 1024
    with pytest.raises(SearchTooLarge, match="--cost distance"):
        api.correspondence(scene, cost="sg", max_memory="1K")
    assert api.correspondence(scene, cost="sg", max_memory="1M")["shapes"][0]["cost"] == "sg"
    target = tmp_path / "clip.json"
    with pytest.raises(SearchTooLarge):
        api.write(scene, target, options=RenderOptions.create(cost="sg", max_memory="1K", frames="0:2"))
    assert not target.exists()
    with pytest.raises(OptionError, match="^max_memory=: "):
        RenderOptions.create(max_memory="lots")
    assert api.write(scene, target, cost="sg", max_memory=1 << 20, frames="0:2") == target and target.exists()
