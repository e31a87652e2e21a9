"""``--cost``, ``--align``, ``--equal-counts`` (a scene's ``[correspondence]``) and ``--balance``
from the command line."""

from __future__ import annotations

import argparse

from ..model import ALIGNS, BALANCES, COSTS, EQUAL_COUNTS, Matching, Scene

__all__ = ["add_matching_flags", "add_balance_flag", "matching_of", "with_matching"]


def add_matching_flags(parser: argparse.ArgumentParser) -> None:
    """Add ``--cost``, ``--align`` and ``--equal-counts`` (all default to the scene's own settings)."""
    parser.add_argument("--cost", choices=COSTS,
                        help="correspondence cost where two keys' vertex counts differ: distance "
                             "(the thesis's work) or sg (Sederberg–Greenwood energy); default: the scene's")
    parser.add_argument("--align", choices=ALIGNS,
                        help="match after moving each key's center of mass to the origin (centroid) "
                             "or as placed (none); default: the scene's")
    parser.add_argument("--equal-counts", choices=EQUAL_COUNTS, dest="equal_counts",
                        help="keys with equal vertex counts: keep the drawn order (drawn) or search "
                             "the least-work correspondence for them too (match); default: the scene's")


def add_balance_flag(parser: argparse.ArgumentParser) -> None:
    """Add ``--balance copies|spread`` (default: the scene's, shape by shape)."""
    parser.add_argument("--balance", choices=BALANCES,
                        help="where balancing puts the copies of a vertex matched to several: stacked on "
                             "it (copies, the thesis) or spread along its edges (spread); default: the scene's")


def matching_of(scene: Scene, args: argparse.Namespace) -> Matching:
    """The scene's matching with the flags given on the command line put over it."""
    return with_matching(scene, args).matching


def with_matching(scene: Scene, args: argparse.Namespace) -> Scene:
    """``scene`` with ``--cost``, ``--align`` and ``--equal-counts`` put over its ``[correspondence]``
    and ``--balance`` over every shape's balance."""
    from ..pipeline.library import with_balance
    from ..pipeline.library import with_matching as put_over

    return with_balance(put_over(scene, getattr(args, "cost", None), getattr(args, "align", None),
                                 getattr(args, "equal_counts", None)), getattr(args, "balance", None))
