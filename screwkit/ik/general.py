"""Every inverse-kinematics solution of any 6R serial chain: the Raghavan–Roth
elimination solved as an eigenvalue problem (Manocha and Canny 1994).

With E_i = exp([S_i] q_i) and G = T M^-1 the loop is E1 E2 E3 E4 E5 E6 = G. Joint 6
leaves its own axis fixed: a point p6 on it and its direction w6. So

    E3 E4 E5 (p6, w6) = E2^-1 E1^-1 G (p6, w6),

two vectors p and l on each side, and with them p.p, p.l, p x l and
(p.p) l - 2 (p.l) p: 14 equations whose two sides have degree at most one in the
cosine and sine of each joint angle (Raghavan and Roth 1993; the products keep that
degree because each side is a rotation about one axis after another). The right side
is a constant plus Q b, b the 8 products (1, c1, s1) x (1, c2, s2) without 1, so the 6
combinations N with N Q = 0 are free of joints 1 and 2: 6 equations in the 9 products
(1, c4, s4) x (1, c5, s5), each of degree one in (c3, s3). In half-angle tangents
x_i = tan(q_i / 2) and with a second copy multiplied by x4 they are 12 equations,
linear in the 12 monomials x4^i x5^j (i <= 3, j <= 2), quadratic in x3:
(M0 + x3 M1 + x3^2 M2) v = 0, a 24 x 24 eigenvalue problem (its companion matrix). Its
real eigenvalues give q3; the vector v of each (the null vector of M(x3), by one step
of inverse iteration rather than the companion's eigenvectors) q4 and q5, the 14
equations q1 and q2, the rotation left q6; every candidate is then polished by Newton
steps on the chain's own forward kinematics and Jacobian (one step, and more only
where the chain's residual is not yet at round-off), and kept when it meets the
pose. At most 16 solutions.

Each side's coefficients are found by sampling: a function of degree one in
(cos, sin) of an angle is fixed by its values at three equally spaced angles, so the
side's values on a 3 x 3 (x 3) grid give its coefficients exactly, from the chain's
screws at any geometry. The angles are shifted (q_i = phi_i + delta_i, fixed
pseudo-random delta) so that no solution sits at a half-angle tangent of infinity.

Special geometry (intersecting or parallel axes) can make Q lose rank or the
eigenvalue problem singular (det M(x3) = 0 for every x3). The same loop is then
written again with another joint first (a cyclic shift: E2 ... E6 (G^-1 E1 G) = G) or
backwards (E6^-1 ... E1^-1 = G^-1), twelve formulations in all (the PUMA 560 and the
UR5e are solved so); a nearly degenerate form is used only when no well-conditioned
one exists; when every one is degenerate the answer says so (a reason, no solutions)
rather than give a wrong count.

A batch of poses is solved together: the elimination is the same for every pose, so
each step is one NumPy call for the whole batch (the 24 x 24 eigenvalue problems
included), and a pose whose form turns out degenerate goes on to the next form with
the other poses that did.

One pose (T of shape (4, 4)) goes the same steps with less bookkeeping: the chain's
constants (its axes and home pose, the left side's coefficients, the right side's
motions at the grid, the screw matrices the polish multiplies) are computed once per
chain and cached, the form that last solved a pose of the chain is tried alone, and
the batch path takes over when that form depends on the pose (a shifted one), is
nearly degenerate here or finds no solution. Its answer is the batch path's.

What the answer claims: every real root of the eigenvalue problem whose imaginary
part is below IK_GENERAL_REAL_TOL becomes a candidate, and every candidate that
Newton brings to the pose (residual at most IK_GENERAL_ACCEPT_TOL) is returned once.
Every genuine real root (its joints 1 and 2 consistent, IK_GENERAL_CONSISTENT_TOL;
special geometry adds spurious ones, e.g. the PUMA's q = 0 and pi) must be accounted
for by as many returned solutions (their angle within IK_GENERAL_EXPLAINED_TOL) as
it has consistent candidates, at most its multiplicity (solutions that share the
eigenvalue joint's angle make a repeated root, one candidate each): a root short of
solutions makes the reason say that the list may be incomplete, so a short list is
never silent (unless a solution it has is singular: solutions coincide there). A
solution where the Jacobian loses rank (solutions coinciding, or a continuum along
aligned axes) is flagged in ``singular`` and the reason says so: of a continuum, Q
holds points only.

An arm whose axes leave it fewer than six degrees of freedom (all parallel, two
coincident; its Jacobian's rank below 6 at every configuration) has continua where
the elimination is degenerate, and the reason says how many freedoms it has. Where
the elimination finds nothing, damped Newton steps from SEARCH_STARTS fixed starts
look for solutions; what they find is returned with a reason that says it came from
a search, which may not find them all.

A batch is solved in chunks of CHUNK poses (memory bounded); one of more than
MAX_POSES poses is refused before any work.
"""

import functools
import weakref
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .._checks import check_chain, check_poses, one_pose
from ..links import Joint
from ..tolerances import (
    IK_GENERAL_ACCEPT_TOL,
    IK_GENERAL_CLUSTER_TOL,
    IK_GENERAL_COMFORT_TOL,
    IK_GENERAL_CONSISTENT_TOL,
    IK_GENERAL_EXPLAINED_TOL,
    IK_GENERAL_LEADING_TOL,
    IK_GENERAL_NULL_TOL,
    IK_GENERAL_RANK_TOL,
    IK_GENERAL_REAL_TOL,
    IK_GENERAL_SAME_TOL,
    IK_GENERAL_SEARCH_DAMPING,
    IK_GENERAL_SINGULAR_TOL,
    length_scale,
)
from ..transforms import _cross, _cross_into, _cross_last, _skew, _wrap_angle
from ._general_kinematics import by_identity, lapack_eigvals, lapack_solve, lapack_svd
from ._general_kinematics import error as _error
from ._general_kinematics import poe as _poe
from ._general_kinematics import polish as _polish
from ._general_kinematics import residuals as _residuals
from ._general_kinematics import singular as _singular

__all__ = ["GeneralIK", "general_6r_ik"]

#: Three equally spaced angles: a function a + b cos + c sin is fixed by its values
#: there, and _FIT turns the three values into (a, b, c).
_GRID = 2 * np.pi * np.arange(3) / 3
_FIT = np.linalg.inv(np.stack([np.ones(3), np.cos(_GRID), np.sin(_GRID)], axis=1))

#: The grid's angles for two and three joints, first joint slowest (ravelled).
_GRID2 = np.stack([a.ravel() for a in np.meshgrid(_GRID, _GRID, indexing="ij")])
_GRID3 = np.stack([a.ravel() for a in np.meshgrid(_GRID, _GRID, _GRID, indexing="ij")])
_FIT2 = np.kron(_FIT, _FIT)
_FIT3 = np.kron(_FIT2, _FIT)

#: (1, cos, sin) times 1 + x^2 as polynomials in x = tan(angle / 2): rows 1, cos,
#: sin; columns the coefficients of x^0, x^1, x^2.
_TO_POLY = np.array([[1.0, 0.0, 1.0], [1.0, 0.0, -1.0], [0.0, 2.0, 0.0]])
_TO_POLY3 = np.kron(np.kron(_TO_POLY, _TO_POLY), _TO_POLY)

#: The angle shifts of the three tries of a formulation (rad), fixed so that the
#: answers are reproducible; any values away from multiples of pi would do.
_SHIFTS = np.array(
    [
        [0.4137, -0.9212, 0.2843, 1.1371, -0.6271, 0.0],
        [-1.2719, 0.3331, 0.8779, -0.2466, 1.3587, 0.0],
        [0.7713, 1.4891, -1.0437, 0.6109, 0.1931, 0.0],
    ]
)


_RANK_REASON = "joints 1 and 2 do not enter the 14 equations independently"
_LEADING_REASON = "the eigenvalue problem's leading matrix is singular"


