"""The scene as loaded: frozen dataclasses over read-only float64 arrays.

A :class:`Scene` holds :class:`Shape` s painted in order. A shape lives through its
:class:`Key` s; each key is one or more :class:`Contour` s (outer outlines, holes,
open strokes) and the :class:`Paint` they are drawn with at that time.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
import numpy as np
from numpy.typing import NDArray

__all__ = [
    "Points", "Color", "BALANCES", "DEFAULT_BALANCE", "COSTS", "ALIGNS", "EQUAL_COUNTS",
    "FILL_RULES", "CAPS", "JOINS", "TURNS", "UNMATCHED", "DEFAULT_FILL", "Contour", "Dash", "Paint", "Hint", "Key",
    "Joint",
    "Shape", "Matching", "Scene", "DrawnContour", "Gradient", "MaskShape", "Mask", "frozen_points",
    "DEFAULT_MAX_MEMORY",
]

Points = NDArray[np.float64]
"""A contour: shape ``(N, 2)``, float64, world units, y up; closed implicitly unless said open."""

Color = tuple[int, int, int, int]
"""Straight (unpremultiplied) RGBA, each 0..255."""

BALANCES: tuple[str, ...] = ("copies", "spread")
DEFAULT_BALANCE = "copies"
"""The balance rule of scenes that name none (benchmarks/balance_rules.py measured the two)."""
COSTS: tuple[str, ...] = ("distance", "sg")
ALIGNS: tuple[str, ...] = ("none", "centroid")
EQUAL_COUNTS: tuple[str, ...] = ("drawn", "match")
FILL_RULES: tuple[str, ...] = ("nonzero", "evenodd")
CAPS: tuple[str, ...] = ("butt", "round", "square")
JOINS: tuple[str, ...] = ("miter", "round", "bevel")
TURNS: tuple[str, ...] = ("cw", "ccw", "shortest")
"""A key's ``turn``: the direction its segment's rigid frame turns (maths §5.13)."""
DEFAULT_MAX_MEMORY = 2 << 30
"""Bytes the exact ``sg`` correspondence search's tables may take (``Matching.max_memory``): 2 GiB."""
UNMATCHED: tuple[str, ...] = ("grow", "fade")
"""What a contour or element without a partner in the next key does: grow from (shrink to) a point, or fade."""

DEFAULT_FILL: Color = (59, 111, 216, 255)


def frozen_points(points: object) -> Points:
    """A read-only float64 ``(N, 2)`` copy of ``points``."""
    array = np.array(points, dtype=np.float64, copy=True).reshape(-1, 2)
    array.flags.writeable = False
    return array


@dataclass(frozen=True, slots=True)
class Contour:
    """One outline of a key: ``points (N, 2)``; ``closed`` joins the last vertex to the first.

    An open contour is stroked as a polyline; filled (as SVG does) as if closed.
    """

    points: Points
    closed: bool = True


@dataclass(frozen=True, slots=True)
class Gradient:
    """A linear or radial gradient fill, as SVG defines it, in world units.

    ``geometry`` is ``(x1, y1, x2, y2)`` (linear) or ``(cx, cy, r, fx, fy)`` (radial, with the focal radius
    ``fr`` after them when it is not 0) in the gradient's
    own space; ``matrix`` ``(a, b, c, d, e, f)`` maps that space to the world (``x' = a·x + c·y + e``,
    ``y' = b·x + d·y + f``: the element's transforms, its bounding box for ``objectBoundingBox``
    units, and ``gradientTransform``). ``stops`` are ``(offset in [0, 1], straight RGBA)`` in order;
    ``spread`` is ``pad``, ``reflect`` or ``repeat``.
    """

    kind: str
    geometry: tuple[float, ...]
    matrix: tuple[float, float, float, float, float, float]
    stops: tuple[tuple[float, Color], ...]
    spread: str = "pad"


