"""Opaque BGRA or RGBA frames as planar YUV 4:2:0 (BT.601, limited range), ready for ffmpeg's ``yuv420p``.

An H.264 or VP9 encoder takes yuv420p; handing ffmpeg raw RGB makes it hold 4
bytes a pixel in every frame queued between the pipe and its RGB → YUV
conversion. Converting here sends 1.5 bytes a pixel and leaves ffmpeg no
conversion to do (docs/performance.md, "Memory").

The result is what ffmpeg's default conversion (swscale) makes of the same
frame, BT.601 in "tv" range (16–235 for Y, 16–240 for U and V):

- ``Y = 16 + (65.481 R + 128.553 G + 24.966 B) / 255`` of every pixel;
- ``U = 128 + (-37.797 R - 74.203 G + 112 B) / 255`` and
  ``V = 128 + (112 R - 93.786 G - 18.214 B) / 255`` of the colour of each 2 × 2 block
  filtered as swscale does: the mean of each pair of pixels across, then, down the
  columns, its bicubic filter (Keys, a = -0.6) halving the rows, centred between a
  block's two rows: 8 rows weighted ``(-1, -3, 8, 28, 28, 8, -3, -1) / 64``
  (the edge rows repeated beyond the picture);

each rounded to the nearest level and kept within 0–255. (A plain 2 × 2 mean looks
the same but makes x264 spend up to 1.3 % more or less on the same frames.)

Only the red, green and blue bytes are read: the premultiplied pixels of an
opaque picture are its straight ones. The work is done in bands of rows that
stay in the processor's cache, in buffers allocated once: about 7 ms a 1080p
frame (benchmarks/bench_render.py, ``--only memory``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["Yuv420", "yuv420_bytes", "PIXEL_ORDERS", "CHROMA_TAPS"]

PIXEL_ORDERS = ("bgra", "rgba")
CHROMA_TAPS = (-1, -3, 8, 28, 28, 8, -3, -1)
"""The vertical chroma filter, in 64ths: rows 2i - 3 … 2i + 4 make chroma row i."""

_BAND = 72  # rows converted at a time (even): about 0.5 MiB of 32-bit buffers at 1920 wide
_HALO = 3  # rows the chroma filter reads beyond a band, on each side
_Y_SHIFT = 24  # Y in the top byte of a 32-bit sum: white's, (235 + 0.5) · 2 ** 24, stays under 2 ** 32
_Y_RED, _Y_BLUE = (np.uint32(round(w / 255 * (1 << _Y_SHIFT))) for w in (65.481, 24.966))
_Y_GREEN = np.uint32(round(128.553 / 255 * (1 << (_Y_SHIFT - 8))))  # for green kept 8 bits up
_Y_OFFSET = np.uint32((16 << _Y_SHIFT) + (1 << (_Y_SHIFT - 1)))  # 16 levels and the rounding
# Chroma sums are of pixel pairs (up to 510 a 16-bit lane) through the filter (in 64ths): the positive taps
# (72 in all) bring a lane to at most 36 720, the negative ones (8) take at most 4 080 from it. Adding
# that first keeps every lane at 0 … 40 800; it cancels in red − green and blue − green.
_TAP_BIAS = 8 * 510
_FRACTION = 16  # fractional bits of the chroma weights
_SHIFT = _FRACTION + 7  # ... which weigh the filtered pair sums: 2 · 64 times the colour
_FOOT = 16  # levels added before rounding, so that the filter's undershoot (down to -12) stays positive
_CHROMA_OFFSET = np.uint32(((128 + _FOOT) << _SHIFT) + (1 << (_SHIFT - 1)))


def _chroma_weights(red: float, blue: float) -> tuple[np.uint32, np.uint32]:
    """The weights of (red − green) and (blue − green) in a chroma row ``(red, -(red + blue), blue) / 255``
    (its terms sum to 0: every grey has chroma 128), scaled by 2 ** 16 and wrapped to unsigned 32 bits
    (modular arithmetic keeps negative ones exact)."""
    red_weight, blue_weight = (round(w / 255 * (1 << _FRACTION)) % (1 << 32) for w in (red, blue))
    return np.uint32(red_weight), np.uint32(blue_weight)


_U = _chroma_weights(-37.797, 112.0)  # green -74.203
_V = _chroma_weights(112.0, -18.214)  # green -93.786


def yuv420_bytes(width: int, height: int) -> int:
    """Bytes of one ``width × height`` yuv420p frame (even sides): Y, then U and V at half size."""
    return width * height * 3 // 2


class Yuv420:
    """Converts opaque ``(height, width, 4)`` frames in ``order`` (:data:`PIXEL_ORDERS`) into one reused
    yuv420p buffer ``(height * width * 3 // 2,)``: the Y plane, then U, then V. Width and height must be even."""

    def __init__(self, width: int, height: int, order: str = "bgra") -> None:
        if width <= 0 or height <= 0 or width % 2 or height % 2:
            raise ValueError(f"yuv420p needs an even width and height, not {width}x{height}")
        if order not in PIXEL_ORDERS:
            raise ValueError(f"unknown pixel order {order!r}; expected one of {', '.join(PIXEL_ORDERS)}")
        self.width, self.height, self.order = width, height, order
        self.out = np.empty(yuv420_bytes(width, height), np.uint8)
        area = width * height
        self.y = self.out[:area].reshape(height, width)
        self.u = self.out[area:area + area // 4].reshape(height // 2, width // 2)
        self.v = self.out[area + area // 4:].reshape(height // 2, width // 2)
        band = min(_BAND, height)
        self._full = [np.empty((band + 2 * _HALO, width), np.uint32) for _ in range(3)]
        self._pairs = [np.empty((band + 2 * _HALO, width // 2), np.uint32) for _ in range(2)]
        self._half = [np.empty((band // 2, width // 2), np.uint32) for _ in range(6)]
        # a pixel's bytes 0 and 2: blue and red (bgra) or red and blue (rgba)
        self._low_y, self._high_y = (_Y_BLUE, _Y_RED) if order == "bgra" else (_Y_RED, _Y_BLUE)

    def __call__(self, pixels: NDArray[np.uint8]) -> NDArray[np.uint8]:
        """``pixels (height, width, 4)`` uint8 as yuv420p ``(height * width * 3 // 2,)``, valid until the next call."""
        if pixels.shape != (self.height, self.width, 4) or pixels.dtype != np.uint8:
            raise ValueError(f"expected uint8 ({self.height}, {self.width}, 4), not {pixels.dtype} {pixels.shape}")
        words = np.ascontiguousarray(pixels).view("<u4")[..., 0]  # a pixel a word, its byte 0 lowest
        for top in range(0, self.height, _BAND):
            self._band(words, top, min(_BAND, self.height - top))
        return self.out

    def _band(self, words: NDArray[np.uint32], top: int, rows: int) -> None:
        """Rows ``top … top + rows`` (an even count) of ``words (height, width)``: Y of every pixel, U and V of
        every 2 × 2 block (the filter reading ``_HALO`` rows beyond the band on each side)."""
        first, last = max(top - _HALO, 0), min(top + rows + _HALO, self.height)
        outer, green, luma = (buffer[:last - first] for buffer in self._full)
        np.bitwise_and(words[first:last], 0x00FF00FF, out=outer)  # bytes 0 and 2, 16 bits apart: added in one go
        np.bitwise_and(words[first:last], 0x0000FF00, out=green)  # green, 8 bits up
        pairs = [buffer[:rows + 2 * _HALO] for buffer in self._pairs]
        for full, across in zip((outer, green), pairs):
            _pair_sums(full, across, first - (top - _HALO))
        own = slice(top - first, top - first + rows)
        self._luma(outer[own], green[own], luma[own], top)
        self._chroma(*pairs, top, rows)

    def _luma(self, outer: NDArray[np.uint32], green: NDArray[np.uint32], luma: NDArray[np.uint32], top: int) -> None:
        """Y of rows ``top …`` from their bytes 0 and 2 (``outer``) and green (8 bits up); both are overwritten."""
        np.bitwise_and(outer, 0xFFFF, out=luma)
        np.multiply(luma, self._low_y, out=luma)
        np.right_shift(outer, 16, out=outer)
        np.multiply(outer, self._high_y, out=outer)
        np.add(luma, outer, out=luma)
        np.multiply(green, _Y_GREEN, out=green)
        np.add(luma, green, out=luma)
        np.add(luma, _Y_OFFSET, out=luma)
        np.right_shift(luma, _Y_SHIFT, out=luma)
        np.copyto(self.y[top:top + luma.shape[0]], luma, casting="unsafe")

    def _chroma(self, outer_pairs: NDArray[np.uint32], green_pairs: NDArray[np.uint32], top: int, rows: int) -> None:
        """U and V of rows ``top … top + rows`` from the pair sums of rows ``top - _HALO … top + rows + _HALO``."""
        count = rows // 2
        sums, green_sums, red, blue, chroma, scratch = (buffer[:count] for buffer in self._half)
        _filter_rows(outer_pairs, sums, scratch, _TAP_BIAS | (_TAP_BIAS << 16))
        _filter_rows(green_pairs, green_sums, scratch, _TAP_BIAS << 8)
        np.right_shift(green_sums, 8, out=green_sums)
        low, high = (blue, red) if self.order == "bgra" else (red, blue)
        np.bitwise_and(sums, 0xFFFF, out=low)
        np.right_shift(sums, 16, out=high)
        np.subtract(red, green_sums, out=red)  # wraps where negative, like the weights: the sums stay exact
        np.subtract(blue, green_sums, out=blue)
        half = slice(top // 2, top // 2 + count)
        for plane, (red_weight, blue_weight) in ((self.u, _U), (self.v, _V)):
            np.multiply(red, red_weight, out=chroma)
            np.multiply(blue, blue_weight, out=scratch)
            np.add(chroma, scratch, out=chroma)
            np.add(chroma, _CHROMA_OFFSET, out=chroma)  # (4 … 284 levels) · 2 ** 23 in all: wrapping cancels
            np.right_shift(chroma, _SHIFT, out=chroma)
            np.clip(chroma, _FOOT, 255 + _FOOT, out=chroma)
            np.subtract(chroma, _FOOT, out=chroma)
            np.copyto(plane[half], chroma, casting="unsafe")


def _pair_sums(full: NDArray[np.uint32], out: NDArray[np.uint32], lead: int) -> None:
    """``out (rows, width/2)``: each pair of neighbouring pixels of ``full (n, width)`` added, from row ``lead`` on;
    the rows before ``lead`` and after the last are copies of the nearest one (the picture's edge repeated)."""
    count = full.shape[0]
    np.add(full[:, 0::2], full[:, 1::2], out=out[lead:lead + count])
    out[:lead] = out[lead]
    out[lead + count:] = out[lead + count - 1]


def _filter_rows(pairs: NDArray[np.uint32], out: NDArray[np.uint32], scratch: NDArray[np.uint32], bias: int) -> None:
    """``out (k, w)``: row i is rows 2i … 2i + 7 of ``pairs (2k + 6, w)`` weighted by :data:`CHROMA_TAPS`, plus
    ``bias`` (at least what the negative taps can take, so that no 16-bit lane goes below 0)."""
    count = out.shape[0]

    def rows(offset: int) -> NDArray[np.uint32]:
        return pairs[offset:offset + 2 * count - 1:2]

    taps = CHROMA_TAPS
    np.add(rows(3), rows(4), out=out)
    np.multiply(out, np.uint32(taps[3]), out=out)
    np.add(rows(2), rows(5), out=scratch)
    np.multiply(scratch, np.uint32(taps[2]), out=scratch)
    np.add(out, scratch, out=out)
    np.add(out, np.uint32(bias), out=out)
    np.add(rows(1), rows(6), out=scratch)
    np.multiply(scratch, np.uint32(-taps[1]), out=scratch)
    np.subtract(out, scratch, out=out)
    np.add(rows(0), rows(7), out=scratch)
    np.multiply(scratch, np.uint32(-taps[0]), out=scratch)
    np.subtract(out, scratch, out=out)
