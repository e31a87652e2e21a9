"""As-rigid-as-possible paths (Alexa, Cohen-Or, Levin, SIGGRAPH 2000; maths §5.4).

The two keys get one compatible triangulation (:mod:`.mesh`). For each triangle
the affine map ``A`` taking its key-0 edges to its key-1 edges splits by polar
decomposition into ``R(γ)·S`` (``S`` symmetric); at ``t`` the wanted map is
``M_T(t) = R(t·γ)·((1-t)·I + t·S)``, with γ on the branch nearest the shape's
best-fit rotation φ (maths §5.2) so that neighbouring triangles turn the same
way. The vertices at ``t`` minimise ``Σ_T area_T · Σ_edges |e(t) - M_T(t)·e0|²``
(``variant="paper"``). That matrix depends on key 0 alone, so it is factored
once per pair of keys (sparse LU, cached) and each frame is one
back-substitution. The vertex mean of the outline moves on a straight line
between the keys'.

The default ``variant="outline"`` changes only the right-hand side and adds
fixed terms: every wanted edge keeps the direction ``M_T(t)·e0`` but takes the
length ``(1-t)·|e0| + t·|e1|``, and each outline edge ``i → i+1`` — the chord
over the boundary pieces the triangulation split it into — is asked, with
weight :data:`OUTLINE_WEIGHT` × the shape's area / n, to point where its pieces
point at its interpolated length. Rigid motions stay exact (every length is
already kept); a part that changes shape, like the roof box's roof, no longer
pulls its outline edges short (docs/arap.md has the numbers).

Degenerate keys never raise and never give NaN:

* copies of a vertex (a zero-length edge, as balancing by copies makes) are
  first spread along their edges (:func:`.balance.spread`), which leaves each
  key's outline as drawn (the vertex mean followed is then the spread keys');
* when key 0 cannot be triangulated (it crosses itself, has no area, is
  collinear) key 1 is triangulated instead (:mod:`.mesh` tries both);
* when neither can, the paths are the exact rigid paths of maths §5.2.

Triangles that fold over between the keys (unrelated outlines, or keys of
opposite winding) are kept with a thousandth of their weight, so that their
neighbours decide where they go.
"""

from __future__ import annotations

from collections import OrderedDict
from dataclasses import dataclass
from typing import Callable

import numpy as np
from numpy.typing import ArrayLike, NDArray

from ..balance import coincident_runs, spread
from ..geometry import best_fit_rotation, centroid
from .mesh import Mesh, MeshError, compatible_mesh, edge_matrix
from .paths import as_times, rigid

__all__ = ["VARIANTS", "OUTLINE_WEIGHT", "arap", "ArapPaths", "arap_paths"]

Array = NDArray[np.float64]

VARIANTS: tuple[str, ...] = ("outline", "paper")
OUTLINE_WEIGHT = 10.0
"""Weight of the outline-edge terms of the ``outline`` variant, in units of the shape's area / n."""

_FOLDED = 1e-3  # weight of a triangle that folds over between the keys, relative to its area
_CACHE = 32  # pairs of keys whose factorisation is kept
_cache: OrderedDict[bytes, Callable[[Array], Array]] = OrderedDict()