@dataclass
class GeneralIK:
    """The solutions of :func:`general_6r_ik` for one pose.

    Parameters
    ----------
    Q : ndarray, shape (k, 6)
        Every real solution found (rad, each in (-pi, pi]), sorted lexicographically;
        k is at most 16 (0 for a pose out of reach or a degenerate arm).
    residuals : ndarray, shape (k,)
        The pose error of each solution after polishing:
        sqrt(|R(q) - R|_F^2 / 2 + |p(q) - p|^2 / scale^2) by the chain's own ``fk``, the
        norm of the error twist [omega; v / scale] to first order (unitless: lengths
        divided by the chain's size).
    reason : str or None
        None when solved; otherwise a sentence: no real solution, a solution at a
        singular configuration (solutions may coincide or form a continuum there),
        or why the elimination could not be set up for this arm and pose.
    formulation : str
        The form of the loop that was solved, e.g. 'joints 1..6' or
        'joints 6..1 shifted by 2' (for the record; '' when none worked).
    singular : ndarray of bool, shape (k,)
        Whether the Jacobian loses rank at each solution (``reason`` then says so):
        solutions may coincide there, or the solution be a point of a continuum.

    Examples
    --------
    The answer for a pose of a 6R arm of no special geometry: every solution
    reaches the pose (residuals of round-off size), and none is singular.

    >>> import screwkit as sk
    >>> arm = sk.Chain.from_table([[0, 0.3, 0.2, 1.0], [0, 0.1, 0.5, -0.7],
    ...     [0, 0.2, 0.4, 1.3], [0, 0.25, 0.1, 0.9], [0, 0.1, 0.3, -1.1],
    ...     [0, 0.2, 0.1, 0.4]])
    >>> found = general_6r_ik(arm, arm.fk([0.3, -0.5, 1.0, 0.7, -1.2, 2.0]))
    >>> found.reason, len(found.Q) <= 16, bool(found.residuals.max() < 1e-9)
    (None, True, True)
    >>> bool(found.singular.any())
    False
    """

    Q: np.ndarray
    residuals: np.ndarray
    reason: str | None = None
    formulation: str = ""
    singular: np.ndarray = None

    def __post_init__(self):
        if self.singular is None:
            self.singular = np.zeros(len(self.Q), bool)


# ---- the loop's two sides, for a batch ----------------------------------------------
#
# Arrays are laid out component first: points and directions (3, n, g) for n poses (or
# candidates) and g angles each, the axes of a formulation (6, 3, n, 1) (n = 1 when they
# do not depend on the pose), angles (n, g).


def _turn(w, c, s, x):
    """Directions x (3, n, g) turned about unit w (3, n, 1) by the angles whose
    cosines and sines are c, s (n, g): Rodrigues' formula."""
    return x * c + _cross(w, x) * s + w * (np.sum(w * x, axis=0) * (1 - c))


def _turn_both(w, r, angle, p, l):
    """Points p and directions l (3, n, g) turned by ``angle`` (n, g) about the axis
    through r (3, n, 1) along unit w (3, n, 1)."""
    c, s = np.cos(angle), np.sin(angle)
    return _turn(w, c, s, p - r) + r, _turn(w, c, s, l)


def _products(p, l):
    """The 14 Raghavan–Roth quantities (14, n, g) of points p and directions l
    (3, n, g)."""
    shape = (
        p.shape[1:] if p.shape == l.shape else np.broadcast_shapes(p.shape, l.shape)[1:]
    )
    out = np.empty((14, *shape))
    out[:3], out[3:6] = p, l
    pp = out[6] = (p * p).sum(axis=0)
    pl = out[7] = (p * l).sum(axis=0)
    _cross_into(out[8:11], p, l)  # p x l, written into place
    np.subtract(pp * l, 2 * pl * p, out=out[11:])
    return out


def _left(w, r, q3, q4, q5):
    """E3 E4 E5 applied to axis 6's point and direction (r[5], w[5]): the 14
    quantities (14, n, g) at the angles (n, g); axes w, r (6, 3, n, 1)."""
    shape = (3,) + np.broadcast_shapes(w.shape[2:], q3.shape)
    p, l = np.broadcast_to(r[5], shape), np.broadcast_to(w[5], shape)
    for k, q in ((4, q5), (3, q4), (2, q3)):
        p, l = _turn_both(w[k], r[k], q, p, l)
    return _products(p, l)


def _right(w, r, hp, hl, q1, q2):
    """E2^-1 E1^-1 applied to G's image (hp, hl) (3, n, 1) of axis 6's point and
    direction: the 14 quantities (14, n, g) at the angles (n, g)."""
    shape = (3,) + np.broadcast_shapes(hp.shape[1:], q1.shape)
    p, l = np.broadcast_to(hp, shape), np.broadcast_to(hl, shape)
    for k, q in ((0, q1), (1, q2)):
        p, l = _turn_both(w[k], r[k], -q, p, l)
    return _products(p, l)


def _pick(axes, rows):
    """The axes (6, 3, n, 1) of the poses ``rows``: themselves when shared (n = 1)."""
    return axes if axes.shape[2] == 1 else axes[:, :, rows]


# ---- one formulation, for a batch ---------------------------------------------------


@dataclass
class _Eliminated:
    """One formulation's elimination for n poses: the pieces the candidates need.

    ``A`` (m, 24, 24) the companion matrices of the ``usable`` poses (bool (n,)),
    ``M`` (m, 3, 12, 12) their matrix polynomials, ``C0`` (n, 14) and ``pinv``
    (n, 8, 14) the right side's constant and the pseudo-inverse of its coefficients
    (for q1, q2), ``reason`` (n,) None or why a pose's form is degenerate,
    ``quality`` (n,) how far from degenerate (1 best, 0 degenerate)."""

    A: np.ndarray
    M: np.ndarray
    C0: np.ndarray
    pinv: np.ndarray
    usable: np.ndarray
    reason: list
    quality: np.ndarray


def _eliminate(w, r, G, shift):
    """The eigenvalue problems of the loops E1 ... E6 = G_k (unit axes w, points r
    (6, 3, n or 1, 1), lengths divided by the chain's size; poses G (n, 4, 4)), angles
    q_i = phi_i + shift_i: an :class:`_Eliminated`."""
    n = G.shape[0]
    if w.shape[2] == 1:  # joints 1, 2 and 6 do not depend on the pose
        hp = G[:, :3, :3] @ r[5, :, 0, 0] + G[:, :3, 3]  # (n, 3)
        hl = G[:, :3, :3] @ w[5, :, 0, 0]
        shared = _shared_constants(w, r, shift)
        left_poly = shared.left_poly
        # einsum, not a matrix product that BLAS may block by the batch's size: the
        # same round-off for a pose alone as in a batch
        if shared.right_map is not None:  # a fixed linear map of the pose's features
            right = np.einsum("nf,fik->nik", _features(hp, hl), shared.right_map)
        else:
            p = np.einsum("gij,nj->ngi", shared.R, hp) + shared.t  # (n, 9 angles, 3)
            l = np.einsum("gij,nj->ngi", shared.R, hl)
            values = _products(p.transpose(2, 0, 1), l.transpose(2, 0, 1))
            right = np.einsum("inj,kj->nik", values, _FIT2)  # (n, 14, 9)
    else:
        r6 = np.broadcast_to(r[5, :, :, 0].T, (n, 3))
        w6 = np.broadcast_to(w[5, :, :, 0].T, (n, 3))
        hp = (np.einsum("nij,nj->in", G[:, :3, :3], r6) + G[:, :3, 3].T)[..., None]
        hl = np.einsum("nij,nj->in", G[:, :3, :3], w6)[..., None]
        a1, a2 = _GRID2[:, None, :] + shift[:2, None, None]
        values = _right(w, r, hp, hl, a1, a2)
        right = np.einsum("inj,kj->nik", values, _FIT2)  # (n, 14, 9)
    C0, Q = right[:, :, 0], right[:, :, 1:]  # (n, 14), (n, 14, 8)
    U, sigma, Vh = lapack_svd(Q)
    reason = [None] * n
    usable = sigma[:, -1] > IK_GENERAL_RANK_TOL * sigma[:, 0]
    if not usable.all():
        for k in np.nonzero(~usable)[0]:
            reason[k] = _RANK_REASON
    if n == 1 and sigma[0, -1] > 0:  # one pose, no zero singular value
        inverse = 1.0 / sigma
    else:
        inverse = np.divide(1.0, sigma, out=np.zeros_like(sigma), where=sigma > 0)
    pinv = np.swapaxes(Vh, 1, 2) @ (np.swapaxes(U[:, :, :8], 1, 2) * inverse[..., None])
    N = np.swapaxes(U[:, :, 8:], 1, 2)  # (n, 6, 14): N Q = 0
    if w.shape[2] != 1:  # joints 3 to 6 depend on the pose
        a3, a4, a5 = _GRID3[:, None, :] + shift[2:5, None, None]
        left = np.einsum("inj,kj->nik", _left(w, r, a3, a4, a5), _FIT3)
        left_poly = left @ _TO_POLY3
    # N (left - C0 e0) in the monomials of the half-angle tangents:
    # (n, 6, power of x3, power of x4, power of x5)
    poly = N @ left_poly - (N @ C0[..., None]) * _TO_POLY3[0]
    poly = poly.reshape(n, 6, 3, 3, 3).transpose(0, 2, 1, 3, 4)
    M = np.zeros((n, 3, 12, 4, 3))
    M[:, :, :6, :3, :] = poly
    M[:, :, 6:, 1:, :] = poly
    M = M.reshape(n, 3, 12, 12)
    sv = lapack_svd(M[:, 2], compute_uv=False)
    if n == 1:  # one pose: its tests on floats (the same values)
        size = max(float(np.abs(M).max()), 1.0)
        leading = sv[0, -1] > IK_GENERAL_LEADING_TOL * size
        if usable[0] and not leading:
            reason[0] = _LEADING_REASON
        ok = bool(usable[0]) and leading
        usable = np.array([ok])
        rank = sigma[0, -1] / sigma[0, 0]
        quality = np.array([min(rank, sv[0, -1] / size) if ok else 0.0])
        if not ok:
            M = M[:0]
    else:
        size = np.maximum(np.abs(M).max(axis=(1, 2, 3)), 1.0)
        leading = sv[:, -1] > IK_GENERAL_LEADING_TOL * size
        if not leading.all():
            for k in np.nonzero(usable & ~leading)[0]:
                reason[k] = _LEADING_REASON
        usable &= leading
        quality = np.where(
            usable, np.minimum(sigma[:, -1] / sigma[:, 0], sv[:, -1] / size), 0.0
        )
        if not usable.all():
            M = M[usable]
    solved = lapack_solve(M[:, 2], np.concatenate([M[:, 0], M[:, 1]], axis=2))
    A = np.zeros((len(M), 24, 24))
    A[:, :12, 12:] = _EYE12
    np.negative(solved, out=A[:, 12:])
    return _Eliminated(A, M, C0, pinv, usable, reason, quality)


