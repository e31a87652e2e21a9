"""How the package compiles its numba kernels: one decorator, with an on-disk cache where one can be written.

numba loads its array maths on the first call of any kernel, and that module probes for a BLAS by
importing ``scipy.linalg`` (0.2 s on this package's benchmark machine, a third of the first call's
cost). No kernel here calls a BLAS routine (no ``np.dot``, no ``np.linalg``), so the array maths is
loaded once this module is, with ``scipy.linalg`` refused to that probe alone: numba then computes
inner products itself, and would still import ``scipy.linalg`` on its own for a linear algebra
kernel. Where ``scipy.linalg`` is loaded already, nothing is refused.
"""

from __future__ import annotations

import importlib.abc
import importlib.machinery
import sys
import threading
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any

from numba import njit

__all__ = ["cached_jit"]


class _RefuseOnThisThread(importlib.abc.MetaPathFinder):
    """Refuses to find one module, for the thread that installed it only."""

    def __init__(self, name: str) -> None:
        self.name, self.thread = name, threading.get_ident()

    def find_spec(self, fullname: str, path: Sequence[str] | None,
                  target: ModuleType | None = None) -> importlib.machinery.ModuleSpec | None:
        if fullname == self.name and threading.get_ident() == self.thread:
            raise ImportError(f"{fullname} is not needed by numba's array maths here")
        return None


def _load_array_maths() -> None:
    """Import ``numba.np.arraymath`` without its BLAS probe's ``scipy.linalg`` import (see the module's
    docstring); a no-op when either is loaded already."""
    if "numba.np.arraymath" in sys.modules or "scipy.linalg" in sys.modules:
        return
    refuse = _RefuseOnThisThread("scipy.linalg")
    sys.meta_path.insert(0, refuse)
    try:
        import numba.np.arraymath  # noqa: F401
    finally:
        sys.meta_path.remove(refuse)


_load_array_maths()


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
