"""A chain's exact kinematics (SymPy): link transforms, FK and frames in the joint
symbols, and joint twists at exact joint values.

The functions take the chain first; each is the :class:`~screwkit.chains.Chain` method
of the same name (``chain.fk_symbolic()`` is ``fk_symbolic(chain)``), so the chain
describes the arm and this module computes on it. The chain's table of parameters
(``chain.table()``) is here too: it prints the same numbers exactly as read.
"""

import numpy as np
import sympy as sp
from sympy.simplify.fu import TR10i

from ._checks import as_sympy_scalar, check_flag, check_integer, describe, is_symbolic
from ._docstrings import CHAIN, fill
from .lie import adjoint
from .links import Convention, Joint, Link, decimal, exact_matrix
from .screws import Twist
from .systems import ScrewSystem
from .transforms import axis_coordinates, exp_twist


def _numbers_out(matrix, values=None):
    """``matrix`` at ``values``, expanded; with no symbol left, trigonometric functions
    of sums are expanded too (sin(pi/4 - atan(u)) becomes an algebraic number), so that
    screw-system ranks see the numbers themselves, not unrelated-looking trigonometric
    atoms."""
    matrix = matrix.subs(values) if values else matrix
    if matrix.free_symbols:
        return matrix.applyfunc(sp.expand)
    return matrix.applyfunc(lambda e: sp.radsimp(sp.expand(sp.expand_trig(e))))


def _require_dh(chain, what):
    if not chain.is_dh:
        raise ValueError(
            f"{what} is defined for a DH chain; {chain.name!r} is built from "
            "screws (it must be built by Chain(links) or Chain.from_table)"
        )


def _exact_q(chain, q, name="q"):
    """q for the exact routines: n numbers or SymPy expressions
    (the joint symbols if None)."""
    if q is None:
        return list(chain.q_symbols)
    if isinstance(q, (str, bytes)) or not isinstance(
        q, (list, tuple, np.ndarray, sp.MatrixBase)
    ):
        raise TypeError(
            f"{name} must be a joint vector of {chain.n} numbers or SymPy "
            f"expressions, got {describe(q)}"
        )
    values = list(q) if not isinstance(q, np.ndarray) else q.ravel().tolist()
    if len(values) != chain.n or (isinstance(q, np.ndarray) and q.ndim != 1):
        raise ValueError(
            f"{name} must have {chain.n} entries for this chain, got {len(values)}"
        )
    return [
        v if isinstance(v, float) else as_sympy_scalar(v, f"{name}[{i}]")
        for i, v in enumerate(values)
    ]


@fill(chain=CHAIN)
def link_transforms(chain, q=None):
    """The n exact link transforms A_i(q_i) of a DH chain.

    {chain}
    q : sequence of n numbers or SymPy expressions, optional
        Joint values; the joint symbols q1..qn by default.

    Returns
    -------
    list of sympy.Matrix (4, 4)
        A_1, ..., A_n.

    Examples
    --------
    Link 2 of a planar 2R arm with unit links: Rz(q2) then 1 m along the new x.

    >>> import screwkit as sk
    >>> A1, A2 = link_transforms(sk.robots.planar([1.0, 1.0]))
    >>> A2[:2, :]
    Matrix([
    [cos(q2), -sin(q2), 0, 1.0*cos(q2)],
    [sin(q2),  cos(q2), 0, 1.0*sin(q2)]])
    """
    chain._require_dh("link_transforms")
    q = chain._exact_q(q)
    return [link.transform(qi, chain.convention) for link, qi in zip(chain.links, q)]


@fill(chain=CHAIN)
def length_symbols(chain):
    """Symbols a_i, d_i for every non-zero link length of a DH chain.

    {chain}

    Returns
    -------
    dict
        {symbol: value (m)}.

    Examples
    --------
    >>> import screwkit as sk
    >>> length_symbols(sk.robots.planar([1.0, 0.5]))
    {a1: 1.0, a2: 0.5}
    """
    chain._require_dh("length_symbols")
    table = {}
    for i, link in enumerate(chain.links, start=1):
        lengths = (
            {"a": link.a}
            if link.joint is Joint.PRISMATIC
            else {"a": link.a, "d": link.d}
        )
        for kind, value in lengths.items():
            if not sp.sympify(value).is_zero:
                index = (
                    i - 1
                    if chain.convention is Convention.MODIFIED and kind == "a"
                    else i
                )
                table[sp.Symbol(f"{kind}{index}", positive=True)] = value
    return table


def _with_symbolic_lengths(chain):
    """The links with every non-zero length replaced by its symbol a_i or d_i."""
    lookup = {str(s): s for s in chain.length_symbols()}
    links = []
    for i, link in enumerate(chain.links, start=1):
        a_index = i - 1 if chain.convention is Convention.MODIFIED else i
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


