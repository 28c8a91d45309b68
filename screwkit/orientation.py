"""Orientation parametrisations: Euler angles, roll-pitch-yaw, unit quaternions.

A rotation matrix has nine entries and three degrees of freedom; these are the usual
three- and four-number descriptions, both ways, exact for SymPy input and batched
(N, 3, 3) for floats. Conventions (angles in radians):

- **ZYZ Euler angles** (alpha, beta, gamma): R = Rz(alpha) Ry(beta) Rz(gamma), the
  angles of a spherical wrist; beta in [0, pi].
- **ZYX Euler angles** (alpha, beta, gamma): R = Rz(alpha) Ry(beta) Rx(gamma);
  beta in [-pi/2, pi/2].
- **roll-pitch-yaw** (roll, pitch, yaw): R = Rz(yaw) Ry(pitch) Rx(roll), turns about
  the fixed x, y, z axes in that order: the ZYX angles listed backwards.
- **unit quaternion** q = (w, x, y, z), scalar first, w = cos(theta/2) and
  (x, y, z) = sin(theta/2) times the unit axis; q and -q are the same rotation
  (the double cover); the conversion from a matrix returns w >= 0.

**Gimbal lock.** Three angles cannot describe every rotation smoothly: where the
middle angle makes the first and third axes line up (ZYZ: beta = 0 or pi; ZYX and
roll-pitch-yaw: pitch = +-pi/2) only their sum or difference is determined. There
the conversions return the documented answer *first angle = 0* (alpha = 0 for ZYZ and
ZYX, yaw = 0 for roll-pitch-yaw), the remaining angle carrying the whole turn, and
:func:`gimbal_lock` says where that happened. The matrix
:func:`euler_rate_matrix` B(phi), with omega = B(phi) dphi/dt, loses rank at the
same angles.

>>> import sympy as sp
>>> rpy_from_rotation(rotation_from_rpy([sp.pi / 3, sp.pi / 4, sp.pi / 6])).T
Matrix([[pi/3, pi/4, pi/6]])
>>> quaternion_from_rotation(rotz(np.pi / 2)).round(4)
array([0.7071, 0.    , 0.    , 0.7071])
"""

import numpy as np
import sympy as sp

from ._checks import (
    as_float_array,
    as_sympy_matrix,
    check_option,
    check_rotation,
    check_shape,
    is_symbolic,
)
from .tolerances import LOCK_TOL, ROTATION_TOL, ZERO_TOL
from .transforms import rotx, roty, rotz, skew

__all__ = [
    "rotation_from_euler",
    "euler_from_rotation",
    "rotation_from_rpy",
    "rpy_from_rotation",
    "rotation_from_quaternion",
    "quaternion_from_rotation",
    "quaternion_multiply",
    "gimbal_lock",
    "euler_rate_matrix",
]

CONVENTIONS = ("ZYZ", "ZYX")

#: allowed deviation of |q| from 1 for float quaternions: the old name of
#: :data:`screwkit.tolerances.ROTATION_TOL` (LOCK_TOL is imported from there too)
UNIT_TOL = ROTATION_TOL


def _triple(value, name):
    """Three angles: a SymPy column (3, 1), or a float64 array (3,) or (N, 3)."""
    if is_symbolic(value):
        return as_sympy_matrix(value, name, (3, 1))
    return check_shape(as_float_array(value, name), name, (3,))


def _convention(convention):
    if isinstance(convention, str):
        convention = convention.upper()
    return check_option(convention, "convention", CONVENTIONS)


def _simplify(expression):
    return sp.simplify(sp.radsimp(expression))


# ---- Euler angles ------------------------------------------------------------------


