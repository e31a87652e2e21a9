"""``stats --json``'s ``crossings``: per shape, segment and method, the swept t where the shape tangles."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from tests.core.exact_tangles import tangled
from tests.helpers import run_main
from tweenrender.core.tangles import SWEEP

SCENE = """
size = [320, 240]
fps = 12
[[shape]]
name = "flap"
[[shape.key]]
time = 0.0
points = [[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]]
[[shape.key]]
time = 1.0
points = [[6, -2], [-3, 6], [-3, 2], [-3, 0], [2, 1]]

[[shape]]
name = "ring"
[[shape.key]]
time = 0.0
contours = [[[0, 0], [6, 0], [6, 6], [0, 6]], [[1, 1], [1, 2], [2, 2], [2, 1]]]
[[shape.key]]
time = 1.0
contours = [[[0, 0], [6, 0], [6, 6], [0, 6]], [[4, 4], [4, 5], [5, 5], [5, 4]]]
"""


def test_crossings_per_method_match_an_exact_brute_force(tmp_path: Path) -> None:
    scene = tmp_path / "flap.toml"
    scene.write_text(SCENE)
    done = run_main("stats", scene, "--json")
    assert done.returncode == 0, done.stderr
    shapes = {s["name"]: s for s in json.loads(done.stdout)["shapes"]}
    flap = shapes["flap"]["methods"]
    k0 = np.array([[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]], dtype=float)
    k1 = np.array([[6, -2], [-3, 6], [-3, 2], [-3, 0], [2, 1]], dtype=float)
    assert not tangled([k0], [True], [None]) and not tangled([k1], [True], [None])
    frames = (1 - SWEEP)[:, None, None] * k0 + SWEEP[:, None, None] * k1
    brute = [float(t) for t, f in zip(SWEEP, frames) if tangled([f], [True], [None])]
    assert brute and flap["linear"]["crossings"] == brute
    assert flap["injective"]["crossings"] == []
    # the injective way round leaves both keys (stray 0.108 against the straight paths' 0.012): auto keeps
    # the straight paths, which need no copies here, and says why
    assert shapes["flap"]["auto"]["method"] == "linear"
    why = shapes["flap"]["auto"]["why"]
    assert "linear: tangled at" in why and "injective: tangled at 0 of 19 t, stray " in why
    strays = {m: float(why.split(f"{m}: tangled at")[1].split("stray ")[1][:5]) for m in ("linear", "injective")}
    assert strays["injective"] > strays["linear"] + 0.02, why
    assert flap["auto"]["crossings"] == brute
    for method, measured in flap.items():
        assert isinstance(measured["crossings"], list), method
    # a hole moving inside its outline never leaves it: no method tangles there
    ring = [s for s in json.loads(done.stdout)["shapes"] if s["name"] == "ring"]
    assert ring and all(r["crossings"] == [] for s in ring for r in s["methods"].values())
