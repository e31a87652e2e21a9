"""In-betweens on a compatible mesh as near their triangles' targets as keeps every triangle's orientation
(maths §5.16).

Where the least-squares fit of every triangle's target Jacobian (:mod:`.bounded_distortion`) turns
some triangle over, the vertices are found by a descent that never lets one turn over: the symmetric
Dirichlet energy ``Σ_f w_f (‖J_f‖² + ‖J_f⁻¹‖²)`` of each triangle's map from its rest shape (its
target) to where it is — 4 where it is its target turned, growing without bound as it flattens — is
lowered from a valid start by scalable locally injective maps (Rabinovich, Lipman and
Sorkine-Hornung 2017, SLIM): each round fits every triangle to its nearest rotation of the target
under weights that follow the energy, then steps toward that fit no further than the first triangle
would turn flat (Smith and Schaefer 2015) and only where the energy falls. Every step keeps every
weighted triangle counter-clockwise, so a valid start gives a valid mesh: an embedding, as the
convex-combination solve is, but shaped by the targets. Pure numpy and scipy.
"""

from __future__ import annotations

import numpy as np
from numpy.typing import NDArray

from .mesh import edge_matrix

__all__ = ["NormalPattern", "NormalSparsity", "distortion", "gradient_operator", "least_distortion", "orientations",
           "sparse_identity", "symmetric_dirichlet"]

Array = NDArray[np.float64]
Triangles = NDArray[np.intp]

_ROUNDS = 40  # SLIM rounds at most
_SETTLED = 1e-4  # stop once a round lowers the energy by less than this share
_HALVINGS = 30  # step halvings before a round gives up
_SAFE = 0.8  # share of the step at which the first triangle would turn over that is taken at most


def gradient_operator(triangles: Triangles, inverses: Array, vertices: int):  # noqa: ANN201 - scipy sparse
    """The ``(2F, V)`` operator taking one coordinate of the vertices to the Jacobians' rows: row
    ``2f + k`` is ``∂(that coordinate)/∂(rest coordinate k)`` on triangle f, ``inverses (F, 2, 2)`` the inverse
    of each triangle's rest edge matrix ``[b − a, c − a]`` (columns)."""
    from scipy.sparse import csr_matrix

    f = len(triangles)
    rows = np.repeat(np.arange(2 * f), 3)
    a, b, c = (np.repeat(triangles[:, i], 2) for i in range(3))
    ga, gb = inverses[:, 0, :].reshape(-1), inverses[:, 1, :].reshape(-1)
    cols = np.stack([a, b, c], axis=1).reshape(-1)
    values = np.stack([-(ga + gb), ga, gb], axis=1).reshape(-1)
    return csr_matrix((values, (rows, cols)), shape=(2 * f, vertices))


def symmetric_dirichlet(jacobians: Array) -> Array:
    """``‖J‖² + ‖J⁻¹‖²`` of each ``(F, 2, 2)`` Jacobian: ``(F,)``, infinite where ``det J ≤ 0``."""
    det = jacobians[:, 0, 0] * jacobians[:, 1, 1] - jacobians[:, 0, 1] * jacobians[:, 1, 0]
    frob = np.einsum("fij,fij->f", jacobians, jacobians)
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.where(det > 0.0, frob + frob / (det * det), np.inf)