@dataclass(frozen=True, slots=True)
class Dash:
    """A stroke's dash pattern, as SVG's ``stroke-dasharray`` and ``stroke-dashoffset`` resolve it: ``lengths``
    dash, gap, dash, gap … (an even count, each ≥ 0, summing to more than 0), and ``offset``, how far into the
    pattern each subpath starts; both in the stroke width's units. The pattern is laid along each contour
    by arc length, starting afresh on each one."""

    lengths: tuple[float, ...]
    offset: float = 0.0


@dataclass(frozen=True, slots=True)
class Paint:
    """How a key is drawn: fill and stroke colours (``None``: not drawn), stroke width, opacity.

    ``stroke_width`` is in pixels, or in world units for shapes whose ``stroke_scales``
    (drawings: widths scale with the view, as in the SVG). ``opacity`` multiplies both.
    ``gradient``, when set, fills instead of ``fill`` (which then holds its stops' mean colour);
    ``stroke_gradient`` likewise strokes instead of ``stroke``; ``pattern`` and ``stroke_pattern`` (a tile of
    shapes repeated) fill and stroke instead of both, ``fill`` and ``stroke`` then holding the tile's mean colour.
    ``dash``, when set, dashes the stroke (``None``: a solid stroke).
    """

    fill: Color | None = DEFAULT_FILL
    stroke: Color | None = None
    stroke_width: float = 2.0
    opacity: float = 1.0
    gradient: Gradient | None = None
    dash: Dash | None = None
    stroke_gradient: Gradient | None = None
    pattern: Pattern | None = None
    stroke_pattern: Pattern | None = None

    @property
    def visible(self) -> bool:
        """Whether anything would be drawn with this paint."""
        fills = self.fill is not None and self.fill[3] > 0
        strokes = self.stroke is not None and self.stroke[3] > 0 and self.stroke_width > 0
        return self.opacity > 0 and (fills or strokes)


@dataclass(frozen=True, slots=True)
class MaskShape:
    """One shape of a mask's content, in world units: its contours, paint (stroke width in world units) and
    drawing rules, and the clip regions and masks on it."""

    contours: tuple[Contour, ...]
    paint: Paint
    fill_rule: str = "nonzero"
    cap: str = "butt"
    join: str = "miter"
    miter_limit: float = 4.0
    clips: tuple[tuple[Contour, ...], ...] = ()
    masks: tuple[Mask, ...] = ()


@dataclass(frozen=True, slots=True, eq=False)
class Pattern:
    """A pattern paint, as SVG's ``<pattern>``: ``shapes`` (contours in the pattern's own units, y down) drawn
    within the tile ``(x, y, width, height)`` (what lies outside it is cut off), the tile repeated over the
    plane; ``matrix`` ``(a, b, c, d, e, f)`` maps the pattern's units to the world (as a gradient's), and
    ``opacity`` multiplies the whole tile (``fill-opacity`` or ``stroke-opacity``); ``share`` is how much of
    the paint the tile is, the rest its plain colour beneath (1 at a key; between a key with a pattern and
    one without, the pattern fades in or out). A picture (SVG's ``<image>``) is a pattern of one tile,
    ``image`` ``(H, W, 4)`` straight RGBA over the tile ``(0, 0, W, H)`` (a pixel a unit), not repeated: its
    edge pixels reach on (the element drawn with it covers no more than the picture), blended or, without
    ``smooth``, the nearest. ``beneath`` is what lies under the share the tile is not (between two keys'
    patterns, the first key's; None: the plain colour). Patterns are equal only to themselves (their shapes
    hold arrays)."""

    tile: tuple[float, float, float, float]
    matrix: tuple[float, float, float, float, float, float]
    shapes: tuple[MaskShape, ...]
    opacity: float = 1.0
    share: float = 1.0
    image: NDArray[np.uint8] | None = None
    smooth: bool = True
    beneath: Pattern | None = None


