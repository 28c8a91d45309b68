"""Rigid-body motions: rotations, homogeneous transforms and the exponential of a twist.

Every function is exact with SymPy input (it returns a ``sympy.Matrix``) and
fast with numeric input (it returns float64 NumPy arrays, vectorised over a
leading batch axis). Angles are in radians, lengths in metres.

>>> import sympy as sp
>>> rotz(sp.pi / 2)
Matrix([
[0, -1, 0],
[1,  0, 0],
[0,  0, 1]])
>>> rotz([0.0, 0.1]).shape
(2, 3, 3)
"""

import numbers

import numpy as np
import sympy as sp

from ._checks import (
    as_float_array,
    as_real_scalar,
    as_scalar_or_batch,
    as_sympy_matrix,
    as_sympy_scalar,
    check_rotation,
    check_shape,
    check_transform,
    describe,
    is_symbolic,
)
from ._docstrings import fill
from .tolerances import SERIES_BELOW, ZERO_TOL

__all__ = [
    "skew",
    "rotx",
    "roty",
    "rotz",
    "rot_axis",
    "transl",
    "homogeneous",
    "inv",
    "twist_from_axis",
    "axis_coordinates",
    "wrap_angle",
    "exp_twist",
    "screw_motion",
]


# ---- the unchecked kernels every layer above uses (checked inputs, no copies) --------


def _skew(v):
    """[v] for a float array v of shape (..., 3): shape (..., 3, 3). No checks."""
    x, y, z = v[..., 0], v[..., 1], v[..., 2]
    zero = np.zeros_like(x)
    return np.stack(
        [
            np.stack([zero, -z, y], -1),
            np.stack([z, zero, -x], -1),
            np.stack([-y, x, zero], -1),
        ],
        -2,
    )


def _rotate_vectors(w, angle, x):
    """x (..., 3) turned about the unit direction w (3,) by angle (..., rad): Rodrigues'
    formula on vectors, x c + (w x x) s + w (w . x)(1 - c). No checks."""
    return _turn_vectors(w, np.cos(angle), np.sin(angle), x)


def _turn_vectors(w, c, s, x):
    """:func:`_rotate_vectors` with the angle's cos c and sin s (...) already known
    (an angle turning several vectors; -s turns back). No checks."""
    c, s = c[..., None], s[..., None]
    return x * c + _cross_last(w, x) * s + w * (_dot_last(x, w)[..., None] * (1 - c))


def _skew_exact(v):
    """[v] for a SymPy 3-vector (or any 3 entries): a 3x3 SymPy matrix. No checks."""
    x, y, z = v
    return sp.Matrix([[0, -z, y], [z, 0, -x], [-y, x, 0]])


def _cross(a, b):
    """a x b along axis 0, for arrays laid out (3, ...) and single 3-vectors (3,): the
    one cross product of screwkit's kernels, cheaper than np.cross on strided data and
    on single vectors. Arrays laid out (..., 3) use np.cross. No checks."""
    return np.stack(
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    )


def _cross_into(out, a, b, add=False):
    """The in-place form of :func:`_cross`: out (3, ...) = a x b, or += with ``add``,
    component by component, for arrays laid out (3, ...): a third of the time of
    building the products as new arrays (the sums are memory-bound). No checks."""
    scratch = np.empty_like(out[0])
    for k, (i, j) in enumerate(((1, 2), (2, 0), (0, 1))):
        if add:
            out[k] += np.multiply(a[i], b[j], out=scratch)
        else:
            np.multiply(a[i], b[j], out=out[k])
        out[k] -= np.multiply(a[j], b[i], out=scratch)
    return out


def _cross_last(a, b):
    """a x b along the last axis, for arrays laid out (..., 3) (or (3,)) that
    broadcast: written out, several times cheaper than np.cross. No checks."""
    a0, a1, a2 = a[..., 0], a[..., 1], a[..., 2]
    b0, b1, b2 = b[..., 0], b[..., 1], b[..., 2]
    return np.stack([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0], -1)


