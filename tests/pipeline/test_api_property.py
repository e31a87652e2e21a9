"""Every public function, given arbitrary values, returns a result or raises a TweenrenderError: never a
TypeError, OverflowError, AttributeError, a warning, or a crash. Whole numbers are kept small or far out of
range (so a valid draw stays cheap: no 16384-pixel frame, no 200 processes); everything else is arbitrary."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

import tweenrender as tr
from tweenrender.errors import TweenrenderError

from tests.helpers import SQUARE, write_scene

SMALL = SQUARE.replace("size = [320, 240]", "size = [32, 24]").replace("time = 2\n", "time = 0.25\n")

_scalars = st.one_of(
    st.none(), st.booleans(),
    st.integers(-3, 3), st.sampled_from([10**9, 2**63, -2**63, 10**400, 16385]),
    st.floats(allow_nan=True, allow_infinity=True), st.sampled_from([1.5, -0.0, 1e308, 5e-324]),
    st.text(max_size=12), st.sampled_from(["linear", "rigid", "none", "#fff", "0:2", "-1", "local:0", "bogus",
                                           "tcp://[::1", "auto", "png", "gif", "\x00", "\ud800"]),
    st.binary(max_size=6),
)
ARBITRARY = st.recursive(_scalars, lambda inner: st.one_of(st.lists(inner, max_size=3), st.tuples(inner, inner),
                                                           st.dictionaries(st.text(max_size=4), inner, max_size=2)),
                         max_leaves=6)
SETTINGS = settings(max_examples=100, deadline=None, derandomize=True,
                    suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])


@pytest.fixture(scope="module")
def scene(tmp_path_factory: pytest.TempPathFactory) -> tr.Scene:
    return tr.load_scene(write_scene(tmp_path_factory.mktemp("scene"), SMALL))


def _only_result_or_refusal(call) -> None:  # type: ignore[no-untyped-def]
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a warning is a failure too
        try:
            result = call()
            if hasattr(result, "__next__"):
                for _ in zip(range(3), result):
                    pass
        except TweenrenderError as error:
            assert str(error) and "\n" not in str(error), repr(str(error))


def _outputs(tmp: Path):  # type: ignore[no-untyped-def]
    """Arbitrary values, or a name in ``tmp`` (never anywhere else) with any suffix."""
    names = st.sampled_from(["o.mp4", "o.gif", "o.webm", "o.png", "o", "o.svg", "o.txt", ".", "o.mov"])
    return st.one_of(ARBITRARY.filter(lambda v: not isinstance(v, (str, bytes))), names.map(lambda n: tmp / n))


@given(path=ARBITRARY, step=ARBITRARY)
@SETTINGS
def test_load_scene(path: object, step: object) -> None:
    if isinstance(path, str) and path:  # a text is a path: only names that cannot exist here
        path = f"/nonexistent/{path!r}"
    if isinstance(path, (list, tuple)):
        path = [f"/nonexistent/{p!r}.svg" if isinstance(p, str) else p for p in path]
    _only_result_or_refusal(lambda: tr.load_scene(path, step))  # type: ignore[arg-type]


@given(scene_value=st.one_of(st.just("scene"), ARBITRARY), time=ARBITRARY, method=ARBITRARY, size=ARBITRARY,
       background=ARBITRARY)
@SETTINGS
def test_frame_and_outlines(scene: tr.Scene, scene_value: object, time: object, method: object, size: object,
                            background: object) -> None:
    target = scene if scene_value == "scene" else scene_value
    _only_result_or_refusal(lambda: tr.frame(target, time, method=method, size=size, background=background))
    _only_result_or_refusal(lambda: tr.outlines(target, time, method=method))
    _only_result_or_refusal(lambda: tr.contours(target, time, method=method))
    _only_result_or_refusal(lambda: tr.frames(target, method=method, size=size, fps=time))


OPTION_NAMES = ["method", "compare", "format", "size", "fps", "frames", "background", "balance", "cost", "align",
                "equal_counts", "max_memory", "paths", "onion", "strip", "workers", "cluster", "max_frames", "progress", "nonsense"]


@given(data=st.data())
@SETTINGS
def test_write(scene: tr.Scene, tmp_path_factory: pytest.TempPathFactory, data: st.DataObject) -> None:
    tmp = tmp_path_factory.mktemp("write")
    path = data.draw(_outputs(tmp))
    options = data.draw(st.dictionaries(st.sampled_from(OPTION_NAMES), ARBITRARY, max_size=3))
    if isinstance(options.get("cluster"), str) and options["cluster"].lower().startswith("local"):
        options["cluster"] = "local:0"  # never start a cluster here; the refusal is what is tested
    _only_result_or_refusal(lambda: tr.write(scene, path, **options))


@given(data=st.data())
@SETTINGS
def test_reports_and_documents(scene: tr.Scene, tmp_path_factory: pytest.TempPathFactory,
                               data: st.DataObject) -> None:
    tmp = tmp_path_factory.mktemp("docs")
    value = data.draw(ARBITRARY)
    path = data.draw(_outputs(tmp))
    _only_result_or_refusal(lambda: tr.stats(scene, t=value))
    _only_result_or_refusal(lambda: tr.stats(scene, methods=value))
    _only_result_or_refusal(lambda: tr.correspondence(scene, path if data.draw(st.booleans()) else None, cost=value))
    _only_result_or_refusal(lambda: tr.qcurves(value if not isinstance(value, tr.Scene) else scene))
    _only_result_or_refusal(lambda: tr.describe(value))
    _only_result_or_refusal(lambda: tr.sheet(scene, path, methods=value, count=data.draw(ARBITRARY),
                                             size=(32, 24)))


@given(k0=ARBITRARY, t=ARBITRARY, method=ARBITRARY)
@SETTINGS
def test_interpolate(k0: object, t: object, method: object) -> None:
    square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
    _only_result_or_refusal(lambda: tr.interpolate(k0, square, t, method))  # type: ignore[arg-type]
    _only_result_or_refusal(lambda: tr.interpolate(square, square, t, method))  # type: ignore[arg-type]


@given(text=st.text(max_size=60), fmt=ARBITRARY)
@SETTINGS
def test_parse_scene(text: str, fmt: object) -> None:
    _only_result_or_refusal(lambda: tr.parse_scene(text, "scene.toml", fmt))  # type: ignore[arg-type]


@given(text=ARBITRARY, path=ARBITRARY)
@SETTINGS
def test_parse_scene_of_anything(text: object, path: object) -> None:
    if isinstance(path, str):
        path = f"/nonexistent/{path!r}.toml"
    _only_result_or_refusal(lambda: tr.parse_scene(text, path))  # type: ignore[arg-type]


@given(options=ARBITRARY, k0=ARBITRARY)
@SETTINGS
def test_write_with_anything_as_options(scene: tr.Scene, tmp_path_factory: pytest.TempPathFactory,
                                        options: object, k0: object) -> None:
    tmp = tmp_path_factory.mktemp("options")
    _only_result_or_refusal(lambda: tr.write(scene, tmp / "o.gif", options=options))  # type: ignore[arg-type]
    _only_result_or_refusal(lambda: tr.interpolate([[0, 0], [1e-300, 0], [0, 1e-300]], [[0, 0]] * 3, k0, "auto"))


def test_the_property_tests_can_fail() -> None:
    """The check itself: a raw TypeError is not accepted."""
    with pytest.raises(TypeError):
        _only_result_or_refusal(lambda: math.floor("x"))  # type: ignore[arg-type]


@pytest.mark.parametrize("fps", [10**400, -10**400])
def test_a_frame_rate_too_large_for_a_float_is_refused(scene: tr.Scene, tmp_path: Path, fps: int) -> None:
    """Found by test_write: float(10**400) raises OverflowError."""
    with pytest.raises(tr.OptionError, match="fps=: expected 1 to 240 frames per second"):
        tr.write(scene, tmp_path / "x.mp4", fps=fps)
    with pytest.raises(tr.OptionError, match="fps=: expected 1 to 240"):
        next(tr.frames(scene, fps=fps))


SQUARE_KEY = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]]
NAN_KEY = [[0.0, 0.0], [1.0, 0.0], [math.nan, 1.0], [0.0, 1.0]]


def _refused(call, kind: type, named: str) -> None:  # type: ignore[no-untyped-def]
    """``call`` refuses with ``kind`` (no other exception, no warning), its one line naming ``named``."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        with pytest.raises(kind) as refusal:
            call()
    assert named in str(refusal.value) and "\n" not in str(refusal.value), str(refusal.value)


