"""Serial chains: from a Denavit–Hartenberg (DH) table or from joint screws
(product of exponentials).

A :class:`Chain` is a fixed, immutable model. Underneath, every chain is its joint
twists and a home pose: T(q) = base exp([S_1] q_1) ... exp([S_n] q_n) M tool
(Lynch and Park's product of exponentials); a DH table is one way to write those screws
down, :meth:`Chain.from_screws` another. Both kinds have the same methods:

* exact (SymPy): ``fk_symbolic`` in the joint symbols q1..qn, ``joint_twists`` at exact
  values;
* fast (NumPy): ``fk``, ``frames``, the Jacobians, one configuration ``(n,)`` or a batch
  ``(N, n)``, computed by straight-line code generated from the chain's numbers when it
  is first used (see :mod:`screwkit._compiled`; no SymPy, about a millisecond).

Standard DH (the default):  A_i = Rz(theta_i) Tz(d_i) Tx(a_i) Rx(alpha_i).
Modified DH (Craig):        A_i = Rx(alpha_{i-1}) Tx(a_{i-1}) Rz(theta_i) Tz(d_i),
where the row of link i holds alpha_{i-1} and a_{i-1}.

>>> import numpy as np
>>> arm = Chain([Link.revolute(a=1.0), Link.revolute(a=0.5)])
>>> np.round(arm.fk([0.0, np.pi / 2])[:2, 3], 6)
array([1. , 0.5])
>>> arm.fk(np.zeros((10, 2))).shape
(10, 4, 4)
"""

import types
from functools import cached_property

import numpy as np
import sympy as sp
from sympy.simplify.fu import TR10i

from . import _compiled, _numeric
from ._checks import (
    ChainType,
    as_float_array,
    as_sympy_scalar,
    check_flag,
    check_integer,
    check_option,
    describe,
    is_symbolic,
)
from ._docstrings import fill
from ._notation import textbook
from .ik import newton as _newton
from .lie import adjoint
from .links import (
    Convention,
    Joint,
    Link,
    axis_points,
    check_convention,
    check_screws,
    decimal,
    dh_factors,
    exact_matrix,
    joint_kind,
    limits_table,
    rigid,
    translation,
)
from .motion import _second_order
from .screws import Twist
from .systems import ScrewSystem
from .tolerances import length_scale
from .transforms import _cross, axis_coordinates, exp_twist
from .urdf import read_urdf

__all__ = ["Joint", "Convention", "Link", "Chain", "textbook", "ROWS"]

#: Rows of the geometric Jacobian, by name.
#: 'planar' is (v_x, v_y) in the chain's base frame, the 2 x n Jacobian of an arm that
#: moves in its base's x-y plane.
ROWS = {
    "all": slice(0, 6),
    "position": slice(0, 3),
    "orientation": slice(3, 6),
    "planar": slice(0, 2),
}

#: Docstring passages the methods share (filled in by :func:`_docstrings.fill`): the
#: Parameters section of the methods taking joint values only, and the sections of the
#: second-order methods.
_Q_PARAMETERS = """Parameters
----------
q : array-like, shape (n,) or (N, n)
    Joint values (rad or m)."""
_DOT_SECTIONS = """Parameters
----------
q : array-like, shape (n,) or (N, n), joint values (rad, m)
dq : array-like, the shape of q, joint rates

Returns
-------
ndarray, shape (6, n) or (N, 6, n), {layout} per second"""
_HESSIAN_SECTIONS = """Parameters
----------
q : array-like, shape (n,) or (N, n), joint values (rad, m)

Returns
-------
ndarray, shape (n, 6, n) or (N, n, 6, n)"""


def check_rows(rows):
    """The slice of the geometric Jacobian's rows named ``rows``
    (one of :data:`ROWS`)."""
    return ROWS[check_option(rows, "rows", tuple(ROWS))]


def _numbers_out(matrix, values=None):
    """``matrix`` at ``values``, expanded; with no symbol left, trigonometric functions
    of sums are expanded too (sin(pi/4 - atan(u)) becomes an algebraic number), so that
    screw-system ranks see the numbers themselves, not unrelated-looking trigonometric
    atoms."""
    matrix = matrix.subs(values) if values else matrix
    if matrix.free_symbols:
        return matrix.applyfunc(sp.expand)
    return matrix.applyfunc(lambda e: sp.radsimp(sp.expand(sp.expand_trig(e))))


