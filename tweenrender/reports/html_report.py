"""One HTML page comparing methods on a scene: animations in sync, sheet, correspondence, charts, table.

The report is a folder (``output/<stem>-report/`` by default) holding ``index.html``
and every file it shows: one WebM per method, the storyboard sheet, the
correspondence picture and the metric charts as PNG. Nothing is fetched from
the network and no script library is used: a few lines of plain JavaScript keep
the videos on one clock. The folder is built beside the target and moved into
place whole with a manifest of its files; it replaces only an earlier report whose
manifest lists every entry, unchanged (:mod:`~tweenrender.encode.manifest`), never
anything else.
"""

from __future__ import annotations

import html
import re
from dataclasses import replace
from pathlib import Path
from typing import Any, Callable, Sequence

from ..core.methods.registry import METHODS, measured_methods
from ..core.stacking import Switch, layered
from ..errors import OptionError, printable
from ..plan.options import own_method_first
from ..model import Scene
from .stats import auto_words, crossing_runs, fallback_words, others_words

__all__ = ["REPORT_FILE", "report_methods", "write_report", "page"]

REPORT_FILE = re.compile(r"(?:index\.html|sheet\.png|correspondence\.png|metrics\.png|(?:"
                         + "|".join(re.escape(name) for name in METHODS) + r")\.webm)")
"""The names of the files a report folder holds: the only names its manifest may list."""

_WIDTH = 384  # pixels of each animation's width (three to a row); the height follows the view


def report_methods(scene: Scene) -> tuple[str, ...]:
    """Every method, ``jointed`` only when some shape has joints; the scene's own first."""
    jointed = any(shape.joints for shape in scene.shapes)
    return own_method_first(scene, measured_methods(jointed))


def _check_target(target: Path) -> None:
    from ..encode.manifest import frame_names
    from ..encode.targets import check_own_folder

    if target.is_symlink() or (target.exists() and not target.is_dir()):
        raise OptionError(f"{printable(str(target))}: is not a folder; refusing to replace it with a report")
    check_own_folder(target, frame_names(REPORT_FILE), "a report")


def write_report(scene: Scene, target: Path, methods: Sequence[str] | None = None,
                 progress: Callable[[str], Callable[[int, int], None] | None] | None = None) -> Path:
    """Write the report folder ``target`` for ``methods`` (default :func:`report_methods`); returns
    the path of its ``index.html``. ``progress(name)`` may give a progress callback per video."""
    from ..encode.atomic import commit_folder, discard, prepare_folder, sibling
    from ..encode.manifest import write_manifest
    from ..plan.job import scene_view, stacking_of, tracks_of
    from ..pipeline.library import write
    from .pictures import write_sheet
    from .match_report import correspond_dict, write_match_picture
    from .metric_report import write_metric_plot
    from .stats import stats_dict

    from ..encode.targets import check_output_name

    from ..pipeline.library import not_an_input

    methods = tuple(methods or report_methods(scene))
    target = check_output_name(target, "expected a folder's name for the report")
    files = ["index.html", "sheet.png", "correspondence.png", "metrics.png", *(f"{m}.webm" for m in methods)]
    not_an_input(target, [scene], folder=True, files=files)
    _check_target(target)
    prepare_folder(target)
    tracks = tracks_of(scene)
    view = scene_view(scene, tracks, methods)
    shared = replace(scene, view=view)  # one view for every video, so sizes compare
    width = _WIDTH
    x0, y0, x1, y1 = view
    height = max(2, int(round(width * (y1 - y0) / (x1 - x0) / 2)) * 2)
    height = min(height, 2 * width)
    folder = sibling(target)
    try:
        folder.mkdir()
        videos = []
        for method in methods:
            name = f"{method}.webm"
            write(shared, folder / name, method=method, size=(width, height), workers=1, draft=True,
                  progress=progress(name) if progress else None)
            videos.append((method, name))
        write_sheet(shared, tracks, methods, view, folder / "sheet.png")
        write_match_picture(scene, correspond_dict(scene), folder / "correspondence.png")
        write_metric_plot(scene, methods, folder / "metrics.png")
        stats = stats_dict(scene, [0.25, 0.5, 0.75], methods)
        switches = stacking_of(scene, tracks)
        (folder / "index.html").write_text(page(scene, videos, stats, (width, height), switches), encoding="utf-8")
        write_manifest(folder)
    except BaseException:
        discard(folder)
        raise
    _check_target(target)  # again: something may have appeared there meanwhile
    commit_folder(folder, target)
    return target / "index.html"