def rotation_from_euler(angles, convention="ZYZ"):
    """The rotation of three Euler angles.

    Parameters
    ----------
    angles : array-like, shape (3,) or (N, 3), or a SymPy 3-vector
        (alpha, beta, gamma) in radians.
    convention : {"ZYZ", "ZYX"}
        R = Rz(alpha) Ry(beta) Rz(gamma), or R = Rz(alpha) Ry(beta) Rx(gamma).

    Returns
    -------
    sympy.Matrix (3, 3) or ndarray, shape (3, 3) or (N, 3, 3)

    Examples
    --------
    >>> rotation_from_euler([0.0, np.pi / 2, 0.0])[:, 2].round(4)
    array([1., 0., 0.])
    """
    angles = _triple(angles, "angles")
    last = rotz if _convention(convention) == "ZYZ" else rotx
    if isinstance(angles, sp.MatrixBase):
        return rotz(angles[0]) * roty(angles[1]) * last(angles[2])
    return rotz(angles[..., 0]) @ roty(angles[..., 1]) @ last(angles[..., 2])


def euler_from_rotation(R, convention="ZYZ"):
    """The Euler angles (alpha, beta, gamma) of a rotation, inverse of
    :func:`rotation_from_euler`.

    Parameters
    ----------
    R : array-like, shape (3, 3) or (N, 3, 3), or a SymPy 3x3 rotation
    convention : {"ZYZ", "ZYX"}

    Returns
    -------
    sympy.Matrix (3, 1) or ndarray, shape (3,) or (N, 3)
        Radians; ZYZ beta in [0, pi], ZYX beta in [-pi/2, pi/2], alpha and gamma in
        (-pi, pi]. At gimbal lock (see :func:`gimbal_lock`) alpha = 0 and gamma
        carries the whole rotation about the aligned axes. Symbolic entries give the
        generic formula, valid away from the lock.

    Examples
    --------
    >>> euler_from_rotation(rotz(0.3) @ roty(0.0) @ rotz(0.4)).round(4)
    array([0. , 0. , 0.7])
    """
    R = check_rotation(R, "R")
    zyz = _convention(convention) == "ZYZ"
    if isinstance(R, sp.MatrixBase):
        return _euler_exact(R, zyz)
    return _euler_numeric(R, zyz)


def _euler_numeric(R, zyz):
    r = lambda i, j: R[..., i - 1, j - 1]  # noqa: E731 (1-based, as in the books)
    if zyz:
        sin_beta = np.hypot(r(1, 3), r(2, 3))
        beta = np.arctan2(sin_beta, r(3, 3))
        alpha = np.arctan2(r(2, 3), r(1, 3))
        gamma = np.arctan2(r(3, 2), -r(3, 1))
        # locked: beta = 0 is Rz(alpha + gamma), beta = pi is Rz(alpha - gamma) Ry(pi)
        up = r(3, 3) > 0
        locked_gamma = np.where(
            up, np.arctan2(r(2, 1), r(1, 1)), np.arctan2(r(2, 1), -r(1, 1))
        )
        locked = sin_beta < LOCK_TOL
    else:
        cos_beta = np.hypot(r(1, 1), r(2, 1))
        beta = np.arctan2(-r(3, 1), cos_beta)
        alpha = np.arctan2(r(2, 1), r(1, 1))
        gamma = np.arctan2(r(3, 2), r(3, 3))
        # locked: beta = +pi/2 gives gamma - alpha, beta = -pi/2 gives gamma + alpha
        down = r(3, 1) < 0
        locked_gamma = np.where(
            down, np.arctan2(r(1, 2), r(2, 2)), np.arctan2(-r(1, 2), r(2, 2))
        )
        locked = cos_beta < LOCK_TOL
    alpha = np.where(locked, 0.0, alpha)
    gamma = np.where(locked, locked_gamma, gamma)
    return np.stack([alpha, beta, gamma], axis=-1)


