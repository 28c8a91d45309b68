"""The kinematics :mod:`screwkit.ik.general` polishes and checks its candidates with.

The product of exponentials of k joint vectors at once, with the space Jacobian, the
pose error twist and Newton's steps on it, and the residual of each solution by the
chain's own forward kinematics. Each joint's motion is the 4 x 4 matrix
exp([S] q) = I + sin(q) [S] + (1 - cos(q)) [S]^2 of a unit revolute screw S (its
[S]^3 = -[S]), for every joint and candidate in one NumPy call, so that the cost of a
call hardly depends on k (one pose has up to 16 candidates, a batch thousands).
"""

import functools

import numpy as np

from .. import _compiled
from ..tolerances import (
    IK_GENERAL_HADAMARD_TOL,
    IK_GENERAL_KEEP_BOUND,
    IK_GENERAL_KEEP_STEP,
    IK_GENERAL_POLISH_TOL,
    IK_GENERAL_SINGULAR_TOL,
)
from ..transforms import _cross_last, _skew

__all__ = []

#: Newton steps that polish each candidate (quadratic convergence from the
#: eigenvalue's 1e-8 or better reaches round-off in two or three).
NEWTON_STEPS = 6

#: Up to this many candidates, the residuals are computed one by one with the chain's
#: scalar forward kinematics (its generated code on floats), cheaper than the batch
#: form on arrays of a few entries.
SCALAR_RESIDUALS = 48


# ---- LAPACK without the public functions' checks ------------------------------------
#
# np.linalg's solve, eigvals, svd and det check and convert their arguments in Python,
# about 5 to 20 us a call, more than the LAPACK work on the solver's small float64
# arrays of one pose. The functions below call the same gufuncs (the same results) on
# arrays known to be float64 stacks of matrices, with the same floating-point error
# handling; where NumPy lacks that module (or its names), the public functions.

try:
    from numpy.linalg import _umath_linalg as _gufuncs
except ImportError:  # pragma: no cover - every NumPy screwkit supports has it
    _gufuncs = None


def _raising(message):
    """The floating-point error state np.linalg's functions call their gufuncs in:
    a failure (LAPACK's, signalled as an invalid operation) raises LinAlgError
    with ``message``; overflow, division and underflow pass."""

    def fail(error, flag):
        raise np.linalg.LinAlgError(message)

    return np.errstate(
        call=fail, invalid="call", over="ignore", divide="ignore", under="ignore"
    )


def lapack_solve(a, b):
    """np.linalg.solve(a, b) of float64 matrices a (..., n, n) and b (..., n, m)
    (LinAlgError for a singular a)."""
    if _gufuncs is None:  # pragma: no cover
        return np.linalg.solve(a, b)
    with _raising("Singular matrix"):
        return _gufuncs.solve(a, b, signature="dd->d")


def lapack_eigvals(a):
    """The eigenvalues (..., n), complex, of float64 matrices a (..., n, n) with
    finite entries, as np.linalg.eigvals gives them (LinAlgError where they do not
    converge)."""
    if _gufuncs is None:  # pragma: no cover
        return np.linalg.eigvals(a).astype(complex)
    with _raising("Eigenvalues did not converge"):
        return _gufuncs.eigvals(a, signature="d->D")


def lapack_svd(a, compute_uv=True):
    """np.linalg.svd(a, compute_uv=compute_uv) (full matrices) of float64 matrices a
    (..., m, n): (u, s, vh), or s alone."""
    if not hasattr(_gufuncs, "svd_f"):  # pragma: no cover - NumPy 1's names
        return np.linalg.svd(a, compute_uv=compute_uv)
    with _raising("SVD did not converge"):
        if compute_uv:
            return _gufuncs.svd_f(a, signature="d->ddd")
        return _gufuncs.svd(a, signature="d->d")


def lapack_det(a):
    """np.linalg.det of float64 matrices a (..., n, n)."""
    if _gufuncs is None:  # pragma: no cover
        return np.linalg.det(a)
    return _gufuncs.det(a, signature="d->d")


