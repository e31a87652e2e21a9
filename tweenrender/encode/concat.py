"""Join video parts rendered separately (``--frames`` chunks) into one file, without re-encoding."""

from __future__ import annotations

import subprocess
import tempfile
from pathlib import Path
from typing import Sequence

from ..errors import EncodeError, OptionError
from .atomic import commit_file, discard, prepare_folder, sibling
from .lifeline import death_signal_setup

__all__ = ["concat", "CONCAT_FORMATS"]

CONCAT_FORMATS = ("mp4", "webm")
"""Containers whose parts join by stream copy (every part starts on a key frame)."""


def _listed(path: Path) -> str:
    """One line of ffmpeg's concat list; a quote in the path is closed, escaped and reopened."""
    text = str(path.resolve()).replace("'", "'\\''")
    return f"file '{text}'\n"


def concat(parts: Sequence[Path | str], target: Path | str, expected: int | None = None) -> Path:
    """Join ``parts`` (same codec, size and rate, in order) into ``target`` with ffmpeg's concat demuxer.

    Streams are copied (``-c copy``): no re-encode, so it takes about as long as
    copying the files. ``expected`` is the total frame count to check, if known.
    The target changes only if the joined file was written and reads back.
    """
    import imageio_ffmpeg

    from .sinks import probe_video

    target = Path(target)
    paths = [Path(p) for p in parts]
    fmt = target.suffix.lower().lstrip(".")
    if fmt not in CONCAT_FORMATS:
        raise OptionError(f"{target}: can join {' or '.join(CONCAT_FORMATS)} parts only, not .{fmt}")
    if not paths:
        raise OptionError(f"{target}: no parts to join")
    for path in paths:
        if not path.is_file():
            raise OptionError(f"{path}: part to join does not exist")
    prepare_folder(target)
    temporary = sibling(target, "." + fmt)
    with tempfile.NamedTemporaryFile("w", suffix=".txt", delete=False) as listing:
        listing.writelines(_listed(p) for p in paths)
    faststart = ["-movflags", "+faststart"] if fmt == "mp4" else []
    command = [imageio_ffmpeg.get_ffmpeg_exe(), "-y", "-hide_banner", "-loglevel", "error", "-nostdin",
               "-f", "concat", "-safe", "0", "-i", listing.name, "-map", "0:v", "-c", "copy", *faststart,
               "-f", fmt, str(temporary)]
    try:
        done = subprocess.run(command, capture_output=True, text=True, preexec_fn=death_signal_setup())
        if done.returncode != 0:
            said = " | ".join(line for line in done.stderr.strip().splitlines()[-4:] if line.strip())
            raise EncodeError(f"{target}: ffmpeg could not join {len(paths)} parts: {said or 'no message'}")
        try:
            frames, _ = probe_video(temporary)
        except Exception as error:  # a file ffmpeg cannot read back is not an output
            raise EncodeError(f"{target}: the joined video cannot be read back ({error})") from None
        if expected is not None and frames != expected:
            raise EncodeError(f"{target}: the joined video has {frames} frames, expected {expected}")
        commit_file(temporary, target)
    except BaseException:
        discard(temporary)
        raise
    finally:
        Path(listing.name).unlink(missing_ok=True)
    return target