def _euler_exact(R, zyz):
    r = lambda i, j: R[i - 1, j - 1]  # noqa: E731
    if zyz:
        sin_beta = _simplify(sp.sqrt(r(1, 3) ** 2 + r(2, 3) ** 2))
        beta = sp.atan2(sin_beta, _simplify(r(3, 3)))
        if sin_beta.is_zero:
            up = bool(_simplify(r(3, 3)) > 0)
            sign = 1 if up else -1
            gamma = sp.atan2(_simplify(r(2, 1)), _simplify(sign * r(1, 1)))
            return sp.Matrix([0, beta, gamma])
        alpha = sp.atan2(_simplify(r(2, 3)), _simplify(r(1, 3)))
        gamma = sp.atan2(_simplify(r(3, 2)), _simplify(-r(3, 1)))
    else:
        cos_beta = _simplify(sp.sqrt(r(1, 1) ** 2 + r(2, 1) ** 2))
        beta = sp.atan2(_simplify(-r(3, 1)), cos_beta)
        if cos_beta.is_zero:
            sign = 1 if bool(_simplify(r(3, 1)) < 0) else -1
            gamma = sp.atan2(_simplify(sign * r(1, 2)), _simplify(r(2, 2)))
            return sp.Matrix([0, beta, gamma])
        alpha = sp.atan2(_simplify(r(2, 1)), _simplify(r(1, 1)))
        gamma = sp.atan2(_simplify(r(3, 2)), _simplify(r(3, 3)))
    return sp.Matrix([alpha, beta, gamma])


def gimbal_lock(R, convention="ZYZ"):
    """Whether Euler angles of ``R`` are at gimbal lock (first and third axes aligned).

    Parameters
    ----------
    R : array-like, shape (3, 3) or (N, 3, 3), or a SymPy 3x3 rotation
    convention : {"ZYZ", "ZYX"} (roll-pitch-yaw locks where ZYX does)

    Returns
    -------
    bool or ndarray of bool, shape (N,)
        ZYZ: sin(beta) = 0; ZYX: cos(beta) = 0 (to ``LOCK_TOL`` for floats, exactly
        for SymPy numbers; False for symbolic entries, which are generic).

    Examples
    --------
    >>> bool(gimbal_lock(roty(np.pi / 2), "ZYX")), bool(gimbal_lock(roty(0.2)))
    (True, False)
    """
    R = check_rotation(R, "R")
    zyz = _convention(convention) == "ZYZ"
    if isinstance(R, sp.MatrixBase):
        a, b = (R[0, 2], R[1, 2]) if zyz else (R[0, 0], R[1, 0])
        return bool(_simplify(a**2 + b**2).is_zero)
    a, b = (R[..., 0, 2], R[..., 1, 2]) if zyz else (R[..., 0, 0], R[..., 1, 0])
    locked = np.hypot(a, b) < LOCK_TOL
    return bool(locked) if locked.ndim == 0 else locked


def rotation_from_rpy(rpy):
    """R = Rz(yaw) Ry(pitch) Rx(roll) from (roll, pitch, yaw) in radians.

    Parameters
    ----------
    rpy : array-like, shape (3,) or (N, 3), or a SymPy 3-vector

    Returns
    -------
    sympy.Matrix (3, 3) or ndarray, shape (3, 3) or (N, 3, 3)

    Examples
    --------
    A yaw of 90 degrees alone is a quarter turn about z: x goes to y.

    >>> (rotation_from_rpy([0.0, 0.0, np.pi / 2]) @ [1, 0, 0]).round(12) + 0.0
    array([0., 1., 0.])
    """
    rpy = _triple(rpy, "rpy")
    if isinstance(rpy, sp.MatrixBase):
        return rotation_from_euler(rpy[::-1, :], "ZYX")
    return rotation_from_euler(rpy[..., ::-1], "ZYX")


