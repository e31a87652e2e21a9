"""Sinks: where frames go (PNG sequence, ffmpeg video, GIF), each written atomically; every format in
one table (:mod:`.formats`)."""

from .concat import concat
from .formats import FORMATS
from .sinks import Sink, open_sink

__all__ = ["FORMATS", "Sink", "open_sink", "concat"]
