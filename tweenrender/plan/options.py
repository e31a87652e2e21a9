"""The render command's options as one frozen, validated object.

:class:`RenderOptions` is what ``tweenrender render`` and :func:`tweenrender.write` share: the
command line fills it from its flags, the library from its keyword arguments, and each value is
checked here, once. A refusal is an :class:`~tweenrender.errors.OptionError` naming the option, so
the library says ``fps=: …`` and the command line ``--fps: …``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, fields, replace
from numbers import Integral, Real
from typing import Any, Callable, Sequence

from ..core.methods.registry import METHODS, unknown_method
from ..errors import OptionError
from ..model import ALIGNS, BALANCES, COSTS, EQUAL_COUNTS, Color, Scene

__all__ = ["RenderOptions", "MatchSettings", "check_scene", "own_method_first", "Progress", "MAX_ONION", "MAX_WORKERS", "DEFAULT_MAX_FRAMES", "SHEET_COUNT", "REEL_SIZE", "REEL_FPS", "canvas_limit",
           "check_method", "check_methods", "check_size", "check_fps", "check_color", "check_choice", "check_memory"]

Progress = Callable[[int, int], None]
"""Called with ``(done, total)`` frames as a render goes."""

MAX_ONION = 20
"""The most ghosted inbetweens on each side of a frame."""
MAX_WORKERS = 256
DEFAULT_MAX_FRAMES = 100_000
"""The guard against renders that would run for days (``max_frames``)."""
SHEET_COUNT = 7
"""Inbetweens per row of a sheet, unless told."""
SHEET_PIXELS = 4096 * 4096
"""The largest sheet, in pixels (width times height): a sheet is drawn whole, at about 22 bytes a pixel
(4096 × 4096 with 200 inbetweens: 16 s and 365 MB here; 16384 × 16384 took minutes and gigabytes)."""
REEL_SIZE = (1280, 720)
"""A demo reel's size, unless told."""
REEL_FPS = 24.0
"""A demo reel's frame rate, unless told."""


def canvas_limit() -> int:
    """The largest frame side in pixels (a comparison's panels together): the scene format's limit."""
    from ..scenefile import LIMITS

    return int(LIMITS["canvas"])


def check_method(name: object, option: str = "method") -> str:
    """``name`` if it is a method of the registry, else an :class:`OptionError` with a "did you mean"."""
    if not isinstance(name, str) or name not in METHODS:
        raise OptionError(unknown_method(name), option)
    return name


def check_methods(names: object, option: str) -> tuple[str, ...]:
    """A non-empty list of method names (a single string is refused, not read letter by letter)."""
    if isinstance(names, (str, bytes)) or not isinstance(names, Sequence):
        raise OptionError(f"expected a list of method names, found {names!r}", option)
    if not names:
        raise OptionError("expected at least one method name, found none", option)
    return tuple(check_method(name, option) for name in names)


def _shown(value: object) -> str:
    """``repr(value)``, a very long one cut (``10**400`` has 401 digits)."""
    text = repr(value)
    return text if len(text) <= 40 else f"{text[:20]}…({len(text)} characters)"


def _whole(value: object, option: str, what: str) -> int:
    if isinstance(value, bool) or not isinstance(value, (Integral, Real)):
        raise OptionError(f"expected {what}, found {value!r}", option)
    if isinstance(value, Real) and not isinstance(value, Integral):
        if not math.isfinite(value) or not float(value).is_integer():
            raise OptionError(f"expected {what}, found {value!r}", option)
    return int(value)


def check_size(size: object, option: str = "size") -> tuple[int, int]:
    """``(width, height)`` in whole pixels from 1 to the canvas limit."""
    limit = canvas_limit()
    what = f"(width, height) in whole pixels from 1 to {limit}"
    if isinstance(size, (str, bytes)) or not isinstance(size, Sequence) or len(size) != 2:
        raise OptionError(f"expected {what}, found {size!r}", option)
    width, height = (_whole(v, option, what) for v in size)
    if not (1 <= width <= limit and 1 <= height <= limit):
        raise OptionError(f"expected {what}, found {width}x{height}", option)
    return width, height


