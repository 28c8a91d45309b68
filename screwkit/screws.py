"""Screws, twists and wrenches: exact 6-vectors ordered [angular; linear].

A screw with axis direction s through the point r and pitch h is
$ = (s; r x s + h s), and (0; s) for h = oo. A twist is (w; v), a wrench (f; m).
The reciprocal product $1 @ $2 = s1 . s0_2 + s0_1 . s2 is, for a twist and a
wrench, the instantaneous power.

>>> import sympy as sp
>>> t = Twist.from_axis([0, 0, 1], [1, 0, 0], 0)  # revolute about z through (1, 0, 0)
>>> t.vector.T
Matrix([[0, 0, 1, 0, -1, 0]])
>>> w = Wrench.from_axis([0, 0, 1], [0, 0, 0], sp.oo)  # a couple about z
>>> t @ w
1
"""

import numpy as np
import sympy as sp

from ._checks import (
    as_float_array,
    as_sympy_matrix,
    as_sympy_scalar,
    check_transform,
    describe,
    is_symbolic,
)
from .lie import adjoint
from .transforms import _is_infinite_pitch, _pitch, axis_coordinates, exp_twist

__all__ = ["Screw", "Twist", "Wrench", "axis_coordinates"]


class Screw:
    """A screw as an exact 6-vector [angular; linear].

    See Twist and Wrench for the typed kinds.

    Parameters
    ----------
    vector : array-like of 6 numbers or SymPy expressions, or a SymPy 6x1 matrix
        The coordinates [angular; linear], kept exact (``self.vector``).

    Examples
    --------
    (s; s0) = (z; 2 z): an axis through the origin along z (s0 parallel to s) with
    pitch s . s0 / s . s = 2.

    >>> screw = Screw([0, 0, 1, 0, 0, 2])
    >>> screw.pitch
    2
    """

    #: the kind of screw as a word, for messages and captions
    noun = "screw"

    def __init__(self, vector):
        self.vector = as_sympy_matrix(vector, "vector", (6, 1))

    # --- constructors -------------------------------------------------------------
    @classmethod
    def from_axis(cls, s, r, h):
        """The screw of axis direction ``s`` through ``r`` with pitch ``h``.

        ``s`` may have any non-zero length and is not normalised: its length is the
        screw's magnitude ([s; r x s + h s]), exact or float alike.

        Parameters
        ----------
        s, r : 3-sequences of numbers or SymPy expressions
            The axis direction and a point of the axis (m); r is ignored when h = oo.
        h : number, SymPy expression or ``sympy.oo``
            0 (revolute), a finite pitch (helical, m/rad), or ``sympy.oo`` (prismatic).

        Returns
        -------
        Screw
            A screw of this class (Screw, Twist or Wrench).

        Examples
        --------
        The z direction through (0, 1, 0): moment r x s = y x z = x, plus h s.

        >>> Screw.from_axis([0, 0, 1], [0, 1, 0], 0)
        Screw([0, 0, 1, 1, 0, 0])
        >>> Screw.from_axis([0, 0, 1], [0, 1, 0], 2)
        Screw([0, 0, 1, 1, 0, 2])
        """
        s = as_sympy_matrix(s, "s", (3, 1))
        if all(e == 0 for e in s):
            raise ValueError(f"s must be a non-zero direction, got {list(s)}")
        if _is_infinite_pitch(h):
            return cls._checked(axis_coordinates(s, None, sp.oo))
        h = _pitch(h, exact=True)
        return cls._checked(axis_coordinates(s, as_sympy_matrix(r, "r", (3, 1)), h))

    @classmethod
    def _checked(cls, vector):
        """A screw from a 6 x 1 SymPy matrix built from checked parts
        (no second check)."""
        screw = cls.__new__(cls)
        screw.vector = vector
        return screw

    @classmethod
    def from_vector(cls, vector):
        """The screw with the given 6 coordinates [angular; linear].

        Parameters
        ----------
        vector : array-like of 6 numbers or SymPy expressions
            The coordinates [angular; linear].

        Returns
        -------
        Screw
            A screw of this class (Screw, Twist or Wrench) holding ``vector``.

        Examples
        --------
        A pure translation along x, (0; x): its pitch is infinite.

        >>> t = Twist.from_vector([0, 0, 0, 1, 0, 0])
        >>> t, t.pitch
        (Twist([0, 0, 0, 1, 0, 0]), oo)
        """
        return cls(vector)

    # --- geometry ----------------------------------------------------------------
    @property
    def primary(self):
        """The first (angular) 3-vector s (a twist's w, a wrench's f)."""
        return self.vector[:3, 0]

    @property
    def secondary(self):
        """The second (linear) 3-vector, r x s + h s."""
        return self.vector[3:, 0]

    def _check_not_zero(self, quantity):
        """The zero screw has no axis: its pitch, direction and point are undefined."""
        if all(sp.simplify(e) == 0 for e in self.vector):
            raise ValueError(
                f"the {quantity} of the zero {self.noun} is undefined: it has no "
                "axis (every coordinate is 0)"
            )

    @property
    def pitch(self):
        """h = (s . s0) / (s . s); ``sympy.oo`` when s = 0 (a translation or couple).

        The zero screw has no pitch: ``ValueError``.
        """
        s, s0 = self.primary, self.secondary
        ss = s.dot(s)
        if sp.simplify(ss) == 0:
            self._check_not_zero("pitch")
            return sp.oo
        return sp.simplify(s.dot(s0) / ss)

    @property
    def direction(self):
        """The direction of the axis (not normalised), s, or s0 for an infinite pitch.

        The zero screw has no direction: ``ValueError``.
        """
        s = self.primary
        if all(sp.simplify(e) == 0 for e in s):
            self._check_not_zero("direction")
            return self.secondary
        return s

    @property
    def point(self):
        """The point of the axis nearest the origin, s x s0 / (s . s); None for an
        infinite pitch.

        The zero screw has no axis: ``ValueError``.
        """
        s, s0 = self.primary, self.secondary
        ss = sp.simplify(s.dot(s))
        if ss == 0:
            self._check_not_zero("point")
            return None
        return (s.cross(s0) / ss).applyfunc(sp.simplify)

    # --- algebra -----------------------------------------------------------------
    # NumPy defers to these operators (no element-wise broadcast of an array with a
    # screw)
    __array_ufunc__ = None

    def _same_kind(self, other, operation):
        if not isinstance(other, Screw):
            raise TypeError(
                f"cannot {operation} a {self.noun} and {describe(other)}: the other "
                f"operand must be a {self.noun} too (Twist.from_vector, "
                "Wrench.from_vector make one from a 6-vector)"
            )
        if type(other) is not type(self):
            raise TypeError(
                f"cannot {operation} a {self.noun} and a {other.noun}: they live in "
                "different spaces (use @ for the reciprocal product)"
            )
        return True

    def __neg__(self):
        return type(self)(-self.vector)

    def __add__(self, other):
        self._same_kind(other, "add")
        return type(self)(self.vector + other.vector)

    __radd__ = __add__

    def __sub__(self, other):
        self._same_kind(other, "subtract")
        return type(self)(self.vector - other.vector)

    def __rsub__(self, other):
        self._same_kind(other, "subtract")
        return type(self)(other.vector - self.vector)

    def __mul__(self, scalar):
        if isinstance(scalar, Screw):
            raise TypeError(
                f"cannot multiply a {self.noun} by a {scalar.noun}: a {self.noun} must "
                "be scaled by one number (use @ for the reciprocal product)"
            )
        if isinstance(scalar, (sp.MatrixBase, list, tuple, np.ndarray)):
            raise TypeError(
                f"a {self.noun} is scaled by one number, got {describe(scalar)}"
            )
        return type(self)(self.vector * as_sympy_scalar(scalar, "scalar"))

    __rmul__ = __mul__

    def __matmul__(self, other):
        """The reciprocal product s . s0' + s0 . s' (for a twist and a wrench: the
        power)."""
        if not isinstance(other, Screw):
            raise TypeError(
                f"the reciprocal product @ takes two screws (a twist and a wrench), "
                f"got a {self.noun} and {describe(other)}"
            )
        return sp.expand(
            self.primary.dot(other.secondary) + self.secondary.dot(other.primary)
        )

    def transform(self, T):
        """This screw written in another frame: Ad(T) $.

        A twist (w; v) becomes (R w; R v + p x R w); a wrench (f; m), in the same
        [angular; linear] order, changes the same way (Modern Robotics, ordering (m; f),
        writes this as the transposed adjoint: F_b = Ad(T_ab)^T F_a).

        Parameters
        ----------
        T : array-like or SymPy matrix, shape (4, 4)
            The pose (R, p) of this screw's frame in the other frame (m).

        Returns
        -------
        Screw
            A screw of the same class: exact for a SymPy T; a float T gives Float
            coordinates.

        Examples
        --------
        A spin about the z axis of a frame placed at p = (1, 0, 0), written in the
        base frame: a spin about the line x = 1, moment p x z = -y.

        >>> import sympy as sp
        >>> T = sp.Matrix([[1, 0, 0, 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
        >>> Twist([0, 0, 1, 0, 0, 0]).transform(T)
        Twist([0, 0, 1, 0, -1, 0])
        """
        T = check_transform(
            T if isinstance(T, sp.MatrixBase) else as_float_array(T, "T"), "T"
        )
        if not isinstance(T, sp.MatrixBase):
            if T.shape != (4, 4):
                raise ValueError(
                    f"T must be one pose of shape (4, 4), got shape {T.shape}"
                )
            T = sp.Matrix(T)
        return type(self)._checked((adjoint(T) * self.vector).applyfunc(sp.expand))

    def __eq__(self, other):
        return type(other) is type(self) and self.vector == other.vector

    def __hash__(self):
        return hash((type(self), tuple(self.vector)))

    def __repr__(self):
        return f"{type(self).__name__}({list(self.vector)})"

    def _repr_latex_(self):
        return f"$\\mathrm{{{type(self).__name__}}}\\;{sp.latex(self.vector.T)}^T$"


