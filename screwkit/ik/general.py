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
real eigenvalues give q3, the eigenvectors q4 and q5, the 14 equations q1 and q2, the
rotation left q6; every candidate is then polished by Newton steps on the chain's own
forward kinematics and Jacobian, and kept when it meets the pose. At most 16
solutions.

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

What the answer claims: every real root of the eigenvalue problem whose imaginary
part is below IK_GENERAL_REAL_TOL becomes a candidate, and every candidate that
Newton brings to the pose (residual at most IK_GENERAL_ACCEPT_TOL) is returned once.
A solution is missed only if the eigenvalue solver's error on its root exceeds
Newton's basin, which round-off does not do for a well-conditioned form (the tests
find nothing missing against a 300-start search on random arms). A solution where
the Jacobian loses rank (solutions coinciding, or a continuum along aligned axes) is
returned with a reason saying so: of a continuum, Q holds points only.
"""

import functools
import weakref
from dataclasses import dataclass

import numpy as np

from .._checks import check_chain, check_poses
from ..links import Joint
from ..tolerances import (
    IK_GENERAL_ACCEPT_TOL,
    IK_GENERAL_CLUSTER_TOL,
    IK_GENERAL_COMFORT_TOL,
    IK_GENERAL_LEADING_TOL,
    IK_GENERAL_NULL_TOL,
    IK_GENERAL_RANK_TOL,
    IK_GENERAL_REAL_TOL,
    IK_GENERAL_SAME_TOL,
    IK_GENERAL_SINGULAR_TOL,
    length_scale,
)
from ..transforms import _cross, _wrap_angle

__all__ = ["GeneralIK", "general_6r_ik"]

#: Newton steps that polish each candidate (quadratic convergence from the
#: eigenvalue's 1e-8 or better reaches round-off in two or three).
NEWTON_STEPS = 6

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
    """

    Q: np.ndarray
    residuals: np.ndarray
    reason: str | None = None
    formulation: str = ""


# ---- the loop's two sides -----------------------------------------------------------


def _cross3(a, b):
    """a x b along the last axis (..., 3): np.cross without its axis handling, which
    costs more than the product for the few small arrays here."""
    return a[..., _NEXT] * b[..., _LAST] - a[..., _LAST] * b[..., _NEXT]


_NEXT, _LAST = [1, 2, 0], [2, 0, 1]


def _turn(w, r, angle, x, point):
    """x (3, m) turned by ``angle`` (m,) about the axis through r along unit w (3,);
    a point if ``point``, else a direction. Rodrigues' formula."""
    w, r = w[:, None], r[:, None]
    d = x - r if point else x
    c, s = np.cos(angle), np.sin(angle)
    turned = d * c + _cross(w, d) * s + w * (np.sum(w * d, axis=0) * (1 - c))
    return turned + r if point else turned


def _products(p, l):
    """The 14 Raghavan–Roth quantities (14, m) of points p and directions l
    (3, m)."""
    pp = np.sum(p * p, axis=0)
    pl = np.sum(p * l, axis=0)
    return np.concatenate([p, l, [pp, pl], _cross(p, l), pp * l - 2 * pl * p])


def _turn_both(w, r, angle, p, l):
    """Points p and directions l (3, m) turned by ``angle`` (m,) about the axis through
    r along unit w (3,), in one Rodrigues step."""
    m = p.shape[1]
    x = np.concatenate([p - r[:, None], l], axis=1)
    angle = np.concatenate([angle, angle])
    w = w[:, None]
    c, s = np.cos(angle), np.sin(angle)
    x = x * c + _cross(w, x) * s + w * (np.sum(w * x, axis=0) * (1 - c))
    return x[:, :m] + r[:, None], x[:, m:]


def _left(w, r, q3, q4, q5):
    """E3 E4 E5 applied to axis 6's point and direction (r[5], w[5]): the 14
    quantities (14, m) at the angles (m,)."""
    p = np.repeat(r[5][:, None], len(q3), axis=1)
    l = np.repeat(w[5][:, None], len(q3), axis=1)
    for k, q in ((4, q5), (3, q4), (2, q3)):
        p, l = _turn_both(w[k], r[k], q, p, l)
    return _products(p, l)


