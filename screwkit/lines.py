"""Lines in Plücker coordinates, the central axis of a wrench, dependent sets of lines.

A line through the point p with direction w is the 6-vector (w; m), m = p x w, ordered
as a screw of pitch 0 ([angular; linear]). Its coordinates are homogeneous (any non-zero
multiple is the same line) and satisfy the Klein quadric w . m = 0; w is not 0 (lines
at infinity, (0; m), are not lines here). The reciprocal product of two lines,
w_a . m_b + w_b . m_a, is their *mutual moment*: 0 exactly when they meet or are
parallel.

Exact input (integers, rationals, square roots, SymPy numbers) gives exact answers
(SymPy); any float gives floats. Symbols without a value are refused: whether two lines
meet is then not a yes or no. Float decisions (parallel, meeting, rank) use relative
tolerances of :mod:`screwkit.tolerances` with lengths measured against the lines' own
size, so the same lines in millimetres give the same answers, scaled.

>>> a = Line.through([0, 0, 0], [1, 0, 0])  # the x axis
>>> b = Line.through([0, 0, 1], [0, 1, 1])  # the line parallel to y at height 1
>>> distance(a, b), mutual_moment(a, b)
(1, -1)
>>> intersection(a, Line.through([2, -1, 0], [2, 1, 0])).T
Matrix([[2, 0, 0]])
"""

from typing import NamedTuple

import numpy as np
import sympy as sp

from . import _line_geometry
from ._checks import (
    as_float_array,
    as_sympy_matrix,
    check_positive,
    check_transform,
    describe,
)
from .screws import Screw, Twist, Wrench
from .systems import ScrewSystem
from .tolerances import (
    KLEIN_TOL,
    LENGTH_TOL,
    LINE_ANGLE_TOL,
    LINE_RANK_TOL,
    length_scale,
)

__all__ = [
    "CentralAxis",
    "CommonNormal",
    "Dependency",
    "Line",
    "central_axis",
    "common_normal",
    "dependency",
    "distance",
    "intersection",
    "mutual_moment",
]


# ---- numbers: exact or float ---------------------------------------------------------


def _has_float(value):
    """True if ``value`` (a number, nested sequence, array or SymPy object) holds a
    float."""
    if isinstance(value, (float, np.floating)):
        return True
    if isinstance(value, np.ndarray):
        if value.dtype.kind == "f":
            return True
        if value.dtype == object:
            return any(_has_float(v) for v in value.flat)
        return False
    if isinstance(value, (sp.Basic, sp.MatrixBase)):
        return value.has(sp.Float)
    if isinstance(value, (list, tuple)):
        return any(_has_float(v) for v in value)
    return False


def _vector(value, name, size, exact):
    """``value`` as an exact SymPy column of ``size`` numbers or a float array."""
    if exact:
        v = as_sympy_matrix(value, name, (size, 1))
        symbols = sorted(str(s) for s in v.free_symbols)
        if symbols:
            raise ValueError(
                f"{name} must hold numbers, got the symbols {symbols} with no value: "
                "substitute numbers (expr.subs) before asking where lines meet"
            )
        return v
    if isinstance(value, sp.MatrixBase):
        value = [sp.sympify(e) for e in value]
    v = as_float_array(value, name)
    if v.shape not in ((size,), (size, 1), (1, size)):
        raise ValueError(f"{name} must have shape ({size},), got shape {v.shape}")
    return v.reshape(size)


def _w(v):
    """The direction half of a 6-vector (a SymPy column stays a column)."""
    return v[:3, :] if isinstance(v, sp.MatrixBase) else v[:3]


def _m(v):
    """The moment half of a 6-vector."""
    return v[3:, :] if isinstance(v, sp.MatrixBase) else v[3:]


def _zero(x, exact):
    return sp.simplify(x) == 0 if exact else x == 0


def _dot(x, y):
    return x.dot(y) if isinstance(x, sp.MatrixBase) else float(np.dot(x, y))


def _cross(x, y):
    return x.cross(y) if isinstance(x, sp.MatrixBase) else np.cross(x, y)


