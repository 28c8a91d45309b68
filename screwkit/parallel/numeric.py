"""The numeric kernels of :mod:`screwkit.parallel`: the platform points of a batch of
poses, and Newton-Raphson on the loop closure, vectorised over a leading batch axis.

Points are laid out component first, (3, N, m), as in :mod:`screwkit.parallel.legs`.
"""

import numpy as np

from .._docstrings import fill
from ..tolerances import (
    PARALLEL_FK_ACCEPT_TOL,
    PARALLEL_NEWTON_MAX_STEP,
    PARALLEL_RANK_TOL,
)
from ..transforms import _cross, _rodrigues, _skew

__all__ = ["points", "solve", "solve_least_squares", "newton", "closure_rows"]


def points(R, p, b):
    """The platform points p + R b of every pose, component first.

    Parameters
    ----------
    R : ndarray, shape (N, 3, 3)
        The platforms' rotations (base frame).
    p : ndarray, shape (N, 3)
        The platforms' origins (m, base frame).
    b : ndarray, shape (m, 3)
        The attachment points in the platform frame (m).

    Returns
    -------
    ndarray, shape (3, N, m)
        Coordinate k of point i at pose n in ``[k, n, i]`` (m, base frame).

    Examples
    --------
    A level platform at (3, 4, 0): its points (0, 0), (1, 0), (0, 1) move with it.

    >>> b = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    >>> C = points(np.eye(3)[None], np.array([[3.0, 4.0, 0.0]]), b)
    >>> C.shape, C[:, 0, :].T.tolist()
    ((3, 1, 3), [[3.0, 4.0, 0.0], [4.0, 4.0, 0.0], [3.0, 5.0, 0.0]])
    """
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


def _exp_rotation(w):
    """exp([w]) for rotation vectors w (N, 3) (rad): transforms' Rodrigues kernel on
    the unit axis w / |w|, with 1 - cos written 2 sin^2(theta / 2) (exact for small
    steps)."""
    theta = np.linalg.norm(w, axis=-1)
    unit = w / np.where(theta > 0, theta, 1.0)[:, None]  # w = 0: no turn
    half = np.sin(0.5 * theta)[:, None, None]
    return _rodrigues(_skew(unit), np.sin(theta)[:, None, None], 2 * half * half)


_SYSTEMS = """Parameters
----------
A : ndarray, shape (N, k, k)
b : ndarray, shape (N, k)
    N systems A x = b."""


@fill(systems=_SYSTEMS)
def solve(A, b):
    """Batched linear solve, one system at a time where the batch has a singular one.

    {systems}

    Returns
    -------
    ndarray, shape (N, k)
        x with A x = b; NaN rows where A is singular.

    Examples
    --------
    Two systems, the second singular:

    >>> A = np.array([[[2.0, 0.0], [0.0, 4.0]], [[1.0, 1.0], [1.0, 1.0]]])
    >>> solve(A, np.array([[2.0, 4.0], [1.0, 1.0]]))
    array([[ 1.,  1.],
           [nan, nan]])
    """
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


@fill(systems=_SYSTEMS)
def solve_least_squares(A, b):
    """Batched minimum-norm least-squares solve (singular values below
    ``PARALLEL_RANK_TOL`` times the largest are dropped).

    {systems}

    Returns
    -------
    ndarray, shape (N, k)
        The x of least norm that minimises |A x - b| (0 where A is 0).

    Examples
    --------
    x + y = 2 twice: of all its solutions, (1, 1) is the shortest.

    >>> A = np.array([[[1.0, 1.0], [1.0, 1.0]]])
    >>> solve_least_squares(A, np.array([[2.0, 2.0]])).round(12)
    array([[1., 1.]])
    """
    with np.errstate(all="ignore"):
        return (np.linalg.pinv(A, rcond=PARALLEL_RANK_TOL) @ b[..., None])[..., 0]


def closure_rows(legs, platform_points, freedoms, T, rho, scale=1.0):
    """The loop closure's residual and its derivative along the free twist components,
    with the linear columns times ``scale`` (every column a length).

    Parameters
    ----------
    legs : the legs' model
    platform_points : ndarray, shape (m, 3)
    freedoms : list of int
    T : ndarray, shape (N, 4, 4)
    rho : ndarray, shape (N, m)
    scale : float
        The mechanism's size (m).

    Returns
    -------
    r : ndarray, shape (N, m)
        The residual (m).
    rows : ndarray, shape (N, m, len(freedoms))
        dr/dV with V's linear components in units of ``scale`` (m).

    Examples
    --------
    A 3-RPR whose legs from (0, 0), (4, 0), (3, 9) to (3, 4), (4, 4), (3, 5) are
    5, 4 and 4 m: closed (r = 0), and the rows over (w_z, v_x, v_y) are
    [(C x n)_z, n_x, n_y], n the unit leg directions.

    >>> from screwkit.parallel.legs import Prismatic
    >>> legs = Prismatic([[0, 0, 0], [4, 0, 0], [3, 9, 0]], planar=True)
    >>> b = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    >>> T = np.eye(4)[None]
    >>> T[0, :3, 3] = [3.0, 4.0, 0.0]
    >>> r, rows = closure_rows(legs, b, [2, 3, 4], T, np.array([[5.0, 4.0, 4.0]]))
    >>> r.tolist(), (rows[0].round(12) + 0.0).tolist()
    ([[0.0, 0.0, 0.0]], [[0.0, 0.6, 0.8], [4.0, 0.0, 1.0], [-3.0, 0.0, -1.0]])
    """
    C = points(T[:, :3, :3], T[:, :3, 3], platform_points)
    r, g, _ = legs.closure(C, rho)
    rows = np.stack([*_cross(C, g), *(scale * g)], axis=-1)
    return r, rows[:, :, freedoms]


