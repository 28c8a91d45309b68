"""Second-order kinematics from the joint twists: Lie brackets, no chain needed.

The kernels behind :mod:`screwkit.motion.acceleration` and the Chain methods
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

from .. import _checks, transforms

__all__ = []

#: Bytes per configuration while each kind of result is computed, the result and its
#: temporaries (measured peaks, rounded up: the Hessians 2.2-2.7 times their n x 6 x n
#: floats, the Jacobians' derivatives 3.3-4.3 times their 6 x n, the accelerations
#: J, dJ and their products about 6 times 6 x n), as a function of n.
WORK_BYTES = {
    "Hessians": lambda n: 3 * 8 * 6 * n * n,
    "Jacobian derivatives": lambda n: 5 * 8 * 6 * n,
    "accelerations": lambda n: 6 * 8 * 6 * n,
}


def check_batch(count, n, kind):
    """Refuse before computing ``kind`` (a key of :data:`WORK_BYTES`) for ``count``
    configurations of an n-joint chain when its arrays would pass the memory limit
    (:data:`screwkit._checks.MAX_RESULT_BYTES`), saying how many fit."""
    per = WORK_BYTES[kind](n)
    fits = max(1, int(_checks.MAX_RESULT_BYTES // per))
    _checks.check_result_bytes(
        count * per,
        f"the {kind} of q's {count} configurations",
        f"pass at most {fits} configurations at once (a loop over chunks of q)",
    )


def _check_jacobians(J, kind):
    """:func:`check_batch` for the Jacobians J (..., 6, n) a kernel is given."""
    check_batch(int(np.prod(J.shape[:-2])), J.shape[-1], kind)


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
    """a x b along axis -2 (..., 3, k): screwkit's one cross product
    (:func:`transforms._cross`, laid out (3, ...)) on that axis."""
    product = transforms._cross(np.moveaxis(a, -2, 0), np.moveaxis(b, -2, 0))
    return np.moveaxis(product, 0, -2)


def _components(J):
    """(..., 6, n) -> (6, n, ...), contiguous: each entry one contiguous array over
    the batch, so that the products below run over contiguous memory (a copy costs
    about a third of one product over a strided view)."""
    return np.ascontiguousarray(np.moveaxis(J, (-2, -1), (0, 1)))


def _rates(dq):
    return np.ascontiguousarray(np.moveaxis(dq, -1, 0))


def batch_first(C):
    """(6, n, ...) -> (..., 6, n): a view (as the chain's fk returns its batch)."""
    return np.moveaxis(C, (0, 1), (-2, -1))


def _before(rows, rates):
    """sum_{j<i} rows[:, j] rates[j] for every i (rows (k, n, ...), rates (n, ...))."""
    out = np.empty_like(rows)
    out[:, 0] = 0.0
    for i in range(1, rows.shape[1]):
        out[:, i] = out[:, i - 1] + rows[:, i - 1] * rates[i - 1]
    return out


def _from(rows, rates):
    """sum_{j>=i} rows[:, j] rates[j] for every i."""
    out = np.empty_like(rows)
    n = rows.shape[1]
    out[:, n - 1] = rows[:, n - 1] * rates[n - 1]
    for i in range(n - 2, -1, -1):
        out[:, i] = out[:, i + 1] + rows[:, i] * rates[i]
    return out


def _cross_into(out, a, b, add=False):
    """out (3, ...) = a x b, or += with ``add``, component by component in place: a
    third of the time of building the products as new arrays (the sums are
    memory-bound)."""
    scratch = np.empty_like(out[0])
    for k, (i, j) in enumerate(((1, 2), (2, 0), (0, 1))):
        if add:
            out[k] += np.multiply(a[i], b[j], out=scratch)
        else:
            np.multiply(a[i], b[j], out=out[k])
        out[k] -= np.multiply(a[j], b[i], out=scratch)
    return out


def _exact_columns(J, dq):
    return [J[:, i] * dq[i] for i in range(J.shape[1])]


def space_dot(Js, dq):
    """dJs/dt = [W_i, J_i], W_i the sum of J_j dq_j over j < i: (..., 6, n)."""
    if isinstance(Js, sp.MatrixBase):
        V, W, columns = _exact_columns(Js, dq), sp.zeros(6, 1), []
        for i in range(Js.shape[1]):
            columns.append(bracket(W, Js[:, i]))
            W = W + V[i]
        return sp.Matrix.hstack(*columns)
    return batch_first(space_dot_rows(_components(Js), _rates(dq)))


def space_dot_rows(C, rates):
    """:func:`space_dot` laid out batch last: C (6, n, ...), rates (n, ...)."""
    check_batch(int(np.prod(C.shape[2:])), C.shape[1], "Jacobian derivatives")
    W = _before(C, rates)
    out = np.empty_like(C)
    _cross_into(out[:3], W[:3], C[:3])
    _cross_into(out[3:], W[:3], C[3:])
    _cross_into(out[3:], W[3:], C[:3], add=True)
    return out


def body_dot(Jb, dq):
    """dJb/dt = [Jb_i, Wb_i], Wb_i the sum of Jb_j dq_j over j > i: (..., 6, n)."""
    if isinstance(Jb, sp.MatrixBase):
        V, W, columns = _exact_columns(Jb, dq), sp.zeros(6, 1), []
        for i in reversed(range(Jb.shape[1])):
            columns.insert(0, bracket(Jb[:, i], W))
            W = W + V[i]
        return sp.Matrix.hstack(*columns)
    _check_jacobians(Jb, "Jacobian derivatives")
    C, rates = _components(Jb), _rates(dq)
    W = _from(C, rates) - C * rates  # the sums over j > i
    out = np.empty_like(C)
    _cross_into(out[:3], C[:3], W[:3])
    _cross_into(out[3:], C[:3], W[3:])
    _cross_into(out[3:], C[3:], W[:3], add=True)
    return batch_first(out)


def geometric_dot(Jg, dq):
    """dJg/dt of the geometric Jacobian (rows [v; omega], columns (u_i; w_i)):
    (W_i x u_i + w_i x S_i; W_i x w_i), W_i the sum of w_j dq_j over j < i and S_i
    that of u_j dq_j over j >= i. (From the space form, with v_i = u_i - w_i x p and
    dp/dt = S_1, by the Jacobi identity; no point p is needed.)"""
    if isinstance(Jg, sp.MatrixBase):
        n = Jg.shape[1]
        columns = []
        for i in range(n):
            W = sum((Jg[3:, j] * dq[j] for j in range(i)), sp.zeros(3, 1))
            S = sum((Jg[:3, j] * dq[j] for j in range(i, n)), sp.zeros(3, 1))
            u, w = Jg[:3, i], Jg[3:, i]
            columns.append(sp.Matrix.vstack(W.cross(u) + w.cross(S), W.cross(w)))
        return sp.Matrix.hstack(*columns)
    return batch_first(geometric_dot_rows(_components(Jg), _rates(dq)))


def geometric_dot_rows(C, rates):
    """:func:`geometric_dot` laid out batch last: C (6, n, ...), rates (n, ...)."""
    check_batch(int(np.prod(C.shape[2:])), C.shape[1], "Jacobian derivatives")
    W, S = _before(C[3:], rates), _from(C[:3], rates)
    out = np.empty_like(C)
    _cross_into(out[:3], W, C[:3])
    _cross_into(out[:3], C[3:], S, add=True)
    _cross_into(out[3:], W, C[3:])
    return out


def _ordered_brackets(J, after):
    """Blocks H[j] (6, n) whose column i is [J_min(i,j), J_max(i,j)], the bracket of
    the earlier column with the later one, where column i comes after column j
    (``after``, the space form) or before it (the body form), else 0: (..., n, 6, n),
    or a list of n SymPy (6, n) matrices."""
    if isinstance(J, sp.MatrixBase):
        n = J.shape[1]
        return [
            sp.Matrix.hstack(
                *[
                    bracket(J[:, min(i, j)], J[:, max(i, j)])
                    if (i > j if after else i < j)
                    else sp.zeros(6, 1)
                    for i in range(n)
                ]
            )
            for j in range(n)
        ]
    _check_jacobians(J, "Hessians")
    n = J.shape[-1]
    shape = J.shape[:-2] + (n, 6, n)
    row_j = np.broadcast_to(J.swapaxes(-1, -2)[..., :, :, None], shape)
    column_i = np.broadcast_to(J[..., None, :, :], shape)
    if after:
        return bracket(row_j, column_i) * np.triu(np.ones((n, n)), 1)[:, None, :]
    return bracket(column_i, row_j) * np.tril(np.ones((n, n)), -1)[:, None, :]


def space_hessian(Js):
    """H[j, :, i] = dJs_i/dq_j = [J_j, J_i] for j < i, else 0: (..., n, 6, n)."""
    return _ordered_brackets(Js, after=True)


def body_hessian(Jb):
    """H[j, :, i] = dJb_i/dq_j = [Jb_i, Jb_j] for j > i, else 0: (..., n, 6, n)."""
    return _ordered_brackets(Jb, after=False)


def geometric_hessian(Jg):
    """H[j] = dJg/dq_j of the geometric Jacobian (rows [v; omega], columns (u; w)):
    column i is (w_j x u_i; w_j x w_i) for j < i and (w_i x u_j; 0) for j >= i
    (:func:`geometric_dot` with dq = e_j); its rows v are symmetric in i and j."""
    if isinstance(Jg, sp.MatrixBase):
        n = Jg.shape[1]
        return [
            geometric_dot(Jg, [1 if k == j else 0 for k in range(n)]) for j in range(n)
        ]
    _check_jacobians(Jg, "Hessians")
    n = Jg.shape[-1]
    shape = Jg.shape[:-2] + (n, 3, n)
    u, w = Jg[..., :3, :], Jg[..., 3:, :]
    w_j = np.broadcast_to(w.swapaxes(-1, -2)[..., :, :, None], shape)
    # A[j, :, i] = w_j x u_i; the rows v take A[j, :, i] for j < i, A[i, :, j] else
    A = _cross(w_j, np.broadcast_to(u[..., None, :, :], shape))
    before = np.triu(np.ones((n, n), dtype=bool), 1)[:, None, :]
    linear = np.where(before, A, np.swapaxes(A, -1, -3))
    angular = _cross(w_j, np.broadcast_to(w[..., None, :, :], shape)) * before
    return np.concatenate([linear, angular], axis=-2)
