"""A chain's numeric kinematics as straight-line Python, generated from numbers
(no SymPy).

Every serial chain, whatever way it was described (a DH table, or joint screws and a
home pose), is the product

    T(q) = C_0  exp([X_1] theta_1) C_1  exp([X_2] theta_2) C_2 ...
    exp([X_n] theta_n) C_n,

of constant rigid transforms C_k and exponentials of unit joint twists X_k = (w; v)
written in the frame just before them, with theta_k = q_k + offset_k. For a unit w the
exponential is

    R = (I + [w]^2) + sin(theta) [w] - cos(theta) [w]^2,
    p = [w] v + theta (v + [w]^2 v) - cos(theta) [w] v - sin(theta) [w]^2 v,

and for w = 0 (a prismatic joint) R = I, p = theta v: every entry is a fixed linear
combination of 1, cos(theta), sin(theta) and theta. :class:`Program` multiplies these
out once, symbol by symbol, dropping every product by an exact 0 or 1, and writes the
result as a Python function. Run on floats it costs microseconds; run on arrays
(a batch of configurations, the batch last) it is vectorised NumPy. Building it takes
about a millisecond per joint.

The same walk gives, at no extra cost, the joint twists in the base frame
(the columns of the space Jacobian, Ad(G_k) X_k for the frame G_k just before joint k),
a point on each joint axis, and any intermediate frame the chain asks to record
(its link frames).
"""

import math
import re
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .tolerances import SNAP_TOL
from .transforms import _skew

#: Coefficients this close to 0 or +-1 are taken as exact (cos(pi/2) computes as 6e-17):
#: :data:`screwkit.tolerances.SNAP_TOL`.
SNAP = SNAP_TOL

#: Configurations per chunk of a batch: the one chunk size of screwkit
#: (the generated code, the Jacobians and their measures, the closed-form IK, the
#: workspace sweeps). The temporaries of a chunk stay in the cache, and the memory of a
#: big batch stays bounded.
CHUNK = 8192


def in_chunks(batch, function, out=None):
    """``function(part)`` over chunks of :data:`CHUNK` rows of ``batch`` (N, ...).

    With ``out`` (an array of N rows), each result is written into its rows and ``out``
    is returned; without, the results are concatenated (one call for a batch of one
    chunk).
    """
    if out is None:
        if batch.shape[0] <= CHUNK:
            return function(batch)
        return np.concatenate(
            [function(batch[k : k + CHUNK]) for k in range(0, batch.shape[0], CHUNK)]
        )
    for k in range(0, batch.shape[0], CHUNK):
        out[k : k + CHUNK] = function(batch[k : k + CHUNK])
    return out


def _snap(array):
    array = np.where(np.abs(array) < SNAP, 0.0, array)
    for one in (1.0, -1.0):
        array = np.where(np.abs(array - one) < SNAP, one, array)
    return array


def exponential_coefficients(twist):
    """The 4x4 coefficient matrices (K1, Kc, Ks, Kt) with
    exp([X] theta) = K1 + Kc cos + Ks sin + Kt theta.

    ``twist`` (6,) is a unit twist: |w| = 1, or w = 0 and |v| = 1.
    """
    w, v = np.asarray(twist[:3], dtype=float), np.asarray(twist[3:], dtype=float)
    K1, Kc, Ks, Kt = (np.zeros((4, 4)) for _ in range(4))
    K1[3, 3] = 1.0
    if not np.any(w):
        K1[:3, :3] = np.eye(3)
        Kt[:3, 3] = v
        return K1, Kc, Ks, Kt
    W = _skew(w)
    W2 = W @ W
    K1[:3, :3], Ks[:3, :3], Kc[:3, :3] = np.eye(3) + W2, W, -W2
    K1[:3, 3], Kt[:3, 3], Kc[:3, 3], Ks[:3, 3] = W @ v, v + W2 @ v, -(W @ v), -(W2 @ v)
    return K1, Kc, Ks, Kt


class JointFactor(NamedTuple):
    """One joint of a Program: exp([twist] theta_k) post, and a point on the axis
    (drawing)."""

    twist: np.ndarray  # X_k (6,), a unit twist in the frame just before the joint
    post: np.ndarray  # C_k (4, 4), the constant after the exponential
    point: np.ndarray  # (3,) a point of the axis in that frame