def newton(
    legs,
    platform_points,
    freedoms,
    rho,
    T0,
    tol,
    max_iterations,
    scale=1.0,
    least_squares=False,
):
    """Newton-Raphson on the loop closure r(C, rho) = 0 over the free twist components.

    Each step solves the rows [C x g, g] (the closure's derivative along the space
    twist) for the twist that cancels the residual, damped so that no component exceeds
    ``PARALLEL_NEWTON_MAX_STEP`` (rad, or times ``scale`` in m), and moves the pose by
    R <- exp([w]) R, p <- p + v + w x p (the first order of exp([V]) T: Newton's
    quadratic convergence is kept).

    Parameters
    ----------
    legs : the legs' model (:mod:`screwkit.parallel.legs`), with ``closure``
    platform_points : ndarray, shape (m, 3)
        Attachment points b_i in the platform frame (m).
    freedoms : list of int
        The free components of the twist [wx, wy, wz, vx, vy, vz].
    rho : ndarray, shape (N, m)
        The actuated joint values (m or rad).
    T0 : ndarray, shape (1, 4, 4) or (N, 4, 4)
        Starting poses.
    tol : float
        Residual (m) below which a pose has converged.
    max_iterations : int
    scale : float
        The mechanism's size (m), for the step's damping and the acceptance floor.
    least_squares : bool
        Take the minimum-norm least-squares step (Gauss-Newton, for a Jacobian that
        loses rank on a continuum of solutions) instead of the exact solve.

    Returns
    -------
    T : ndarray, shape (N, 4, 4)
        The poses, NaN where Newton did not converge.
    success : ndarray of bool, shape (N,)
    iterations : ndarray of int, shape (N,)
    error : ndarray, shape (N,)
        The largest loop-closure residual of each pose (m).

    Examples
    --------
    The 3-RPR of :func:`closure_rows`, started 0.1 m off the pose whose legs are 5,
    4 and 4 m, returns to it (x, y and the angle about z free):

    >>> from screwkit.parallel.legs import Prismatic
    >>> legs = Prismatic([[0, 0, 0], [4, 0, 0], [3, 9, 0]], planar=True)
    >>> b = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    >>> T0 = np.eye(4)[None]
    >>> T0[0, :3, 3] = [3.1, 3.9, 0.0]
    >>> T, success, iterations, error = newton(
    ...     legs, b, [2, 3, 4], np.array([[5.0, 4.0, 4.0]]), T0, 1e-10, 50)
    >>> T[0, :3, 3].round(6) + 0.0, success
    (array([3., 4., 0.]), array([ True]))
    """
    N = len(rho)
    R = np.array(np.broadcast_to(T0[:, :3, :3], (N, 3, 3)))
    p = np.array(np.broadcast_to(T0[:, :3, 3], (N, 3)))
    free = freedoms
    iterations = np.zeros(N, int)
    done = np.zeros(N, bool)
    # the step measured in rad for w and in mechanism sizes for v
    units = np.array([1.0, 1.0, 1.0, scale, scale, scale])
    for _ in range(max_iterations):
        C = points(R, p, platform_points)
        r, g, dr = legs.closure(C, rho)
        error = np.max(np.abs(r), axis=1)
        done = done | (error < tol)
        if done.all():
            break
        rows = np.stack([*_cross(C, g), *g], axis=-1)
        rows = rows if len(free) == 6 else rows[:, :, free]
        step = np.zeros((N, 6))
        if least_squares:  # the columns made lengths, so the rank is unit-free
            step[:, free] = solve_least_squares(rows * units[free], -r) * units[free]
        else:
            with np.errstate(all="ignore"):
                step[:, free] = solve(rows, -r)
        step[done] = 0.0
        size = np.max(np.abs(step) / units, axis=1, keepdims=True)
        step = step * np.minimum(
            1.0, PARALLEL_NEWTON_MAX_STEP / np.where(size > 0, size, 1.0)
        )  # damped
        iterations += ~done
        w, v = step[:, :3], step[:, 3:]
        R = _exp_rotation(w) @ R
        p = p + v + np.cross(w, p)
    C = points(R, p, platform_points)
    error = np.max(np.abs(legs.closure(C, rho)[0]), axis=1)
    success = np.isfinite(error) & (error < max(tol, PARALLEL_FK_ACCEPT_TOL * scale))
    T = np.zeros((N, 4, 4))
    T[:, :3, :3], T[:, :3, 3], T[:, 3, 3] = R, p, 1.0
    T[~success] = np.nan
    return T, success, iterations, error