def _right(w, r, hp, hl, q1, q2):
    """E2^-1 E1^-1 applied to G's image (hp, hl) of axis 6's point and direction:
    the 14 quantities (14, m) at the angles (m,)."""
    p = np.repeat(hp[:, None], len(q1), axis=1)
    l = np.repeat(hl[:, None], len(q1), axis=1)
    for k, q in ((0, q1), (1, q2)):
        p, l = _turn_both(w[k], r[k], -q, p, l)
    return _products(p, l)


# ---- one formulation ----------------------------------------------------------------


def _companion(w, r, G, shift):
    """The eigenvalue problem of the loop E1 ... E6 = G (unit axes w, points r, the
    lengths divided by the chain's size), angles q_i = phi_i + shift_i.

    Returns (A, Q, C0, reason): A the 24 x 24 companion matrix whose eigenvalues are
    tan(phi_3 / 2), Q (14, 8) and C0 (14,) the right side's coefficients (for q1,
    q2); A is None with a reason when this formulation is degenerate.
    """
    hp, hl = G[:3, :3] @ r[5] + G[:3, 3], G[:3, :3] @ w[5]
    a1, a2 = _GRID2 + shift[:2, None]
    right = _right(w, r, hp, hl, a1, a2) @ _FIT2.T  # (14, 9) coefficients
    C0, Q = right[:, 0], right[:, 1:]
    U, sigma, _ = np.linalg.svd(Q)
    if sigma[-1] <= IK_GENERAL_RANK_TOL * sigma[0]:
        return None, Q, C0, _RANK_REASON, 0.0, None
    N = U[:, 8:].T  # (6, 14): N Q = 0
    left = _left_coefficients(w[2:], r[2:], shift[2:5].tobytes()).copy()
    left[:, 0] -= C0
    # (6, power of x3, power of x4, power of x5)
    poly = (N @ left @ _TO_POLY3).reshape(6, 3, 3, 3)
    M = np.zeros((3, 12, 4, 3))
    M[:, :6, :3, :] = poly.transpose(1, 0, 2, 3)
    M[:, 6:, 1:, :] = poly.transpose(1, 0, 2, 3)
    M = M.reshape(3, 12, 12)
    sv = np.linalg.svd(M[2], compute_uv=False)
    size = max(np.abs(M).max(), 1.0)
    if sv[-1] <= IK_GENERAL_LEADING_TOL * size:
        reason = "the eigenvalue problem's leading matrix is singular"
        return None, Q, C0, reason, 0.0, None
    solved = np.linalg.solve(M[2], np.concatenate([M[0], M[1]], axis=1))
    A = np.zeros((24, 24))
    A[:12, 12:] = np.eye(12)
    A[12:, :12] = -solved[:, :12]
    A[12:, 12:] = -solved[:, 12:]
    return A, Q, C0, None, min(sigma[-1] / sigma[0], sv[-1] / size), M


@functools.lru_cache(maxsize=64)
def _left_coefficients_cached(w, r, shift):
    """_left_coefficients on bytes (hashable), cached: joints 3 to 6 of a chain's
    first formulation do not depend on the pose."""
    w, r = np.frombuffer(w).reshape(4, 3), np.frombuffer(r).reshape(4, 3)
    a3, a4, a5 = _GRID3 + np.frombuffer(shift)[:, None]
    pad = np.zeros((2, 3))
    left = _left(np.vstack([pad, w]), np.vstack([pad, r]), a3, a4, a5) @ _FIT3.T
    left.setflags(write=False)
    return left


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
    replaced.

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
    return np.concatenate(roots), np.concatenate(vectors)


