"""In-betweens on a compatible mesh that keep each triangle's shape, then made injective (maths §5.16).

The convex-combination solve of :mod:`.injective` is valid at every t but lets a shape wander and
distort: its weights, blended inside a far frame, say nothing of the triangles' own shapes. Here,
after Alexa, Cohen-Or and Levin (2000) and Chen, Weber, Keren and Ben-Chen (2013):

1. each triangle's change from key 0 to key 1 is the affine map ``A = R(θ)·S`` (polar
   decomposition, ``S`` symmetric positive definite; ``det A > 0`` since the mesh is valid in both
   keys); at ``t`` its target is ``B(t) = R(t·θ)·((1 − t)·I + t·S)``, which turns and stretches by
   a share of its own change and never flips;
2. the vertices solve the least-squares fit of every triangle's Jacobian to its target, the frame
   held (one sparse factorisation for all t), triangles weighted by area, those between the
   contours (not inside any filled region) lightly: the shape's own triangles decide its form;
3. where a triangle would flip (det ≤ 0) — on real drawings, most in-betweens: a growing contour's
   triangles, an overlay's twisted ones — the vertices are projected onto the injective set: they
   descend from a valid start toward the targets, never letting a triangle turn over
   (:mod:`.mesh_distortion`). Two chains of descents do so at ``_GRID − 1`` grid points ``k / _GRID``:
   one from key 0 upward, each grid point from the one below, one from key 1 downward. The grid points'
   descents take at most ``_WORK`` triangle-rounds in all (each round a sparse factorisation): a larger
   mesh takes fewer rounds a grid point, and one too large for a round each (above some 20 000
   triangles) the convex-combination solve as it is;
4. an in-between is drawn from the mean-value weights (:mod:`.tutte`) of the grid points about it, each
   chain's blended by the quadratic B-spline shares of the grid points at ``s`` (:func:`_grid_basis`: at
   most three nonzero, 3/4 for a grid point at its own ``s``), the chain from key 0 weighing ``1 − u`` and
   the one from key 1 ``u = 3s² − 2s³``: a convex combination of valid triangulations' weights, so valid
   (Floater and Gotsman 1999), on the keys at the ends, and once differentiable in ``s``. Blended by where
   ``s`` lies between two grid points, as before, every vertex's path turned a corner at each grid point
   (``tests/core/test_shape_keeping.py``). Where a chain could not keep up
   with its targets (triangles that must grow a thousandfold, a slit's collapsed ones), the two chains
   end far apart; picking the nearer chain at each grid point, as this step did before, then jumped from
   one to the other between two frames (often at the last frame step: a pop), where the weights now move
   from one to the other over the whole segment. ``u`` is flat at the keys, so a far chain's share grows
   slowly out of each key (blended by ``s`` itself, a share of 1/24 of a far chain moved the frame next
   to a key by 3 × the clip's median step). Where the fit of every grid point's targets keeps every
   triangle's orientation, the fit of ``s``'s own targets is drawn where it does too (drawing some
   in-betweens from fits and the rest from blended grid points would jump where the two meet).

It depends on ``s`` alone, so a render's blocks of frames and a report's measures agree.

Every triangle positively oriented and the frame convex and held make the mesh an embedding at
every t (a locally injective map with a simple boundary is injective), so no contour crosses itself
or another and a hole stays inside its outline.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from ..contours import inside
from .compatible import CompatibleMesh
from .mesh import edge_matrix
from .mesh_distortion import NormalSparsity, gradient_operator, least_distortion, orientations, sparse_identity
from .tutte import ConvexEmbedding

__all__ = ["ShapeKeepingSolve", "material_triangles"]

Array = NDArray[np.float64]

_AIR = 1e-2  # weight of a triangle between the contours, against one inside a filled region
_GRID = 16  # grid points between the keys whose kept vertices the in-betweens between them blend
_LINK = 15  # rounds of the descent toward a grid point's targets, at most
_KNOTS = np.concatenate([[0.0] * 3, (np.arange(1, _GRID - 1) + 0.5) / _GRID, [1.0] * 3])
"""The knots of the grid points' quadratic B-spline basis (:func:`_grid_basis`): ``_GRID + 1`` control points, the
knots between grid points, so each grid point but the two next to the keys centres its own basis function."""
_WORK = 600_000  # triangle-rounds of descent a mesh's grid points may take in all (fewer rounds on larger meshes)


def _grid_basis(s: float) -> Array:
    """Each grid point's share ``(_GRID + 1,)`` of the in-between at ``s`` in [0, 1]: the clamped quadratic
    B-spline basis (:data:`_KNOTS`), non-negative and summing to 1 (so a convex combination), at most three
    nonzero, continuously differentiable in ``s`` (no corner where a grid point's share peaks), and the keys
    alone at the ends."""
    from scipy.interpolate import BSpline

    return np.asarray(BSpline.design_matrix(np.array([s]), _KNOTS, 2).toarray()[0])


def material_triangles(mesh: CompatibleMesh, cuts: list[int], closed: list[bool]) -> NDArray[np.bool_]:
    """Which triangles of ``mesh`` lie inside the filled region of the closed contours in key 0 (even-odd
    over every closed contour, probed at the triangle's centroid): ``(F,)`` bool."""
    middle = mesh.p0[mesh.triangles].mean(axis=1)
    filled = np.zeros(len(middle), dtype=bool)
    for start, end, shut in zip(cuts, cuts[1:], closed):
        if shut and end - start >= 3:
            filled ^= inside(middle, mesh.p0[start:end])
    return filled


class ShapeKeepingSolve:
    """The shape-keeping positions of every mesh vertex at ``s`` in [0, 1]: call with ``s`` for ``(V, 2)``."""

    def __init__(self, mesh: CompatibleMesh, material: NDArray[np.bool_]) -> None:
        p0, p1, tri = mesh.p0, mesh.p1, mesh.triangles
        self.mesh, self.tri = mesh, tri
        e0, e1 = edge_matrix(p0, tri), edge_matrix(p1, tri)  # (F, 2, 2), edges as columns
        d0, d1 = np.linalg.det(e0), np.linalg.det(e1)
        scale = float(np.abs(p0).max(initial=1.0)) ** 2
        self.good = (d0 > 1e-12 * scale) & (d1 > 1e-12 * scale)  # slivers flat to rounding take no part
        inv0 = np.zeros_like(e0)
        inv0[self.good] = np.linalg.inv(e0[self.good])
        self.inv0 = inv0
        change = e1 @ inv0
        u, sigma, vt = np.linalg.svd(change)
        rotation = u @ vt
        self.theta = np.arctan2(rotation[:, 1, 0], rotation[:, 0, 0])
        self.stretch = np.einsum("fji,fj,fjk->fik", vt, sigma, vt)  # Vᵀ Σ V: symmetric, positive definite
        area = 0.25 * (np.abs(d0) + np.abs(d1))
        self.base = np.where(self.good, area * np.where(material, 1.0, _AIR), 0.0)
        self.operator = gradient_operator(tri, inv0, len(p0))
        fixed = np.zeros(len(p0), dtype=bool)
        fixed[mesh.frame] = True
        self.free, self.fixed = np.flatnonzero(~fixed), np.flatnonzero(fixed)
        self._system: tuple[object, object, Array, float] | None = None
        self.embedding = ConvexEmbedding(mesh)
        self.w0, self.w1 = self.embedding.weights(p0), self.embedding.weights(p1)
        self._mean_values: dict[tuple[int, int], Array] = {}
        self._sides: dict[tuple[int, int], Array] = {}
        self._fits: dict[int, Array | None] = {}
        self._sparsity: NormalSparsity | None = None  # the descents' normal matrix layout, one for all grid points
        # rounds of the descent per grid point, within the work bound (0: the mesh takes the convex solve)
        self.rounds = min(_LINK, int(_WORK // (2 * (_GRID - 1) * max(len(tri), 1))))

    def targets(self, s: float) -> Array:
        """Each triangle's Jacobian at ``s``: ``R(s·θ)·((1 − s)·I + s·S)``, ``(F, 2, 2)``."""
        angle = s * self.theta
        cos, sin = np.cos(angle), np.sin(angle)
        turn = np.stack([np.stack([cos, -sin], -1), np.stack([sin, cos], -1)], axis=-2)
        return turn @ ((1.0 - s) * np.eye(2) + s * self.stretch)

    def _solve(self, goal: Array, convex: Array) -> Array:
        """The vertices ``(V, 2)`` whose Jacobians fit ``goal (F, 2, 2)`` best, triangles weighted as set up;
        a vanishing pull toward ``convex (V, 2)`` places a vertex no triangle with area holds."""
        if self._system is None:  # the weights never change: one factorisation for every t and round
            from scipy.sparse import diags
            from scipy.sparse.linalg import splu

            g = self.operator
            free = g[:, self.free]
            weighted = (free.T @ diags(np.repeat(self.base, 2))).tocsr()  # (free, 2F)
            normal = (weighted @ free).tocsc()
            pull = 1e-9 * float(normal.diagonal().mean() or 1.0)
            held = g[:, self.fixed] @ self.mesh.p0[self.fixed]  # (2F, 2): the held frame's part of each row
            self._system = (splu(normal + pull * sparse_identity(len(self.free))), weighted, held, pull)
        lu, weighted, held, pull = self._system
        out = np.array(self.mesh.p0, dtype=np.float64)
        for r in range(2):
            rhs = goal[:, r, :].reshape(-1) - held[:, r]
            out[self.free, r] = lu.solve(weighted @ rhs + pull * convex[self.free, r])  # type: ignore[attr-defined]
        return out

    def _valid(self, x: Array) -> bool:
        return bool(np.all(orientations(x, self.tri)[self.good] > 0.0)) and bool(np.all(np.isfinite(x)))

    def convex(self, s: float) -> Array:
        """The convex-combination solve at ``s``: the keys' mean-value weights blended, ``(V, 2)`` (maths §5.9)."""
        return self.embedding((1.0 - s) * self.w0 + s * self.w1)

    def __call__(self, s: float) -> Array:
        if s <= 0.0:
            return np.array(self.mesh.p0)
        if s >= 1.0:
            return np.array(self.mesh.p1)
        if self._fits_hold():
            x = self._solve(self.targets(s), self.convex(s))
            if self._valid(x):
                return x
        if not self.rounds:
            return self.convex(s)  # a mesh too large for the descent's work bound
        basis = _grid_basis(s)
        weights = np.zeros(len(self.embedding.rows))
        u = s * s * (3.0 - 2.0 * s)  # the chain from key 1's share: flat at both keys
        for step, part in ((-1, 1.0 - u), (1, u)):
            for k in np.flatnonzero(basis).tolist():
                weights += part * float(basis[k]) * self._weights(k, step)
        return self.embedding(weights)

    def _fits_hold(self) -> bool:
        """Whether the fit of every grid point's targets turns no triangle over (then each in-between is its
        own fit where that does too: drawing some from fits and the rest from blended grid points would
        jump where the two meet)."""
        return all(self._fit(k) is not None for k in range(1, _GRID))

    def _weights(self, k: int, step: int) -> Array:
        """The mean-value weights ``(E,)`` of grid point ``k`` as the chain ``step`` reaches it (:meth:`_side`)."""
        key = (k, step)
        if key not in self._mean_values:
            self._mean_values[key] = self.embedding.weights(self._side(k, step))
        return self._mean_values[key]

    def _rest(self, target: Array) -> Array:
        """The inverse edge matrices ``(F, 2, 2)`` of the triangles as ``target (F, 2, 2)`` shapes them."""
        return self.inv0 @ np.linalg.inv(target)

    def _fit(self, k: int) -> Array | None:
        """The keys at k = 0 and ``_GRID``, the least-squares fit of grid point k's targets where it turns no
        triangle over, else None: ``(V, 2)``."""
        if k <= 0:
            return self.mesh.p0
        if k >= _GRID:
            return self.mesh.p1
        if k not in self._fits:
            found = self._solve(self.targets(k / _GRID), self.mesh.p0)
            self._fits[k] = found if self._valid(found) else None
        return self._fits[k]

    def _side(self, k: int, step: int) -> Array:
        """The kept vertices ``(V, 2)`` at grid point ``k`` reached from one key alone, grid point by grid point
        (``step`` −1: from key 0 upward, each from the one below; +1: from key 1 downward)."""
        found = self._fit(k)
        if found is None:
            found = self._sides.get((k, step))
        if found is None:
            if self._sparsity is None:
                self._sparsity = NormalSparsity(self.tri, self.free, len(self.mesh.p0))
            found = least_distortion(self._side(k + step, step), self.tri, self._rest(self.targets(k / _GRID)),
                                     self.base, self.free, self.rounds, self._sparsity)
            self._sides[(k, step)] = found
        return found