#: The identity the companion matrices hold.
_EYE12 = np.eye(12)
_EYE12.setflags(write=False)


@functools.lru_cache(maxsize=64)
def _left_coefficients_cached(w, r, shift):
    """_left_coefficients on bytes (hashable), cached: joints 3 to 6 of a chain's
    first formulation do not depend on the pose."""
    w, r = np.frombuffer(w).reshape(4, 3), np.frombuffer(r).reshape(4, 3)
    a3, a4, a5 = _GRID3[:, None, :] + np.frombuffer(shift)[:, None, None]
    pad = np.zeros((2, 3))
    axes = np.vstack([pad, w])[:, :, None, None], np.vstack([pad, r])[:, :, None, None]
    left = _left(*axes, a3, a4, a5)[:, 0] @ _FIT3.T
    left.setflags(write=False)
    return left


@functools.lru_cache(maxsize=64)
def _right_motions_cached(w, r, shift):
    """_right_motions on bytes (hashable), cached."""
    w, r = np.frombuffer(w).reshape(2, 3), np.frombuffer(r).reshape(2, 3)
    angles = _GRID2 + np.frombuffer(shift)[:, None]
    p, l = np.zeros((3, 1, 9)), np.broadcast_to(np.eye(3)[:, :, None], (3, 3, 9))
    for k in range(2):
        p, l = _turn_both(w[k, :, None, None], r[k, :, None, None], -angles[k], p, l)
    R, t = l.transpose(2, 0, 1).copy(), p[:, 0].T.copy()
    R.setflags(write=False)
    t.setflags(write=False)
    return R, t


def _right_motions(w, r, shift):
    """The rigid motions E2^-1 E1^-1 of the right side at the grid's 9 angles of
    joints 1 and 2 (axes w, points r (2, 3); their shifts, bytes): rotations
    (9, 3, 3) and translations (9, 3), x -> R x + t."""
    return _right_motions_cached(
        np.ascontiguousarray(w).tobytes(), np.ascontiguousarray(r).tobytes(), shift
    )


class _Shared(NamedTuple):
    """The pose-independent constants of a form whose axes do not depend on the
    pose (:func:`_shared_constants`)."""

    #: The right side's motions at the grid: rotations (9, 3, 3), translations (9, 3).
    R: np.ndarray
    t: np.ndarray
    #: The left side's coefficients (14, 27), and in the half-angle monomials (14, 27).
    left: np.ndarray
    left_poly: np.ndarray
    #: The right side's coefficients (14, 9) as a linear map of the pose's features
    #: (:func:`_features`): (27, 14, 9). This and the rest only for the axes of a
    #: form that serve pose after pose (read-only, cached), else None.
    right_map: np.ndarray
    #: The rotation E2^-1 E1^-1 (9, 9 entries) in (1, c1, s1) x (1, c2, s2) of phi1,
    #: phi2.
    turn12: np.ndarray
    #: E3 E4 E5's rotation applied to u and v (27, 6) (two unit vectors normal to
    #: axis 6, :func:`_wrist_frame`) in (1, c3, s3) x (1, c4, s4) x (1, c5, s5).
    turn345: np.ndarray
    #: u (3,).
    u: np.ndarray


def _shared_constants(w, r, shift):
    """For the axes w, r (6, 3, 1, 1) of a form that do not depend on the pose and
    the angle shifts (6,): a :class:`_Shared`, kept by the axes' identity."""

    def make():
        R, t = _right_motions(w[:2, :, 0, 0], r[:2, :, 0, 0], shift[:2].tobytes())
        left = _left_coefficients(w[2:, :, 0, 0], r[2:, :, 0, 0], shift[2:5].tobytes())
        left_poly = left @ _TO_POLY3
        if w.flags.writeable:  # the axes of this pose alone: no maps worth fitting
            found = _Shared(R, t, left, left_poly, None, None, None, None)
            left_poly.setflags(write=False)
            return found
        _, _, u, v = _wrist_frame(w)
        turns = _rotations(w[2:5, :, 0, 0], _GRID3 + shift[2:5, None])
        # R3 R4 R5 (u, v) at the grid, fitted: (27 monomials, 3, 2)
        moved = turns[0] @ turns[1] @ turns[2] @ np.stack([u[0], v[0]], axis=1)
        turn345 = np.einsum("kg,gij->kij", _FIT3, moved).reshape(27, 6)
        found = _Shared(
            R,
            t,
            left,
            left_poly,
            _right_map(R, t),
            np.einsum("kg,gij->kij", _FIT2, R).reshape(9, 9),
            turn345,
            u[0].copy(),
        )
        for array in found:
            array.setflags(write=False)
        return found

    return by_identity((w, r), shift.tobytes(), make)


def _rotations(w, angles):
    """The rotations (m, g, 3, 3) about unit axes w (m, 3) by the angles (m, g)."""
    K = _skew(w)[:, None]
    angle = angles[..., None, None]
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * (K @ K)


def _features(hp, hl):
    """The 27 features (n, 27) of the images hp, hl (n, 3) of axis 6's point and
    direction of which the right side's coefficients are a linear map: 1, hp, hl,
    hp.hp, hp.hl, hp x hl, (hp.hp) hl, (hp.hl) hp and the products hl_i hp_j."""
    n = len(hp)
    if n == 1:  # one pose: on floats (the same operations, the same values)
        (px, py, pz), (lx, ly, lz) = hp[0].tolist(), hl[0].tolist()
        pp = px * px + py * py + pz * pz
        pl = px * lx + py * ly + pz * lz
        return np.array(
            [
                [1.0, px, py, pz, lx, ly, lz, pp, pl]
                + [py * lz - pz * ly, pz * lx - px * lz, px * ly - py * lx]
                + [pp * lx, pp * ly, pp * lz, pl * px, pl * py, pl * pz]
                + [lx * px, lx * py, lx * pz, ly * px, ly * py, ly * pz]
                + [lz * px, lz * py, lz * pz]
            ]
        )
    f = np.empty((n, 27))
    f[:, 0] = 1.0
    f[:, 1:4], f[:, 4:7] = hp, hl
    pp = f[:, 7] = (hp * hp).sum(axis=1)
    pl = f[:, 8] = (hp * hl).sum(axis=1)
    f[:, 9:12] = _cross_last(hp, hl)
    f[:, 12:15] = pp[:, None] * hl
    f[:, 15:18] = pl[:, None] * hp
    f[:, 18:] = (hl[:, :, None] * hp[:, None]).reshape(n, 9)
    return f


