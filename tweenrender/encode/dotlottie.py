"""dotLottie (``.lottie``): the Lottie animation in a ZIP archive (Deflate) with a manifest, as the
dotLottie format (dotlottie.io, version 1) lays it out::

    manifest.json            version, generator, the animations and how each plays (loop, speed, …)
    animations/<id>.json     the Lottie JSON, byte for byte what :mod:`.lottie` writes

The manifest's ``loop`` is the clip's (``--loop``); the animation plays forward at speed 1, on its own.
"""

from __future__ import annotations

import json
import re
import zipfile
from pathlib import Path
from typing import Any

from .atomic import replacing
from .lottie import lottie_text
from .vector_data import VectorClip

__all__ = ["write_dotlottie", "dotlottie_manifest", "animation_id"]


def animation_id(stem: str) -> str:
    """The animation's id (its file's name in ``animations/``, without ``.json``): the target's stem in
    letters, digits, ``-`` and ``_`` (others become ``_``), ``animation`` when nothing is left."""
    cleaned = re.sub(r"[^A-Za-z0-9_-]", "_", stem).strip("_")
    return cleaned or "animation"


def dotlottie_manifest(ident: str, loop: bool) -> dict[str, Any]:
    """The ``manifest.json`` of one animation ``ident`` played forward once (or, ``loop``, over and over)."""
    return {"version": "1.0", "generator": "tweenrender", "author": "tweenrender", "revision": 1,
            "activeAnimationId": ident,
            "animations": [{"id": ident, "speed": 1, "loop": loop, "autoplay": True, "direction": 1,
                            "playMode": "normal"}]}


def write_dotlottie(clip: VectorClip, target: Path) -> Path:
    """Write ``clip`` to ``target`` as a dotLottie archive, atomically; returns ``target``."""
    ident = animation_id(target.stem)
    manifest = json.dumps(dotlottie_manifest(ident, clip.loop), separators=(",", ":"))
    animation = lottie_text(clip, target.stem)
    with replacing(target, ".lottie", "the dotLottie file") as temporary:
        with zipfile.ZipFile(temporary, "w", compression=zipfile.ZIP_DEFLATED, compresslevel=9) as archive:
            archive.writestr("manifest.json", manifest)
            archive.writestr(f"animations/{ident}.json", animation)
    return target
