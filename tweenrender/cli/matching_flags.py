"""``--cost``, ``--align``, ``--equal-counts`` (a scene's ``[correspondence]``), ``--max-memory`` and
``--balance`` from the command line; the library checks their values."""

from __future__ import annotations

import argparse
from typing import Any

from ..api import ALIGNS, BALANCES, COSTS, EQUAL_COUNTS

__all__ = ["add_matching_flags", "add_balance_flag", "matching_options"]


def add_matching_flags(parser: argparse.ArgumentParser) -> None:
    """Add ``--cost``, ``--align`` and ``--equal-counts`` (all default to the scene's own settings) and
    ``--max-memory``."""
    parser.add_argument("--cost", metavar="|".join(COSTS),
                        help="correspondence cost where two keys' vertex counts differ: distance "
                             "(the thesis's work) or sg (Sederberg–Greenwood energy); default: the scene's")
    parser.add_argument("--align", metavar="|".join(ALIGNS),
                        help="match after moving each key's center of mass to the origin (centroid) "
                             "or as placed (none); default: the scene's")
    parser.add_argument("--equal-counts", metavar="|".join(EQUAL_COUNTS), dest="equal_counts",
                        help="keys with equal vertex counts: keep the drawn order (drawn) or search "
                             "the least-work correspondence for them too (match); default: the scene's")
    parser.add_argument("--max-memory", metavar="SIZE", dest="max_memory",
                        help="the most the exact sg search's tables may take (about 120 bytes a pair of "
                             "vertices), e.g. 512M or 2G: a larger search is refused before it starts; default 2G")


def add_balance_flag(parser: argparse.ArgumentParser) -> None:
    """Add ``--balance copies|spread`` (default: the scene's, shape by shape)."""
    parser.add_argument("--balance", metavar="|".join(BALANCES),
                        help="where balancing puts the copies of a vertex matched to several: stacked on "
                             "it (copies, the thesis) or spread along its edges (spread); default: the scene's")


def matching_options(args: argparse.Namespace) -> dict[str, Any]:
    """The matching and balance flags given, by the library's names."""
    return {name: getattr(args, name, None) for name in ("cost", "align", "equal_counts", "max_memory", "balance")
            if getattr(args, name, None) is not None}