@dataclass(frozen=True, slots=True)
class Mask:
    """An SVG mask in world units: what it lets through of an element at each point is its content's
    luminance times alpha there (``alpha``: the alpha alone; ``linear``: the luminance of its colours in
    linear RGB), inside ``region`` (closed contours, nonzero), times the masks on the mask itself."""

    region: tuple[Contour, ...]
    shapes: tuple[MaskShape, ...]
    alpha: bool = False
    masks: tuple[Mask, ...] = ()
    linear: bool = False


@dataclass(frozen=True, slots=True)
class Hint:
    """A shape hint: ``letter`` (a–z) sits on vertex ``vertex`` of contour ``contour`` of its key
    (snapped onto the outline when the scene was read); the same letter of the next key is its partner."""

    letter: str
    contour: int
    vertex: int


@dataclass(frozen=True, slots=True)
class Key:
    """A keyframe: its time in seconds, its contours, the easing of the segment it starts, its paint.

    ``hidden`` marks where an element appearing in the next key grows from (or one
    leaving after the previous key shrinks to): it is interpolated towards, never
    drawn on its own. ``fill_rule``, ``cap``, ``join`` and ``miter_limit`` ``None`` are the shape's
    (a drawing's keys carry their own). ``layer`` is a drawing's key's place in that drawing's
    paint order (0 first; ``None`` for shapes of a scene file, painted in file order); ``clips``
    its SVG clip paths in world units, ``masks`` its SVG masks.
    ``ease`` is the easing as the scene writes it (``"spacing"`` for a spacing chart); ``easing`` the
    curve it names (a :mod:`.core.timing.easing` object, a spacing chart included; ``None``: parsed
    from ``ease`` when the timeline is built). ``hints`` are this key's shape
    hints; ``delay`` the seconds after ``time`` at which the segment starting here starts to
    move (a stagger or a hold; it still ends on time).
    Steering of the segment starting here (maths §5.13–5.15): ``turn`` (``"cw"``, ``"ccw"``,
    ``"shortest"``; ``None``: not set, the shortest) and ``turns`` (extra whole turns) choose its rigid
    frame's total turn; ``arcs`` are ``(letter, (x, y))``: the vertex hinted ``letter`` passes through
    ``(x, y)`` at the segment's middle. A *breakdown* key has ``breakdown`` (its favour ``f``); its
    contours are the in-between at ``f`` of the segment it splits, made when the scene is read (and
    again by the timeline under the correspondence in force).
    """

    time: float
    contours: tuple[Contour, ...]
    ease: str = "linear"
    paint: Paint = field(default_factory=Paint)
    hidden: bool = False
    fill_rule: str | None = None
    cap: str | None = None
    join: str | None = None
    miter_limit: float | None = None
    layer: int | None = None
    # clip regions (closed contours, nonzero), every one intersected with what the key draws
    clips: tuple[tuple[Contour, ...], ...] = ()
    easing: object | None = None
    hints: tuple[Hint, ...] = ()
    delay: float = 0.0
    turn: str | None = None
    turns: int = 0
    arcs: tuple[tuple[str, tuple[float, float]], ...] = ()
    breakdown: float | None = None
    masks: tuple[Mask, ...] = ()  # SVG masks, every one multiplied into what the key draws
    # the SVG groups with an opacity it is drawn in, outermost first: (group number, opacity); the elements
    # of one group are composited together, then drawn at its opacity (as SVG's group opacity)
    groups: tuple[tuple[int, float], ...] = ()

    @property
    def points(self) -> Points:
        """The first contour's points: the whole outline of a one-contour key."""
        return self.contours[0].points

    @classmethod
    def outline(cls, time: float, points: object, ease: str = "linear", paint: Paint | None = None) -> Key:
        """A key of one closed outline ``points (N, 2)``."""
        return cls(time, (Contour(frozen_points(points)),), ease, paint or Paint())


Joint = tuple[int, int]
"""A chord between two vertex indices of a shape's first key."""