def least_distortion(x: Array, tri: Triangles, rest: Array, weights: Array, free: NDArray[np.intp],
                     rounds: int = _ROUNDS, sparsity: NormalSparsity | None = None) -> Array:
    """``x (V, 2)`` with its rows ``free`` moved to lower ``Σ_f w_f·SD(E_f(x)·rest_f)``, the symmetric
    Dirichlet energy of each triangle ``tri (F, 3)`` against its rest shape (``rest (F, 2, 2)``: the inverse
    of its rest edge matrix; ``weights (F,)``, zero for a triangle left out), by at most ``rounds`` SLIM
    rounds. Every weighted triangle counter-clockwise in ``x`` stays so; an ``x`` with one that is not is
    returned as it is. Returns a new ``(V, 2)``. ``sparsity``: the mesh's normal matrix layout, shared by
    descents on one mesh (built here without it)."""
    x = np.array(x, dtype=np.float64)
    used = weights > 0.0
    if not len(free) or not np.any(used) or not np.all(orientations(x, tri[used]) > 0.0):
        return x
    weights = weights / weights.sum()
    operator = gradient_operator(tri, rest, len(x)).tocsc()
    held_rows = np.setdiff1d(np.arange(len(x)), free)
    g_held = operator[:, held_rows]
    parts = (operator[:, free].tocsr(), [g_held @ x[held_rows, r] for r in range(2)],
             NormalPattern(tri, rest, free, len(x), sparsity))
    energy = _energy(x, tri, rest, weights, used)
    for _ in range(rounds):
        goal = _slim_goal(x, tri, rest, weights, used, parts, free)
        if goal is None:
            break
        direction = np.zeros_like(x)
        direction[free] = goal[free] - x[free]
        step = min(1.0, _SAFE * _flip_step(x, direction, tri[used]))
        found = None
        for _ in range(_HALVINGS):
            trial = x + step * direction
            value = _energy(trial, tri, rest, weights, used)
            if value < energy and np.all(orientations(trial, tri[used]) > 0.0):
                found = trial, value
                break
            step *= 0.5
        if found is None:
            break
        settled = energy - found[1] < _SETTLED * energy
        x, energy = found
        if settled:
            break
    return x


def distortion(x: Array, tri: Triangles, rest: Array, weights: Array) -> float:
    """``Σ_f w_f·SD(E_f(x)·rest_f)`` over the triangles weighted above 0 (as :func:`least_distortion` lowers it),
    infinite where one of them is turned over."""
    used = weights > 0.0
    return _energy(x, tri, rest, weights, used)


def orientations(x: Array, triangles: Triangles) -> Array:
    """Twice each triangle's signed area in ``x (V, 2)`` (positive counter-clockwise): ``(F,)``."""
    e = edge_matrix(x, triangles)
    return e[:, 0, 0] * e[:, 1, 1] - e[:, 0, 1] * e[:, 1, 0]


def _energy(x: Array, tri: Triangles, inverses: Array, weights: Array, used: NDArray[np.bool_]) -> float:
    values = symmetric_dirichlet((edge_matrix(x, tri) @ inverses)[used])
    return float(np.sum(weights[used] * values))


def _slim_goal(x: Array, tri: Triangles, rest: Array, weights: Array, used: NDArray[np.bool_],
               parts: tuple, free: NDArray[np.intp]) -> Array | None:  # noqa: ANN001 - scipy sparse
    """The vertices ``(V, 2)`` whose Jacobians best fit each triangle's nearest rotation, under SLIM's
    weights for the symmetric Dirichlet energy (the held rows kept); None where the solve fails.
    ``parts``: the gradient operator's free columns ``(2F, P)`` and the held rows' share of each
    Jacobian row, one ``(2F,)`` per coordinate."""
    g_free, held, pattern = parts
    u, sigma, rotation = _polar2(edge_matrix(x, tri) @ rest)
    sigma = np.maximum(sigma, 1e-12)
    # the energy s² + s⁻² per singular value: SLIM's weight sqrt(f'(s) / (2 (s - 1))) in closed form
    w2 = np.where(used[:, None], (1.0 + sigma) * (1.0 + sigma * sigma) / sigma ** 3, 0.0)
    square = np.einsum("fij,fj,fkj->fik", u, w2, u) * weights[:, None, None]  # a·Wᵀ W = a·U diag(w²) Uᵀ
    pulled = square @ rotation  # a·Wᵀ W R: (F, 2, 2), row r for coordinate r
    c = [[np.repeat(square[:, r, q], 2) for q in range(2)] for r in range(2)]
    rhs = np.concatenate([g_free.T @ (pulled[:, r, :].reshape(-1) - c[r][0] * held[0] - c[r][1] * held[1])
                          for r in range(2)])
    solved = pattern.solve(square, rhs)
    if solved is None or not np.all(np.isfinite(solved)):
        return None
    out = np.array(x)
    out[free, 0], out[free, 1] = solved[:len(free)], solved[len(free):]
    return out