def rpy_from_rotation(R):
    """(roll, pitch, yaw) of a rotation, inverse of :func:`rotation_from_rpy`.

    Pitch in [-pi/2, pi/2]; at pitch = +-pi/2 (gimbal lock) yaw = 0 and roll carries
    the turn.

    Parameters
    ----------
    R : array-like, shape (3, 3) or (N, 3, 3), or a SymPy 3x3 matrix
        Rotation matrices.

    Returns
    -------
    ndarray, shape (3,) or (N, 3), or sympy.Matrix (3, 1)
        (roll, pitch, yaw) (rad).

    Examples
    --------
    A turn about x is all roll:

    >>> rpy_from_rotation(rotx(0.3)).round(4) + 0.0
    array([0.3, 0. , 0. ])
    """
    angles = euler_from_rotation(R, "ZYX")
    if isinstance(angles, sp.MatrixBase):
        return angles[::-1, :]
    return angles[..., ::-1].copy()


# ---- unit quaternions --------------------------------------------------------------


def _quaternion(value):
    if is_symbolic(value):
        q = as_sympy_matrix(value, "q", (4, 1))
        norm = _simplify(sum(e**2 for e in q))
        if norm.is_number and not sp.Eq(norm, 1) == sp.true:
            raise ValueError(f"q must be a unit quaternion, got |q|^2 = {norm}")
        return q
    q = check_shape(as_float_array(value, "q"), "q", (4,))
    norm = np.linalg.norm(q, axis=-1)
    if q.size and not np.all(np.abs(norm - 1) <= ROTATION_TOL):
        worst = norm.ravel()[np.argmax(np.abs(norm - 1).ravel())]
        raise ValueError(
            f"q must be a unit quaternion (w, x, y, z), got one of norm {worst:.6g}"
        )
    return q


def rotation_from_quaternion(q):
    """The rotation of a unit quaternion q = (w, x, y, z), scalar first.

    R = (w^2 - u.u) I + 2 u u^T + 2 w [u], with u = (x, y, z); q and -q give the
    same R.

    Parameters
    ----------
    q : array-like, shape (4,) or (N, 4), or a SymPy 4-vector; |q| = 1

    Returns
    -------
    sympy.Matrix (3, 3) or ndarray, shape (3, 3) or (N, 3, 3)

    Examples
    --------
    >>> rotation_from_quaternion([0.0, 0.0, 0.0, 1.0]).round(4)  # a half turn about z
    array([[-1.,  0.,  0.],
           [ 0., -1.,  0.],
           [ 0.,  0.,  1.]])
    """
    q = _quaternion(q)
    if isinstance(q, sp.MatrixBase):
        w, u = q[0], q[1:, :]
        R = (w**2 - (u.T * u)[0]) * sp.eye(3) + 2 * u * u.T + 2 * w * skew(u)
        return R.applyfunc(sp.expand)
    w, u = q[..., 0], q[..., 1:]
    eye = np.eye(3)
    return (
        (w**2 - np.sum(u * u, axis=-1))[..., None, None] * eye
        + 2 * u[..., :, None] * u[..., None, :]
        + 2 * w[..., None, None] * skew(u)
    )


