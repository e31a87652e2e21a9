"""Pattern paints as skia shaders: a :class:`~tweenrender.model.Pattern`'s tile recorded as a picture, repeated,
placed through a viewport; and the shaders an element's paint fills and strokes with."""

from __future__ import annotations

import numpy as np
import skia

from ..core.view import Viewport
from ..model import Paint, Pattern
from .surface import paint_color

__all__ = ["pattern_shader", "paint_shaders"]

_CAPS = {"butt": skia.Paint.kButt_Cap, "round": skia.Paint.kRound_Cap, "square": skia.Paint.kSquare_Cap}
_JOINS = {"miter": skia.Paint.kMiter_Join, "round": skia.Paint.kRound_Join, "bevel": skia.Paint.kBevel_Join}


def pattern_shader(pattern: Pattern, viewport: Viewport) -> skia.Shader | None:
    """The shader that paints ``pattern`` on a canvas drawn through ``viewport``; None where it cannot be
    placed (an empty tile, a flat matrix, non-finite numbers)."""
    x, y, w, h = pattern.tile
    a, b, c, d, e, f = pattern.matrix
    # the tile recorded from its own corner: pattern units → pixels, through the tile's corner
    full = viewport.matrix @ np.array([[a, c, e], [b, d, f], [0.0, 0.0, 1.0]]) @ np.array(
        [[1.0, 0.0, x], [0.0, 1.0, y], [0.0, 0.0, 1.0]])
    if not (w > 0 and h > 0 and np.all(np.isfinite(full)) and np.all(np.isfinite(pattern.tile))):
        return None
    matrix = skia.Matrix.MakeAll(*(float(v) for v in full[0]), *(float(v) for v in full[1]), 0.0, 0.0, 1.0)
    if not matrix.invert(skia.Matrix()):
        return None
    if pattern.image is not None:
        return _picture_shader(pattern, matrix)
    tile = skia.Rect.MakeWH(w, h)
    recorder = skia.PictureRecorder()
    canvas = recorder.beginRecording(tile)
    canvas.clipRect(tile)
    canvas.translate(-x, -y)
    layered = pattern.opacity < 1.0
    if layered:
        canvas.saveLayerAlpha(None, int(round(255 * max(pattern.opacity, 0.0))))
    for shape in pattern.shapes:
        _draw(canvas, shape)
    if layered:
        canvas.restore()
    picture = recorder.finishRecordingAsPicture()
    return picture.makeShader(skia.TileMode.kRepeat, skia.TileMode.kRepeat, skia.FilterMode.kLinear, matrix, tile)


_PICTURES: dict[int, tuple[np.ndarray, skia.Image]] = {}  # the pictures made lately, by their pixels' id
_KEPT_PICTURES = 8


def _picture(pixels: np.ndarray) -> skia.Image:
    """The skia image of ``pixels (H, W, 4)`` (straight RGBA), made once while it is drawn frame after frame."""
    found = _PICTURES.get(id(pixels))
    if found is not None and found[0] is pixels:
        return found[1]
    image = skia.Image.fromarray(np.ascontiguousarray(pixels), colorType=skia.ColorType.kRGBA_8888_ColorType,
                                 alphaType=skia.AlphaType.kUnpremul_AlphaType)
    if len(_PICTURES) >= _KEPT_PICTURES:
        _PICTURES.pop(next(iter(_PICTURES)))
    _PICTURES[id(pixels)] = (pixels, image)  # the pixels kept with it: their id is not reused meanwhile
    return image


def _picture_shader(pattern: Pattern, matrix: skia.Matrix) -> skia.Shader:
    """A picture's shader (its pixels, straight RGBA, premultiplied by skia), edge pixels reaching on."""
    image = _picture(pattern.image)  # type: ignore[arg-type]
    sampling = skia.SamplingOptions(skia.FilterMode.kLinear if pattern.smooth else skia.FilterMode.kNearest)
    shader = image.makeShader(skia.TileMode.kClamp, skia.TileMode.kClamp, sampling, matrix)
    if pattern.opacity < 1.0:
        shader = skia.Shaders.Blend(skia.BlendMode.kDstIn, shader,
                                    skia.Shaders.Color(skia.Color4f(0.0, 0.0, 0.0, max(pattern.opacity, 0.0))))
    return shader