@dataclass(frozen=True)
class Term:
    """coefficient * f1 * f2 * ...: a number times a product of named values.

    The names are those of the generated code: ``c3``, ``s3``, ``t3``
    (cos, sin and the angle of joint 3) and ``e12`` (an earlier line). No factors: the
    constant ``coefficient``.
    """

    coefficient: float
    factors: tuple = ()

    def times(self, other):
        """The product of two terms (coefficients multiplied, factors side by side)."""
        return Term(self.coefficient * other.coefficient, self.factors + other.factors)

    def negated(self):
        return Term(-self.coefficient, self.factors)

    def magnitude_text(self):
        """|coefficient| * factors as code: 'c1*e4', or '0.4318*c1*e4'."""
        product, size = "*".join(self.factors), abs(self.coefficient)
        return product if size == 1.0 else f"{size!r}*{product}"

    def text(self):
        """The term as code, sign included: 'e4', '-1.0*c2', '0.4318*s1'."""
        product = "*".join(self.factors)
        return product if self.coefficient == 1.0 else f"{self.coefficient!r}*{product}"


class Program:
    """Generates the straight-line code of one chain; see the module docstring.

    Parameters
    ----------
    start : (4, 4) the constant C_0
    factors : list of (twist (6,), post (4, 4), point (3,)) per joint, a JointFactor:
        X_k, the constant C_k after the exponential, and a point on the joint axis in
        the frame just before it
    marks : dict {k: (4, 4) offset}: record the frame reached after joint k
        (k = 0 before any joint) times the offset, as a link frame
    """

    def __init__(self, start, factors, marks=None):
        self.start = np.asarray(start, dtype=float)
        self.factors = [
            JointFactor(
                np.asarray(x, dtype=float),
                np.asarray(c, dtype=float),
                np.asarray(r, dtype=float),
            )
            for x, c, r in factors
        ]
        self.marks = dict(marks or {})
        self.n = len(self.factors)

    # ---- code generation -------------------------------------------------------------
    # An entry of a matrix being multiplied out is a float (a constant) or a Term.

    def _new(self, expression):
        name = f"e{self._count}"
        self._count += 1
        self._lines.append(f"    {name} = {expression}")
        return name

    def _combine(self, terms):
        """The sum of ``terms`` (Terms; a Term without factors is a constant).

        Returns a float when nothing variable remains, the Term itself for a single
        scaled name, otherwise Term(1.0, (name of a new line,)).
        """
        constant, parts = 0.0, []
        for term in terms:
            coefficient = float(term.coefficient)
            if coefficient == 0.0:
                continue
            if not term.factors:
                constant += coefficient
            else:
                parts.append(Term(coefficient, term.factors))
        if not parts:
            return constant
        if constant == 0.0 and len(parts) == 1 and len(parts[0].factors) == 1:
            return parts[0]
        pieces = [(part.coefficient < 0, part.magnitude_text()) for part in parts]
        if constant != 0.0:
            pieces.append((constant < 0, repr(abs(constant))))
        (negative, first), rest = pieces[0], pieces[1:]
        expression = " ".join(
            [("-" if negative else "") + first]
            + [f"{'-' if minus else '+'} {text}" for minus, text in rest]
        )
        return Term(1.0, (self._new(expression),))

    @staticmethod
    def _term(entry):
        """An entry as one Term (a constant has no factors)."""
        return Term(entry, ()) if isinstance(entry, float) else entry

    @staticmethod
    def _product(a, b):
        """The Term of the product of two entries."""
        return Program._term(a).times(Program._term(b))

    def _times(self, T, F):
        """T (3x4 entries) times F (4x4 entries, last row 0 0 0 1)."""
        rows = []
        for r in range(3):
            row = []
            for k in range(4):
                terms = [self._product(T[r][j], F[j][k]) for j in range(3)]
                if k == 3:
                    terms.append(self._term(T[r][3]))
                row.append(self._combine(terms))
            rows.append(row)
        return rows

    @staticmethod
    def _constant(C):
        return [[float(v) for v in row] for row in _snap(np.asarray(C, dtype=float))]

    def _factor(self, k, twist, post):
        """The entries of exp([X] theta_k) C_k as lines in 1, c_k, s_k, t_k."""
        K1, Kc, Ks, Kt = (_snap(K @ post) for K in exponential_coefficients(twist))
        entries = []
        for r in range(4):
            row = []
            for j in range(4):
                terms = [
                    Term(K1[r, j], ()),
                    Term(Kc[r, j], (f"c{k}",)),
                    Term(Ks[r, j], (f"s{k}",)),
                    Term(Kt[r, j], (f"t{k}",)),
                ]
                row.append(self._combine(terms))
            entries.append(row)
        return entries

    def _axis(self, G, twist, point):
        """The joint's twist in the base frame, Ad(G) X, and its point G r: 9
        entries."""
        w, v, point = (
            _snap(twist[:3]),
            _snap(twist[3:]),
            _snap(np.asarray(point, dtype=float)),
        )

        def rotate(x, r):
            return self._combine(
                [self._product(G[r][j], float(x[j])) for j in range(3)]
            )

        omega = [rotate(w, r) for r in range(3)]
        linear = [rotate(v, r) for r in range(3)]
        p = [G[r][3] for r in range(3)]
        moment = []
        for r, (a, b, c, d) in enumerate([(1, 2, 2, 1), (2, 0, 0, 2), (0, 1, 1, 0)]):
            ab, cd = self._product(p[a], omega[b]), self._product(p[c], omega[d])
            moment.append(self._combine([self._term(linear[r]), ab, cd.negated()]))
        located = [
            self._combine(
                [self._product(G[r][j], float(point[j])) for j in range(3)]
                + [self._term(p[r])]
            )
            for r in range(3)
        ]
        return omega + moment + located

    def _at_point(self, twist, p):
        """A space twist (omega; v) as a geometric Jacobian column:
        (v + omega x p; omega)."""
        omega, v = twist[:3], twist[3:]
        linear = []
        for r, (a, b, c, d) in enumerate([(1, 2, 2, 1), (2, 0, 0, 2), (0, 1, 1, 0)]):
            ab, cd = self._product(omega[a], p[b]), self._product(omega[c], p[d])
            linear.append(self._combine([self._term(v[r]), ab, cd.negated()]))
        return linear + omega

    @staticmethod
    def _text(entry):
        return repr(entry) if isinstance(entry, float) else entry.text()

    def source(self, outputs, offsets=None):
        """Python source of ``kinematics(t, c, s)`` returning a tuple of entries.

        With ``offsets`` (n floats), the scalar form ``kinematics(q)`` instead: q a
        list of n floats (one configuration), t_k = q_k + offset_k and its cosine and
        sine computed inside (``_cos``, ``_sin``: :func:`math.cos`, :func:`math.sin`),
        the same entries as the first form at t = q + offsets.

        outputs : 'pose' (the 12 entries of T's top rows), 'axes' (per joint the twist
            [omega; v] and a point, 9 entries, then the pose), 'frames' (12 entries per
            recorded frame, in the order of ``marks``), 'space'
            (the space Jacobian, 6 x n, row by row) or 'geometric'
            (the geometric Jacobian [v + omega x p; omega], 6 x n).
        """
        self._lines, self._count = [], 0
        T = self._constant(self.start)[:3]
        recorded, axes = {}, []
        if 0 in self.marks and outputs == "frames":
            recorded[0] = self._times(T, self._constant(self.marks[0]))
        for k, (twist, post, point) in enumerate(self.factors, start=1):
            if outputs in ("axes", "space", "geometric"):
                axes += self._axis(T, twist, point)
            T = self._times(T, self._factor(k, twist, post))
            if k in self.marks and outputs == "frames":
                recorded[k] = self._times(T, self._constant(self.marks[k]))
        twists = [
            axes[9 * j : 9 * j + 6] for j in range(self.n)
        ]  # (omega; v) of each joint
        if outputs == "pose":
            result = [e for row in T for e in row]
        elif outputs == "axes":
            result = axes + [e for row in T for e in row]
        elif outputs == "space":
            result = [twist[r] for r in range(6) for twist in twists]
        elif outputs == "geometric":
            moved = [
                self._at_point(twist, [T[r][3] for r in range(3)]) for twist in twists
            ]
            result = [column[r] for r in range(6) for column in moved]
        else:
            result = [e for k in sorted(recorded) for row in recorded[k] for e in row]
        body = "\n".join(self._lines)
        returned = ", ".join(self._text(e) for e in result)
        used = sorted(set(re.findall(r"\b([tcs])(\d+)\b", body + " " + returned)))
        if offsets is not None:
            return self._scalar_source(used, offsets, body, returned)
        loads = [f"    {v}{k} = {v}[{int(k) - 1}]" for v, k in used]
        return (
            "def kinematics(t, c, s):\n"
            + "\n".join(loads + self._lines)
            + f"\n    return ({returned},)\n"
        )

    @staticmethod
    def _scalar_source(used, offsets, body, returned):
        """The scalar form's source: each joint's t, c and s computed from q, as
        floats (the joints the entries use)."""
        joints = sorted({int(k) for _, k in used})
        loads = []
        for k in joints:
            loads.append(f"    t{k} = q[{k - 1}] + {float(offsets[k - 1])!r}")
            loads += [f"    c{k} = _cos(t{k})", f"    s{k} = _sin(t{k})"]
        return (
            "def kinematics(q):\n"
            + "\n".join(loads + body.split("\n") if body else loads)
            + f"\n    return ({returned},)\n"
        )

    def compile(self, outputs, offsets=None):
        """The generated function for ``outputs`` (see :meth:`source`; with
        ``offsets``, its scalar form for one configuration)."""
        namespace = {"_cos": math.cos, "_sin": math.sin}
        exec(
            compile(
                self.source(outputs, offsets),
                f"<screwkit kinematics: {outputs}>",
                "exec",
            ),
            namespace,
        )
        return namespace["kinematics"]


