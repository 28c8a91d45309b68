"""Serial chains described by Denavit–Hartenberg (DH) parameters.

A :class:`Chain` is a fixed model (links, base and tool); it computes forward kinematics
exactly (``fk_symbolic``: a SymPy matrix in the joint symbols q1..qn) or fast (``fk``:
float64, one configuration ``(n,)`` or a batch ``(N, n)``). The fast path is the exact
product compiled once with ``sympy.lambdify(..., cse=True)``, so both paths are the same
formula.

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
import enum
from dataclasses import dataclass
from functools import cached_property

import numpy as np
import sympy as sp
from sympy.simplify.fu import TR10i

from ._checks import as_float_array, check_transform, describe
from .transforms import exp_twist

_CHUNK = 8192  # poses per chunk of a batch

__all__ = ["Joint", "Convention", "Link", "Chain", "textbook"]


class Joint(enum.Enum):
    """The kind of a joint: its variable q is an angle (revolute) or a length (prismatic)."""

    REVOLUTE = "R"
    PRISMATIC = "P"


class Convention(enum.Enum):
    """Which DH convention a chain's table follows."""

    STANDARD = "standard"  # Rz(theta) Tz(d) Tx(a) Rx(alpha)
    MODIFIED = "modified"  # Craig: Rx(alpha) Tx(a) Rz(theta) Tz(d)


@dataclass(frozen=True)
class Link:
    """One row of a DH table (m, rad).

    The joint variable q adds to ``offset``: theta = q + offset for a revolute joint (then
    ``theta`` is unused), d = q + offset for a prismatic one (then ``d`` is unused).
    ``qlim`` is (min, max) of q, or None for no limit.
    """

    joint: Joint
    d: object = 0
    a: object = 0
    alpha: object = 0
    theta: object = 0
    offset: object = 0
    qlim: tuple = None

    @classmethod
    def revolute(cls, d=0, a=0, alpha=0, offset=0, qlim=None):
        """A revolute link: theta = q + offset."""
        return cls(Joint.REVOLUTE, d=d, a=a, alpha=alpha, offset=offset, qlim=_check_qlim(qlim))

    @classmethod
    def prismatic(cls, theta=0, a=0, alpha=0, offset=0, qlim=None):
        """A prismatic link: d = q + offset."""
        return cls(Joint.PRISMATIC, theta=theta, a=a, alpha=alpha, offset=offset, qlim=_check_qlim(qlim))

    def transform(self, q, convention=Convention.STANDARD):
        """The exact 4x4 link transform A(q) (a SymPy matrix) for a joint value or symbol q."""
        theta, d = (q + self.offset, self.d) if self.joint is Joint.REVOLUTE else (self.theta, q + self.offset)
        ct, st = sp.cos(theta), sp.sin(theta)
        ca, sa = sp.cos(_exact(self.alpha)), sp.sin(_exact(self.alpha))
        a = _exact(self.a)
        if convention is Convention.STANDARD:
            return sp.Matrix([[ct, -st * ca, st * sa, a * ct],
                              [st, ct * ca, -ct * sa, a * st],
                              [0, sa, ca, d],
                              [0, 0, 0, 1]])
        return sp.Matrix([[ct, -st, 0, a],
                          [st * ca, ct * ca, -sa, -sa * d],
                          [st * sa, ct * sa, ca, ca * d],
                          [0, 0, 0, 1]])


def _check_qlim(qlim):
    if qlim is None:
        return None
    limits = as_float_array(qlim, "qlim")
    if limits.shape != (2,) or not limits[0] < limits[1]:
        raise ValueError(f"qlim must be a pair (min, max) with min < max, got {qlim!r}")
    return (float(limits[0]), float(limits[1]))


def _exact(value):
    """Floats that are integers or multiples of pi/2 become exact, so cos(pi/2) is exactly 0."""
    value = sp.sympify(value)
    if isinstance(value, sp.Float):
        quarter_turns = float(value) / (np.pi / 2)
        if abs(quarter_turns - round(quarter_turns)) < 1e-15:
            return sp.pi / 2 * round(quarter_turns)
    return value


