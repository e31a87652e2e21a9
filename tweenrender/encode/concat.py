"""Join video parts rendered separately (``--frames`` chunks) into one file: parts by stream copy, or
lossless parts encoded once (a GIF, whose palette must see every frame), as the format's
:attr:`~.formats.Format.join` says."""

from __future__ import annotations

from pathlib import Path
from typing import Sequence

from ..errors import EncodeError, OptionError
from .atomic import commit_file, discard, prepare_folder, sibling
from .formats import FORMATS, LOSSLESS, TABLE, by_suffix
from .lifeline import run_program

__all__ = ["concat", "CONCAT_FORMATS"]

CONCAT_FORMATS = tuple(name for name in FORMATS if TABLE[name].join in ("copy", "lossless"))
"""Targets parts can be joined into (:attr:`.formats.Format.join`): by stream copy (every part starts on a
key frame), or by encoding lossless parts (:data:`.formats.LOSSLESS`) once, exactly as a single render would."""


def _listed(path: Path, seconds: float | None = None) -> str:
    """One entry of ffmpeg's concat list (with its duration, if given); a quote in the path is closed,
    escaped and reopened."""
    text = str(path.resolve()).replace("'", "'\\''")
    return f"file '{text}'\n" + (f"duration {seconds!r}\n" if seconds is not None else "")


def concat(parts: Sequence[Path | str], target: Path | str, expected: int | None = None,
           fmt: str | None = None, rate: float | None = None, alpha: bool = False) -> Path:
    """Join ``parts`` (same codec, size and rate, in order) into ``target`` with ffmpeg's concat demuxer.

    MP4 and WebM streams are copied (``-c copy``): no re-encode, so it takes about as
    long as copying the files. A GIF is encoded from lossless parts with the same
    palette filter as a single render, so it comes out the same, byte for byte.
    ``expected`` is the total frame count to check, if known; ``fmt`` the target's
    format (default: the one its name ends in, :func:`.formats.by_suffix`); ``rate`` the frame rate, which a GIF
    needs (each part lasts exactly its frames, so no frame overlaps the next part's);
    ``alpha`` keeps a GIF's transparency (its parts carry it).
    The target changes only if the joined file was written and reads back.
    """
    from .sinks import encoder_options, ffmpeg_exe, read_back

    target = Path(target)
    paths = [Path(p) for p in parts]
    named = TABLE.get(fmt) if fmt else by_suffix(target.suffix)
    if named is None or named.name not in CONCAT_FORMATS:
        asked = named.name if named is not None else fmt or target.suffix.lower()
        raise OptionError(f"{target}: can join parts into {', '.join(CONCAT_FORMATS)} only, not {asked}")
    fmt = named.name
    if not paths:
        raise OptionError(f"{target}: no parts to join")
    lossless = TABLE[fmt].join == "lossless"
    for path in paths:
        if not path.is_file():
            raise OptionError(f"{path}: part to join does not exist")
        if lossless and path.suffix.lower() != LOSSLESS.suffix:
            raise OptionError(f"{path}: a {TABLE[fmt].codec} is joined from lossless {LOSSLESS.suffix} parts, "
                              f"not {path.suffix or 'this'}")
    prepare_folder(target)
    temporary = sibling(target, "." + fmt)
    seconds: list[float | None] = [None] * len(paths)
    if lossless:
        if rate is None:
            raise OptionError(f"{target}: joining {TABLE[fmt].codec} parts needs the frame rate")
        seconds = [_frames_of(path) / rate for path in paths]
    # the list beside the target, like every temporary: a killed run's is swept by the next one
    listing = sibling(target, ".txt")
    try:
        listing.write_text("".join(_listed(p, s) for p, s in zip(paths, seconds)))
    except OSError as error:
        discard(listing)
        raise EncodeError(f"{target}: cannot write the list of parts beside it ({error.strerror or error})") from None
    if lossless:
        output = encoder_options(fmt, alpha=alpha)
    else:
        output = ["-map", "0:v", "-c", "copy", *TABLE[fmt].container, "-f", str(TABLE[fmt].muxer)]
    command = [ffmpeg_exe(), "-y", "-hide_banner", "-loglevel", "error", "-nostdin",
               "-f", "concat", "-safe", "0", "-i", str(listing), *output, str(temporary)]
    try:
        done = run_program(command, text=True)
        if done.returncode != 0:
            said = " | ".join(line for line in done.stderr.strip().splitlines()[-4:] if line.strip())
            raise EncodeError(f"{target}: ffmpeg could not join {len(paths)} parts: {said or 'no message'}")
        try:
            frames, _ = read_back(temporary, fmt)
        except Exception as error:  # a file ffmpeg cannot read back is not an output
            raise EncodeError(f"{target}: the joined video cannot be read back ({error})") from None
        if expected is not None and frames != expected:
            raise EncodeError(f"{target}: the joined video has {frames} frames, expected {expected}")
        commit_file(temporary, target)
    except BaseException:
        discard(temporary)
        raise
    finally:
        discard(listing)
    return target


def _frames_of(part: Path) -> int:
    from .sinks import probe_video

    try:
        return probe_video(part)[0]
    except ValueError as error:
        raise EncodeError(f"{part}: the part cannot be read ({error})") from None
