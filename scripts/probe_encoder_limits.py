"""Measure the frame sizes the bundled ffmpeg takes, to check ``tweenrender/encode/formats.py``.

    python scripts/probe_encoder_limits.py           # the cheap probes (thin frames), seconds
    python scripts/probe_encoder_limits.py --large   # also ffmpeg's picture check, 1 GiB a frame

Each probe pipes one black frame of raw RGBA into the bundled ffmpeg: through the
real encoder for thin frames, through ffmpeg's picture check alone (``-f null``,
no encoding) for the large ones. It prints what ffmpeg did beside what
``check_frame_size`` says, and exits 1 if they disagree.
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
from pathlib import Path

import imageio_ffmpeg

from tweenrender.encode.formats import formats_for
from tweenrender.encode.sinks import ffmpeg_command

THIN = [("mp4", 16384, 2), ("mp4", 16386, 2), ("mp4", 2, 16384), ("mp4", 2, 16386), ("webm", 16384, 2),
        ("webm", 16386, 2), ("webm", 65536, 2), ("gif", 65534, 2), ("gif", 65536, 2), ("mp4", 321, 240),
        ("webm", 320, 241), ("gif", 321, 241)]
LARGE = [("mp4", 16384, 16128), ("mp4", 16384, 16130), ("mp4", 16128, 16384), ("mp4", 16130, 16384),
         ("mp4", 16254, 16254), ("mp4", 16256, 16256), ("mp4", 16382, 16130)]


def taken(fmt: str, width: int, height: int, encode: bool) -> bool:
    folder = tempfile.TemporaryDirectory(prefix="probe-")
    if encode:
        command = ffmpeg_command(fmt, width, height, 24, "pipe:0", str(Path(folder.name) / f"probe.{fmt}"))
    else:  # ffmpeg's picture check on the input, no encoder
        command = [imageio_ffmpeg.get_ffmpeg_exe(), "-hide_banner", "-loglevel", "error", "-f", "rawvideo",
                   "-pix_fmt", "rgba", "-s", f"{width}x{height}", "-i", "pipe:0", "-c:v", "rawvideo", "-f", "null", "-"]
    with folder:
        done = subprocess.run(command, input=bytes(width * height * 4), capture_output=True)
    return done.returncode == 0


def main(argv: list[str]) -> int:
    cases = [(c, True) for c in THIN] + ([(c, False) for c in LARGE] if "--large" in argv else [])
    wrong = 0
    for (fmt, width, height), encode in cases:
        measured = taken(fmt, width, height, encode)
        predicted = fmt in formats_for(width, height)
        wrong += measured != predicted
        print(f"{fmt:5} {width:>6}x{height:<6} {'encoder' if encode else 'picture check':13} "
              f"ffmpeg {'takes' if measured else 'refuses':8} formats.py {'takes' if predicted else 'refuses':8}"
              f"{'' if measured == predicted else '  DISAGREE'}", flush=True)
    print(f"{len(cases) - wrong} of {len(cases)} agree")
    return 1 if wrong else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
