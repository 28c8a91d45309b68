"""Frame changes and logarithms of rigid motions: the adjoint, the Lie bracket, log R
and log T.

If T = T_ab is the pose of frame {b} in frame {a}, a twist V_b = (omega; v) written in
{b} coordinates is written in {a} coordinates as V_a = Ad(T) V_b, with
(screw order [angular; linear])

    Ad(T) = [[R, 0], [[p] R, R]].

A wrench (f; m), in the same [angular; linear] order (force first), changes frame by the
same matrix: f_a = R f_b, m_a = R m_b + p x f_a. Written in Modern Robotics' order
(m; f) this is their "transposed adjoint" rule F_b = Ad(T_ab)^T F_a; both keep the power
V . F unchanged.

The logarithms invert the exponentials of :mod:`screwkit.transforms`:
``log_rotation(R)`` is the rotation vector omega theta with theta in [0, pi], and
``log_transform(T)`` the 6-vector [omega; v] theta with
``exp_twist(log_transform(T), 1) == T``.

Every function is exact for SymPy input and float64 (batched over leading axes)
otherwise.

>>> import numpy as np
>>> T = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 3], [0, 0, 0, 1]])
>>> np.round(log_transform(T), 4)                  # (pi/2, 0, 0; 0, 3 pi/4, 3 pi/4)
array([1.5708, 0.    , 0.    , 0.    , 2.3562, 2.3562])
"""

import numpy as np
import sympy as sp

from ._checks import (
    as_float_array,
    as_sympy_matrix,
    check_rotation,
    check_transform,
    is_symbolic,
)
from .tolerances import DIVISION_FLOOR, SMALL_ANGLE, ZERO_TOL
from .transforms import _skew, _skew_exact

__all__ = ["adjoint", "ad", "log_rotation", "log_transform", "vee"]


def vee(W):
    """The 3-vector w of a skew-symmetric matrix W = [w] (the inverse of ``skew``).

    Parameters
    ----------
    W : array-like, shape (3, 3) or (..., 3, 3), or a SymPy 3x3 matrix
        Skew-symmetric matrices.

    Returns
    -------
    ndarray, shape (3,) or (..., 3), or sympy.Matrix (3, 1)
        w = (W[2, 1], W[0, 2], W[1, 0]).

    Examples
    --------
    >>> W = [[0, -3, 2], [3, 0, -1], [-2, 1, 0]]  # [w] of w = (1, 2, 3)
    >>> vee(W)
    array([1., 2., 3.])
    """
    if is_symbolic(W):
        W = as_sympy_matrix(W, "W", (3, 3))
        return sp.Matrix([W[2, 1], W[0, 2], W[1, 0]])
    W = as_float_array(W, "W")
    if W.shape[-2:] != (3, 3):
        raise ValueError(f"W must have shape (3, 3) or (N, 3, 3), got shape {W.shape}")
    return np.stack([W[..., 2, 1], W[..., 0, 2], W[..., 1, 0]], -1)


def adjoint(T):
    """The 6x6 adjoint Ad(T) = [[R, 0], [[p] R, R]] of a pose T, for screws
    [angular; linear].

    ``adjoint(T) @ V`` writes in the frame of T's reference a twist (or wrench (f; m))
    given in the moving frame. Ad(T1 T2) = Ad(T1) Ad(T2) and Ad(T^-1) = Ad(T)^-1.

    Parameters
    ----------
    T : array-like, shape (4, 4) or (N, 4, 4), a rigid transform (m);
        or a SymPy 4x4 matrix

    Returns
    -------
    ndarray, shape (6, 6) or (N, 6, 6); sympy.Matrix (6, 6) for SymPy input

    Examples
    --------
    The identity pose changes nothing: Ad(I) is the 6x6 identity.

    >>> float(adjoint(np.eye(4)).trace())
    6.0

    Frame {b} sits at p = (1, 0, 0) in {a}. A spin about {b}'s z axis, written in {a},
    is a rotation about the line x = 1: its moment is p x z = -y.

    >>> T = np.eye(4)
    >>> T[0, 3] = 1.0
    >>> adjoint(T) @ [0, 0, 1, 0, 0, 0]
    array([ 0.,  0.,  1.,  0., -1.,  0.])
    """
    T = check_transform(T, "T")
    if isinstance(T, sp.MatrixBase):
        R, p = T[:3, :3], T[:3, 3]
        return sp.Matrix(sp.BlockMatrix([[R, sp.zeros(3, 3)], [_skew_exact(p) * R, R]]))
    R, p = T[..., :3, :3], T[..., :3, 3]
    A = np.zeros(T.shape[:-2] + (6, 6))
    A[..., :3, :3] = R
    A[..., 3:, 3:] = R
    A[..., 3:, :3] = _skew(p) @ R
    return A