def check_fps(fps: object, option: str = "fps") -> float:
    """A frame rate within the scene format's limits."""
    from ..scenefile import LIMITS

    low, high = LIMITS["fps"]
    if isinstance(fps, bool) or not isinstance(fps, Real) or not low <= fps <= high:  # no float(): 10**400
        raise OptionError(f"expected {low:g} to {high:g} frames per second, found {_shown(fps)}", option)
    return float(fps)


def check_color(value: object, option: str = "background") -> Color:
    """A colour: ``#rgb``, ``#rgba``, ``#rrggbb``, ``#rrggbbaa``, ``none``, or an ``(r, g, b, a)`` tuple."""
    from ..scenefile import parse_color

    if isinstance(value, str):
        if value.strip().lower() == "none":
            return (0, 0, 0, 0)
        return parse_color(value, lambda message: OptionError(message, option))
    what = "a colour text or an (r, g, b, a) tuple of 0 to 255"
    if not isinstance(value, Sequence) or len(value) != 4:
        raise OptionError(f"expected {what}, found {value!r}", option)
    r, g, b, a = (_whole(v, option, what) for v in value)
    if not all(0 <= v <= 255 for v in (r, g, b, a)):
        raise OptionError(f"expected {what}, found {value!r}", option)
    return (r, g, b, a)


def check_scene(scene: object) -> Scene:
    """``scene`` itself, refused unless it is a :class:`~tweenrender.model.Scene`."""
    if not isinstance(scene, Scene):
        raise OptionError(f"scene: expected a scene from load_scene(), found {type(scene).__name__}")
    return scene


def own_method_first(scene: Scene, methods: Sequence[str] | None = None) -> tuple[str, ...]:
    """``methods`` (default the scene's compare list) with the scene's own method first: the rows and panels
    of a sheet, reel or report open with what ``render`` draws."""
    listed = scene.compare if methods is None else tuple(methods)
    return (scene.method, *(m for m in listed if m != scene.method))


def check_choice(value: object, choices: Sequence[str], option: str) -> str:
    if not isinstance(value, str) or value not in choices:
        raise OptionError(f"expected one of {', '.join(choices)}, found {value!r}", option)
    return value


def _count(value: object, low: int, high: int, option: str) -> int:
    what = f"a whole number from {low} to {high}"
    number = _whole(value, option, what)
    if not low <= number <= high:
        raise OptionError(f"expected {what}, found {value!r}", option)
    return number


def _flag(value: object, option: str) -> bool:
    if not isinstance(value, bool):
        raise OptionError(f"expected True or False, found {value!r}", option)
    return value


