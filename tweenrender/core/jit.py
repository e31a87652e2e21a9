"""How the package compiles its numba kernels: one decorator, with an on-disk cache where one can be written."""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from numba import njit

__all__ = ["cached_jit"]


def cached_jit(func: Callable[..., Any]) -> Callable[..., Any]:
    """``func`` compiled lazily with an on-disk cache; without the cache where no cache folder is usable.

    numba caches next to the kernel's module (``__pycache__``) or, when that is
    read-only, in the user's cache folder (``NUMBA_CACHE_DIR`` overrides both).
    When neither can be written numba refuses ``cache=True`` at decoration time:
    compiling on every run is slower but still correct. ``error_model="numpy"``
    lets a division by zero give ``inf`` instead of raising; ``nogil`` lets other
    threads run while a kernel does.
    """
    try:
        return njit(cache=True, nogil=True, error_model="numpy")(func)
    except RuntimeError:
        return njit(cache=False, nogil=True, error_model="numpy")(func)