def _norm(x):
    return (
        sp.sqrt(x.dot(x)) if isinstance(x, sp.MatrixBase) else float(np.linalg.norm(x))
    )


def _simplify(x):
    if isinstance(x, sp.MatrixBase):
        return x.applyfunc(sp.simplify)
    return sp.simplify(x) if isinstance(x, sp.Basic) else x


# ---- the line ------------------------------------------------------------------------


class Line:
    """A line in Plücker coordinates (w; m): direction w, moment m = p x w.

    Parameters
    ----------
    plucker : array-like of 6 numbers, a SymPy 6-vector, or a Screw of pitch 0
        The coordinates (w; m): w (any non-zero length, unitless) and m (m, for a unit
        w). Exact when no entry is a float. They must satisfy w . m = 0 (exactly, or
        for floats within ``KLEIN_TOL`` of |w| |m|, and the small excess is then
        removed from m).

    Examples
    --------
    >>> L = Line([0, 0, 1, 0, -2, 0])  # parallel to z through (2, 0, 0)
    >>> L.point.T
    Matrix([[2, 0, 0]])
    >>> Line([0, 0, 1, 0, 0, 1])
    Traceback (most recent call last):
    ...
    ValueError: plucker must satisfy w . m = 0 (the Klein quadric) to be a line, got w . m = 1 for w = [0, 0, 1], m = [0, 0, 1]
    """  # noqa: E501 (the doctest's ValueError is one line)

    def __init__(self, plucker):
        if isinstance(plucker, Line):
            self._v, self.exact = plucker._v, plucker.exact
            return
        if isinstance(plucker, Screw):
            plucker = plucker.vector
        exact = not _has_float(plucker)
        v = _vector(plucker, "plucker", 6, exact)
        self._set(v, exact, "plucker")

    def _set(self, v, exact, name):
        w, m = _w(v), _m(v)
        if exact:
            w = sp.Matrix(w)
            m = sp.Matrix(m)
        if all(_zero(e, exact) for e in w):
            raise ValueError(
                f"{name} must have a non-zero direction w (a line at infinity (0; m) "
                "is "
                f"not a line), got w = {list(w)}"
            )
        wm = _dot(w, m)
        if exact:
            wm = sp.simplify(wm)
            if wm != 0:
                raise ValueError(
                    f"{name} must satisfy w . m = 0 (the Klein quadric) to be a line, "
                    f"got w . m = {wm} for w = {list(w)}, m = {list(m)}"
                )
            self._v = sp.Matrix.vstack(w, m)
        else:
            if abs(wm) > KLEIN_TOL * _norm(w) * _norm(m):
                raise ValueError(
                    f"{name} must satisfy w . m = 0 (the Klein quadric) to be a line, "
                    f"got w . m = {wm:.3g} for w = {list(w)}, m = {list(m)}"
                )
            m = m - wm / _dot(w, w) * w
            self._v = np.concatenate([w, m])
        self.exact = exact

    @classmethod
    def _of(cls, v, exact):
        line = cls.__new__(cls)
        line._v, line.exact = v, exact
        return line

    # --- constructors ----------------------------------------------------------------
    @classmethod
    def through(cls, p, q):
        """The line through the points p and q, directed from p to q.

        Parameters
        ----------
        p, q : array-like of 3 numbers (m)
            Two distinct points.

        Returns
        -------
        Line
            w = q - p, m = p x q.

        Examples
        --------
        >>> Line.through([1, 0, 0], [1, 1, 0]).vector.T
        Matrix([[0, 1, 0, 0, 0, 1]])
        """
        exact = not (_has_float(p) or _has_float(q))
        p, q = _vector(p, "p", 3, exact), _vector(q, "q", 3, exact)
        w = q - p
        if all(_zero(e, exact) for e in w):
            raise ValueError(
                f"q must differ from p (two points make a line), got p = q = {list(p)}"
            )
        line = cls.__new__(cls)
        line._set(_stack(w, _cross(p, q), exact), exact, "q")
        return line

    @classmethod
    def from_point_direction(cls, p, d):
        """The line through the point p with direction d.

        Parameters
        ----------
        p : array-like of 3 numbers (m)
            A point of the line.
        d : array-like of 3 numbers
            Its direction, not zero (any length).

        Returns
        -------
        Line
            w = d, m = p x d.

        Examples
        --------
        >>> Line.from_point_direction([0, 2, 0], [1, 0, 0]).moment.T
        Matrix([[0, 0, -2]])
        """
        exact = not (_has_float(p) or _has_float(d))
        p, d = _vector(p, "p", 3, exact), _vector(d, "d", 3, exact)
        if all(_zero(e, exact) for e in d):
            raise ValueError(f"d must be a non-zero direction, got {list(d)}")
        line = cls.__new__(cls)
        line._set(_stack(d, _cross(p, d), exact), exact, "d")
        return line

    @classmethod
    def from_planes(cls, n1, d1, n2, d2):
        """The line where the planes n1 . x = d1 and n2 . x = d2 meet.

        Parameters
        ----------
        n1, n2 : array-like of 3 numbers
            The planes' normals (not zero, not parallel).
        d1, d2 : number (m, times |n|)
            The planes' offsets.

        Returns
        -------
        Line
            w = n1 x n2, m = d2 n1 - d1 n2 (for x on both planes,
            x x (n1 x n2) = n1 (x . n2) - n2 (x . n1)).

        Examples
        --------
        >>> Line.from_planes([1, 0, 0], 1, [0, 1, 0], 2).point.T  # x = 1, y = 2
        Matrix([[1, 2, 0]])
        """
        exact = not any(_has_float(v) for v in (n1, d1, n2, d2))
        n1, n2 = _vector(n1, "n1", 3, exact), _vector(n2, "n2", 3, exact)
        d1 = _vector([d1], "d1", 1, exact)[0]
        d2 = _vector([d2], "d2", 1, exact)[0]
        for n, name in ((n1, "n1"), (n2, "n2")):
            if all(_zero(e, exact) for e in n):
                raise ValueError(f"{name} must be a non-zero normal, got {list(n)}")
        w = _cross(n1, n2)
        if all(_zero(e, exact) for e in w) or (
            not exact and _norm(w) <= LINE_ANGLE_TOL * _norm(n1) * _norm(n2)
        ):
            raise ValueError(
                "n2 must not be parallel to n1: parallel planes meet in no line, got "
                f"n1 = {list(n1)}, n2 = {list(n2)}"
            )
        line = cls.__new__(cls)
        line._set(_stack(w, d2 * n1 - d1 * n2, exact), exact, "n2")
        return line

    # --- coordinates -----------------------------------------------------------------
    @property
    def vector(self):
        """The Plücker coordinates (w; m): a SymPy 6 x 1 matrix (exact) or an array
        (6,)."""
        return self._v

    @property
    def direction(self):
        """The direction w (as given, not normalised)."""
        return _w(self._v)

    @property
    def moment(self):
        """The moment m = p x w about the origin."""
        return _m(self._v)

    @property
    def unit(self):
        """The unit direction w / |w|."""
        w = self.direction
        return (w / _norm(w)).applyfunc(sp.simplify) if self.exact else w / _norm(w)

    @property
    def point(self):
        """The point of the line nearest the origin, w x m / (w . w) (m)."""
        w, m = self.direction, self.moment
        p = _cross(w, m) / _dot(w, w)
        return p.applyfunc(sp.simplify) if self.exact else p

    def screw(self, h=0, kind=Twist):
        """The screw on this line with pitch h: (w; m + h w), a screw as a line plus a
        pitch.

        Parameters
        ----------
        h : number or SymPy expression (m/rad)
            The pitch.
        kind : {Twist, Wrench, Screw}, optional
            The kind of screw (default Twist).

        Returns
        -------
        Screw
            Of the given kind; its magnitude is |w|.

        Examples
        --------
        >>> Line.through([0, 0, 0], [0, 0, 1]).screw(2).vector.T
        Matrix([[0, 0, 1, 0, 0, 2]])
        """
        if kind not in (Twist, Wrench, Screw):
            raise TypeError(f"kind must be Twist, Wrench or Screw, got {kind!r}")
        if isinstance(h, (str, bytes, bool)) or h is None:
            raise TypeError(f"h must be a number (a pitch in m/rad), got {describe(h)}")
        v = self._v if self.exact else sp.Matrix(self._v.tolist())
        return kind(sp.Matrix.vstack(v[:3, :], v[3:, :] + h * v[:3, :]))

    def transform(self, T):
        """This line moved by the rigid motion T: (R w; R m + p x R w).

        Parameters
        ----------
        T : array-like or SymPy matrix, shape (4, 4)
            The rigid motion (R, p) (m).

        Returns
        -------
        Line
            Exact when both the line and T are exact.

        Examples
        --------
        >>> T = sp.Matrix([[0, -1, 0, 1], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]])
        >>> Line.through([0, 0, 0], [1, 0, 0]).transform(T).point.T
        Matrix([[1, 0, 0]])
        """
        exact = self.exact and not _has_float(T)
        if exact:
            T = check_transform(as_sympy_matrix(T, "T", (4, 4)), "T")
            R, p = T[:3, :3], T[:3, 3]
            w, m = R * self.direction, R * self.moment
            return Line._of(
                sp.Matrix.vstack(w, m + p.cross(w)).applyfunc(sp.simplify), True
            )
        T = check_transform(as_float_array(_floats(T), "T"), "T")
        if T.shape != (4, 4):
            raise ValueError(f"T must be one pose of shape (4, 4), got shape {T.shape}")
        v = _float_vector(self)
        R, p = T[:3, :3], T[:3, 3]
        w, m = R @ v[:3], R @ v[3:]
        return Line._of(np.concatenate([w, m + np.cross(p, w)]), False)

    def __eq__(self, other):
        """The same coordinates (use :func:`intersection` for the same line as a set
        of points)."""
        if not isinstance(other, Line) or self.exact != other.exact:
            return NotImplemented
        if self.exact:
            return self._v == other._v
        return bool(np.array_equal(self._v, other._v))

    __hash__ = None

    def __repr__(self):
        entries = list(self._v) if self.exact else [float(x) for x in self._v]
        return f"Line({entries})"

    def _repr_latex_(self):
        v = self._v if self.exact else sp.Matrix(self._v.tolist())
        return f"$\\mathrm{{Line}}\\;{sp.latex(v.T)}^T$"