_MEMORY_UNITS = {"": 1, "K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}
_MEMORY = re.compile(r"\s*(\d+(?:\.\d*)?|\.\d+)\s*([KMGT]?)(?:i?B)?\s*", re.IGNORECASE)
MIN_MEMORY = 1 << 10
"""The smallest memory limit taken (a KiB): anything less is surely a slip of the unit."""


def check_memory(value: object, option: str = "max_memory") -> int:
    """A memory limit in bytes from a whole number of bytes or a text such as ``512M``, ``2G``, ``1.5GiB``
    (K, M, G, T: binary multiples; a bare number: bytes)."""
    if isinstance(value, bool):
        raise OptionError(f"expected a size such as 512M or 2G, found {value!r}", option)
    if isinstance(value, Integral):
        number = int(value)
    elif isinstance(value, str) and (found := _MEMORY.fullmatch(value)):
        number = int(float(found.group(1)) * _MEMORY_UNITS[found.group(2).upper()])
    else:
        raise OptionError(f"expected a size such as 512M or 2G (K, M, G, T: KiB to TiB), found {value!r}", option)
    if not MIN_MEMORY <= number <= 1 << 50:
        raise OptionError(f"expected a size from 1K to 1024T, found {value!r}", option)
    return number


MAX_ERROR_RANGE = (0.001, 100.0)
"""Output pixels the keyframed paths of a vector file may stray from the exact inbetween (``max_error``)."""


def _max_error(value: object) -> float:
    low, high = MAX_ERROR_RANGE
    if isinstance(value, bool) or not isinstance(value, Real) or not low <= float(value) <= high:
        raise OptionError(f"expected {low:g} to {high:g} output pixels, found {value!r}", "max_error")
    return float(value)


@dataclass(frozen=True, slots=True)
class MatchSettings:
    """How the keys are put in correspondence and balanced, over the scene's own: ``cost``, ``align`` and
    ``equal_counts`` over its ``[correspondence]``, ``balance`` over every shape's (None keeps the scene's);
    ``max_memory`` the bytes (or a text such as ``512M``) the ``sg`` search's tables may take (None: 2 GiB).

    What ``--cost``, ``--align``, ``--equal-counts``, ``--max-memory`` and ``--balance`` give every command;
    the values are checked when they are put over a scene (:meth:`over`)."""

    cost: str | None = None
    align: str | None = None
    equal_counts: str | None = None
    balance: str | None = None
    max_memory: int | str | None = None

    @classmethod
    def names(cls) -> tuple[str, ...]:
        return tuple(f.name for f in fields(cls))

    @classmethod
    def create(cls, **given: str | None) -> MatchSettings:
        """The settings ``given`` by name; a name that is not one of :meth:`names` is refused."""
        for name in given:
            if name not in cls.names():
                from ..errors import did_you_mean

                raise OptionError(f"unknown option {name!r}{did_you_mean(name, cls.names())}; "
                                  f"expected some of {', '.join(cls.names())}")
        return cls(**given)

    def over(self, scene: object) -> Scene:
        """``scene`` (checked) with these settings put over its own; itself when none is given."""
        scene = check_scene(scene)
        changes = {name: check_choice(value, choices, name)
                   for name, value, choices in (("cost", self.cost, COSTS), ("align", self.align, ALIGNS),
                                                ("equal_counts", self.equal_counts, EQUAL_COUNTS))
                   if value is not None}
        if self.max_memory is not None:
            changes["max_memory"] = check_memory(self.max_memory)
        if changes:
            scene = replace(scene, matching=replace(scene.matching, **changes))
        if self.balance is None:
            return scene
        balance = check_choice(self.balance, BALANCES, "balance")
        return replace(scene, balance=balance, shapes=tuple(replace(shape, balance=None) for shape in scene.shapes))


@dataclass(frozen=True, slots=True)
class RenderOptions:
    """Everything ``render`` takes besides the scene and the target, validated (see :meth:`create`).

    ``compare`` is ``None`` (one picture), ``True`` (the scene's compare list) or methods; ``frames`` a
    ``"A:B"`` text or a ``range`` (checked against the scene when the clip is known); ``size`` each
    panel's; ``background`` a colour; ``cost``, ``align``, ``equal_counts`` put over the scene's
    ``[correspondence]``, ``balance`` over every shape's; ``max_memory`` what the ``sg`` search's tables
    may take (bytes, or ``512M``, ``2G``; default 2 GiB); ``max_error`` (vector formats only) how far, in
    output pixels, the keyframed paths may stray from the exact inbetween at a frame (default 0.25);
    ``loop`` makes a file that can say so play over and over (``encode.formats.Format.loop``); ``draft``
    encodes an MP4 or WebM at its encoder's quickest settings, for a look: the same quality asked for, a
    larger file (``encode.formats.Format.draft``).
    """

    method: str | None = None
    compare: tuple[str, ...] | bool | None = None
    format: str | None = None
    size: tuple[int, int] | None = None
    fps: float | None = None
    frames: str | range | None = None
    background: Color | None = None
    balance: str | None = None
    cost: str | None = None
    align: str | None = None
    equal_counts: str | None = None
    max_memory: int | str | None = None
    paths: bool = False
    onion: int = 0
    strip: bool = False
    workers: int | None = None
    cluster: str | None = None
    max_frames: int = DEFAULT_MAX_FRAMES
    progress: Progress | None = None
    max_error: float | None = None  # vector formats: output pixels the keyframed paths may stray
    loop: bool = False  # the file says it plays over and over (formats whose table entry has a loop)
    draft: bool = False  # MP4 and WebM encoded quickly, into a larger file

    @property
    def match(self) -> MatchSettings:
        """The correspondence and balance settings among these options."""
        return MatchSettings(self.cost, self.align, self.equal_counts, self.balance, self.max_memory)

    @classmethod
    def names(cls) -> tuple[str, ...]:
        """The options' long names, as :func:`tweenrender.write` and the command line take them."""
        return tuple(f.name for f in fields(cls))

    def given(self) -> dict[str, Any]:
        """The options that differ from the defaults, by name: what :meth:`create` takes to check them again."""
        return {f.name: getattr(self, f.name) for f in fields(self) if getattr(self, f.name) != f.default}

    @classmethod
    def create(cls, **given: Any) -> RenderOptions:
        """The options ``given`` by name (``None``: the default), each checked; unknown names are refused."""
        unknown = [name for name in given if name not in cls.names()]
        if unknown:
            from ..errors import did_you_mean

            raise OptionError(f"unknown option {unknown[0]!r}{did_you_mean(unknown[0], cls.names())}; "
                              f"expected some of {', '.join(cls.names())}")
        v = {name: value for name, value in given.items() if value is not None}
        if "method" in v and v.get("compare") not in (None, False):
            raise OptionError("method and compare do not go together: list the methods in compare")
        if "workers" in v and "cluster" in v:
            raise OptionError("workers and cluster do not go together: the cluster's workers draw the frames")
        compare = v.get("compare")
        if compare is not None and compare is not True and compare is not False:
            compare = check_methods(compare, "compare")
        if "format" in v:
            from ..encode.formats import lookup

            lookup(v["format"])
        if "frames" in v and not isinstance(v["frames"], (str, range)):
            raise OptionError(f"expected A:B (a text) or a range of frame indices, found {v['frames']!r}", "frames")
        if "cluster" in v and not isinstance(v["cluster"], str):
            raise OptionError(f"expected a scheduler address or local:N, found {v['cluster']!r}", "cluster")
        if "cluster" in v:
            from .cluster_address import parse_address

            parse_address(v["cluster"])  # before any work: a bad address is a usage error, not a late failure
        if "progress" in v and not callable(v["progress"]):
            raise OptionError(f"expected a function of (done, total), found {v['progress']!r}", "progress")
        return cls(
            method=check_method(v["method"]) if "method" in v else None,
            compare=compare or None,
            format=v.get("format"),
            size=check_size(v["size"]) if "size" in v else None,
            fps=check_fps(v["fps"]) if "fps" in v else None,
            frames=v.get("frames"),
            background=check_color(v["background"]) if "background" in v else None,
            balance=check_choice(v["balance"], BALANCES, "balance") if "balance" in v else None,
            cost=check_choice(v["cost"], COSTS, "cost") if "cost" in v else None,
            align=check_choice(v["align"], ALIGNS, "align") if "align" in v else None,
            equal_counts=check_choice(v["equal_counts"], EQUAL_COUNTS, "equal_counts")
            if "equal_counts" in v else None,
            max_memory=check_memory(v["max_memory"]) if "max_memory" in v else None,
            paths=_flag(v.get("paths", False), "paths"),
            onion=_count(v.get("onion", 0), 0, MAX_ONION, "onion"),
            strip=_flag(v.get("strip", False), "strip"),
            workers=_count(v["workers"], 1, MAX_WORKERS, "workers") if "workers" in v else None,
            cluster=v.get("cluster"),
            max_frames=_count(v.get("max_frames", DEFAULT_MAX_FRAMES), 1, 10**12, "max_frames"),
            progress=v.get("progress"),
            max_error=_max_error(v["max_error"]) if "max_error" in v else None,
            loop=_flag(v.get("loop", False), "loop"),
            draft=_flag(v.get("draft", False), "draft"),
        )