class Twist(Screw):
    """A twist (w; v): a joint's motion, or a platform's instantaneous motion.

    Parameters
    ----------
    vector : array-like of 6 numbers or SymPy expressions
        The coordinates (w; v) (rad/s, m/s, or per unit joint rate).

    Examples
    --------
    A spin about z does no work against a force along z (reciprocal: product 0),
    and 10 W against a couple of 10 N m about z:

    >>> spin = Twist([0, 0, 1, 0, 0, 0])
    >>> spin @ Wrench.from_axis([0, 0, 1], [1, 0, 0], 0), spin @ Wrench([0] * 5 + [10])
    (0, 10)
    """

    #: the kind of screw as a word, for messages and captions
    noun = "twist"

    def exp(self, theta):
        """The rigid motion exp([V] theta) of moving ``theta`` along this twist.

        See :func:`screwkit.transforms.exp_twist`.

        Parameters
        ----------
        theta : float, array-like of shape (N,), or a SymPy expression
            The distance moved along the twist (rad, or m for a pure translation).

        Returns
        -------
        sympy.Matrix (4, 4) or ndarray, shape (4, 4) or (N, 4, 4)
            Exact (a SymPy matrix) when theta or the twist holds SymPy symbols or theta
            is a SymPy number; float64 for a numeric theta.

        Examples
        --------
        >>> np.round(Twist.from_axis([0, 0, 1], [1, 0, 0], 0).exp(np.pi)[:3, 3], 12)
        array([2., 0., 0.])
        """
        if is_symbolic(theta) or self.vector.free_symbols:
            return exp_twist(self.vector, theta)
        return exp_twist(np.array(self.vector, dtype=float).ravel(), theta)


class Wrench(Screw):
    """A wrench (f; m): a force and moment, or a constraint a limb applies.

    Parameters
    ----------
    vector : array-like of 6 numbers or SymPy expressions
        The coordinates (f; m) (N, N m).

    Examples
    --------
    10 N down through (1, 0, 0): its moment about the origin is r x f = 10 y.

    >>> Wrench.from_axis([0, 0, -10], [1, 0, 0], 0)
    Wrench([0, 0, -10, 0, 10, 0])
    """

    #: the kind of screw as a word, for messages and captions
    noun = "wrench"