def _right_map(R, t):
    """The right side's coefficients (14, 9) in (1, c1, s1) x (1, c2, s2) as a
    linear map (27, 14, 9) of :func:`_features`, from its motions R (9, 3, 3), t
    (9, 3) at the grid: each of the 14 quantities of p = R hp + t, l = R hl is a
    polynomial in hp, hl whose terms are those features, so the map is found
    exactly (to round-off) by least squares from fixed pseudo-random samples."""
    hp, hl = _MAP_SAMPLES
    p = np.einsum("gij,nj->ngi", R, hp) + t
    l = np.einsum("gij,nj->ngi", R, hl)
    values = _products(p.transpose(2, 0, 1), l.transpose(2, 0, 1))  # (14, n, 9)
    right = np.einsum("inj,kj->nik", values, _FIT2).reshape(len(hp), -1)
    solution = np.linalg.lstsq(_features(hp, hl), right, rcond=None)[0]
    return solution.reshape(27, 14, 9)


#: The samples of hp, hl (2, 64, 3) :func:`_right_map` fits the map to.
_MAP_SAMPLES = np.random.default_rng(27).standard_normal((2, 64, 3))


def _left_coefficients(w, r, shift):
    """The left side's coefficients (14, 27) in (1, c3, s3) x (1, c4, s4) x
    (1, c5, s5), from joints 3 to 6 (axes w, points r, (4, 3)) and the shifts of
    q3, q4, q5 (bytes)."""
    return _left_coefficients_cached(
        np.ascontiguousarray(w).tobytes(), np.ascontiguousarray(r).tobytes(), shift
    )


def _half_angle(x):
    """The angle (rad) whose half-angle tangent is x."""
    return 2 * np.arctan(x)


#: Where the monomials x4^i x5^j (i <= 3, j <= 2; flat index 3 i + j) are, for the
#: products of the 6 with i <= 2, j <= 1 by x4 and by x5.
_LOW = np.array([3 * i + j for i in range(3) for j in range(2)])
_TIMES_X4, _TIMES_X5 = _LOW + 3, _LOW + 1

#: A fixed weight: two solutions that share x3 are told apart by x4 + _MIX x5.
_MIX = 0.6180339887


def _repeated_roots(M, x3, V):
    """Eigenvectors V (k, 12) for the roots x3 (k,), with those of repeated roots
    replaced, and the multiplicity (k,) of each root (how many of the roots x3 it
    stands for).

    Solutions that share q3 (e.g. two wrist configurations) give a repeated root whose
    eigenvectors are any mixture of their monomial vectors. The null space B of
    M(x3) holds them all; multiplying by x4 + _MIX x5 maps the monomials of low degree
    onto others, (B[x4] + _MIX B[x5]) c = (x4 + _MIX x5) B[low] c, a small eigenvalue
    problem whose eigenvectors c give the solutions' monomial vectors B c."""
    order = np.argsort(x3.real)
    x3, V = x3[order], V[order]
    gaps = np.abs(np.diff(x3.real)) > IK_GENERAL_CLUSTER_TOL * (1 + np.abs(x3[1:]))
    starts = np.concatenate([[0], np.nonzero(gaps)[0] + 1, [len(x3)]])
    roots, vectors = [x3], [V]
    multiplicity = [np.repeat(np.diff(starts), np.diff(starts))]
    for a, b in zip(starts[:-1], starts[1:]):
        if b - a < 2:
            continue
        x = float(np.mean(x3[a:b].real))
        _, sigma, Vh = np.linalg.svd(M[0] + x * M[1] + x * x * M[2])
        d = min(int(np.sum(sigma <= IK_GENERAL_NULL_TOL * sigma[0])), len(_LOW))
        if d < 2:
            continue
        B = Vh[-d:].T
        K = np.linalg.lstsq(B[_LOW], B[_TIMES_X4] + _MIX * B[_TIMES_X5], rcond=None)
        C = np.linalg.eig(K[0])[1]
        roots.append(np.full(d, x, dtype=complex))
        vectors.append((B @ C).T)
        multiplicity.append(np.full(d, b - a))
    return np.concatenate(roots), np.concatenate(vectors), np.concatenate(multiplicity)


def _candidates(w, r, G, shift, found):
    """Joint vectors (k, 6) of the loops E1 ... E6 = G_j from the eigenvalue problems
    of ``found`` (an :class:`_Eliminated`), the pose j (k,) of each, and its claim
    (k,) on the solutions: 0 when inconsistent, else the multiplicity m >= 1 of its
    root (its q3) in the spectrum. A candidate is consistent when its joints 1 and 2
    products are those of two angles: its root is genuine, and as many solutions
    must account for it as it has consistent candidates, at most m
    (:func:`_unexplained`)."""
    values = lapack_eigvals(found.A)
    real = np.abs(values.imag) <= IK_GENERAL_REAL_TOL * (1 + np.abs(values))
    usable = np.nonzero(found.usable)[0]
    which, column = np.nonzero(real)
    x3 = values[which, column]
    V = _null_vectors(found.M[0] if len(found.M) == 1 else found.M[which], x3.real)
    x3, V, which, multiplicity = _with_repeated_roots(found.M, x3, V, which)
    pose = usable[which]
    V = V.reshape(-1, 4, 3)
    # x4 and x5 from the monomials' ratios, least squares (V is real, or complex
    # where repeated roots were separated)
    phi = np.empty((3, len(x3)))
    phi[0] = x3.real
    if V.dtype.kind == "f":  # the four sums of products at once
        sums = (V.reshape(-1, 12, 1) * V.reshape(-1, 1, 12)).reshape(-1, 144) @ _RATIOS
        phi[1:] = (sums[:, :2] / sums[:, 2:]).T
    else:
        low, high = V[:, :-1].conj(), V[:, 1:]
        ratio = (low * high).sum(axis=(1, 2)) / (low * low.conj()).sum(axis=(1, 2))
        phi[1] = ratio.real
        low, high = V[:, :, :-1].conj(), V[:, :, 1:]
        ratio = (low * high).sum(axis=(1, 2)) / (low * low.conj()).sum(axis=(1, 2))
        phi[2] = ratio.real
    phi = _half_angle(phi)
    q = np.empty((len(x3), 6))
    q[:, 2:5] = (phi + shift[2:5, None]).T
    # q1, q2: the right side's 8 products from the 14 values of the left side
    wk, rk = _pick(w, pose), _pick(r, pose)
    shared = _shared_constants(w, r, shift) if w.shape[2] == 1 else None
    if shared is not None:  # from the cached coefficients of the left side
        f = np.empty((3, len(x3), 3))  # (1, cos, sin) of phi3, phi4, phi5, (k, 3) each
        f[:, :, 0], f[:, :, 1], f[:, :, 2] = 1.0, np.cos(phi), np.sin(phi)
        monomials = (f[0, :, :, None] * f[1, :, None]).reshape(-1, 9, 1) * f[2, :, None]
        monomials = monomials.reshape(-1, 27)
        values = monomials @ shared.left.T  # (k, 14)
    else:
        q3, q4, q5 = q[:, 2:5, None].transpose(1, 0, 2)
        values = _left(wk, rk, q3, q4, q5)[:, :, 0].T
    if len(usable) == 1:  # one problem: its right side for every candidate
        j = usable[0]
        b = (found.pinv[j] @ (values - found.C0[j])[:, :, None])[:, :, 0]
    else:
        b = (found.pinv[pose] @ (values - found.C0[pose])[:, :, None])[:, :, 0]
    # b's columns: (1, c1, s1) x (1, c2, s2) without the first, in that order:
    # (c2, s2, c1, c1c2, c1s2, s1, s1c2, s1s2)
    q[:, :2] = np.arctan2(b[:, _SINES], b[:, _COSINES]) + shift[:2]
    if shared is not None and shared.turn12 is not None:
        Gk = G if len(G) == 1 else G[pose]  # one pose's G serves every candidate
        q[:, 5] = _last_angle_shared(shared, Gk, q[:, :2] - shift[:2], monomials)
    else:
        q[:, 5] = _last_angle(wk, rk, G[pose], q)
    return q, pose, np.where(_consistent(b), multiplicity, 0)


