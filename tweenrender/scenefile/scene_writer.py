"""The scene a command line of drawings means, written as a ``[[drawing]]`` scene file: where editing
starts (``tweenrender init``).

The scene renders exactly as ``render A.svg B.svg.. --step S --ease C --hold S --stagger S`` does: the
same drawings at the same times (``i × (step + hold)`` seconds), the same timing, the scene's defaults
for the rest. File names are written relative to the scene file's folder.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Sequence

__all__ = ["drawings_toml"]


def _string(text: str) -> str:
    """``text`` as a TOML basic string (JSON's escapes are TOML's)."""
    return json.dumps(text, ensure_ascii=False)


def _number(value: float) -> str:
    """A float as TOML reads back the same value."""
    return repr(float(value))


def drawings_toml(drawings: Sequence[Path], folder: Path, step: float = 1.0, ease: str = "linear",
                  hold: float = 0.0, stagger: float = 0.0) -> str:
    """The TOML text of the scene of ``drawings`` (see the module's docstring); ``folder`` is where the
    scene file goes, which its file names are relative to."""
    names = [os.path.relpath(Path(p).absolute(), folder.absolute()) for p in drawings]
    period = float(step) + float(hold)
    lines = [f"# {len(drawings)} drawings, {float(step):g} s apart"
             + (f", each held {float(hold):g} s first" if hold else "") + ": edit from here", ""]
    if ease != "linear":
        lines.append(f"ease = {_string(ease)}")
    if stagger:
        lines.append(f"stagger = {_number(stagger)}")
    if ease != "linear" or stagger:
        lines.append("")
    for i, name in enumerate(names):
        lines += ["[[drawing]]", f"time = {_number(i * period)}", f"svg = {_string(Path(name).as_posix())}"]
        if hold:
            lines.append(f"hold = {_number(hold)}")
        lines.append("")
    return "\n".join(lines)