def _dot_last(a, b):
    """a . b along the last axis of length 3, for arrays that broadcast: written out,
    several times cheaper than np.sum(a * b, -1) or a matrix product. No checks."""
    return a[..., 0] * b[..., 0] + a[..., 1] * b[..., 1] + a[..., 2] * b[..., 2]


def _rodrigues(W, s, c1):
    """I + s [w] + c1 [w]^2 from W = [w] (..., 3, 3), s = sin and c1 = 1 - cos
    (..., 1, 1)."""
    return np.eye(3) + s * W + c1 * (W @ W)


def _rotations_about(w, angle):
    """R(w, angle) (..., 3, 3) about a unit axis w (3,) for angles (...). No checks."""
    angle = np.asarray(angle)[..., None, None]
    return _rodrigues(_skew(np.asarray(w, float)), np.sin(angle), 1 - np.cos(angle))


def _rodrigues_exact(W, theta):
    """I + sin(theta) W + (1 - cos(theta)) W^2 for a SymPy W = [w] (|w| = 1),
    exactly."""
    return sp.eye(3) + sp.sin(theta) * W + (1 - sp.cos(theta)) * W * W


def _is_infinite_pitch(h):
    """True for the pitch of a pure translation: sympy.oo, or a real +inf
    (a Python or NumPy float, or a 0-d array); the one test of an infinite pitch
    (no other check)."""
    if h is sp.oo:
        return True
    return (
        isinstance(h, (numbers.Real, np.ndarray))
        and not isinstance(h, (bool, np.bool_))
        and np.ndim(h) == 0
        and np.asarray(h).dtype.kind in "iuf"
        and bool(np.isposinf(h))
    )


def axis_coordinates(s, r, h):
    """The screw coordinates of an axis: (s; r x s + h s), or (0; s) for the pitch
    h = oo.

    The one place screwkit writes this formula
    (also :func:`screwkit.screws.axis_coordinates`). ``s`` is used as given
    (not normalised).

    Parameters
    ----------
    s, r : SymPy 3x1 matrices (exact), or float arrays of shape (3,) or (N, 3);
        r is unused for h = oo
    h : the pitch (m/rad): a number, a SymPy expression, or oo / inf for a translation

    Returns
    -------
    sympy.Matrix (6, 1), or ndarray (6,) / (N, 6)

    Examples
    --------
    The z axis moved to x = 1: its moment r x s = (1, 0, 0) x (0, 0, 1) is -y.

    >>> s, r = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0])
    >>> axis_coordinates(s, r, 0.5)  # pitch 0.5 adds 0.5 s to the moment
    array([ 0. ,  0. ,  1. ,  0. , -1. ,  0.5])
    >>> axis_coordinates(s, r, np.inf)  # a translation along z
    array([0., 0., 0., 0., 0., 1.])
    """
    if isinstance(s, sp.MatrixBase):
        if _is_infinite_pitch(h):
            return sp.Matrix.vstack(sp.zeros(3, 1), s)
        (r1, r2, r3), (s1, s2, s3) = r.flat(), s.flat()
        moment = [r2 * s3 - r3 * s2, r3 * s1 - r1 * s3, r1 * s2 - r2 * s1]
        if h != 0:
            moment = [m + h * si for m, si in zip(moment, (s1, s2, s3))]
        return sp.Matrix(6, 1, [s1, s2, s3] + moment)
    s = np.asarray(s, dtype=float)
    if _is_infinite_pitch(h):
        return np.concatenate([np.zeros_like(s), s], axis=-1)
    return np.concatenate([s, np.cross(r, s) + h * s], axis=-1)


# ---- checked, public -----------------------------------------------------------------


def _vector3(value, name):
    """A 3-vector: SymPy column (3, 1), or a float64 array (3,) or (N, 3)."""
    if is_symbolic(value):
        return as_sympy_matrix(value, name, (3, 1))
    return check_shape(as_float_array(value, name), name, (3,))