def _stack(w, m, exact):
    return (
        sp.Matrix.vstack(sp.Matrix(w), sp.Matrix(m))
        if exact
        else np.concatenate([w, m])
    )


def _floats(value):
    if isinstance(value, sp.MatrixBase):
        return np.array(value.tolist(), dtype=object)
    return value


def _float_vector(line):
    return np.array([float(e) for e in line._v]) if line.exact else line._v


def _as_line(value, name):
    """A Line (kept), a 6-vector or a pitch-0 Screw as a Line; TypeError otherwise."""
    if isinstance(value, Line):
        return value
    if isinstance(value, (str, bytes)) or value is None or isinstance(value, bool):
        raise TypeError(
            f"{name} must be a Line or its 6 Plücker coordinates, got {describe(value)}"
        )
    try:
        return Line(value)
    except (TypeError, ValueError) as error:
        message = str(error).replace("plucker", name, 1)
        raise type(error)(message) from None


def _as_lines(value, name):
    """One line -> ([Line], True); a batch ((N, 6) array, list of lines) -> (list,
    False)."""
    if isinstance(value, Line) or isinstance(value, Screw):
        return [_as_line(value, name)], True
    if isinstance(value, np.ndarray) and value.ndim == 2:
        return [_as_line(row, f"{name}[{i}]") for i, row in enumerate(value)], False
    if (
        isinstance(value, (list, tuple))
        and value
        and all(
            isinstance(v, (Line, Screw, list, tuple, np.ndarray, sp.MatrixBase))
            for v in value
        )
    ):
        return [_as_line(v, f"{name}[{i}]") for i, v in enumerate(value)], False
    return [_as_line(value, name)], True