def _candidates(w, r, G, shift):
    """Joint vectors (k, 6) of the loop E1 ... E6 = G from its eigenvalue problem,
    or (None, reason)."""
    A, Q, C0, reason, quality, M = _companion(w, r, G, shift)
    if A is None:
        return None, reason, quality
    values, vectors = np.linalg.eig(A)
    real = np.abs(values.imag) <= IK_GENERAL_REAL_TOL * (1 + np.abs(values))
    if not np.any(real):
        return np.zeros((0, 6)), None, quality
    x3, Z = values[real], vectors[:, real]
    # the eigenvector is (v, x3 v): take the better-scaled half
    V = np.where(np.abs(x3) <= 1, Z[:12], Z[12:]).T
    x3, V = _repeated_roots(M, x3, V)
    V = V.reshape(-1, 4, 3)
    x4 = np.sum(V[:, :-1].conj() * V[:, 1:], axis=(1, 2)) / np.sum(
        np.abs(V[:, :-1]) ** 2, axis=(1, 2)
    )
    x5 = np.sum(V[:, :, :-1].conj() * V[:, :, 1:], axis=(1, 2)) / np.sum(
        np.abs(V[:, :, :-1]) ** 2, axis=(1, 2)
    )
    q3 = _half_angle(x3.real) + shift[2]
    q4 = _half_angle(x4.real) + shift[3]
    q5 = _half_angle(x5.real) + shift[4]
    # q1, q2: the right side's 8 products from the 14 values of the left side
    b = np.linalg.lstsq(Q, _left(w, r, q3, q4, q5) - C0[:, None], rcond=None)[0]
    # b's rows: (1, c1, s1) x (1, c2, s2) without the first, in that order
    q1 = np.arctan2(b[5], b[2]) + shift[0]
    q2 = np.arctan2(b[1], b[0]) + shift[1]
    q = np.stack([q1, q2, q3, q4, q5, np.zeros_like(q1)], axis=1)
    q[:, 5] = _last_angle(w, r, G, q)
    return q, None, quality


def _last_angle(w, r, G, q):
    """q6 (k,) from q1..q5: the rotation E6 = (E1 ... E5)^-1 G about axis 6."""
    w6 = w[5]
    u = _cross3(w6, np.array([1.0, 0.0, 0.0]))
    if np.linalg.norm(u) < 0.5:
        u = _cross3(w6, np.array([0.0, 1.0, 0.0]))
    u = u / np.linalg.norm(u)
    Gu = np.repeat((G[:3, :3] @ u)[:, None], q.shape[0], axis=1)
    for k in range(5):  # (E1 ... E5)^-1 = E5^-1 ... E1^-1: undo joint 1 first
        Gu = _turn(w[k], r[k], -q[:, k], Gu, False)
    return np.arctan2(_cross3(w6, u) @ Gu, u @ Gu)


# ---- the twelve formulations ---------------------------------------------------------


def _inverse(T):
    """The inverse of a rigid transform (4, 4), unchecked."""
    inverse = np.eye(4)
    inverse[:3, :3] = T[:3, :3].T
    inverse[:3, 3] = -T[:3, :3].T @ T[:3, 3]
    return inverse


def _adjoint_inverse(G, S):
    """Ad(G^-1) applied to screws S (k, 6) [omega; v]."""
    R, p = G[:3, :3], G[:3, 3]
    w = S[:, :3] @ R  # R^T omega
    v = (S[:, 3:] - _cross3(p, S[:, :3])) @ R
    return np.concatenate([w, v], axis=1)


def _formulation(S, G, index):
    """(name, screws, target, joint order, sign) of form ``index`` (0 to 11) of the
    loop: joints 1..6 (index < 6) or 6..1, cyclically shifted by index % 6."""
    backwards, k = divmod(index, 6)
    screws, target = (-S[::-1], _inverse(G)) if backwards else (S, G)
    order = np.arange(6)[::-1] if backwards else np.arange(6)
    moved = np.concatenate([screws[k:], _adjoint_inverse(target, screws[:k])])
    name = "joints " + ("6..1" if backwards else "1..6")
    return (
        name + (f" shifted by {k}" if k else ""),
        moved,
        target,
        np.roll(order, -k),
        -1.0 if backwards else 1.0,
    )


#: Each chain's joint axes (directions, points) and home pose at q = 0, kept while
#: the chain lives (a chain is immutable).
_GEOMETRY = weakref.WeakKeyDictionary()


def _geometry(chain):
    """The axes z, o (6, 3) and the home pose M (4, 4) of a chain at q = 0 (m)."""
    if chain not in _GEOMETRY:
        z, o = chain.joint_axes(np.zeros(6))
        _GEOMETRY[chain] = (z, o, chain.fk(np.zeros(6)))
    return _GEOMETRY[chain]


