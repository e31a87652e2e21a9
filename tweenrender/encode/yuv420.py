"""Opaque BGRA or RGBA frames as planar YUV 4:2:0 (BT.601, limited range), ready for ffmpeg's ``yuv420p``.

An H.264 or VP9 encoder takes yuv420p; handing ffmpeg raw RGB makes it hold 4
bytes a pixel in every frame queued between the pipe and its RGB → YUV
conversion. Converting here sends 1.5 bytes a pixel and leaves ffmpeg no
conversion to do (docs/performance.md, "Memory").

The numbers are those of ffmpeg's default conversion (swscale: BT.601, "tv"
range, 16–235 for Y and 16–240 for U and V):

- ``Y = 16 + (65.481 R + 128.553 G + 24.966 B) / 255`` of every pixel,
- ``U = 128 + (-37.797 R - 74.203 G + 112 B) / 255`` and
  ``V = 128 + (112 R - 93.786 G - 18.214 B) / 255`` of each 2 × 2 block's mean colour,

each rounded to the nearest level (integer weights with 16 or more fractional bits).

Only the red, green and blue bytes are read: the premultiplied pixels of an
opaque picture are its straight ones. The work is done in bands of rows that
stay in the processor's cache, in buffers allocated once: about 5 ms a 1080p
frame (benchmarks/bench_render.py, ``--only memory``).
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

__all__ = ["Yuv420", "yuv420_bytes", "PIXEL_ORDERS"]

PIXEL_ORDERS = ("bgra", "rgba")
_BAND = 72  # rows converted at a time (even): about 0.5 MiB of 32-bit buffers at 1920 wide
_Y_SHIFT = 24  # Y in the top byte of a 32-bit sum: white's, (235 + 0.5) · 2 ** 24, stays under 2 ** 32
_Y_RED, _Y_BLUE = (np.uint32(round(w / 255 * (1 << _Y_SHIFT))) for w in (65.481, 24.966))
_Y_GREEN = np.uint32(round(128.553 / 255 * (1 << (_Y_SHIFT - 8))))  # for green kept 8 bits up
_Y_OFFSET = np.uint32((16 << _Y_SHIFT) + (1 << (_Y_SHIFT - 1)))  # 16 levels and the rounding
_FRACTION = 16  # fractional bits of the chroma weights
_SHIFT = _FRACTION + 2  # ... which weigh sums of 4 pixels
_CHROMA_OFFSET = np.uint32((128 << _SHIFT) + (1 << (_SHIFT - 1)))


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
        self._full = [np.empty((band, width), np.uint32) for _ in range(3)]
        self._pairs = np.empty((band // 2, width), np.uint32)
        self._half = [np.empty((band // 2, width // 2), np.uint32) for _ in range(5)]
        # a pixel's bytes 0 and 2: blue and red (bgra) or red and blue (rgba)
        self._low_y, self._high_y = (_Y_BLUE, _Y_RED) if order == "bgra" else (_Y_RED, _Y_BLUE)

    def __call__(self, pixels: NDArray[np.uint8]) -> NDArray[np.uint8]:
        """``pixels (height, width, 4)`` uint8 as yuv420p ``(height * width * 3 // 2,)``, valid until the next call."""
        if pixels.shape != (self.height, self.width, 4) or pixels.dtype != np.uint8:
            raise ValueError(f"expected uint8 ({self.height}, {self.width}, 4), not {pixels.dtype} {pixels.shape}")
        words = np.ascontiguousarray(pixels).view("<u4")[..., 0]  # a pixel a word, its byte 0 lowest
        for top in range(0, self.height, _BAND):
            self._band(words[top:top + _BAND], top)
        return self.out

    def _band(self, words: NDArray[np.uint32], top: int) -> None:
        """Rows ``top …`` (an even count of them): Y of every pixel, U and V of every 2 × 2 block."""
        rows = words.shape[0]
        outer, green, luma = (buffer[:rows] for buffer in self._full)
        pairs = self._pairs[:rows // 2]
        sums, green_sums, red, blue, chroma = (buffer[:rows // 2] for buffer in self._half)
        np.bitwise_and(words, 0x00FF00FF, out=outer)  # bytes 0 and 2, 16 bits apart: summed in one go
        np.bitwise_and(words, 0x0000FF00, out=green)  # green, 8 bits up
        _block_sums(outer, pairs, sums)
        _block_sums(green, pairs, green_sums)
        np.bitwise_and(outer, 0xFFFF, out=luma)
        np.multiply(luma, self._low_y, out=luma)
        np.right_shift(outer, 16, out=outer)
        np.multiply(outer, self._high_y, out=outer)
        np.add(luma, outer, out=luma)
        np.multiply(green, _Y_GREEN, out=green)
        np.add(luma, green, out=luma)
        np.add(luma, _Y_OFFSET, out=luma)
        np.right_shift(luma, _Y_SHIFT, out=luma)
        np.copyto(self.y[top:top + rows], luma, casting="unsafe")
        # U and V from each block's sums: (red − green) and (blue − green), wrapped like the weights
        np.right_shift(green_sums, 8, out=green_sums)
        low, high = (blue, red) if self.order == "bgra" else (red, blue)
        np.bitwise_and(sums, 0xFFFF, out=low)
        np.right_shift(sums, 16, out=high)
        np.subtract(red, green_sums, out=red)
        np.subtract(blue, green_sums, out=blue)
        half = slice(top // 2, top // 2 + rows // 2)
        for plane, (red_weight, blue_weight) in ((self.u, _U), (self.v, _V)):
            np.multiply(red, red_weight, out=chroma)
            np.multiply(blue, blue_weight, out=sums)
            np.add(chroma, sums, out=chroma)
            np.add(chroma, _CHROMA_OFFSET, out=chroma)  # the true total lies in 0 … 2 ** 26: wrapping cancels
            np.right_shift(chroma, _SHIFT, out=chroma)
            np.copyto(plane[half], chroma, casting="unsafe")


def _block_sums(full: NDArray[np.uint32], pairs: NDArray[np.uint32], out: NDArray[np.uint32]) -> None:
    """``out (rows/2, width/2)``: the sum of each 2 × 2 block of ``full (rows, width)``, through ``pairs
    (rows/2, width)`` (rows first: adding whole rows is faster than adding every other pixel)."""
    np.add(full[0::2], full[1::2], out=pairs)
    np.add(pairs[:, 0::2], pairs[:, 1::2], out=out)
