"""The Paden–Kahan subproblems: the geometric steps of closed-form inverse kinematics.

Each subproblem asks for the joint angles that move a point somewhere, about zero-pitch
twists xi = (w; v) with |w| = 1 (the axis through r = w x v):

* :func:`subproblem1` -- the angle theta with exp(theta xi) p = q;
* :func:`subproblem2` -- the pairs (theta1, theta2) with exp(theta1 xi1) exp(theta2 xi2)
  p = q, for two axes that meet in a point;
* :func:`subproblem3` -- the angles with |exp(theta xi) p - q| = delta;
* :func:`subproblem4` -- the angles that bring p onto the plane n . x = d;
* :func:`subproblem5` -- three cones: p0 + R1 p1 = R2 (p2 + R3 p3) (Elias and Wen);
* :func:`subproblem6` -- two equations, each h . R p about two axes (Elias and Wen);
* :func:`subproblem1_prismatic`, :func:`subproblem3_prismatic` -- the same questions for
  a translation along a unit direction s (the twist (0; s)).

Each returns a :class:`Solutions` list: SymPy expressions for SymPy input (the formula a
student reads), floats otherwise. No solution is an empty list whose ``reason`` says
why; when every angle solves the problem (the point is on the axis) the list holds the
angle 0 and ``free`` is True. Formulas after Murray, Li and Sastry, *A Mathematical
Introduction to Robotic Manipulation* (1994), sec. 3.3; subproblem 4 after Elias and
Wen's IK-Geo (2022).

>>> import numpy as np
>>> z_axis = [0, 0, 1, 0, 0, 0]            # rotation about z through the origin
>>> [round(t, 6) for t in subproblem1(z_axis, [1, 0, 0], [0, 1, 0])]
[1.570796]
>>> import sympy as sp
>>> subproblem1(z_axis, [1, 0, 0], [sp.Rational(1, 2), sp.sqrt(3) / 2, 0])
[pi/3]
"""

import numpy as np
import sympy as sp

from .._checks import (
    as_float_array,
    as_sympy_matrix,
    as_sympy_scalar,
    describe,
    is_symbolic,
)
from .._compiled import cos_sin  # by tan(theta / 2): three times np.cos's speed
from ..tolerances import (
    IK_ACCEPT_TOL,
    IK_DUPLICATE_TOL,
    IK_RANK_TOL,
    IK_ROOT_TOL,
)
from ..tolerances import SUBPROBLEM_TOL as TOL
from ..transforms import _cross, _cross_last, _dot_last
from ._quartic import quartic_roots

__all__ = [
    "Solutions",
    "subproblem1",
    "subproblem2",
    "subproblem3",
    "subproblem4",
    "subproblem5",
    "subproblem6",
    "subproblem1_prismatic",
    "subproblem3_prismatic",
]


class Solutions(list):
    """The solutions of a subproblem: a list of angles (rad), pairs or distances (m).

    Parameters
    ----------
    solutions : iterable
        The solutions: floats, or SymPy expressions for SymPy input.
    reason : str or None
        Why the list is empty; None when it is not.
    free : bool
        True when every angle solves the problem (the list then holds the
        representative 0).

    Examples
    --------
    A list that can also say why it is empty:

    >>> Solutions([0.5])
    [0.5]
    >>> Solutions([], reason="unreachable")
    Solutions([], reason='unreachable')
    >>> Solutions([0.0], free=True)
    [0.0] (every angle: free)
    """

    def __init__(self, solutions=(), reason=None, free=False):
        super().__init__(solutions)
        self.reason = reason
        self.free = free

    def __repr__(self):
        if not self:
            return f"Solutions([], reason={self.reason!r})"
        return super().__repr__() + (" (every angle: free)" if self.free else "")


# ---- input ---------------------------------------------------------------------------


def _symbolic(*values):
    return any(is_symbolic(v) for v in values)


def _twist(twist, name, exact):
    """(w, r): the unit direction and the point w x v of a zero-pitch unit twist."""
    if exact:
        xi = as_sympy_matrix(twist, name, (6, 1))
        w, v = xi[:3, 0], xi[3:, 0]
        norm2, pitch = sp.simplify(w.dot(w)), sp.simplify(w.dot(v))
        if norm2.is_number and norm2 != 1:
            raise ValueError(
                f"{name} must have a unit angular part (a revolute axis), "
                f"got |w|^2 = {norm2}"
            )
        if pitch.is_number and pitch != 0:
            raise ValueError(
                f"{name} must have pitch 0 (w . v = 0), got w . v = {pitch}"
            )
        return w, w.cross(v)
    xi = as_float_array(twist, name)
    if xi.shape != (6,):
        raise ValueError(
            f"{name} must be a twist of shape (6,), ordered [w; v], "
            f"got shape {xi.shape}"
        )
    w, v = xi[:3], xi[3:]
    if abs(np.linalg.norm(w) - 1) > TOL:
        raise ValueError(
            f"{name} must have a unit angular part (a revolute axis), "
            f"got |w| = {np.linalg.norm(w):.6g}"
        )
    if abs(w @ v) > TOL * (1 + np.linalg.norm(v)):
        raise ValueError(
            f"{name} must have pitch 0 (w . v = 0), got w . v = {w @ v:.6g}"
        )
    return w, _cross(w, v)


def _direction(s, name, exact):
    if exact:
        s = as_sympy_matrix(s, name, (3, 1))
        norm2 = sp.simplify(s.dot(s))
        if norm2.is_number and norm2 != 1:
            raise ValueError(
                f"{name} must be a unit direction, got |{name}|^2 = {norm2}"
            )
        return s
    s = _point(s, name, False)
    if abs(np.linalg.norm(s) - 1) > TOL:
        raise ValueError(
            f"{name} must be a unit direction, got |{name}| = {np.linalg.norm(s):.6g}"
        )
    return s


def _point(p, name, exact):
    if exact:
        return as_sympy_matrix(p, name, (3, 1))
    p = as_float_array(p, name)
    if p.shape != (3,):
        raise ValueError(f"{name} must be a point of shape (3,), got {describe(p)}")
    return p


def _distance(delta, name, exact):
    if exact:
        delta = as_sympy_scalar(delta, name)
        if delta.is_negative:
            raise ValueError(f"{name} must be a distance >= 0, got {delta}")
        return delta
    if isinstance(delta, bool) or np.ndim(delta) != 0:
        raise TypeError(
            f"{name} must be one distance (a number, m), got {describe(delta)}"
        )
    delta = float(as_float_array(delta, name))
    if delta < 0:
        raise ValueError(f"{name} must be a distance >= 0, got {delta}")
    return delta


# ---- helpers for both layers ---------------------------------------------------------