def _pairs(a, b):
    A, single_a = _as_lines(a, "a")
    B, single_b = _as_lines(b, "b")
    if not single_a and not single_b and len(A) != len(B):
        raise ValueError(
            f"b must hold as many lines as a (or one), got {len(B)} and {len(A)}"
        )
    n = max(len(A), len(B))
    A = A * n if single_a else A
    B = B * n if single_b else B
    return list(zip(A, B)), single_a and single_b


def _common(la, lb):
    """Both lines exact, or both as floats."""
    if la.exact and lb.exact:
        return la._v, lb._v, True
    return _float_vector(la), _float_vector(lb), False


# ---- two lines -----------------------------------------------------------------------


def mutual_moment(a, b):
    """The mutual moment of two lines, w_a . m_b + w_b . m_a (their reciprocal
    product).

    For unit directions it is -d sin(alpha), d the distance along the common normal n
    from a to b and alpha the angle from a's direction to b's, right-handed about n: 0
    exactly when the lines meet or are parallel.

    Parameters
    ----------
    a, b : Line, 6-vector, or (N, 6) array of lines
        The lines (a batch of one side is paired with one line or with a batch of the
        same length).

    Returns
    -------
    number or ndarray, shape (N,)
        With the coordinates as given (not normalised): exact for exact lines (m, for
        unit directions).

    Examples
    --------
    >>> mutual_moment(Line.through([0, 0, 0], [0, 0, 1]), Line([0, 1, 0, 0, 0, 2]))
    2
    """
    pairs, single = _pairs(a, b)
    values = []
    for la, lb in pairs:
        va, vb, exact = _common(la, lb)
        value = _dot(_w(va), _m(vb)) + _dot(_w(vb), _m(va))
        values.append(sp.simplify(value) if exact else value)
    return values[0] if single else _batch(values)


