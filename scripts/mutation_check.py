"""Mutation check: do the tests catch plausible bugs in the core, timeline, encoders, atomic writes and more?

    python scripts/mutation_check.py            # every mutant, one after another (about 25 minutes)
    python scripts/mutation_check.py -k "server writer reader"   # the preview server, scene writer, SVG reader
    python scripts/mutation_check.py -k ease    # only mutants whose name contains "ease"
    python scripts/mutation_check.py -k "svg manifest"   # ... "svg" or "manifest"
    python scripts/mutation_check.py --list     # the mutants, without running anything

The tree (package, tests, scenes) is copied once to a temporary folder. Each mutant
is one small textual change to one file of that copy (the original text must occur
there exactly once, so a stale mutant is reported rather than silently skipped); the
tests named for it run against the copy (``PYTHONPATH`` points there, so the copy's
package is the one imported, in subprocesses too), and the file is put back. A mutant
is *killed* when those tests fail (or run past the time limit), *survives* when they
pass. The unmutated copy must pass the same tests first. Prints each mutant's fate
and the score; exits 1 if fewer than ``--required`` percent (default 90) are killed.
"""

from __future__ import annotations

import argparse
import os
import shutil
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SKIP = shutil.ignore_patterns(".venv", ".git", "output", "__pycache__", ".pytest_cache", ".hypothesis",
                              "*.egg-info", "build", "dist", "benchmarks")


@dataclass(frozen=True)
class Mutant:
    name: str
    file: str  # relative to the root
    before: str  # exact text, found once
    after: str
    tests: tuple[str, ...]  # pytest targets


CORE = ("tests/core", "tests/cli/test_reliability.py", "tests/pipeline/test_library.py")
STATS = ("tests/cli/test_main.py", "tests/core/test_measures.py")
TIMELINE = ("tests/core/test_timeline.py", "tests/pipeline/test_library.py", "tests/raster/test_frames.py")
ENCODE = ("tests/encode", "tests/cli/test_main.py")
STROKE = ("tests/raster/test_round_stroke.py",)
CONTROLS = ("tests/core/test_easing.py", "tests/core/test_hints.py", "tests/scenefile/test_controls.py",
            "tests/cli/test_timing_flags.py")
ATOMIC = ("tests/cli/test_targets.py", "tests/cli/test_reliability.py", "tests/encode")
VECTOR = ("tests/vector/test_keyframes.py", "tests/vector/test_vector_output.py", "tests/vector/test_curves.py")
PAINT = ("tests/encode/test_vector_paint_players.py",)
OWNED = ("tests/encode/test_manifest.py", "tests/cli/test_targets.py")
_CLUSTER_TESTS = "tests/pipeline/test_cluster_failures.py::"
CLUSTER = tuple(_CLUSTER_TESTS + name for name in ("test_a_bad_address_is_refused_before_connecting",
                                                   "test_a_port_where_nothing_listens_is_one_line",
                                                   "test_an_http_server_is_not_taken_for_a_scheduler"))
DRAWING = ("tests/scenefile/test_drawing_rules.py", "tests/scenefile/test_hostile_inputs.py")
_SECURITY = "tests/preview/test_preview_security.py::"
SERVER_ORIGIN = (_SECURITY + "test_cross_origin_method_post_is_refused_and_changes_nothing",
                 _SECURITY + "test_a_cross_site_request_without_origin_is_refused",
                 _SECURITY + "test_state_needs_the_token", _SECURITY + "test_own_origin_with_the_token_is_answered")
SERVER_HOST = (_SECURITY + "test_a_foreign_host_is_refused_even_with_the_token",
               _SECURITY + "test_own_origin_with_the_token_is_answered")
SERVER_TOKEN = (_SECURITY + "test_state_needs_the_token",
                _SECURITY + "test_edit_is_refused_across_origins_and_without_the_token",
                _SECURITY + "test_the_page_carries_a_token_of_the_run",
                _SECURITY + "test_a_body_too_long_is_refused_before_it_is_sent")
SERVER_CONNECTIONS = ("tests/preview/test_preview_connections.py",)
_EDITS_TESTS = "tests/scenefile/test_scene_edits.py::"
INIT = ("tests/cli/test_init.py", _EDITS_TESTS + "test_the_scene_of_drawings_draws_what_the_command_line_draws",
        _EDITS_TESTS + "test_the_scene_of_drawings_reads_back_its_names_and_times_exactly")
EDITS = ("tests/scenefile/test_scene_edits.py",)
PREVIEW_EDITS = ("tests/preview/test_preview_edits.py",)
SVG_CSS = ("tests/scenefile/test_svg_css.py",)
SVG_UNITS = ("tests/scenefile/test_svg_small_rules.py", "tests/scenefile/test_svg.py")
SVG_VIEW = ("tests/scenefile/test_svg_viewports.py", "tests/scenefile/test_empty_drawings.py",
            "tests/scenefile/test_svg_small_rules.py::test_a_nested_view_box_origin_moves_its_content")
SVG_ERRORS = ("tests/scenefile/test_svg_error_rules.py",)
STEERING = ("tests/core/test_steering.py", "tests/scenefile/test_steering_fields.py")