def _zero(value, scale, exact):
    """Is a consistency residual zero? Exactly (or undecidable: assumed) or within
    TOL * scale."""
    if exact:
        value = sp.simplify(value)
        return not (value.is_number and value != 0)
    return abs(value) <= TOL * scale


def _sign(value, scale, exact):
    """-1, 0 or 1; a symbolic value that cannot be decided counts as positive."""
    if exact:
        value = sp.simplify(value)
        if value.is_number:
            return int(sp.sign(value))
        return 1
    return 0 if abs(value) <= TOL * scale else int(np.sign(value))


def _atan2(y, x, exact):
    return sp.simplify(sp.atan2(y, x)) if exact else float(np.arctan2(y, x))


def _project(w, u, exact):
    """u without its component along w."""
    return u - w * w.dot(u) if exact else u - w * (w @ u)


def _dot(a, b, exact):
    return sp.simplify(a.dot(b)) if exact else float(a @ b)


def _norm(a, exact):
    return sp.sqrt(_dot(a, a, exact)) if exact else float(np.linalg.norm(a))


def _vector_cross(a, b, exact):
    return a.cross(b) if exact else _cross(a, b)


# ---- batch kernels: float arrays, no checks ------------------------------------------
# The closed-form engines (:mod:`.spherical_wrist`, :mod:`.ur`, :mod:`.stanford`) run
# their steps through these, over a whole batch of poses at once; the scalar
# subproblems below run their numeric case through them too, so each formula is written
# once. Each kernel says how its vectors are laid out: (3, ...) (components first, so
# that products with a fixed axis are one matrix product) or (..., 3).


def _dot_batch(w, v):
    """w . v for a fixed w (3,) and vectors v (3, ...): one matrix product."""
    return (w @ v.reshape(3, -1)).reshape(v.shape[1:])


def sinusoid_angles(A, B, C):
    """The angles theta with A cos(theta) + B sin(theta) = C, the equation every
    closed-form step of one angle comes down to.

    Parameters
    ----------
    A, B, C : array-like, broadcasting to shape (...), any one unit

    Returns
    -------
    phi, half : arrays (...), rad: the angles are phi - half and phi + half, with
        phi = atan2(B, A) and half = atan2(sqrt(A^2 + B^2 - C^2), C)
    excess : array (...), A^2 + B^2 - C^2: negative where no angle solves it (``half``
        is then that of excess 0)
    radius2 : array (...), A^2 + B^2: 0 where every angle or none solves it
    """
    radius2 = A**2 + B**2
    excess = radius2 - C**2
    phi = np.arctan2(B, A)
    half = np.arctan2(np.sqrt(np.maximum(excess, 0.0)), C)
    return phi, half, excess, radius2


def plane_angles(w, n, h, x):
    """Subproblem 4 over a batch: the angles about the unit axis w through the origin
    that bring the points x onto the plane n . y = h.

    With A = n . x - (w . x)(w . n), B = (n x w) . x and C = h - (w . x)(n . w), the
    angles solve A cos + B sin = C (:func:`sinusoid_angles`).

    Parameters
    ----------
    w, n : array, shape (3,), unit axis direction and unit plane normal
    h : float or array (...), the plane's offset (m)
    x : array, shape (3, ...), points (m), laid out components first

    Returns
    -------
    phi, half, excess, radius2 : arrays (...), as :func:`sinusoid_angles` returns them
        (rad, rad, m^2, m^2): the angles are phi -+ half
    """
    along = _dot_batch(w, x)
    A = _dot_batch(n, x) - along * (w @ n)
    B = _dot_batch(_cross(n, w), x)
    C = h - along * (n @ w)
    return sinusoid_angles(A, B, C)


def distance_angles(w, u, v, delta2):
    """Subproblem 3 in the plane across the unit axis w.

    Parameters
    ----------
    w : array, shape (3,), unit axis direction
    u, v : array, shape (3,), vectors perpendicular to w (m)
    delta2 : array (...), squared distances across the axis (m^2)

    Returns
    -------
    theta0 : float, rad, the angle about w from u to v
    cosine : array (...), (|u|^2 + |v|^2 - delta2) / (2 |u| |v|): the angles are
        theta0 -+ arccos(cosine); a cosine beyond +-1 means no angle reaches delta
    """
    lu, lv = np.linalg.norm(u), np.linalg.norm(v)
    cosine = (lu**2 + lv**2 - delta2) / (2 * lu * lv)
    return np.arctan2(_cross(u, v) @ w, u @ v), cosine


def rotation_angles(w, a, b):
    """Subproblem 1 over a batch: the angle about the unit axis w (through the origin)
    that turns a towards b, atan2(w . (a' x b'), a' . b') with a', b' their parts
    across w.

    Parameters
    ----------
    w : array, shape (3,), unit axis direction
    a, b : arrays, shapes broadcasting to (..., 3), vectors laid out components last

    Returns
    -------
    theta : array (...), rad in (-pi, pi]; 0 where a' or b' is 0 (every angle)
    """
    a_ = a - w * (a @ w)[..., None]
    b_ = b - w * (b @ w)[..., None]
    return np.arctan2(np.cross(a_, b_) @ w, np.sum(a_ * b_, axis=-1))


def meeting_points(w1, w2, x, y):
    """Subproblem 2 over a batch, for two axes through the origin: the points z with
    z . w2 = x . w2, z . w1 = y . w1 and |z| = |x|, where the circle of x about w2
    meets the circle of y about w1 (then exp(theta2 w2) x = z = exp(-theta1 w1) y).

    z = alpha w1 + beta w2 + gamma (w1 x w2), with alpha, beta from the two planes and
    gamma^2 = (|x|^2 - alpha^2 - beta^2 - 2 alpha beta w1 . w2) / |w1 x w2|^2.

    Parameters
    ----------
    w1, w2 : array, shape (3,), unit directions of two axes that are not parallel
    x, y : arrays, shapes broadcasting to (..., 3), vectors laid out components last

    Returns
    -------
    z : array (..., 2, 3), the two points, gamma = -|gamma| first
    gamma2 : array (...): negative where the circles do not meet (z then takes
        gamma = 0)
    """
    c12 = w1 @ w2
    n = np.cross(w1, w2)
    xw2, yw1 = x @ w2, y @ w1
    alpha = (c12 * xw2 - yw1) / (c12**2 - 1)
    beta = (c12 * yw1 - xw2) / (c12**2 - 1)
    gamma2 = (np.sum(x * x, -1) - alpha**2 - beta**2 - 2 * alpha * beta * c12) / (n @ n)
    gamma = np.sqrt(np.maximum(gamma2, 0.0))[..., None] * np.array([-1.0, 1.0])
    z = alpha[..., None, None] * w1 + beta[..., None, None] * w2 + gamma[..., None] * n
    return z, gamma2


