"""What a serial chain is made of: DH links and joint screws, checked once.

* :class:`Link` is one row of a Denavit–Hartenberg table (standard or modified, see
  :class:`Convention`), with numbers that are floats or exact SymPy values;
* a joint screw (omega; v) is checked to be a unit screw (:func:`check_screws`) and
  named a :class:`Joint` kind by its pitch: revolute (0), helical (finite) or prismatic
  (omega = 0).

:mod:`screwkit.chains` builds chains from either (:func:`dh_description`,
:func:`screw_description`); a chain's joint values are checked here too
(:func:`check_q`, the Chain's method of that name). Every DH link is also,
numerically, a pre transform, a joint twist and a post transform:
A(q) = pre exp([X] (q + offset)) post (:func:`dh_factors`), which is how a DH chain
joins the product of exponentials.
"""

import enum
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ._checks import as_float_array, check_poses, describe, real_number
from ._docstrings import CHAIN, CHAIN_Q, fill
from .screws import Screw
from .tolerances import QUARTER_TURN_TOL, UNIT_SCREW_TOL, ZERO_TOL, length_scale
from .transforms import _cross

__all__ = ["Joint", "Convention", "Link"]

#: How far from 1 the norm of a joint screw's omega (or of v, for a prismatic joint) may
#: be: the old name of :data:`screwkit.tolerances.UNIT_SCREW_TOL`.
UNIT_TOL = UNIT_SCREW_TOL


class Joint(enum.Enum):
    """The kind of a joint: its variable q is an angle (revolute, helical) or a length
    (prismatic).

    Examples
    --------
    >>> Joint("P"), Link.revolute(a=1).joint is Joint.REVOLUTE
    (<Joint.PRISMATIC: 'P'>, True)
    """

    REVOLUTE = "R"
    PRISMATIC = "P"
    HELICAL = "H"  # rotation q (rad) with translation h q along the axis


class Convention(enum.Enum):
    """Which DH convention a chain's table follows.

    Examples
    --------
    A link of length a = 1 turned a quarter turn: the standard convention turns
    before the length (its frame ends at y = 1), Craig's modified one after (x = 1).

    >>> link = Link.revolute(a=1)
    >>> link.transform(sp.pi / 2, Convention.STANDARD)[:3, 3].T
    Matrix([[0, 1, 0]])
    >>> link.transform(sp.pi / 2, Convention.MODIFIED)[:3, 3].T
    Matrix([[1, 0, 0]])
    """

    STANDARD = "standard"  # Rz(theta) Tz(d) Tx(a) Rx(alpha)
    MODIFIED = "modified"  # Craig: Rx(alpha) Tx(a) Rz(theta) Tz(d)


def check_convention(convention):
    if not isinstance(convention, Convention):
        raise TypeError(
            "convention must be a Convention (STANDARD or MODIFIED), got "
            f"{convention!r}"
        )
    return convention


def _link_sections(joint, unit):
    """The end of Link.revolute's and Link.prismatic's docstrings: the parameters they
    share and the Returns section, for a joint variable q in ``unit``."""
    return f"""alpha : number or SymPy expression, optional
    The DH twist (rad).
offset : number or SymPy expression, optional
    Added to q ({unit}).
qlim : (float, float) or None, optional
    (min, max) of q ({unit}), or None for no limit.

Returns
-------
Link
    The link, ``joint=Joint.{joint}``."""


def _check_parameter(value, name):
    """A DH number: a finite real number, or a SymPy expression
    (exact, possibly symbolic)."""
    if isinstance(value, sp.Basic):
        value = sp.sympify(value)
        if (
            not isinstance(value, sp.Expr)
            or value.has(sp.nan, sp.zoo, sp.oo, -sp.oo)
            or value.is_real is False
        ):
            raise ValueError(
                f"{name} must be a finite real number or SymPy expression, got {value}"
            )
        return value
    return real_number(value, name, "a real number (m or rad)")


