"""Frame sinks. Each writes to a temporary sibling of its target, checks the result,
and only then moves it into place; ``abort`` removes the temporary and leaves any
earlier output untouched."""

from __future__ import annotations

import subprocess
import tempfile
from pathlib import Path
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..errors import EncodeError, UsageError
from .atomic import commit_file, commit_folder, discard, prepare_folder, sibling

__all__ = ["FORMATS", "Sink", "open_sink", "PngSequence", "FFmpegVideo", "probe_video"]

FORMATS = ("mp4", "webm", "gif", "png")

# Output options per container: H.264 and VP9 in yuv420p (what every player plays).
_CODECS: dict[str, list[str]] = {
    "mp4": ["-c:v", "libx264", "-preset", "medium", "-crf", "18", "-pix_fmt", "yuv420p",
            "-movflags", "+faststart", "-f", "mp4"],
    "webm": ["-c:v", "libvpx-vp9", "-b:v", "0", "-crf", "32", "-pix_fmt", "yuv420p",
             "-deadline", "good", "-cpu-used", "4", "-row-mt", "1", "-f", "webm"],
    "gif": ["-filter_complex", "split[a][b];[a]palettegen=stats_mode=diff[p];[b][p]paletteuse=dither=sierra2_4a",
            "-loop", "0", "-f", "gif"],
}


class Sink(Protocol):
    target: Path

    def write(self, rgba: NDArray[np.uint8]) -> None:
        """Take one straight-RGBA frame ``(height, width, 4)``."""

    def close(self) -> Path:
        """Finish, check, and move the output into place; returns the target."""

    def abort(self) -> None:
        """Drop everything written so far; the target is left as it was."""


def open_sink(fmt: str, target: Path, width: int, height: int, fps: float, frames: int) -> Sink:
    """A sink for ``frames`` frames of ``width × height`` at ``fps`` into ``target``."""
    if fmt not in FORMATS:
        raise UsageError(f"unknown format {fmt!r}; expected one of {', '.join(FORMATS)}")
    if fmt in ("mp4", "webm") and (width % 2 or height % 2):
        raise UsageError(f"{fmt} video in yuv420p needs an even width and height, found {width}x{height}")
    prepare_folder(target)
    if fmt == "png":
        return PngSequence(target, frames)
    return FFmpegVideo(fmt, target, width, height, fps, frames)


class PngSequence:
    """A folder of ``frame_0000.png …`` built beside ``target`` and swapped in when complete."""

    def __init__(self, target: Path, frames: int) -> None:
        self.target = target
        self.expected = frames
        self.temporary = sibling(target)
        self.temporary.mkdir()
        self.count = 0
        self.digits = max(4, len(str(max(frames - 1, 0))))

    def write(self, rgba: NDArray[np.uint8]) -> None:
        import imageio.v3 as iio

        name = self.temporary / f"frame_{self.count:0{self.digits}d}.png"
        try:
            iio.imwrite(name, rgba, extension=".png")
        except OSError as error:
            raise EncodeError(f"{self.target}: cannot write {name.name} ({error.strerror or error})") from None
        self.count += 1

    def close(self) -> Path:
        if self.count != self.expected:
            self.abort()
            raise EncodeError(f"{self.target}: wrote {self.count} frames, expected {self.expected}")
        commit_folder(self.temporary, self.target)
        return self.target

    def abort(self) -> None:
        discard(self.temporary)


class FFmpegVideo:
    """Raw RGBA frames piped into the ffmpeg bundled with imageio-ffmpeg."""

    def __init__(self, fmt: str, target: Path, width: int, height: int, fps: float, frames: int) -> None:
        import imageio_ffmpeg

        self.fmt, self.target = fmt, target
        self.width, self.height, self.fps, self.expected = width, height, fps, frames
        self.temporary = sibling(target, "." + fmt)
        self.log = tempfile.TemporaryFile()
        command = [
            imageio_ffmpeg.get_ffmpeg_exe(), "-y", "-hide_banner", "-loglevel", "error", "-nostdin",
            "-f", "rawvideo", "-pix_fmt", "rgba", "-s", f"{width}x{height}", "-framerate", f"{fps:g}",
            "-i", "pipe:0", "-an", *_CODECS[fmt], str(self.temporary),
        ]
        self.process = subprocess.Popen(command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                        stderr=self.log)
        self.count = 0

    def _ffmpeg_said(self) -> str:
        self.log.seek(0)
        text = self.log.read().decode("utf-8", "replace").strip()
        lines = [line for line in text.splitlines() if line.strip()]
        return " | ".join(lines[-4:]) if lines else "no message"

    def write(self, rgba: NDArray[np.uint8]) -> None:
        assert self.process.stdin is not None
        try:
            self.process.stdin.write(memoryview(np.ascontiguousarray(rgba)).cast("B"))
        except (BrokenPipeError, OSError):
            self.process.wait()
            message = self._ffmpeg_said()
            self.abort()
            raise EncodeError(f"{self.target}: ffmpeg stopped after {self.count} frames: {message}") from None
        self.count += 1

    def close(self) -> Path:
        assert self.process.stdin is not None
        try:
            self.process.stdin.close()
        except OSError:
            pass
        code = self.process.wait()
        if code != 0:
            message = self._ffmpeg_said()
            self.abort()
            raise EncodeError(f"{self.target}: ffmpeg failed (exit {code}): {message}")
        try:
            frames, size = probe_video(self.temporary)
        except Exception as error:  # a file ffmpeg cannot read back is not an output
            self.abort()
            raise EncodeError(f"{self.target}: the written video cannot be read back ({error})") from None
        if frames != self.expected or size != (self.width, self.height):
            self.abort()
            raise EncodeError(f"{self.target}: the written video has {frames} frames of {size[0]}x{size[1]}, "
                              f"expected {self.expected} of {self.width}x{self.height}")
        commit_file(self.temporary, self.target)
        self.log.close()
        return self.target

    def abort(self) -> None:
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()
        discard(self.temporary)
        self.log.close()


def probe_video(path: Path) -> tuple[int, tuple[int, int]]:
    """Decoded frame count and ``(width, height)`` of a video file."""
    import imageio_ffmpeg

    reader = imageio_ffmpeg.read_frames(str(path))
    try:
        meta = reader.__next__()
    finally:
        reader.close()
    frames, _ = imageio_ffmpeg.count_frames_and_secs(str(path))
    return int(frames), tuple(int(v) for v in meta["size"])  # type: ignore[return-value]
