"""What the inspecting commands print, as plain data: ``stats``, ``correspond``, ``qcurves`` and
``check --json`` are each one call here (``tr.stats``, ``tr.correspondence``, ``tr.qcurves``,
``tr.describe``), and the optional picture is written atomically beside it.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any, Sequence

from ..errors import OptionError
from ..model import Scene
from ..pipeline.library import not_an_input
from ..plan.options import MatchSettings, check_scene

__all__ = ["stats", "correspondence", "qcurves", "describe", "scene_name", "picture_target"]


def scene_name(scene: Scene) -> str | list[str] | None:
    """What a report calls its scene: the scene file as given, or, for a morph of drawings, the list of
    its SVG files."""
    if scene.path is not None and scene.path.suffix.lower() == ".svg":
        return [str(p) for p in scene.sources] or [str(scene.path)]
    return str(scene.path) if scene.path is not None else None


def picture_target(path: str | os.PathLike[str], what: str) -> Path:
    """``path`` as the name of a PNG picture, refused unless it ends in ``.png``."""
    if not isinstance(path, (str, os.PathLike)):
        raise OptionError(f"expected a file name ending in .png for {what}, found {path!r}", "picture")
    target = Path(path)
    if target.suffix.lower() != ".png":
        raise OptionError(f"{target}: {what} is a PNG; give a name ending in .png", "picture")
    return target


def stats(scene: Scene, t: Sequence[float] = (0.5,), methods: Sequence[str] | None = None) -> dict[str, Any]:
    """The thesis's ch. 6 perimeter report and the quality measures per shape, segment and method, at
    ``t`` within each segment (what ``stats --json`` prints)."""
    from .stats import stats_dict
    from ..plan.options import check_methods

    scene = check_scene(scene)
    if isinstance(t, (str, bytes)) or not isinstance(t, Sequence) or not t or \
            not all(isinstance(v, (int, float)) and not isinstance(v, bool) and 0.0 <= v <= 1.0 for v in t):
        raise OptionError(f"expected numbers in [0, 1], found {t!r}", "t")
    chosen = None if methods is None else check_methods(methods, "methods")
    return {"scene": scene_name(scene), **_without_scene(stats_dict(scene, [float(v) for v in t], chosen))}


def correspondence(scene: Scene, picture: str | os.PathLike[str] | None = None,
                   match: MatchSettings = MatchSettings()) -> dict[str, Any]:
    """The vertex correspondence of every segment: pairs, balanced count, work (what ``correspond
    --json`` prints); ``picture`` names a PNG to draw it in."""
    from .match_report import correspond_dict, write_match_picture

    target = None if picture is None else picture_target(picture, "the picture")
    scene = match.over(scene)
    if target is not None:
        not_an_input(target, [scene])
    report = {"scene": scene_name(scene), **_without_scene(correspond_dict(scene, scene.matching))}
    if target is not None:
        write_match_picture(scene, report, target)
    return report


def qcurves(scene: Scene, picture: str | os.PathLike[str] | None = None) -> dict[str, Any]:
    """Every vertex's Q-curve, the motion it shows and auto's choice (what ``qcurves --json`` prints);
    ``picture`` names a PNG to plot them in."""
    from .qcurve_report import qcurves_dict, write_qcurve_plot

    target = None if picture is None else picture_target(picture, "the plot")
    scene = check_scene(scene)
    if target is not None:
        not_an_input(target, [scene])
    report = {"scene": scene_name(scene), **_without_scene(qcurves_dict(scene))}
    if target is not None:
        write_qcurve_plot(report, target)
    return report


def describe(scene: Scene) -> dict[str, Any]:
    """The scene as loaded, in world units (what ``check --json`` prints)."""
    from ..core.timing.timeline import tracks_of
    from .check_report import scene_dict
    from ..plan.job import scene_view

    scene = check_scene(scene)
    report = scene_dict(scene, scene_view(scene, tracks_of(scene), (None,)))
    report["scene"] = scene_name(scene)
    return report


def _without_scene(report: dict[str, Any]) -> dict[str, Any]:
    return {key: value for key, value in report.items() if key != "scene"}
