"""Frame sinks. Each writes to a temporary sibling of its target, checks the result,
and only then moves it into place; ``abort`` removes the temporary and leaves any
earlier output untouched."""

from __future__ import annotations

import contextlib
import os
import re
import signal
import subprocess
import sys
import tempfile
import threading
from pathlib import Path
from typing import Protocol

import numpy as np
from numpy.typing import NDArray

from ..errors import EncodeError, OptionError
from .atomic import commit_file, commit_folder, discard, os_reason, prepare_folder, sibling
from .lifeline import run_program, start_program
from .formats import TABLE, check_alpha, check_frame_size, lookup, reader, tuning, writer
from .manifest import write_manifest
from .targets import check_frames_folder
from .yuv420 import PIXEL_ORDERS, Yuv420

__all__ = ["PIXEL_FORMATS", "Sink", "open_sink", "PngSequence", "frames_folder", "FFmpegVideo", "probe_video",
           "read_back", "find_ffmpeg_early", "ffmpeg_search_done", "ffmpeg_command", "ffmpeg_exe", "encoder_options",
           "x264_tuning", "png_bytes", "sends_yuv420", "YUV420_TAGS"]

PIXEL_FORMATS = ("rgba", "bgra", "rgb24")
"""Layouts a video sink takes (ffmpeg's names): bgra is skia's own surface layout. ffmpeg is also given
yuv420p, the planes :mod:`.yuv420` makes of opaque rgba or bgra frames (see :func:`sends_yuv420`)."""

YUV420_TAGS = ["-color_range", "tv", "-colorspace", "smpte170m"]
"""What the planes of :mod:`.yuv420` are (BT.601 limited range), given with them to ffmpeg, which writes it into
the file: a player then decodes them with that matrix whatever the frame size (an untagged HD video is read
as BT.709 by many)."""

# A pipe holds 64 KiB by default: each 8 MB frame then trickles through in 128
# wake-ups. 1 MiB (Linux's limit for an unprivileged process) lets ffmpeg
# read in larger gulps; elsewhere the default stays.
_PIPE_BYTES = 1 << 20

class Sink(Protocol):
    target: Path

    def write(self, rgba: NDArray[np.uint8]) -> None:
        """Take one straight-RGBA frame ``(height, width, 4)``."""

    def close(self) -> Path:
        """Finish, check, and move the output into place; returns the target."""

    def abort(self) -> None:
        """Drop everything written so far; the target is left as it was."""


def open_sink(fmt: str, target: Path, width: int, height: int, fps: float, frames: int,
              pixel_format: str = "rgba", alpha: bool = False, draft: bool = False) -> Sink:
    """A sink for ``frames`` frames of ``width × height`` at ``fps`` into ``target``.

    ``pixel_format`` is the layout of the arrays given to ``write`` (video
    sinks; PNG frames are always straight RGBA). ``alpha`` keeps transparency
    (formats that can, :attr:`.formats.Format.keeps_alpha`); ``draft`` encodes with the encoder's
    quickest settings (:attr:`.formats.Format.draft`). The sink is the format's :attr:`~.formats.Format.writer`.
    """
    if fmt not in TABLE:
        lookup(fmt)  # refused, naming the formats there are
    if TABLE[fmt].vector:
        raise OptionError(f"a {fmt} file holds the animated paths, not frames: no sink takes them", "format")
    check_alpha(fmt, alpha)
    check_frame_size(fmt, width, height)
    if TABLE[fmt].folder:
        check_frames_folder(target)
    prepare_folder(target)
    sink: Sink = writer(fmt)(fmt, target, width, height, fps, frames, pixel_format, alpha, draft)
    return sink


_FOUND: list[str] = []  # the ffmpeg found, once a process
_FINDING = threading.Lock()
_EARLY: list[threading.Thread] = []  # the search find_ffmpeg_early began


def ffmpeg_exe() -> str:
    """The path of the ffmpeg bundled with imageio-ffmpeg (found, and checked by running it, once a process;
    a search :func:`find_ffmpeg_early` began is waited for, its thread ended)."""
    ffmpeg_search_done()
    with _FINDING:
        if not _FOUND:
            import imageio_ffmpeg

            try:
                _FOUND.append(imageio_ffmpeg.get_ffmpeg_exe())
            except RuntimeError:
                _why_ffmpeg_cannot_start()
                # it starts now: the search failed while file descriptors or memory were short for a moment
                # (another thread held them), so search again, once
                try:
                    _FOUND.append(imageio_ffmpeg.get_ffmpeg_exe())
                except RuntimeError:
                    _short_of_descriptors()
                    raise
        return _FOUND[0]


