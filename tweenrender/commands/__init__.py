"""One module per command; each has ``register(subparsers)`` and imports heavy code only when run.

A command's ``run(args) -> int`` returns the exit code and raises
:class:`~tweenrender.errors.TweenrenderError` for anything the user must fix.
"""

from __future__ import annotations

from importlib import import_module

__all__ = ["COMMANDS", "register_all"]

COMMANDS = ("render", "check", "stats", "correspond", "qcurves", "sheet", "reel")


def register_all(subparsers) -> None:  # type: ignore[no-untyped-def]
    """Add every command that exists to ``subparsers`` (argparse's ``add_subparsers`` result)."""
    for name in COMMANDS:
        try:
            module = import_module(f".{name}", __name__)
        except ModuleNotFoundError as error:
            if error.name != f"{__name__}.{name}":
                raise
            continue
        module.register(subparsers)
