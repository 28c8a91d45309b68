"""Limbs for the mobility zeroth step: each builder returns a list of (s, r, h) triples.

(The module is not called ``joints``: that name means the joint kinds
:class:`screwkit.Joint`, a chain's ``joints`` and the DH rows ``Link.revolute``.)

A limb reads like its name: ``prismatic(x) + revolute(x, A) + universal(y, z, B)`` is a
PRU limb. Multi-freedom joints are sets of 1-freedom screws through one point: C = R + P
on one axis, U = two crossing R, S = three crossing R.

>>> import sympy as sp
>>> len(spherical([0, 0, 1]))
3
"""

import random

import sympy as sp

from ._checks import as_sympy_matrix, as_sympy_scalar, check_rotation, describe
from .screws import Screw, Wrench
from .tolerances import SAMPLE_ZERO_TOL, ZERO_TOL
from .transforms import _is_infinite_pitch

__all__ = [
    "revolute",
    "prismatic",
    "helical",
    "cylindrical",
    "universal",
    "spherical",
    "parallelogram",
    "rotate_limb",
    "translate_limb",
]


def _vec(v, name):
    return as_sympy_matrix(v, name, (3, 1))


def _direction(v, name):
    v = _vec(v, name)
    if all(e == 0 for e in v):
        raise ValueError(f"{name} must be a non-zero direction, got {list(v)}")
    return v


def _is_zero(expr):
    """True if ``expr`` is zero for every value of its symbols: exactly after expansion,
    or, when trigonometric identities are needed, at three random points (to
    ``SAMPLE_ZERO_TOL``)."""
    expr = sp.expand(expr)
    if expr == 0:
        return True
    symbols = sorted(expr.free_symbols, key=str)
    if not symbols:
        return abs(complex(expr.evalf())) < ZERO_TOL
    rng = random.Random(7)
    for _ in range(3):
        point = {x: sp.Float(rng.uniform(0.3, 1.7)) for x in symbols}
        if abs(complex(expr.evalf(subs=point))) > SAMPLE_ZERO_TOL:
            return False
    return True


def _parallel(u, v):
    return all(_is_zero(e) for e in u.cross(v))


def revolute(s, r):
    """R: rotation about the axis ``s`` through the point ``r``.

    Parameters
    ----------
    s : 3-sequence of numbers or SymPy expressions, non-zero
        The axis direction.
    r : 3-sequence of numbers or SymPy expressions
        A point of the axis (m).

    Returns
    -------
    list of (sympy.Matrix, sympy.Matrix, int)
        One (s, r, h) triple, h = 0.

    Examples
    --------
    The vertical axis through (1, 0, 0); its screw (s; r x s) has moment -y:

    >>> [joint] = revolute([0, 0, 1], [1, 0, 0])
    >>> [list(v) for v in joint[:2]], joint[2], Screw.from_axis(*joint)
    ([[0, 0, 1], [1, 0, 0]], 0, Screw([0, 0, 1, 0, -1, 0]))
    """
    return [(_direction(s, "s"), _vec(r, "r"), 0)]


def prismatic(s, r=(0, 0, 0)):
    """P: translation along ``s``.

    Parameters
    ----------
    s : 3-sequence of numbers or SymPy expressions, non-zero
        The direction of travel.
    r : 3-sequence, optional
        A point (m), only for drawing: a prismatic twist has no position.

    Returns
    -------
    list of (sympy.Matrix, sympy.Matrix, sympy.oo)
        One (s, r, h) triple, h = oo.

    Examples
    --------
    A slide along x: the screw (0; s), whatever the point.

    >>> [joint] = prismatic([1, 0, 0])
    >>> joint[2], Screw.from_axis(*joint)
    (oo, Screw([0, 0, 0, 1, 0, 0]))
    """
    return [(_direction(s, "s"), _vec(r, "r"), sp.oo)]


def helical(s, r, h):
    """H: rotation about (s, r) with translation h per radian along it.

    Parameters
    ----------
    s, r : 3-sequences of numbers or SymPy expressions
        The axis, as for :func:`revolute`.
    h : number or SymPy expression
        The pitch (m/rad), finite.

    Returns
    -------
    list of (sympy.Matrix, sympy.Matrix, sympy.Expr)
        One (s, r, h) triple.

    Examples
    --------
    A screw thread along z advancing 1 cm per radian: its screw is (z; h z).

    >>> [joint] = helical([0, 0, 1], [0, 0, 0], sp.Rational(1, 100))
    >>> Screw.from_axis(*joint)
    Screw([0, 0, 1, 0, 0, 1/100])
    """
    if isinstance(h, (str, bytes)) or h is None or _is_infinite_pitch(h):
        raise TypeError(
            "h must be a finite pitch (m/rad): a number or a SymPy expression, got "
            f"{describe(h)}"
        )
    return [(_direction(s, "s"), _vec(r, "r"), as_sympy_scalar(h, "h"))]