#: by_identity's store: (the arrays, the value) by the arrays' ids and a key.
_BY_IDENTITY = {}
_BY_IDENTITY_SIZE = 256


def by_identity(arrays, key, make):
    """``make()``, kept by the identity of ``arrays`` (a tuple of read-only arrays,
    e.g. a chain's cached axes) and a hashable ``key``: a look-up that costs no
    copy or hash of the arrays' bytes. The arrays are held with the value, so that
    their ids are not reused while it is kept."""
    ids = (*map(id, arrays), key)
    found = _BY_IDENTITY.get(ids)
    if found is not None:
        return found[1]
    if len(_BY_IDENTITY) >= _BY_IDENTITY_SIZE:
        _BY_IDENTITY.clear()
    value = make()
    _BY_IDENTITY[ids] = (arrays, value)
    return value


@functools.lru_cache(maxsize=64)
def _screw_matrices_cached(w, r):
    """screw_matrices on bytes (hashable), cached."""
    w, r = np.frombuffer(w).reshape(-1, 3), np.frombuffer(r).reshape(-1, 3)
    S = np.zeros((len(w), 4, 4))
    S[:, :3, :3] = _skew(w)
    S[:, :3, 3] = _cross_last(r, w)
    lines = np.zeros((len(w), 4, 2))  # each axis as a direction and a point
    lines[:, :3, 0], lines[:, :3, 1], lines[:, 3, 1] = w, r, 1.0
    found = S, S @ S, lines
    for array in found:
        array.setflags(write=False)
    return found


def screw_matrices(w, r):
    """[S] and [S]^2 (6, 4, 4) of the unit revolute screws S = (w, r x w) of the axes
    along unit w through r (6, 3), and the axes as homogeneous (w, 0) and (r, 1)
    columns (6, 4, 2); cached (a chain's axes are used call after call)."""
    return by_identity(
        (w, r),
        "screws",
        lambda: _screw_matrices_cached(
            np.ascontiguousarray(w, float).tobytes(),
            np.ascontiguousarray(r, float).tobytes(),
        ),
    )


#: The identity of a pose.
_EYE4 = np.eye(4)
_EYE4.setflags(write=False)


def poe(w, r, home, q):
    """The pose exp([S1] q1) ... exp([S6] q6) M (rotation (k, 3, 3), position (k, 3))
    and the space Jacobian (k, 6, 6), [omega; v] rows, of the axes (w, r) (6, 3) and
    the home pose M (4, 4) at the joint vectors q (k, 6)."""
    S, S2, lines = screw_matrices(w, r)
    angle = q[..., None, None]
    E = _EYE4 + np.sin(angle) * S + (1 - np.cos(angle)) * S2  # (k, 6, 4, 4)
    prefix = np.empty_like(E)  # E1 ... E(i-1), the motion before joint i
    prefix[:, 0] = _EYE4
    for i in range(1, 6):
        np.matmul(prefix[:, i - 1], E[:, i - 1], out=prefix[:, i])
    T = prefix[:, 5] @ E[:, 5] @ home
    # the axes at q: rows (w, r) of each joint's column, then (r x w)
    moved = (prefix[..., :3, :] @ lines).swapaxes(2, 3)  # (k, 6, 2, 3)
    J = np.empty((len(q), 6, 6))
    Jt = J.swapaxes(1, 2)  # (k, joint, row), a view
    Jt[..., :3] = ws = moved[:, :, 0]
    Jt[..., 3:] = _cross_last(moved[:, :, 1], ws)
    return T[:, :3, :3], T[:, :3, 3], J