def skew(v):
    """The 3x3 skew-symmetric matrix [v] with [v] w = v x w.

    Parameters
    ----------
    v : array-like, shape (3,) or (N, 3), or a SymPy 3-vector
        The vector(s).

    Returns
    -------
    sympy.Matrix (3, 3) or ndarray, shape (3, 3) or (N, 3, 3)
        [v], exact for a SymPy vector.

    Examples
    --------
    [v] w is the cross product: (1, 2, 3) x (4, 5, 6) = (-3, 6, -3).

    >>> skew([1, 2, 3]) @ [4, 5, 6]
    array([-3.,  6., -3.])
    """
    v = _vector3(v, "v")
    if isinstance(v, sp.MatrixBase):
        return _skew_exact(v)
    return _skew(v)


def _elementary_rotation(theta, axis):
    """Rotation by ``theta`` about the x (0), y (1) or z (2) axis of the frame."""
    theta = as_scalar_or_batch(theta, "theta")
    i, j = [(1, 2), (2, 0), (0, 1)][axis]
    if isinstance(theta, sp.Basic):
        R = sp.eye(3)
        c, s = sp.cos(theta), sp.sin(theta)
        R[i, i], R[i, j], R[j, i], R[j, j] = c, -s, s, c
        return R
    R = np.zeros(theta.shape + (3, 3))
    R[..., axis, axis] = 1.0
    c, s = np.cos(theta), np.sin(theta)
    R[..., i, i], R[..., i, j], R[..., j, i], R[..., j, j] = c, -s, s, c
    return R


#: The sections rotx, roty and rotz share, to their Examples heading (filled in by
#: :func:`_docstrings.fill`).
_ELEMENTARY_SECTIONS = """Parameters
----------
theta : float, array-like of shape (N,), or a SymPy expression
    The angle (rad); N angles give a batch.

Returns
-------
ndarray, shape (3, 3) or (N, 3, 3), or sympy.Matrix (3, 3)
    The rotation matrix (exact when ``theta`` is symbolic).

Examples
--------"""


@fill(sections=_ELEMENTARY_SECTIONS)
def rotx(theta):
    """Rotation by ``theta`` about the x axis.

    {sections}

    >>> rotx(0.5)[1:, 1:].round(4)
    array([[ 0.8776, -0.4794],
           [ 0.4794,  0.8776]])
    """
    return _elementary_rotation(theta, 0)


@fill(sections=_ELEMENTARY_SECTIONS)
def roty(theta):
    """Rotation by ``theta`` about the y axis.

    {sections}

    A quarter turn about y carries z to x.

    >>> (roty(np.pi / 2) @ [0, 0, 1]).round(12) + 0.0
    array([1., 0., 0.])
    """
    return _elementary_rotation(theta, 1)


@fill(sections=_ELEMENTARY_SECTIONS)
def rotz(theta):
    """Rotation by ``theta`` about the z axis.

    {sections}

    A quarter turn about z carries x to y and y to -x (the columns of R are the
    images of x, y, z):

    >>> rotz(np.pi / 2)[:, :2].round(12) + 0.0
    array([[ 0., -1.],
           [ 1.,  0.],
           [ 0.,  0.]])
    """
    return _elementary_rotation(theta, 2)


