"""The package's shape: public names, layers, imports (docs/architecture.md)."""

from __future__ import annotations

import ast
import functools
import importlib
import pkgutil
import subprocess
import sys
from collections import Counter
from pathlib import Path

import pytest

import tweenrender

PACKAGE = Path(tweenrender.__file__).parent
PUBLIC = {"load_scene": "function", "frame": "function", "frames": "function", "outlines": "function",
          "write": "function", "TweenrenderError": "class"}
# A stage may import only the stages listed for it (and errors, model, its own package).
ALLOWED = {
    "scenefile": {"core"},
    "core": set(),
    "plan": {"scenefile", "core", "encode"},
    "raster": {"core"},
    "vector": {"core", "plan", "encode"},
    "encode": set(),
    "pipeline": {"scenefile", "core", "plan", "raster", "vector", "encode"},
    "reports": {"scenefile", "core", "plan", "raster", "vector", "encode", "pipeline"},
    "api": {"scenefile", "core", "plan", "raster", "vector", "encode", "pipeline", "reports"},
    "preview": {"api"},
    "cli": {"api", "preview"},  # cli/preview.py starts the page; test below
}
FRONT_ENDS = ("cli", "preview")
THIRD_PARTY_HOME = {"skia": {"raster"}, "imageio_ffmpeg": {"encode"}, "imageio": {"encode"},
                    "svgelements": {"scenefile"}, "tinycss2": {"scenefile"}, "cssselect2": {"scenefile"},
                    "shapely": {"scenefile"}, "argparse": {"cli"}, "watchfiles": {"preview"}}


def modules() -> list[str]:
    return [m.name for m in pkgutil.walk_packages(tweenrender.__path__, "tweenrender.")]


@functools.lru_cache(maxsize=None)
def imports_of(path: Path, name: str) -> frozenset[str]:
    """Every module ``path`` (the module ``name``) imports, at any depth of its code, resolved (each file parsed
    once a run: the tests below walk the whole package, some once per library)."""
    package = name if path.name == "__init__.py" else name.rpartition(".")[0]
    found: set[str] = set()
    for node in ast.walk(ast.parse(path.read_text())):
        if isinstance(node, ast.Import):
            found.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                parts = package.split(".")
                parts = parts[: len(parts) - node.level + 1]
                base = ".".join(parts + ([base] if base else []))
            found.add(base)
            found.update(f"{base}.{alias.name}" for alias in node.names)
    return frozenset(found)


def graph() -> dict[str, set[str]]:
    names = set(modules()) | {"tweenrender"}
    edges = {}
    for name in names:
        spec = importlib.util.find_spec(name)
        assert spec is not None and spec.origin is not None
        edges[name] = {m for m in imports_of(Path(spec.origin), name) if m in names and m != name}
    return edges


def stage(module: str) -> str | None:
    parts = module.split(".")
    return parts[1] if len(parts) > 2 or (len(parts) == 2 and parts[1] in ALLOWED) else None


def test_public_names_hold_after_every_submodule_is_imported() -> None:
    code = ("import importlib, pkgutil, inspect, json, tweenrender as tr\n"
            "for m in pkgutil.walk_packages(tr.__path__, 'tweenrender.'):\n"
            "    if not m.name.endswith('__main__'): importlib.import_module(m.name)\n"
            "print(json.dumps({n: 'class' if inspect.isclass(getattr(tr, n)) else 'function' if "
            "inspect.isfunction(getattr(tr, n)) else type(getattr(tr, n)).__name__ for n in tr.__all__}))\n")
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    import json

    kinds = json.loads(done.stdout)
    for name, kind in PUBLIC.items():
        assert kinds.get(name) == kind, f"tweenrender.{name} is {kinds.get(name)}, expected a {kind}"
    assert all(kind in ("class", "function") for kind in kinds.values()), kinds


def test_no_module_directly_under_the_package_is_named_like_a_public_name() -> None:
    # only those can shadow a public name (``import tweenrender.x`` sets the attribute ``x``)
    for name in modules():
        if name.count(".") == 1:
            assert name.rpartition(".")[2] not in tweenrender.__all__, name


def test_no_module_name_is_used_twice_outside_the_cli() -> None:
    counts = Counter(name.rpartition(".")[2] for name in modules()
                     if not name.startswith("tweenrender.cli.") and not name.endswith("__init__"))
    stems = {name.rpartition(".")[2] for name in modules()}
    twice = sorted(n for n, k in counts.items() if k > 1)
    assert not twice, twice
    # a command module may share its name only with the library module it calls
    from tweenrender.cli.main import COMMANDS

    for name in modules():
        if name.startswith("tweenrender.cli."):
            short = name.rpartition(".")[2]
            assert short in COMMANDS or counts[short] == 0 or short == "__init__", name
    assert "__init__" not in stems