def _batch(values):
    if all(isinstance(v, (float, np.floating)) for v in values):
        return np.array(values, dtype=float)
    return values


class CommonNormal(NamedTuple):
    """The common normal of two lines: the shortest segment from one to the other.

    Parameters
    ----------
    foot_a, foot_b : SymPy 3-vector or ndarray (3,)
        Its feet on a and on b (m).
    distance : number
        Its length, the distance of the lines (m).
    unique : bool
        False for parallel lines (any foot on a, moved along the direction, gives
        another) and for the same line.

    Examples
    --------
    The x axis and the line parallel to y at height 2: the normal is the z axis
    from the origin up to (0, 0, 2).

    >>> cn = common_normal(Line.through([0, 0, 0], [1, 0, 0]),
    ...                    Line.through([0, 0, 2], [0, 1, 2]))
    >>> cn.segment.T, cn.distance, cn.unique
    (Matrix([[0, 0, 2]]), 2, True)
    """

    foot_a: object
    foot_b: object
    distance: object
    unique: bool

    @property
    def segment(self):
        """foot_b - foot_a, the segment from a to b (m)."""
        return self.foot_b - self.foot_a


def _scale(*lines):
    return length_scale(*[np.array([float(e) for e in ln.point]) for ln in lines])


def _parallel(ua, ub, exact):
    c = _cross(ua, ub)
    if exact:
        return all(sp.simplify(e) == 0 for e in c)
    return _norm(c) <= LINE_ANGLE_TOL