@dataclass(frozen=True, slots=True)
class Shape:
    """A named element of the scene and its keys (strictly increasing times).

    ``method`` ``None`` is the scene's method; ``balance`` ``None`` the scene's;
    ``unmatched`` ``None`` the scene's rule for contours without a partner.
    """

    name: str
    keys: tuple[Key, ...]
    method: str | None = None
    joints: tuple[Joint, ...] = ()
    fill_rule: str = "nonzero"
    cap: str = "round"
    join: str = "round"
    miter_limit: float = 4.0
    stroke_scales: bool = False  # True: stroke widths are world units (drawings), else pixels
    unmatched: str | None = None
    balance: str | None = None  # None: the scene's balance
    # keys of equal vertex counts: None follows the scene's [correspondence]; drawings say "match",
    # since the order an SVG editor wrote a contour in is no animator's correspondence
    equal_counts: str | None = None
    stagger: float = 0.0  # seconds between the starts of the shape's contours in each segment

    @property
    def paint(self) -> Paint:
        """The first key's paint."""
        return self.keys[0].paint

    @property
    def fill(self) -> Color | None:
        return self.keys[0].paint.fill

    @property
    def stroke(self) -> Color | None:
        return self.keys[0].paint.stroke


@dataclass(frozen=True, slots=True)
class Matching:
    """How keys with different vertex counts are put in correspondence (maths §2)."""

    cost: str = "distance"
    align: str = "centroid"
    # keys of equal vertex counts: keep the drawn order ("drawn") or search them too ("match")
    equal_counts: str = "drawn"
    # Sederberg–Greenwood constants (maths §2.1)
    ks: float = 1.0
    cs: float = 0.5
    es: float = 2.0
    kb: float = 1.0
    eb: float = 2.0
    mb: float = 10.0
    pb: float = 1000.0
    # bytes the sg search's tables may take: a search that would need more is refused before it starts
    max_memory: int = DEFAULT_MAX_MEMORY


@dataclass(frozen=True, slots=True)
class Scene:
    shapes: tuple[Shape, ...]
    title: str | None = None
    size: tuple[int, int] = (1280, 720)
    fps: float = 24.0
    background: Color = (255, 255, 255, 255)
    view: tuple[float, float, float, float] | None = None  # None: fit every key
    method: str = "nonlinear"
    compare: tuple[str, ...] = ("linear", "nonlinear")
    matching: Matching = field(default_factory=Matching)
    path: Path | None = None
    unmatched: str = "grow"
    balance: str = DEFAULT_BALANCE  # how balancing places copies of a vertex (maths §5.6)
    end_hold: float = 0.0  # seconds the last keys stay after the last key's time (drawings' --hold)
    sources: tuple[Path, ...] = ()  # every file the scene was read from: the scene file, SVG keys, drawings

    @property
    def duration(self) -> float:
        """Seconds from time 0 to the last key of any shape, and its hold."""
        return max((shape.keys[-1].time for shape in self.shapes), default=0.0) + self.end_hold

    def method_of(self, shape: Shape) -> str:
        return shape.method or self.method

    def balance_of(self, shape: Shape) -> str:
        return shape.balance or self.balance


@dataclass(frozen=True, slots=True)
class DrawnContour:
    """One contour as drawn at a time: ``points (N, 2)`` in scene units, y up, as ``outlines`` gives
    them (``reversed``: drawn in the other direction, so that it winds as in its key); ``closed`` (False: an open stroke, never filled); ``hole`` (inside an odd
    number of its element's closed contours); ``element`` (the SVG id, else the loader's name, e.g.
    ``path1``; a scene file's shape name); its element's ``fill_rule``; ``fill`` and ``stroke`` as
    straight RGBA floats in [0, 1] (``None``: not drawn); ``stroke_width`` in scene units; ``opacity``.
    """

    points: Points
    closed: bool
    hole: bool
    element: str
    fill_rule: str
    fill: tuple[float, float, float, float] | None
    stroke: tuple[float, float, float, float] | None
    stroke_width: float
    opacity: float
    reversed: bool = False
    gradient: Gradient | None = None  # a gradient fill (``fill`` then holds its stops' mean colour)