_STYLE = """
body { font: 15px/1.45 system-ui, sans-serif; margin: 24px auto; max-width: 1240px; color: #1e222d;
       padding: 0 16px; }
h1 { font-size: 24px; margin-bottom: 4px; } h2 { font-size: 19px; margin-top: 32px; }
.note { color: #5a5f6b; margin-top: 0; }
.grid { display: flex; flex-wrap: wrap; gap: 12px; }
figure { margin: 0; } figcaption { font-weight: 600; text-align: center; }
video { display: block; border: 1px solid #d5d8de; background: #fff; max-width: 100%; height: auto; }
img { max-width: 100%; border: 1px solid #d5d8de; }
table { border-collapse: collapse; margin-bottom: 18px; }
th, td { padding: 3px 10px; border-bottom: 1px solid #e3e5ea; text-align: right; }
th:first-child, td:first-child { text-align: left; }
td.bad { color: #c81e28; font-weight: 600; }
button { font: inherit; padding: 4px 14px; }
"""

# Every video follows the first: started together, nudged back when one drifts, paused together.
_SCRIPT = """
const videos = Array.from(document.querySelectorAll("video"));
const lead = videos[0];
const button = document.getElementById("playing");
function playAll() { videos.forEach(v => { v.currentTime = lead.currentTime; v.play().catch(() => {}); }); }
if (lead) {
  lead.addEventListener("timeupdate", () => {
    videos.forEach(v => { if (v !== lead && Math.abs(v.currentTime - lead.currentTime) > 0.08) {
      v.currentTime = lead.currentTime; } });
  });
  button.addEventListener("click", () => {
    if (lead.paused) { playAll(); button.textContent = "Pause"; }
    else { videos.forEach(v => v.pause()); button.textContent = "Play"; }
  });
  playAll();
}
"""


_SURROGATE = re.compile("[\ud800-\udfff]")


def _esc(text: Any) -> str:
    """``text`` for HTML: markup characters escaped, a lone surrogate (which UTF-8 cannot hold) as U+FFFD."""
    return html.escape(_SURROGATE.sub("\ufffd", str(text)), quote=True)


def _crossing_text(at: list[float]) -> str:
    if not at:
        return "never"
    return "t = " + ", ".join(f"{a:g}" if a == b else f"{a:g}–{b:g}" for a, b in crossing_runs(at))


def _table(entry: dict[str, Any]) -> str:
    start, end = entry["times"]
    m, n = entry["vertices"]
    rows = []
    for method, r in entry["methods"].items():
        ratios = " / ".join(f"{x:.4f}" for x in r["perimeter_ratio"])
        areas = " / ".join(f"{x:.4f}" for x in r["area_ratio"])
        crossing = _crossing_text(r["self_intersects"])
        tangled = sorted(set(r.get("crossings", [])) | set(r.get("stroke_crossings", [])))
        stray = r.get("stray_max")
        rows.append(f"<tr><td>{_esc(method)}</td><td>{ratios}</td><td>{areas}</td>"
                    f"<td>{r['edge_error_max']:.4f}</td><td>{r['angle_error_max']:.2f}</td>"
                    f"<td class=\"{'bad' if r['self_intersects'] else ''}\">{_esc(crossing)}</td>"
                    f"<td class=\"{'bad' if tangled else ''}\">{_esc(_crossing_text(tangled))}</td>"
                    f"<td>{'' if stray is None else f'{stray:.3f}'}</td></tr>")
    where = _esc(entry["name"])
    if "element" in entry:
        where = f"element {_esc(entry['element'])}, contour {entry['contour']}"
    elif "contour" in entry:
        where += f", contour {entry['contour']}"
    auto = entry.get("auto")
    drawn = "" if auto is None else f"<p>{_esc(auto_words(auto))}</p>\n"
    return (f"<h3>{where}, segment {entry['segment']} ({start:g}–{end:g} s): {m} and {n} "
            f"vertices, {entry['balanced']} after balancing</h3>\n" + drawn +
            "<table><thead><tr><th>method</th><th>perimeter ratio at t = .25 / .5 / .75</th>"
            "<th>area ratio at t = .25 / .5 / .75</th><th>worst edge error</th>"
            "<th>worst angle error (°)</th><th>crosses itself</th><th>shape tangles</th>"
            "<th>stray (share of area)</th></tr></thead>\n<tbody>\n"
            + "\n".join(rows) + "\n</tbody></table>" + _fallback_notes(entry))


def _fallback_notes(entry: dict[str, Any]) -> str:
    """Where a method had no morph of its own (``injective``'s ``fallback``), why: a note per method."""
    return "".join(f"\n<p class=\"note\">{_esc(method)}: {_esc(fallback_words(r['fallback']))}</p>"
                   for method, r in entry["methods"].items() if r.get("fallback"))