def rot_axis(axis, theta):
    """Rotation by ``theta`` (rad) about a unit ``axis`` (Rodrigues' formula).

    R = I + sin(theta) [w] + (1 - cos(theta)) [w]^2, with w = axis / |axis|.

    Parameters
    ----------
    axis : array-like, shape (3,), non-zero (it is normalised), or a SymPy 3-vector
    theta : float, array of shape (N,), or a SymPy expression

    Returns
    -------
    sympy.Matrix (3, 3) if ``axis`` or ``theta`` is symbolic
        (a float angle then becomes a SymPy Float), else ndarray, shape (3, 3) or
        (N, 3, 3)

    Examples
    --------
    About z (the axis is normalised) it is :func:`rotz`:

    >>> rot_axis([0, 0, 2], np.pi / 2).round(12)
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])

    A third of a turn about (1, 1, 1) permutes the axes: x goes to y.

    >>> (rot_axis([1, 1, 1], 2 * np.pi / 3) @ [1, 0, 0]).round(12) + 0.0
    array([0., 1., 0.])
    """
    w = _unit_vector(axis, "axis")
    if isinstance(w, sp.MatrixBase) or is_symbolic(theta):
        theta = _exact_angle(theta, "theta")
        return _rodrigues_exact(_skew_exact(w), theta)
    theta = as_scalar_or_batch(theta, "theta")
    s = np.sin(theta)[..., None, None]
    c = np.cos(theta)[..., None, None]
    return _rodrigues(_skew(w), s, 1.0 - c)


def _exact_angle(theta, name):
    """One angle for an exact (SymPy) result: a float becomes a SymPy Float, a batch is
    refused."""
    if isinstance(theta, (list, tuple, np.ndarray, sp.MatrixBase)):
        raise TypeError(
            f"{name} must be a single number or SymPy expression when the result is "
            f"symbolic (SymPy in, SymPy out), got {describe(theta)}; for a batch of "
            "angles pass numbers"
        )
    return as_sympy_scalar(theta, name)


#: A numeric axis shorter than this (unitless) is taken as zero and refused: the old
#: name of :data:`screwkit.tolerances.ZERO_TOL`.
ZERO_AXIS = ZERO_TOL


def _unit_vector(value, name):
    v = _vector3(value, name)
    if isinstance(v, sp.MatrixBase):
        norm_squared = sp.trigsimp(sum(e**2 for e in v))  # cos^2 + sin^2 is 1
        if norm_squared == 0:
            raise ValueError(f"{name} must be a non-zero 3-vector, got {list(v)}")
        return v if norm_squared == 1 else v / sp.sqrt(norm_squared)
    if v.ndim != 1:
        raise ValueError(
            f"{name} must be a single 3-vector of shape (3,), got shape {v.shape}"
        )
    norm = _norm(v)
    if norm < ZERO_AXIS:
        raise ValueError(
            f"{name} must be a non-zero 3-vector (norm at least {ZERO_AXIS:g}), got "
            f"{v.tolist()}"
        )
    scale = np.abs(v).max()
    u = v / scale  # scaled first: the norm of [1e200, 0, 0] must not overflow to inf
    return u / np.linalg.norm(u)


def _norm(v):
    """|v| of a 1-D float array without overflow or underflow in the squares."""
    scale = np.abs(v).max()
    return 0.0 if scale == 0 else float(scale * np.linalg.norm(v / scale))


def transl(*p):
    """The pure translation by p = (x, y, z).

    Call as ``transl(x, y, z)`` or ``transl(p)`` with p of shape (3,) or (N, 3).

    Parameters
    ----------
    *p : three numbers x, y, z (m), or one array-like of shape (3,) or (N, 3)
        The translation; x, y and z may also be batches of one length N, or SymPy
        expressions.

    Returns
    -------
    ndarray, shape (4, 4) or (N, 4, 4), or sympy.Matrix (4, 4)
        The homogeneous transform [[I, p], [0, 1]].

    Examples
    --------
    >>> transl(1, 2, 3)[:3, 3]
    array([1., 2., 3.])
    """
    if len(p) == 3:
        p = [p[0], p[1], p[2]]
        if not is_symbolic(p):
            x, y, z = (as_float_array(v, n) for v, n in zip(p, "xyz"))
            try:
                p = np.stack(np.broadcast_arrays(x, y, z), -1)
            except ValueError:
                raise ValueError(
                    "x, y and z must be numbers or batches of one length, got shapes "
                    f"{x.shape}, {y.shape} and {z.shape}"
                ) from None
    elif len(p) == 1:
        p = p[0]
        if p is None:
            raise TypeError(
                "p must be a 3-vector (x, y, z) or a batch (N, 3), got None"
            )
    else:
        raise TypeError(
            f"transl takes a 3-vector p or three numbers x, y, z, got {len(p)} "
            "arguments"
        )
    return homogeneous(None, p)