def _consistent(b):
    """Whether the right side's products b (k, 8), columns (c2, s2, c1, c1c2, c1s2,
    s1, s1c2, s1s2), are those of two angles (IK_GENERAL_CONSISTENT_TOL): c1^2 + s1^2
    and c2^2 + s2^2 against 1, c1c2, c1s2, s1c2, s1s2 against the products of c1,
    s1 and c2, s2. A few candidates on floats, more as arrays (the same values)."""
    if len(b) <= 24:
        tol = IK_GENERAL_CONSISTENT_TOL
        return np.array(
            [
                abs(c1 * c1 + s1 * s1 - 1) <= tol  # a NaN fails, as in the arrays
                and abs(c2 * c2 + s2 * s2 - 1) <= tol
                and abs(c1c2 - c1 * c2) <= tol
                and abs(c1s2 - c1 * s2) <= tol
                and abs(s1c2 - s1 * c2) <= tol
                and abs(s1s2 - s1 * s2) <= tol
                for c2, s2, c1, c1c2, c1s2, s1, s1c2, s1s2 in b.tolist()
            ],
            bool,
        )
    norms = b[:, _SQUARES].reshape(-1, 2, 2) ** 2
    gaps = np.abs(norms.sum(axis=2) - 1).max(axis=1)
    products = np.abs(b[:, _PRODUCTS] - b[:, _FACTORS_1] * b[:, _FACTORS_2])
    return np.maximum(gaps, products.max(axis=1)) <= IK_GENERAL_CONSISTENT_TOL


#: b's columns (c2, s2, c1, c1c2, c1s2, s1, s1c2, s1s2): (c1, s1, c2, s2), and the
#: products with their factors.
_SQUARES = np.array([2, 5, 0, 1])
_SINES, _COSINES = np.array([5, 1]), np.array([2, 0])
_PRODUCTS, _FACTORS_1, _FACTORS_2 = np.array([[3, 4, 6, 7], [2, 2, 5, 5], [0, 1, 0, 1]])


def _ratio_sums():
    """The (144, 4) 0/1 matrix that sums the products v_a v_b (a, b flat indices of
    the monomials x4^i x5^j, 3 i + j) into those of x4's and x5's least-squares
    ratios: sum v(i, j) v(i + 1, j), sum v(i, j) v(i, j + 1), and the squares of the
    low monomials of each (i < 3; j < 2)."""
    R = np.zeros((12, 12, 4))
    for i in range(4):
        for j in range(3):
            a = 3 * i + j
            if i < 3:
                R[a, a + 3, 0] = R[a, a, 2] = 1.0
            if j < 2:
                R[a, a + 1, 1] = R[a, a, 3] = 1.0
    R = R.reshape(144, 4)
    R.setflags(write=False)
    return R


_RATIOS = _ratio_sums()

#: A fixed right side for one step of inverse iteration (:func:`_null_vectors`).
_PROBE = np.random.default_rng(12).standard_normal((12, 1))


def _null_vectors(M, x):
    """A vector v (k, 12) with M_j(x_j) v = 0 for each real root x (k,) of the
    matrix polynomials M (k, 3, 12, 12), or of one (3, 12, 12): one step of
    inverse iteration, M(x)^-1 b for a fixed b (M(x) is singular to round-off, so
    the solve amplifies its null direction by 1 / sigma_min; the vectors' scale
    does not matter, only their ratios), or the last right singular vector where
    M(x) is singular to working precision (its LU breaks down, or the solve
    overflows)."""
    x = x[:, None, None]
    Mx = M[..., 0, :, :] + x * (M[..., 1, :, :] + x * M[..., 2, :, :])
    try:
        V = lapack_solve(Mx, _PROBE)[..., 0]
    except np.linalg.LinAlgError:  # an exactly singular M(x): those by SVD below
        V = np.full((len(Mx), 12), np.nan)
        regular = np.linalg.det(Mx) != 0
        if regular.any():  # b as a stack of (12, 1) matrices: one meaning in NumPy 1, 2
            b = np.broadcast_to(_PROBE, (int(regular.sum()), 12, 1))
            V[regular] = np.linalg.solve(Mx[regular], b)[..., 0]
    size = np.abs(V).sum(axis=1)
    # a zero vector, an overflow or a NaN
    bad = [not 0.0 < x < np.inf for x in size.tolist()]
    if any(bad):
        V[bad] = np.linalg.svd(Mx[bad])[2][:, -1]
    return V


def _with_repeated_roots(M, x3, V, which):
    """The roots x3 (k,), their vectors V (k, 12), problems ``which`` (k,) and
    multiplicities (k,), with the vectors of repeated roots replaced
    (:func:`_repeated_roots`) in the problems that have any."""
    if 0 < len(x3) <= 24:  # few roots: no two close (a loose test), no sort
        x = x3.real
        if not which.any():  # one problem's roots: on floats
            x = sorted(x.tolist())
            tol = IK_GENERAL_CLUSTER_TOL * (1 + max(-x[0], x[-1]))
            if all(b - a > tol for a, b in zip(x, x[1:])):
                return x3, V, which, np.ones(len(x3), int)
        else:
            tol = IK_GENERAL_CLUSTER_TOL * (1 + np.abs(x).max())
            near = np.abs(x[:, None] - x) <= tol
            if (near & (which[:, None] == which)).sum() == len(x):
                return x3, V, which, np.ones(len(x3), int)
    order = np.lexsort((x3.real, which))
    x3, V, which = x3[order], V[order], which[order]
    close = (which[1:] == which[:-1]) & (
        np.abs(np.diff(x3.real)) <= IK_GENERAL_CLUSTER_TOL * (1 + np.abs(x3[1:]))
    )
    if not close.any():
        return x3, V, which, np.ones(len(x3), int)
    parts = []
    for j in np.unique(which):
        mine = which == j
        if np.any(close & mine[1:]):
            x, v, m = _repeated_roots(M[j], x3[mine], V[mine])
            parts.append((x, v, np.full(len(x), j), m))
        else:
            parts.append((x3[mine], V[mine], which[mine], np.ones(np.sum(mine), int)))
    return tuple(np.concatenate(p) for p in zip(*parts))


def _wrist_frame(w):
    """For axes w (6, 3, m, 1): [w_i] and [w_i]^2 (m, 5, 3, 3) of axes 1 to 5, and
    two unit vectors u, v = w6 x u (m, 3) normal to axis 6."""
    w6 = w[5, :, :, 0].T
    u = _cross_last(w6, np.array([1.0, 0.0, 0.0]))
    u = np.where(
        np.linalg.norm(u, axis=1, keepdims=True) < 0.5,
        _cross_last(w6, np.array([0.0, 1.0, 0.0])),
        u,
    )
    u = u / np.linalg.norm(u, axis=1, keepdims=True)
    K = _skew(w[:5, :, :, 0].transpose(2, 0, 1))
    return K, K @ K, u, _cross_last(w6, u)


@functools.lru_cache(maxsize=64)
def _wrist_frame_cached(w):
    """_wrist_frame of shared axes w (bytes of (6, 3)), cached."""
    frame = _wrist_frame(np.frombuffer(w).reshape(6, 3, 1, 1))
    for array in frame:
        array.setflags(write=False)
    return frame


def _last_angle(w, r, G, q):
    """q6 (k,) from q1..q5 (k, 6): the rotation E6 = (E1 ... E5)^-1 G_k about axis 6
    (axes w, r (6, 3, k or 1, 1), poses G (k, 4, 4))."""
    if w.shape[2] == 1:
        K, K2, u, v = by_identity(
            (w,),
            "wrist",
            lambda: _wrist_frame_cached(np.ascontiguousarray(w).tobytes()),
        )
    else:
        K, K2, u, v = _wrist_frame(w)
    Gu = G[:, :3, :3] @ u[..., None]  # (k, 3, 1)
    # the rotations about axes 1 to 5 by -q (Rodrigues' formula), (k, 5, 3, 3)
    angle = -q[:, :5, None, None]
    turns = np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K2
    for j in range(5):  # (E1 ... E5)^-1 = E5^-1 ... E1^-1: undo joint 1 first
        Gu = turns[:, j] @ Gu
    Gu = Gu[..., 0]
    return np.arctan2((v * Gu).sum(axis=1), (u * Gu).sum(axis=1))


def _last_angle_shared(shared, G, phi, monomials):
    """q6 (k,) as :func:`_last_angle` gives it, for a form whose axes do not depend
    on the pose, from its cached rotations in the angles' monomials (a
    :class:`_Shared`): with u, v normal to axis 6, E6's angle is that of
    (R3 R4 R5 (u, v)) . (R2^T R1^T G u); ``phi`` (k, 2) the form's phi1, phi2,
    ``monomials`` (k, 27) those of phi3, phi4, phi5, G (k, 4, 4) or one (1, 4, 4)
    for all."""
    f = np.empty((len(phi), 2, 3))  # (1, cos, sin) of phi1 and phi2
    f[:, :, 0], f[:, :, 1], f[:, :, 2] = 1.0, np.cos(phi), np.sin(phi)
    f = (f[:, 0, :, None] * f[:, 1, None]).reshape(-1, 9)  # (1, c1, s1) x (1, c2, s2)
    turned = (f @ shared.turn12).reshape(-1, 3, 3)
    # R2^T R1^T G u (k, 3, 1); G (k or 1, 4, 4)
    x = turned @ (G[:, :3, :3] @ shared.u)[..., None]
    y = (monomials @ shared.turn345).reshape(-1, 3, 2)
    cos_sin = (x * y).sum(axis=1)
    return np.arctan2(cos_sin[:, 1], cos_sin[:, 0])