def ad(twist):
    """The 6x6 matrix [ad_V] = [[[w], 0], [[v], [w]]] of a twist V = (w; v).

    [ad_V1] V2 is the Lie bracket [V1, V2]: the derivative of Ad(exp([V1] t)) V2 at
    t = 0.

    Parameters
    ----------
    twist : array-like, shape (6,) or (N, 6), or a SymPy 6-vector
        The twist(s) V = (w; v) (rad/s, m/s).

    Returns
    -------
    ndarray, shape (6, 6) or (N, 6, 6), or sympy.Matrix (6, 6)
        [ad_V].

    Examples
    --------
    >>> ad([1, 2, 3, 4, 5, 6])[3:, :3]
    array([[ 0., -6.,  5.],
           [ 6.,  0., -4.],
           [-5.,  4.,  0.]])
    """
    if is_symbolic(twist):
        V = as_sympy_matrix(twist, "twist", (6, 1))
        W = _skew_exact(V[:3, 0])
        return sp.Matrix(
            sp.BlockMatrix([[W, sp.zeros(3, 3)], [_skew_exact(V[3:, 0]), W]])
        )
    V = as_float_array(twist, "twist")
    if V.shape[-1:] != (6,) or V.ndim > 2:
        raise ValueError(
            f"twist must have shape (6,) or (N, 6), ordered [w; v], got shape {V.shape}"
        )
    W = _skew(V[..., :3])
    A = np.zeros(V.shape[:-1] + (6, 6))
    A[..., :3, :3] = W
    A[..., 3:, 3:] = W
    A[..., 3:, :3] = _skew(V[..., 3:])
    return A


def log_rotation(R):
    """The rotation vector omega theta of a rotation R = exp([omega] theta), theta in
    [0, pi].

    theta = atan2(|vee(R - R^T)| / 2, (tr R - 1) / 2), exact to round-off at every
    angle: near 0 by the series of theta / sin(theta); near pi from the symmetric part
    (R + R^T) / 2 = cos(theta) I + (1 - cos(theta)) omega omega^T, since the skew part
    vanishes there. At exactly theta = pi the rotations by omega and -omega are the
    same; the axis returned is the one whose largest-magnitude component is positive.

    Parameters
    ----------
    R : array-like, shape (3, 3) or (N, 3, 3), a rotation matrix; or a SymPy 3x3 matrix

    Returns
    -------
    ndarray, shape (3,) or (N, 3) (rad); sympy.Matrix (3, 1) for SymPy input

    Examples
    --------
    >>> np.round(log_rotation([[0, -1, 0], [1, 0, 0], [0, 0, 1]]), 6)   # Rz(90 deg)
    array([0.      , 0.      , 1.570796])

    A half turn about x (theta = pi, where the skew part vanishes):

    >>> np.round(log_rotation(np.diag([1.0, -1.0, -1.0])), 6)
    array([3.141593, 0.      , 0.      ])
    """
    R = check_rotation(R, "R")
    if isinstance(R, sp.MatrixBase):
        return _log_rotation_exact(R)
    skew_part = 0.5 * vee(R - np.swapaxes(R, -1, -2))  # omega sin(theta)
    sin_theta = np.linalg.norm(skew_part, axis=-1)
    cos_theta = np.clip(0.5 * (np.trace(R, axis1=-2, axis2=-1) - 1.0), -1.0, 1.0)
    theta = np.arctan2(sin_theta, cos_theta)
    small = theta < SMALL_ANGLE
    safe_sin = np.where(small | (sin_theta == 0), 1.0, sin_theta)
    scale = np.where(
        small, 1.0 + theta**2 / 6.0, theta / safe_sin
    )  # theta / sin(theta)
    result = scale[..., None] * skew_part
    near_pi = cos_theta < -0.5  # sin(theta) is small relative to 1 - cos(theta) here
    if np.any(near_pi):
        result = np.where(
            near_pi[..., None],
            _axis_near_pi(R, skew_part, cos_theta) * theta[..., None],
            result,
        )
    return result


