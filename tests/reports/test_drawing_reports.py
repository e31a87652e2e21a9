"""Every report on pairs of real drawings: per element and contour, never "nothing moves" while
something moves, and the HTML report of a drawing pair in a real headless browser."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

import tweenrender as tr
from tweenrender.reports.match_report import correspond_dict, correspond_text, write_match_picture
from tweenrender.reports.metric_report import metric_panels, write_metric_plot
from tweenrender.reports.qcurve_report import qcurves_dict, qcurves_text, write_qcurve_plot
from tweenrender.reports.stats import stats_dict, stats_text

from ..browser import chromium, open_page, page_url
from ..helpers import DATA

ICONS = DATA / "icons"
PAIRS = [  # holes, several pieces, open strokes, evenodd, many colours, stacking that changes
    ("mdi/alpha-a.svg", "mdi/alpha-o-box.svg"),
    ("feather/smile.svg", "bootstrap/emoji-smile.svg"),
    ("heroicons/check-circle.svg", "octicons/sun-24.svg"),
    ("tabler/circle-check.svg", "tabler/sun.svg"),
    ("twemoji/1f4c4.svg", "twemoji/1f69a.svg"),
    ("simple-icons/github.svg", "lucide/apple.svg"),
]


@pytest.mark.parametrize("a, b", PAIRS, ids=[f"{a}->{b}" for a, b in PAIRS])
def test_every_report_works_on_a_drawing_pair_per_element_and_contour(a: str, b: str, tmp_path: Path) -> None:
    scene = tr.load_scene([ICONS / a, ICONS / b])
    names = {shape.name for shape in scene.shapes}
    stats = stats_dict(scene, [0.5], ["linear", "auto"])
    matches = correspond_dict(scene)
    curves = qcurves_dict(scene)
    for report in (stats, matches, curves):
        # the measures take contours in both keys (closed ones): a pair without says why it has none
        assert report["shapes"] or "grow" in report["note"]
        for entry in report["shapes"]:
            assert entry["element"] in names and isinstance(entry["contour"], int)
    assert "nothing moves" not in stats_text(stats) + qcurves_text(curves)
    assert "no shape has two keys" not in correspond_text(matches)
    assert len(metric_panels(scene, ["linear"])) == min(len(stats["shapes"]), 12)
    write_metric_plot(scene, ["linear"], tmp_path / "metrics.png")
    write_match_picture(scene, matches, tmp_path / "m.png")
    write_qcurve_plot(curves, tmp_path / "q.png")
    assert all((tmp_path / name).stat().st_size > 1000 for name in ("m.png", "q.png", "metrics.png"))


def test_open_strokes_that_move_are_not_said_to_stand_still() -> None:
    # feather's check is one open polyline: the measures of closed outlines have nothing to take,
    # but the report must not say that nothing moves
    scene = tr.load_scene([ICONS / "feather" / "check.svg", ICONS / "feather" / "heart.svg"])
    words = stats_text(stats_dict(scene, [0.5], ["linear"]))
    assert "nothing moves" not in words and "open strokes" in words
    assert "no shape has two keys" not in correspond_text(correspond_dict(scene))


def test_the_pictures_of_open_strokes_alone_say_why_they_have_no_panel() -> None:
    """The charts and the Q-curve plot of a pair whose moving contours are open strokes have no panel; they say
    what the text reports say (the measures need closed outlines), drawn as the same note would be, never
    that nothing moves."""
    from tweenrender.raster.plots.metric_plot import metrics_picture
    from tweenrender.raster.plots.qcurve_plot import qcurves_picture
    from tweenrender.reports.metric_report import metrics_png
    from tweenrender.reports.qcurve_report import report_picture
    from tweenrender.reports.segments import nothing_measured

    scene = tr.load_scene([ICONS / "feather" / "check.svg", ICONS / "tabler" / "letter-a.svg"])
    note = nothing_measured(scene)
    assert "nothing moves" not in note
    charts = metrics_png(scene, ["linear"])
    assert np.array_equal(charts, metrics_picture([], note=note))
    assert not np.array_equal(charts, metrics_picture([], note="no shape has two keys: nothing moves"))
    curves = qcurves_dict(scene)
    assert np.array_equal(report_picture(curves), qcurves_picture([], note=curves["note"]))
    assert not np.array_equal(report_picture(curves), qcurves_picture([], note="no shape has two keys: nothing moves"))


def test_the_report_of_a_drawing_pair_in_a_real_browser(tmp_path: Path) -> None:
    if chromium() is None:
        pytest.skip("Debian's chromium is not installed (apt-get install chromium); .ci/run installs it")
    from tweenrender.reports.html_report import write_report

    # the ringed letter A becomes the apple's red body (the leaf and the stalk grow), so contours move
    scene = tr.load_scene([ICONS / "mdi" / "alpha-a-circle-outline.svg", ICONS / "twemoji" / "1f34e.svg"])
    index = write_report(scene, tmp_path / "report", ["linear", "auto"])
    text = index.read_text()
    assert "element " in text and ", contour " in text
    seen = open_page(page_url(index))
    assert seen.errors == []
    videos = [m for m in seen.media if m["tag"] == "video"]
    images = [m for m in seen.media if m["tag"] == "img"]
    assert len(videos) == 2 and len(images) == 3
    for video in videos:
        assert video["error"] is None and video["readyState"] >= 2 and video["width"] > 0, video
    for image in images:
        assert image["complete"] and image["naturalWidth"] > 0, image
    import imageio.v3 as iio

    shot = np.asarray(iio.imread(seen.screenshot, extension=".png"))
    assert len(np.unique(shot.reshape(-1, shot.shape[-1]), axis=0)) > 50


def test_the_report_says_where_the_paint_order_switches(tmp_path: Path) -> None:
    from tweenrender.reports.html_report import write_report

    index = write_report(tr.load_scene([ICONS / "twemoji" / "1f4c4.svg", ICONS / "twemoji" / "1f69a.svg"]),
                         tmp_path / "report", ["linear"])
    text = index.read_text()
    assert "Paint order" in text and "the paint order switches at" in text and "/32)" in text


@pytest.mark.parametrize("a, b", [("twemoji/1f60e", "tabler/mood-smile"), ("simple-icons/github", "bootstrap/emoji-smile")])
def test_the_correspondence_of_a_contour_joined_by_a_slit_is_reported_on_the_joined_contour(a: str, b: str) -> None:
    """Where a contour without room is joined into its neighbour (maths §5.17), the pair's vertex pairs
    index the joined contour: the report names its vertex counts and every pair stays within them (before,
    the keys' own contours were read beside the joined one's pairs: a broadcast error, exit 1)."""
    scene = tr.load_scene([DATA / "icons" / f"{a}.svg", DATA / "icons" / f"{b}.svg"], step=1.0)
    report = correspond_dict(scene)
    assert report["shapes"]
    for entry in report["shapes"]:
        pairs = np.asarray(entry["pairs"])
        assert len(pairs) == entry["balanced"]
        assert pairs[:, 0].max() < entry["counts"][0] and pairs[:, 1].max() < entry["counts"][1]
        assert sorted(set(pairs[:, 0].tolist())) == list(range(entry["counts"][0]))  # every vertex paired
        assert sorted(set(pairs[:, 1].tolist())) == list(range(entry["counts"][1]))