@fill(chain=CHAIN)
def fk_symbolic(chain, simplify=True, symbolic_lengths=False, upto=None):
    """The exact end-effector pose in the joint symbols q1..qn.

    {chain}
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

    Examples
    --------
    The tip of a planar 2R arm: (a1 c1 + a2 c12, a1 s1 + a2 s12).

    >>> import screwkit as sk
    >>> T = fk_symbolic(sk.robots.planar([1.0, 1.0]), symbolic_lengths=True)
    >>> T[:2, 3]
    Matrix([
    [a1*cos(q1) + a2*cos(q1 + q2)],
    [a1*sin(q1) + a2*sin(q1 + q2)]])
    """
    simplify = check_flag(simplify, "simplify")
    symbolic_lengths = check_flag(symbolic_lengths, "symbolic_lengths")

    def tidy(T):
        return T.applyfunc(lambda e: TR10i(sp.expand(e))) if simplify else T

    if not chain.is_dh:
        if symbolic_lengths or upto is not None:
            raise ValueError(
                "symbolic_lengths and upto are for DH chains; this chain is built "
                "from screws"
            )
        T = exact_matrix(chain.base)
        factors = [
            exp_twist(S, q) for S, q in zip(chain._exact_screws, chain.q_symbols)
        ]
        home = exact_matrix(chain._home)
        factors = ([home] + factors if chain.frame == "body" else factors + [home]) + [
            exact_matrix(chain.tool)
        ]
        for F in factors:
            T = tidy(T * F)
        return T
    links = chain._with_symbolic_lengths() if symbolic_lengths else chain.links
    count = chain.n if upto is None else check_integer(upto, "upto", minimum=0)
    if count > chain.n:
        raise ValueError(f"upto must be between 0 and {chain.n}, got {upto!r}")
    full = upto is None
    T = exact_matrix(chain.base) if full else sp.eye(4)
    for link, q in zip(links[:count], chain.q_symbols):
        T = tidy(T * link.transform(q, chain.convention))
    if full:
        T = tidy(T * exact_matrix(chain.tool))
    return T


@fill(chain=CHAIN)
def frames_symbolic(chain, symbolic_lengths=False):
    """The exact frames base @ A_1 ... A_k for k = 0..n (no tool) of a DH chain.

    {chain}
    symbolic_lengths : bool, optional
        Use the symbols a_i, d_i for lengths.

    Returns
    -------
    list of sympy.Matrix (4, 4)
        n + 1 frames, the base first.

    Examples
    --------
    The origins of a planar 2R arm's frames: the base, the elbow, the tip.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> [F[:2, 3].T for F in frames_symbolic(arm, symbolic_lengths=True)]
    [Matrix([[0, 0]]), Matrix([[a1*cos(q1), a1*sin(q1)]]),
     Matrix([[a1*cos(q1) + a2*cos(q1 + q2), a1*sin(q1) + a2*sin(q1 + q2)]])]
    """
    chain._require_dh("frames_symbolic")
    symbolic_lengths = check_flag(symbolic_lengths, "symbolic_lengths")
    base = exact_matrix(chain.base)
    return [
        (base * chain.fk_symbolic(symbolic_lengths=symbolic_lengths, upto=k)).applyfunc(
            sp.expand
        )
        for k in range(chain.n + 1)
    ]


@fill(chain=CHAIN)
def joint_frames(chain, frames):
    """Of the n + 1 frames of a DH chain (base first, no tool), the n whose z axis
    is a joint axis.

    Standard DH: joint i moves about z of frame i-1; modified DH: about z of frame
    i.

    {chain}
    frames : list of n + 1 4x4 matrices
        As :meth:`frames_symbolic` returns them.

    Returns
    -------
    list of 4x4 matrices
        The n joint frames.

    Examples
    --------
    Standard DH: a planar 2R arm's joints turn about z of frames 0 (the base) and 1
    (the elbow, at a1 (c1, s1)).

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> F0, F1 = joint_frames(arm, frames_symbolic(arm, symbolic_lengths=True))
    >>> F1[:3, 3].T
    Matrix([[a1*cos(q1), a1*sin(q1), 0]])
    """
    chain._require_dh("joint_frames")
    if not isinstance(frames, (list, tuple)) or len(frames) != chain.n + 1:
        raise TypeError(
            f"frames must be the n + 1 = {chain.n + 1} frames of "
            f"frames_symbolic(), got {describe(frames)}"
        )
    return frames[:-1] if chain.convention is Convention.STANDARD else frames[1:]