@dataclass(frozen=True)
class ArapPaths:
    """The factored system of one pair of keys; call it with ``t (T,)`` for ``(T, n, 2)``."""

    mesh: Mesh
    solve: Callable[[Array], Array]  # (V - 1, k) right-hand sides → (V - 1, k) solutions
    terms_t: object  # sparse (V, R): the weighted incidence of every term's edge, transposed
    edges0: Array  # (3F, 2) triangle edges in key 0
    stretched: Array  # (3F, 2) S_T applied to each edge
    angle: Array  # (F,) γ of each triangle
    lengths: Array | None  # (2, 3F + n) each term's edge length in key 0 and key 1; None: as the paper
    chords: object  # sparse (n, 3F): each outline edge as the sum of its boundary pieces
    c0: Array
    c1: Array

    def __call__(self, t: ArrayLike) -> Array:
        t = as_times(t)
        count, n = len(t), self.mesh.n
        (x0, y0), (sx, sy) = self.edges0.T, self.stretched.T
        keep, take = 1.0 - t, t
        bx = np.outer(x0, keep) + np.outer(sx, take)  # (3F, T): ((1-t)·I + t·S)·e0
        by = np.outer(y0, keep) + np.outer(sy, take)
        turn = np.outer(self.angle, t)  # (F, T): one turn per triangle, for its three edges
        c, s = np.repeat(np.cos(turn), 3, axis=0), np.repeat(np.sin(turn), 3, axis=0)
        wx, wy = c * bx - s * by, s * bx + c * by  # R(t·γ)·(...)·e0
        wx = np.concatenate([wx, self.chords @ wx])  # (R, T): then each outline edge, summed
        wy = np.concatenate([wy, self.chords @ wy])
        if self.lengths is not None:
            size = np.hypot(wx, wy)
            goal = np.outer(self.lengths[0], keep) + np.outer(self.lengths[1], take)
            scale = np.divide(goal, size, out=np.ones_like(size), where=size > 0)
            wx, wy = wx * scale, wy * scale
        columns = np.concatenate([wx, wy], axis=1)  # (R, 2T): x of every frame, then y
        rhs = np.asarray(self.terms_t @ columns)  # (V, 2T)
        x = np.zeros((len(rhs), 2 * count))
        x[1:] = self.solve(rhs[1:])  # vertex 0 pinned at the origin: translation is free
        frames = np.stack([x[:n, :count].T, x[:n, count:].T], axis=-1)  # (T, n, 2)
        center = (1.0 - t)[:, None] * self.c0 + t[:, None] * self.c1
        return frames + (center - frames.mean(axis=1))[:, None, :]


def arap_paths(k0: Array, k1: Array, variant: str = "outline") -> Callable[[Array], Array]:
    """Triangulate, decompose and factor for keys ``(n, 2)``; raises :class:`.mesh.MeshError` when
    neither key is a simple polygon with distinct vertices. Returns the paths, a function of ``t (T,)``.

    The system is built on the key that was triangulated: when that is key 1, the
    paths are those from key 1 to key 0, run backwards.
    """
    if variant not in VARIANTS:
        raise ValueError(f"unknown variant {variant!r}; expected one of {', '.join(VARIANTS)}")
    mesh = compatible_mesh(k0, k1)
    if mesh.source == 0:
        return _factor(k0, k1, mesh, variant)
    flipped = _doubled_areas(mesh.p1, mesh.triangles).sum() < 0
    triangles = mesh.triangles[:, ::-1].copy() if flipped else mesh.triangles
    backwards = _factor(k1, k0, Mesh(mesh.p1, mesh.p0, triangles, mesh.n, mesh.folds, 0), variant)
    return lambda t: backwards(1.0 - as_times(t))


def _doubled_areas(points: Array, triangles: NDArray[np.intp]) -> Array:
    return np.linalg.det(edge_matrix(points, triangles))


def _factor(k0: Array, k1: Array, mesh: Mesh, variant: str) -> ArapPaths:
    """The system of ``mesh`` (valid in its ``p0``) factored, for keys ``(n, 2)``."""
    from scipy.sparse import csr_matrix
    from scipy.sparse.linalg import splu

    outline = variant == "outline"
    p0, p1, triangles, n = mesh.p0, mesh.p1, mesh.triangles, mesh.n
    m0, m1 = edge_matrix(p0, triangles), edge_matrix(p1, triangles)
    det = np.linalg.det(m0)
    usable = np.abs(det) > 1e-14 * np.abs(det).max()
    inverse = np.linalg.inv(np.where(usable[:, None, None], m0, np.eye(2)))
    maps = np.where(usable[:, None, None], m1 @ inverse, np.eye(2))  # (F, 2, 2)
    gamma = np.arctan2(maps[:, 1, 0] - maps[:, 0, 1], maps[:, 0, 0] + maps[:, 1, 1])
    phi = float(best_fit_rotation(np.asarray(k0), np.asarray(k1)))
    gamma = phi + np.mod(gamma - phi + np.pi, 2.0 * np.pi) - np.pi  # the branch nearest φ
    c, s = np.cos(gamma), np.sin(gamma)
    unturn = np.stack([np.stack([c, s], -1), np.stack([-s, c], -1)], -2)  # R(-γ)
    stretch = unturn @ maps
    stretch = 0.5 * (stretch + np.swapaxes(stretch, 1, 2))

    tails = triangles.reshape(-1)
    heads = np.roll(triangles, -1, axis=1).reshape(-1)
    edges0 = p0[heads] - p0[tails]  # (3F, 2)
    owner = np.repeat(np.arange(len(triangles)), 3)
    stretched = np.einsum("eij,ej->ei", stretch[owner], edges0)
    area = 0.5 * np.abs(det)
    folded = np.linalg.det(m1) * det <= 0
    weight = np.repeat(np.where(folded, _FOLDED * area, area), 3)
    chords = _chord_matrix(tails, heads, n)
    chord_weight = np.full(n, OUTLINE_WEIGHT * area.sum() / n if outline else 0.0)
    rows = np.arange(len(tails) + n)
    term_tails = np.concatenate([tails, np.arange(n)])
    term_heads = np.concatenate([heads, (np.arange(n) + 1) % n])
    terms = csr_matrix((np.concatenate([-np.ones(len(rows)), np.ones(len(rows))]),
                        (np.concatenate([rows, rows]), np.concatenate([term_tails, term_heads]))),
                       shape=(len(rows), len(p0)))
    weighted_t = (terms.multiply(np.concatenate([weight, chord_weight])[:, None])).T.tocsr()
    laplacian = (weighted_t @ terms).tocsc()
    try:
        factor = splu(laplacian[1:, 1:].tocsc())
    except RuntimeError as error:  # singular: the mesh is not connected, or has no area
        raise MeshError(f"the triangulation gives no system to solve ({error})") from None
    lengths = np.stack([np.linalg.norm(p0[term_heads] - p0[term_tails], axis=1),
                        np.linalg.norm(p1[term_heads] - p1[term_tails], axis=1)])
    return ArapPaths(mesh, factor.solve, weighted_t, edges0, stretched, gamma,
                     lengths if outline else None, chords,
                     centroid(np.asarray(k0)), centroid(np.asarray(k1)))