@pytest.mark.parametrize("text, path, fmt, named", [
    (None, "s.toml", "toml", "text"),
    (b"[scene]", "s.toml", "toml", "text"),
    ("[scene]", None, "toml", "path"),
    ("[scene]", "s.toml", None, "fmt"),
])
def test_parse_scene_refuses_what_is_not_text_and_a_name(text: object, path: object, fmt: object, named: str) -> None:
    _refused(lambda: tr.parse_scene(text, path, fmt), tr.OptionError, f"{named}=")  # type: ignore[arg-type]


@pytest.mark.parametrize("step", [10**400, -10**400, math.nan, math.inf, 0, -1, 1e308])
def test_load_scene_refuses_a_step_out_of_range(scene: tr.Scene, step: object) -> None:
    _refused(lambda: tr.load_scene(scene.path, step), tr.OptionError, "step=")  # type: ignore[arg-type]
    drawing = Path(__file__).parents[2] / "scenes" / "svg"
    svgs = sorted(drawing.glob("*.svg"))[:2]
    _refused(lambda: tr.load_scene(svgs, step), tr.OptionError, "step=")  # type: ignore[arg-type]


@pytest.mark.parametrize("k0, t, named", [
    (NAN_KEY, [0.5], "k0"), ([[math.inf, 0.0], *SQUARE_KEY[1:]], [0.5], "k0"),
    (SQUARE_KEY, [math.nan], "t"), (SQUARE_KEY, [1e308], "t"), (SQUARE_KEY, -math.inf, "t"),
])
@pytest.mark.parametrize("method", ["linear", "rigid", "arap", "auto"])
def test_interpolate_refuses_nan_and_overflowing_times(k0: object, t: object, named: str, method: str) -> None:
    _refused(lambda: tr.interpolate(k0, SQUARE_KEY, t, method), tr.GeometryError, f"{named}:")  # type: ignore[arg-type]


@pytest.mark.parametrize("options, named", [
    (tr.RenderOptions(size=(0, 0)), "size="), (tr.RenderOptions(fps=-5), "fps="),
    (tr.RenderOptions(onion=-1), "onion="), (tr.RenderOptions(method="bogus"), "method="),
    ({"fps": 3}, "options="),
])
def test_write_checks_options_built_directly(scene: tr.Scene, tmp_path: Path, options: object, named: str) -> None:
    _refused(lambda: tr.write(scene, tmp_path / "o.mp4", options=options), tr.OptionError, named)  # type: ignore[arg-type]
    assert not list(tmp_path.iterdir())


@pytest.mark.parametrize("time", [1e308, -1e308, math.nan, 10**400])
def test_a_time_out_of_range_is_refused_or_drawn_without_warning(scene: tr.Scene, time: float) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        try:
            picture = tr.frame(scene, time)
        except tr.OptionError as error:
            assert "time=" in str(error)
        else:
            assert picture.shape == (24, 32, 4)