def cylindrical(s, r):
    """C: rotation about and translation along the same axis.

    Parameters
    ----------
    s, r : 3-sequences of numbers or SymPy expressions
        The axis, as for :func:`revolute`.

    Returns
    -------
    list of (s, r, h) triples
        R then P on the axis (h = 0, then h = oo).

    Examples
    --------
    >>> [Screw.from_axis(*joint) for joint in cylindrical([0, 0, 1], [1, 0, 0])]
    [Screw([0, 0, 1, 0, -1, 0]), Screw([0, 0, 0, 0, 0, 1])]
    """
    return revolute(s, r) + prismatic(s, r)


def universal(s1, s2, r):
    """U: two revolute axes s1, s2 crossing at r.

    Parameters
    ----------
    s1, s2 : 3-sequences of numbers or SymPy expressions
        The two axis directions; they must not be parallel.
    r : 3-sequence of numbers or SymPy expressions
        The point where they cross (m).

    Returns
    -------
    list of (s, r, h) triples
        Two revolute joints (h = 0).

    Examples
    --------
    Axes x and y crossing at (0, 0, 1): moments r x s = z x x = y and z x y = -x.

    >>> [Screw.from_axis(*joint) for joint in universal([1, 0, 0], [0, 1, 0],
    ...                                                 [0, 0, 1])]
    [Screw([1, 0, 0, 0, 1, 0]), Screw([0, 1, 0, -1, 0, 0])]
    """
    first, second = revolute(_vec(s1, "s1"), r), revolute(_vec(s2, "s2"), r)
    if _parallel(first[0][0], second[0][0]):
        raise ValueError(
            "s1 and s2 of a universal joint must not be parallel, got s1 = "
            f"{list(first[0][0])} and s2 = {list(second[0][0])} "
            "(two parallel axes make a planar pair, not a U)"
        )
    return first + second


def spherical(r, axes=((1, 0, 0), (0, 1, 0), (0, 0, 1))):
    """S: three independent revolute axes through the centre r.

    Parameters
    ----------
    r : 3-sequence of numbers or SymPy expressions
        The centre (m).
    axes : three 3-sequences, optional
        Independent (not coplanar) axis directions; x, y and z by default.

    Returns
    -------
    list of (s, r, h) triples
        Three revolute joints (h = 0), each axis through the centre r.

    Examples
    --------
    A ball joint at the origin: rotations about x, y and z.

    >>> [Screw.from_axis(*joint) for joint in spherical([0, 0, 0])]
    [Screw([1, 0, 0, 0, 0, 0]), Screw([0, 1, 0, 0, 0, 0]), Screw([0, 0, 1, 0, 0, 0])]
    """
    if isinstance(axes, (str, bytes)) or not hasattr(axes, "__len__") or len(axes) != 3:
        raise ValueError(
            f"axes of a spherical joint must be three directions, got {describe(axes)}"
        )
    first = _direction(axes[0], "axes[0]")
    centre = _vec(r, "r")  # checked in the order a revolute() per axis would check them
    joints = [(first, centre, 0)] + [
        (_direction(axis, f"axes[{k}]"), centre.copy(), 0)
        for k, axis in enumerate(axes)
        if k
    ]
    if _is_zero(sp.Matrix.hstack(*(s for s, _, _ in joints)).det()):
        raise ValueError(
            "axes of a spherical joint must be independent (not in one plane), got "
            f"{[list(s) for s, _, _ in joints]}"
        )
    return joints


def parallelogram(s, a1, a2, b1, b2):
    """Pa: four parallel revolute axes s at the corners A1, A2 (base side) and B1, B2.

    The corners must make a parallelogram: B1 - A1 = B2 - A2
    (equal, parallel long sides), with A1 != A2 and B1 != A1.

    Parameters
    ----------
    s : 3-sequence of numbers or SymPy expressions, non-zero
        The common direction of the four axes.
    a1, a2 : 3-sequences of numbers or SymPy expressions
        The base-side corners A1, A2 (m).
    b1, b2 : 3-sequences of numbers or SymPy expressions
        The other corners B1, B2 (m).

    Returns
    -------
    list of (s, r, h) triples
        Four revolute joints (h = 0), one at each corner.

    Examples
    --------
    A unit square in the xz plane, hinged about y at its corners:

    >>> limb = parallelogram([0, 1, 0], [0, 0, 0], [1, 0, 0], [0, 0, 1], [1, 0, 1])
    >>> [list(r) for _, r, _ in limb]
    [[0, 0, 0], [1, 0, 0], [0, 0, 1], [1, 0, 1]]
    """
    corners = [
        _vec(c, name) for c, name in ((a1, "a1"), (a2, "a2"), (b1, "b1"), (b2, "b2"))
    ]
    A1, A2, B1, B2 = corners
    if not all(_is_zero(e) for e in (B1 - A1) - (B2 - A2)):
        raise ValueError(
            "a1, a2, b1, b2 must be the corners of a parallelogram "
            f"(b1 - a1 = b2 - a2), got b1 - a1 = {list(B1 - A1)} and b2 - a2 = "
            f"{list(B2 - A2)}"
        )
    for P, Q, names in ((A1, A2, "a1 and a2"), (A1, B1, "a1 and b1")):
        if all(_is_zero(e) for e in P - Q):
            raise ValueError(
                f"{names} of a parallelogram must be different points, got {list(P)} "
                "for both"
            )
    s = _direction(s, "s")
    return [(s.copy(), corner, 0) for corner in corners]