#: The form that last solved a chain's pose, by the chain's axes (bytes): tried first
#: next time, since special geometry makes the same forms degenerate for every pose.
_LAST_FORM = {}
_LAST_FORM_SIZE = 64


# ---- the public function ------------------------------------------------------------


def _rotations(w, angle):
    """Rotations (k, 3, 3) by ``angle`` (k,) about the unit axis w (3,)."""
    K = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    s, c = np.sin(angle)[:, None, None], np.cos(angle)[:, None, None]
    return np.eye(3) + s * K + (1 - c) * (K @ K)


def _poe(w, r, home, q):
    """The pose exp([S1] q1) ... exp([S6] q6) M (rotation (k, 3, 3), position (k, 3))
    and the space Jacobian (k, 6, 6), [omega; v] rows, of the axes (w, r)."""
    R = np.broadcast_to(np.eye(3), (len(q), 3, 3))
    p = np.zeros((len(q), 3))
    J = np.empty((len(q), 6, 6))
    for i in range(6):
        wi, ri = R @ w[i], R @ r[i] + p
        J[:, :3, i], J[:, 3:, i] = wi, _cross3(ri, wi)
        Ri = _rotations(w[i], q[:, i])
        p = p + (R @ (r[i] - Ri @ r[i])[..., None])[..., 0]
        R = R @ Ri
    return R @ home[:3, :3], R @ home[:3, 3] + p, J


def _polish(w, r, home, target, q):
    """Newton steps on the pose from the candidates q (k, 6), lengths divided by the
    chain's size.

    A step solves J_s dq = e, e = (omega, dp - omega x p): omega the vee of the skew
    part of R* R(q)^T, dp the position error, the spatial error twist to first order
    with the same Jacobian at a solution (quadratic convergence, no logarithm)."""
    q = q.copy()
    active = np.arange(len(q))
    for _ in range(NEWTON_STEPS):
        R, p, J = _poe(w, r, home, q[active])
        E = target[:3, :3] @ np.swapaxes(R, 1, 2)
        omega = (
            np.stack(
                [
                    E[:, 2, 1] - E[:, 1, 2],
                    E[:, 0, 2] - E[:, 2, 0],
                    E[:, 1, 0] - E[:, 0, 1],
                ],
                axis=1,
            )
            / 2
        )
        e = np.concatenate([omega, target[:3, 3] - p - _cross3(omega, p)], axis=1)
        moving = np.linalg.norm(e, axis=1) > IK_GENERAL_ACCEPT_TOL * 1e-3
        active, e, J = active[moving], e[moving], J[moving]
        if not len(active):
            break
        q[active] += (np.linalg.pinv(J) @ e[..., None])[..., 0]
    return q


def _residuals(chain, T, q, scale):
    """The pose error (k,) of each q by the chain's own forward kinematics:
    sqrt(|R(q) - R|_F^2 / 2 + |p(q) - p|^2 / scale^2), which is the norm of the error
    twist [omega; v / scale] to first order (|R(q) - R|_F = 2 sqrt(2) sin(angle / 2))
    and, unlike the skew part of R(q)^T R, vanishes only at the pose itself."""
    Tq = chain.fk(q)
    rotation = np.sum((Tq[:, :3, :3] - T[:3, :3]) ** 2, axis=(1, 2)) / 2
    position = np.sum((Tq[:, :3, 3] - T[:3, 3]) ** 2, axis=1) / scale**2
    return np.sqrt(rotation + position)


def _say(w, r, home, Q):
    """The reason of an answer: None for isolated solutions; a sentence for none or for
    a solution where the Jacobian loses rank."""
    if not len(Q):
        return "no real solution: the pose is out of reach"
    sigma = np.linalg.svd(_poe(w, r, home, Q)[2], compute_uv=False)
    singular = sigma[:, -1] <= IK_GENERAL_SINGULAR_TOL * sigma[:, 0]
    if not np.any(singular):
        return None
    return (
        f"{int(np.sum(singular))} of the {len(Q)} solutions are at a singular "
        "configuration (the Jacobian loses rank): solutions there may coincide or "
        "form a continuum (aligned axes), of which Q holds points only"
    )