def _axis_near_pi(R, skew_part, cos_theta):
    """The unit axis from the symmetric part of R (accurate when theta is far from
    0)."""
    outer = 0.5 * (R + np.swapaxes(R, -1, -2)) - cos_theta[..., None, None] * np.eye(3)
    outer = (
        outer / np.maximum(1.0 - cos_theta, 0.5)[..., None, None]
    )  # omega omega^T (used where c < -0.5)
    column = np.argmax(np.diagonal(outer, axis1=-2, axis2=-1), axis=-1)
    axis = np.take_along_axis(outer, column[..., None, None], axis=-1)[..., 0]
    axis = axis / np.maximum(
        np.linalg.norm(axis, axis=-1, keepdims=True), DIVISION_FLOOR
    )
    # the sign: along omega sin(theta) when that is informative, else largest component
    # positive
    dot = np.sum(axis * skew_part, axis=-1)
    largest = np.take_along_axis(
        axis, np.argmax(np.abs(axis), axis=-1)[..., None], axis=-1
    )[..., 0]
    sign = np.where(np.abs(dot) > ZERO_TOL, np.sign(dot), np.sign(largest))
    return axis * sign[..., None]


def _log_rotation_exact(R):
    cos_theta = (
        sp.nsimplify(sp.simplify((R.trace() - 1) / 2))
        if not R.free_symbols
        else sp.simplify((R.trace() - 1) / 2)
    )
    if cos_theta == 1:
        return sp.zeros(3, 1)
    skew_part = vee(R - R.T) / 2
    if cos_theta == -1:
        outer = (R + R.T) / 2 + sp.eye(3)  # 2 omega omega^T
        diagonal = [outer[i, i] for i in range(3)]
        k = max(range(3), key=lambda i: float(diagonal[i]))
        axis = (outer[:, k] / sp.sqrt(2 * diagonal[k])).applyfunc(sp.radsimp)
        largest = max(axis, key=lambda e: abs(float(e)))
        return axis * sp.pi * (1 if largest > 0 else -1)
    theta = sp.acos(cos_theta)
    sin_theta = sp.sqrt(sp.simplify(skew_part.dot(skew_part)))
    return (skew_part * theta / sin_theta).applyfunc(sp.simplify)


def log_transform(T):
    """The twist coordinates [omega; v] theta of a pose T = exp([V] theta), theta in
    [0, pi].

    With phi = omega theta = log_rotation(R) and the translation p,
    v theta = (I - [phi] / 2 + k [phi]^2) p,
    k = (1 - (theta / 2) cot(theta / 2)) / theta^2, which tends to 1/12 as theta -> 0
    (a pure translation gives [0; p]) and is 1 / pi^2 at pi.
    ``exp_twist(log_transform(T), 1)`` is T.

    Parameters
    ----------
    T : array-like, shape (4, 4) or (N, 4, 4), or a SymPy 4x4 matrix
        The rigid transform(s) (m).

    Returns
    -------
    ndarray, shape (6,) or (N, 6), ordered [omega theta (rad); v theta (m)];
        sympy.Matrix (6, 1) for SymPy input

    Examples
    --------
    A pure translation by p gives [0; p]:

    >>> T = np.eye(4)
    >>> T[:3, 3] = [1.0, 2.0, 3.0]
    >>> log_transform(T)
    array([0., 0., 0., 1., 2., 3.])

    A quarter turn about the vertical line through (1, 0, 0) (so p = (1, -1, 0)):
    omega = z, v = -omega x r = -y, both times theta = pi / 2.

    >>> T = np.array([[0, -1, 0, 1], [1, 0, 0, -1], [0, 0, 1, 0], [0, 0, 0, 1]])
    >>> np.round(log_transform(T), 4) + 0.0
    array([ 0.    ,  0.    ,  1.5708,  0.    , -1.5708,  0.    ])
    """
    T = check_transform(T, "T")
    if isinstance(T, sp.MatrixBase):
        phi = log_rotation(T[:3, :3])
        theta = sp.sqrt(phi.dot(phi))
        A = _skew_exact(phi)
        if theta == 0:
            k = sp.Rational(1, 12)
        else:
            k = (1 - theta / 2 * sp.cot(theta / 2)) / theta**2
        v = (sp.eye(3) - A / 2 + k * A * A) * T[:3, 3]
        return sp.Matrix.vstack(phi, v.applyfunc(sp.simplify))
    phi = log_rotation(T[..., :3, :3])
    theta = np.linalg.norm(phi, axis=-1)
    small = theta < SMALL_ANGLE
    half = np.where(small, 1.0, theta / 2)
    k = np.where(
        small,
        1.0 / 12.0 + theta**2 / 720.0,
        (1.0 - half / np.tan(half)) / np.where(small, 1.0, theta) ** 2,
    )
    p = T[..., :3, 3]
    phi_p = np.cross(phi, p)
    v = p - 0.5 * phi_p + k[..., None] * np.cross(phi, phi_p)
    return np.concatenate([phi, v], axis=-1)