# ---- subproblems 5 and 6: two equations, each linear in two unit vectors -------------
# Both come down to A1 x1 + A2 x2 = d with x_i = (cos theta_i, sin theta_i): two
# equations, each a sinusoid in theta1 plus one in theta2 (Elias and Wen 2022).


def _cone_terms(k, p):
    """R(k, theta) p = a + b cos(theta) + e sin(theta) for unit axes k and vectors p,
    both (..., 3): returns a = k (k . p), b = p - a, e = k x p, each (..., 3)."""
    a = k * _dot_last(k, p)[..., None]
    return a, p - a, _cross_last(k, p)


def _angle_about(k, a, b):
    """The angle about the unit axes k (..., 3) turning a towards b (..., 3), rad; 0
    where a or b is on the axis."""
    a_ = a - k * _dot_last(a, k)[..., None]
    b_ = b - k * _dot_last(b, k)[..., None]
    return np.arctan2(_dot_last(_cross_last(a_, b_), k), _dot_last(a_, b_))


def _det2(A):
    return A[..., 0, 0] * A[..., 1, 1] - A[..., 0, 1] * A[..., 1, 0]


def _unit(theta):
    return np.stack(cos_sin(theta), -1)


def _mv(A, x):
    """A x for stacks of 2x2 matrices (..., 2, 2) and vectors (..., 2) (written out:
    einsum on a trailing 2x2 is ten times slower)."""
    x0, x1 = x[..., 0], x[..., 1]
    return np.stack(
        [A[..., 0, 0] * x0 + A[..., 0, 1] * x1, A[..., 1, 0] * x0 + A[..., 1, 1] * x1],
        -1,
    )


def _two_roots(A, B, C):
    """The two angles of A cos + B sin = C, (..., 2), and whether they are real
    (...): the excess A^2 + B^2 - C^2 clipped by IK_RANK_TOL."""
    phi, half, excess, radius2 = sinusoid_angles(A, B, C)
    ok = (excess >= -IK_RANK_TOL * np.maximum(radius2, C * C)) & (radius2 > 0)
    return np.stack([phi - half, phi + half], -1), ok


def _quartic_candidates(A1, A2, d):
    """The candidates of A1 x1 + A2 x2 = d for A1 of rank 2: x1 = adj(A1) (d - A2 x2) /
    det(A1) with |x1| = 1 is a trigonometric polynomial of degree 2 in theta2, a
    quartic in z = exp(i theta2) (:func:`~screwkit.ik._quartic.quartic_roots`; its
    roots on the unit circle, polished by Newton). Returns angles (..., 4, 2), a mask
    (..., 4) and where theta2 is free (...)."""
    det = _det2(A1)
    adj = np.stack(
        [
            np.stack([A1[..., 1, 1], -A1[..., 0, 1]], -1),
            np.stack([-A1[..., 1, 0], A1[..., 0, 0]], -1),
        ],
        -2,
    )
    f = _mv(adj, d)
    G = -adj @ A2
    H = np.swapaxes(G, -1, -2) @ G
    fG = _mv(np.swapaxes(G, -1, -2), f)
    c0 = np.sum(f * f, -1) + (H[..., 0, 0] + H[..., 1, 1]) / 2 - det**2
    c1, s1 = 2 * fG[..., 0], 2 * fG[..., 1]
    c2, s2 = (H[..., 0, 0] - H[..., 1, 1]) / 2, H[..., 0, 1]
    size = np.abs(np.stack([c0, c1, s1, c2, s2], -1)).max(-1) + np.finfo(float).tiny
    lead = (c2 - 1j * s2) / 2
    quartic = np.abs(lead) > IK_RANK_TOL * size
    z = quartic_roots(
        np.stack(
            [
                np.where(quartic, lead, 1.0),
                (c1 - 1j * s1) / 2,
                c0 + 0j,
                (c1 + 1j * s1) / 2,
                (c2 + 1j * s2) / 2,
            ],
            -1,
        )
    )
    # degree 1 (c2 = s2 = 0): c0 + c1 cos + s1 sin = 0, two roots
    linear, linear_ok = _two_roots(c1, s1, -c0)
    theta2 = np.where(quartic[..., None], np.angle(z), np.concatenate([linear] * 2, -1))
    no = np.zeros_like(linear_ok)
    ok = np.where(
        quartic[..., None],
        np.abs(np.abs(z) - 1) < IK_ROOT_TOL,
        np.stack([linear_ok, linear_ok, no, no], -1),
    )
    # no theta2 in it (A2's block vanishes after elimination): every theta2 or none
    flat = np.abs(np.stack([c1, s1, c2, s2], -1)).max(-1) <= IK_RANK_TOL * (
        np.sum(f * f, -1) + det**2 + np.finfo(float).tiny
    )
    free = flat & (np.abs(c0) <= IK_RANK_TOL * (np.sum(f * f, -1) + det**2))
    theta2 = np.where(flat[..., None], 0.0, theta2)
    ok = np.where(flat[..., None], free[..., None] & [True, False, False, False], ok)
    # a step of Newton on the trigonometric polynomial
    c, s = cos_sin(theta2)
    cc, ss = c * c - s * s, 2 * s * c
    coef = [x[..., None] for x in (c0, c1, s1, c2, s2)]
    P = coef[0] + coef[1] * c + coef[2] * s + coef[3] * cc + coef[4] * ss
    dP = -coef[1] * s + coef[2] * c - 2 * coef[3] * ss + 2 * coef[4] * cc
    steep = np.abs(dP) > IK_RANK_TOL * size[..., None]
    theta2 = theta2 - np.where(steep, P / np.where(steep, dP, 1.0), 0.0)
    e = f[..., None, :] + _mv(G[..., None, :, :], _unit(theta2))
    sign = np.where(det < 0, -1.0, 1.0)[..., None]
    theta1 = np.arctan2(sign * e[..., 1], sign * e[..., 0])
    return np.stack([theta1, theta2], -1), ok, free