def quaternion_from_rotation(R):
    """The unit quaternion (w, x, y, z) of a rotation, with w >= 0.

    Computed from the largest of 1 + trace R and 1 + 2 r_ii - trace R (Shepperd's
    method), so it stays accurate near the half turn. For a half turn (w = 0) the
    first non-zero of x, y, z is made positive.

    Parameters
    ----------
    R : array-like, shape (3, 3) or (N, 3, 3), or a SymPy 3x3 rotation

    Returns
    -------
    sympy.Matrix (4, 1) or ndarray, shape (4,) or (N, 4)

    Examples
    --------
    A quarter turn about x: w = cos(45 deg), (x, y, z) = sin(45 deg) (1, 0, 0).

    >>> quaternion_from_rotation(rotx(np.pi / 2)).round(4) + 0.0
    array([0.7071, 0.7071, 0.    , 0.    ])
    """
    R = check_rotation(R, "R")
    if isinstance(R, sp.MatrixBase):
        return _quaternion_exact(R)
    trace = np.trace(R, axis1=-2, axis2=-1)
    diagonal = np.diagonal(R, axis1=-2, axis2=-1)
    # four times the squares of w, x, y, z
    squares = np.concatenate(
        [(1 + trace)[..., None], 1 + 2 * diagonal - trace[..., None]], axis=-1
    )
    best = np.argmax(squares, axis=-1)
    big = np.sqrt(np.take_along_axis(squares, best[..., None], -1)[..., 0]) / 2
    r = lambda i, j: R[..., i, j]  # noqa: E731
    # the products 4 q_a q_b from the off-diagonal entries
    wx, wy, wz = r(2, 1) - r(1, 2), r(0, 2) - r(2, 0), r(1, 0) - r(0, 1)
    xy, xz, yz = r(0, 1) + r(1, 0), r(0, 2) + r(2, 0), r(1, 2) + r(2, 1)
    rows = np.stack(
        [
            np.stack([4 * big**2, wx, wy, wz], -1),
            np.stack([wx, 4 * big**2, xy, xz], -1),
            np.stack([wy, xy, 4 * big**2, yz], -1),
            np.stack([wz, xz, yz, 4 * big**2], -1),
        ],
        -2,
    )
    q = np.take_along_axis(rows, best[..., None, None], -2)[..., 0, :] / (
        4 * big[..., None]
    )
    return _canonical(q)


def _canonical(q):
    """Choose the sign of q: w > 0, or for w = 0 the first non-zero entry > 0.

    Entries before the first one above ZERO_TOL (round-off of a half turn's w, say
    -6e-17) are set to exactly 0, so that the promise holds as written: w >= 0, and
    where w == 0 the first non-zero entry is positive.
    """
    tol = ZERO_TOL
    q = np.array(q, dtype=float)
    big = np.abs(q) > tol
    first = np.argmax(big, axis=-1)  # the first entry above round-off (0 if none)
    before = np.arange(4) < first[..., None]
    q[before] = 0.0
    lead = np.take_along_axis(q, first[..., None], -1)[..., 0]
    return np.where((lead < 0)[..., None], -q, q)


def _quaternion_exact(R):
    trace = R.trace()
    squares = [1 + trace] + [1 + 2 * R[i, i] - trace for i in range(3)]
    numeric = [
        float(sp.re(s.subs({x: 0.3 for x in s.free_symbols}).evalf())) for s in squares
    ]
    best = 0 if R.free_symbols else int(np.argmax(numeric))
    big = _simplify(sp.sqrt(squares[best]) / 2)
    wx, wy, wz = R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]
    xy, xz, yz = R[0, 1] + R[1, 0], R[0, 2] + R[2, 0], R[1, 2] + R[2, 1]
    products = [
        [None, wx, wy, wz],
        [wx, None, xy, xz],
        [wy, xy, None, yz],
        [wz, xz, yz, None],
    ][best]
    q = [big if k == best else _simplify(products[k] / (4 * big)) for k in range(4)]
    lead = next((e for e in q if not _simplify(e).is_zero), 1)
    if lead.is_number and lead < 0:
        q = [-e for e in q]
    return sp.Matrix(q)