def _short_of_descriptors() -> None:
    """Raise ``OSError(EMFILE)`` where this process's limit of open files (``ulimit -n``) leaves no room to
    start a program (its standard streams and the pipe that reports its start): imageio-ffmpeg calls an
    ffmpeg it could not start that way "not found"."""
    import errno
    import resource

    limit = resource.getrlimit(resource.RLIMIT_NOFILE)[0]
    if limit == resource.RLIM_INFINITY:
        return
    try:
        used = len(os.listdir("/proc/self/fd")) - 1  # the listing holds one itself
    except OSError as error:
        if error.errno in (errno.EMFILE, errno.ENFILE):
            raise
        return
    if used + 4 > limit:
        raise OSError(errno.EMFILE, f"too many open files to start ffmpeg ({used} open, at most {limit})")


def _why_ffmpeg_cannot_start() -> None:
    """imageio-ffmpeg calls any ffmpeg it could not run "not found"; one it could not start for want of
    file descriptors or memory raises that ``OSError`` (or :class:`MemoryError`) here instead."""
    import errno

    try:  # where imageio-ffmpeg keeps the one it bundles (its own, unpublished names)
        from imageio_ffmpeg._definitions import FNAME_PER_PLATFORM, get_platform
        from imageio_ffmpeg._utils import _get_bin_dir

        bundled = Path(_get_bin_dir()) / FNAME_PER_PLATFORM.get(get_platform(), "ffmpeg")
    except (ImportError, AttributeError):
        return
    try:
        subprocess.run([str(bundled), "-version"], stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, timeout=30, check=False)
    except OSError as error:
        if error.errno in (errno.ENOMEM, errno.EAGAIN):
            raise MemoryError("ffmpeg could not start: out of memory") from error
        if error.errno in (errno.EMFILE, errno.ENFILE):
            raise
    except subprocess.SubprocessError:
        pass


def find_ffmpeg_early() -> None:
    """Look for ffmpeg on a thread of its own while this one goes on: imageio-ffmpeg checks the one it
    finds by running it (about 20 ms before an encoder could start otherwise). A failure is left for
    :func:`ffmpeg_exe` to report where it is needed."""
    def find() -> None:
        with contextlib.suppress(Exception):
            ffmpeg_exe()

    if not _EARLY and not _FOUND:
        _EARLY.append(threading.Thread(target=find, name="find-ffmpeg", daemon=True))
        _EARLY[0].start()


def ffmpeg_search_done() -> None:
    """Wait for the search :func:`find_ffmpeg_early` began (and the ffmpeg it runs to check) to end: a
    command that stops early, on bad input or a signal, leaves no child process behind."""
    for early in _EARLY:
        if early is not threading.current_thread():
            early.join()


def x264_tuning(width: int, height: int, cpus: int | None = None) -> list[str]:
    """x264's threads and lookahead for ``width × height`` frames on this machine (``cpus`` cores).

    x264's defaults (1.5 frame threads per core, 40 frames of lookahead, a
    lookahead thread buffering more) hold about 575 MiB at 1080p and 1.6 GiB at
    4K. One thread per core and 10 frames of lookahead (5 above 1080p) encode
    as fast for a file within 0.3 %, in about 330 MiB at 1080p
    (benchmarks/bench_render.py measures both).
    """
    if cpus is None:
        cpus = len(os.sched_getaffinity(0)) if hasattr(os, "sched_getaffinity") else (os.cpu_count() or 1)
    lookahead = 10 if width * height <= 2_100_000 else 5
    return ["-threads", str(max(1, min(cpus, 16))), "-x264-params", f"rc-lookahead={lookahead}:sync-lookahead=0"]


def encoder_options(fmt: str, width: int = 0, height: int = 0, alpha: bool = False,
                    draft: bool = False) -> list[str]:
    """ffmpeg's output options (codec, pixel format, container) for ``fmt`` frames of ``width × height``,
    with the format's :attr:`~.formats.Format.tuning` for that size after the encoder's name; with
    ``alpha``, those that keep transparency; with ``draft``, the encoder's quickest settings."""
    codec = TABLE[fmt].options(alpha, draft)
    tune = tuning(fmt)
    if tune is not None and width and height:
        after = codec.index("-c:v") + 2
        return [*codec[:after], *tune(width, height), *codec[after:]]
    return codec


def sends_yuv420(fmt: str, width: int, height: int, alpha: bool = False) -> bool:
    """Whether a video sink converts opaque ``width × height`` frames for ``fmt`` to yuv420p itself (:mod:`.yuv420`)
    rather than send RGB: MP4 and WebM without transparency, at even sizes (their encoders take yuv420p
    anyway: :attr:`.formats.Format.yuv420`). ffmpeg then holds 1.5 bytes a pixel in each frame it queues instead of 4, and converts nothing."""
    return TABLE[fmt].yuv420 and not alpha and width % 2 == 0 and height % 2 == 0


