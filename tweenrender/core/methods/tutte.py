"""Convex-combination embeddings of a compatible mesh (Tutte; Floater 2003; Floater and Gotsman 1999).

A mesh whose frame is convex and held, and each of whose other vertices is a combination of its neighbours
by positive weights summing to 1, is a valid triangulation (every triangle positively oriented). A valid
triangulation is reproduced by its own mean-value weights (Floater 2003), which are positive; and a
convex combination of several such weightings is again positive and sums to 1. So blending the weights of
any valid triangulations of one mesh gives a valid one at every blend, moving continuously from one to the
other (Floater and Gotsman): the in-betweens of :mod:`.injective` and of :mod:`.bounded_distortion`.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .compatible import CompatibleError, CompatibleMesh

__all__ = ["ConvexEmbedding", "mean_value_weights"]

Array = NDArray[np.float64]

_FLAT = 1e8  # tan(θ/2) is kept within [1/_FLAT, _FLAT]


def mean_value_weights(points: Array, triangles: NDArray[np.intp]) -> tuple[NDArray[np.intp], NDArray[np.intp], Array]:
    """Floater's mean-value weights of a triangulation ``points (V, 2)``, ``triangles (F, 3)``
    (counter-clockwise): ``(rows, cols, w)`` with one entry per directed edge ``i → j``, in the order
    of ``np.unique`` over ``i·V + j``, ``w`` normalised so each row sums to 1."""
    v = len(points)
    i = triangles.reshape(-1)
    j = np.roll(triangles, -1, axis=1).reshape(-1)
    k = np.roll(triangles, -2, axis=1).reshape(-1)
    a, b = points[j] - points[i], points[k] - points[i]
    la, lb = np.linalg.norm(a, axis=1), np.linalg.norm(b, axis=1)
    sine, cosine = np.abs(a[:, 0] * b[:, 1] - a[:, 1] * b[:, 0]), (a * b).sum(axis=1)  # times la·lb
    # tan(θ/2) = sin / (1 + cos) = (1 - cos) / sin, each where it does not cancel
    with np.errstate(divide="ignore", invalid="ignore"):
        half = np.where(cosine >= 0, sine / (la * lb + cosine), (la * lb - cosine) / sine)
    # a triangle flat to rounding (an overlay sliver) keeps a finite, positive weight
    half = np.clip(np.nan_to_num(half, nan=_FLAT, posinf=_FLAT), 1.0 / _FLAT, _FLAT)
    codes = np.concatenate([i * v + j, i * v + k])
    values = np.concatenate([half / la, half / lb])
    unique, where = np.unique(codes, return_inverse=True)
    w = np.bincount(where, weights=values, minlength=len(unique))
    rows, cols = unique // v, unique % v
    w /= np.bincount(rows, weights=w, minlength=v)[rows]
    return rows, cols, w


class ConvexEmbedding:
    """The triangulations of ``mesh`` with its frame held: :meth:`weights` of a valid one, and the one that
    weights give (call with ``w (E,)`` for ``(V, 2)``)."""

    def __init__(self, mesh: CompatibleMesh) -> None:
        self.mesh = mesh
        self.rows, self.cols, _ = mean_value_weights(mesh.p0, mesh.triangles)
        size = len(mesh.p0)
        fixed = np.zeros(size, dtype=bool)
        fixed[mesh.frame] = True
        self.free = np.flatnonzero(~fixed)
        self.slot = np.full(size, -1)
        self.slot[self.free] = np.arange(len(self.free))
        keep = ~fixed[self.rows]
        self.inner = keep & ~fixed[self.cols]  # between two free vertices: in the matrix
        self.outer = keep & fixed[self.cols]  # from a free vertex to the frame: on the right-hand side
        self._layout: tuple[NDArray[np.intp], NDArray[np.int32], NDArray[np.int32]] | None = None

    def _matrix(self, w: Array):  # noqa: ANN202 - a scipy sparse matrix
        """``I − W`` over the free vertices for weights ``w (E,)``, in compressed columns: its layout (which entry
        goes where) is worked out once, each call only places the weights."""
        from scipy.sparse import csc_matrix

        size = len(self.free)
        if self._layout is None:
            r_in, c_in = self.slot[self.rows[self.inner]], self.slot[self.cols[self.inner]]
            rows = np.concatenate([np.arange(size), r_in])
            cols = np.concatenate([np.arange(size), c_in])
            numbered = csc_matrix((np.arange(1.0, len(rows) + 1.0), (rows, cols)), shape=(size, size))
            numbered.sort_indices()
            self._layout = numbered.data.astype(np.intp) - 1, numbered.indices, numbered.indptr
        order, indices, indptr = self._layout
        values = np.concatenate([np.ones(size), -w[self.inner]])[order]
        return csc_matrix((values, indices, indptr), shape=(size, size))

    def weights(self, points: Array) -> Array:
        """The mean-value weights ``(E,)`` of the mesh drawn at ``points (V, 2)``, one per directed edge in the
        order of :func:`mean_value_weights`."""
        rows, cols, w = mean_value_weights(points, self.mesh.triangles)
        if not (np.array_equal(rows, self.rows) and np.array_equal(cols, self.cols)):
            raise CompatibleError("the two keys' meshes differ")
        return w

    def __call__(self, w: Array) -> Array:
        """The vertices ``(V, 2)`` where each one off the frame is the combination of its neighbours by ``w (E,)``,
        the frame held (one sparse LU).

        ``I − W`` is diagonally dominant by rows (each row of ``W`` is positive and sums to at most 1 over the
        free vertices), which elimination keeps, so its diagonal serves as the pivots; and its pattern is
        symmetric (each edge runs both ways), so the fill-reducing order is taken from ``A + Aᵀ`` (SuperLU's
        symmetric mode): a quarter less work than partial pivoting on a column order."""
        from scipy.sparse.linalg import splu

        size = len(self.free)
        matrix = self._matrix(w)
        rhs = np.zeros((size, 2))
        np.add.at(rhs, self.slot[self.rows[self.outer]], w[self.outer][:, None] * self.mesh.p0[self.cols[self.outer]])
        out = np.array(self.mesh.p0)
        out[self.free] = splu(matrix, permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0,
                              options={"SymmetricMode": True}).solve(rhs)
        return out