def _check_limb(limb, name="limb"):
    """A limb: a list of (s, r, h) triples, as every builder here returns."""
    if not isinstance(limb, (list, tuple)) or not all(
        isinstance(joint, (list, tuple)) and len(joint) == 3 for joint in limb
    ):
        raise TypeError(
            f"{name} must be a list of (s, r, h) triples (e.g. revolute(s, r) + "
            f"prismatic(s)), got {describe(limb)}"
        )
    return limb


def rotate_limb(limb, R):
    """The limb turned by the rotation matrix R (3x3) about the origin of the fixed
    frame.

    R must be a rotation (orthonormal, determinant +1): a scaling or a reflection is
    refused.

    Parameters
    ----------
    limb : list of (s, r, h) triples
        A limb, as the builders here return.
    R : array-like or SymPy matrix, shape (3, 3)
        The rotation.

    Returns
    -------
    list of (s, r, h) triples
        (R s, R r, h) for each joint.

    Examples
    --------
    A quarter turn about z carries the x axis through (1, 0, 0) to the y axis
    through (0, 1, 0):

    >>> quarter_turn = [[0, -1, 0], [1, 0, 0], [0, 0, 1]]
    >>> [(s, r, h)] = rotate_limb(revolute([1, 0, 0], [1, 0, 0]), quarter_turn)
    >>> list(s), list(r), h
    ([0, 1, 0], [0, 1, 0], 0)
    """
    _check_limb(limb)
    if not (isinstance(R, sp.MatrixBase) and _exact_rotation(R)):
        R = check_rotation(R, "R")  # refuses a scaling or a reflection, with the reason
    rows = as_sympy_matrix(R, "R", (3, 3)).tolist()

    def turn(v, name):
        # R v entry by entry (no matrix product), each entry expanded
        v = _vec(v, name).flat()
        return sp.Matrix(
            3,
            1,
            [
                sp.expand(sp.Add(*[c * e for c, e in zip(row, v) if c != 0 and e != 0]))
                for row in rows
            ],
        )

    return [(turn(s, "s"), turn(r, "r"), h) for s, r, h in limb]


def _exact_rotation(R):
    """True if R is a constant 3x3 SymPy matrix with R^T R = I and det R = 1 exactly."""
    if R.shape != (3, 3) or R.free_symbols or R.has(sp.Float):
        return False
    key = tuple(R.flat())
    if (
        key not in _EXACT_ROTATIONS
    ):  # the same few turns (by 2 pi k / n) come back often
        gram = (R.T * R).applyfunc(sp.expand)
        _EXACT_ROTATIONS[key] = gram == sp.eye(3) and sp.expand(R.det()) == 1
    return _EXACT_ROTATIONS[key]


_EXACT_ROTATIONS = {}


def translate_limb(limb, p):
    """The limb moved by the vector p.

    Parameters
    ----------
    limb : list of (s, r, h) triples
        A limb, as the builders here return.
    p : 3-sequence of numbers or SymPy expressions
        The translation (m).

    Returns
    -------
    list of (s, r, h) triples
        (s, r + p, h) for each joint.

    Examples
    --------
    >>> [(s, r, h)] = translate_limb(revolute([0, 0, 1], [0, 0, 0]), [1, 2, 0])
    >>> list(s), list(r), h
    ([0, 0, 1], [1, 2, 0], 0)
    """
    _check_limb(limb)
    p = _vec(p, "p")
    return [(_vec(s, "s"), _vec(r, "r") + p, h) for s, r, h in limb]


def check_limbs(limbs, twists=True):
    """``limbs`` as given if it is a non-empty list of non-empty limbs, each joint an
    (s, r, h) triple (or a Twist, with ``twists``); else the error naming the limb and
    joint at fault."""
    if not isinstance(limbs, (list, tuple)) or not limbs:
        raise ValueError(
            f"limbs must be a non-empty list of limbs, got {describe(limbs)}"
        )
    expected = "an (s, r, h) triple or a Twist" if twists else "an (s, r, h) triple"
    for i, limb in enumerate(limbs):
        if not isinstance(limb, (list, tuple)) or not limb:
            raise ValueError(
                f"limb {i} must be a non-empty list of (s, r, h) joint screws, got "
                f"{limb!r}"
            )
        for j, joint in enumerate(limb):
            if twists and isinstance(joint, Screw):
                if isinstance(joint, Wrench):
                    raise TypeError(
                        f"limb {i}, joint {j} is a wrench; a limb is made of joint "
                        "twists"
                    )
                continue
            if not isinstance(joint, (list, tuple)) or len(joint) != 3:
                raise TypeError(
                    f"limb {i}, joint {j} must be {expected}, got {describe(joint)}"
                )
    return limbs
