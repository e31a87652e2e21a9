"""Fixtures: the command line run in-process, the ``--update-golden`` switch, and every Lottie a test writes
to its ``tmp_path`` validated against the Lottie JSON Schema afterwards."""

from __future__ import annotations

import pytest


def pytest_addoption(parser: pytest.Parser) -> None:
    parser.addoption("--update-golden", action="store_true",
                     help="rewrite the golden images in tests/golden (those tests then skip)")


@pytest.fixture
def update_golden(request: pytest.FixtureRequest) -> bool:
    return bool(request.config.getoption("--update-golden"))


@pytest.fixture
def cli(capsys: pytest.CaptureFixture[str]):
    """Run ``tweenrender ARGS`` in-process; returns (exit code, stdout, stderr)."""
    from tweenrender.cli.main import main

    def run(*args: str) -> tuple[int, str, str]:
        code = main([str(a) for a in args])
        out, err = capsys.readouterr()
        return code, out, err

    return run


@pytest.fixture
def open_tmp_path():
    """A fresh folder any user can reach (pytest's own are private to their owner), removed afterwards."""
    import shutil
    import tempfile
    from pathlib import Path

    folder = Path(tempfile.mkdtemp(prefix="tweenrender-test-"))
    folder.chmod(0o755)
    try:
        yield folder
    finally:
        for path in folder.rglob("*"):  # let every folder be emptied, whatever the test left locked
            if path.is_dir() and not path.is_symlink():
                path.chmod(0o755)
        shutil.rmtree(folder)


@pytest.fixture(scope="module")
def pool():
    """Two worker processes shared by a module's tests."""
    from concurrent.futures import ProcessPoolExecutor

    with ProcessPoolExecutor(max_workers=2) as executor:
        yield executor


@pytest.fixture(autouse=True)
def _lottie_files_are_schema_valid(request: pytest.FixtureRequest):
    """After a test that has a ``tmp_path``, every Lottie left in it validates (:mod:`tests.lottie_schema`),
    but for tests marked ``lottie_input`` (they write malformed Lottie files to be refused)."""
    folder = request.getfixturevalue("tmp_path") if "tmp_path" in request.fixturenames else None
    yield
    if folder is not None and request.node.get_closest_marker("lottie_input") is None:
        from tests.lottie_schema import check_folder

        check_folder(folder)