def _normal_of(la, lb):
    va, vb, exact = _common(la, lb)
    if exact:
        la, lb = Line._of(va, True), Line._of(vb, True)
    else:
        la, lb = Line._of(va, False), Line._of(vb, False)
    pa, pb, ua, ub = la.point, lb.point, la.unit, lb.unit
    if _parallel(ua, ub, exact):
        foot_b = pb + ub * _dot(pa - pb, ub) / _dot(ub, ub)
        if exact:
            foot_b = foot_b.applyfunc(sp.simplify)
        return CommonNormal(pa, foot_b, _simplify(_norm(foot_b - pa)), False)
    n = _cross(ua, ub)
    nn = _dot(n, n)
    ta = _dot(_cross(pb - pa, ub), n) / nn
    tb = _dot(_cross(pb - pa, ua), n) / nn
    fa, fb = pa + ua * ta, pb + ub * tb
    if exact:
        fa, fb = fa.applyfunc(sp.simplify), fb.applyfunc(sp.simplify)
    return CommonNormal(fa, fb, _simplify(_norm(fb - fa)), True)


def common_normal(a, b):
    """The common normal of two lines: its feet, its length, whether it is unique.

    Parameters
    ----------
    a, b : Line, 6-vector, or (N, 6) array of lines
        The lines, the normal running from a to b (a batch pairs as in
        :func:`mutual_moment`).

    Returns
    -------
    CommonNormal or list of CommonNormal
        ``foot_a``, ``foot_b`` (m), ``distance`` (m), ``unique`` (False for parallel
        lines: then foot_a is a's point nearest the origin); ``.segment`` is
        foot_b - foot_a. A list for a batch.

    Examples
    --------
    >>> cn = common_normal(Line.through([0, 0, 0], [1, 0, 0]),
    ...                    Line.through([5, 0, 2], [5, 1, 2]))
    >>> cn.foot_a.T, cn.foot_b.T, cn.distance
    (Matrix([[5, 0, 0]]), Matrix([[5, 0, 2]]), 2)
    """
    pairs, single = _pairs(a, b)
    normals = [_normal_of(la, lb) for la, lb in pairs]
    return normals[0] if single else normals


def distance(a, b):
    """The distance of two lines (the length of their common normal).

    Parameters
    ----------
    a, b : Line, 6-vector, or (N, 6) array of lines
        The lines (a batch pairs as in :func:`mutual_moment`).

    Returns
    -------
    number or ndarray, shape (N,)
        In m; exact for exact lines.

    Examples
    --------
    >>> distance(Line.through([0, 0, 0], [0, 0, 1]), Line.through([1, 1, 0], [1, 1, 1]))
    sqrt(2)
    """
    pairs, single = _pairs(a, b)
    values = [_normal_of(la, lb).distance for la, lb in pairs]
    return values[0] if single else _batch(values)


def _intersect(la, lb):
    cn = _normal_of(la, lb)
    exact = la.exact and lb.exact
    tol = 0 if exact else LENGTH_TOL * _scale(la, lb)
    meets = cn.distance == 0 if exact else cn.distance <= tol
    if not cn.unique:
        return "same line" if meets else "parallel"
    if not meets:
        return None
    return cn.foot_a if exact else (cn.foot_a + cn.foot_b) / 2


def intersection(a, b):
    """Where two lines meet.

    Parameters
    ----------
    a, b : Line, 6-vector, or (N, 6) array of lines
        The lines.

    Returns
    -------
    point, None, 'parallel' or 'same line'
        The common point (m: a SymPy 3-vector, or an array (3,) for floats); None for
        skew lines; the word for parallel distinct lines or one line twice. A list for
        a batch. Floats meet when their distance is below ``LENGTH_TOL`` times the
        lines' size (the largest coordinate of their points nearest the origin, 1 if
        both pass through it) and are parallel below ``LINE_ANGLE_TOL``.

    Examples
    --------
    >>> x_axis = Line.through([0, 0, 0], [1, 0, 0])
    >>> intersection(x_axis, Line.through([0, 1, 0], [1, 1, 0]))
    'parallel'
    >>> print(intersection(x_axis, Line.through([0, 1, 1], [0, 2, 1])))
    None
    """
    pairs, single = _pairs(a, b)
    points = [_intersect(la, lb) for la, lb in pairs]
    return points[0] if single else points


# ---- the central axis of a wrench (Poinsot) -----------------------------------------