class Chain(ChainType):
    """A serial chain between a fixed ``base`` and a ``tool`` transform; immutable.

    ``Chain(links, ...)`` describes it by a DH table; :meth:`from_table` takes the table
    as an array, and :meth:`from_screws` builds a chain from joint screws and a home
    pose.

    Parameters
    ----------
    links : sequence of Link, one per joint (n >= 1)
    convention : Convention.STANDARD (default) or Convention.MODIFIED
    base, tool : 4x4 rigid transforms (default identity): T = base @ A_1 ... A_n @ tool
    name : str, used in messages and titles
    configurations : optional {name: joint vector (n,)}, named configurations
        ('zero', ...)
    """

    #: The URDF joint names in order for a chain from :meth:`from_urdf`, None otherwise.
    joint_names = None

    def __init__(
        self,
        links,
        convention=Convention.STANDARD,
        base=None,
        tool=None,
        name="chain",
        configurations=None,
    ):
        links = list(links) if isinstance(links, (list, tuple)) else links
        if (
            not isinstance(links, list)
            or not links
            or not all(isinstance(k, Link) for k in links)
        ):
            raise TypeError(
                f"links must be a non-empty list of Link, got {describe(links)}"
            )
        self._setup(
            links=tuple(links),
            convention=check_convention(convention),
            screws=None,
            base=base,
            tool=tool,
            name=name,
            configurations=configurations,
            qlim=[link.qlim for link in links],
            joints=tuple(link.joint for link in links),
        )

    def _setup(
        self,
        *,
        links,
        convention,
        screws,
        base,
        tool,
        name,
        configurations,
        qlim,
        joints,
        home=None,
        frame=None,
        exact_screws=None,
    ):
        if not isinstance(name, str):
            raise TypeError(f"name must be a string, got {describe(name)}")
        state = self.__dict__
        state["links"], state["convention"] = links, convention
        state["_screws"], state["_exact_screws"], state["_home"], state["frame"] = (
            screws,
            exact_screws,
            home,
            frame,
        )
        state["base"], state["tool"] = rigid(base, "base"), rigid(tool, "tool")
        state["name"], state["joints"] = name, joints
        state["q_symbols"] = sp.symbols(f"q1:{len(joints) + 1}", real=True)
        limits = np.array(
            [limit if limit else (-np.inf, np.inf) for limit in qlim], dtype=float
        )
        limits.setflags(write=False)
        state["_qlim"] = limits
        named = {}
        for key, value in (configurations or {}).items():
            named[key] = self.check_one(value, f"configurations[{key!r}]").copy()
            named[key].setflags(write=False)
        state["configurations"] = types.MappingProxyType(named)

    def __setattr__(self, name, value):
        raise AttributeError(
            f"a Chain is immutable: cannot set {name!r}; make a new chain "
            "(e.g. chain.with_tool(T), chain.with_base(T))"
        )

    # ---- constructors ----------------------------------------------------------------

    @classmethod
    def from_table(
        cls, table, joints=None, convention=Convention.STANDARD, qlim=None, **options
    ):
        """A chain from a DH table.

        For a revolute joint, theta is the joint offset (theta = q + offset); for a
        prismatic one, d is (d = q + offset).

        Parameters
        ----------
        table : array-like, shape (n, 4)
            Columns (theta, d, a, alpha), in rad and m.
        joints : sequence of Joint, or str, optional
            A string such as 'RRP'; all revolute by default.
        convention : Convention, optional
            ``Convention.STANDARD`` (default) or ``Convention.MODIFIED``.
        qlim : array-like, shape (n, 2), or None, optional
            Joint limits (rad or m; +-inf: no limit).
        **options
            ``base``, ``tool``, ``name``, ``configurations``, as for :class:`Chain`.

        Returns
        -------
        Chain
            The chain.
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
                links.append(
                    Link.revolute(d=d, a=a, alpha=alpha, offset=theta, qlim=limit)
                )
            else:
                links.append(
                    Link.prismatic(theta=theta, a=a, alpha=alpha, offset=d, qlim=limit)
                )
        return cls(links, convention, **options)

    @classmethod
    def from_screws(
        cls,
        axes,
        home,
        frame="space",
        qlim=None,
        base=None,
        tool=None,
        name="chain",
        configurations=None,
    ):
        """A chain from its joint screws and home pose: the product of exponentials.

        frame="space": T(q) = base exp([S_1] q_1) ... exp([S_n] q_n) M tool, the S_i
        written in the base frame at q = 0; frame="body": T(q) = base M
        exp([B_1] q_1) ... exp([B_n] q_n) tool, the B_i written in the end-effector
        frame at q = 0.

        Parameters
        ----------
        axes : list of n Twist objects or 6-vectors [omega; v], or an (n, 6) array
            Unit screw axes, ``|omega| = 1`` for a revolute (pitch 0) or helical
            (pitch omega . v) joint, omega = 0 and ``|v| = 1`` for a prismatic one.
        home : array-like, shape (4, 4)
            The rigid transform M, the end-effector pose at q = 0 (m).
        frame : {'space', 'body'}, optional
            Where the axes are written.
        qlim : array-like, shape (n, 2), or None, optional
            Joint limits (rad, or m for prismatic joints; +-inf: none).
        base, tool : array-like, shape (4, 4), optional
            Rigid transforms (default identity).
        name : str, optional
            Used in messages and titles.
        configurations : dict, optional
            {name: joint vector (n,)}, named configurations.

        Returns
        -------
        Chain
            The chain.
        """
        if frame not in ("space", "body"):
            raise ValueError(f"frame must be 'space' or 'body', got {frame!r}")
        screws, exact = check_screws(axes)
        n = screws.shape[0]
        limits = [None] * n if qlim is None else limits_table(qlim, n)
        scale = length_scale(screws[:, 3:])
        chain = cls.__new__(cls)
        chain._setup(
            links=None,
            convention=None,
            screws=screws,
            exact_screws=exact,
            home=rigid(home, "home"),
            frame=frame,
            base=base,
            tool=tool,
            name=name,
            configurations=configurations,
            qlim=limits,
            joints=tuple(joint_kind(s, scale) for s in screws),
        )
        return chain

    @classmethod
    def from_urdf(cls, source, base_link=None, tip_link=None):
        """A chain from a URDF file or text.

        The joints from ``base_link`` to ``tip_link`` become joint screws in the base
        link's frame, exact where the file's numbers are (:mod:`screwkit.urdf`).
        Revolute, continuous and prismatic joints; fixed joints folded into their
        neighbours; limits into ``qlim``; ``chain.joint_names`` lists the URDF joint
        names.

        Parameters
        ----------
        source : str or os.PathLike
            URDF text (starting with '<') or a URDF file's path.
        base_link : str or None, optional
            The link whose frame is the base frame (default: the root).
        tip_link : str or None, optional
            The end-effector link (required when the tree branches).

        Returns
        -------
        Chain
            A chain from screws, named after the robot.
        """
        urdf = read_urdf(source, base_link, tip_link)
        chain = cls.from_screws(
            list(urdf.axes),
            urdf.home,
            name=urdf.name,
            qlim=[q or (-np.inf, np.inf) for q in urdf.qlim],
        )
        chain.__dict__["joint_names"] = urdf.joint_names
        return chain

    def _copy(self, **changes):
        """A new chain like this one with some constructor arguments changed."""
        options = dict(
            base=self.base,
            tool=self.tool,
            name=self.name,
            configurations=dict(self.configurations),
        )
        options.update(changes)
        if self.links is not None:
            return Chain(self.links, self.convention, **options)
        chain = Chain.from_screws(
            self._exact_screws,
            self._home,
            self.frame,
            qlim=[tuple(limit) for limit in self._qlim],
            **options,
        )
        chain.__dict__["joint_names"] = self.joint_names
        return chain

    def with_tool(self, tool):
        """The same chain with another tool transform.

        Parameters
        ----------
        tool : array-like, shape (4, 4)
            The rigid transform of the tool in the last frame (m).

        Returns
        -------
        Chain
            A new chain (chains are immutable).
        """
        return self._copy(tool=tool)

    def with_base(self, base):
        """The same chain on another base transform.

        Parameters
        ----------
        base : array-like, shape (4, 4)
            The rigid transform of the chain's base in the world frame (m).

        Returns
        -------
        Chain
            A new chain (chains are immutable).
        """
        return self._copy(base=base)

    # ---- description -----------------------------------------------------------------

    @property
    def n(self):
        """Number of joints."""
        return len(self.joints)

    @property
    def qlim(self):
        """Joint limits, shape (n, 2); -inf/inf where a joint has none."""
        return self._qlim.copy()

    @property
    def is_dh(self):
        """True for a chain described by a DH table, False for one built from screws."""
        return self.links is not None

    def __repr__(self):
        kinds = "".join(j.value for j in self.joints)
        form = (
            f"{self.convention.value} DH"
            if self.is_dh
            else f"product of exponentials, {self.frame} form"
        )
        return f"Chain({self.name!r}, {self.n} joints {kinds}, {form})"

    def table(self):
        """The chain's parameters as rows of strings, and a header.

        Returns
        -------
        header : list of str
            The columns' titles, with units.
        rows : list of list of str
            One row per joint: the DH table (theta, d, a, alpha; the joint variable
            marked q_i) or the joint screws (omega, v, pitch), and limits.
        """

        def number(value, scale=1.0):
            value = float(value) * scale
            return f"{value:.6g}" if value != 0 else "0"

        def limits(row):
            return (
                ""
                if row[0] == -np.inf and row[1] == np.inf
                else f"[{number(row[0], *(() if kind is Joint.PRISMATIC else (180 / np.pi,)))}, "  # noqa: E501
                f"{number(row[1], *(() if kind is Joint.PRISMATIC else (180 / np.pi,)))}]"  # noqa: E501
            )

        rows = []
        if self.is_dh:
            header = ["joint", "θ (deg)", "d (m)", "a (m)", "α (deg)", "limits"]
            for i, (link, kind, row) in enumerate(
                zip(self.links, self.joints, self._qlim), start=1
            ):
                degrees = 180 / np.pi
                offset = (
                    f" + {number(link.offset, degrees)}" if float(link.offset) else ""
                )
                theta = (
                    f"q{i}{offset}"
                    if kind is Joint.REVOLUTE
                    else number(link.theta, degrees)
                )
                d = (
                    number(link.d)
                    if kind is Joint.REVOLUTE
                    else f"q{i}"
                    + (f" + {number(link.offset)}" if float(link.offset) else "")
                )
                rows.append(
                    [
                        f"{i} {kind.value}",
                        theta,
                        d,
                        number(link.a),
                        number(link.alpha, degrees),
                        limits(row),
                    ]
                )
        else:
            header = ["joint", "ω", "v (m)", "pitch (m/rad)", "limits"]
            for i, (screw, kind, row) in enumerate(
                zip(self._screws, self.joints, self._qlim), start=1
            ):
                pitch = (
                    "∞"
                    if kind is Joint.PRISMATIC
                    else number(np.dot(screw[:3], screw[3:]))
                )
                rows.append(
                    [
                        f"{i} {kind.value}",
                        "(" + ", ".join(number(x) for x in screw[:3]) + ")",
                        "(" + ", ".join(number(x) for x in screw[3:]) + ")",
                        pitch,
                        limits(row),
                    ]
                )
        return header, rows

    def _repr_html_(self):
        """The parameter table, typeset (Jupyter and the book); ``repr`` stays one
        line."""
        header, rows = self.table()
        form = (
            f"{self.convention.value} DH"
            if self.is_dh
            else f"joint screws, {self.frame} form"
        )
        cells = "".join(f"<th>{h}</th>" for h in header)
        body = "".join(
            "<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows
        )
        return (
            f'<table class="screwkit-chain"><caption>{self.name}: {form}</caption>'
            f"<tr>{cells}</tr>{body}</table>"
        )

    # ---- input checks ----------------------------------------------------------------

    def check_q(self, q, name="q"):
        """``q`` checked and converted; a clear error otherwise.

        Parameters
        ----------
        q : array-like, shape (n,) or (N, n)
            Joint values (rad or m).
        name : str, optional
            The argument's name in the error message.

        Returns
        -------
        ndarray, shape (n,) or (N, n)
            ``q`` as float64.
        """
        q = as_float_array(q, name)
        if q.ndim not in (1, 2) or q.shape[-1] != self.n:
            raise ValueError(
                f"{name} must have {self.n} entries for this chain, shape ({self.n},) "
                f"or (N, {self.n}), got shape {q.shape}"
            )
        return q

    def check_one(self, q, name="q"):
        """``q`` checked as one configuration (a batch is refused, clearly).

        Parameters
        ----------
        q : array-like, shape (n,)
            Joint values (rad or m).
        name : str, optional
            The argument's name in the error message.

        Returns
        -------
        ndarray, shape (n,)
            ``q`` as float64.
        """
        q = self.check_q(q, name)
        if q.ndim != 1:
            raise ValueError(
                f"{name} must be one configuration of shape ({self.n},), got shape "
                f"{q.shape}"
            )
        return q

    @fill(parameters=_Q_PARAMETERS)
    def within_limits(self, q):
        """Whether every joint of q lies within its limits.

        {parameters}

        Returns
        -------
        bool or ndarray of bool, shape (N,)
            True where every joint is within its limits.
        """
        q = self.check_q(q)
        return np.all((q >= self._qlim[:, 0]) & (q <= self._qlim[:, 1]), axis=-1)

    # ---- exact -----------------------------------------------------------------------

    def _require_dh(self, what):
        if not self.is_dh:
            raise ValueError(
                f"{what} is defined for a DH chain; {self.name!r} is built from "
                "screws (it must be built by Chain(links) or Chain.from_table)"
            )

    def _exact_q(self, q, name="q"):
        """q for the exact routines: n numbers or SymPy expressions
        (the joint symbols if None)."""
        if q is None:
            return list(self.q_symbols)
        if isinstance(q, (str, bytes)) or not isinstance(
            q, (list, tuple, np.ndarray, sp.MatrixBase)
        ):
            raise TypeError(
                f"{name} must be a joint vector of {self.n} numbers or SymPy "
                f"expressions, got {describe(q)}"
            )
        values = list(q) if not isinstance(q, np.ndarray) else q.ravel().tolist()
        if len(values) != self.n or (isinstance(q, np.ndarray) and q.ndim != 1):
            raise ValueError(
                f"{name} must have {self.n} entries for this chain, got {len(values)}"
            )
        return [
            v if isinstance(v, float) else as_sympy_scalar(v, f"{name}[{i}]")
            for i, v in enumerate(values)
        ]

    def link_transforms(self, q=None):
        """The n exact link transforms A_i(q_i) of a DH chain.

        Parameters
        ----------
        q : sequence of n numbers or SymPy expressions, optional
            Joint values; the joint symbols q1..qn by default.

        Returns
        -------
        list of sympy.Matrix (4, 4)
            A_1, ..., A_n.
        """
        self._require_dh("link_transforms")
        q = self._exact_q(q)
        return [link.transform(qi, self.convention) for link, qi in zip(self.links, q)]

    def length_symbols(self):
        """Symbols a_i, d_i for every non-zero link length of a DH chain.

        Returns
        -------
        dict
            {symbol: value (m)}.
        """
        self._require_dh("length_symbols")
        table = {}
        for i, link in enumerate(self.links, start=1):
            lengths = (
                {"a": link.a}
                if link.joint is Joint.PRISMATIC
                else {"a": link.a, "d": link.d}
            )
            for kind, value in lengths.items():
                if not sp.sympify(value).is_zero:
                    index = (
                        i - 1
                        if self.convention is Convention.MODIFIED and kind == "a"
                        else i
                    )
                    table[sp.Symbol(f"{kind}{index}", positive=True)] = value
        return table

    def _with_symbolic_lengths(self):
        """The links with every non-zero length replaced by its symbol a_i or d_i."""
        lookup = {str(s): s for s in self.length_symbols()}
        links = []
        for i, link in enumerate(self.links, start=1):
            a_index = i - 1 if self.convention is Convention.MODIFIED else i
            a = lookup.get(f"a{a_index}", 0)
            d = lookup.get(f"d{i}", 0) if link.joint is Joint.REVOLUTE else link.d
            links.append(
                Link(
                    link.joint,
                    d=d,
                    a=a,
                    alpha=link.alpha,
                    theta=link.theta,
                    offset=link.offset,
                    qlim=link.qlim,
                )
            )
        return links

    def fk_symbolic(self, simplify=True, symbolic_lengths=False, upto=None):
        """The exact end-effector pose in the joint symbols q1..qn.

        Parameters
        ----------
        simplify : bool, optional
            Combine sums of angles (cos(q2)cos(q3) - sin(q2)sin(q3) -> cos(q2 + q3))
            after each factor, as textbooks write c23.
        symbolic_lengths : bool, optional
            (DH) use the symbols a_i, d_i of :meth:`length_symbols` for lengths.
        upto : int or None, optional
            (DH) k in 0..n gives the pose of frame k, 0T_k, without base or tool.

        Returns
        -------
        sympy.Matrix (4, 4)
            The pose.
        """
        simplify = check_flag(simplify, "simplify")
        symbolic_lengths = check_flag(symbolic_lengths, "symbolic_lengths")

        def tidy(T):
            return T.applyfunc(lambda e: TR10i(sp.expand(e))) if simplify else T

        if not self.is_dh:
            if symbolic_lengths or upto is not None:
                raise ValueError(
                    "symbolic_lengths and upto are for DH chains; this chain is built "
                    "from screws"
                )
            T = exact_matrix(self.base)
            factors = [
                exp_twist(S, q) for S, q in zip(self._exact_screws, self.q_symbols)
            ]
            home = exact_matrix(self._home)
            factors = (
                [home] + factors if self.frame == "body" else factors + [home]
            ) + [exact_matrix(self.tool)]
            for F in factors:
                T = tidy(T * F)
            return T
        links = self._with_symbolic_lengths() if symbolic_lengths else self.links
        count = self.n if upto is None else check_integer(upto, "upto", minimum=0)
        if count > self.n:
            raise ValueError(f"upto must be between 0 and {self.n}, got {upto!r}")
        full = upto is None
        T = exact_matrix(self.base) if full else sp.eye(4)
        for link, q in zip(links[:count], self.q_symbols):
            T = tidy(T * link.transform(q, self.convention))
        if full:
            T = tidy(T * exact_matrix(self.tool))
        return T

    def frames_symbolic(self, symbolic_lengths=False):
        """The exact frames base @ A_1 ... A_k for k = 0..n (no tool) of a DH chain.

        Parameters
        ----------
        symbolic_lengths : bool, optional
            Use the symbols a_i, d_i for lengths.

        Returns
        -------
        list of sympy.Matrix (4, 4)
            n + 1 frames, the base first.
        """
        self._require_dh("frames_symbolic")
        symbolic_lengths = check_flag(symbolic_lengths, "symbolic_lengths")
        base = exact_matrix(self.base)
        return [
            (
                base * self.fk_symbolic(symbolic_lengths=symbolic_lengths, upto=k)
            ).applyfunc(sp.expand)
            for k in range(self.n + 1)
        ]

    def joint_frames(self, frames):
        """Of the n + 1 frames of a DH chain (base first, no tool), the n whose z axis
        is a joint axis.

        Standard DH: joint i moves about z of frame i-1; modified DH: about z of frame
        i.

        Parameters
        ----------
        frames : list of n + 1 4x4 matrices
            As :meth:`frames_symbolic` returns them.

        Returns
        -------
        list of 4x4 matrices
            The n joint frames.
        """
        self._require_dh("joint_frames")
        if not isinstance(frames, (list, tuple)) or len(frames) != self.n + 1:
            raise TypeError(
                f"frames must be the n + 1 = {self.n + 1} frames of "
                f"frames_symbolic(), got {describe(frames)}"
            )
        return frames[:-1] if self.convention is Convention.STANDARD else frames[1:]

    def twists_symbolic(self, q=None, symbolic_lengths=False, rational=False):
        """The joint twists [omega; v] in the base frame, exactly.

        These are the columns of the space Jacobian.

        Parameters
        ----------
        q : sequence of n exact values or symbols, optional
            The joint vector (default the joint symbols q1..qn).
        symbolic_lengths : bool, optional
            (DH) use the symbols a_i, d_i for lengths.
        rational : bool, optional
            Read every decimal number of the model (lengths, pitches, base, tool,
            home) as the exact decimal it prints as (0.4318 -> 2159/5000) before any
            product, so no round-off term can appear.

        Returns
        -------
        list of sympy.Matrix (6, 1)
            The n twists.
        """
        q = self._exact_q(q)
        symbolic_lengths = check_flag(symbolic_lengths, "symbolic_lengths")
        rational = check_flag(rational, "rational")
        values = dict(
            zip(self.q_symbols, [decimal(v) if isinstance(v, float) else v for v in q])
        )
        base = exact_matrix(self.base)
        if rational:
            base = base.applyfunc(decimal)
        if self.is_dh:
            lengths = self.length_symbols() if rational and not symbolic_lengths else {}
            frames = self.frames_symbolic(symbolic_lengths or bool(lengths))
            frames = (
                [base * exact_matrix(self.base).inv() * T for T in frames]
                if rational
                else frames
            )
            twists = []
            for kind, T in zip(self.joints, self.joint_frames(frames)):
                z, o = T[:3, 2], T[:3, 3]
                twists.append(
                    axis_coordinates(z, o, 0)
                    if kind is Joint.REVOLUTE
                    else axis_coordinates(z, None, sp.oo)
                )
            exact = {s: decimal(sp.sympify(v)) for s, v in lengths.items()}
            return [_numbers_out(t.xreplace(exact).subs(values)) for t in twists]
        screws, home = self._exact_screws, exact_matrix(self._home)
        if rational:
            screws, home = (
                [S.applyfunc(decimal) for S in screws],
                home.applyfunc(decimal),
            )
        G = base * (home if self.frame == "body" else sp.eye(4))
        twists = []
        for S, qi in zip(screws, self.q_symbols):
            twists.append(_numbers_out(adjoint(G) * S, values))
            G = (G * exp_twist(S, qi)).applyfunc(sp.simplify)
        return twists

    def joint_twists(self, q):
        """The joint twists at q in the base frame.

        Exact q (SymPy numbers or symbols; the model's decimals and float entries of q
        are read as the exact decimals they print as): a
        :class:`~screwkit.systems.ScrewSystem` of Twists, so that ``.rank`` and
        ``.reciprocal()`` give a singular configuration's lost freedoms and the wrenches
        the structure bears without motors. Numeric q (n,): the same ScrewSystem, of
        float twists, whose rank is by SVD with its tolerance
        (1e-9 relative, :mod:`screwkit.systems`), as :func:`screwkit.mobility` does. A
        batch (N, n): the (N, n, 6) array of the space Jacobians' columns
        (``space_jacobian(q).T`` is one configuration's (n, 6) array).

        Parameters
        ----------
        q : sequence of n exact values or symbols, array-like (n,), or (N, n)
            Joint values (rad or m).

        Returns
        -------
        ScrewSystem or ndarray, shape (N, n, 6)
            The twists of one configuration, or the batch's array.
        """
        if is_symbolic(q):
            return ScrewSystem(
                [Twist(t) for t in self.twists_symbolic(q, rational=True)]
            )
        twists = np.swapaxes(self.space_jacobian(q), -1, -2)
        if twists.ndim == 3:
            return twists
        return ScrewSystem([Twist(t) for t in twists])

    # ---- fast ------------------------------------------------------------------------

    @cached_property
    def _program(self):
        """The chain as constants and unit joint twists for :mod:`screwkit._compiled`
        (floats only)."""
        if self.is_dh:
            parts = [
                dh_factors(link, i, self.convention)
                for i, link in enumerate(self.links, start=1)
            ]
            pres = [pre for pre, _, _ in parts] + [np.eye(4)]
            start = np.asarray(self.base) @ pres[0]
            factors, marks = [], {0: np.linalg.inv(pres[0])}
            for k, (_, twist, post) in enumerate(parts, start=1):
                after = post @ pres[k]
                if k == self.n:
                    after = after @ self.tool
                factors.append((twist, after, np.zeros(3)))
                marks[k] = np.linalg.inv(pres[k])
            offsets = np.array(
                [float(link._numbers(i)[0][3]) for i, link in enumerate(self.links, 1)]
            )
            return _compiled.Program(start, factors, marks), offsets
        home = np.asarray(self._home)
        if self.frame == "space":
            start, last = np.asarray(self.base), home @ self.tool
            points = axis_points(self._screws, np.zeros(3))
        else:
            start, last = np.asarray(self.base) @ home, np.asarray(self.tool)
            # the screws are in end-effector coordinates: start from the base origin
            # seen there
            points = axis_points(self._screws, -home[:3, :3].T @ home[:3, 3])
        factors = [(S, np.eye(4), r) for S, r in zip(self._screws, points)]
        factors[-1] = (factors[-1][0], last, factors[-1][2])
        marks = {k: translation(points[k]) for k in range(self.n)}
        marks[self.n] = np.eye(4)
        return _compiled.Program(start, factors, marks), np.zeros(self.n)

    @cached_property
    def _functions(self):
        """The generated functions, compiled on first use: {'pose' | 'axes' | 'frames':
        function}."""
        return {}

    def source(self, outputs="pose"):
        """The straight-line Python that computes this chain's ``outputs`` (a string).

        The function ``kinematics(t, c, s)`` generated from the chain's numbers (see
        :mod:`screwkit._compiled`): ``t`` the joint angles plus their offsets
        (t = q + offset; the DH theta or d offsets), ``c``, ``s`` their cosines and
        sines; it returns the entries row by row. ``outputs``: 'pose'
        (the 12 entries of T's top three rows), 'frames', 'space' or 'geometric'
        (the Jacobians, 6 x n) or 'axes' (each joint's twist and a point, then the
        pose). What :meth:`fk` and the Jacobians run, as text to read.

        Parameters
        ----------
        outputs : {'pose', 'frames', 'space', 'geometric', 'axes'}, optional
            What the generated function returns.

        Returns
        -------
        str
            The function's source.

        Examples
        --------
        >>> arm = Chain([Link.revolute(a=1.0)])
        >>> print(arm.source())  # doctest: +NORMALIZE_WHITESPACE
        def kinematics(t, c, s):
            c1 = c[0]
            s1 = s[0]
            return (c1, -1.0*s1, 0.0, c1, s1, c1, 0.0, s1, 0.0, 0.0, 1.0, 0.0,)
        """
        check_option(
            outputs, "outputs", ("pose", "frames", "space", "geometric", "axes")
        )
        return self._program[0].source(outputs)

    def _run(self, outputs, q, rows=None, out=None):
        """Generated code ``outputs`` at q: a list of entries for (n,), else
        ``out[rows[k]]`` filled."""
        program, offsets = self._program
        if outputs not in self._functions:
            self._functions[outputs] = program.compile(outputs)
        function = self._functions[outputs]
        if q.ndim == 1:
            return _compiled.evaluate(function, q + offsets)
        return _compiled.evaluate_batch(function, q + offsets, out, rows)

    @fill(parameters=_Q_PARAMETERS)
    def fk(self, q):
        """The end-effector pose.

        {parameters}

        Returns
        -------
        ndarray, shape (4, 4) or (N, 4, 4)
            The pose(s) in the base's world frame (m).
        """
        q = self.check_q(q)
        if q.ndim == 1:
            T = np.eye(4)
            T[:3] = np.reshape(self._run("pose", q), (3, 4))
            return T
        T = np.empty((4, 4, q.shape[0]))
        T[3] = np.array([0.0, 0.0, 0.0, 1.0])[:, None]
        self._run("pose", q, range(12), T.reshape(16, -1))
        return T.transpose(
            2, 0, 1
        )  # a view: each entry was computed as one contiguous row

    @fill(parameters=_Q_PARAMETERS)
    def frames(self, q):
        """The base frame and every link frame.

        DH chain: frame k is base @ A_1 ... A_k; the last frame also carries the tool.
        Chain from screws: frame k < n sits on the axis of joint k + 1
        (a point of it, moved by joints 1..k), frame 0 has the base's orientation, and
        the last frame is the end effector.

        {parameters}

        Returns
        -------
        ndarray, shape (n + 1, 4, 4) or (N, n + 1, 4, 4)
            The frames (m).
        """
        q = self.check_q(q)
        count = self.n + 1
        if q.ndim == 1:
            T = np.zeros((count, 4, 4))
            T[:, :3] = np.reshape(self._run("frames", q), (count, 3, 4))
            T[:, 3, 3] = 1.0
            return T
        T = np.zeros((count, 4, 4, q.shape[0]))
        T[:, 3, 3] = 1.0
        rows = [16 * (k // 12) + k % 12 for k in range(12 * count)]
        self._run("frames", q, rows, T.reshape(16 * count, -1))
        return np.ascontiguousarray(T.transpose(3, 0, 1, 2))

    def _twists_and_pose(self, q):
        """Joint twists, axis points and pose, batch last: omega, v, point (3, n[, N]),
        T (3, 4[, N])."""
        rows = 9 * self.n + 12
        if q.ndim == 1:
            values = np.array(self._run("axes", q))
        else:
            values = np.empty((rows, q.shape[0]))
            self._run("axes", q, range(rows), values)
        axes = values[:-12].reshape((self.n, 3, 3) + values.shape[1:])
        axes = np.moveaxis(axes, 0, 2)  # (3 kinds, 3 coordinates, n[, N])
        return (
            axes[0],
            axes[1],
            axes[2],
            values[-12:].reshape((3, 4) + values.shape[1:]),
        )

    @fill(parameters=_Q_PARAMETERS)
    def joint_axes(self, q):
        """Direction z_i and a point o_i of every joint axis in the base frame.

        DH: joint i moves about z of frame i-1 (standard) or of frame i (modified),
        through its origin. A prismatic joint's direction is its translation; its point
        is for drawing.

        {parameters}

        Returns
        -------
        z, o : ndarray, shape (n, 3) or (N, n, 3)
            Unit directions and points (m).
        """
        q = self.check_q(q)
        omega, v, point, _ = self._twists_and_pose(q)
        prismatic = np.array([j is Joint.PRISMATIC for j in self.joints])
        z = np.where(prismatic if q.ndim == 1 else prismatic[:, None], v, omega)
        z, point = np.moveaxis(z, 0, -1), np.moveaxis(point, 0, -1)  # (n[, N], 3)
        if q.ndim == 1:
            return z, point
        return np.swapaxes(z, 0, 1), np.swapaxes(point, 0, 1)

    # ---- Jacobians: outputs of the generated program ---------------------------------

    def _generated_jacobian(self, q, outputs):
        """A Jacobian generated as straight-line code ('space' or 'geometric'): (6, n)
        or (N, 6, n)."""
        q = self.check_q(q)
        n, rows = self.n, 6 * self.n
        if q.ndim == 1:
            return np.reshape(self._run(outputs, q), (6, n))

        def part(q_part):
            values = self._run(
                outputs, q_part, range(rows), np.empty((rows, q_part.shape[0]))
            )
            return values.reshape(6, n, -1).transpose(2, 0, 1)

        return _compiled.in_chunks(q, part, np.empty((q.shape[0], 6, n)))

    @fill(parameters=_Q_PARAMETERS)
    def space_jacobian(self, q):
        """The space Jacobian, columns [omega; v].

        Column i is the twist of joint i in the base frame, Ad(G_i) X_i:
        (z_i; o_i x z_i) for a revolute joint about z_i through o_i
        (v is the velocity of the body point at the base origin), (0; z_i) for a
        prismatic one, (z_i; o_i x z_i + h z_i) for a helical one of pitch h.

        {parameters}

        Returns
        -------
        ndarray, shape (6, n) or (N, 6, n)
            The Jacobian(s).
        """
        return self._generated_jacobian(q, "space")

    @fill(parameters=_Q_PARAMETERS)
    def geometric_jacobian(self, q):
        """The geometric Jacobian, rows [v; omega].

        Column i is the space twist moved to the end-effector point p:
        (v_i + omega_i x p; omega_i), i.e. (z_i x (p - o_i); z_i) for a revolute joint
        and (z_i; 0) for a prismatic one.

        {parameters}

        Returns
        -------
        ndarray, shape (6, n) or (N, 6, n)
            The Jacobian(s), base frame, end-effector point.
        """
        return self._generated_jacobian(q, "geometric")

    @fill(parameters=_Q_PARAMETERS)
    def body_jacobian(self, q):
        """The body Jacobian, columns [omega; v].

        Column i is joint i's twist in the end-effector frame, J_b = Ad(T^-1) J_s:
        (R^T omega_i; R^T (v_i + omega_i x p)) for the pose T = (R, p).

        {parameters}

        Returns
        -------
        ndarray, shape (6, n) or (N, 6, n)
            The Jacobian(s).
        """

        def columns(q_part):
            omega, v, _, T = self._twists_and_pose(q_part)
            R, linear = T[:, :3], v + _cross(omega, T[:, 3][:, None])
            rotate = "ji...,jk...->ik..."  # R^T x, column by column, batch last
            J = np.concatenate(
                [np.einsum(rotate, R, omega), np.einsum(rotate, R, linear)]
            )
            return J if q_part.ndim == 1 else J.transpose(2, 0, 1)

        q = self.check_q(q)
        if q.ndim == 1:
            return columns(q)
        return _compiled.in_chunks(q, columns, np.empty((q.shape[0], 6, self.n)))

    def jacobian_rows(self, q, rows="all"):
        """Some rows of the geometric Jacobian.

        'planar' reads v_x, v_y in the chain's base frame.

        Parameters
        ----------
        q : array-like, shape (n,) or (N, n)
            Joint values (rad or m).
        rows : {'all', 'position', 'orientation', 'planar'}, optional
            A key of :data:`ROWS`.

        Returns
        -------
        ndarray, shape (m, n) or (N, m, n)
            The m rows (6, 3, 3 or 2).
        """
        selected = check_rows(rows)
        J = self.geometric_jacobian(q)
        if rows == "planar":
            R = np.asarray(self.base)[:3, :3]
            return np.einsum("ji,...jk->...ik", R, J[..., :3, :])[..., selected, :]
        return J[..., selected, :]

    def singular_values(self, q, rows="all"):
        """Singular values of the geometric Jacobian's rows, largest first.

        Parameters
        ----------
        q : array-like, shape (n,) or (N, n)
            Joint values (rad or m).
        rows : {'all', 'position', 'orientation', 'planar'}, optional
            The rows of J used.

        Returns
        -------
        ndarray, shape (k,) or (N, k)
            k = min(rows, n) singular values.
        """
        check_rows(rows)
        q = self.check_q(q)

        def part(q_part):
            return np.linalg.svd(self.jacobian_rows(q_part, rows), compute_uv=False)

        return part(q) if q.ndim == 1 else _compiled.in_chunks(q, part)

    def lost_rank(self, sigma, rows="all"):
        """Whether Jacobian rows have lost rank, by NumPy's rule on the smallest
        singular value.

        Parameters
        ----------
        sigma : ndarray, shape (..., k)
            Singular values, largest first, as :meth:`singular_values` returns them.
        rows : {'all', 'position', 'orientation', 'planar'}, optional
            The rows they are of.

        Returns
        -------
        bool or ndarray of bool, shape (...)
            True where the rank is below k.
        """
        return _numeric.lost_rank(sigma, len(range(6)[check_rows(rows)]), self.n)

    def manipulability(self, q, rows="all"):
        """Yoshikawa's manipulability, the product of the singular values: () or (N,).

        That is sqrt(det(J J^T)) for J with no more rows than columns
        (sqrt(det(J^T J)) otherwise). Exactly 0.0 where J has lost rank
        (by NumPy's rank tolerance), so a singular configuration is an answer, not
        noise. With rows='all' the product mixes metres and radians; 'position' gives
        the volume factor of the velocity ellipsoid in m/s.

        Parameters
        ----------
        q : array-like, shape (n,) or (N, n)
            Joint values (rad or m).
        rows : {'all', 'position', 'orientation', 'planar'}, optional
            'position' (the rows v), 'orientation' (the rows omega) or 'planar'
            (v_x, v_y in the chain's base frame).

        Returns
        -------
        float or ndarray, shape (N,)
            The manipulability.
        """
        sigma = self.singular_values(q, rows)
        return np.where(self.lost_rank(sigma, rows), 0.0, np.prod(sigma, axis=-1))[()]

    def numeric_ik(self, T, q0, **options):
        """Numerical inverse kinematics of this chain: see
        :func:`screwkit.ik.numeric_ik`.

        Parameters
        ----------
        T : array-like, shape (4, 4)
            The target pose (m).
        q0 : array-like, shape (n,)
            The initial guess (rad or m).
        **options
            Tolerances and limits, as :func:`screwkit.ik.numeric_ik` takes them.

        Returns
        -------
        NumericIKResult
            With ``q``, ``success``, ``iterations`` and ``error``.
        """
        return _newton.numeric_ik(self, T, q0, **options)

    # ---- product of exponentials -----------------------------------------------------

    def home(self):
        """The end-effector pose at q = 0: the home pose of the product of
        exponentials.

        Returns
        -------
        ndarray, shape (4, 4)
            M (m).
        """
        return self.fk(np.zeros(self.n))

    def screw_axes(self):
        """The joint screws at q = 0 in the base frame.

        Revolute: (z, p x z) for the axis z through p; prismatic: (0, z).

        Returns
        -------
        ndarray, shape (n, 6)
            Rows [omega; v]: the columns of the space Jacobian at q = 0.
        """
        return self.space_jacobian(np.zeros(self.n)).T

    def body_screw_axes(self):
        """The joint screws at q = 0 in the end-effector frame.

        Returns
        -------
        ndarray, shape (n, 6)
            Rows [omega; v].
        """
        return self.body_jacobian(np.zeros(self.n)).T

    def fk_poe(self, q):
        """The pose by the product of exponentials exp([S1] q1) ... exp([Sn] qn) M.

        An independent route to :meth:`fk` (a loop of 4x4 exponentials), for checking.

        Parameters
        ----------
        q : array-like, shape (n,)
            Joint values (rad or m).

        Returns
        -------
        ndarray, shape (4, 4)
            The pose (m).
        """
        q = self.check_one(q)
        T = np.eye(4)
        for S, qi in zip(self.screw_axes(), q):
            T = T @ exp_twist(S, qi)
        return T @ self.home()

    # ---- second order: Jacobians in time (see screwkit.motion.acceleration) -------

    def _rates(self, q, dq):
        """q and the joint rates dq as float64 of one shape, (n,) or (N, n)."""
        q, dq = self.check_q(q), self.check_q(dq, "dq")
        if dq.shape != q.shape:
            raise ValueError(
                f"dq must have the shape of q, {q.shape}, got shape {dq.shape}"
            )
        return q, dq

    def _generated_jacobian_dot(self, outputs, q, dq):
        """dJ/dt of a generated Jacobian, 'space' or 'geometric', at rates dq.

        A batch q (N, n) is worked on laid out (6, n, N) as the generated code computes
        it, each entry contiguous over the batch (no transpose, no copy)."""
        q, dq = self._rates(q, dq)
        dot = getattr(_second_order, f"{outputs}_dot")  # space_dot, geometric_dot
        dot_rows = getattr(_second_order, f"{outputs}_dot_rows")
        if q.ndim == 1:
            return dot(self._generated_jacobian(q, outputs), dq)
        values = np.empty((6 * self.n, q.shape[0]))
        self._run(outputs, q, range(6 * self.n), values)
        rows = values.reshape(6, self.n, -1)
        return _second_order.batch_first(dot_rows(rows, np.ascontiguousarray(dq.T)))

    @fill(sections=_DOT_SECTIONS.format(layout="columns [omega; v]"))
    def space_jacobian_dot(self, q, dq):
        """The time derivative of the space Jacobian at joint rates dq (rad/s, m/s).

        Column i is the bracket [W_i, J_i] of joint i's twist with W_i, the sum of
        J_j dq_j over the joints j < i before it (the twist of link i - 1).

        {sections}
        """
        return self._generated_jacobian_dot("space", q, dq)

    @fill(sections=_DOT_SECTIONS.format(layout="columns [omega; v]"))
    def body_jacobian_dot(self, q, dq):
        """The time derivative of the body Jacobian at joint rates dq.

        Column i is [Jb_i, Wb_i], Wb_i the sum of Jb_j dq_j over the joints j > i.

        {sections}
        """
        q, dq = self._rates(q, dq)
        return _second_order.body_dot(self.body_jacobian(q), dq)

    @fill(sections=_DOT_SECTIONS.format(layout="rows [v; omega]"))
    def geometric_jacobian_dot(self, q, dq):
        """The time derivative of the geometric Jacobian at joint rates dq.

        Column i, (u_i; w_i), changes by (W_i x u_i + w_i x S_i; W_i x w_i), with W_i
        the sum of w_j dq_j over the joints j < i and S_i that of u_j dq_j over
        j >= i (the brackets of the space form moved to the end point).

        {sections}
        """
        return self._generated_jacobian_dot("geometric", q, dq)

    @fill(sections=_HESSIAN_SECTIONS)
    def space_hessian(self, q):
        """The kinematic Hessian of the space Jacobian, H[j, :, i] = dJ_i/dq_j.

        dJ_i/dq_j = [J_j, J_i] for j < i and 0 otherwise; dJ/dt = sum_j H[j] dq_j.

        {sections}
        """
        return _second_order.space_hessian(self.space_jacobian(self.check_q(q)))

    @fill(sections=_HESSIAN_SECTIONS)
    def body_hessian(self, q):
        """The kinematic Hessian of the body Jacobian, H[j, :, i] = dJb_i/dq_j.

        dJb_i/dq_j = [Jb_i, Jb_j] for j > i and 0 otherwise.

        {sections}
        """
        return _second_order.body_hessian(self.body_jacobian(self.check_q(q)))

    @fill(sections=_HESSIAN_SECTIONS)
    def geometric_hessian(self, q):
        """The kinematic Hessian of the geometric Jacobian, H[j, :, i] = dJ_i/dq_j.

        Rows [v; omega], as the Robotics Toolbox's ``hessian0``; its rows v are
        symmetric in i and j (they are the second derivatives of the end point).

        {sections}
        """
        return _second_order.geometric_hessian(self.geometric_jacobian(self.check_q(q)))