def ffmpeg_command(fmt: str, width: int, height: int, fps: float, source: str, output: str,
                   pixel_format: str = "rgba", alpha: bool = False, draft: bool = False) -> list[str]:
    """The bundled ffmpeg's command line that encodes raw ``pixel_format`` frames from ``source`` as ``fmt``."""
    if pixel_format not in (*PIXEL_FORMATS, "yuv420p"):
        raise OptionError(f"unknown pixel format {pixel_format!r}; expected one of {', '.join(PIXEL_FORMATS)} "
                          "or yuv420p")
    tags = YUV420_TAGS if pixel_format == "yuv420p" else []
    return [ffmpeg_exe(), "-y", "-hide_banner", "-loglevel", "error", "-nostdin",
            "-f", "rawvideo", "-pix_fmt", pixel_format, "-s", f"{width}x{height}", "-framerate", f"{fps:g}", *tags,
            "-i", source, "-an", *encoder_options(fmt, width, height, alpha, draft), output]


def png_bytes(rgba: NDArray[np.uint8]) -> bytes:
    """One straight-RGBA frame ``(height, width, 4)`` as the bytes of a PNG file.

    Compressing a 1080p frame costs several times drawing it, and the encoder
    holds the GIL, so parallel PNG renders do this in the drawing processes.
    """
    import imageio.v3 as iio

    return iio.imwrite("<bytes>", rgba, extension=".png")


def frames_folder(fmt: str, target: Path, width: int, height: int, fps: float, frames: int,
                  pixel_format: str = "rgba", alpha: bool = False, draft: bool = False) -> PngSequence:
    """The sink :func:`open_sink` makes for a folder of frames (:attr:`.formats.Format.writer`): ``frames``
    PNG files of straight RGBA, whatever the size, rate, layout, transparency and draft."""
    return PngSequence(target, frames)


class PngSequence:
    """A folder of ``frame_0000.png …`` built beside ``target`` and swapped in when complete."""

    def __init__(self, target: Path, frames: int) -> None:
        self.target = target
        self.expected = frames
        self.temporary = sibling(target)
        try:
            self.temporary.mkdir()
        except OSError as error:
            raise EncodeError(f"{target}: cannot create the frames folder ({os_reason(error)})") from None
        self.count = 0
        self.digits = max(4, len(str(max(frames - 1, 0))))

    def write(self, rgba: NDArray[np.uint8]) -> None:
        """Take one straight-RGBA frame ``(height, width, 4)``."""
        self.write_encoded(png_bytes(rgba))

    def write_encoded(self, data: bytes) -> None:
        """Take one frame already encoded by :func:`png_bytes` (e.g. in the process that drew it)."""
        name = self.temporary / f"frame_{self.count:0{self.digits}d}.png"
        try:
            name.write_bytes(data)
        except OSError as error:
            self.abort()
            raise EncodeError(f"{self.target}: cannot write {name.name} ({os_reason(error)})") from None
        self.count += 1

    def close(self) -> Path:
        if self.count != self.expected:
            self.abort()
            raise EncodeError(f"{self.target}: wrote {self.count} frames, expected {self.expected}")
        try:
            write_manifest(self.temporary)
            check_frames_folder(self.target)  # again: files may have been saved there meanwhile
        except (OptionError, EncodeError):
            self.abort()
            raise
        commit_folder(self.temporary, self.target)
        return self.target

    def abort(self) -> None:
        discard(self.temporary)