def _rank1_candidates(A1, A2, d, size):
    """The candidates of A1 x1 + A2 x2 = d for A1 of rank 1 or 0: with u across A1's
    columns, u . A2 x2 = u . d gives theta2 (two angles), then v . A1 x1 =
    v . (d - A2 x2) along them gives theta1 (two each). Returns angles (..., 4, 2), a
    mask (..., 4) and where an angle is free (...): a continuum."""
    columns = np.swapaxes(A1, -1, -2)  # (..., 2 columns, 2)
    lengths = np.linalg.norm(columns, axis=-1)
    big = np.take_along_axis(columns, lengths.argmax(-1)[..., None, None], -2)[
        ..., 0, :
    ]
    norm = np.linalg.norm(big, axis=-1)
    zero1 = norm <= IK_RANK_TOL * size
    v = np.where(
        zero1[..., None], [1.0, 0.0], big / np.where(zero1, 1.0, norm)[..., None]
    )
    u = np.stack([-v[..., 1], v[..., 0]], -1)
    uA2 = np.einsum("...i,...ij->...j", u, A2)
    ud = np.sum(u * d, -1)
    theta2, ok2 = _two_roots(uA2[..., 0], uA2[..., 1], ud)
    flat2 = np.linalg.norm(uA2, axis=-1) <= IK_RANK_TOL * size
    free = flat2 & (np.abs(ud) <= IK_RANK_TOL * size)
    theta2 = np.where(flat2[..., None], 0.0, theta2)
    ok2 = np.where(flat2, free, ok2)
    vA1 = np.einsum("...i,...ij->...j", v, A1)  # (..., 2)
    rest = np.sum(
        v[..., None, :]
        * (d[..., None, :] - np.einsum("...ij,...kj->...ki", A2, _unit(theta2))),
        -1,
    )  # (..., 2)
    theta1, ok1 = _two_roots(vA1[..., None, 0], vA1[..., None, 1], rest)  # (..., 2, 2)
    free = free | zero1
    theta1 = np.where(zero1[..., None, None], 0.0, theta1)
    ok1 = np.where(zero1[..., None], True, ok1)
    angles = np.stack(
        [theta1.reshape(theta1.shape[:-2] + (4,)), np.repeat(theta2, 2, -1)], -1
    )
    ok = np.repeat(ok1 & ok2[..., None], 2, -1)
    return angles, ok, free


def sinusoid_pairs(A1, A2, d):
    """Subproblem 6's core over a batch: the angle pairs with A1 x1 + A2 x2 = d, where
    x_i = (cos theta_i, sin theta_i): two equations, each a sinusoid in theta1 plus one
    in theta2.

    The unknown whose block is better conditioned is eliminated: for a block of rank
    2, x1 = adj(A1) (d - A2 x2) / det(A1) and |x1| = 1 is a quartic in
    z = exp(i theta2); for rank 1 (axes that meet or are parallel make it so), the two
    equations are solved one after the other (:data:`~screwkit.tolerances.IK_RANK_TOL`
    decides). Every candidate (a root on the unit circle) is polished by a step of
    Newton on both equations and kept when its residual is below
    :data:`~screwkit.tolerances.IK_ACCEPT_TOL` (relative to the equations' size);
    duplicates are dropped.

    Parameters
    ----------
    A1, A2 : array, shape (..., 2, 2), the coefficients of x1 and x2 (any one unit)
    d : array, shape (..., 2), the right-hand sides (the same unit)

    Returns
    -------
    theta : array (..., 4, 2), rad in (-pi, pi]: (theta1, theta2) of up to four
        solutions
    ok : array of bool (..., 4): which rows are solutions
    free : array of bool (...): True where an angle is free (a continuum of solutions;
        the rows then hold the representatives with that angle 0)
    """
    A1, A2, d = np.broadcast_arrays(A1, A2, d[..., None])
    d = d[..., 0]
    size = 1.0 + np.sqrt(
        np.sum(A1**2, (-1, -2)) + np.sum(A2**2, (-1, -2)) + np.sum(d**2, -1)
    )
    r1 = np.abs(_det2(A1)) / (np.sum(A1**2, (-1, -2)) + np.finfo(float).tiny)
    r2 = np.abs(_det2(A2)) / (np.sum(A2**2, (-1, -2)) + np.finfo(float).tiny)
    swap = r2 > r1
    Aa = np.where(swap[..., None, None], A2, A1)
    Ab = np.where(swap[..., None, None], A1, A2)
    theta, ok, free = _quartic_candidates(Aa, Ab, d)
    rank1 = np.maximum(r1, r2) <= IK_RANK_TOL
    if np.any(rank1):
        low, low_ok, low_free = _rank1_candidates(Aa, Ab, d, size)
        theta = np.where(rank1[..., None, None], low, theta)
        ok = np.where(rank1[..., None], low_ok, ok)
        free = np.where(rank1, low_free, free)
    theta = np.where(swap[..., None, None], theta[..., ::-1], theta)
    # the candidates kept so far (about half: roots off the unit circle are not), each
    # polished by a step of Newton on both equations and checked
    kept = np.nonzero(ok)
    pose = kept[:-1]
    A1, A2, d, size = A1[pose], A2[pose], d[pose], size[pose]
    angles = theta[kept]
    x1, x2 = _unit(angles[:, 0]), _unit(angles[:, 1])
    F = _mv(A1, x1) + _mv(A2, x2) - d
    j1 = _mv(A1, x1[:, ::-1] * [-1, 1])  # the Jacobian's columns
    j2 = _mv(A2, x2[:, ::-1] * [-1, 1])
    det = j1[:, 0] * j2[:, 1] - j2[:, 0] * j1[:, 1]
    regular = np.abs(det) > IK_RANK_TOL * size**2
    det = np.where(regular, det, 1.0)
    step = np.stack(  # Cramer's rule
        [
            (j2[:, 1] * F[:, 0] - j2[:, 0] * F[:, 1]) / det,
            (j1[:, 0] * F[:, 1] - j1[:, 1] * F[:, 0]) / det,
        ],
        -1,
    )
    angles = angles - np.where(regular[:, None], step, 0.0)
    x1, x2 = _unit(angles[:, 0]), _unit(angles[:, 1])
    residual = np.linalg.norm(_mv(A1, x1) + _mv(A2, x2) - d, axis=-1)
    theta[kept] = angles
    ok[kept] = residual <= IK_ACCEPT_TOL * size
    theta = np.pi - np.mod(np.pi - theta, 2 * np.pi)
    for i in range(1, 4):  # a double root found twice is one solution
        for j in range(i):
            gap = np.abs(theta[..., i, :] - theta[..., j, :])  # both in (-pi, pi]
            gap = np.minimum(gap, 2 * np.pi - gap)
            ok[..., i] &= ~(ok[..., j] & np.all(gap < IK_DUPLICATE_TOL, -1))
    return theta, ok, free