MUTANTS = [
    # -- core: paths ---------------------------------------------------------------------------------
    Mutant("linear: keys swapped", "tweenrender/core/methods/paths.py",
           "return (1.0 - t) * k0 + t * k1", "return t * k0 + (1.0 - t) * k1", CORE),
    Mutant("bezier2: middle weight halved", "tweenrender/core/methods/paths.py",
           "2.0 * s * t * p1", "s * t * p1", CORE),
    Mutant("nonlinear: middle control point on the reshaped frame", "tweenrender/core/methods/paths.py",
           "p1 = 2.0 * reshaped - 0.5 * (k0 + k1)", "p1 = reshaped", CORE),
    Mutant("nonlinear: first key's distances only", "tweenrender/core/methods/paths.py",
           "dist = 0.5 * (np.linalg.norm(u0, axis=-1) + np.linalg.norm(u1, axis=-1))",
           "dist = np.linalg.norm(u0, axis=-1)", CORE),
    Mutant("nonlinear: 180° fallback turns the wrong way", "tweenrender/core/methods/paths.py",
           "rotate(u0, phi / 2)", "rotate(u0, -phi / 2)", CORE),
    Mutant("rigid: second key's spokes turned the wrong way", "tweenrender/core/methods/paths.py",
           "u1 = rotate(k1 - c1, -phi)", "u1 = rotate(k1 - c1, phi)", CORE),
    Mutant("rigid: spokes not blended (non-rigid change dropped)", "tweenrender/core/methods/paths.py",
           "spokes = linear(u0, u1, t)", "spokes = linear(u0, u0, t)", CORE),
    Mutant("rigid: turn eased by t²", "tweenrender/core/methods/paths.py",
           "rotate(spokes, (t * phi)[:, None])", "rotate(spokes, (t * t * phi)[:, None])", CORE),
    Mutant("rigid: center moves along the first key's", "tweenrender/core/methods/paths.py",
           "center = (1.0 - t)[:, None] * c0 + t[:, None] * c1", "center = (1.0 - t)[:, None] * c0 + t[:, None] * c0",
           CORE),
    # -- core: geometry and methods ------------------------------------------------------------------
    Mutant("centroid: median instead of mean", "tweenrender/core/geometry.py",
           "return points.mean(axis=-2)", "return np.median(points, axis=-2)", CORE),
    Mutant("signed area: doubled", "tweenrender/core/geometry.py",
           "return 0.5 * cross(points, np.roll(points, -1, axis=-2)).sum(axis=-1)",
           "return cross(points, np.roll(points, -1, axis=-2)).sum(axis=-1)", CORE + STATS),
    Mutant("best-fit rotation: atan2 arguments swapped", "tweenrender/core/geometry.py",
           "phi = np.arctan2(s, c)", "phi = np.arctan2(c, s)", CORE),
    Mutant("best-fit rotation: a half turn reported as -180°", "tweenrender/core/geometry.py",
           "return np.where(phi <= -np.pi, np.pi, phi)", "return phi", CORE),
    Mutant("nonlinear: no fallback near a half turn", "tweenrender/core/methods/paths.py",
           "flat = length <= _DEGENERATE * scale", "flat = length < 0.0", CORE),
    Mutant("rotate: clockwise y", "tweenrender/core/geometry.py",
           "s * x + c * y", "-s * x + c * y", CORE),
    Mutant("perimeter: longest edge", "tweenrender/core/geometry.py",
           "return edge_lengths(points).sum(axis=-1)", "return edge_lengths(points).max(axis=-1)", CORE + STATS),
    Mutant("interpolate: the last key not forced", "tweenrender/core/methods/registry.py",
           "    frames[t == 1.0] = k1\n", "", CORE),
    # -- core: Q-curves and auto ---------------------------------------------------------------------
    Mutant("auto: non-rigid only when every vertex changes", "tweenrender/core/methods/qcurves.py",
           'if "nonrigid" in kinds:', 'if kinds and all(kind == "nonrigid" for kind in kinds):',
           CORE + ("tests/cli/test_qcurves.py",)),
    Mutant("auto: any turn taken as rigid", "tweenrender/core/methods/qcurves.py",
           "turning = (gap02 <= tol) & (np.linalg.norm(q1 - cos_phi[:, None] * qm, axis=-1) <= tol)",
           "turning = np.linalg.norm(q1 - cos_phi[:, None] * qm, axis=-1) <= tol",
           CORE + ("tests/cli/test_qcurves.py",)),
    Mutant("auto: nonlinear for non-rigid change too", "tweenrender/core/methods/qcurves.py",
           'return "nonlinear" if motion.kind == "rotation" else "linear"',
           'return "nonlinear" if motion.kind != "translation" else "linear"', CORE + ("tests/cli/test_qcurves.py",)),
    # -- core: measures and correspondence -----------------------------------------------------------
    Mutant("stats: area ratio of the perimeters", "tweenrender/core/measures.py",
           "ratio = signed_area(frames) / reference", "ratio = perimeter(frames) / reference", STATS),
    Mutant("stats: ratio minimum is the mean", "tweenrender/core/measures.py",
           "ratio_min=float(swept_ratio.min())", "ratio_min=float(swept_ratio.mean())", STATS),
    Mutant("correspondence: second key centred on the first's centroid", "tweenrender/core/correspondence/correspond.py",
           "return a - centroid(a), b - centroid(b)", "return a - centroid(a), b - centroid(a)",
           ("tests/core/test_correspond.py", "tests/cli/test_correspond.py")),
    # -- timeline ------------------------------------------------------------------------------------
    Mutant("ease: in-out made linear", "tweenrender/core/timing/easing.py",
           'NAMED["in-out"]: lambda u: u * u * (3.0 - 2.0 * u),', 'NAMED["in-out"]: lambda u: u,', TIMELINE),
    Mutant("ease: in and out swapped", "tweenrender/core/timing/easing.py",
           'NAMED["in"]: lambda u: u * u,\n    NAMED["out"]: lambda u: 1.0 - (1.0 - u) ** 2,',
           'NAMED["in"]: lambda u: 1.0 - (1.0 - u) ** 2,\n    NAMED["out"]: lambda u: u * u,',
           TIMELINE),
    Mutant("ease: out is cubic", "tweenrender/core/timing/easing.py",
           "lambda u: 1.0 - (1.0 - u) ** 2", "lambda u: 1.0 - (1.0 - u) ** 3", TIMELINE),
    Mutant("ease: the segment takes the ease of the key that ends it", "tweenrender/core/timing/timeline.py",
           "easing=easing_of(before), delay=before.delay", "easing=easing_of(after), delay=before.delay",
           TIMELINE),
    Mutant("cubic-bezier: no bisection where Newton stalls", "tweenrender/core/timing/easing.py",
           "if left.any():  # bisection", "if False:  # bisection", CONTROLS),
    Mutant("cubic-bezier: y read with the x handles", "tweenrender/core/timing/easing.py",
           "out = _bezier(s, self.y1, self.y2)", "out = _bezier(s, self.x1, self.y2)", CONTROLS),
    Mutant("steps: jump-start does not jump at the start", "tweenrender/core/timing/easing.py",
           'if self.jump in ("jump-start", "jump-both"):', 'if self.jump in ("jump-both",):', CONTROLS),
    Mutant("spacing: no Fritsch–Carlson limit", "tweenrender/core/timing/spacing.py",
           "if length > 3.0 * delta[k]:", "if length > 300.0 * delta[k]:", CONTROLS),
    Mutant("hints: pieces solved with sg stretch of the wrong step", "tweenrender/core/correspondence/_hint_kernel.py",
           "energy[r, c, step] = best + stretch[ni, nj, step]", "energy[r, c, step] = best + stretch[ni, nj, 1]",
           CONTROLS),
    Mutant("hints: a piece's end costs counted twice", "tweenrender/core/correspondence/hint_search.py",
           "path = np.concatenate([piece[:-1] for piece in nodes])", "path = np.concatenate([piece for piece in nodes])",
           CONTROLS),
    Mutant("stagger: every element starts together", "tweenrender/scenefile/drawings.py",
           "out[c][k] = key.hold + i * key.stagger", "out[c][k] = key.hold", CONTROLS),
    Mutant("frame count: the last key's frame dropped", "tweenrender/core/timing/timeline.py",
           "return math.ceil(duration * fps - 1e-9) + 1", "return math.ceil(duration * fps - 1e-9)",
           TIMELINE + ("tests/cli/test_main.py",)),
    Mutant("frame count: rounded (a last key between two frame times never shown)", "tweenrender/core/timing/timeline.py",
           "return math.ceil(duration * fps - 1e-9) + 1", "return round(duration * fps) + 1", TIMELINE),
    Mutant("local t: measured from time 0", "tweenrender/core/timing/timeline.py",
           "begin = self.start + self.delay + rank * self.stagger", "begin = self.delay + rank * self.stagger",
           TIMELINE),
    Mutant("local t: not clamped outside the segment", "tweenrender/core/timing/timeline.py",
           "return np.clip((times - begin) / span, 0.0, 1.0)", "return (times - begin) / span", TIMELINE),
    Mutant("timeline: a time on a key picks the segment before", "tweenrender/core/timing/timeline.py",
           'np.searchsorted(starts, times, side="right")', 'np.searchsorted(starts, times, side="left")', TIMELINE),
    # -- encode --------------------------------------------------------------------------------------
    Mutant("PNG sink: fewer frames than expected accepted", "tweenrender/encode/sinks.py",
           "if self.count != self.expected:", "if self.count > self.expected:", ENCODE),
    Mutant("video sink: the frame count not checked", "tweenrender/encode/sinks.py",
           "if frames != self.expected or size != (self.width, self.height):",
           "if size != (self.width, self.height):", ENCODE),
    Mutant("video sink: abort leaves the temporary", "tweenrender/encode/sinks.py",
           "            self.process.wait()\n        discard(self.temporary)\n        self.log.close()",
           "            self.process.wait()\n        self.log.close()", ENCODE + ("tests/cli/test_reliability.py",)),
    Mutant("render: the sink told the wrong frame count", "tweenrender/pipeline/stream.py",
           "job.rate, len(indices), pixel_format=layout,", "job.rate, len(indices) + 1, pixel_format=layout,",
           ENCODE),
    Mutant("render: video at the default rate", "tweenrender/pipeline/stream.py",
           "sink = open_sink(fmt, target, width, height, job.rate,",
           "sink = open_sink(fmt, target, width, height, 24.0,", ENCODE),
    Mutant("ffmpeg: frame rate rounded to whole frames", "tweenrender/encode/sinks.py",
           '"-framerate", f"{fps:g}"', '"-framerate", f"{round(fps)}"', ENCODE),
    Mutant("probe: the first progress line's frame count", "tweenrender/encode/sinks.py",
           "return int(counts[-1]), (", "return int(counts[0]), (", ENCODE),
    Mutant("chunks: parts joined in reverse", "tweenrender/pipeline/chunks.py",
           "for future, size in zip(futures, sizes):", "for future, size in zip(futures[::-1], sizes[::-1]):",
           ("tests/pipeline/test_workers.py", "tests/pipeline/test_chunks.py")),
    Mutant("yuv420: U and V planes swapped", "tweenrender/encode/yuv420.py",
           "in ((self.u, _U), (self.v, _V)):", "in ((self.u, _V), (self.v, _U)):", ENCODE),
    Mutant("yuv420: chroma of the left pixel of each pair only", "tweenrender/encode/yuv420.py",
           "np.add(full[:, 0::2], full[:, 1::2], out=", "np.add(full[:, 0::2], full[:, 0::2], out=", ENCODE),
    Mutant("yuv420: chroma rows averaged in pairs, not filtered", "tweenrender/encode/yuv420.py",
           "CHROMA_TAPS = (-1, -3, 8, 28, 28, 8, -3, -1)", "CHROMA_TAPS = (0, 0, 0, 32, 32, 0, 0, 0)", ENCODE),
    Mutant("yuv420: the picture's top row not repeated above it", "tweenrender/encode/yuv420.py",
           "    out[:lead] = out[lead]\n", "", ENCODE),
    Mutant("yuv420: Y without its 16 levels of foot", "tweenrender/encode/yuv420.py",
           "_Y_OFFSET = np.uint32((16 << _Y_SHIFT) + (1 << (_Y_SHIFT - 1)))",
           "_Y_OFFSET = np.uint32(1 << (_Y_SHIFT - 1))", ENCODE),
    Mutant("ffmpeg: yuv420p planes sent without their colour tags", "tweenrender/encode/sinks.py",
           'tags = YUV420_TAGS if pixel_format == "yuv420p" else []', "tags = []",
           ENCODE + ("tests/pipeline/test_chunks.py",)),
    Mutant("sink: a transparent WebM sent as yuv420p", "tweenrender/encode/sinks.py",
           "return TABLE[fmt].yuv420 and not alpha and width", "return TABLE[fmt].yuv420 and width", ENCODE),
    Mutant("formats: odd sizes allowed for H.264", "tweenrender/encode/formats.py",
           "if self.even and (width % 2 or height % 2):", "if False:", ENCODE),
    Mutant("formats: ffmpeg's picture check ignored", "tweenrender/encode/formats.py",
           "if self.ffmpeg and 8 * (width + 128) * (height + 128) >= PICTURE_LIMIT:", "if False:", ENCODE),
    Mutant("ffmpeg: no death signal", "tweenrender/encode/lifeline.py",
           "        _set_death_signal()\n        if os.getppid() != parent:",
           "        if os.getppid() != parent:", ("tests/encode/test_lifeline.py", "tests/cli/test_signals.py")),
    # -- raster: the compiled round stroke -----------------------------------------------------------
    Mutant("round stroke: no second edge where two cross a pixel", "tweenrender/raster/_stroke_kernel.py",
           "if c < 1.0 and second > 0.0:", "if False:", STROKE),
    Mutant("round stroke: two edges' common part without the edge lines' own", "tweenrender/raster/_stroke_kernel.py",
           "return 0.25 * sides + 0.5 * (u1 * first + u2 * second)", "return 0.25 * sides", STROKE),
    Mutant("round stroke: the second edge line turned the other way", "tweenrender/raster/_stroke_kernel.py",
           "second = _line_inside(u2, n2x, n2y, -cross,", "second = _line_inside(u2, n2x, n2y, cross,", STROKE),
    Mutant("round stroke: a side on an edge line counted twice", "tweenrender/raster/_stroke_kernel.py",
           "out1, out2 = u1 > 0.0, u2 > 0.0", "out1, out2 = False, False", STROKE),
    Mutant("round stroke: the nearest interior offset not kept as the second", "tweenrender/raster/_stroke_kernel.py",
           "state[x, _X_2], state[x, _Y_2] = state[x, _X], state[x, _Y]", "pass", STROKE),
    Mutant("kernels: numba's BLAS probe imports scipy.linalg again", "tweenrender/core/jit.py",
           "\n_load_array_maths()\n", "\n", ("tests/core/test_jit.py",)),
    Mutant("round stroke: reach of half a pixel, not half a diagonal", "tweenrender/raster/_stroke_kernel.py",
           "_HALF_DIAGONAL = 0.7072", "_HALF_DIAGONAL = 0.5", STROKE),
    Mutant("round stroke: the stroke's alpha ignored where it blends", "tweenrender/raster/_stroke_kernel.py",
           "keep = 1.0 - alpha * c", "keep = 1.0 - c", STROKE),
    Mutant("round stroke: a closed outline's last segment left out", "tweenrender/raster/_stroke_kernel.py",
           "j = start + (i + 1) % n", "j = start + min(i + 1, n - 1)", STROKE),
    Mutant("round stroke: the clip box ignored", "tweenrender/raster/round_stroke.py",
           "left, top, right, bottom = clip if clip is not None else (0, 0, wide, height)",
           "left, top, right, bottom = (0, 0, wide, height)", STROKE),
    Mutant("round stroke: drawn under a layer onto the surface", "tweenrender/raster/round_stroke.py",
           'if top is None or np.asarray(top).__array_interface__["data"][0] != address:', "if top is None:",
           STROKE),
    # -- atomic writes and targets -------------------------------------------------------------------
    Mutant("roll-back deletes the old folder", "tweenrender/encode/atomic.py",
           "            if old is not None:\n                os.replace(old, target)\n            raise",
           "            if old is not None:\n                shutil.rmtree(old, ignore_errors=True)\n            raise",
           ATOMIC),
    Mutant("commit: copy instead of an atomic move", "tweenrender/encode/atomic.py",
           "        _fsync(temporary)\n        os.replace(temporary, target)",
           "        _fsync(temporary)\n        shutil.copyfile(temporary, target)", ATOMIC),
    Mutant("replacing: temporary kept on an interrupt", "tweenrender/encode/atomic.py",
           "    except BaseException:\n        discard(temporary)\n        raise",
           "    except BaseException:\n        raise", ("tests/encode/test_atomic.py", "tests/cli")),
    Mutant("sweep: a live process's temporaries removed", "tweenrender/encode/atomic.py",
           "if not match or alive(int(match.group(1))):", "if not match:", ATOMIC),
    Mutant("sweep: a stepped-aside folder not put back", "tweenrender/encode/atomic.py",
           'if match.group(2) == ".old" and not target.exists():', "if False:", ATOMIC),
    Mutant("prepare: an unwritable folder not reported", "tweenrender/encode/atomic.py",
           "if not os.access(parent, os.W_OK):", "if False:", ATOMIC),
    Mutant("frame names: any suffix accepted", "tweenrender/encode/targets.py",
           'FRAME_NAME = re.compile(r"frame_\\d{4,}\\.png")', 'FRAME_NAME = re.compile(r"frame_\\d{4,}\\.png.*")',
           OWNED),
    Mutant("manifest: one that is a folder taken for an empty list", "tweenrender/encode/manifest.py",
           'return f"its {MANIFEST} is not a file"', "return {}", OWNED),
    Mutant("manifest: another tool's list taken for ours", "tweenrender/encode/manifest.py",
           "if data.get(\"written_by\") != _STAMP or not isinstance(files, dict):", "if not isinstance(files, dict):",
           OWNED),
    Mutant("manifest: a file changed since not noticed", "tweenrender/encode/manifest.py",
           'if (info.st_size, info.st_mtime_ns) != (entry["bytes"], entry["mtime_ns"]):', "if False:", OWNED),
    Mutant("manifest: an unlisted entry accepted", "tweenrender/encode/manifest.py",
           "if entry is None or not ours(name):", "if entry is not None and not ours(name):", OWNED),
    Mutant("report: a shape name left unescaped in the table", "tweenrender/reports/html_report.py",
           'where = _esc(entry["name"])', 'where = entry["name"]', ("tests/cli/test_names.py",)),
    Mutant("svg reader: nested viewport scaled by max (slice) not min (meet)", "tweenrender/scenefile/svg_viewport.py",
           'if words[1:2] == ["slice"] else min(sx, sy)', 'if words[1:2] == ["slice"] else max(sx, sy)', DRAWING),
    Mutant("svg reader: display none drawn", "tweenrender/scenefile/svg_document.py",
           'return own.get("display", "").strip() == "none"', 'return own.get("display", "").strip() == "None"', DRAWING),
    Mutant("contours: size term of pairing zeroed", "tweenrender/core/contours.py",
           "+ _SIZE_WEIGHT * np.abs(sa[:, None] - sb[None]))", "+ 0.0 * np.abs(sa[:, None] - sb[None]))",
           ("tests/core/test_contours.py",)),
    Mutant("svg reader: css !important declarations not applied", "tweenrender/scenefile/svg_css.py",
           "    for important in (False, True):", "    for important in (False,):",
           ("tests/scenefile/test_svg_css.py",)),
    Mutant("svg reader: a pipe not named as one", "tweenrender/scenefile/svg_document.py",
           '(stat.S_ISFIFO, "a pipe (FIFO)"),', "",
           ("tests/scenefile/test_hostile_inputs.py",)),
    Mutant("svg reader: an infinite transform number accepted", "tweenrender/scenefile/svg_document.py",
           "        if not math.isfinite(float(number)):", "        if False:", ("tests/scenefile/test_hostile_inputs.py",)),
    Mutant("scene: key count not limited", "tweenrender/scenefile/scene_limits.py",
           "        if count > LIMITS[what]:", "        if count > 10 * LIMITS[what]:",
           ("tests/scenefile/test_hostile_inputs.py",)),
    Mutant("output name: no room left for the temporary", "tweenrender/encode/targets.py",
           "    allowed = most - _TEMPORARY_EXTRA", "    allowed = most", ("tests/cli/test_names.py",)),
    Mutant("cluster: any scheme accepted", "tweenrender/plan/cluster_address.py",
           '    if scheme != "tcp":', '    if scheme == "ucx":', CLUSTER),
    Mutant("cluster: an out-of-range port accepted", "tweenrender/plan/cluster_address.py",
           "        if not 1 <= port <= 65535:", "        if not 1 <= port:", CLUSTER),
    Mutant("cluster: a silent listener taken for a scheduler", "tweenrender/pipeline/cluster.py",
           "                probe(where)\n", "                pass\n", CLUSTER),
    Mutant("frames folder: not checked again before the swap", "tweenrender/encode/sinks.py",
           "            check_frames_folder(self.target)  # again", "            pass  # again", ATOMIC),
    Mutant("output name: a parent folder accepted", "tweenrender/encode/targets.py",
           'elif target.name == "..":', 'elif target.name == "...":', ATOMIC),
    Mutant("commit: the old link or folder left beside the target", "tweenrender/encode/atomic.py",
           "        discard(old)  # a folder", "        pass  # a folder", ATOMIC),
    Mutant("signals: a hang-up not handled", "tweenrender/cli/main.py",
           '("SIGTERM", "SIGHUP")', '("SIGTERM",)', ("tests/cli/test_signals.py",)),
    Mutant("keyframes: the tolerance taken as its square", "tweenrender/vector/keyframes.py",
           "limit = tolerance * tolerance", "limit = tolerance", VECTOR),
    Mutant("keyframes: the full check skipped after the screen", "tweenrender/vector/keyframes.py",
           "        if _within(values, a, int(b), limit):", "        if True:", VECTOR),
    Mutant("keyframes: a fitted end taken off its room", "tweenrender/vector/keyframes.py",
           "offset = np.clip(room.least[0], room.lo[0], room.hi[0])", "offset = room.least[0]", VECTOR),
    Mutant("keyframes: a timed span held to the whole tolerance", "tweenrender/vector/keyframes.py",
           "lambda b: _eased(values, a, start, b, limit * EASED_SHARE)", "lambda b: _eased(values, a, start, b, limit)",
           VECTOR),
    Mutant("keyframes: the last fitted keyframe not exact", "tweenrender/vector/keyframes.py",
           "    if b == len(values) - 1:\n        return values[b]", "    if False:\n        return values[b]", VECTOR),
    Mutant("keyframes: a span's timing written with its handles swapped", "tweenrender/vector/keyframes.py",
           "(1 / 3, p, 2 / 3, q)", "(1 / 3, q, 2 / 3, p)", VECTOR),
    Mutant("lottie: fill rules swapped", "tweenrender/encode/lottie.py",
           '_FILL_RULES = {"nonzero": 1, "evenodd": 2}', '_FILL_RULES = {"nonzero": 2, "evenodd": 1}', VECTOR),
    Mutant("lottie: layers hand over at the key frame (rlottie draws both)", "tweenrender/encode/lottie.py",
           "_EARLY_IN, _EARLY_OUT = 0.499, 0.501", "_EARLY_IN, _EARLY_OUT = 0.0, 0.0", VECTOR),
    Mutant("lottie: easing handles' x and y swapped", "tweenrender/encode/lottie_values.py",
           'key["o"] = {"x": [x1], "y": [y1]}', 'key["o"] = {"x": [y1], "y": [x1]}', VECTOR),
    Mutant("lottie: a baked span's own timing dropped", "tweenrender/encode/lottie_values.py",
           "(eases[index] if eases else STRAIGHT)", "(STRAIGHT)", VECTOR),
    Mutant("svg: a baked span's own timing dropped", "tweenrender/encode/smil.py",
           "splines = list(eases) or [STRAIGHT] * (len(frames) - 1)", "splines = [STRAIGHT] * (len(frames) - 1)",
           VECTOR),
    Mutant("svg: keyTimes over F - 1 frames", "tweenrender/encode/smil.py",
           "times = [f / total for f in frames]", "times = [f / (total - 1) for f in frames]", VECTOR),
    Mutant("vector: the keyframes given the whole bound, the curve fit's share forgotten", "tweenrender/vector/export.py",
           "return max(max_error - fitted - 2 * _ROUNDING,", "return max(max_error - 2 * _ROUNDING,", VECTOR),
    Mutant("lottie: tangents written as points, not relative to their vertex", "tweenrender/encode/lottie_values.py",
           '"i": compact(points[:, 0] - vertex)', '"i": compact(points[:, 0])', VECTOR),
    Mutant("curves: a singular fit solved exactly", "tweenrender/vector/curves.py",
           "return np.linalg.pinv(normal + ridge * np.trace(normal) / 2 * np.eye(2)) @ basis.T",
           "return np.linalg.solve(normal + ridge * np.trace(normal) / 2 * np.eye(2), basis.T)", VECTOR),
    Mutant("vector: a linear segment's easing dropped", "tweenrender/vector/export.py",
           "ease = _timing(segment) or STRAIGHT", "ease = STRAIGHT", VECTOR),
    Mutant("vector paint: a radial gradient's ellipse turned the other way", "tweenrender/vector/paint_keys.py",
           "angle[f], ratio[f] = np.degrees(theta),", "angle[f], ratio[f] = -np.degrees(theta),", PAINT),
    Mutant("vector paint: a linear gradient's ends swapped", "tweenrender/vector/paint_keys.py",
           "return start, start + g / float(g @ g)", "return start + g / float(g @ g), start", PAINT),
    Mutant("vector paint: no stops between those changing colour and alpha", "tweenrender/vector/paint_keys.py",
           "int(np.ceil(np.sqrt(worst / 4.0 / _HALF_STEP)))", "1", PAINT),
    Mutant("lottie: a clip path of several contours left out", "tweenrender/encode/lottie_paint.py",
           "    if not several:\n        return None", "    if True:\n        return None", PAINT),
    # -- start-up, memory and the preview ------------------------------------------------------------
    Mutant("assignment: column potentials raised instead of lowered", "tweenrender/core/correspondence/assignment.py",
           "v[used] -= delta", "v[used] += delta", ("tests/core/test_assignment.py",)),
    Mutant("small search: ties go to the diagonal step", "tweenrender/core/correspondence/_small_dtw.py",
           "better = diagonal < left", "better = diagonal <= left", ("tests/core/test_small_dtw.py",)),
    Mutant("small search: the last start met among equals", "tweenrender/core/correspondence/_small_dtw.py",
           "start = next(s for s in _start_order(n) if costs[s] == best)",
           "start = [s for s in _start_order(n) if costs[s] == best][-1]", ("tests/core/test_small_dtw.py",)),
    Mutant("checkpointed search: a stretch recomputed from the checkpoint before", "tweenrender/core/correspondence/_lean_dtw.py",
           "prev[:] = checkpoints[stretch, :]", "prev[:] = checkpoints[max(stretch - 1, 0), :]",
           ("tests/core/test_lean_dtw.py",)),
    Mutant("divide and conquer: a middle start's band the overlap, not the hull, of its bounding paths",
           "tweenrender/core/correspondence/_cyclic_dtw.py",
           "hi[i] = min(mid + n, max(row_last[slot_lo, i], row_last[slot_hi, i]))",
           "hi[i] = min(mid + n, min(row_last[slot_lo, i], row_last[slot_hi, i]))",
           ("tests/core/test_correspond.py", "tests/core/test_lean_dtw.py")),
    Mutant("workers: the memory budget ignored", "tweenrender/pipeline/workers.py",
           "        if tree_mib(fmt, pixels, processes) > memory_budget_mib(pixels):\n            break",
           "        if False:\n            break", ("tests/pipeline/test_chunks.py",)),
    Mutant("preview: a bad save replaces the shown take", "tweenrender/preview/takes.py",
           "            elif error is not None:\n                self.error = error",
           "            elif error is not None:\n                self.error, self.take = error, None",
           ("tests/preview/test_preview.py",)),
    # -- this round's start-up and memory work -------------------------------------------------------
    Mutant("boxes: the sample count read from the wrong field", "tweenrender/encode/media_boxes.py",
           'return struct.unpack_from(">I", stsz, 8)[0]', 'return struct.unpack_from(">I", stsz, 4)[0]',
           ("tests/encode/test_media_boxes.py",)),
    Mutant("boxes: width and height read 4 bytes early", "tweenrender/encode/media_boxes.py",
           'struct.unpack_from(">HH", stsd, 8 + 32)', 'struct.unpack_from(">HH", stsd, 8 + 28)',
           ("tests/encode/test_media_boxes.py",)),
    Mutant("boxes: any track taken for the video", "tweenrender/encode/media_boxes.py",
           'if handler[8:12] != b"vide":', 'if False:', ("tests/encode/test_media_boxes.py",)),
    Mutant("webm: a laced block counted as one frame", "tweenrender/encode/webm_elements.py",
           "(self.data[at + 3] + 1 if laced else 1)", "1", ("tests/encode/test_webm_elements.py",)),
    Mutant("webm: blocks in block groups not counted", "tweenrender/encode/webm_elements.py",
           "                    if child == _BLOCK:", "                    if False:",
           ("tests/encode/test_webm_elements.py",)),
    Mutant("webm: every track's blocks counted", "tweenrender/encode/webm_elements.py",
           "return frames.get(number, 0), picture", "return sum(frames.values()), picture",
           ("tests/encode/test_webm_elements.py",)),
    Mutant("webm: a cluster of unknown size runs to the segment's end", "tweenrender/encode/webm_elements.py",
           "            if kind in _TOP_LEVEL:\n", "            if False:\n",
           ("tests/encode/test_webm_elements.py",)),
    Mutant("gif: an image's local colour table not skipped", "tweenrender/encode/gif_blocks.py",
           "at + 10 + _colour_table(data[at + 9]) + 1", "at + 10 + 1", ("tests/encode/test_gif_blocks.py",)),
    Mutant("gif: extensions counted as frames", "tweenrender/encode/gif_blocks.py",
           "            at = _after_sub_blocks(data, at + 2, end)\n",
           "            at = _after_sub_blocks(data, at + 2, end)\n            frames += 1\n",
           ("tests/encode/test_gif_blocks.py",)),
    Mutant("gif: no trailer taken as the end", "tweenrender/encode/gif_blocks.py",
           '            raise ValueError("cut short: no trailer")', "            return frames, (width, height)",
           ("tests/encode/test_gif_blocks.py",)),
    Mutant("point arrays: an integer -0 lifted", "tweenrender/scenefile/point_arrays.py",
           "        if _INTEGER_MINUS_ZERO.search(body):", "        if False:",
           ("tests/scenefile/test_point_arrays.py",)),
    Mutant("point arrays: coordinates past the range lifted", "tweenrender/scenefile/point_arrays.py",
           "or not (np.abs(values) <= limit).all():", "or not np.isfinite(values).all():",
           ("tests/scenefile/test_point_arrays.py",)),
    Mutant("point arrays: lines after an array renumbered", "tweenrender/scenefile/point_arrays.py",
           '"\\n" * body.count("\\n")]', '""]', ("tests/scenefile/test_point_arrays.py",)),
    Mutant("point arrays: a lifted parse kept after an error", "tweenrender/scenefile/load.py",
           "                if not arrays.keys() - reader.read_arrays:\n                    return scene",
           "                return scene", ("tests/scenefile/test_point_arrays.py",)),
    Mutant("frame blocks: the old block kept while the next is made", "tweenrender/pipeline/frames.py",
           "            self._blocks.pop(method, None)", "            pass", ("tests/pipeline/test_frame_blocks.py",)),
    Mutant("frame blocks: no vertex budget", "tweenrender/pipeline/frames.py",
           "min(_BLOCK, _BLOCK_POINTS // max(points, 1))", "_BLOCK", ("tests/pipeline/test_frame_blocks.py",)),
    Mutant("exit: quick even with a thread to wait for", "tweenrender/cli/main.py",
           'if "llvmlite" not in sys.modules or waits:', 'if "llvmlite" not in sys.modules:',
           ("tests/cli/test_quick_exit.py",)),
    Mutant("exit: handlers skipped", "tweenrender/cli/main.py",
           "    atexit._run_exitfuncs()\n", "", ("tests/cli/test_quick_exit.py",)),
    Mutant("ffmpeg search: not waited for on the way out", "tweenrender/cli/render.py",
           "        encoder_search_done()\n    return 0", "        pass\n    return 0",
           ("tests/encode/test_sinks.py",)),
    # -- steering: turn direction, arcs, breakdowns, init ---------------------------------------------
    Mutant("steering: cw turns the short way", "tweenrender/core/timing/steering.py",
           "base = phi - TAU if phi > 0 else phi", "base = phi", STEERING),
    Mutant("steering: whole turns the other way", "tweenrender/core/timing/steering.py",
           "return base + TAU * turns", "return base - TAU * turns", STEERING),
    Mutant("steering: arc weight 2t(1 - t)", "tweenrender/core/timing/steering.py",
           "weight = (4.0 * t * (1.0 - t))", "weight = (2.0 * t * (1.0 - t))", STEERING),
    Mutant("steering: arcs shared by vertex count", "tweenrender/core/timing/steering.py",
           "share = (s - s_a) / (s_b - s_a) if s_b > s_a else 0.0",
           "share = (v - a) / (b - a) if b > a else 0.0", STEERING),
    Mutant("steering: the halves do not share the turn", "tweenrender/core/timing/timeline.py",
           "delta = whole_turns_to(target, h0, h1)", "delta = 0.0", STEERING),
    Mutant("steering: a breakdown at its time, not its favour", "tweenrender/core/timing/timeline.py",
           "f = np.array([float(key.breakdown)])",
           "f = np.array([(key.time - keys[k - 1].time) / (keys[end].time - keys[k - 1].time)])", STEERING),
    Mutant("init: replaces an existing scene", "tweenrender/encode/atomic.py",
           "        os.link(temporary, target)", "        os.replace(temporary, target)", ("tests/cli/test_init.py",)),
    # -- limits and temporaries ---------------------------------------------------------------------
    Mutant("scratch: a folder whose owner runs swept", "tweenrender/encode/scratch.py",
           "if not runs or (own and int(pid) == os.getpid()):", "if True:", ("tests/encode/test_scratch.py",)),
    Mutant("scratch: an owner's start time not compared", "tweenrender/encode/scratch.py",
           "(started == 0 or now == 0 or now == started)", "True", ("tests/encode/test_scratch.py",)),
    Mutant("pairing: a pair that saves nothing kept", "tweenrender/scenefile/drawings.py",
           "for r, c in zip(rows, cols) if saving[r, c] < 0.0]", "for r, c in zip(rows, cols)]",
           ("tests/scenefile/test_element_pairing.py",)),
    Mutant("spread: subnormal edges measured by their squares", "tweenrender/core/balance.py",
           "first, second = float(np.hypot(*(corner - before))), float(np.hypot(*(after - corner)))",
           "first, second = float(np.linalg.norm(corner - before)), float(np.linalg.norm(after - corner))",
           ("tests/core/test_balance.py",)),
    # -- the preview server: who may ask, how long and how many ----------------------------------------
    Mutant("preview server: Origin not checked", "tweenrender/preview/server.py",
           "(origin is None or origin in self.server.origins)", "True", SERVER_ORIGIN),
    Mutant("preview server: Origin null taken for no page", "tweenrender/preview/server.py",
           "(origin is None or origin in self.server.origins)",
           "(origin in (None, \"null\") or origin in self.server.origins)", SERVER_ORIGIN),
    Mutant("preview server: Sec-Fetch-Site not checked", "tweenrender/preview/server.py",
           ' \\\n                and site in (None, "same-origin", "none"):', ":", SERVER_ORIGIN),
    Mutant("preview server: Host not checked", "tweenrender/preview/server.py",
           'headers.get("Host", "") in self.server.hosts and ', "", SERVER_HOST),
    Mutant("preview server: Host taken without its port", "tweenrender/preview/server.py",
           'self.hosts = {f"127.0.0.1:{port}", f"localhost:{port}"}',
           'self.hosts = {f"127.0.0.1:{port}", f"localhost:{port}", "127.0.0.1", "localhost"}', SERVER_HOST),
    Mutant("preview server: state answered without the token", "tweenrender/preview/server.py",
           'if not self.server.token_matches(query.get("token", [None])[0]):', "if False:", SERVER_TOKEN),
    Mutant("preview server: a POST's token not checked", "tweenrender/preview/server.py",
           "if not isinstance(payload, dict) or not self.server.token_matches(payload.get(\"token\")):",
           "if not isinstance(payload, dict):", SERVER_TOKEN),
    Mutant("preview server: token compared as a prefix", "tweenrender/preview/server.py",
           "hmac.compare_digest(given.encode(), self.token.encode())", "self.token.startswith(given)",
           SERVER_TOKEN),
    Mutant("preview server: one token for every run", "tweenrender/preview/server.py",
           "self.token = secrets.token_urlsafe(24)", 'self.token = "tweenrender-preview-token-0"', SERVER_TOKEN),
    Mutant("preview server: no timeout on a silent connection", "tweenrender/preview/server.py",
           "timeout = REQUEST_SECONDS  # the socket's", "timeout = None  # the socket's", SERVER_CONNECTIONS),
    Mutant("preview server: no cap on threads", "tweenrender/preview/server.py",
           "if not self._slots.acquire(blocking=False):", "if False:", SERVER_CONNECTIONS),
    Mutant("preview server: a connection's slot not given back", "tweenrender/preview/server.py",
           "        finally:\n            self._slots.release()", "        finally:\n            pass",
           SERVER_CONNECTIONS),
    Mutant("preview server: a body of any length read", "tweenrender/preview/server.py",
           "if not 0 <= length <= _MAX_BODY:", "if not 0 <= length:", SERVER_TOKEN),
    # -- the scene writer: what init writes, the preview's edits ---------------------------------------
    Mutant("scene writer: init's times without the hold", "tweenrender/scenefile/scene_writer.py",
           "period = float(step) + float(hold)", "period = float(step)", INIT),
    Mutant("scene writer: init's hold left out", "tweenrender/scenefile/scene_writer.py",
           'lines.append(f"hold = {_number(hold)}")', "pass", INIT),
    Mutant("scene writer: init's ease left out", "tweenrender/scenefile/scene_writer.py",
           'lines.append(f"ease = {_string(ease)}")', "pass", INIT),
    Mutant("scene writer: init's stagger left out", "tweenrender/scenefile/scene_writer.py",
           'lines.append(f"stagger = {_number(stagger)}")', "pass", INIT),
    Mutant("scene writer: init's file names absolute", "tweenrender/scenefile/scene_writer.py",
           "names = [os.path.relpath(Path(p).absolute(), folder.absolute()) for p in drawings]",
           "names = [str(Path(p).absolute()) for p in drawings]", INIT),
    Mutant("scene writer: init's file names unescaped", "tweenrender/scenefile/scene_writer.py",
           "return json.dumps(text, ensure_ascii=False)", "return f'\"{text}\"'", INIT),
    Mutant("scene writer: init's times to six digits", "tweenrender/scenefile/scene_writer.py",
           "return repr(float(value))", 'return f"{float(value):g}"', INIT),
    Mutant("scene writer: an edit drops the comments", "tweenrender/scenefile/scene_edits.py",
           "    return tomlkit.dumps(document)\n\n\ndef written_tables",
           "    return tomlkit.dumps(document.unwrap())\n\n\ndef written_tables", EDITS),
    Mutant("scene writer: unhint leaves its arc", "tweenrender/scenefile/scene_edits.py",
           "        if arcs is not None and letter in arcs:  # an arc belongs to its hint",
           "        if False:  # an arc belongs to its hint", EDITS),
    Mutant("scene writer: an ease kept beside a spacing chart", "tweenrender/scenefile/scene_edits.py",
           'if "spacing" in table:  # a key has', "if False:  # a key has", EDITS),
    Mutant("scene writer: a key index one past the end accepted", "tweenrender/scenefile/scene_edits.py",
           "if not 0 <= self.index < len(keys):", "if not 0 <= self.index <= len(keys):", EDITS),
    Mutant("scene writer: a negative key index counted from the end", "tweenrender/scenefile/scene_edits.py",
           "if not 0 <= self.index < len(keys):", "if not -len(keys) <= self.index < len(keys):", EDITS),
    Mutant("scene writer: a hint letter of several letters", "tweenrender/scenefile/scene_edits.py",
           '_LETTER = re.compile(r"[a-z]")', '_LETTER = re.compile(r"[a-z]+")', EDITS),
    Mutant("scene writer: a breakdown inserted before its key", "tweenrender/scenefile/scene_edits.py",
           "keys.insert(self.index + 1, entry)", "keys.insert(self.index, entry)", EDITS),
    Mutant("scene writer: a baked hint at the key before's place", "tweenrender/scenefile/scene_edits.py",
           "nearest_point((1.0 - f) * a + f * b,", "nearest_point(a,", EDITS),
    Mutant("scene writer: undo over the user's own save", "tweenrender/preview/edits.py",
           "            if now != self._written:", "            if False:", PREVIEW_EDITS),
    Mutant("scene writer: drawings' scene written over an existing file", "tweenrender/preview/edits.py",
           "        if not os.path.lexists(path):", "        if True:", PREVIEW_EDITS),
    Mutant("scene writer: the scene saved for drawings not announced", "tweenrender/preview/edits.py",
           "                    self.announce(str(path))", "                    pass", PREVIEW_EDITS),
    # -- the SVG reader: units, cascade, viewports, error rules ----------------------------------------
    Mutant("svg reader: an <image>'s preserveAspectRatio ignored", "tweenrender/scenefile/svg_image.py",
           'fit = aspect_matrix(box, w, h, node.attrs.get("preserveAspectRatio", "xMidYMid meet").strip())',
           'fit = aspect_matrix(box, w, h, "none")', ("tests/scenefile/test_svg_images.py",)),
    Mutant("svg reader: pixelated pictures blended", "tweenrender/scenefile/svg_image.py",
           "rendering not in _NEAREST)", "True)", ("tests/scenefile/test_svg_images.py",)),
    Mutant("svg reader: Q read as a millimetre", "tweenrender/scenefile/svg_lengths.py",
           "return number * 96.0 / 25.4 / 4.0", "return number * 96.0 / 25.4", SVG_UNITS),
    Mutant("svg reader: ex a whole em", "tweenrender/scenefile/svg_lengths.py",
           '_PER_UNIT = {"em": 1.0, "ex": 0.5, "ch": 0.5}', '_PER_UNIT = {"em": 1.0, "ex": 1.0, "ch": 0.5}',
           SVG_UNITS),
    Mutant("svg reader: vmin the larger side", "tweenrender/scenefile/svg_lengths.py",
           '"vmin": min(width, height)', '"vmin": max(width, height)', SVG_UNITS),
    Mutant("svg reader: rem read as em", "tweenrender/scenefile/svg_lengths.py",
           'value = number * (rem if unit == "rem" else', 'value = number * (em if unit == "rem" else', SVG_UNITS),
    Mutant("svg reader: inline style below the sheets", "tweenrender/scenefile/svg_css.py",
           "layers = (*sheet, inline)", "layers = (inline, *sheet)", SVG_CSS),
    Mutant("svg reader: presentation attributes over the sheets", "tweenrender/scenefile/svg_css.py",
           "if strong is important and name in wanted)",
           "if strong is important and name in wanted and name not in presentation)", SVG_CSS),
    Mutant("svg reader: rules inside @media left out", "tweenrender/scenefile/svg_css.py",
           '_APPLIED_AT_RULES = ("media", "supports")', '_APPLIED_AT_RULES = ("supports",)', SVG_CSS),
    Mutant("svg reader: a sheet of another type read as CSS", "tweenrender/scenefile/svg_css.py",
           'return kind in ("", "text/css")', "return True", SVG_CSS),
    Mutant("svg reader: xMax aligned as xMid", "tweenrender/scenefile/svg_viewport.py",
           'where = {"Min": 0.0, "Mid": 0.5, "Max": 1.0}', 'where = {"Min": 0.0, "Mid": 0.5, "Max": 0.5}',
           SVG_VIEW),
    Mutant("svg reader: preserveAspectRatio none kept uniform", "tweenrender/scenefile/svg_viewport.py",
           'if align != "none":', "if True:", SVG_VIEW),
    Mutant("svg reader: the viewBox's origin ignored", "tweenrender/scenefile/svg_viewport.py",
           "-x * sx + (width - w * sx) * fx", "(width - w * sx) * fx", SVG_VIEW),
    Mutant("svg reader: overflow visible still clipped", "tweenrender/scenefile/svg_viewport.py",
           'clipped = overflow.strip().lower() not in ("visible", "auto")', "clipped = True", SVG_VIEW),
    Mutant("svg reader: a viewBox of zero width accepted", "tweenrender/scenefile/svg_viewport.py",
           "numbers[2] <= 0 or numbers[3] <= 0", "numbers[2] < 0 or numbers[3] < 0", SVG_VIEW),
    Mutant("svg reader: a comma between a command's numbers refused", "tweenrender/scenefile/svg_pathdata.py",
           "position = (_SEPARATORS if k else _SPACE).match(", "position = _SPACE.match(", SVG_ERRORS),
    Mutant("svg reader: arc flags read as numbers", "tweenrender/scenefile/svg_pathdata.py",
           "if arc and k in (3, 4):", "if False:", SVG_ERRORS),
    Mutant("svg reader: numbers after a moveto repeat it", "tweenrender/scenefile/svg_pathdata.py",
           '            command = "L" if command == "M" else "l"', "            pass", SVG_ERRORS),
    Mutant("svg reader: a path not starting with a moveto drawn", "tweenrender/scenefile/svg_pathdata.py",
           'if not out and command not in "Mm":', "if False:", SVG_ERRORS),
    Mutant("svg reader: T read with four numbers, as Q", "tweenrender/scenefile/svg_pathdata.py",
           '"T": 2,', '"T": 4,', SVG_ERRORS),
]