class FFmpegVideo:
    """Raw frames piped into the ffmpeg bundled with imageio-ffmpeg.

    ffmpeg is its own process, so it encodes frame n while this one draws
    frame n + 1. ``write`` hands the array's memory to the pipe without a copy,
    or, for an opaque MP4 or WebM (:func:`sends_yuv420`), its yuv420p planes
    converted into one reused buffer.
    """

    def __init__(self, fmt: str, target: Path, width: int, height: int, fps: float, frames: int,
                 pixel_format: str = "rgba", alpha: bool = False, draft: bool = False) -> None:
        self.fmt, self.target = fmt, target
        self.width, self.height, self.fps, self.expected = width, height, fps, frames
        self.pixel_format = pixel_format
        self.channels = 3 if pixel_format == "rgb24" else 4
        self.to_yuv420: Yuv420 | None = None
        if pixel_format in PIXEL_ORDERS and sends_yuv420(fmt, width, height, alpha):
            self.to_yuv420 = Yuv420(width, height, pixel_format)
        self.temporary = sibling(target, "." + fmt)
        sent = pixel_format if self.to_yuv420 is None else "yuv420p"
        command = ffmpeg_command(fmt, width, height, fps, "pipe:0", str(self.temporary), sent, alpha, draft)
        self.log = tempfile.TemporaryFile()
        # unbuffered: Python's 8 KiB buffer would only add a copy of every frame. Its own
        # session: a terminal's Ctrl-C reaches only this process, which then stops ffmpeg
        # itself (abort), instead of racing ffmpeg's own shutdown. It dies with this process.
        self.process = start_program(command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                     stderr=self.log, bufsize=0, start_new_session=True)
        _grow_pipe(self.process.stdin)
        self.count = 0

    def _ffmpeg_said(self) -> str:
        self.log.seek(0)
        text = self.log.read().decode("utf-8", "replace").strip()
        lines = [line for line in text.splitlines() if line.strip()]
        return " | ".join(lines[-4:]) if lines else "no message"

    def write(self, rgba: NDArray[np.uint8]) -> None:
        """Take one frame ``(height, width, channels)`` in this sink's ``pixel_format``."""
        assert self.process.stdin is not None
        if rgba.shape != (self.height, self.width, self.channels) or rgba.dtype != np.uint8:
            self.abort()
            raise EncodeError(f"{self.target}: frame {self.count} is {rgba.dtype} {rgba.shape}, expected uint8 "
                              f"({self.height}, {self.width}, {self.channels}) {self.pixel_format}")
        try:
            data = np.ascontiguousarray(rgba) if self.to_yuv420 is None else self.to_yuv420(rgba)
            view = memoryview(data).cast("B")
            while view:  # an unbuffered pipe may take part of a frame at a time
                written = self.process.stdin.write(view)
                view = view[written:]
        except (BrokenPipeError, OSError):
            code = self.process.wait()
            message = self._ffmpeg_said()
            self.abort()
            raise EncodeError(f"{self.target}: ffmpeg {_ended(code)} after {self.count} frames: {message}") from None
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
            raise EncodeError(f"{self.target}: ffmpeg {_ended(code)}: {message}")
        try:
            frames, size = read_back(self.temporary, self.fmt)
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


def _ended(code: int) -> str:
    """How ffmpeg ended, from its exit status: "failed (exit 1)", or the signal that stopped it
    ("stopped by SIGXFSZ (File size limit exceeded)": ``ulimit -f``; SIGKILL: often out of memory)."""
    if code >= 0:
        return f"failed (exit {code})"
    try:
        name = signal.Signals(-code).name
    except ValueError:
        name = f"signal {-code}"
    return f"stopped by {name} ({signal.strsignal(-code) or 'no description'})"


def _grow_pipe(pipe: object) -> None:
    """Ask for a larger pipe buffer where the system allows it (Linux); otherwise keep the default."""
    if sys.platform != "linux":
        return
    try:
        import fcntl

        fcntl.fcntl(pipe.fileno(), getattr(fcntl, "F_SETPIPE_SZ", 1031), _PIPE_BYTES)  # type: ignore[attr-defined]
    except (OSError, ValueError, AttributeError):
        pass  # a smaller limit (/proc/sys/fs/pipe-max-size) only costs wake-ups


def read_back(path: Path, fmt: str) -> tuple[int, tuple[int, int]]:
    """Frame count and ``(width, height)`` of a written ``fmt`` video, as the format's
    :attr:`~.formats.Format.reader` reads them: from the file's own structure, or by :func:`probe_video`."""
    read = reader(fmt)
    if read is None:
        raise ValueError(f"a written {fmt} output is not read back")
    return read(path)


def probe_video(path: Path) -> tuple[int, tuple[int, int]]:
    """Frame count and ``(width, height)`` of a video file.

    One ffmpeg run that copies the stream to nowhere (no decoding): the input's
    stream line gives the size, the final progress line the frame count.
    """
    done = run_program([ffmpeg_exe(), "-hide_banner", "-nostdin", "-i", str(path),
                        "-map", "0:v:0", "-c", "copy", "-f", "null", "-"], text=True, errors="replace")
    said = done.stderr
    stream = re.search(r"Stream #0:\d+.*?: Video: [^\n]*?(?<!\w)(\d{1,5})x(\d{1,5})(?!\w)", said)
    counts = re.findall(r"frame=\s*(\d+)", said)
    if done.returncode != 0 or stream is None or not counts:
        lines = [line for line in said.strip().splitlines() if line.strip()]
        raise ValueError(lines[-1] if lines else f"ffmpeg exit {done.returncode}")
    return int(counts[-1]), (int(stream.group(1)), int(stream.group(2)))