def quaternion_multiply(p, q):
    """The Hamilton product p q: the rotation of q followed by that of p (in the fixed
    frame), R(p q) = R(p) R(q).

    Parameters
    ----------
    p, q : array-like, shape (4,) or (N, 4), or SymPy 4-vectors; (w, x, y, z)

    Returns
    -------
    sympy.Matrix (4, 1) or ndarray, shape (4,) or (N, 4)

    Examples
    --------
    Two quarter turns about z make a half turn about z, q = (0, 0, 0, 1):

    >>> q = [np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)]
    >>> quaternion_multiply(q, q).round(12) + 0.0
    array([0., 0., 0., 1.])
    """
    if is_symbolic(p) or is_symbolic(q):
        p = as_sympy_matrix(p, "p", (4, 1))
        q = as_sympy_matrix(q, "q", (4, 1))
        w = p[0] * q[0] - (p[1:, :].T * q[1:, :])[0]
        u = p[0] * q[1:, :] + q[0] * p[1:, :] + p[1:, :].cross(q[1:, :])
        return sp.Matrix([w, *u]).applyfunc(sp.expand)
    p = check_shape(as_float_array(p, "p"), "p", (4,))
    q = check_shape(as_float_array(q, "q"), "q", (4,))
    w = p[..., 0] * q[..., 0] - np.sum(p[..., 1:] * q[..., 1:], axis=-1)
    u = (
        p[..., :1] * q[..., 1:]
        + q[..., :1] * p[..., 1:]
        + np.cross(p[..., 1:], q[..., 1:])
    )
    return np.concatenate([w[..., None], u], axis=-1)


# ---- the analytic Jacobian of Euler rates ------------------------------------------


def euler_rate_matrix(angles, convention="ZYZ", frame="space"):
    """B(phi) with omega = B(phi) dphi/dt: angular velocity from Euler-angle rates.

    Parameters
    ----------
    angles : array-like, shape (3,) or (N, 3), or a SymPy 3-vector
        ZYZ or ZYX (alpha, beta, gamma), or (roll, pitch, yaw) for ``"RPY"``.
    convention : {"ZYZ", "ZYX", "RPY"}
    frame : {"space", "body"}
        omega in the fixed frame (B), or in the rotated body frame (R^T B).

    Returns
    -------
    sympy.Matrix (3, 3) or ndarray, shape (3, 3) or (N, 3, 3)
        Columns: the axes of the three turns, in the chosen frame. det B is
        -sin(beta) for ZYZ, -cos(beta) for ZYX and cos(pitch) for RPY: B is singular
        at gimbal lock, where some angular velocities need infinite angle rates.

    Examples
    --------
    >>> euler_rate_matrix([0.0, 0.0, 0.0], "ZYZ") + 0.0
    array([[0., 0., 0.],
           [0., 1., 0.],
           [1., 0., 1.]])
    """
    if isinstance(convention, str):
        convention = convention.upper()
    convention = check_option(convention, "convention", ("ZYZ", "ZYX", "RPY"))
    frame = check_option(frame, "frame", ("space", "body"))
    angles = _triple(angles, "angles")
    exact = isinstance(angles, sp.MatrixBase)
    lib = sp if exact else np
    if convention == "RPY":
        yaw_first = angles[::-1, :] if exact else angles[..., ::-1]
    else:
        yaw_first = angles
    a = yaw_first[0] if exact else yaw_first[..., 0]
    b = yaw_first[1] if exact else yaw_first[..., 1]
    ca, sa, cb, sb = lib.cos(a), lib.sin(a), lib.cos(b), lib.sin(b)
    zero, one = (0, 1) if exact else (np.zeros_like(a), np.ones_like(a))
    first = [zero, zero, one]  # z
    second = [-sa, ca, zero]  # Rz(a) y
    if convention == "ZYZ":
        third = [ca * sb, sa * sb, cb]  # Rz(a) Ry(b) z
    else:
        third = [ca * cb, sa * cb, -sb]  # Rz(a) Ry(b) x
    columns = [first, second, third]
    if convention == "RPY":
        columns = columns[::-1]  # rates ordered (roll, pitch, yaw)
    if exact:
        B = sp.Matrix(3, 3, lambda i, j: columns[j][i])
    else:
        B = np.stack([np.stack(c, -1) for c in columns], -1)
    if frame == "body":
        R = (
            rotation_from_rpy(angles)
            if convention == "RPY"
            else rotation_from_euler(angles, convention)
        )
        B = (R.T * B).applyfunc(sp.simplify) if exact else np.swapaxes(R, -1, -2) @ B
    return B