class CentralAxis(NamedTuple):
    """A wrench as a force along a line plus a couple about that line (Poinsot).

    Parameters
    ----------
    line : Line or None
        The central axis (direction f), None for a pure couple (f = 0).
    pitch : number
        h = f . m / (f . f) (m), ``sympy.oo`` or ``inf`` for a pure couple.
    force : SymPy 3-vector or ndarray (3,)
        f (N).
    couple : SymPy 3-vector or ndarray (3,)
        The couple along the axis, h f (N m); the whole moment m for a pure couple.

    Examples
    --------
    1 N along z with a moment of 1 N m about z: a force on the z axis and a couple
    of pitch 1 m along it.

    >>> ca = central_axis([0, 0, 1, 0, 0, 1])
    >>> ca.line.point.T, ca.pitch, ca.force.T, ca.couple.T
    (Matrix([[0, 0, 0]]), 1, Matrix([[0, 0, 1]]), Matrix([[0, 0, 1]]))
    """

    line: object
    pitch: object
    force: object
    couple: object


def central_axis(wrench):
    """The central axis of a wrench (f; m): the line along which it is a force plus a
    parallel couple.

    Moving the reference point to r changes the moment to m - r x f; it is parallel
    to f for the points r = f x m / (f . f) + t f, and the couple left there is
    h f with h = f . m / (f . f).

    Parameters
    ----------
    wrench : Wrench, Screw or array-like of 6 numbers
        (f; m): the resultant force (N) and its moment about the origin (N m).

    Returns
    -------
    CentralAxis
        ``line``, ``pitch`` (m), ``force``, ``couple``. Exact for exact input.

    Examples
    --------
    >>> ca = central_axis([0, 0, 2, 2, 0, 6])  # 2 N along z, moment (2, 0, 6) N m
    >>> ca.line.point.T, ca.pitch, ca.couple.T
    (Matrix([[0, 1, 0]]), 3, Matrix([[0, 0, 6]]))
    """
    if isinstance(wrench, Screw):
        wrench = wrench.vector
    if isinstance(wrench, (str, bytes)) or wrench is None:
        raise TypeError(
            f"wrench must be a Wrench or 6 numbers (f; m), got {describe(wrench)}"
        )
    exact = not _has_float(wrench)
    v = _vector(wrench, "wrench", 6, exact)
    f, m = _w(v), _m(v)
    ff = _dot(f, f)
    if exact and sp.simplify(ff) == 0 or not exact and ff == 0:
        if all(_zero(e, exact) for e in m):
            raise ValueError("wrench must not be zero: the zero wrench has no axis")
        return CentralAxis(None, sp.oo if exact else np.inf, f, m)
    h = _dot(f, m) / ff
    r = _cross(f, m) / ff
    if exact:
        h, r = sp.simplify(h), r.applyfunc(sp.simplify)
    line = Line._of(_stack(f, _cross(r, f), exact), exact)
    if exact:
        line._v = line._v.applyfunc(sp.simplify)
    return CentralAxis(line, h, f, h * f)


# ---- dependent sets of lines (Grassmann geometry) -----------------------------------


class Dependency(NamedTuple):
    """The rank of a set of lines and the named configuration of their span.

    Parameters
    ----------
    rank : int
        The dimension of the span of the lines' Plücker vectors (0 to 6).
    count : int
        The number of lines.
    dependent : bool
        rank < count: the lines are linearly dependent (a parallel manipulator whose
        legs are these lines is singular when six of them have rank < 6).
    name : str
        The configuration of the lines of the span (Merlet's catalogue of Grassmann
        geometry, in words): 'one line', 'two skew lines', 'flat pencil', 'star'
        (all lines through a point), 'parallel lines' (a star at infinity), 'plane'
        (all lines in a plane), 'two flat pencils', 'regulus', 'lines meeting two
        lines', 'parabolic congruence', 'elliptic congruence', 'point and plane',
        'special complex', 'general complex' or 'independent' (rank 6).
    data : dict
        The geometry that names it: 'point', 'plane' (n, d) with n . x = d,
        'direction', 'line', 'lines', 'axis' and 'pitch' (of a complex), each present
        where it applies.
    description : str
        The configuration in one sentence.

    Examples
    --------
    Three lines in the plane z = 0 span a plane of lines (rank 3), whatever their
    directions:

    >>> plane = [Line.through([0, 0, 0], [1, 0, 0]), Line.through([0, 0, 0], [0, 1, 0]),
    ...          Line.through([1, 0, 0], [0, 1, 0])]
    >>> result = dependency(plane)
    >>> result.rank, result.count, result.dependent, result.name
    (3, 3, False, 'plane')
    """

    rank: int
    count: int
    dependent: bool
    name: str
    data: dict
    description: str


