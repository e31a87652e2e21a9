"""What the video encoder costs a frame on this machine, measured rather than assumed.

A few frames of the clip itself are encoded with the package's own settings into a scratch
file; the encoder's CPU time (the operating system's count for the finished child) over
the frames is its cost. Its start-up is in that count, so the figure errs high — towards
one drawing process, which is never slower than the encoder it feeds.
"""

from __future__ import annotations

import os
import resource
import subprocess
from typing import Sequence

import numpy as np
from numpy.typing import NDArray

__all__ = ["encoder_seconds"]


def encoder_seconds(fmt: str, pictures: Sequence[NDArray[np.uint8]], fps: float, alpha: bool = False,
                    draft: bool = False) -> float:
    """CPU seconds ffmpeg spends per frame encoding ``pictures`` (straight RGBA ``(H, W, 4)``, at least
    one) as ``fmt``, the way a render sends them (yuv420p planes for an opaque MP4 or WebM; with ``draft``,
    at the encoder's quickest settings)."""
    from .lifeline import start_program
    from .sinks import ffmpeg_command, sends_yuv420
    from .yuv420 import Yuv420

    height, width = pictures[0].shape[:2]
    planes = Yuv420(width, height, "rgba") if sends_yuv420(fmt, width, height, alpha) else None
    from .scratch import scratch_folder

    with scratch_folder("probe") as folder:
        output = os.path.join(folder, f"probe.{fmt}")
        command = ffmpeg_command(fmt, width, height, fps, "pipe:0", output,
                                 "rgba" if planes is None else "yuv420p", alpha, draft)
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        process = start_program(command, stdin=subprocess.PIPE, stdout=subprocess.DEVNULL,
                                stderr=subprocess.DEVNULL, start_new_session=True)
        assert process.stdin is not None
        try:
            for picture in pictures:
                data = np.ascontiguousarray(picture) if planes is None else planes(picture)
                process.stdin.write(memoryview(data).cast("B"))
            process.stdin.close()
        except OSError:
            pass
        process.wait()
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
    spent = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return spent / len(pictures)