class Chain:
    """A serial chain of DH links between a fixed ``base`` and a ``tool`` transform.

    Parameters
    ----------
    links : sequence of Link, one per joint (n >= 1)
    convention : Convention.STANDARD (default) or Convention.MODIFIED
    base, tool : 4x4 transforms (default identity): T = base @ A_1 ... A_n @ tool
    name : str, used in messages and titles
    """

    def __init__(self, links, convention=Convention.STANDARD, base=None, tool=None, name="chain"):
        links = list(links) if isinstance(links, (list, tuple)) else links
        if not isinstance(links, list) or not links or not all(isinstance(k, Link) for k in links):
            raise TypeError(f"links must be a non-empty list of Link, got {describe(links)}")
        if not isinstance(convention, Convention):
            raise TypeError(f"convention must be a Convention (STANDARD or MODIFIED), got {convention!r}")
        self.links = tuple(links)
        self.convention = convention
        self.base = np.eye(4) if base is None else check_transform(np.asarray(base, dtype=float), "base")
        self.tool = np.eye(4) if tool is None else check_transform(np.asarray(tool, dtype=float), "tool")
        self.name = name
        self.q_symbols = sp.symbols(f"q1:{self.n + 1}", real=True)
        #: named configurations (e.g. 'zero', 'ready'): name -> (n,) array
        self.configurations = {}

    @classmethod
    def from_table(cls, table, joints=None, convention=Convention.STANDARD, qlim=None, **options):
        """A chain from a DH table of shape (n, 4), columns (theta, d, a, alpha) in m and rad.

        For a revolute joint, theta is the joint offset (theta = q + offset); for a prismatic
        one, d is (d = q + offset). ``joints`` is a sequence of Joint, or a string such as
        'RRP' (default all revolute); ``qlim`` an (n, 2) array or None.
        """
        rows = as_float_array(table, "table")
        if rows.ndim != 2 or rows.shape[1] != 4 or rows.shape[0] < 1:
            raise ValueError(f"table must have shape (n, 4), columns (theta, d, a, alpha), got shape {rows.shape}")
        n = rows.shape[0]
        kinds = [Joint.REVOLUTE] * n if joints is None else [Joint(j) if isinstance(j, str) else j for j in joints]
        if len(kinds) != n or not all(isinstance(j, Joint) for j in kinds):
            raise ValueError(f"joints must name {n} joints ('R' or 'P', or Joint members), got {joints!r}")
        limits = [None] * n if qlim is None else as_float_array(qlim, "qlim")
        if qlim is not None and limits.shape != (n, 2):
            raise ValueError(f"qlim must have shape ({n}, 2), got shape {limits.shape}")
        links = []
        for (theta, d, a, alpha), kind, limit in zip(rows, kinds, limits):
            limit = None if limit is None else tuple(limit)
            if kind is Joint.REVOLUTE:
                links.append(Link.revolute(d=d, a=a, alpha=alpha, offset=theta, qlim=limit))
            else:
                links.append(Link.prismatic(theta=theta, a=a, alpha=alpha, offset=d, qlim=limit))
        return cls(links, convention, **options)

    @property
    def n(self):
        """Number of joints."""
        return len(self.links)

    @property
    def joints(self):
        """The joint kinds, one per link."""
        return tuple(link.joint for link in self.links)

    @property
    def qlim(self):
        """Joint limits, shape (n, 2); -inf/inf where a joint has none."""
        return np.array([link.qlim if link.qlim else (-np.inf, np.inf) for link in self.links])

    def __repr__(self):
        kinds = "".join(j.value for j in self.joints)
        return f"Chain({self.name!r}, {self.n} joints {kinds}, {self.convention.value} DH)"

    # ---- input checks -------------------------------------------------------------------

    def check_q(self, q, name="q"):
        """``q`` as float64, shape (n,) or (N, n); a clear error otherwise."""
        q = as_float_array(q, name)
        if q.ndim not in (1, 2) or q.shape[-1] != self.n:
            raise ValueError(
                f"{name} must have {self.n} entries for this chain, shape ({self.n},) or (N, {self.n}), "
                f"got shape {q.shape}"
            )
        return q

    def within_limits(self, q):
        """True where every joint of q (shape (n,) or (N, n)) lies within its limits."""
        q = self.check_q(q)
        limits = self.qlim
        return np.all((q >= limits[:, 0]) & (q <= limits[:, 1]), axis=-1)

    # ---- exact ----------------------------------------------------------------------------

    def link_transforms(self, q=None):
        """The n exact link transforms A_i(q_i); q defaults to the joint symbols."""
        q = self.q_symbols if q is None else q
        return [link.transform(qi, self.convention) for link, qi in zip(self.links, q)]

    def length_symbols(self):
        """Symbols a_i, d_i for every non-zero link length: {symbol: value} (m)."""
        table = {}
        for i, link in enumerate(self.links, start=1):
            lengths = {"a": link.a} if link.joint is Joint.PRISMATIC else {"a": link.a, "d": link.d}
            for kind, value in lengths.items():
                if sp.sympify(value) != 0:
                    index = i - 1 if self.convention is Convention.MODIFIED and kind == "a" else i
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
            links.append(Link(link.joint, d=d, a=a, alpha=link.alpha, theta=link.theta,
                              offset=link.offset, qlim=link.qlim))
        return links

    def fk_symbolic(self, simplify=True, symbolic_lengths=False, upto=None):
        """The exact end-effector pose, a 4x4 SymPy matrix in the joint symbols q1..qn.

        simplify : combine sums of angles (cos(q2)cos(q3) - sin(q2)sin(q3) -> cos(q2 + q3))
            after each link, as textbooks write c23
        symbolic_lengths : use the symbols a_i, d_i of :meth:`length_symbols` for lengths
        upto : k in 0..n gives the pose of frame k, 0T_k, without base or tool
        """
        links = self._with_symbolic_lengths() if symbolic_lengths else self.links
        count = self.n if upto is None else int(upto)
        if not 0 <= count <= self.n:
            raise ValueError(f"upto must be between 0 and {self.n}, got {upto!r}")
        full = upto is None
        T = _exact_matrix(self.base) if full else sp.eye(4)
        for link, q in zip(links[:count], self.q_symbols):
            T = T * link.transform(q, self.convention)
            if simplify:
                T = T.applyfunc(lambda e: TR10i(sp.expand(e)))
        if full:
            T = T * _exact_matrix(self.tool)
            if simplify:
                T = T.applyfunc(lambda e: TR10i(sp.expand(e)))
        return T

    def frames_symbolic(self, symbolic_lengths=False):
        """The exact frames base @ A_1 ... A_k for k = 0..n (no tool): a list of n + 1 SymPy matrices."""
        base = _exact_matrix(self.base)
        return [(base * self.fk_symbolic(symbolic_lengths=symbolic_lengths, upto=k)).applyfunc(sp.expand)
                for k in range(self.n + 1)]

    def joint_frames(self, frames):
        """Of the n + 1 frames (base first, no tool), the n whose z axis is a joint axis.

        Standard DH: joint i moves about z of frame i-1; modified DH: about z of frame i.
        """
        return frames[:-1] if self.convention is Convention.STANDARD else frames[1:]

    # ---- fast -----------------------------------------------------------------------------

    @cached_property
    def _revolute_offsets(self):
        return np.array([float(sp.sympify(link.offset)) if link.joint is Joint.REVOLUTE else 0.0
                         for link in self.links])

    @cached_property
    def _angle_chain(self):
        """This chain with the revolute offsets moved into the joint symbols theta_i = q_i + offset_i."""
        angles = sp.symbols(f"theta1:{self.n + 1}", real=True)
        chain = Chain([Link(k.joint, k.d, k.a, k.alpha, k.theta, 0 if k.joint is Joint.REVOLUTE else k.offset)
                       for k in self.links], self.convention, self.base, self.tool)
        chain.q_symbols = angles
        return chain

    @cached_property
    def _fk_functions(self):
        """The exact end-effector pose compiled once (rows 0..2 of T, 12 entries)."""
        T = self._angle_chain.fk_symbolic(simplify=True)
        return _compile([T[i, j] for i in range(3) for j in range(4)], self._angle_chain.q_symbols)

    @cached_property
    def _angle_frames(self):
        """frames_symbolic() in the angles theta_i, and the pose with the tool: computed once."""
        return self._angle_chain.frames_symbolic(), self._angle_chain.fk_symbolic()

    @cached_property
    def _frames_functions(self):
        """Every frame base @ A_1 ... A_k (k = 0..n, the last with the tool) compiled once."""
        frames, end = self._angle_frames
        entries = [T[i, j] for T in frames[:-1] + [end] for i in range(3) for j in range(4)]
        return _compile(entries, self._angle_chain.q_symbols)

    @cached_property
    def _axes_functions(self):
        """The joint axes (z_i, o_i, i = 1..n) and the end-effector point p compiled once, 6n + 3 entries."""
        frames, end = self._angle_frames
        entries = [T[i, j] for T in self.joint_frames(frames) for j in (2, 3) for i in range(3)]
        return _compile(entries + list(end[:3, 3]), self._angle_chain.q_symbols)

    def _evaluate(self, functions, q, out=None, rows=None):
        """Run compiled ``functions`` (see :func:`_compile`) at q.

        q (n,) gives the list of entries (floats). A batch Q (N, n) writes entry k into
        ``out[rows[k]]`` (out of shape (M, N), the batch last: contiguous per entry) and returns out.
        """
        one, batch = functions
        angles = q + self._revolute_offsets
        if q.ndim == 1:
            return one(angles.tolist())
        angles = np.ascontiguousarray(angles.T)
        # in chunks, so that the temporaries stay in the cache and memory is reused
        for start in range(0, q.shape[0], _CHUNK):
            part = angles[:, start:start + _CHUNK]
            for row, value in zip(rows, batch(part, np.cos(part), np.sin(part))):
                out[row, start:start + _CHUNK] = value
        return out

    def fk(self, q):
        """The end-effector pose: q (n,) -> (4, 4); a batch Q (N, n) -> (N, 4, 4) (m)."""
        q = self.check_q(q)
        if q.ndim == 1:
            T = np.eye(4)
            T[:3] = np.reshape(self._evaluate(self._fk_functions, q), (3, 4))
            return T
        T = np.empty((4, 4, q.shape[0]))
        T[3] = np.array([0.0, 0.0, 0.0, 1.0])[:, None]
        self._evaluate(self._fk_functions, q, T.reshape(16, -1), range(12))
        return T.transpose(2, 0, 1)

    def frames(self, q):
        """The base frame and every link frame: q (n,) -> (n + 1, 4, 4), (N, n) -> (N, n + 1, 4, 4).

        Frame k is base @ A_1 ... A_k; the last frame also carries the tool.
        """
        q = self.check_q(q)
        count = self.n + 1
        if q.ndim == 1:
            T = np.zeros((count, 4, 4))
            T[:, :3] = np.reshape(self._evaluate(self._frames_functions, q), (count, 3, 4))
            T[:, 3, 3] = 1.0
            return T
        T = np.zeros((count, 4, 4, q.shape[0]))
        T[:, 3, 3] = 1.0
        rows = [16 * (k // 12) + k % 12 for k in range(12 * count)]
        self._evaluate(self._frames_functions, q, T.reshape(16 * count, -1), rows)
        return T.transpose(3, 0, 1, 2)

    def joint_axes(self, q):
        """Direction z_i and a point o_i of every joint axis in the base frame, each (n, 3) or (N, n, 3).

        Standard DH: joint i moves about z of frame i-1; modified DH: about z of frame i.
        """
        from .jacobians import joint_axes

        return joint_axes(self, q)

    # ---- Jacobians ------------------------------------------------------------------------

    def geometric_jacobian(self, q):
        """Rows [v; omega] in the base frame at the end-effector point: (n,) -> (6, n), (N, n) -> (N, 6, n)."""
        from .jacobians import geometric_jacobian

        return geometric_jacobian(self, q)

    def space_jacobian(self, q):
        """Columns are the joint twists [omega; v] in the base frame: (n,) -> (6, n), (N, n) -> (N, 6, n)."""
        from .jacobians import space_jacobian

        return space_jacobian(self, q)

    def manipulability(self, q, rows="all"):
        """Yoshikawa's sqrt(det(J J^T)) of the geometric Jacobian: () or (N,); 0.0 where singular.

        rows: 'all', 'position' (the rows v), 'orientation' (the rows omega) or 'planar' (v_x, v_y).
        """
        from .jacobians import manipulability

        return manipulability(self, q, rows)

    # ---- product of exponentials ----------------------------------------------------------

    def home(self):
        """The end-effector pose at q = 0, M (4, 4): the home pose of the product of exponentials."""
        return self.fk(np.zeros(self.n))

    def screw_axes(self):
        """The joint screws at q = 0 in the base frame, (n, 6) rows [omega; v]: the columns of
        the space Jacobian at q = 0. Revolute: (z, p x z) for the axis z through p; prismatic: (0, z).
        """
        return self.space_jacobian(np.zeros(self.n)).T

    def fk_poe(self, q):
        """The pose by the product of exponentials exp([S1] q1) ... exp([Sn] qn) M, q (n,) -> (4, 4)."""
        q = self.check_q(q)
        if q.ndim != 1:
            raise ValueError(f"q must be one configuration of shape ({self.n},), got shape {q.shape}")
        T = np.eye(4)
        for S, qi in zip(self.screw_axes(), q):
            T = T @ exp_twist(S, qi)
        return T @ self.home()


def _compile(entries, angles):
    """Compile exact expressions of joint angles (and prismatic variables) once.

    Returns (one, batch): ``one(angles)`` takes a list of n floats (math module, no array
    overhead); ``batch(angles, cosines, sines)`` takes (n, M) arrays. Trigonometric functions
    of arrays cost far more than products, so the batch version is given each cos/sin once
    and sums of angles are expanded into products (cos(t2 + t3) -> c2 c3 - s2 s3).
    """
    n = len(angles)
    one = sp.lambdify([angles], entries, modules="math", cse=True)
    c = sp.symbols(f"c1:{n + 1}")
    s = sp.symbols(f"s1:{n + 1}")
    trig = {sp.cos(t): ci for t, ci in zip(angles, c)} | {sp.sin(t): si for t, si in zip(angles, s)}
    sums = {f: sp.expand_trig(f) for e in entries for f in e.atoms(sp.cos, sp.sin) if f not in trig}
    batch_entries = [sp.sympify(e).xreplace(sums).xreplace(trig) for e in entries]
    batch = sp.lambdify([angles, c, s], batch_entries, modules="numpy", cse=True)
    return one, batch


def _exact_matrix(T):
    """A numeric 4x4 as a SymPy matrix, exact where the entries are integers."""
    return sp.Matrix(4, 4, [sp.Integer(int(v)) if float(v).is_integer() else sp.Float(v) for v in T.flat])


def textbook(expr, q_symbols=None, collect=True):
    """``expr`` in textbook notation: cos(q1) -> c1, sin(q2 + q3) -> s23.

    With ``collect``, sums are grouped by c1/s1 first, then by the next angles, which gives
    nested forms like c1 (c23 (...) - s23 (...)) - s1 (...).
    """
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: textbook(e, q_symbols, collect))
    expr = sp.sympify(expr)
    q_symbols = q_symbols or sorted((s for s in expr.free_symbols if str(s).startswith("q")), key=str)
    index = {q: str(q)[1:] for q in q_symbols}
    replacements, order = {}, []
    for function, letter in ((sp.cos, "c"), (sp.sin, "s")):
        for call in expr.atoms(function):
            argument = call.args[0]
            terms = argument.args if isinstance(argument, sp.Add) else (argument,)
            if all(t in index for t in terms):
                label = "".join(sorted((index[t] for t in terms), key=int))
                symbol = sp.Symbol(f"{letter}_{{{label}}}" if len(label) > 1 else f"{letter}{label}")
                replacements[call] = symbol
                order.append((label, letter, symbol))
    result = expr.xreplace(replacements)
    if collect and order:
        order.sort(key=lambda item: (len(item[0]), item[0], item[1]))
        result = _nested_collect(sp.expand(result), [symbol for _, _, symbol in order])
    return result


def _nested_collect(expr, symbols):
    """Collect by the first symbol pair (c_k, s_k) present, then recurse into the coefficients."""
    present = [s for s in symbols if expr.has(s)]
    if not present or not isinstance(expr, sp.Add):
        return expr
    lead = str(present[0])[1:]
    group = [s for s in present if str(s)[1:] == lead]
    rest = [s for s in present if s not in group]
    collected = sp.collect(expr, group, evaluate=False)
    if len(collected) == 1 and sp.S.One in collected:
        return _nested_collect(expr, rest)
    return sp.Add(*[_nested_collect(coeff, rest) * key for key, coeff in collected.items()])
