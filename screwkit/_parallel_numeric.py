"""The numeric kernels of :mod:`screwkit.parallel`: fast pose checks, platform points of
a batch, and Newton-Raphson on the loop closure, vectorised over a leading batch axis.

Points are laid out component first, (3, N, m), as in :mod:`screwkit._parallel_legs`.
"""

import numpy as np

from ._checks import ORTHONORMAL_TOL, check_transform

#: Where R_ij sits in a flattened 4 x 4 pose, for i, j = 0, 1, 2.
_ROTATION = [0, 1, 2, 4, 5, 6, 8, 9, 10]

__all__ = ["check_poses", "points", "cross", "rodrigues", "solve", "newton"]


def check_poses(T, name):
    """check_transform, with a fast first pass for a float batch (N, 4, 4): the full
    check (and its message) runs only when the fast one finds something wrong."""
    if (
        isinstance(T, np.ndarray)
        and T.dtype == float
        and T.ndim == 3
        and T.shape[1:] == (4, 4)
    ):
        flat = T.reshape(-1, 16)
        worst, det = 0.0, 1.0
        for start in range(0, len(flat), 8192):  # blocks that stay in the cache
            block_worst, block_det = _gram_and_det(
                flat[start : start + 8192].T[_ROTATION]
            )
            worst, det = max(worst, block_worst), min(det, block_det)
        last = np.max(np.abs(T[:, 3, :] - [0.0, 0.0, 0.0, 1.0]), initial=0.0)
        if (
            worst <= ORTHONORMAL_TOL
            and last <= 1e-12
            and det > 0
            and np.isfinite(T).all()
        ):
            return T
    return check_transform(T, name)


def _gram_and_det(r):
    """max |R^T R - I| and min det R over rotations given as rows r[3 i + j] = R_ij."""
    col = [(r[j], r[3 + j], r[6 + j]) for j in range(3)]
    dot, term = np.empty(r.shape[1]), np.empty(r.shape[1])  # in place: no temporaries
    worst = 0.0
    for i in range(3):
        for j in range(i, 3):
            np.multiply(col[i][0], col[j][0], out=dot)
            for k in (1, 2):
                dot += np.multiply(col[i][k], col[j][k], out=term)
            target = float(i == j)
            worst = max(worst, dot.max() - target, target - dot.min())
    # det R = c0 . (c1 x c2) > 0 (a reflection passes the Gram test)
    np.multiply(col[1][1], col[2][2], out=dot)
    dot -= np.multiply(col[1][2], col[2][1], out=term)
    det = dot * col[0][0]
    np.multiply(col[1][2], col[2][0], out=dot)
    dot -= np.multiply(col[1][0], col[2][2], out=term)
    det += np.multiply(dot, col[0][1], out=term)
    np.multiply(col[1][0], col[2][1], out=dot)
    dot -= np.multiply(col[1][1], col[2][0], out=term)
    det += np.multiply(dot, col[0][2], out=term)
    return worst, det.min(initial=1.0)


def points(R, p, b):
    """p + R b for poses R (N, 3, 3), p (N, 3) and points b (m, 3): (3, N, m)."""
    N, m = len(R), len(b)
    M = np.empty((3, N, 4))  # row k of [R p] for every pose, then one product
    M[:, :, :3], M[:, :, 3] = R.transpose(1, 0, 2), p.T
    M = M.reshape(-1, 4)
    B = np.vstack([b.T, np.ones(m)])  # homogeneous points as columns
    out = np.empty((3 * N, m))
    # products of 2048 rows stay on one BLAS thread (threads contend on a busy machine)
    for start in range(0, 3 * N, 2048):
        np.matmul(M[start : start + 2048], B, out=out[start : start + 2048])
    return out.reshape(3, N, m)


def cross(a, b):
    return np.stack(
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    )


def rodrigues(w):
    """exp([w]) for w of shape (N, 3)."""
    theta = np.linalg.norm(w, axis=-1)[..., None, None]
    K = np.zeros(w.shape[:-1] + (3, 3))
    K[..., 0, 1], K[..., 0, 2], K[..., 1, 2] = -w[..., 2], w[..., 1], -w[..., 0]
    K = K - np.swapaxes(K, -1, -2)
    small = theta < 1e-8
    safe = np.where(small, 1.0, theta)
    a = np.where(small, 1.0, np.sin(safe) / safe)
    b = np.where(small, 0.5, (1 - np.cos(safe)) / safe**2)
    return np.eye(3) + a * K + b * (K @ K)


def solve(A, b):
    """Batched A x = b for square A (N, k, k); NaN rows where A is singular."""
    try:
        return np.linalg.solve(A, b[..., None])[..., 0]
    except np.linalg.LinAlgError:
        out = np.full(b.shape, np.nan)
        for n in range(len(A)):
            try:
                out[n] = np.linalg.solve(A[n], b[n])
            except np.linalg.LinAlgError:
                pass
        return out


def newton(legs, platform_points, freedoms, rho, T0, tol, max_iterations):
    """Newton-Raphson on the loop closure r(C, rho) = 0 over the free twist components,
    from the poses T0 (1 or N, 4, 4): (T, success, iterations, error), T NaN where it
    did not converge. Each step solves the rows [C x g, g] (the closure's derivative
    along the space twist) for the twist that cancels the residual, damped to 0.5 in
    any component, and moves the pose by R <- exp([w]) R, p <- p + v + w x p (the first
    order of exp([V]) T: Newton's quadratic convergence is kept)."""
    N = len(rho)
    R = np.array(np.broadcast_to(T0[:, :3, :3], (N, 3, 3)))
    p = np.array(np.broadcast_to(T0[:, :3, 3], (N, 3)))
    free = freedoms
    iterations = np.zeros(N, int)
    done = np.zeros(N, bool)
    for _ in range(max_iterations):
        C = points(R, p, platform_points)
        r, g, dr = legs.closure(C, rho)
        error = np.max(np.abs(r), axis=1)
        done = done | (error < tol)
        if done.all():
            break
        rows = np.stack([*cross(C, g), *g], axis=-1)
        rows = rows if len(free) == 6 else rows[:, :, free]
        step = np.zeros((N, 6))
        with np.errstate(all="ignore"):
            step[:, free] = solve(rows, -r)
        step[done] = 0.0
        size = np.max(np.abs(step), axis=1, keepdims=True)
        step = step * np.minimum(1.0, 0.5 / np.where(size > 0, size, 1.0))  # damped
        iterations += ~done
        w, v = step[:, :3], step[:, 3:]
        R = rodrigues(w) @ R
        p = p + v + np.cross(w, p)
    C = points(R, p, platform_points)
    error = np.max(np.abs(legs.closure(C, rho)[0]), axis=1)
    success = np.isfinite(error) & (error < max(tol, 1e-10))
    T = np.zeros((N, 4, 4))
    T[:, :3, :3], T[:, :3, 3], T[:, 3, 3] = R, p, 1.0
    T[~success] = np.nan
    return T, success, iterations, error
