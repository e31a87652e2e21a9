"""One span on a CSS cubic-bezier free in both handles (vector/free_timing.py), replayed as players replay it: each
span's progress found by bisection (tests/vector_players.py, written apart from the module's own), held before the
first keyframe and after the last."""

from __future__ import annotations

import numpy as np
import pytest

from tests.vector_players import bezier_timing
from tweenrender.vector.free_timing import free_span

T = np.linspace(0.0, 1.0, 25)


def _played(frames: tuple[int, ...], values: np.ndarray, eases: tuple, count: int) -> np.ndarray:
    out = np.empty((count, values.shape[1]))
    for f in range(count):
        k = int(np.clip(np.searchsorted(frames, f, side="right") - 1, 0, len(frames) - 1))
        if k == len(frames) - 1:
            out[f] = values[k]
            continue
        x = (f - frames[k]) / (frames[k + 1] - frames[k])
        out[f] = values[k] + bezier_timing(np.array([x]), eases[k])[0] * (values[k + 1] - values[k])
    return out


def _scaled(scale: np.ndarray) -> np.ndarray:
    """A contour of radius 60 px scaled by ``scale (F,)`` about (300, 40) from its centre (120, 200): the centre and
    the scale times the radius, ``(F, 3)``."""
    centre = np.array([300.0, 40.0]) + scale[:, None] * (np.array([120.0, 200.0]) - [300.0, 40.0])
    return np.concatenate([centre, 60.0 * scale[:, None]], axis=1)


@pytest.mark.parametrize("scale, spans", [(np.sqrt(T), 1), (np.sqrt(1.0 - T), 1),
                                          (np.sqrt(np.clip((T - 0.25) / 0.75, 0.0, 1.0)), 1),
                                          (np.sqrt(np.clip((T - 0.2) / 0.8, 0.0, 1.0)), 2)],
                         ids=["growing", "shrinking", "growing-late", "growing-between-frames"])
def test_a_scale_about_a_point_is_one_span_within_the_bound(scale: np.ndarray, spans: int) -> None:
    """One span moves (any other holds the first or last value), and, where the growth starts between two frames,
    one step before it."""
    values = _scaled(scale)
    found = free_span(values, 0.1)
    assert found is not None
    moving = [(a, b) for a, b in zip(found.frames, found.frames[1:]) if not np.array_equal(values[a], values[b])]
    assert len(moving) == spans and sum(b - a > 1 for a, b in moving) == 1
    error = np.linalg.norm(_played(found.frames, found.values, found.eases, len(T)) - values, axis=1)
    assert float(error.max()) <= 0.1


def test_values_off_one_straight_line_are_not_one_span() -> None:
    values = _scaled(np.sqrt(T))
    values[:, 1] += 30.0 * np.sin(np.pi * T)  # the centre bows off the line
    assert free_span(values, 0.1) is None


def test_a_timing_no_cubic_bezier_follows_is_not_one_span() -> None:
    wave = 0.5 - 0.5 * np.cos(3 * np.pi * T)  # there and back and there: not monotone
    assert free_span(_scaled(wave), 0.1) is None


def test_contours_growing_on_one_timing_search_their_handles_once(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    """Contours that grow on one timing have the same progress but for rounding (a clip's pieces, a face's eyes): the
    handles are searched once for them all, and each span is still checked at every frame as a player plays it."""
    import scipy.optimize

    from tests.helpers import count_calls
    from tweenrender.vector import free_timing

    free_timing._searched.clear()
    searches = count_calls(monkeypatch, scipy.optimize, "minimize")
    eased = np.sqrt(T * T * (3.0 - 2.0 * T))  # the area on a smoothstep: not √t, so the handles are searched
    spans = [free_span(_scaled(eased) + shift, 0.2) for shift in (0.0, 1e-11, 250.0)]
    assert len(searches) == 1
    for found, shift in zip(spans, (0.0, 1e-11, 250.0)):
        assert found is not None
        played = _played(found.frames, found.values, found.eases, len(T))
        assert np.linalg.norm(played - (_scaled(eased) + shift), axis=1).max() <= 0.2