def run_tests(tree: Path, tests: tuple[str, ...], timeout: float) -> tuple[str, float]:
    """'passed', 'failed' or 'timeout' for ``tests`` run in ``tree``, and the seconds it took;
    pytest's report is left in ``tree/../pytest.log``."""
    env = {**os.environ, "PYTHONPATH": str(tree), "PYTHONDONTWRITEBYTECODE": "1"}
    started = time.monotonic()
    command = [sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", "-o", "addopts=",
               "--hypothesis-seed=0", *tests]
    with open(tree.parent / "pytest.log", "wb") as log:
        process = subprocess.Popen(command, cwd=tree, env=env, stdout=log, stderr=subprocess.STDOUT,
                                   start_new_session=True)
        try:
            code = process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, 9)
            process.wait()
            return "timeout", time.monotonic() - started
    if code not in (0, 1):
        raise RuntimeError(f"pytest exited {code} for {' '.join(tests)} (collection error or no tests)")
    return ("passed" if code == 0 else "failed"), time.monotonic() - started


def main(argv: list[str]) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("-k", default="", help="only mutants whose name contains one of these words "
                                               "(separated by spaces or commas)")
    parser.add_argument("--list", action="store_true", help="list the mutants and stop")
    parser.add_argument("--timeout", type=float, default=300.0, help="seconds per test run (default 300)")
    parser.add_argument("--required", type=float, default=90.0, help="percent to kill (default 90)")
    args = parser.parse_args(argv)
    words = [w for w in args.k.lower().replace(",", " ").split()] or [""]
    mutants = [m for m in MUTANTS if any(w in m.name.lower() for w in words)]
    if not mutants:
        print(f"no mutant's name contains {args.k!r}")
        return 2
    if args.list:
        for m in mutants:
            print(f"{m.file}: {m.name}")
        print(f"{len(mutants)} mutants")
        return 0
    with tempfile.TemporaryDirectory(prefix="tweenrender-mutants-") as folder:
        tree = Path(folder) / "tree"
        shutil.copytree(ROOT, tree, ignore=SKIP)
        for m in mutants:  # every mutant must still apply to the code as it is
            found = (tree / m.file).read_text().count(m.before)
            if found != 1:
                print(f"stale mutant {m.name!r}: its text occurs {found} times in {m.file}")
                return 2
        targets = tuple(sorted({t for m in mutants for t in m.tests}))
        print(f"unmutated tree: {' '.join(targets)} ...", flush=True)
        fate, seconds = run_tests(tree, targets, args.timeout * 4)
        if fate != "passed":
            report = (tree.parent / "pytest.log").read_text(errors="replace").splitlines()
            print("\n".join(report[-30:]))
            print(f"the unmutated tree does not pass its own tests ({fate}); nothing to measure")
            return 2
        print(f"  passed in {seconds:.0f} s\n", flush=True)
        killed = 0
        for number, m in enumerate(mutants, start=1):
            path = tree / m.file
            original = path.read_text()
            path.write_text(original.replace(m.before, m.after))
            try:
                fate, seconds = run_tests(tree, m.tests, args.timeout)
            finally:
                path.write_text(original)
            dead = fate != "passed"
            killed += dead
            word = {"failed": "killed", "timeout": "killed (timeout)", "passed": "SURVIVED"}[fate]
            print(f"{number:3d}. {word:17} {seconds:5.0f} s  {m.file}: {m.name}", flush=True)
    score = 100.0 * killed / len(mutants)
    print(f"\n{killed} of {len(mutants)} mutants killed: {score:.1f} % (required {args.required:g} %)")
    return 0 if score >= args.required else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