class NormalSparsity:
    """Where each triangle's share goes in the normal matrix of SLIM's weighted fit (:class:`NormalPattern`),
    and its LDLᵀ factorisation: they depend on the mesh alone (``tri (F, 3)``, the ``free (P,)`` vertices of
    ``vertices``), not on the rest shapes, so the descents toward each grid point's targets of one mesh share
    one (its ordering and elimination tree worked out once, each round refactoring in place)."""

    def __init__(self, tri: Triangles, free: NDArray[np.intp], vertices: int) -> None:
        index = np.full(vertices, -1, dtype=np.int64)
        index[free] = np.arange(len(free))
        corner = index[tri]  # (F, 3)
        size = 2 * len(free)
        self.size = size
        r = np.arange(2)[None, :, None, None, None]
        q = np.arange(2)[None, None, :, None, None]
        ci = corner[:, None, None, :, None]
        cj = corner[:, None, None, None, :]
        self.kept = np.broadcast_to((ci >= 0) & (cj >= 0), (len(tri), 2, 2, 3, 3))
        rows = np.broadcast_to(r * len(free) + ci, self.kept.shape)[self.kept]
        cols = np.broadcast_to(q * len(free) + cj, self.kept.shape)[self.kept]
        keys = np.concatenate([cols * size + rows, np.arange(size, dtype=np.int64) * (size + 1)])
        unique, slots = np.unique(keys, return_inverse=True)
        self.slot, self.diagonal = slots[:len(rows)], slots[len(rows):]  # each share's place; the diagonal's
        self.indices = (unique % size).astype(np.int32)
        self.indptr = np.searchsorted(unique // size, np.arange(size + 1)).astype(np.int32)
        column = np.repeat(np.arange(size), np.diff(self.indptr))
        self.upper = np.flatnonzero(self.indices <= column)  # the upper triangle's entries (row ≤ column)
        self.upper_indptr = np.concatenate([[0], np.cumsum(np.bincount(column[self.upper], minlength=size))
                                            ]).astype(np.int32)
        self.factor: object | None = None  # the LDLᵀ factorisation of the last matrix, refactored in place


class NormalPattern:
    """The normal matrix of SLIM's weighted fit, ``Gᵀ C G`` over the free vertices' two coordinates
    (``(2P, 2P)``, coordinate-major), assembled from each triangle's share: triangle f adds
    ``C_f[r, q] · L_f[i, j]`` at row ``r·P + free index of corner i``, column ``q·P + … of corner j``, where
    ``L_f = g_fᵀ g_f`` (``(3, 3)``, ``g_f`` its corners' gradients) and ``C_f`` its ``(2, 2)`` weight. The
    sparsity and each share's place in it (:class:`NormalSparsity`) are worked out once a mesh (``sparsity``,
    or here); a round only sums the shares (one ``bincount``), with a vanishing ``1e-12 ×`` mean diagonal added
    to the diagonal."""

    def __init__(self, tri: Triangles, rest: Array, free: NDArray[np.intp], vertices: int,
                 sparsity: NormalSparsity | None = None) -> None:
        grads = np.stack([-(rest[:, 0, :] + rest[:, 1, :]), rest[:, 0, :], rest[:, 1, :]], axis=-1)  # (F, 2, 3)
        self.local = np.einsum("fki,fkj->fij", grads, grads)  # (F, 3, 3)
        self.sparsity = sparsity if sparsity is not None else NormalSparsity(tri, free, vertices)
        self.size = self.sparsity.size

    def _data(self, weight: Array) -> Array:
        at = self.sparsity
        shares = weight[:, :, :, None, None] * self.local[:, None, None, :, :]  # (F, 2, 2, 3, 3)
        data = np.bincount(at.slot, weights=shares[at.kept], minlength=len(at.indices))
        data[at.diagonal] += 1e-12 * (float(data[at.diagonal].mean()) or 1.0)
        return data

    def matrix(self, weight: Array):  # noqa: ANN201 - a scipy sparse matrix
        """The normal matrix for each triangle's weight ``weight (F, 2, 2)``, in compressed columns."""
        from scipy.sparse import csc_matrix

        at = self.sparsity
        return csc_matrix((self._data(weight), at.indices, at.indptr), shape=(self.size, self.size))

    def solve(self, weight: Array, rhs: Array) -> Array | None:
        """The normal matrix for ``weight (F, 2, 2)`` solved for ``rhs (2P,)``: ``(2P,)``, None where it cannot be
        factored. Symmetric and positive definite, it takes an LDLᵀ factorisation (QDLDL), whose ordering and
        elimination tree are worked out once a mesh and each round refactors in place; without the
        ``qdldl`` package, a sparse LU in symmetric mode (about three times the time)."""
        from scipy.sparse import csc_matrix

        at = self.sparsity
        data = self._data(weight)
        try:
            import qdldl
        except ImportError:  # qdldl is a dependency; an install without it still solves
            from scipy.sparse.linalg import splu

            try:
                lu = splu(csc_matrix((data, at.indices, at.indptr), shape=(self.size, self.size)),
                          permc_spec="MMD_AT_PLUS_A", diag_pivot_thresh=0.0, options={"SymmetricMode": True})
                return lu.solve(rhs)
            except RuntimeError:
                return None
        upper = csc_matrix((data[at.upper], at.indices[at.upper], at.upper_indptr), shape=(self.size, self.size))
        try:
            if at.factor is None:
                at.factor = qdldl.Solver(upper, upper=True)
            else:
                at.factor.update(upper, upper=True)  # type: ignore[attr-defined]
            return at.factor.solve(rhs)  # type: ignore[attr-defined]
        except (RuntimeError, ValueError):
            at.factor = None  # a failed factorisation leaves nothing to refactor
            return None


def _rotations(angle: Array) -> Array:
    cos, sin = np.cos(angle), np.sin(angle)
    return np.stack([np.stack([cos, -sin], -1), np.stack([sin, cos], -1)], axis=-2)


def _polar2(jac: Array) -> tuple[Array, Array, Array]:
    """Of each ``(F, 2, 2)`` Jacobian with a positive determinant, in closed form: ``U`` of its singular value
    decomposition ``(F, 2, 2)``, its singular values ``(F, 2)`` (largest first) and its nearest rotation
    ``U Vᵀ`` ``(F, 2, 2)``."""
    a, b, c, d = jac[:, 0, 0], jac[:, 0, 1], jac[:, 1, 0], jac[:, 1, 1]
    e, f, g, h = 0.5 * (a + d), 0.5 * (a - d), 0.5 * (c + b), 0.5 * (c - b)
    q, r = np.hypot(e, h), np.hypot(f, g)
    turn, shear = np.arctan2(h, e), np.arctan2(g, f)
    return _rotations(0.5 * (turn + shear)), np.stack([q + r, q - r], axis=-1), _rotations(turn)


def _flip_step(x: Array, direction: Array, tri: Triangles) -> float:
    """The least positive step along ``direction (V, 2)`` at which a triangle of ``x`` turns flat
    (``det(e + α·d) = 0``, a quadratic in α); infinity where none does."""
    e, d = edge_matrix(x, tri), edge_matrix(direction, tri)
    qa = d[:, 0, 0] * d[:, 1, 1] - d[:, 0, 1] * d[:, 1, 0]
    qb = e[:, 0, 0] * d[:, 1, 1] + d[:, 0, 0] * e[:, 1, 1] - e[:, 0, 1] * d[:, 1, 0] - d[:, 0, 1] * e[:, 1, 0]
    qc = e[:, 0, 0] * e[:, 1, 1] - e[:, 0, 1] * e[:, 1, 0]
    roots = []
    linear = np.abs(qa) <= 1e-14 * (np.abs(qb) + np.abs(qc))
    with np.errstate(divide="ignore", invalid="ignore"):
        lin = -qc[linear] / qb[linear]
        roots.append(lin[lin > 0])
        qa2, qb2, qc2 = qa[~linear], qb[~linear], qc[~linear]
        disc = qb2 * qb2 - 4 * qa2 * qc2
        ok = disc >= 0
        sq = np.sqrt(disc[ok])
        for r in ((-qb2[ok] - sq) / (2 * qa2[ok]), (-qb2[ok] + sq) / (2 * qa2[ok])):
            roots.append(r[r > 0])
    every = np.concatenate(roots) if roots else np.zeros(0)
    return float(every.min()) if len(every) else float("inf")


def sparse_identity(size: int):  # noqa: ANN201 - a scipy sparse matrix
    """The ``(size, size)`` identity, in compressed columns."""
    from scipy.sparse import identity

    return identity(size, format="csc")
