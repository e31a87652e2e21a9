"""The perimeter ratio of a whole scene over its clip, for metric strips and storyboards.

At a time ``time``, each moving shape (one with at least two keys) contributes
its inbetween perimeter ``P(time)`` and the mean ``(P(K0) + P(K1)) / 2`` of the
two keys of the segment it is in (its first or last segment outside its keys).
The scene's ratio is ``Σ P(time) / Σ mean``: the thesis's ch. 6 ratio, summed
over the moving shapes so that one number describes a panel. It is 1 at every
key where the keys have equal perimeters, and ``cos(φ/2)`` at mid-turn for a
linear rigid turn by φ.
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from numpy.typing import ArrayLike, NDArray

from .geometry import outline_length
from .timing.timeline import Track

__all__ = ["scene_perimeter_ratio", "segment_midpoints"]

Array = NDArray[np.float64]


def scene_perimeter_ratio(tracks: Sequence[Track], methods: Sequence[str], times: ArrayLike) -> Array:
    """Summed inbetween perimeter over summed segment key means, ``(T,)`` for ``times (T,)`` seconds.

    ``methods`` holds one method per track. Without moving shapes the ratio is 1.
    """
    times = np.atleast_1d(np.asarray(times, dtype=np.float64))
    inbetween = np.zeros(len(times))
    reference = np.zeros(len(times))
    for track, method in zip(tracks, methods):
        if not track.segments:
            continue
        index = track.segment_index(times)
        means = np.array([0.5 * (outline_length([p.k0 for p in s.pairs], [p.closed for p in s.pairs])
                                 + outline_length([p.k1 for p in s.pairs], [p.closed for p in s.pairs]))
                          for s in track.segments])
        inbetween += np.array([outline_length(at.contours, at.closed) for at in track.at(times, method)])
        reference += means[index]
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = inbetween / reference
    return np.where(reference > 0, ratio, 1.0)


def segment_midpoints(tracks: Sequence[Track]) -> Array:
    """The distinct mid-times (seconds) of every segment of every track, sorted: ``(M,)``."""
    mids = {round(0.5 * (s.start + s.end), 9) for track in tracks for s in track.segments}
    return np.array(sorted(mids), dtype=np.float64)