def homogeneous(R=None, p=None):
    """The 4x4 transform [[R, p], [0, 1]] from a rotation ``R`` and a translation ``p``.

    Parameters
    ----------
    R : array-like, shape (3, 3) or (N, 3, 3); identity if None
    p : array-like, shape (3,) or (N, 3); zero if None

    Returns
    -------
    sympy.Matrix (4, 4) if either input is symbolic, else ndarray (4, 4) or (N, 4, 4)

    Examples
    --------
    Rotate a quarter turn about z, then shift by (1, 0, 0): the point x = 1 goes to
    (0, 1, 0) and then to (1, 1, 0).

    >>> T = homogeneous(rotz(np.pi / 2), [1, 0, 0])
    >>> (T @ [1, 0, 0, 1]).round(12) + 0.0
    array([1., 1., 0., 1.])
    """
    if is_symbolic(R) or is_symbolic(p):
        R = sp.eye(3) if R is None else check_rotation(R, "R")
        p = sp.zeros(3, 1) if p is None else as_sympy_matrix(p, "p", (3, 1))
        return sp.Matrix(
            sp.BlockMatrix([[sp.Matrix(R), p], [sp.zeros(1, 3), sp.ones(1, 1)]])
        )
    R = np.eye(3) if R is None else check_rotation(R, "R")
    p = np.zeros(3) if p is None else _vector3(p, "p")
    try:
        np.broadcast_shapes(R.shape[:-2], p.shape[:-1])
    except ValueError:
        raise ValueError(
            "R and p must be one of each or batches of one length, got R of shape "
            f"{R.shape} and p of shape {p.shape}"
        ) from None
    return _assemble(R, p)


def _assemble(R, p):
    """[[R, p], [0, 1]] from checked float arrays R (..., 3, 3) and p (..., 3)."""
    batch = np.broadcast_shapes(R.shape[:-2], p.shape[:-1])
    T = np.zeros(batch + (4, 4))
    T[..., :3, :3] = R
    T[..., :3, 3] = p
    T[..., 3, 3] = 1.0
    return T


def inv(T):
    """The inverse of a homogeneous transform, [[R^T, -R^T p], [0, 1]].

    Exact and cheaper than a general matrix inverse.

    Parameters
    ----------
    T : array-like, shape (4, 4) or (N, 4, 4), or a SymPy 4x4 matrix
        Homogeneous transform(s) (lengths in m).

    Returns
    -------
    ndarray, shape (4, 4) or (N, 4, 4), or sympy.Matrix (4, 4)
        The inverse transform(s).

    Examples
    --------
    >>> T = transl(1, 2, 3) @ homogeneous(rotz(0.3))
    >>> np.allclose(inv(T) @ T, np.eye(4))
    True
    """
    T = check_transform(T, "T")
    if isinstance(T, sp.MatrixBase):
        Rt = T[:3, :3].T
        return homogeneous(Rt, -Rt * T[:3, 3])
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    return _assemble(Rt, -np.einsum("...ij,...j->...i", Rt, T[..., :3, 3]))


def wrap_angle(angle):
    """Wrap angles into (-pi, pi].

    Parameters
    ----------
    angle : float or array-like of any shape
        Angles (rad).

    Returns
    -------
    float or ndarray of the same shape
        The angles plus a multiple of 2 pi, in (-pi, pi].

    Examples
    --------
    >>> float(wrap_angle(3 * np.pi / 2)), float(wrap_angle(-np.pi))
    (-1.5707963267948966, 3.141592653589793)
    """
    return _wrap_angle(as_scalar_or_batch(angle, "angle"))