# ---- the twelve formulations ---------------------------------------------------------


def _inverse(T):
    """The inverse of rigid transforms (..., 4, 4), unchecked."""
    inverse = np.zeros_like(T)
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    inverse[..., :3, :3] = Rt
    inverse[..., :3, 3] = -(Rt @ T[..., :3, 3, None])[..., 0]
    inverse[..., 3, 3] = 1.0
    return inverse


def _adjoint_inverse(G, S):
    """Ad(G_n^-1) applied to screws S (k, 6) [omega; v], for poses G (n, 4, 4):
    (n, k, 6)."""
    R, p = G[:, None, :3, :3], G[:, None, :3, 3]
    w = (S[:, None, :3] @ R)[..., 0, :]  # R^T omega
    v = ((S[:, 3:] - _cross_last(p, S[:, :3]))[..., None, :] @ R)[..., 0, :]
    return np.concatenate([w, v], axis=-1)


def _formulation(S, G, index):
    """(name, w, r, target, joint order) of form ``index`` (0 to 11) of the loop for
    poses G (n, 4, 4): joints 1..6 (index < 6) or 6..1, cyclically shifted by
    index % 6; w, r (6, 3, n, 1) the axes (n = 1 when they do not depend on the pose),
    r the point of each axis nearest the origin. The form's angle phi_i is the angle
    of joint order[i] itself: backwards, E(S6, q6)^-1 ... E(S1, q1)^-1 = G^-1 is
    E(-S6, q6) ... E(-S1, q1) = G^-1, the screws negated and the angles kept."""
    backwards, k = divmod(index, 6)
    if not k:  # the axes do not depend on the pose: cached
        target = _inverse(G) if backwards else G
        axes, order = _unshifted(np.ascontiguousarray(S).tobytes(), backwards)
        return (*axes, target, order)
    screws, target = (-S[::-1], _inverse(G)) if backwards else (S, G)
    order = np.arange(6)[::-1] if backwards else np.arange(6)
    if k:
        n = len(G)
        kept = np.broadcast_to(screws[k:], (n, 6 - k, 6))
        screws = np.concatenate([kept, _adjoint_inverse(target, screws[:k])], axis=1)
    else:
        screws = screws[None]
    w = screws[..., :3]
    r = _cross_last(w, screws[..., 3:])
    name = "joints " + ("6..1" if backwards else "1..6")
    return (
        name + (f" shifted by {k}" if k else ""),
        w.transpose(1, 2, 0)[..., None],
        r.transpose(1, 2, 0)[..., None],
        target,
        np.roll(order, -k),
    )


@functools.lru_cache(maxsize=64)
def _unshifted(S, backwards):
    """(name, w, r, joint order) of the unshifted form of the loop, joints 1..6 or
    (``backwards``) 6..1, for the screws S (bytes of (6, 6)): :func:`_formulation`'s
    axes (6, 3, 1, 1), which do not depend on the pose, cached (read-only)."""
    S = np.frombuffer(S).reshape(6, 6)
    screws = (-S[::-1] if backwards else S)[None]
    w = screws[..., :3]
    r = _cross_last(w, screws[..., 3:])
    order = np.arange(6)[::-1] if backwards else np.arange(6)
    found = (
        w.transpose(1, 2, 0)[..., None],  # views, as the other forms' axes
        r.transpose(1, 2, 0)[..., None],
        order.copy(),
    )
    for array in found:
        array.setflags(write=False)
    return ("joints " + ("6..1" if backwards else "1..6"), *found[:2]), found[2]


@dataclass(frozen=True, eq=False)
class _Arm:
    """A 6R chain's constants for the solver, computed once per chain: its axes'
    unit directions ``w`` and points ``r`` (6, 3) at q = 0 and its home pose ``home``
    (4, 4) and inverse, lengths divided by ``scale`` (the chain's size, m); its unit
    screws ``screws`` (6, 6), (w; r x w), and ``key`` (bytes) their bytes, which
    name its geometry."""

    w: np.ndarray
    r: np.ndarray
    home: np.ndarray
    home_inverse: np.ndarray
    scale: float
    screws: np.ndarray
    key: bytes


#: Each chain's constants (an _Arm), kept while the chain lives (a chain is immutable).
_ARMS = weakref.WeakKeyDictionary()


def _arm(chain):
    """The :class:`_Arm` of a 6R chain, computed on first use."""
    try:
        return _ARMS[chain]
    except KeyError:
        pass
    z, o = chain.joint_axes(np.zeros(6))
    M = chain.fk(np.zeros(6))
    scale = length_scale(o, M[:3, 3])
    home = M.copy()
    home[:3, 3] /= scale
    r = o / scale
    screws = np.concatenate([z, _cross_last(r, z)], axis=1)
    arm = _Arm(z, r, home, _inverse(home), float(scale), screws, screws.tobytes())
    _ARMS[chain] = arm
    return arm


#: The form that last solved a chain's pose, by the chain's axes (bytes): tried first
#: next time, since special geometry makes the same forms degenerate for every pose.
_LAST_FORM = {}
_LAST_FORM_SIZE = 64


# ---- the public function ------------------------------------------------------------


#: The search that stands in when the elimination finds nothing: Newton from this
#: many fixed pseudo-random starts a pose, this many damped steps each.
SEARCH_STARTS = 64
SEARCH_STEPS = 40


def _search(w, r, home, targets):
    """Joint vectors (k, 6) that damped Newton steps bring near the targets (n, 4, 4)
    from SEARCH_STARTS starts each, and the pose (k,) of each (to be polished and
    checked): the answer when the elimination is degenerate or finds no root."""
    starts = np.random.default_rng(6).uniform(-np.pi, np.pi, (SEARCH_STARTS, 6))
    n = len(targets)
    q = np.tile(starts, (n, 1))
    pose = np.repeat(np.arange(n), SEARCH_STARTS)
    for _ in range(SEARCH_STEPS):
        e, J = _error(w, r, home, targets[pose], q)
        JT = np.swapaxes(J, 1, 2)
        damped = JT @ J + IK_GENERAL_SEARCH_DAMPING * np.eye(6)
        step = np.linalg.solve(damped, JT @ e[..., None])[..., 0]
        size = np.max(np.abs(step), axis=1, keepdims=True)
        q = q + step * (0.5 / np.maximum(size, 0.5))  # at most 0.5 rad a joint
    return q, pose


#: Fixed pseudo-random configurations at which an arm's mobility is measured.
_MOBILITY_Q = np.random.default_rng(43).uniform(-np.pi, np.pi, (4, 6))


def _mobility(chain):
    """The rank of a 6R chain's Jacobian at a generic configuration: 6 for an arm
    whose poses have isolated solutions; less when its axes leave it fewer degrees
    of freedom (all parallel: 3; two coincident: at most 5), so that every pose it
    reaches has a continuum of solutions.

    Parameters
    ----------
    chain : Chain
        A serial chain of 6 revolute joints.

    Returns
    -------
    int
        The largest rank of the space Jacobian (lengths divided by the chain's
        size, rank to IK_GENERAL_SINGULAR_TOL) at four fixed pseudo-random
        configurations.
    """
    if chain not in _MOBILITY:
        arm = _arm(chain)
        J = _poe(arm.w, arm.r, arm.home, _MOBILITY_Q)[2]
        sigma = np.linalg.svd(J, compute_uv=False)
        ranks = np.sum(sigma > IK_GENERAL_SINGULAR_TOL * sigma[:, :1], axis=1)
        _MOBILITY[chain] = int(np.max(ranks))
    return _MOBILITY[chain]


_MOBILITY = weakref.WeakKeyDictionary()


def _mobility_reason(rank, reason, found):
    """The reason of an answer of an arm of mobility ``rank`` < 6."""
    said = (
        f"the arm's axes leave it {rank} degrees of freedom (its Jacobian has rank "
        f"{rank} < 6 at every configuration): "
    )
    if found:
        said += (
            f"the solutions form a continuum (of dimension {6 - rank} or more), of "
            "which Q holds points only"
        )
    else:
        said += "no point of a solution was found; the pose is likely out of its reach"
    return said + (f"; {reason}" if reason else "")


