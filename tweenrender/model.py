"""The scene as loaded: frozen dataclasses over read-only float64 arrays."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
from numpy.typing import NDArray

__all__ = [
    "Points", "Color", "METHODS", "BALANCES", "DEFAULT_BALANCE", "EASES", "COSTS", "ALIGNS", "EQUAL_COUNTS",
    "Key", "Joint", "Shape", "Matching", "Scene", "frozen_points",
]

Points = NDArray[np.float64]
"""A polygon: shape ``(N, 2)``, float64, world units, y up, closed implicitly."""

Color = tuple[int, int, int, int]
"""Straight (unpremultiplied) RGBA, each 0..255."""

Method = Literal["linear", "nonlinear", "rigid", "jointed", "arap", "intrinsic", "intrinsic-length", "auto"]
METHODS: tuple[str, ...] = ("linear", "nonlinear", "rigid", "jointed", "arap", "intrinsic", "intrinsic-length", "auto")
BALANCES: tuple[str, ...] = ("copies", "spread")
DEFAULT_BALANCE = "copies"
"""The balance rule of scenes that name none (benchmarks/balance_rules.py measured the two)."""
EASES: tuple[str, ...] = ("linear", "in", "out", "in-out")
COSTS: tuple[str, ...] = ("distance", "sg")
ALIGNS: tuple[str, ...] = ("none", "centroid")
EQUAL_COUNTS: tuple[str, ...] = ("drawn", "match")


def frozen_points(points: object) -> Points:
    """A read-only float64 ``(N, 2)`` copy of ``points``."""
    array = np.array(points, dtype=np.float64, copy=True).reshape(-1, 2)
    array.flags.writeable = False
    return array


@dataclass(frozen=True, slots=True)
class Key:
    """A keyframe: its time in seconds, its polygon and the easing of the segment it starts."""

    time: float
    points: Points
    ease: str = "linear"


Joint = tuple[int, int]
"""A chord between two vertex indices of a shape's first key."""


@dataclass(frozen=True, slots=True)
class Shape:
    name: str
    keys: tuple[Key, ...]
    fill: Color = (59, 111, 216, 255)
    stroke: Color | None = None
    stroke_width: float = 2.0
    method: str | None = None  # None: the scene's method
    joints: tuple[Joint, ...] = ()
    balance: str | None = None  # None: the scene's balance


@dataclass(frozen=True, slots=True)
class Matching:
    """How keys with different vertex counts are put in correspondence (maths §2)."""

    cost: str = "distance"
    align: str = "centroid"
    # keys of equal vertex counts: keep the drawn order ("drawn") or search them too ("match")
    equal_counts: str = "drawn"
    # Sederberg–Greenwood constants (maths §2.1)
    ks: float = 1.0
    cs: float = 0.5
    es: float = 2.0
    kb: float = 1.0
    eb: float = 2.0
    mb: float = 10.0
    pb: float = 1000.0


@dataclass(frozen=True, slots=True)
class Scene:
    shapes: tuple[Shape, ...]
    title: str | None = None
    size: tuple[int, int] = (1280, 720)
    fps: float = 24.0
    background: Color = (255, 255, 255, 255)
    view: tuple[float, float, float, float] | None = None  # None: fit every key
    method: str = "nonlinear"
    compare: tuple[str, ...] = ("linear", "nonlinear")
    matching: Matching = field(default_factory=Matching)
    path: Path | None = None
    balance: str = DEFAULT_BALANCE  # how balancing places copies of a vertex (maths §5.6)

    @property
    def duration(self) -> float:
        """Seconds from time 0 to the last key of any shape."""
        return max(shape.keys[-1].time for shape in self.shapes)

    def method_of(self, shape: Shape) -> str:
        return shape.method or self.method

    def balance_of(self, shape: Shape) -> str:
        return shape.balance or self.balance