def _others_table(entry: dict[str, Any]) -> str:
    """A segment with no closed contour in both keys (``stats``' ``others``): what auto draws, and per method
    where the element tangles and where its strokes cross."""
    start, end = entry["times"]
    rows = []
    for method, r in entry["methods"].items():
        rows.append(f"<tr><td>{_esc(method)}</td>"
                    f"<td class=\"{'bad' if r['crossings'] else ''}\">{_esc(_crossing_text(r['crossings']))}</td>"
                    f"<td class=\"{'bad' if r['stroke_crossings'] else ''}\">"
                    f"{_esc(_crossing_text(r['stroke_crossings']))}</td></tr>")
    return (f"<h3>element {_esc(entry['name'])}, segment {entry['segment']} ({start:g}–{end:g} s): "
            f"{_esc(others_words(entry))}</h3>\n<p>{_esc(auto_words(entry['auto']))}</p>\n"
            "<table><thead><tr><th>method</th><th>shape tangles</th><th>strokes cross</th></tr></thead>\n<tbody>\n"
            + "\n".join(rows) + "\n</tbody></table>" + _fallback_notes(entry))


def stacking_words(scene: Scene, switches: Sequence[Switch]) -> list[str]:
    """One sentence per switch of paint order: when, and which elements change places."""
    names = [shape.name for shape in scene.shapes]
    out = []
    for switch in switches:
        swapped = ", ".join(f"{names[a]} and {names[b]}" for a, b in switch.pairs[:8])
        more = f" and {len(switch.pairs) - 8} more pairs" if len(switch.pairs) > 8 else ""
        out.append(f"Between the keys at {switch.start:g} s and {switch.end:g} s the paint order switches at "
                   f"{switch.time:.4g} s (t = {round(switch.t * 32)}/32), where the elements that change places "
                   f"overlap least ({min(switch.areas):.4g} square units): {swapped}{more}.")
    return out


def page(scene: Scene, videos: Sequence[tuple[str, str]], stats: dict[str, Any], size: tuple[int, int],
         switches: Sequence[Switch] = ()) -> str:
    """The ``index.html`` text: ``videos`` are ``(method, file name)`` pairs; ``stats`` is
    :func:`~tweenrender.reports.stats.stats_dict` for the same methods; ``switches`` where the paint
    order of drawings changes (:func:`~tweenrender.plan.job.stacking_of`)."""
    from .. import __version__

    title = scene.title or (scene.path.stem if scene.path else "scene")
    width, height = size
    figures = "\n".join(
        f'<figure><video src="{_esc(name)}" width="{width}" height="{height}" muted loop autoplay playsinline '
        f'preload="auto"></video><figcaption>{_esc(method)}</figcaption></figure>' for method, name in videos)
    nothing = stats.get("note", "no shape has two keys: nothing moves")
    tables = "\n".join(_table(entry) for entry in stats["shapes"]) or f"<p>{_esc(nothing[0].upper() + nothing[1:])}.</p>"
    tables += "".join("\n" + _others_table(entry) for entry in stats.get("others", []))
    source = _esc(scene.path) if scene.path else "a scene built in Python"
    stacking = "".join(f"<p>{_esc(words)}</p>\n" for words in stacking_words(scene, switches))
    if stacking:
        stacking = "<h2>Paint order</h2>\n" + stacking
    return f"""<!doctype html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="generator" content="tweenrender {_esc(__version__)}">
<meta name="viewport" content="width=device-width, initial-scale=1">
<link rel="icon" href="data:,">
<title>{_esc(title)} — methods compared</title>
<style>{_STYLE}</style>
</head>
<body>
<h1>{_esc(title)}</h1>
<p class="note">{source} · {len(videos)} methods · {scene.fps:g} fps · the perimeter and area ratios
are taken against the keys' values interpolated at t; errors are the worst over 101 t of each segment.</p>

<h2>Animations</h2>
<div class="grid">
{figures}
</div>
<p><button id="playing" type="button">Pause</button></p>
{stacking}
<h2>Storyboard</h2>
<p class="note">{"Keys and inbetweens as drawn, outlines thin, one row per method." if layered(scene.shapes)
                  else "Keys in bold, inbetweens thin, one row per method."}</p>
<img src="sheet.png" alt="Storyboard: keys and inbetweens of every method">

<h2>Correspondence</h2>
<img src="correspondence.png" alt="Which vertex of each key goes with which">

<h2>Measures over t</h2>
<img src="metrics.png" alt="Perimeter and area ratios, edge and angle errors over t, and self-intersections">

<h2>Measures</h2>
{tables}
<script>{_SCRIPT}</script>
</body>
</html>
"""
