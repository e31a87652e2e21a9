"""Values remembered by key: the last few asked for, the least recently asked dropped first."""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Callable
from typing import Generic, TypeVar

__all__ = ["Remembered"]

V = TypeVar("V")


class Remembered(Generic[V]):
    """At most ``most`` values (and, with ``size``, at most ``most_bytes`` of them in all), by key."""

    def __init__(self, most: int, size: Callable[[V], int] | None = None, most_bytes: int = 0) -> None:
        self._values: OrderedDict[bytes, V] = OrderedDict()
        self._most, self._size, self._most_bytes = most, size, most_bytes

    def get(self, key: bytes, compute: Callable[[], V]) -> V:
        """The value remembered for ``key``, else ``compute()``, remembered."""
        found = self._values.get(key)
        if found is not None:
            self._values.move_to_end(key)
            return found
        value = compute()
        self._values[key] = value
        while len(self._values) > self._most or (
                self._size is not None and len(self._values) > 1
                and sum(self._size(v) for v in self._values.values()) > self._most_bytes):
            self._values.popitem(last=False)
        return value

    def known(self, key: bytes) -> V | None:
        """The value remembered for ``key``, or None (nothing computed)."""
        found = self._values.get(key)
        if found is not None:
            self._values.move_to_end(key)
        return found

    def clear(self) -> None:
        """Forget every value."""
        self._values.clear()
