"""Independent areas for the tests, with shapely (GEOS): what closed contours fill under a fill rule.

The contours' edges are split into faces (``polygonize`` of their union); a face is filled when the
winding number of a point inside it — the sum of the turning angles of each contour seen from the
point, over 2π — is odd (``evenodd``) or not zero (``nonzero``).
"""

from __future__ import annotations

from typing import Sequence

import numpy as np
from shapely import polygonize, unary_union
from shapely.geometry import LinearRing, Polygon
from shapely.geometry.base import BaseGeometry


def winding_number(point: tuple[float, float], contours: Sequence[np.ndarray]) -> int:
    """How many times the closed ``contours`` wind about ``point`` (angle sum)."""
    total = 0.0
    for c in contours:
        d = np.asarray(c, dtype=float) - np.asarray(point, dtype=float)
        angle = np.arctan2(d[:, 1], d[:, 0])
        turn = np.roll(angle, -1) - angle
        total += float(((turn + np.pi) % (2 * np.pi) - np.pi).sum())
    return round(total / (2 * np.pi))


def drawn_area(contours: Sequence[np.ndarray], rule: str) -> BaseGeometry:
    """The region closed ``contours (N_i, 2)`` fill under ``rule`` (``"nonzero"`` or ``"evenodd"``)."""
    rings = [LinearRing(c) for c in contours if len(c) >= 3 and Polygon(c).area > 0]
    if not rings:
        return Polygon()
    kept = []
    for face in polygonize([unary_union(rings)]).geoms:
        p = face.representative_point()
        w = winding_number((p.x, p.y), contours)
        if (w % 2 == 1) if rule == "evenodd" else w != 0:
            kept.append(face)
    return unary_union(kept) if kept else Polygon()


def stray_share(frame: BaseGeometry, key0: BaseGeometry, key1: BaseGeometry, reach: float) -> float:
    """The share of ``frame``'s area farther than ``reach`` from both keys' areas."""
    if frame.area == 0:
        return 0.0
    near = unary_union([key0.buffer(reach, 64), key1.buffer(reach, 64)])
    return frame.difference(near).area / frame.area