def error(w, r, home, targets, q):
    """The error twists e (k, 6) of q (k, 6) against their targets (k, 4, 4) and the
    space Jacobians (k, 6, 6): e = (omega, dp - omega x p), omega the vee of the skew
    part of R* R(q)^T and dp the position error, the spatial error twist to first
    order."""
    R, p, J = poe(w, r, home, q)
    E = targets[:, :3, :3] @ np.swapaxes(R, 1, 2)
    e = np.empty((len(E), 6))
    # omega, the vee of (E - E^T) / 2: entries (2, 1), (0, 2), (1, 0) less (1, 2),
    # (2, 0), (0, 1); then dp - omega x p
    omega = e[:, :3]
    np.subtract(E[:, _VEE_ROWS, _VEE_COLUMNS], E[:, _VEE_COLUMNS, _VEE_ROWS], out=omega)
    omega /= 2
    e[:, 3:] = targets[:, :3, 3] - p - _cross_last(omega, p)
    return e, J


#: The entries of a 3 x 3 matrix whose differences with their transposes' give its
#: skew part's vee: (2, 1), (0, 2), (1, 0).
_VEE_ROWS, _VEE_COLUMNS = np.array([2, 0, 1]), np.array([1, 2, 0])


def newton_step(J, e, det=None):
    """The Newton steps pinv(J) e (k, 6) for Jacobians J (k, 6, 6) (their
    determinants ``det`` (k,) if known) and errors e (k, 6): an LU solve where J
    is well conditioned (IK_GENERAL_HADAMARD_TOL; the pseudo-inverse's step there,
    up to round-off), the pseudo-inverse's minimum-norm step where J is nearly
    singular (a solution on a continuum, where the two differ)."""
    det = lapack_det(J) if det is None else det
    ratio = np.abs(det) / np.sqrt((J * J).sum(axis=1).prod(axis=1))
    if all(x > IK_GENERAL_HADAMARD_TOL for x in ratio.tolist()):
        return lapack_solve(J, e[:, :, None])[..., 0]  # every J well conditioned
    near = ~(ratio > IK_GENERAL_HADAMARD_TOL)  # a NaN too
    dq = np.empty(e.shape)
    if not near.all():
        dq[~near] = lapack_solve(J[~near], e[~near, :, None])[..., 0]
    dq[near] = (np.linalg.pinv(J[near]) @ e[near, :, None])[..., 0]
    return dq


def polish(w, r, home, targets, q, measure):
    """Newton steps J_s dq = e (:func:`error`) on the pose from the candidates q
    (k, 6) towards their targets (k, 4, 4), lengths divided by the chain's size:
    quadratic convergence near a solution, no logarithm.

    ``measure(q, rows)`` gives the residuals (m,) of the candidates ``rows`` (an
    index array (m,) or a slice) at q (m, 6) by the chain's own forward kinematics
    (:func:`residuals`): after the first step it decides which candidates need
    more (a residual above IK_GENERAL_POLISH_TOL; from a simple root, none), so
    that the usual candidate costs one error and Jacobian. Returns the polished q
    (k, 6), the space Jacobians (k, 6, 6) for the singular flags, the residuals
    (k,) and the Jacobians' Hadamard ratios (k,) (:func:`_hadamard`). A Jacobian
    is the one before the last step where that step moved no joint by more than
    IK_GENERAL_KEEP_STEP and the Jacobian is far from singular (its Hadamard bound
    above IK_GENERAL_KEEP_BOUND; :func:`singular`): the step cannot change its flag;
    elsewhere it is computed again at the polished q."""
    q = q.copy()
    e, J = error(w, r, home, targets, q)
    det = lapack_det(J)
    flags = [x > IK_GENERAL_POLISH_TOL for x in np.sqrt((e * e).sum(axis=1)).tolist()]
    moving, every, some = np.array(flags, bool), all(flags), any(flags)
    moved = np.zeros(len(q))  # each row's largest joint step since its Jacobian
    if every or (some and np.isfinite(q).all()):
        # each row's step is its own solve: every row at once (finite q: finite J),
        # those that need none kept still
        step = newton_step(J, e, det)
        if not every:
            step = np.where(moving[:, None], step, 0.0)
        q += step
        moved = np.abs(step).max(axis=1)
    elif some:
        step = newton_step(J[moving], e[moving], det[moving])
        q[moving] += step
        moved[moving] = np.abs(step).max(axis=1)
    found = measure(q, slice(None))
    # candidates the first step did not bring to round-off: Newton goes on
    if all(x <= IK_GENERAL_POLISH_TOL for x in found.tolist()):
        active = np.zeros(0, int)
    else:
        active = np.nonzero(~(found <= IK_GENERAL_POLISH_TOL))[0]
    again = active
    for _ in range(NEWTON_STEPS - 1):
        if not len(active):
            break
        e, J_active = error(w, r, home, targets[active], q[active])
        J[active], moved[active] = J_active, 0.0
        det[active] = det_active = lapack_det(J_active)
        going = np.sqrt((e * e).sum(axis=1)) > IK_GENERAL_POLISH_TOL
        active, e, J_active = active[going], e[going], J_active[going]
        if len(active):
            step = newton_step(J_active, e, det_active[going])
            q[active] += step
            moved[active] = np.abs(step).max(axis=1)
    if len(again):
        found[again] = measure(q[again], again)
    bound = _hadamard(J, det)
    stale = [
        i
        for i, (step, b) in enumerate(zip(moved.tolist(), bound.tolist()))
        if step > 0 and not (step <= IK_GENERAL_KEEP_STEP and b > IK_GENERAL_KEEP_BOUND)
    ]
    if stale:
        J[stale] = J_stale = poe(w, r, home, q[stale])[2]
        bound[stale] = _hadamard(J_stale)
    return q, J, found, bound