def three_cones(k1, k2, k3, p0, p1, p2, p3):
    """Subproblem 5 over a batch: the angles with p0 + R(k1, theta1) p1 =
    R(k2, theta2) (p2 + R(k3, theta3) p3), rotations about unit axes through the
    origin.

    With v1 = p0 + R1 p1 and v3 = p2 + R3 p3, a theta2 exists exactly when
    k2 . v1 = k2 . v3 and |v1| = |v3|: two equations, each a sinusoid in theta1 plus
    one in theta3 (:func:`sinusoid_pairs`); theta2 is then subproblem 1 from v3 to v1.

    Parameters
    ----------
    k1, k2, k3 : array, shape (..., 3), unit axes
    p0, p1, p2, p3 : array, shape (..., 3), vectors (m)

    Returns
    -------
    theta : array (..., 4, 3), rad: (theta1, theta2, theta3) of up to four solutions
    ok : array of bool (..., 4): which rows are solutions
    free : array of bool (..., 4): True where an angle is free (a continuum; the row
        holds the representative with that angle 0)
    """
    k1, k2, k3, p0, p1, p2, p3 = np.broadcast_arrays(k1, k2, k3, p0, p1, p2, p3)
    size = 1.0 + sum(np.sqrt(_dot_last(p, p)) for p in (p0, p1, p2, p3))
    a1, b1, e1 = _cone_terms(k1, p1)
    a3, b3, e3 = _cone_terms(k3, p3)
    o1, o3 = p0 + a1, p2 + a3
    dot = _dot_last
    A1 = np.stack(
        [
            np.stack([dot(k2, b1), dot(k2, e1)], -1),
            np.stack([dot(o1, b1), dot(o1, e1)], -1) * 2 / size[..., None],
        ],
        -2,
    )
    A3 = -np.stack(
        [
            np.stack([dot(k2, b3), dot(k2, e3)], -1),
            np.stack([dot(o3, b3), dot(o3, e3)], -1) * 2 / size[..., None],
        ],
        -2,
    )
    d = np.stack(
        [
            dot(k2, o3 - o1),
            (dot(o3, o3) + dot(b3, b3) - dot(o1, o1) - dot(b1, b1)) / size,
        ],
        -1,
    )
    theta13, ok, free = sinusoid_pairs(A1, A3, d)
    c, s = cos_sin(theta13)
    c1, c3, s1, s3 = c[..., 0], c[..., 1], s[..., 0], s[..., 1]
    v1 = o1[..., None, :] + b1[..., None, :] * c1[..., None]
    v1 = v1 + e1[..., None, :] * s1[..., None]
    v3 = o3[..., None, :] + b3[..., None, :] * c3[..., None]
    v3 = v3 + e3[..., None, :] * s3[..., None]
    kk = k2[..., None, :]
    theta2 = _angle_about(kk, v3, v1)
    v3_across = v3 - kk * _dot_last(v3, kk)[..., None]
    across = np.sqrt(_dot_last(v3_across, v3_across))
    free = free[..., None] | (across <= IK_RANK_TOL * size[..., None])
    theta = np.stack([theta13[..., 0], theta2, theta13[..., 1]], -1)
    return theta, ok, free & ok


def two_pairs(h, k, p, d):
    """Subproblem 6 over a batch: the angles with
    h1 . R(k1, theta1) p1 + h2 . R(k2, theta2) p2 = d1 and
    h3 . R(k3, theta1) p3 + h4 . R(k4, theta2) p4 = d2.

    Each term h . R(k, theta) p = h . a + (h . b) cos(theta) + (h . e) sin(theta)
    (a, b, e: the parts of p along k, across it, and k x p), so the two equations are
    A1 x1 + A2 x2 = d' (:func:`sinusoid_pairs`).

    Parameters
    ----------
    h, k, p : array, shape (..., 4, 3): the four terms' vectors, unit axes and vectors
    d : array, shape (..., 2): the right-hand sides

    Returns
    -------
    theta, ok, free : as :func:`sinusoid_pairs` returns them
    """
    h, k, p = np.broadcast_arrays(h, k, p)
    a, b, e = _cone_terms(k, p)
    hb, he, ha = (_dot_last(h, x) for x in (b, e, a))  # (..., 4)
    A1 = np.stack(
        [
            np.stack([hb[..., 0], he[..., 0]], -1),
            np.stack([hb[..., 2], he[..., 2]], -1),
        ],
        -2,
    )
    A2 = np.stack(
        [
            np.stack([hb[..., 1], he[..., 1]], -1),
            np.stack([hb[..., 3], he[..., 3]], -1),
        ],
        -2,
    )
    rhs = d - np.stack([ha[..., 0] + ha[..., 1], ha[..., 2] + ha[..., 3]], -1)
    return sinusoid_pairs(A1, A2, rhs)


# ---- the subproblems -----------------------------------------------------------------


def subproblem1(twist, p, q):
    """The angle theta of the rotation about ``twist`` that takes the point p to q.

    With r on the axis, u = p - r and v = q - r, and u', v' their parts perpendicular to
    w: theta = atan2(w . (u' x v'), u' . v'). Solvable when w . u = w . v
    and |u'| = |v'|.

    Parameters
    ----------
    twist : array-like, shape (6,)
        A zero-pitch unit twist [w; v], |w| = 1, w . v = 0 (SymPy entries give SymPy
        answers).
    p, q : array-like, shape (3,)
        Points (m).

    Returns
    -------
    Solutions
        [theta] (rad), or [] with ``reason``; ``free`` if p is on the axis.

    Examples
    --------
    Turning x onto y about z takes a quarter turn; SymPy entries give it exactly.

    >>> z_axis = sp.Matrix([0, 0, 1, 0, 0, 0])
    >>> subproblem1(z_axis, [1, 0, 0], [0, 1, 0])
    [pi/2]
    >>> subproblem1(z_axis, [1, 0, 0], [0, 2, 0]).reason
    'p and q are at different distances from the axis'
    """
    exact = _symbolic(twist, p, q)
    w, r = _twist(twist, "twist", exact)
    p, q = _point(p, "p", exact), _point(q, "q", exact)
    return _subproblem1(w, r, p, q, exact)


def _subproblem1(w, r, p, q, exact):
    u, v = p - r, q - r
    scale = 1.0 if exact else 1.0 + float(np.linalg.norm(u) + np.linalg.norm(v))
    if not _zero(_dot(w, u, exact) - _dot(w, v, exact), scale, exact):
        return Solutions(
            reason="p and q lie in different planes perpendicular to the axis "
            "(w . (p - q) is not 0)"
        )
    u1, v1 = _project(w, u, exact), _project(w, v, exact)
    if not _zero(_dot(u1, u1, exact) - _dot(v1, v1, exact), scale * scale, exact):
        return Solutions(reason="p and q are at different distances from the axis")
    if _sign(_dot(u1, u1, exact), scale * scale, exact) == 0:
        return Solutions([sp.S.Zero if exact else 0.0], free=True)
    if not exact:
        return Solutions([float(rotation_angles(w, u, v))])
    return Solutions(
        [
            _atan2(
                _dot(w, _vector_cross(u1, v1, exact), exact), _dot(u1, v1, exact), exact
            )
        ]
    )