def _draw(canvas: skia.Canvas, shape: object) -> None:
    """One shape of a tile (a :class:`~tweenrender.model.MaskShape`, the pattern's units) in its plain colours,
    or a picture's pixels."""
    paint = shape.paint  # type: ignore[attr-defined]
    path = skia.Path()
    for contour in shape.contours:  # type: ignore[attr-defined]
        points = np.asarray(contour.points, dtype=np.float64)
        if len(points) >= 2 and np.all(np.isfinite(points)):
            path.addPoly([skia.Point(float(px), float(py)) for px, py in points], bool(contour.closed))
    even = shape.fill_rule == "evenodd"  # type: ignore[attr-defined]
    path.setFillType(skia.PathFillType.kEvenOdd if even else skia.PathFillType.kWinding)
    opacity = max(min(paint.opacity, 1.0), 0.0)
    if paint.fill is not None and paint.fill[3] > 0:
        fill = skia.Paint(AntiAlias=True, Color=paint_color(paint.fill, opacity))
        picture = paint.pattern
        if picture is not None and picture.image is not None:  # a picture in the tile: its pixels
            a, b, c, d, e, f = picture.matrix
            fill.setShader(_picture_shader(picture, skia.Matrix.MakeAll(a, c, e, b, d, f, 0.0, 0.0, 1.0)))
        canvas.drawPath(path, fill)
    if paint.stroke is not None and paint.stroke[3] > 0 and paint.stroke_width > 0:
        stroke = skia.Paint(AntiAlias=True, Style=skia.Paint.kStroke_Style, Color=paint_color(paint.stroke, opacity),
                            StrokeWidth=float(paint.stroke_width))
        stroke.setStrokeCap(_CAPS.get(shape.cap, skia.Paint.kButt_Cap))  # type: ignore[attr-defined]
        stroke.setStrokeJoin(_JOINS.get(shape.join, skia.Paint.kMiter_Join))  # type: ignore[attr-defined]
        stroke.setStrokeMiter(float(shape.miter_limit))  # type: ignore[attr-defined]
        canvas.drawPath(path, stroke)


def paint_shaders(paint: Paint, viewport: Viewport) -> tuple[skia.Shader | None, skia.Shader | None]:
    """The shaders ``paint`` fills and strokes with (a gradient's or a pattern's), None for a plain colour."""
    from .gradients import gradient_shader

    fill = stroke = None
    if paint.fill is not None:
        if paint.pattern is not None:
            fill = _over_colour(pattern_shader(paint.pattern, viewport), paint.pattern, paint.fill, viewport)
        elif paint.gradient is not None:
            fill = gradient_shader(paint.gradient, viewport)
    if paint.stroke is not None:
        if paint.stroke_pattern is not None:
            stroke = _over_colour(pattern_shader(paint.stroke_pattern, viewport), paint.stroke_pattern, paint.stroke,
                                  viewport)
        elif paint.stroke_gradient is not None:
            stroke = gradient_shader(paint.stroke_gradient, viewport)
    return fill, stroke


def _over_colour(shader: skia.Shader | None, pattern: Pattern, colour: tuple[int, int, int, int],
                 viewport: Viewport) -> skia.Shader | None:
    """A pattern that is part of the paint (its share below 1) over what lies beneath it: the pattern it
    cross-fades from, or the paint's plain colour."""
    if shader is None or pattern.share >= 1.0:
        return shader
    beneath = pattern_shader(pattern.beneath, viewport) if pattern.beneath is not None else None
    if beneath is None:
        r, g, b, a = colour
        beneath = skia.Shaders.Color(skia.Color(int(r), int(g), int(b), int(a)))
    return skia.Shaders.Lerp(float(pattern.share), beneath, shader)
