"""Sinks: where frames go (PNG sequence, ffmpeg video, GIF), each written atomically."""

from .concat import concat
from .sinks import FORMATS, Sink, open_sink

__all__ = ["FORMATS", "Sink", "open_sink", "concat"]