def subproblem2(twist1, twist2, p, q):
    """The angle pairs (theta1, theta2) with exp(theta1 xi1) exp(theta2 xi2) p = q.

    The axes must meet in a point r. The middle point z = exp(theta2 xi2) p =
    exp(-theta1 xi1) q lies on both circles: z = r + alpha w1 + beta w2 + gamma
    (w1 x w2), with alpha, beta from w1 . (z - r) = w1 . (q - r) and
    w2 . (z - r) = w2 . (p - r), and gamma^2 = (|u|^2 - alpha^2 - beta^2 - 2 alpha beta
    w1 . w2) / |w1 x w2|^2 (u = p - r). Two pairs for gamma^2 > 0, one for gamma^2 = 0,
    none for gamma^2 < 0.

    Parameters
    ----------
    twist1, twist2 : array-like, shape (6,)
        Zero-pitch unit twists [w; v] whose axes meet in one point (else a
        ``ValueError``).
    p, q : array-like, shape (3,)
        Points (m).

    Returns
    -------
    Solutions
        A list of (theta1, theta2) pairs (rad), or [] with ``reason``.

    Examples
    --------
    x onto z by a turn about z, then one about x: z first takes x to +-y, and a
    quarter turn about x takes +-y to z.

    >>> x_axis = sp.Matrix([1, 0, 0, 0, 0, 0])
    >>> z_axis = sp.Matrix([0, 0, 1, 0, 0, 0])
    >>> subproblem2(x_axis, z_axis, [1, 0, 0], [0, 0, 1])
    [(-pi/2, -pi/2), (pi/2, pi/2)]
    """
    exact = _symbolic(twist1, twist2, p, q)
    w1, r1 = _twist(twist1, "twist1", exact)
    w2, r2 = _twist(twist2, "twist2", exact)
    p, q = _point(p, "p", exact), _point(q, "q", exact)
    n = _vector_cross(w1, w2, exact)
    n2 = _dot(n, n, exact)
    if _sign(n2, 1.0, exact) == 0:
        raise ValueError(
            "twist1 and twist2 must have axes that meet in one point, got parallel axes"
        )
    gap = _dot(r2 - r1, n, exact)
    if not _zero(gap, (1.0 if exact else 1.0 + float(np.linalg.norm(r2 - r1))), exact):
        raise ValueError(
            "twist1 and twist2 must have axes that meet in one point, got skew "
            f"axes {float(abs(gap)) / float(sp.sqrt(n2)):.6g} m apart"
        )
    # the common point: r1 + t w1 on the second axis
    c12 = _dot(w1, w2, exact)
    d = r2 - r1
    t = (_dot(d, w1, exact) - c12 * _dot(d, w2, exact)) / (1 - c12 * c12)
    r = r1 + w1 * t
    u, v = p - r, q - r
    if exact:
        denominator = c12 * c12 - 1
        alpha = (c12 * _dot(w2, u, exact) - _dot(w1, v, exact)) / denominator
        beta = (c12 * _dot(w1, v, exact) - _dot(w2, u, exact)) / denominator
        gamma2 = (_dot(u, u, exact) - alpha**2 - beta**2 - 2 * alpha * beta * c12) / n2
        gamma2 = sp.simplify(gamma2)
        sign = _sign(gamma2, 1, exact)
        middle = r + w1 * alpha + w2 * beta
        roots = [sp.S.Zero] if sign == 0 else [sp.sqrt(gamma2), -sp.sqrt(gamma2)]
        points = [middle + n * root for root in roots]
    else:  # the batch kernel, on one pose: z - r for gamma = -|gamma|, +|gamma|
        (below, above), gamma2 = meeting_points(w1, w2, u, v)
        scale = 1.0 + float(np.linalg.norm(u) + np.linalg.norm(v))
        sign = _sign(float(gamma2), scale * scale, exact)
        points = [r + (below + above) / 2] if sign == 0 else [r + above, r + below]
    if sign < 0:
        return Solutions(
            reason="the circles of p about axis 2 and of q about axis 1 do not "
            "meet (gamma^2 < 0)"
        )
    pairs, free = [], False
    for z in points:
        theta2 = _subproblem1(w2, r, p, z, exact)
        theta1 = _subproblem1(w1, r, z, q, exact)
        if not theta1 or not theta2:
            return Solutions(
                reason="p and q are at different distances from the common point"
            )
        free = free or theta1.free or theta2.free
        pairs.append((theta1[0], theta2[0]))
    return Solutions(pairs, free=free)


def subproblem3(twist, p, q, delta):
    """The angles theta with |exp(theta xi) p - q| = delta.

    In the plane perpendicular to w: delta'^2 = delta^2 - (w . (p - q))^2 and
    theta = theta0 +- acos((|u'|^2 + |v'|^2 - delta'^2) / (2 |u'| |v'|)), theta0 being
    the subproblem-1 angle from u' to v'. Two, one or no solutions.

    Parameters
    ----------
    twist : array-like, shape (6,)
        The rotation's axis, as for :func:`subproblem1`.
    p : array-like, shape (3,)
        The point turned about the axis (m).
    q : array-like, shape (3,)
        The point it must end at distance delta from (m).
    delta : float
        The distance, >= 0 (m).

    Returns
    -------
    Solutions
        Angles (rad), or [] with ``reason``; ``free`` if the distance does not depend
        on the angle and equals delta.

    Examples
    --------
    Turning x about z to sqrt(2) from where it starts: 2 - 2 cos(theta) = 2, so
    theta = +-pi/2.

    >>> z_axis = sp.Matrix([0, 0, 1, 0, 0, 0])
    >>> subproblem3(z_axis, [1, 0, 0], [1, 0, 0], sp.sqrt(2))
    [-pi/2, pi/2]
    """
    exact = _symbolic(twist, p, q, delta)
    w, r = _twist(twist, "twist", exact)
    p, q = _point(p, "p", exact), _point(q, "q", exact)
    delta = _distance(delta, "delta", exact)
    u1, v1 = _project(w, p - r, exact), _project(w, q - r, exact)
    height = _dot(w, p - q, exact)
    delta2 = delta**2 - height**2
    lu, lv = _norm(u1, exact), _norm(v1, exact)
    scale = 1.0 if exact else 1.0 + lu + lv + abs(height) + delta
    if (
        _sign(lu * lv, scale * scale, exact) == 0
    ):  # the distance does not depend on theta
        constant = lu**2 + lv**2 + height**2 - delta**2
        if _zero(constant, scale * scale, exact):
            return Solutions([sp.S.Zero if exact else 0.0], free=True)
        return Solutions(
            reason="p or q is on the axis, so the distance stays "
            f"{_fmt(sp.sqrt(lu**2 + lv**2 + height**2))} m"
        )
    if exact:
        theta0 = _atan2(
            _dot(w, _vector_cross(u1, v1, exact), exact), _dot(u1, v1, exact), exact
        )
        cosine = (lu**2 + lv**2 - delta2) / (2 * lu * lv)
    else:
        theta0, cosine = (float(x) for x in distance_angles(w, u1, v1, delta2))
    if exact:
        cosine = sp.simplify(cosine)
        outside = cosine.is_number and abs(cosine) > 1
        touching = cosine.is_number and abs(cosine) == 1
    else:
        outside = abs(cosine) > 1 + TOL
        touching = abs(abs(cosine) - 1) <= TOL
        cosine = min(1.0, max(-1.0, cosine))
    if outside:
        closest = sp.sqrt((lu - lv) ** 2 + height**2)
        farthest = sp.sqrt((lu + lv) ** 2 + height**2)
        return Solutions(
            reason=f"delta = {_fmt(delta)} m is outside the distances the rotation "
            f"reaches, {_fmt(closest)} to {_fmt(farthest)} m"
        )
    beta = sp.acos(cosine) if exact else float(np.arccos(cosine))
    if touching:
        return Solutions([sp.simplify(theta0 + beta) if exact else theta0 + beta])
    both = [theta0 - beta, theta0 + beta]
    return Solutions([sp.simplify(t) for t in both] if exact else both)