def evaluate(function, angles):
    """Run a generated function at one configuration: ``angles`` (n,) floats -> list of
    entries."""
    values = angles.tolist()
    return function(
        values, [math.cos(x) for x in values], [math.sin(x) for x in values]
    )


def cos_sin(angles):
    """cos and sin of an array of angles (rad), from t = tan(theta / 2) as
    cos = 2 / (1 + t^2) - 1 and sin = 2 t / (1 + t^2).

    NumPy computes tan with SIMD instructions and cos, sin without on many machines:
    this is about three times faster for a batch, and as accurate
    (within 6e-16, 3 units in the last place, of the C library's cos and sin; tested).
    At theta = pi, t is about 1.6e16 and the formulas give -1 and 1.2e-16, as np.cos and
    np.sin do.
    """
    t = np.tan(0.5 * angles)
    d = 2.0 / (1.0 + t * t)
    return d - 1.0, t * d


def evaluate_batch(function, angles, out, rows):
    """Run a generated function over a batch ``angles`` (N, n): entry k goes to
    ``out[rows[k]]``.

    ``out`` has shape (M, N), the batch last (each entry's values contiguous). Chunks of
    :data:`CHUNK` configurations keep the temporaries in the cache.
    """
    angles = np.ascontiguousarray(angles.T)
    for start in range(0, angles.shape[1], CHUNK):
        part = angles[:, start : start + CHUNK]
        stop = start + part.shape[1]
        for row, value in zip(rows, function(part, *cos_sin(part))):
            out[row, start:stop] = value
    return out