@dataclass(frozen=True)
class Link:
    """One row of a DH table (m, rad).

    The joint variable q adds to ``offset``: theta = q + offset for a revolute joint
    (then ``theta`` is unused), d = q + offset for a prismatic one
    (then ``d`` is unused). ``qlim`` is (min, max) of q, or None for no limit
    (+-inf in either place is no limit there). Numbers may be floats or exact SymPy
    values (``sympy.pi / 2``); symbols are allowed for the exact path (``fk_symbolic``)
    but the numeric path needs numbers.

    Parameters
    ----------
    joint : Joint
        ``Joint.REVOLUTE`` or ``Joint.PRISMATIC``.
    d : number or SymPy expression, optional
        Offset along the previous z (m).
    a : number or SymPy expression, optional
        Length along the common normal x (m).
    alpha : number or SymPy expression, optional
        Twist about x (rad).
    theta : number or SymPy expression, optional
        Angle about the previous z (rad).
    offset : number or SymPy expression, optional
        Added to the joint variable q (rad or m).
    qlim : (float, float) or None, optional
        (min, max) of q, or None for no limit.

    Examples
    --------
    >>> Link(Joint.REVOLUTE, a=1)
    Link(joint=<Joint.REVOLUTE: 'R'>, d=0, a=1, alpha=0, theta=0, offset=0, qlim=None)
    """

    joint: Joint
    d: object = 0
    a: object = 0
    alpha: object = 0
    theta: object = 0
    offset: object = 0
    qlim: tuple = None

    def __post_init__(self):
        if not isinstance(self.joint, Joint) or self.joint is Joint.HELICAL:
            raise TypeError(
                "joint must be Joint.REVOLUTE or Joint.PRISMATIC for a DH link, got "
                f"{self.joint!r}"
            )
        for name in ("d", "a", "alpha", "theta", "offset"):
            object.__setattr__(self, name, _check_parameter(getattr(self, name), name))
        object.__setattr__(self, "qlim", _check_qlim(self.qlim))

    @classmethod
    @fill(rest=_link_sections("REVOLUTE", "rad"))
    def revolute(cls, d=0, a=0, alpha=0, offset=0, qlim=None):
        """A revolute link: theta = q + offset.

        Parameters
        ----------
        d, a : number or SymPy expression, optional
            The DH lengths (m).
        {rest}

        Examples
        --------
        A 1 m link turned a quarter turn ends on the y axis:

        >>> Link.revolute(a=1).transform(sp.pi / 2)[:3, 3].T
        Matrix([[0, 1, 0]])
        """
        return cls(Joint.REVOLUTE, d=d, a=a, alpha=alpha, offset=offset, qlim=qlim)

    @classmethod
    @fill(rest=_link_sections("PRISMATIC", "m"))
    def prismatic(cls, theta=0, a=0, alpha=0, offset=0, qlim=None):
        """A prismatic link: d = q + offset.

        Parameters
        ----------
        theta : number or SymPy expression, optional
            The DH angle (rad).
        a : number or SymPy expression, optional
            The DH length (m).
        {rest}

        Examples
        --------
        A slide along z of at most 0.5 m, extended by half a metre:

        >>> link = Link.prismatic(qlim=(0, 0.5))
        >>> link.qlim, link.transform(sp.Rational(1, 2))[:3, 3].T
        ((0.0, 0.5), Matrix([[0, 0, 1/2]]))
        """
        return cls(
            Joint.PRISMATIC, theta=theta, a=a, alpha=alpha, offset=offset, qlim=qlim
        )

    def transform(self, q, convention=Convention.STANDARD):
        """The exact link transform A(q).

        Parameters
        ----------
        q : number, SymPy symbol or expression
            The joint value (rad or m).
        convention : Convention, optional
            ``Convention.STANDARD`` (Rz Tz Tx Rx, the default) or
            ``Convention.MODIFIED`` (Craig: Rx Tx Rz Tz).

        Returns
        -------
        sympy.Matrix (4, 4)
            The homogeneous transform of the link.

        Examples
        --------
        With alpha = pi / 2 the next z axis is the old -y (Rx(pi / 2) carries z to -y):

        >>> Link.revolute(alpha=sp.pi / 2).transform(0)[:3, 2].T
        Matrix([[0, -1, 0]])
        """
        check_convention(convention)
        theta, d = (
            (q + self.offset, self.d)
            if self.joint is Joint.REVOLUTE
            else (self.theta, q + self.offset)
        )
        ct, st = sp.cos(theta), sp.sin(theta)
        ca, sa = sp.cos(_exact(self.alpha)), sp.sin(_exact(self.alpha))
        a = _exact(self.a)
        if convention is Convention.STANDARD:
            return sp.Matrix(
                [
                    [ct, -st * ca, st * sa, a * ct],
                    [st, ct * ca, -ct * sa, a * st],
                    [0, sa, ca, d],
                    [0, 0, 0, 1],
                ]
            )
        return sp.Matrix(
            [
                [ct, -st, 0, a],
                [st * ca, ct * ca, -sa, -sa * d],
                [st * sa, ct * sa, ca, ca * d],
                [0, 0, 0, 1],
            ]
        )

    def _numbers(self, index):
        """(d, a, theta, offset) as floats and (cos alpha, sin alpha), for the numeric
        path."""
        values = []
        for name in ("d", "a", "theta", "offset", "alpha"):
            value = getattr(self, name)
            if isinstance(value, sp.Basic) and value.free_symbols:
                raise ValueError(
                    f"link {index}'s {name} is the expression {value}: the numeric "
                    "path (fk, Jacobians) needs numbers; use fk_symbolic for symbols"
                )
            values.append(value)
        alpha = values.pop()
        if isinstance(alpha, sp.Basic):  # exact: cos(pi/2) is exactly 0
            return [float(v) for v in values], (
                float(sp.cos(alpha)),
                float(sp.sin(alpha)),
            )
        quarter_turns = round(alpha / (np.pi / 2))
        if (
            abs(alpha / (np.pi / 2) - quarter_turns) < QUARTER_TURN_TOL
        ):  # as _exact: a float multiple of pi/2
            cos_sin = [(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][
                quarter_turns % 4
            ]
        else:
            cos_sin = (float(np.cos(alpha)), float(np.sin(alpha)))
        return [float(v) for v in values], cos_sin


def _limit_numbers(qlim, name, expected):
    """Joint limits as a float array (+-inf allowed: no limit); TypeError for anything
    else."""
    if isinstance(qlim, (str, bytes)):
        raise TypeError(f"{name} must be {expected} or None, got {qlim!r}")
    try:
        return np.asarray(qlim, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(
            f"{name} must be {expected} of numbers or None, got {describe(qlim)}"
        ) from None


def _check_qlim(qlim, name="qlim"):
    """(min, max) as floats, None for no limit; +-inf means no limit on that side."""
    if qlim is None:
        return None
    limits = _limit_numbers(qlim, name, "a pair (min, max)")
    if limits.shape != (2,) or np.any(np.isnan(limits)) or not limits[0] < limits[1]:
        raise ValueError(
            f"{name} must be a pair (min, max) with min < max, got {qlim!r}"
        )
    if limits[0] == -np.inf and limits[1] == np.inf:
        return None
    return (float(limits[0]), float(limits[1]))


def _exact(value):
    """Floats that are integers or multiples of pi/2 become exact, so cos(pi/2) is
    exactly 0."""
    value = sp.sympify(value)
    if isinstance(value, sp.Float):
        quarter_turns = float(value) / (np.pi / 2)
        if abs(quarter_turns - round(quarter_turns)) < QUARTER_TURN_TOL:
            return sp.pi / 2 * round(quarter_turns)
    return value


def decimal(value):
    """A Float as the exact decimal it prints as (0.4318 -> 2159/5000); other values
    unchanged."""
    value = sp.sympify(value)
    if isinstance(value, sp.Float):
        return sp.nsimplify(value, rational=True)
    if value.has(sp.Float):
        return value.xreplace(
            {f: sp.nsimplify(f, rational=True) for f in value.atoms(sp.Float)}
        )
    return value


def exact_matrix(T):
    """A numeric 4x4 as a SymPy matrix, exact where the entries are integers."""
    return sp.Matrix(
        4,
        4,
        [sp.Integer(int(v)) if float(v).is_integer() else sp.Float(v) for v in T.flat],
    )


def rigid(value, name):
    """A 4x4 rigid transform as a fresh, read-only float array
    (never the caller's array)."""
    if value is None:
        T = np.eye(4)
    else:
        if isinstance(value, sp.MatrixBase):
            value = (
                np.array(value.evalf(), dtype=float)
                if not value.free_symbols
                else value
            )
        T = check_poses(value, name, single_only=True).copy()
    T.setflags(write=False)
    return T


def translation(p):
    T = np.eye(4)
    T[:3, 3] = p
    return T


def dh_factors(link, index, convention):
    """(pre, twist, post) of a DH link: A(q) = pre exp([X] (q + offset)) post
    (floats)."""
    (d, a, theta, _), (ca, sa) = link._numbers(index)
    Rx = np.array([[1.0, 0, 0, 0], [0, ca, -sa, 0], [0, sa, ca, 0], [0, 0, 0, 1]])
    Tx, Tz = translation([a, 0, 0]), translation([0, 0, d])
    ct, st = np.cos(theta), np.sin(theta)
    Rz = np.array([[ct, -st, 0, 0], [st, ct, 0, 0], [0, 0, 1.0, 0], [0, 0, 0, 1]])
    revolute = link.joint is Joint.REVOLUTE
    twist = (
        np.array([0, 0, 1.0, 0, 0, 0]) if revolute else np.array([0, 0, 0, 0, 0, 1.0])
    )
    if convention is Convention.STANDARD:
        return np.eye(4), twist, (Tz if revolute else Rz) @ Tx @ Rx
    return Rx @ Tx, twist, Tz if revolute else Rz


def check_screws(axes):
    """The joint screws as an (n, 6) float array of unit screws, and their exact
    forms."""
    if isinstance(axes, np.ndarray) and axes.ndim == 2:
        items = list(axes)
    elif isinstance(axes, (list, tuple)):
        items = list(axes)
    else:
        raise TypeError(
            "axes must be a list of Twist objects or 6-vectors [omega; v], got "
            f"{describe(axes)}"
        )
    if not items:
        raise ValueError("axes must hold at least one joint screw, got none")
    numbers, exact = [], []
    for i, item in enumerate(items):
        name = f"axes[{i}]"
        if isinstance(item, Screw):
            if item.noun == "wrench":
                raise TypeError(
                    f"{name} must be a twist (a joint's motion), got a Wrench"
                )
            vector = item.vector
        elif isinstance(item, sp.MatrixBase) or (
            isinstance(item, (list, tuple, np.ndarray))
            and any(isinstance(e, sp.Basic) for e in np.ravel(item))
        ):
            vector = sp.Matrix(item)
        else:
            vector = None
        if vector is not None:
            if vector.shape not in ((6, 1), (1, 6)) or vector.free_symbols:
                raise ValueError(
                    f"{name} must be a 6-vector of numbers [omega; v], got {vector.T}"
                )
            values = np.array([float(e) for e in vector], dtype=float)
            exact.append(sp.Matrix(6, 1, list(vector)))
        else:
            values = as_float_array(item, name)
            if values.shape != (6,):
                raise ValueError(
                    f"{name} must be a 6-vector [omega; v], got shape {values.shape}"
                )
            exact.append(
                sp.Matrix(
                    6,
                    1,
                    [
                        sp.Integer(int(v)) if v.is_integer() else sp.Float(v)
                        for v in values
                    ],
                )
            )
        w, v = np.linalg.norm(values[:3]), np.linalg.norm(values[3:])
        if w == 0 and v == 0:
            raise ValueError(f"{name} must be a unit screw axis, got the zero twist")
        if w != 0 and abs(w - 1) > UNIT_SCREW_TOL:
            raise ValueError(
                f"{name} must be a unit screw axis: |omega| = 1 for a revolute or "
                "helical joint (or omega = 0 and |v| = 1 for a prismatic one), got "
                f"|omega| = {w:.6g}"
            )
        if w == 0 and abs(v - 1) > UNIT_SCREW_TOL:
            raise ValueError(
                f"{name} is prismatic (omega = 0) and must have |v| = 1, got |v| = "
                f"{v:.6g}"
            )
        numbers.append(
            values / (w or v)
        )  # unit to the last bit: the exponential assumes it
    return np.array(numbers), exact


def joint_kind(screw, scale=1.0):
    """The kind of a unit joint screw (omega; v): prismatic if omega = 0, else helical
    if its pitch omega . v is a length above ``ZERO_TOL * scale``, else revolute.

    Parameters
    ----------
    screw : ndarray, shape (6,), a unit screw [omega; v] (v in m)
    scale : float, the chain's size (m, :func:`screwkit.tolerances.length_scale`)

    Returns
    -------
    Joint
    """
    if not np.any(screw[:3]):
        return Joint.PRISMATIC
    pitch = abs(np.dot(screw[:3], screw[3:]))
    return Joint.HELICAL if pitch > ZERO_TOL * scale else Joint.REVOLUTE


def axis_points(screws, start):
    """A point on each screw axis (revolute/helical): the one nearest the previous
    joint's point.

    Only for drawing: the first joint's point is the one nearest ``start``; a prismatic
    joint keeps the previous point.
    """
    points, previous = [], np.asarray(start, dtype=float)
    for screw in screws:
        w, v = screw[:3], screw[3:]
        if np.any(w):
            h = np.dot(w, v)
            nearest_origin = _cross(w, v - h * w)  # the axis point nearest the origin
            previous = nearest_origin + np.dot(previous - nearest_origin, w) * w
        points.append(previous.copy())
    return np.array(points)


def limits_table(qlim, n):
    """An (n, 2) table of limits as a list of (min, max) or None (+-inf: no limit)."""
    limits = _limit_numbers(qlim, "qlim", f"an ({n}, 2) array")
    if limits.shape != (n, 2):
        raise ValueError(f"qlim must have shape ({n}, 2), got shape {limits.shape}")
    return [_check_qlim(row, f"qlim[{i}]") for i, row in enumerate(limits)]


def links_from_table(table, joints=None, qlim=None):
    """The links of a DH table: :meth:`screwkit.Chain.from_table`'s rows, checked.

    Parameters
    ----------
    table : array-like, shape (n, 4)
        Columns (theta, d, a, alpha), in rad and m; theta is a revolute joint's
        offset, d a prismatic joint's.
    joints : sequence of Joint, or str, optional
        A string such as 'RRP'; all revolute by default.
    qlim : array-like, shape (n, 2), or None, optional
        Joint limits (rad or m; +-inf: no limit).

    Returns
    -------
    list of Link
        One link per row.
    """
    rows = as_float_array(table, "table")
    if rows.ndim != 2 or rows.shape[1] != 4 or rows.shape[0] < 1:
        raise ValueError(
            "table must have shape (n, 4), columns (theta, d, a, alpha), got "
            f"shape {rows.shape}"
        )
    n = rows.shape[0]
    try:
        kinds = (
            [Joint.REVOLUTE] * n
            if joints is None
            else [Joint(j) if isinstance(j, str) else j for j in joints]
        )
    except (ValueError, TypeError):
        kinds = None
    if (
        kinds is None
        or len(kinds) != n
        or not all(k in (Joint.REVOLUTE, Joint.PRISMATIC) for k in kinds)
    ):
        raise ValueError(
            f"joints must name {n} joints ('R' or 'P', or Joint members), got "
            f"{joints!r}"
        )
    limits = [None] * n if qlim is None else limits_table(qlim, n)
    links = []
    for (theta, d, a, alpha), kind, limit in zip(rows, kinds, limits):
        if kind is Joint.REVOLUTE:
            links.append(Link.revolute(d=d, a=a, alpha=alpha, offset=theta, qlim=limit))
        else:
            links.append(
                Link.prismatic(theta=theta, a=a, alpha=alpha, offset=d, qlim=limit)
            )
    return links


# ---- a chain's description and joint values (the Chain's constructors and checks) ----


def _limits_array(qlim):
    """The (n, 2) read-only float table of limits (min, max) or None: +-inf for none."""
    limits = np.array(
        [limit if limit else (-np.inf, np.inf) for limit in qlim], dtype=float
    )
    limits.setflags(write=False)
    return limits


def dh_description(links, convention):
    """What a :class:`~screwkit.chains.Chain` keeps of a DH table, checked: its
    links, convention, joint kinds and limits (the chain's attributes by name)."""
    links = list(links) if isinstance(links, (list, tuple)) else links
    if (
        not isinstance(links, list)
        or not links
        or not all(isinstance(k, Link) for k in links)
    ):
        raise TypeError(
            f"links must be a non-empty list of Link, got {describe(links)}"
        )
    return dict(
        links=tuple(links),
        convention=check_convention(convention),
        joints=tuple(link.joint for link in links),
        _qlim=_limits_array([link.qlim for link in links]),
    )


def screw_description(axes, home, frame, qlim):
    """What a :class:`~screwkit.chains.Chain` keeps of joint screws, checked: the
    screws (floats and exact), home pose, frame, joint kinds and limits."""
    if frame not in ("space", "body"):
        raise ValueError(f"frame must be 'space' or 'body', got {frame!r}")
    screws, exact = check_screws(axes)
    n = screws.shape[0]
    limits = [None] * n if qlim is None else limits_table(qlim, n)
    scale = length_scale(screws[:, 3:])
    return dict(
        _screws=screws,
        _exact_screws=exact,
        _home=rigid(home, "home"),
        frame=frame,
        joints=tuple(joint_kind(s, scale) for s in screws),
        _qlim=_limits_array(limits),
    )


def _joint_values(shape):
    """The Parameters and Returns of a check of joint values of ``shape``."""
    return (
        CHAIN
        + f"""
q : array-like, shape {shape}
    Joint values (rad or m).
name : str, optional
    The argument's name in the error message.

Returns
-------
ndarray, shape {shape}
    ``q`` as float64."""
    )


@fill(sections=_joint_values("(n,) or (N, n)"))
def check_q(chain, q, name="q"):
    """``q`` checked and converted; a clear error otherwise.

    {sections}

    Examples
    --------
    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> arm.check_q([0, 1])
    array([0., 1.])
    >>> arm.check_q([0, 1, 2])  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: q must have 2 entries for this chain, ... got shape (3,)
    """
    q = as_float_array(q, name)
    if q.ndim not in (1, 2) or q.shape[-1] != chain.n:
        raise ValueError(
            f"{name} must have {chain.n} entries for this chain, shape ({chain.n},) "
            f"or (N, {chain.n}), got shape {q.shape}"
        )
    return q


@fill(sections=_joint_values("(n,)"))
def check_one(chain, q, name="q"):
    """``q`` checked as one configuration (a batch is refused, clearly).

    {sections}

    Examples
    --------
    A batch of two configurations of the planar 2R arm, where one is meant:

    >>> import screwkit as sk
    >>> sk.robots.planar([1.0, 1.0]).check_one([[0, 1], [1, 0]])
    Traceback (most recent call last):
    ...
    ValueError: q must be one configuration of shape (2,), got shape (2, 2)
    """
    q = check_q(chain, q, name)
    if q.ndim != 1:
        raise ValueError(
            f"{name} must be one configuration of shape ({chain.n},), got shape "
            f"{q.shape}"
        )
    return q


@fill(parameters=CHAIN_Q)
def within_limits(chain, q):
    """Whether every joint of q lies within its limits.

    {parameters}

    Returns
    -------
    bool or ndarray of bool, shape (N,)
        True where every joint is within its limits.

    Examples
    --------
    A planar 2R arm whose joints turn within +-90 degrees:

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0], qlim=[(-np.pi / 2, np.pi / 2)] * 2)
    >>> arm.within_limits([[0.0, 1.0], [0.0, 2.0]])
    array([ True, False])
    """
    q = check_q(chain, q)
    return np.all((q >= chain._qlim[:, 0]) & (q <= chain._qlim[:, 1]), axis=-1)