def _line_rows(lines):
    if isinstance(lines, ScrewSystem):
        lines = list(lines.screws)
    if isinstance(lines, (str, bytes)) or not isinstance(
        lines, (list, tuple, np.ndarray)
    ):
        raise TypeError(
            "lines must be a list of Lines or 6-vectors, an (N, 6) array or a "
            f"ScrewSystem of lines, got {describe(lines)}"
        )
    if len(lines) == 0:
        raise ValueError("lines must hold at least one line, got none")
    out = []
    for i, item in enumerate(lines):
        if isinstance(item, Screw):
            item = item.vector
        out.append(_as_line(item, f"lines[{i}]"))
    return out


def dependency(lines, tol=None):
    """The rank of a set of lines and the named configuration of their span.

    The lines' Plücker vectors span a linear space S of dimension r (the rank); the
    lines of S (its points on the Klein quadric w . m = 0) are the configuration:
    rank 1 one line; rank 2 a flat pencil (lines of a plane through a point) or two
    skew lines; rank 3 a star (all lines through a point, or all parallel to one
    direction), all lines of a plane, two flat pencils with a common line, or a
    regulus; rank 4 the lines meeting every line of the reciprocal 2-system: two
    skew lines (hyperbolic congruence), one line twice (parabolic), no real line
    (elliptic), or a point and a plane through it; rank 5 a linear complex, special
    (all lines meeting one line) or general; rank 6 independent. The names are decided
    from the quadratic form w . m restricted to S or to its reciprocal space.

    Parameters
    ----------
    lines : list of Line or 6-vectors, (N, 6) array, or ScrewSystem of lines
        The lines, e.g. ``pm.wrenches(T)[0]`` (a parallel manipulator's leg lines) or
        ``chain.joint_twists(q)`` (a serial chain's revolute joint axes).
    tol : float, optional
        Relative tolerance of the rank and of the form's zero tests for float lines
        (default ``LINE_RANK_TOL``); the moments are divided by the lines' size first,
        so the answer is the same in m and mm. Exact lines are decided exactly.

    Returns
    -------
    Dependency
        ``rank``, ``count``, ``dependent``, ``name``, ``data``, ``description``.

    Examples
    --------
    >>> star = [Line.through([0, 0, 0], d) for d in ([1, 0, 0], [0, 1, 0], [1, 1, 1])]
    >>> result = dependency(star + [Line.through([0, 0, 0], [1, 2, 3])])
    >>> result.rank, result.name, result.data["point"].T
    (3, 'star', Matrix([[0, 0, 0]]))
    """
    rows = _line_rows(lines)
    tol = LINE_RANK_TOL if tol is None else check_positive(tol, "tol")
    if not tol < 1:
        raise ValueError(f"tol must be a positive number below 1, got {tol!r}")
    result = _line_geometry.classify(
        [ln._v for ln in rows], all(ln.exact for ln in rows), tol
    )
    rank, name, data, words = result
    data = {
        key: _wrap(value, rows[0].exact and all(ln.exact for ln in rows))
        for key, value in data.items()
    }
    return Dependency(rank, len(rows), rank < len(rows), name, data, words)


def _wrap(value, exact):
    """Plücker vectors of the data as Lines; points, planes and numbers as they are."""
    if isinstance(value, _line_geometry.PluckerLine):
        return Line._of(value.vector, exact)
    if isinstance(value, list):
        return [_wrap(v, exact) for v in value]
    return value
