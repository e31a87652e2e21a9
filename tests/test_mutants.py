"""The mutation check's mutants follow the code they mutate: each one's text occurs exactly once in its file and
its tests exist (a mutant whose text moved away is reported stale only when the whole check is run)."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


def _mutants() -> list:  # noqa: ANN401 - the script's own Mutant records
    spec = importlib.util.spec_from_file_location("mutation_check", ROOT / "scripts" / "mutation_check.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules.setdefault(spec.name, module)  # its dataclasses look their module up
    spec.loader.exec_module(module)
    return list(module.MUTANTS)


@pytest.mark.parametrize("mutant", _mutants(), ids=lambda m: m.name)
def test_each_mutant_changes_text_found_once_and_names_tests_that_exist(mutant) -> None:  # noqa: ANN001
    assert (ROOT / mutant.file).read_text(encoding="utf-8").count(mutant.before) == 1, mutant.file
    assert mutant.before != mutant.after
    for test in mutant.tests:
        assert (ROOT / test.split("::")[0]).exists(), test
