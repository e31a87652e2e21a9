"""Frames are evaluated in blocks: a detailed scene's blocks hold fewer frames, every frame is the shape
at its own time whatever the block, and a block's outlines are let go before the next block's are made."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tweenrender.pipeline import frames as job_module
from tweenrender.pipeline.frames import Frames
from tweenrender.plan.job import RenderJob
from tweenrender.scenefile import load_scene

ROOT = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize(("budget", "expected"), [(1 << 20, 32), (200, None), (1, 1)])
def test_blocks_hold_at_most_the_budget_of_vertices(monkeypatch, budget: int, expected: int | None) -> None:
    scene = load_scene(ROOT / "scenes" / "bird-feet.toml")
    points = sum(max(sum(len(c.points) for c in key.contours) for key in shape.keys) for shape in scene.shapes)
    monkeypatch.setattr(job_module, "_BLOCK_POINTS", budget)
    frames = Frames(RenderJob(scene, size=(64, 36)))
    size = frames.block_frames()
    assert size == (expected if expected is not None else min(32, budget // points))
    assert expected is not None or size < 32
    assert 1 <= size <= 32 and (size == 1 or size * points <= budget)
    reference = Frames(RenderJob(scene, size=(64, 36)))
    for index in range(0, 40, 3):
        blocked = frames.frame_shapes(None, index)
        single = reference.shapes_at(None, index / frames.job.rate)
        for a, b in zip(blocked, single):
            for ca, cb in zip(a.contours, b.contours):
                np.testing.assert_allclose(ca, cb, rtol=0, atol=1e-9)


def test_the_previous_block_is_let_go_before_the_next_is_made(monkeypatch) -> None:
    monkeypatch.setattr(job_module, "_BLOCK_POINTS", 1)  # a frame a block
    frames = Frames(RenderJob(load_scene(ROOT / "scenes" / "square.toml"), size=(64, 36)))
    held: list[int] = []
    original = job_module.Track.at

    def at(track, times, method):  # type: ignore[no-untyped-def]
        held.append(len(frames._blocks))
        return original(track, times, method)

    monkeypatch.setattr(job_module.Track, "at", at)
    for index in range(4):
        frames.frame_shapes(None, index)
    assert held and set(held) == {0}