def _hadamard(J, det=None):
    """|det J| / |J|_F^6 (k,) of Jacobians J (k, 6, 6) (their determinants ``det``
    (k,) if known): a lower bound of sigma_min / sigma_max
    (sigma_min sigma_max^5 >= |det J|, |J|_F >= sigma_max)."""
    det = lapack_det(J) if det is None else det
    return np.abs(det) / (J * J).sum(axis=(1, 2)) ** 3


def residuals(chain, T, q, scale):
    """The pose error (k,) of each q (k, 6) against its pose T (k, 4, 4) by the
    chain's own forward kinematics: sqrt(|R(q) - R|_F^2 / 2 + |p(q) - p|^2 / scale^2),
    which is the norm of the error twist [omega; v / scale] to first order
    (|R(q) - R|_F = 2 sqrt(2) sin(angle / 2)) and, unlike the skew part of R(q)^T R,
    vanishes only at the pose itself."""
    if len(q) <= SCALAR_RESIDUALS:
        pose = _compiled.scalar(chain, "pose")
        top = np.array([pose(row) for row in q.tolist()]).reshape(-1, 3, 4)
    else:
        top = chain.fk(q)[:, :3]
    # the squared differences weighted: rotation entries by 1/2, position by 1/scale^2
    return np.sqrt(((top - T[:, :3]) ** 2 * _weights(scale)).sum(axis=(1, 2)))


@functools.lru_cache(maxsize=64)
def _weights(scale):
    """The weights (3, 4) of :func:`residuals`' squared differences: 1/2 for the
    rotation's entries, 1/scale^2 for the position's (read-only)."""
    weights = np.full((3, 4), 0.5)
    weights[:, 3] = 1 / scale**2
    weights.setflags(write=False)
    return weights


def singular(J, bound=None):
    """Whether each Jacobian J (k, 6, 6) (its :func:`_hadamard` ratio ``bound``
    (k,) if known) loses rank (IK_GENERAL_SINGULAR_TOL)."""
    flags = np.zeros(len(J), bool)
    # sigma_min / sigma_max >= |det J| / |J|_F^6: where that bound clears the
    # tolerance, J keeps its rank and needs no SVD
    bound = _hadamard(J) if bound is None else bound
    if all(b > IK_GENERAL_SINGULAR_TOL for b in bound.tolist()):
        return flags
    check = ~(bound > IK_GENERAL_SINGULAR_TOL)
    if check.any():
        sigma = lapack_svd(J[check], compute_uv=False)
        flags[check] = sigma[:, -1] <= IK_GENERAL_SINGULAR_TOL * sigma[:, 0]
    return flags