def _distinct(Q, residuals):
    """The solutions with no earlier (better) one within IK_GENERAL_SAME_TOL, sorted
    lexicographically."""
    order = np.argsort(residuals)
    Q, residuals = Q[order], residuals[order]
    same = np.max(np.abs(_wrap_angle(Q[:, None] - Q[None])), axis=2) <= (
        IK_GENERAL_SAME_TOL
    )
    keep = []
    for i in range(len(Q)):
        if not any(same[i, j] for j in keep):
            keep.append(i)
    Q, residuals = Q[keep], residuals[keep]
    order = np.lexsort(Q.T[::-1])
    return Q[order], residuals[order]


def general_6r_ik(chain, T):
    """Every real inverse-kinematics solution of a 6R chain for one pose.

    The Raghavan–Roth equations eliminated to a 24 x 24 eigenvalue problem in
    tan(q3 / 2) (Manocha and Canny 1994), each real root back-substituted and
    polished by Newton steps on ``chain.fk`` and ``chain.body_jacobian``; see the
    module's docstring. Any geometry (DH or screws, base and tool included); an arm
    whose special axes make every form of the elimination degenerate gets a reason,
    not a wrong count.

    Parameters
    ----------
    chain : Chain
        A serial chain of 6 revolute joints.
    T : array-like, shape (4, 4)
        The end-effector pose, a rigid transform in the chain's world frame (m).

    Returns
    -------
    GeneralIK
        ``Q`` (k, 6) the solutions (rad, in (-pi, pi], sorted), ``residuals`` (k,),
        ``reason`` (None when solved).

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
    T = check_poses(T, "T", single_only=True)
    z, o, M = _geometry(chain)
    scale = length_scale(o, M[:3, 3])
    M_scaled, T_scaled = M.copy(), T.copy()
    M_scaled[:3, 3] /= scale
    T_scaled[:3, 3] /= scale
    Sn = np.concatenate([z, _cross3(o / scale, z)], axis=1)  # unit screws (w; r x w)
    G = T_scaled @ _inverse(M_scaled)

    def finish(attempt, phi, name, order, sign):
        """The answer from the candidates phi of a form."""
        if len(_LAST_FORM) >= _LAST_FORM_SIZE:
            _LAST_FORM.clear()
        _LAST_FORM[key] = attempt
        q = np.empty_like(phi)
        q[:, order] = sign * phi
        q = _polish(z, o / scale, M_scaled, T_scaled, q)
        residuals = _residuals(chain, T, q, scale)
        good = residuals <= IK_GENERAL_ACCEPT_TOL
        Q, residuals = _distinct(_wrap_angle(q[good]), residuals[good])
        return GeneralIK(Q, residuals, _say(z, o / scale, M_scaled, Q), name)

    reasons, fallback = [], None
    # a singular leading matrix from special geometry stays singular at any shift:
    # every form is tried at the first shift before another shift is
    key = Sn.tobytes()
    tries = [(s, f) for s in range(len(_SHIFTS)) for f in range(12)]
    if key in _LAST_FORM:
        tries.remove(_LAST_FORM[key])
        tries.insert(0, _LAST_FORM[key])
    for attempt in tries:
        shift = _SHIFTS[attempt[0]]
        name, screws, target, order, sign = _formulation(Sn, G, attempt[1])
        w = screws[:, :3]
        r = _cross3(w, screws[:, 3:])  # the point of each axis nearest the origin
        phi, reason, quality = _candidates(w, r, target, shift)
        if phi is None:
            reasons.append(f"{name}: {reason}")
            continue
        if quality < IK_GENERAL_COMFORT_TOL:  # nearly degenerate: look on
            if fallback is None or quality > fallback[0]:
                fallback = (quality, attempt, phi, name, order, sign)
            continue
        return finish(attempt, phi, name, order, sign)
    if fallback is not None:
        return finish(*fallback[1:])
    return GeneralIK(
        np.zeros((0, 6)),
        np.zeros(0),
        "every form of the elimination is degenerate for this arm and pose (special "
        "geometry, or solutions that form a continuum, e.g. along aligned axes): "
        + "; ".join(reasons[:2])
        + "; ...",
    )