def _wrap_angle(angle):
    """wrap_angle without the input check, for the numeric layer's own arrays."""
    return np.pi - np.mod(np.pi - angle, 2 * np.pi)


#: The axis parameters of twist_from_axis and screw_motion (filled in by fill).
_AXIS_PARAMETERS = """s : array-like, shape (3,), non-zero
    Direction of the axis (normalised here).
r : array-like, shape (3,)
    A point of the axis (m)."""


@fill(axis=_AXIS_PARAMETERS)
def twist_from_axis(s, r, h):
    """The unit twist of a screw axis, ordered [angular; linear].

    A rotation about the line through ``r`` with direction ``s`` and pitch ``h``
    (metres per radian) has twist (s; r x s + h s); a pure translation along
    ``s`` (``h = sympy.oo``) has twist (0; s). ``s`` is normalised.

    Parameters
    ----------
    {axis}
    h : float, a SymPy expression or ``sympy.oo``
        Pitch (m/rad); 0 for a revolute joint, ``sympy.oo`` for a prismatic one.

    Returns
    -------
    ndarray, shape (6,), or sympy.Matrix (6, 1)
        The twist [omega; v]: a SymPy matrix if any input is symbolic.

    Examples
    --------
    >>> twist_from_axis([0, 0, 1], [1, 0, 0], 0)
    array([ 0.,  0.,  1.,  0., -1.,  0.])
    """
    prismatic = _is_infinite_pitch(h)
    if is_symbolic(s) or is_symbolic(r) or (is_symbolic(h) and not prismatic):
        s = _unit_vector(as_sympy_matrix(s, "s", (3, 1)), "s")
        if prismatic:
            return axis_coordinates(s, None, sp.oo)
        return axis_coordinates(
            s, as_sympy_matrix(r, "r", (3, 1)), _pitch(h, exact=True)
        )
    s = _unit_vector(s, "s")
    if prismatic:
        return axis_coordinates(s, None, np.inf)
    r = _vector3(r, "r")
    if r.ndim != 1:
        raise ValueError(f"r must be a single point of shape (3,), got shape {r.shape}")
    return axis_coordinates(s, r, _pitch(h, exact=False))


_PITCH = (
    "h must be a pitch: a finite real number or SymPy expression (m/rad), or sympy.oo "
    "(or the float inf) for a translation"
)


def _pitch(h, exact):
    """A finite pitch (m/rad): a SymPy expression if ``exact``, else a float; the one
    check of a pitch after :func:`_is_infinite_pitch` (strings such as "inf" refused).
    """
    try:
        return as_sympy_scalar(h, "h") if exact else as_real_scalar(h, "h")
    except TypeError:
        raise TypeError(f"{_PITCH}, got {describe(h)}") from None
    except ValueError:
        raise ValueError(f"{_PITCH}; h must be finite, got {h!r}") from None