def _say(singular, unexplained=()):
    """The reason of an answer from the singular flags (k,) of its solutions and the
    real roots of the eigenvalue problem (rad) that no solution accounts for: None
    for isolated solutions that account for every root; a sentence for none, for a
    solution where the Jacobian loses rank, or for a root left over (there may be a
    solution that Newton did not bring to the pose)."""
    if len(unexplained):
        angles = ", ".join(f"{a:.4f}" for a in unexplained[:4])
        missing = (
            f"{len(unexplained)} real root(s) of the eigenvalue problem (its joint at "
            f"{angles} rad) gave fewer solutions of the pose than the root has "
            "candidates (a repeated root one for each solution that shares it): the "
            "list may be incomplete"
        )
        other = _say(singular)
        return missing if other is None or not len(singular) else f"{missing}; {other}"
    if not len(singular):
        return "no real solution: the pose is out of reach"
    if not singular.any():
        return None
    return (
        f"{int(np.sum(singular))} of the {len(singular)} solutions are at a singular "
        "configuration (the Jacobian loses rank): solutions there may coincide or "
        "form a continuum (aligned axes), of which Q holds points only"
    )


def _unexplained(root, root_pose, multiplicity, kept, singular, poses, joint):
    """The real roots (rad) that fewer solutions account for than they should, by
    pose: {pose: angles}.

    ``root`` (k,) are the genuine roots' angles of ``joint`` (one a consistent
    candidate), ``root_pose`` (k,) their poses, ``multiplicity`` (k,) each root's
    multiplicity in the spectrum; ``kept`` a (Q, residuals) pair for each of
    ``poses`` (sorted) and ``singular`` (all solutions,) their flags. The roots
    within IK_GENERAL_EXPLAINED_TOL of one another are one root: its c consistent
    candidates, m its multiplicity, call for min(c, m) distinct solutions whose
    angle of ``joint`` is within IK_GENERAL_EXPLAINED_TOL of it (solutions sharing
    that angle make a repeated root). Fewer is a solution lost, unless one of them
    is singular (solutions coincide there, and a double root may stand for one)."""
    if not len(root):
        return {}
    if len(kept) == 1 and _apart(root, multiplicity):
        # one pose, simple roots apart: each calls for one solution at its angle
        near = np.abs(_wrap_angle(root[:, None] - kept[0][0][:, joint])) <= (
            IK_GENERAL_EXPLAINED_TOL
        )
        if near.any(axis=1).all():
            return {}
    same = (root_pose[:, None] == root_pose) & (
        np.abs(_wrap_angle(root[:, None] - root)) <= IK_GENERAL_EXPLAINED_TOL
    )
    wanted = np.minimum(same.sum(axis=1), (same * multiplicity).max(axis=1))
    if len(kept) == 1:  # one pose: its solutions' angles against its roots
        near = np.abs(_wrap_angle(root[:, None] - kept[0][0][:, joint])) <= (
            IK_GENERAL_EXPLAINED_TOL
        )
        left = (near.sum(axis=1) < wanted) & ~(near & singular).any(axis=1)
        if not left.any():
            return {}
        return {int(poses[0]): np.unique(np.round(_wrap_angle(root[left]), 4))}
    counts = np.array([len(Q) for Q, _ in kept])
    width = max(int(counts.max()), 1)
    angles = np.full((len(kept), width), np.nan)
    flags = np.zeros((len(kept), width), bool)
    rows = np.repeat(np.arange(len(kept)), counts)
    columns = np.arange(len(rows)) - np.repeat(np.cumsum(counts) - counts, counts)
    if len(rows):
        angles[rows, columns] = np.concatenate([Q[:, joint] for Q, _ in kept])
        flags[rows, columns] = singular
    where = np.searchsorted(poses, root_pose)  # poses is sorted
    near = np.abs(_wrap_angle(root[:, None] - angles[where])) <= (
        IK_GENERAL_EXPLAINED_TOL
    )
    left = (np.sum(near, axis=1) < wanted) & ~np.any(near & flags[where], axis=1)
    return {
        int(j): np.unique(np.round(_wrap_angle(root[left & (root_pose == j)]), 4))
        for j in np.unique(root_pose[left])
    }


def _apart(root, multiplicity):
    """Whether the roots (k,) (rad) of one pose are simple (``multiplicity`` (k,)
    all 1) and no two within 2 IK_GENERAL_EXPLAINED_TOL of each other (modulo a
    turn; on floats): each then calls for one solution of its own."""
    if any(m != 1 for m in multiplicity.tolist()):
        return False
    angles = sorted(root.tolist())
    gaps = [b - a for a, b in zip(angles, angles[1:])]
    gaps.append(angles[0] + 2 * np.pi - angles[-1])  # round the turn
    return len(angles) == 1 or min(gaps) > 2 * IK_GENERAL_EXPLAINED_TOL


def _distinct(Q, residuals):
    """The solutions with no earlier (better) one within IK_GENERAL_SAME_TOL, sorted
    lexicographically, their residuals and their rows in Q."""
    same = np.abs(_wrap_angle(Q[:, None] - Q[None])).max(axis=2) <= (
        IK_GENERAL_SAME_TOL
    )
    if same.sum() == len(Q):  # the diagonal alone: all distinct
        order = np.lexsort(Q.T[::-1])
        return Q[order], residuals[order], order
    # a pair besides the diagonal: the better of each kept, in order of residual
    order = np.argsort(residuals, kind="stable")
    Q, residuals, same = Q[order], residuals[order], same[np.ix_(order, order)]
    keep = []
    for i in range(len(Q)):
        if not any(same[i, j] for j in keep):
            keep.append(i)
    Q, residuals, index = Q[keep], residuals[keep], order[keep]
    order = np.lexsort(Q.T[::-1])
    return Q[order], residuals[order], index[order]


def general_6r_ik(chain, T):
    """Every real inverse-kinematics solution of a 6R chain, for one pose or a batch.

    The Raghavan–Roth equations eliminated to a 24 x 24 eigenvalue problem in
    tan(q3 / 2) (Manocha and Canny 1994), each real root back-substituted and
    polished by Newton steps on the chain's forward kinematics; see the module's
    docstring. Any geometry (DH or screws, base and tool included); an arm whose
    special axes make every form of the elimination degenerate gets a reason, not a
    wrong count. A batch is solved together (one eigenvalue call for all its poses),
    which is several times faster a pose than one call each.

    Parameters
    ----------
    chain : Chain
        A serial chain of 6 revolute joints.
    T : array-like, shape (4, 4) or (N, 4, 4)
        The end-effector pose(s), rigid transforms in the chain's world frame (m).

    Returns
    -------
    GeneralIK, or a list of N for a batch
        ``Q`` (k, 6) the solutions (rad, in (-pi, pi], sorted), ``residuals`` (k,),
        ``reason`` (None when solved).

    Examples
    --------
    A 6R arm of no special geometry (no axes meeting or parallel): the joint vector
    that made a pose is among the solutions found.

    >>> import numpy as np, screwkit as sk
    >>> arm = sk.Chain.from_table([[0, 0.3, 0.2, 1.0], [0, 0.1, 0.5, -0.7],
    ...     [0, 0.2, 0.4, 1.3], [0, 0.25, 0.1, 0.9], [0, 0.1, 0.3, -1.1],
    ...     [0, 0.2, 0.1, 0.4]])
    >>> q = np.array([0.3, -0.5, 1.0, 0.7, -1.2, 2.0])
    >>> result = general_6r_ik(arm, arm.fk(q))
    >>> bool(np.min(np.abs(result.Q - q).max(axis=1)) < 1e-9)
    True
    """
    check_chain(chain)
    if chain.n != 6 or any(j is not Joint.REVOLUTE for j in chain.joints):
        kinds = "".join(j.value for j in chain.joints)
        raise ValueError(
            f"chain must have 6 revolute joints (6R), got {chain.n} joints {kinds}"
        )
    if one_pose(T) is not None:  # one plain pose: checked on floats, solved alone
        return _solve_one(chain, T)
    _check_batch_size(T, "T", MAX_POSES, "general_6r_ik")
    T = check_poses(T, "T")
    if T.ndim == 2:
        return _solve_one(chain, T)
    batch = T
    answers = []
    for start in range(0, len(batch), CHUNK):  # memory bounded: ~10 kB a pose
        answers += _solve(chain, batch[start : start + CHUNK])
    return answers


#: The largest batch of poses :func:`general_6r_ik` solves in one call (about a
#: millisecond of CPU a pose: 100,000 poses take minutes); it solves a batch in
#: chunks of CHUNK poses.
MAX_POSES = 100_000
CHUNK = 4096