def test_no_import_cycle() -> None:
    edges = graph()
    state: dict[str, int] = {}
    stack: list[str] = []

    def visit(node: str) -> None:
        state[node] = 1
        stack.append(node)
        for nxt in sorted(edges[node]):
            if state.get(nxt) == 1 and not node.startswith(nxt + "."):
                cycle = stack[stack.index(nxt):] + [nxt]
                raise AssertionError("import cycle: " + " → ".join(cycle))
            if nxt not in state:
                visit(nxt)
        stack.pop()
        state[node] = 2

    for node in sorted(edges):
        if node not in state:
            visit(node)


def test_stages_import_only_the_stages_below_them() -> None:
    for module, targets in graph().items():
        own = stage(module)
        if own is None:
            continue
        for target in targets:
            other = stage(target)
            assert other is None or other == own or other in ALLOWED[own], f"{module} imports {target}"


def test_the_front_ends_use_only_the_front_door() -> None:
    # the command line and the preview reach the package through api and errors only (and their own modules);
    # the preview command alone starts the preview's page
    allowed = {"tweenrender.api", "tweenrender.errors"}
    seen = set()
    for module, targets in graph().items():
        own = stage(module)
        if own not in FRONT_ENDS:
            continue
        seen.add(own)
        for target in targets - allowed:
            if target.startswith(f"tweenrender.{own}") or target == f"tweenrender.{own}":
                continue
            if module == "tweenrender.cli.preview" and target == "tweenrender.preview":
                continue
            raise AssertionError(f"{module} imports {target}")
    assert seen == set(FRONT_ENDS)


def _package_of(module: str) -> str:
    spec = importlib.util.find_spec(module)
    return module if spec.origin.endswith("__init__.py") else module.rpartition(".")[0]


def test_no_private_name_is_imported_from_another_package() -> None:
    # a name or module starting with _ belongs to its package (and the packages inside it)
    known = set(modules()) | {"tweenrender"}
    for name in known:
        own = _package_of(name)
        for target in imports_of(Path(importlib.util.find_spec(name).origin), name):
            holder, _, leaf = target.rpartition(".")
            if not leaf.startswith("_") or leaf.startswith("__") or holder not in known:
                continue
            owner = holder if target in known else _package_of(holder)  # a private module: its package's
            assert own == owner or own.startswith(owner + "."), f"{name} imports {target}"


@pytest.mark.parametrize("library", sorted(THIRD_PARTY_HOME))
def test_heavy_libraries_are_imported_in_their_own_stage_only(library: str) -> None:
    for name in modules():
        spec = importlib.util.find_spec(name)
        used = {m.split(".")[0] for m in imports_of(Path(spec.origin), name)}
        if library in used:
            assert stage(name) in THIRD_PARTY_HOME[library], f"{name} imports {library}"


def test_the_core_raises_tweenrender_errors() -> None:
    from tweenrender.core.methods.joints import JointError
    from tweenrender.core.methods.registry import interpolate
    from tweenrender.errors import GeometryError

    import numpy as np

    assert issubclass(JointError, tweenrender.TweenrenderError)
    with pytest.raises(GeometryError, match="unknown method 'sideways'"):
        interpolate(np.zeros((3, 2)), np.ones((3, 2)), [0.5], "sideways")
    with pytest.raises(tweenrender.TweenrenderError):
        interpolate(np.zeros((3, 2)), np.ones((4, 2)), [0.5], "linear")


def test_nothing_below_the_cli_raises_usage_errors() -> None:
    for name in modules():
        if name.startswith("tweenrender.cli") or name == "tweenrender.errors":
            continue
        spec = importlib.util.find_spec(name)
        assert "UsageError" not in Path(spec.origin).read_text(), f"{name} mentions UsageError"


def test_the_installed_metadata_states_the_licence_as_an_spdx_expression_with_its_text() -> None:
    """PEP 639: ``License-Expression`` and the file it names (an old-style licence table warns on every
    build with current setuptools)."""
    from importlib.metadata import distribution

    meta = distribution("tweenrender").metadata
    assert meta["License-Expression"] == "MIT"
    assert meta.get_all("License-File") == ["LICENSE"]
    text = (PACKAGE.parent / "LICENSE").read_text(encoding="utf-8")
    assert text.startswith("MIT License") and "WITHOUT WARRANTY OF ANY KIND" in text
