"""The Lottie Animation Community's JSON Schema (PyPI ``lottie-specs``, read offline) applied to Lottie files:
every Lottie a test leaves in its ``tmp_path`` (``.json`` with ``v`` and ``layers`` at the top, and the
animations inside ``.lottie`` archives) is validated after the test (the fixture in ``tests/conftest.py``)."""

from __future__ import annotations

import json
import zipfile
from functools import lru_cache
from pathlib import Path
from typing import Any


@lru_cache(maxsize=1)
def _validator() -> Any:
    import jsonschema
    from lottie_specs.resources import load_specs

    return jsonschema.Draft202012Validator(load_specs())


def schema_errors(document: object) -> list[str]:
    """What the schema finds wrong with a Lottie document: ``"key/path: message"`` each (none: valid)."""
    found = sorted(_validator().iter_errors(document), key=lambda e: [str(p) for p in e.absolute_path])
    return ["/".join(str(p) for p in e.absolute_path) + ": " + e.message[:300] for e in found]


def lottie_documents(folder: Path) -> list[tuple[str, object]]:
    """The Lottie documents under ``folder``: ``(where, document)`` each."""
    out: list[tuple[str, object]] = []
    for path in sorted(folder.rglob("*.json")):
        try:
            document = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError, ValueError, RecursionError):  # not a file we wrote
            continue
        if isinstance(document, dict) and "v" in document and "layers" in document:
            out.append((str(path), document))
    for path in sorted(folder.rglob("*.lottie")):
        try:
            with zipfile.ZipFile(path) as archive:
                for name in archive.namelist():
                    if name.startswith("animations/") and name.endswith(".json"):
                        out.append((f"{path}:{name}", json.loads(archive.read(name))))
        except (OSError, zipfile.BadZipFile, ValueError):
            continue
    return out


def check_folder(folder: Path) -> int:
    """Assert every Lottie document under ``folder`` is valid; returns how many were checked."""
    documents = lottie_documents(folder)
    for where, document in documents:
        errors = schema_errors(document)
        assert not errors, f"{where} is not valid Lottie: " + "; ".join(errors[:5])
    return len(documents)