def subproblem4(twist, p, normal, d):
    """The angles theta that bring p onto the plane normal . x = d:
    normal . exp(theta xi) p = d.

    With u = p - r: normal . exp(theta xi) p = A cos(theta) + B sin(theta) + C, where
    A = n . u', B = n . (w x u), C = n . r + (n . w)(w . u). So
    theta = atan2(B, A) +- acos((d - C) / sqrt(A^2 + B^2)).

    Parameters
    ----------
    twist : array-like, shape (6,)
        The axis of the rotation (see :func:`subproblem1`).
    p : array-like, shape (3,)
        The point brought onto the plane (m).
    normal : array-like, shape (3,)
        The plane's unit normal.
    d : float
        The plane's offset along the normal (m).

    Returns
    -------
    Solutions
        Angles (rad), or [] with ``reason``; ``free`` if p's circle lies in the plane.

    Examples
    --------
    x turned about z reaches the plane y = 1/2 where sin(theta) = 1/2:

    >>> z_axis = sp.Matrix([0, 0, 1, 0, 0, 0])
    >>> subproblem4(z_axis, [1, 0, 0], [0, 1, 0], sp.Rational(1, 2))
    [pi/6, 5*pi/6]
    """
    exact = _symbolic(twist, p, normal, d)
    w, r = _twist(twist, "twist", exact)
    p = _point(p, "p", exact)
    n = _direction(normal, "normal", exact)
    if exact:
        d = as_sympy_scalar(d, "d")
    elif isinstance(d, bool) or np.ndim(d) != 0:
        raise TypeError(f"d must be one number (m), got {describe(d)}")
    else:
        d = float(as_float_array(d, "d"))
    u = p - r
    if not exact:
        return _subproblem4_numeric(w, r, u, n, d)
    A = _dot(n, _project(w, u, exact), exact)
    B = _dot(n, _vector_cross(w, u, exact), exact)
    C = _dot(n, r, exact) + _dot(n, w, exact) * _dot(w, u, exact)
    radius2 = A**2 + B**2
    scale = 1.0
    if _sign(radius2, scale * scale, exact) == 0:
        if _zero(d - C, scale, exact):
            return Solutions([sp.S.Zero if exact else 0.0], free=True)
        return Solutions(
            reason=f"the circle of p stays at n . x = {_fmt(C)}, not {_fmt(d)}"
        )
    excess = radius2 - (d - C) ** 2
    sign = _sign(excess, scale * scale, exact)
    if sign < 0:
        return Solutions(
            reason=f"the circle of p spans n . x from {_fmt(C - sp.sqrt(radius2))} "
            f"to {_fmt(C + sp.sqrt(radius2))}, not {_fmt(d)}"
        )
    phi = _atan2(B, A, exact)
    half = sp.atan2(sp.sqrt(sp.simplify(excess)), d - C)
    angles = [phi] if sign == 0 else [phi - half, phi + half]
    return Solutions([sp.simplify(t) for t in angles])


def _subproblem4_numeric(w, r, u, n, d):
    """subproblem4 for floats, through the batch kernel :func:`plane_angles`."""
    phi, half, excess, radius2 = (float(x) for x in plane_angles(w, n, d - n @ r, u))
    C = float(
        n @ r + (n @ w) * (w @ u)
    )  # the height of the circle's centre, for the reasons
    scale = 1.0 + float(np.linalg.norm(u)) + abs(d) + abs(C)
    if _sign(radius2, scale * scale, False) == 0:
        if _zero(d - C, scale, False):
            return Solutions([0.0], free=True)
        return Solutions(
            reason=f"the circle of p stays at n . x = {_fmt(C)}, not {_fmt(d)}"
        )
    sign = _sign(excess, scale * scale, False)
    if sign < 0:
        radius = float(np.sqrt(radius2))
        return Solutions(
            reason=f"the circle of p spans n . x from {_fmt(C - radius)} "
            f"to {_fmt(C + radius)}, not {_fmt(d)}"
        )
    return Solutions([phi + half] if sign == 0 else [phi - half, phi + half])


def subproblem5(k1, k2, k3, p0, p1, p2, p3):
    """The angle triples with
    p0 + R(k1, theta1) p1 = R(k2, theta2) (p2 + R(k3, theta3) p3) (Elias and Wen's
    subproblem 5, three cones), rotations about axes through the origin.

    Up to four solutions: k2 . (p0 + R1 p1) = k2 . (p2 + R3 p3) and the equal
    lengths ``|p0 + R1 p1| = |p2 + R3 p3|`` are two equations, each a sinusoid in
    theta1 plus one in theta3, which eliminate to a quartic; theta2 then turns
    p2 + R3 p3 onto p0 + R1 p1 (subproblem 1). Floats only.

    Parameters
    ----------
    k1, k2, k3 : array-like, shape (3,)
        Unit axis directions.
    p0, p1, p2, p3 : array-like, shape (3,)
        Vectors (m).

    Returns
    -------
    Solutions
        (theta1, theta2, theta3) triples (rad, in (-pi, pi]), or [] with ``reason``;
        ``free`` when an angle is free (a continuum; that angle is 0 in the list).

    Examples
    --------
    p0 made from known angles (0.3, -0.5, 1.0) about z, x and y: the triple is
    among the solutions found.

    >>> from screwkit.transforms import rotx, roty, rotz
    >>> x, y, z = np.eye(3)
    >>> p0 = rotx(-0.5) @ (y + roty(1.0) @ z) - rotz(0.3) @ x
    >>> found = subproblem5(z, x, y, p0, x, y, z)
    >>> any(np.allclose(t, (0.3, -0.5, 1.0)) for t in found)
    True
    """
    k = [_direction(v, name, False) for v, name in ((k1, "k1"), (k2, "k2"), (k3, "k3"))]
    p = [_point(v, f"p{i}", False) for i, v in enumerate((p0, p1, p2, p3))]
    theta, ok, free = three_cones(*k, *p)
    if not ok.any():
        return Solutions(
            reason="the circles of p0 + R(k1, theta1) p1 and p2 + R(k3, theta3) p3 "
            "never share a height along k2 and a distance from the origin"
        )
    return Solutions(
        [tuple(float(a) for a in row) for row in theta[ok]], free=bool(free[ok].any())
    )