@fill(chain=CHAIN)
def twists_symbolic(chain, q=None, symbolic_lengths=False, rational=False):
    """The joint twists [omega; v] in the base frame, exactly.

    These are the columns of the space Jacobian.

    {chain}
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

    Examples
    --------
    Joint 2 of a planar 2R arm turns about z through the elbow o = a1 (c1, s1, 0):
    its twist is (z; o x z) = (0, 0, 1, a1 s1, -a1 c1, 0).

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> twists_symbolic(arm, symbolic_lengths=True)[1].T
    Matrix([[0, 0, 1, a1*sin(q1), -a1*cos(q1), 0]])
    """
    q = chain._exact_q(q)
    symbolic_lengths = check_flag(symbolic_lengths, "symbolic_lengths")
    rational = check_flag(rational, "rational")
    values = dict(
        zip(chain.q_symbols, [decimal(v) if isinstance(v, float) else v for v in q])
    )
    base = exact_matrix(chain.base)
    if rational:
        base = base.applyfunc(decimal)
    if chain.is_dh:
        lengths = chain.length_symbols() if rational and not symbolic_lengths else {}
        frames = chain.frames_symbolic(symbolic_lengths or bool(lengths))
        frames = (
            [base * exact_matrix(chain.base).inv() * T for T in frames]
            if rational
            else frames
        )
        twists = []
        for kind, T in zip(chain.joints, chain.joint_frames(frames)):
            z, o = T[:3, 2], T[:3, 3]
            twists.append(
                axis_coordinates(z, o, 0)
                if kind is Joint.REVOLUTE
                else axis_coordinates(z, None, sp.oo)
            )
        exact = {s: decimal(sp.sympify(v)) for s, v in lengths.items()}
        return [_numbers_out(t.xreplace(exact).subs(values)) for t in twists]
    screws, home = chain._exact_screws, exact_matrix(chain._home)
    if rational:
        screws, home = (
            [S.applyfunc(decimal) for S in screws],
            home.applyfunc(decimal),
        )
    G = base * (home if chain.frame == "body" else sp.eye(4))
    twists = []
    for S, qi in zip(screws, chain.q_symbols):
        twists.append(_numbers_out(adjoint(G) * S, values))
        G = (G * exp_twist(S, qi)).applyfunc(sp.simplify)
    return twists


@fill(chain=CHAIN)
def joint_twists(chain, q):
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

    {chain}
    q : sequence of n exact values or symbols, array-like (n,), or (N, n)
        Joint values (rad or m).

    Returns
    -------
    ScrewSystem or ndarray, shape (N, n, 6)
        The twists of one configuration, or the batch's array.

    Examples
    --------
    A planar 3R arm stretched out has three parallel axes in one plane: their
    twists span 2 dimensions, not 3 (a singular configuration); bent, all 3.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0, 1.0])
    >>> joint_twists(arm, [0, 0, 0]).rank, joint_twists(arm, [0, sp.pi / 2, 0]).rank
    (2, 3)
    >>> joint_twists(arm, np.zeros((4, 3))).shape  # a batch of 4
    (4, 3, 6)
    """
    if is_symbolic(q):
        return ScrewSystem([Twist(t) for t in chain.twists_symbolic(q, rational=True)])
    twists = np.swapaxes(chain.space_jacobian(q), -1, -2)
    if twists.ndim == 3:
        return twists
    return ScrewSystem([Twist(t) for t in twists])


@fill(chain=CHAIN)
def table(chain):
    """The chain's parameters as rows of strings, and a header.

    {chain}

    Returns
    -------
    header : list of str
        The columns' titles, with units.
    rows : list of list of str
        One row per joint: the DH table (theta, d, a, alpha; the joint variable
        marked q_i) or the joint screws (omega, v, pitch), and limits.

    Examples
    --------
    >>> import screwkit as sk
    >>> header, rows = table(sk.robots.planar([1.0, 0.5]))
    >>> header
    ['joint', 'θ (deg)', 'd (m)', 'a (m)', 'α (deg)', 'limits']
    >>> rows
    [['1 R', 'q1', '0', '1', '0', ''], ['2 R', 'q2', '0', '0.5', '0', '']]
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
    if chain.is_dh:
        header = ["joint", "θ (deg)", "d (m)", "a (m)", "α (deg)", "limits"]
        for i, (link, kind, row) in enumerate(
            zip(chain.links, chain.joints, chain._qlim), start=1
        ):
            degrees = 180 / np.pi
            offset = f" + {number(link.offset, degrees)}" if float(link.offset) else ""
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
            zip(chain._screws, chain.joints, chain._qlim), start=1
        ):
            pitch = (
                "∞" if kind is Joint.PRISMATIC else number(np.dot(screw[:3], screw[3:]))
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


def _repr_html_(chain):
    """The parameter table, typeset (Jupyter and the book); ``repr`` stays one
    line."""
    header, rows = chain.table()
    form = (
        f"{chain.convention.value} DH"
        if chain.is_dh
        else f"joint screws, {chain.frame} form"
    )
    cells = "".join(f"<th>{h}</th>" for h in header)
    body = "".join(
        "<tr>" + "".join(f"<td>{c}</td>" for c in row) + "</tr>" for row in rows
    )
    return (
        f'<table class="screwkit-chain"><caption>{chain.name}: {form}</caption>'
        f"<tr>{cells}</tr>{body}</table>"
    )
