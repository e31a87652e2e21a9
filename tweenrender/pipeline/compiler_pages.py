"""The compiler's code given back to the system once a process's kernels are running.

numba links each kernel it compiles or loads from its cache with LLVM, whose library
(``libllvmlite.so``) then stays resident, about 66 MiB, although nothing runs it again
until another kernel is linked: a rendering process draws every frame with kernels
already linked. Its read-only mappings are unmodified copies of the file, so asking
Linux to page them out (``madvise(MADV_PAGEOUT)``, Linux 5.4 and later) loses nothing:
a later use reads them back from the file. Measured on the stroked 1080p scene: the
drawing process 208 → 143 MiB (docs/performance.md, "Memory").
"""

from __future__ import annotations

import sys

__all__ = ["page_out_compiler", "compiler_resident_bytes"]

_MADV_PAGEOUT = 21  # <linux/mman.h>
_LIBRARY = "libllvmlite"


def _compiler_mappings() -> list[tuple[int, int]]:
    """``(start, end)`` of every read-only mapping of LLVM's library in this process (none where numba was
    never loaded or elsewhere than on Linux)."""
    if sys.platform != "linux" or "llvmlite.binding" not in sys.modules:
        return []
    found = []
    try:
        with open("/proc/self/maps") as maps:
            for line in maps:
                fields = line.split()
                if len(fields) >= 6 and fields[5].rsplit("/", 1)[-1].startswith(_LIBRARY) and "w" not in fields[1]:
                    start, end = (int(address, 16) for address in fields[0].split("-"))
                    found.append((start, end))
    except OSError:
        return []
    return found


def page_out_compiler() -> int:
    """Ask the system to page out LLVM's read-only code and data in this process; returns the bytes of the
    mappings it accepted (0 where numba is not loaded, the system is not Linux or refuses the advice)."""
    mappings = _compiler_mappings()
    if not mappings:
        return 0
    import ctypes

    madvise = ctypes.CDLL(None, use_errno=True).madvise
    madvise.argtypes = [ctypes.c_void_p, ctypes.c_size_t, ctypes.c_int]
    madvise.restype = ctypes.c_int
    return sum(end - start for start, end in mappings if madvise(start, end - start, _MADV_PAGEOUT) == 0)


def compiler_resident_bytes(private: bool = False) -> int:
    """Bytes of LLVM's read-only mappings resident in this process (``/proc/self/smaps``; 0 where none); with
    ``private``, only those no other process maps (another process using the library shares its pages, which
    stay resident for it)."""
    starts = {start for start, _ in _compiler_mappings()}
    if not starts:
        return 0
    fields = ("Private_Clean:", "Private_Dirty:") if private else ("Rss:",)
    total, inside = 0, False
    with open("/proc/self/smaps") as smaps:
        for line in smaps:
            head = line.split(maxsplit=1)[0]
            if "-" in head and not head.endswith(":"):
                inside = int(head.split("-")[0], 16) in starts
            elif inside and head in fields:
                total += int(line.split()[1]) * 1024
    return total