def exp_twist(twist, theta):
    """The rigid motion exp([twist] theta) as a 4x4 homogeneous transform.

    For a unit angular part w (|w| = 1) and linear part v:
    R = I + sin(theta)[w] + (1 - cos(theta))[w]^2 and
    p = (I theta + (1 - cos(theta))[w] + (theta - sin(theta))[w]^2) v.
    For w = 0 (a translation) R = I and p = v theta. A non-unit w is
    normalised and theta scaled by |w|.

    Parameters
    ----------
    twist : array-like, shape (6,), ordered [w; v], or a SymPy 6-vector
    theta : float, array of shape (N,), or a SymPy expression
        (rad, or m for a translation)

    Returns
    -------
    sympy.Matrix (4, 4) or ndarray, shape (4, 4) or (N, 4, 4)

    Examples
    --------
    A unit rotation about z through the origin turns by ``theta``:

    >>> exp_twist([0, 0, 1, 0, 0, 0], np.pi / 2).round(12)[:3, :3]
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])

    A pure translation (w = 0, v = x) moves by v theta:

    >>> exp_twist([0, 0, 0, 1, 0, 0], 2.0)[:3, 3]
    array([2., 0., 0.])
    """
    if is_symbolic(twist) or is_symbolic(theta):
        xi = as_sympy_matrix(twist, "twist", (6, 1))
        return _exp_twist_symbolic(xi, _exact_angle(theta, "theta"))
    xi = as_float_array(twist, "twist")
    if xi.shape != (6,):
        raise ValueError(
            f"twist must have shape (6,), ordered [w; v], got shape {xi.shape}"
        )
    theta = as_scalar_or_batch(theta, "theta")
    w, v = xi[:3], xi[3:]
    norm = _norm(w)
    if norm < ZERO_AXIS:
        with np.errstate(over="ignore"):
            p = theta[..., None] * v
        _check_finite_product(p, "twist * theta")
        return _assemble(np.eye(3), p)
    with np.errstate(over="ignore"):
        w, v, theta = w / norm, v / norm, theta * norm
    _check_finite_product(theta, "|w| * theta")
    W = _skew(w)
    W2 = W @ W
    s = np.sin(theta)[..., None, None]
    c1 = (2.0 * np.sin(theta / 2) ** 2)[
        ..., None, None
    ]  # 1 - cos, without cancellation
    t = theta[..., None, None]
    # theta - sin(theta) cancels for small theta: its series there
    # (error below 1e-20 rad)
    small = np.abs(theta) < SERIES_BELOW
    series = theta**3 / 6 - theta**5 / 120 + theta**7 / 5040
    t_minus_s = np.where(small, series, theta - np.sin(theta))[..., None, None]
    R = _rodrigues(W, s, c1)
    # p = G v with G = I theta + (1 - cos) [w] + (theta - sin) [w]^2, applied to v
    # directly
    with np.errstate(over="ignore", invalid="ignore"):
        p = t[..., 0] * v + c1[..., 0] * (W @ v) + t_minus_s[..., 0] * (W2 @ v)
    _check_finite_product(p, "twist * theta")
    return _assemble(R, p)


def _check_finite_product(value, what):
    """Finite inputs whose product overflows give a clear error, not a silent inf or
    NaN."""
    if not np.all(np.isfinite(value)):
        raise ValueError(
            f"{what} overflows float64: twist and theta must be far below 1e308 in size"
        )


def _exp_twist_symbolic(xi, theta):
    w, v = xi[:3, 0], xi[3:, 0]
    norm = sp.sqrt(sum(e**2 for e in w))
    if norm == 0:
        return homogeneous(sp.eye(3), v * theta)
    if norm != 1:
        w, v, theta = w / norm, v / norm, theta * norm
    W = _skew_exact(w)
    R = _rodrigues_exact(W, theta)
    G = theta * sp.eye(3) + (1 - sp.cos(theta)) * W + (theta - sp.sin(theta)) * W * W
    return homogeneous(R.applyfunc(sp.simplify), (G * v).applyfunc(sp.simplify))


@fill(axis=_AXIS_PARAMETERS)
def screw_motion(s, r, h, theta):
    """The motion along a screw axis: rotate by theta about (s, r), advance h theta.

    With ``h = sympy.oo`` the motion is a translation by ``theta`` metres along ``s``.
    Equivalent to ``exp_twist(twist_from_axis(s, r, h), theta)``.

    Parameters
    ----------
    {axis}
    h : float, a SymPy expression or ``sympy.oo``
        Pitch (m/rad).
    theta : float, array-like of shape (N,), or a SymPy expression
        The screw's magnitude: rad, or m for ``h = sympy.oo``.

    Returns
    -------
    ndarray, shape (4, 4) or (N, 4, 4), or sympy.Matrix (4, 4)
        The homogeneous transform (exact if any input is symbolic).

    Examples
    --------
    >>> screw_motion([0, 0, 1], [1, 0, 0], 0, np.pi)[:3, 3].round(12)
    array([2., 0., 0.])
    """
    return exp_twist(twist_from_axis(s, r, h), theta)
