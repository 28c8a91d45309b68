"""Second-order kinematics from the joint twists: Lie brackets, no chain needed.

The kernels behind :mod:`screwkit.acceleration` and the Chain methods
``space_jacobian_dot`` and friends. Each takes Jacobians that are already computed
(columns [omega; v], the screw order) and joint rates, float64 arrays with any leading
batch axes, or SymPy matrices for one exact configuration. Nothing here checks its
arguments: the callers do.

The one formula: joint i's twist in the base frame is J_i = Ad(e^[S_1]q_1 ...
e^[S_{i-1}]q_{i-1}) S_i, so only the joints before it move it, each by a bracket,

    dJ_i / dq_j = [J_j, J_i] = ad(J_j) J_i     (j < i; 0 for j >= i),

and dJ_i/dt = [W_i, J_i] with W_i = sum_{j<i} J_j dq_j, the twist of link i-1.
The body Jacobian is moved only by the joints after a column:
dJb_i/dq_j = [Jb_i, Jb_j] for j > i.
"""

import numpy as np
import sympy as sp

__all__ = []


def bracket(a, b):
    """The Lie bracket [a, b] = ad(a) b of twists laid out on axis -2 (..., 6, k):
    (w_a x w_b; w_a x v_b + v_a x w_b). Float arrays or SymPy 6 x k matrices."""
    if isinstance(a, sp.MatrixBase):
        return sp.Matrix.hstack(
            *[
                sp.Matrix.vstack(
                    a[:3, k].cross(b[:3, k]),
                    a[:3, k].cross(b[3:, k]) + a[3:, k].cross(b[:3, k]),
                )
                for k in range(a.shape[1])
            ]
        )
    wa, va, wb, vb = a[..., :3, :], a[..., 3:, :], b[..., :3, :], b[..., 3:, :]
    return np.concatenate([_cross(wa, wb), _cross(wa, vb) + _cross(va, wb)], axis=-2)


def _cross(a, b):
    """a x b along axis -2 (..., 3, k), written out (cheaper than np.cross there)."""
    a0, a1, a2 = a[..., 0, :], a[..., 1, :], a[..., 2, :]
    b0, b1, b2 = b[..., 0, :], b[..., 1, :], b[..., 2, :]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], -2)


def _columns_times(J, dq):
    """The twists J_i dq_i, column by column: (..., 6, n)."""
    if isinstance(J, sp.MatrixBase):
        return sp.Matrix.hstack(*[J[:, i] * dq[i] for i in range(J.shape[1])])
    return J * dq[..., None, :]


def _sums_before(V):
    """W_i = sum_{j<i} V_j (column 0 is zero): the twist of link i - 1."""
    if isinstance(V, sp.MatrixBase):
        columns, total = [], sp.zeros(6, 1)
        for i in range(V.shape[1]):
            columns.append(total)
            total = total + V[:, i]
        return sp.Matrix.hstack(*columns)
    W = np.cumsum(V, axis=-1)
    return W - V


def _sums_after(V):
    """W_i = sum_{j>i} V_j (the last column is zero)."""
    if isinstance(V, sp.MatrixBase):
        n = V.shape[1]
        reversed_sums = _sums_before(V[:, ::-1])
        return reversed_sums[:, ::-1] if n else reversed_sums
    return _sums_before(V[..., ::-1])[..., ::-1]


def space_dot(Js, dq):
    """dJs/dt = [W_i, J_i], W_i the sum of J_j dq_j over j < i: (..., 6, n)."""
    return bracket(_sums_before(_columns_times(Js, dq)), Js)


def body_dot(Jb, dq):
    """dJb/dt = [Jb_i, Wb_i], Wb_i the sum of Jb_j dq_j over j > i: (..., 6, n)."""
    return bracket(Jb, _sums_after(_columns_times(Jb, dq)))


def _point_terms(dJs, Js, dq, p):
    """The geometric Jacobian's derivative from the space one and the end point p:
    Jg_i = (v_i + w_i x p; w_i), so dJg_i = (dv_i + dw_i x p + w_i x pdot; dw_i)
    with pdot = v + w x p of the twist Js dq."""
    if isinstance(Js, sp.MatrixBase):
        V = Js * sp.Matrix(dq)
        pdot = V[3:, 0] + V[:3, 0].cross(p)
        return sp.Matrix.hstack(
            *[
                sp.Matrix.vstack(
                    dJs[3:, i] + dJs[:3, i].cross(p) + Js[:3, i].cross(pdot),
                    dJs[:3, i],
                )
                for i in range(Js.shape[1])
            ]
        )
    V = np.einsum("...ij,...j->...i", Js, dq)
    p = p[..., :, None]
    pdot = V[..., 3:, None] + _cross(V[..., :3, None], p)
    linear = dJs[..., 3:, :] + _cross(dJs[..., :3, :], p) + _cross(Js[..., :3, :], pdot)
    return np.concatenate([linear, dJs[..., :3, :]], axis=-2)


def geometric_dot(Js, dq, p):
    """dJg/dt of the end point p (..., 3), rows [v; omega], from the space Jacobian."""
    return _point_terms(space_dot(Js, dq), Js, dq, p)


def space_hessian(Js):
    """H[j, :, i] = dJs_i/dq_j = [J_j, J_i] for j < i, else 0: (..., n, 6, n)."""
    if isinstance(Js, sp.MatrixBase):
        n = Js.shape[1]
        return [
            sp.Matrix.hstack(
                *[
                    bracket(Js[:, j], Js[:, i]) if j < i else sp.zeros(6, 1)
                    for i in range(n)
                ]
            )
            for j in range(n)
        ]
    n = Js.shape[-1]
    shape = Js.shape[:-2] + (n, 6, n)
    row_j = np.broadcast_to(Js.swapaxes(-1, -2)[..., :, :, None], shape)
    column_i = np.broadcast_to(Js[..., None, :, :], shape)
    H = bracket(row_j, column_i)
    return H * np.triu(np.ones((n, n)), 1)[:, None, :]


def body_hessian(Jb):
    """H[j, :, i] = dJb_i/dq_j = [Jb_i, Jb_j] for j > i, else 0: (..., n, 6, n)."""
    if isinstance(Jb, sp.MatrixBase):
        n = Jb.shape[1]
        return [
            sp.Matrix.hstack(
                *[
                    bracket(Jb[:, i], Jb[:, j]) if j > i else sp.zeros(6, 1)
                    for i in range(n)
                ]
            )
            for j in range(n)
        ]
    n = Jb.shape[-1]
    shape = Jb.shape[:-2] + (n, 6, n)
    row_j = np.broadcast_to(Jb.swapaxes(-1, -2)[..., :, :, None], shape)
    column_i = np.broadcast_to(Jb[..., None, :, :], shape)
    return bracket(column_i, row_j) * np.tril(np.ones((n, n)), -1)[:, None, :]


def geometric_hessian(Js, p):
    """H[j] = dJg/dq_j of the end point p, rows [v; omega]: (..., n, 6, n).

    The space Hessian's H[j] is dJs/dt for the unit rate e_j, so H[j] of the geometric
    Jacobian is the same point terms with dq = e_j."""
    if isinstance(Js, sp.MatrixBase):
        n = Js.shape[1]
        return [
            _point_terms(Hj, Js, [1 if k == j else 0 for k in range(n)], p)
            for j, Hj in enumerate(space_hessian(Js))
        ]
    n = Js.shape[-1]
    Hs = space_hessian(Js)
    J = Js[..., None, :, :]
    return _point_terms(Hs, J, np.eye(n), p[..., None, :])