def subproblem6(h, k, p, d):
    """The angle pairs with h1 . R(k1, theta1) p1 + h2 . R(k2, theta2) p2 = d1 and
    h3 . R(k3, theta1) p3 + h4 . R(k4, theta2) p4 = d2 (Elias and Wen's subproblem 6).

    Each term is h . a + (h . b) cos(theta) + (h . e) sin(theta) (a, b: the parts of p
    along and across k, e = k x p): two equations linear in (cos theta1, sin theta1)
    and in (cos theta2, sin theta2); eliminating one pair leaves a quartic. Up to four
    solutions. Floats only.

    Parameters
    ----------
    h : array-like, shape (4, 3)
        The vectors h1 ... h4.
    k : array-like, shape (4, 3)
        Unit axes k1 ... k4 (k1, k3 turn by theta1; k2, k4 by theta2).
    p : array-like, shape (4, 3)
        The vectors p1 ... p4.
    d : array-like, shape (2,)
        The right-hand sides d1, d2.

    Returns
    -------
    Solutions
        (theta1, theta2) pairs (rad, in (-pi, pi]), or [] with ``reason``; ``free`` when
        an angle is free (a continuum; that angle is 0 in the list).

    Examples
    --------
    The right-hand sides made from known angles (0.3, -0.5) about z and x: the pair
    is among the solutions found.

    >>> from screwkit.transforms import rotx, rotz
    >>> x, y, z = np.eye(3)
    >>> h, k = np.array([y, z, x, y]), np.array([z, x, z, x])
    >>> p = np.array([x, y, x + y, z])
    >>> d = [y @ rotz(0.3) @ x + z @ rotx(-0.5) @ y,
    ...      x @ rotz(0.3) @ (x + y) + y @ rotx(-0.5) @ z]
    >>> any(np.allclose(t, (0.3, -0.5)) for t in subproblem6(h, k, p, d))
    True
    """
    arrays = {}
    for value, name, shape in (
        (h, "h", (4, 3)),
        (k, "k", (4, 3)),
        (p, "p", (4, 3)),
        (d, "d", (2,)),
    ):
        array = as_float_array(value, name)
        if array.shape != shape:
            raise ValueError(f"{name} must have shape {shape}, got {describe(array)}")
        arrays[name] = array
    norms = np.linalg.norm(arrays["k"], axis=1)
    if np.any(np.abs(norms - 1) > TOL):
        raise ValueError(
            f"k must hold unit axes, got norms {np.round(norms, 6).tolist()}"
        )
    theta, ok, free = two_pairs(arrays["h"], arrays["k"], arrays["p"], arrays["d"])
    if not ok.any():
        return Solutions(reason="the two equations have no common real solution")
    return Solutions(
        [tuple(float(a) for a in row) for row in theta[ok]], free=bool(free)
    )


def subproblem1_prismatic(s, p, q):
    """The distance t of the translation along the unit direction s with p + t s = q.

    t = s . (q - p), provided q - p is parallel to s.

    Parameters
    ----------
    s : array-like, shape (3,)
        A unit direction (the twist (0; s)).
    p, q : array-like, shape (3,)
        Points (m).

    Returns
    -------
    Solutions
        [t] (m), or [] with ``reason``.

    Examples
    --------
    >>> subproblem1_prismatic([0, 0, 1], [1, 0, 0], [1, 0, 3])
    [3.0]
    """
    exact = _symbolic(s, p, q)
    s = _direction(s, "s", exact)
    p, q = _point(p, "p", exact), _point(q, "q", exact)
    t = _dot(s, q - p, exact)
    off = q - p - s * t
    scale = 1.0 if exact else 1.0 + float(np.linalg.norm(q - p))
    if not _zero(_dot(off, off, exact), scale * scale, exact):
        return Solutions(
            reason=f"q is {_fmt(_norm(off, exact))} m off the line through p along s"
        )
    return Solutions([t])


def subproblem3_prismatic(s, p, q, delta):
    """The distances t with |p + t s - q| = delta (a line meets a sphere).

    With u = p - q: t = -s . u +- sqrt((s . u)^2 - |u|^2 + delta^2).

    Parameters
    ----------
    s : array-like, shape (3,)
        A unit direction (the twist (0; s)).
    p : array-like, shape (3,)
        The point moved along s (m).
    q : array-like, shape (3,)
        The centre of the sphere (m).
    delta : float
        The sphere's radius, >= 0 (m).

    Returns
    -------
    Solutions
        Distances (m), or [] with ``reason``.

    Examples
    --------
    The x axis meets the sphere of radius 2 about the origin at x = +-2; the line
    y = 3 misses it.

    >>> subproblem3_prismatic([1, 0, 0], [0, 0, 0], [0, 0, 0], 2)
    [-2.0, 2.0]
    >>> subproblem3_prismatic([1, 0, 0], [0, 3, 0], [0, 0, 0], 2).reason
    'the line passes 3.0000 m from q, farther than delta = 2.0000 m'
    """
    exact = _symbolic(s, p, q, delta)
    s = _direction(s, "s", exact)
    p, q = _point(p, "p", exact), _point(q, "q", exact)
    delta = _distance(delta, "delta", exact)
    u = p - q
    along = _dot(s, u, exact)
    discriminant = along**2 - _dot(u, u, exact) + delta**2
    scale = 1.0 if exact else 1.0 + float(np.linalg.norm(u)) + delta
    sign = _sign(discriminant, scale * scale, exact)
    if sign < 0:
        miss = sp.sqrt(_dot(u, u, exact) - along**2)
        return Solutions(
            reason=f"the line passes {_fmt(miss)} m from q, farther than "
            f"delta = {_fmt(delta)} m"
        )
    if sign == 0:
        return Solutions([-along])
    root = sp.sqrt(discriminant) if exact else float(np.sqrt(discriminant))
    both = [-along - root, -along + root]
    return Solutions([sp.simplify(t) for t in both] if exact else both)


def _fmt(value):
    """A number for a message: 4 decimals, or the exact expression."""
    try:
        return f"{float(value):.4f}"
    except TypeError:
        return str(value)