#: The entry types of a list the scalar path takes as it is (bool, str and the rest go
#: through the full check).
_PLAIN = frozenset((float, int, np.float64))


def one(q, n):
    """One plain configuration as a list of n floats, or None.

    The scalar path's check, cheaper than the work it guards: ``q`` a float64 array
    (n,), or a list or tuple of n Python floats or ints, every entry finite. Anything
    else (a batch, another type, a wrong length, a NaN) gives None, and the caller's
    full check (``Chain.check_q``) runs and says what is wrong.
    """
    kind = type(q)
    if kind is np.ndarray:
        if q.shape != (n,) or q.dtype.char != "d":
            return None
        values = q.tolist()
    elif kind is list or kind is tuple:
        if len(q) != n:
            return None
        for x in q:
            if type(x) not in _PLAIN:
                return None
        try:
            values = [float(x) for x in q]
        except OverflowError:
            return None
    else:
        return None
    total = sum(values)
    if total - total != 0.0:  # a NaN or an infinity (or a sum past 1.8e308)
        return None
    return values


def scalar(chain, outputs):
    """The generated function of ``outputs`` in its scalar form, ``f(values)`` for one
    configuration (a list of n floats) -> tuple of entries; compiled on first use."""
    try:
        return chain._functions[outputs, "one"]
    except KeyError:
        program, offsets = chain._program
        function = program.compile(outputs, offsets.tolist())
        chain._functions[outputs, "one"] = function
        return function