def _check_batch_size(T, name, limit, what):
    """Refuse a batch of poses T (an array's shape is read, nothing is converted)
    larger than ``limit``, before any work on it, with a message that says so."""
    if isinstance(T, np.ndarray) and T.ndim >= 3:
        count, given = int(np.prod(T.shape[:-2])), f"shape {T.shape}"
    elif isinstance(T, (list, tuple)):
        count, given = len(T), f"a {type(T).__name__} of {len(T):,} entries"
    else:
        return
    if count > limit:
        raise ValueError(
            f"{name} must be a batch of at most {limit:,} poses for {what}, got "
            f"{count:,} ({given}): solve it in parts"
        )


def _finish(chain, arm, T, T_scaled, phi, pose, poses, name, order, claims=None):
    """The answers (a list of GeneralIK) of ``poses`` (of T (n, 4, 4), T_scaled its
    lengths divided by the chain's size) from the candidates phi (k, 6) of the form
    ``name`` (joint order ``order``), pose (k,) naming each candidate's pose:
    polished, checked, told apart and flagged. ``claims`` (k,): which candidates'
    third angles are genuine real roots of the eigenvalue problem, which solutions
    must account for: 0 not, else the root's multiplicity (:func:`_candidates`;
    None, a search: none)."""
    q = np.empty_like(phi)
    q[:, order] = phi
    targets = T[pose]

    def measure(q, rows):
        return _residuals(chain, targets[rows], q, arm.scale)

    q, J, residuals, bound = _polish(arm.w, arm.r, arm.home, T_scaled[pose], q, measure)
    good = residuals <= IK_GENERAL_ACCEPT_TOL
    claims = np.zeros(len(phi), int) if claims is None else claims
    genuine = claims > 0
    if genuine.all():
        root, root_pose, multiplicity = phi[:, 2], pose, claims
    else:
        root, root_pose, multiplicity = phi[genuine, 2], pose[genuine], claims[genuine]
    if not good.all():
        q, pose, residuals, J, bound = (
            q[good],
            pose[good],
            residuals[good],
            J[good],
            bound[good],
        )
    q = _wrap_angle(q)
    if len(poses) == 1:
        Q, res, index = _distinct(q, residuals)
        kept = [(Q, res)]
    else:
        by_pose = np.argsort(pose, kind="stable")
        q, pose, residuals, J, bound = (
            x[by_pose] for x in (q, pose, residuals, J, bound)
        )
        starts = np.searchsorted(pose, poses, "left")
        ends = np.searchsorted(pose, poses, "right")
        parts = [_distinct(q[a:b], residuals[a:b]) for a, b in zip(starts, ends)]
        kept = [(Q, res) for Q, res, _ in parts]
        index = np.concatenate([a + i for (_, _, i), a in zip(parts, starts)])
    singular = _singular(J[index], bound[index])
    left = _unexplained(root, root_pose, multiplicity, kept, singular, poses, order[2])
    answers, start = [], 0
    for j, (Q, res) in zip(poses, kept):
        flags = singular[start : start + len(Q)]
        answers.append(GeneralIK(Q, res, _say(flags, left.get(j, ())), name, flags))
        start += len(Q)
    return answers


def _remember(key, attempt):
    """Keep ``attempt`` as the form that last solved a pose of the chain ``key``."""
    if key not in _LAST_FORM and len(_LAST_FORM) >= _LAST_FORM_SIZE:
        _LAST_FORM.clear()
    _LAST_FORM[key] = attempt


def _solve_one(chain, T):
    """The answer (a GeneralIK) of one checked pose T (4, 4), as :func:`_solve` gives
    it, with less bookkeeping: the form that last solved a pose of this chain (at
    first joints 1..6) is tried alone when its axes do not depend on the pose (the
    unshifted forms, whose constants are cached) and it is well conditioned here,
    and the pose has a solution; otherwise :func:`_solve` solves it."""
    arm = _arm(chain)
    attempt = _LAST_FORM.get(arm.key, (0, 0))
    if attempt[1] % 6 or _mobility(chain) < 6:
        return _solve(chain, T[None])[0]
    T_scaled = T[None].copy()
    T_scaled[:, :3, 3] /= arm.scale
    G = T_scaled @ arm.home_inverse
    name, w, r, target, order = _formulation(arm.screws, G, attempt[1])
    shift = _SHIFTS[attempt[0]]
    found = _eliminate(w, r, target, shift)
    if not (found.usable[0] and found.quality[0] >= IK_GENERAL_COMFORT_TOL):
        return _solve(chain, T[None])[0]
    phi, which, claims = _candidates(w, r, target, shift, found)
    pose = np.zeros(len(phi), int)
    answer = _finish(chain, arm, T[None], T_scaled, phi, pose, [0], name, order, claims)
    if not len(answer[0].Q):  # none: the batch path searches
        return _solve(chain, T[None])[0]
    _remember(arm.key, attempt)
    return answer[0]


def _solve(chain, T):
    """The answers (a list of GeneralIK) for poses T (n, 4, 4): each form of the loop
    is tried on the poses that no earlier form solved; a nearly degenerate form is
    kept as a pose's fallback, used only when no well-conditioned form exists."""
    arm = _arm(chain)
    T_scaled = T.copy()
    T_scaled[:, :3, 3] /= arm.scale
    G = T_scaled @ arm.home_inverse
    n = len(T)
    answers, reasons, fallback = [None] * n, [[] for _ in range(n)], {}

    def finish(phi, pose, poses, name, order, claims=None):
        """_finish, the answers stored in ``answers``."""
        found = _finish(chain, arm, T, T_scaled, phi, pose, poses, name, order, claims)
        for j, answer in zip(poses, found):
            answers[j] = answer

    # a singular leading matrix from special geometry stays singular at any shift:
    # every form is tried at the first shift before another shift is
    key = arm.key
    tries = [(s, f) for s in range(len(_SHIFTS)) for f in range(12)]
    if key in _LAST_FORM:
        tries.remove(_LAST_FORM[key])
        tries.insert(0, _LAST_FORM[key])
    pending = np.arange(n)
    for attempt in tries:
        if not len(pending):
            break
        shift = _SHIFTS[attempt[0]]
        name, w, r, target, order = _formulation(arm.screws, G[pending], attempt[1])
        found = _eliminate(w, r, target, shift)
        for j, why in zip(pending, found.reason):
            if why is not None:
                reasons[j].append(f"{name}: {why}")
        phi, which, claims = _candidates(w, r, target, shift, found)
        comfortable = found.usable & (found.quality >= IK_GENERAL_COMFORT_TOL)
        for i in np.nonzero(found.usable & ~comfortable)[0]:  # nearly degenerate
            j = pending[i]
            if j not in fallback or found.quality[i] > fallback[j][0]:
                mine = which == i
                fallback[j] = (found.quality[i], phi[mine], name, order, claims[mine])
        if np.any(comfortable):
            take = comfortable[which]
            finish(
                phi[take],
                pending[which[take]],
                pending[comfortable],
                name,
                order,
                claims[take],
            )
            _remember(key, attempt)
        pending = pending[~comfortable]
    for j in pending:
        if j in fallback:
            _, phi, name, order, mine = fallback[j]
            finish(phi, np.full(len(phi), j), [j], name, order, mine)
        else:
            answers[j] = GeneralIK(
                np.zeros((0, 6)),
                np.zeros(0),
                "every form of the elimination is degenerate for this arm and pose "
                "(special geometry, or solutions that form a continuum, e.g. along "
                "aligned axes): " + "; ".join(reasons[j][:2]) + "; ...",
            )
    empty = [j for j in range(n) if not len(answers[j].Q)]
    if empty:  # special geometry can hide roots from a form that looks well posed
        q, pose = _search(arm.w, arm.r, arm.home, T_scaled[empty])
        before = [answers[j] for j in empty]
        finish(q, np.asarray(empty)[pose], empty, "Newton search", [0, 1, 2, 3, 4, 5])
        for j, old in zip(empty, before):
            if not len(answers[j].Q):
                answers[j] = old
                continue
            answers[j].reason = (
                f"the elimination found no solution ({old.reason}), but a Newton "
                f"search from {SEARCH_STARTS} starts found these {len(answers[j].Q)}: "
                "the pose is reachable, and there may be other solutions"
                + ("; " + answers[j].reason if answers[j].reason else "")
            )
    rank = _mobility(chain)
    if rank < 6:
        for answer in answers:
            answer.reason = _mobility_reason(rank, answer.reason, len(answer.Q))
    return answers