def _chord_matrix(tails: NDArray[np.intp], heads: NDArray[np.intp], n: int) -> object:
    """Sparse ``(n, 3F)``: outline edge ``i → i+1`` as the signed sum of the triangle edges along it."""
    from scipy.sparse import csr_matrix

    row_of = {(int(a), int(b)): r for r, (a, b) in enumerate(zip(tails, heads))}
    boundary: dict[int, list[int]] = {}
    for (a, b) in row_of:
        if (b, a) not in row_of:
            boundary.setdefault(a, []).append(b)
            boundary.setdefault(b, []).append(a)
    rows, cols, signs = [], [], []
    for i in range(n):
        goal = (i + 1) % n
        # the boundary path from i to i + 1 through added vertices only
        for start in boundary.get(i, []):
            path, previous, here = [i], i, start
            while here >= n:
                path.append(here)
                nxt = [v for v in boundary[here] if v != previous]
                previous, here = here, nxt[0]
            if here == goal:
                path.append(goal)
                break
        else:
            continue
        for a, b in zip(path, path[1:]):
            if (a, b) in row_of:
                rows.append(i), cols.append(row_of[(a, b)]), signs.append(1.0)
            else:
                rows.append(i), cols.append(row_of[(b, a)]), signs.append(-1.0)
    return csr_matrix((signs, (rows, cols)), shape=(n, len(tails)))


def arap(k0: Array, k1: Array, t: ArrayLike, variant: str = "outline") -> Array:
    """As-rigid-as-possible inbetweens of corresponding keys ``(n, 2)`` at ``t (T,)``: ``(T, n, 2)``.

    The factorisation for a pair of keys is cached, so calls for successive
    blocks of frames of one segment pay it once.
    """
    k0 = np.asarray(k0, dtype=np.float64)
    k1 = np.asarray(k1, dtype=np.float64)
    return _paths_for(k0, k1, variant)(as_times(t))


def _paths_for(k0: Array, k1: Array, variant: str) -> Callable[[Array], Array]:
    key = variant.encode() + b"|" + k0.tobytes() + b"|" + k1.tobytes()
    found = _cache.get(key)
    if found is not None:
        _cache.move_to_end(key)
        return found
    paths = _build(k0, k1, variant)
    _cache[key] = paths
    while len(_cache) > _CACHE:
        _cache.popitem(last=False)
    return paths


def _build(k0: Array, k1: Array, variant: str) -> Callable[[Array], Array]:
    """The ARAP paths of the keys, or a fallback for keys that cannot be triangulated (see above)."""
    a, b = (spread(k0, k1) if coincident_runs(k0) or coincident_runs(k1) else (k0, k1))
    if not (np.all(np.isfinite(a)) and np.all(np.isfinite(b))):
        return lambda t: rigid(k0, k1, t)
    try:
        return arap_paths(a, b, variant)
    except MeshError:
        return lambda t: rigid(k0, k1, t)
