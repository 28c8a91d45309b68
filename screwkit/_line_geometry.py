"""Grassmann geometry: the named configuration of the span of a set of lines.

The kernel of :func:`screwkit.lines.dependency`. The lines' Plücker vectors span S
(dimension r); its lines are its points on the Klein quadric Q(x) = x^T K x = 0,
K = [[0, I], [I, 0]]. The configuration is named from Q restricted to S (ranks 1 to 3)
or to the reciprocal space R = K S^perp (ranks 4 and 5): which of its members are lines,
and how they meet. Exact vectors are decided exactly (SymPy); floats on vectors with
unit
directions and moments divided by the lines' size L (then every quantity is unitless and
the answer is the same in m and mm), the data scaled back by L at the end.
"""

from typing import NamedTuple

import numpy as np
import sympy as sp

K = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])


class PluckerLine(NamedTuple):
    """A line of the data (its Plücker 6-vector), wrapped as a Line by the caller."""

    vector: object


class _Exact:
    """Exact arithmetic on SymPy columns."""

    exact = True

    def __init__(self):
        self.K = sp.Matrix(K.astype(int))

    def zero(self, x):
        return sp.simplify(x) == 0

    def vec_zero(self, v):
        return all(self.zero(e) for e in v)

    def rank(self, M):
        return M.rank(simplify=True) if M.shape[0] and M.shape[1] else 0

    def span(self, rows):
        M = sp.Matrix.vstack(*[sp.Matrix(r).T for r in rows])
        basis = [c.applyfunc(sp.simplify) for c in M.T.columnspace(simplify=True)]
        complement = (M * self.K).nullspace(simplify=True)
        return basis, [c.applyfunc(sp.simplify) for c in complement]

    def gram(self, vectors):
        B = sp.Matrix.hstack(*vectors)
        return (B.T * self.K * B).applyfunc(sp.simplify)

    def sign(self, x):
        x = sp.simplify(x)
        return 0 if x == 0 else (1 if x > 0 else -1)

    def sqrt(self, x):
        return sp.sqrt(x)

    def null(self, G):
        return [v.applyfunc(sp.simplify) for v in G.nullspace(simplify=True)]

    def solve_point(self, vectors):
        """p with m_i = p x w_i for every vector (w_i; m_i): least squares."""
        A = sp.Matrix.vstack(*[-_skew_sp(v[:3, 0]) for v in vectors])
        b = sp.Matrix.vstack(*[v[3:, 0] for v in vectors])
        return ((A.T * A).inv() * A.T * b).applyfunc(sp.simplify)

    def cross(self, a, b):
        return sp.Matrix(a).cross(sp.Matrix(b)).applyfunc(sp.simplify)

    def dot(self, a, b):
        return sp.simplify(sp.Matrix(a).dot(sp.Matrix(b)))

    def out(self, x):
        return x.applyfunc(sp.simplify) if isinstance(x, sp.MatrixBase) else x

    def fmt(self, x):
        return str(sp.simplify(x))


class _Float:
    """Float arithmetic with a relative tolerance (vectors are unitless here)."""

    exact = False

    def __init__(self, tol):
        self.tol = tol
        self.K = K
        self.size = 1.0

    def zero(self, x):
        return abs(x) <= self.tol

    def vec_zero(self, v):
        return float(np.linalg.norm(v)) <= self.tol

    def rank(self, M):
        if M.size == 0:
            return 0
        s = np.linalg.svd(M, compute_uv=False)
        return int(np.sum(s > self.tol * max(1.0, s[0])))

    def span(self, rows):
        M = np.array(rows, dtype=float)
        _, s, Vt = np.linalg.svd(M)
        r = int(np.sum(s > self.tol * max(1.0, s[0])))
        return [Vt[i].reshape(6, 1) for i in range(r)], [
            (self.K @ Vt[i]).reshape(6, 1) for i in range(r, 6)
        ]

    def gram(self, vectors):
        B = np.hstack(vectors)
        return B.T @ self.K @ B

    def sign(self, x):
        return 0 if abs(x) <= self.tol else (1 if x > 0 else -1)

    def sqrt(self, x):
        return float(np.sqrt(max(x, 0.0)))

    def null(self, G):
        w, V = np.linalg.eigh(G)
        return [V[:, [i]] for i in range(len(w)) if abs(w[i]) <= self.tol]

    def solve_point(self, vectors):
        A = np.vstack([-_skew_np(v[:3, 0]) for v in vectors])
        b = np.concatenate([v[3:, 0] for v in vectors])
        return np.linalg.lstsq(A, b, rcond=None)[0].reshape(3, 1)

    def cross(self, a, b):
        return np.cross(np.ravel(a), np.ravel(b)).reshape(3, 1)

    def dot(self, a, b):
        return float(np.dot(np.ravel(a), np.ravel(b)))

    def out(self, x):
        return x

    def fmt(self, x):
        # words only: round-off below the tolerance (times the lines' size) reads as 0
        x = float(x)
        return "0" if abs(x) <= self.tol * self.size else f"{x:.4g}"


def _skew_sp(w):
    return sp.Matrix([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def _skew_np(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


# ---- the 2 x 2 forms and their lines -------------------------------------------------


def _isotropic(G, x1, x2, ar):
    """The two vectors s x1 + t x2 with Q = 0, for the 2 x 2 form G of (x1, x2) with
    det G < 0."""
    a, b, c = G[0, 0], G[0, 1], G[1, 1]
    if ar.zero(a):
        return [x1, c * x1 - 2 * b * x2]
    root = ar.sqrt(b * b - a * c)
    return [(-b + root) * x1 + a * x2, (-b - root) * x1 + a * x2]


def _norm_line(v, ar):
    """A line's vector scaled to a unit direction (a line at infinity: unit moment)."""
    w = v[:3, 0]
    n = ar.dot(w, w)
    if ar.zero(n):
        m = v[3:, 0]
        return ar.out(v / ar.sqrt(ar.dot(m, m)))
    return ar.out(v / ar.sqrt(n))


def _at_infinity(v, ar):
    return ar.vec_zero(v[:3, 0])


def _point_of(v, ar):
    w, m = v[:3, 0], v[3:, 0]
    return ar.out(ar.cross(w, m) / ar.dot(w, w))


def _pencil(x, y, ar):
    """(point or None, direction or None, plane (n, d)) of the flat pencil spanned by
    the meeting lines x and y (a point at infinity: the common direction)."""
    if _at_infinity(x, ar):
        x, y = y, x
    if _at_infinity(y, ar):  # x proper, y the line at infinity of planes normal to m_y
        y = x + y
    wx, wy = x[:3, 0], y[:3, 0]
    n = ar.cross(wx, wy)
    px, py = _point_of(x, ar), _point_of(y, ar)
    if ar.vec_zero(n):
        n = ar.cross(wx, py - px)
        return None, ar.out(wx), (ar.out(n), ar.dot(n, px))
    point = ar.solve_point([x, y])
    return point, None, (ar.out(n), ar.dot(n, point))


def _pencil_words(point, direction, plane, ar):
    where = (
        f"through the point {_fmt_vec(point, ar)}"
        if point is not None
        else f"parallel to {_fmt_vec(direction, ar)}"
    )
    return f"{where} in the plane {_fmt_plane(plane, ar)}"


def _fmt_vec(v, ar):
    entries = list(v) if ar.exact else np.ravel(v)
    return "(" + ", ".join(ar.fmt(e) for e in entries) + ")"


def _fmt_plane(plane, ar):
    n, d = plane
    return f"{_fmt_vec(n, ar)} . x = {ar.fmt(d)}"


def _line_words(v, ar):
    if _at_infinity(v, ar):
        return f"the line at infinity of the planes normal to {_fmt_vec(v[3:, 0], ar)}"
    return (
        f"the line through {_fmt_vec(_point_of(v, ar), ar)} along "
        f"{_fmt_vec(v[:3, 0], ar)}"
    )


# ---- the catalogue -------------------------------------------------------------------


def classify(vectors, exact, tol):
    """(rank, name, data, description) of the span of the Plücker ``vectors``."""
    if exact:
        ar, L = _Exact(), 1
        rows = [list(v) for v in vectors]
    else:
        ar = _Float(tol)
        vs = [np.array([float(e) for e in v]) for v in vectors]
        vs = [v / np.linalg.norm(v[:3]) for v in vs]
        L = (
            max([float(np.max(np.abs(np.cross(v[:3], v[3:])))) for v in vs] + [0.0])
            or 1.0
        )
        rows = [np.concatenate([v[:3], v[3:] / L]) for v in vs]
    S, R = ar.span(rows)
    r = len(S)
    name, data, words = _name(r, S, R, ar)
    if not exact:
        data = _rescale(data, L)
        ar.size = L
        words = _words_rescaled(r, name, data, ar) or words
    return r, name, data, words


def _rescale(value, L):
    """Unitless float data back to metres: moments, points, offsets, pitch times L
    (directions and normals stay)."""
    if isinstance(value, dict):
        return {
            key: np.ravel(v) if key == "direction" else _rescale(v, L)
            for key, v in value.items()
        }
    if isinstance(value, PluckerLine):
        v = np.ravel(value.vector).astype(float).copy()
        v[3:] *= L
        return PluckerLine(v)
    if isinstance(value, list):
        return [_rescale(v, L) for v in value]
    if isinstance(value, tuple):  # a plane (n, d)
        return (np.ravel(value[0]), value[1] * L)
    if isinstance(value, str):
        return value
    if isinstance(value, np.ndarray):
        return np.ravel(value) * L
    return value * L


def _words_rescaled(r, name, data, ar):
    """The description with the data in metres (floats)."""
    del r
    parts = []
    for key in ("point", "direction", "plane", "pitch"):
        if key in data:
            value = data[key]
            text = (
                _fmt_plane(value, ar)
                if key == "plane"
                else ar.fmt(value)
                if key == "pitch"
                else _fmt_vec(value, ar)
            )
            parts.append(f"{key} {text}")
    for key in ("line", "axis"):
        if key in data:
            v = np.ravel(data[key].vector).reshape(6, 1)
            parts.append(f"{key}: {_line_words(v, ar)}")
    if "lines" in data:
        lines = "; ".join(
            _line_words(np.ravel(x.vector).reshape(6, 1), ar) for x in data["lines"]
        )
        parts.append(f"lines: {lines}")
    return f"{_NAMES[name]}" + (f" ({'; '.join(parts)})" if parts else "")


_NAMES = {
    "one line": "rank 1: every line is the same line",
    "flat pencil": "rank 2: a flat pencil, the lines of one plane through one point",
    "two skew lines": "rank 2: two skew lines (their span holds no other line)",
    "star": "rank 3: a star, lines through one point",
    "parallel lines": "rank 3: lines parallel to one direction (a star at infinity)",
    "plane": "rank 3: lines in one plane",
    "two flat pencils": "rank 3: two flat pencils in different planes with a common "
    "line",
    "regulus": "rank 3: a regulus, one ruling of a hyperboloid or a hyperbolic "
    "paraboloid",
    "lines meeting two lines": "rank 4: a hyperbolic congruence, the lines meeting two "
    "skew lines",
    "parabolic congruence": "rank 4: a parabolic congruence, lines meeting one line, "
    "tangent to it in a linear way",
    "elliptic congruence": "rank 4: an elliptic congruence (its two directrices are "
    "complex)",
    "point and plane": "rank 4: the lines through a point or in a plane through it",
    "special complex": "rank 5: a special linear complex, every line meeting one line",
    "general complex": "rank 5: a general linear complex, the lines reciprocal to one "
    "screw",
    "independent": "rank 6: independent lines (no dependency)",
}


def _name(r, S, R, ar):
    if r == 1:
        return (
            "one line",
            {"line": PluckerLine(_norm_line(S[0], ar))},
            _NAMES["one line"],
        )
    if r == 2:
        G = ar.gram(S)
        if ar.rank(G) == 0:
            return _pencil_class("flat pencil", S[0], S[1], ar)
        lines = [_norm_line(x, ar) for x in _isotropic(G, S[0], S[1], ar)]
        return (
            "two skew lines",
            {"lines": [PluckerLine(x) for x in lines]},
            _NAMES["two skew lines"],
        )
    if r == 3:
        return _rank3(S, ar)
    if r == 4:
        return _rank4(R, ar)
    if r == 5:
        return _rank5(R[0], ar)
    return "independent", {}, _NAMES["independent"]


def _pencil_data(point, direction, plane):
    data = {"plane": plane}
    if point is not None:
        data["point"] = point
    else:
        data["direction"] = direction
    return data


def _pencil_class(name, x, y, ar):
    """(name, data, words) of a class whose lines are the flat pencil spanned by the
    meeting lines x and y (a flat pencil; the point and plane of a rank-4 system)."""
    point, direction, plane = _pencil(x, y, ar)
    words = _pencil_words(point, direction, plane, ar)
    return name, _pencil_data(point, direction, plane), f"{_NAMES[name]}: {words}"


def _rank3(S, ar):
    G = ar.gram(S)
    rank_G = ar.rank(G)
    if rank_G == 0:
        W = (
            sp.Matrix.hstack(*[x[:3, 0] for x in S])
            if ar.exact
            else np.hstack([x[:3] for x in S])
        )
        directions = ar.rank(W)
        if directions == 3:
            point = ar.solve_point(S)
            return (
                "star",
                {"point": point},
                f"{_NAMES['star']} {_fmt_vec(point, ar)}",
            )
        proper = [x for x in S if not _at_infinity(x, ar)]
        if directions == 1:
            d = ar.out(proper[0][:3, 0])
            return (
                "parallel lines",
                {"direction": d},
                f"{_NAMES['parallel lines']} {_fmt_vec(d, ar)}",
            )
        ws = [x[:3, 0] for x in proper]
        n = next(
            ar.cross(a, b) for a in ws for b in ws if not ar.vec_zero(ar.cross(a, b))
        )
        plane = (ar.out(n), ar.dot(n, _point_of(proper[0], ar)))
        return "plane", {"plane": plane}, f"{_NAMES['plane']} {_fmt_plane(plane, ar)}"
    if rank_G == 2:
        common = ar.null(G)[0]
        B = sp.Matrix.hstack(*S) if ar.exact else np.hstack(S)
        line = B * common if ar.exact else B @ common
        others = [x for x in S if ar.rank(_hstack([line, x], ar)) == 2]
        x1 = others[0]
        x2 = next(x for x in others[1:] if ar.rank(_hstack([line, x1, x], ar)) == 3)
        G2 = ar.gram([x1, x2])
        pencils = []
        for v in _isotropic(G2, x1, x2, ar):
            point, direction, plane = _pencil(line, _reduce(v, line, ar), ar)
            pencils.append(_pencil_data(point, direction, plane))
        data = {"line": PluckerLine(_norm_line(line, ar)), "pencils": pencils}
        return (
            "two flat pencils",
            data,
            f"{_NAMES['two flat pencils']}: {_line_words(line, ar)}",
        )
    return "regulus", {}, _NAMES["regulus"]


def _hstack(vs, ar):
    return sp.Matrix.hstack(*vs) if ar.exact else np.hstack(vs)


def _reduce(v, line, ar):
    """v itself (isotropic and conjugate to the common line: both span a pencil)."""
    del line, ar
    return v


def _rank4(R, ar):
    G = ar.gram(R)
    rank_G = ar.rank(G)
    if rank_G == 0:
        return _pencil_class("point and plane", R[0], R[1], ar)
    if rank_G == 1:
        line = ar.null(G)[0]
        B = _hstack(R, ar)
        v = B * line if ar.exact else B @ line
        return (
            "parabolic congruence",
            {"line": PluckerLine(_norm_line(v, ar))},
            f"{_NAMES['parabolic congruence']}: {_line_words(v, ar)}",
        )
    det = G[0, 0] * G[1, 1] - G[0, 1] * G[1, 0]
    if ar.sign(det) > 0:
        return "elliptic congruence", {}, _NAMES["elliptic congruence"]
    lines = [_norm_line(x, ar) for x in _isotropic(G, R[0], R[1], ar)]
    words = "; ".join(_line_words(x, ar) for x in lines)
    return (
        "lines meeting two lines",
        {"lines": [PluckerLine(x) for x in lines]},
        f"{_NAMES['lines meeting two lines']}: {words}",
    )


def _rank5(rho, ar):
    w, m = rho[:3, 0], rho[3:, 0]
    if (
        ar.zero(ar.dot(w, m))
        if ar.exact
        else abs(ar.dot(w, m)) <= ar.tol * ar.dot(rho, rho)
    ):
        return (
            "special complex",
            {"line": PluckerLine(_norm_line(rho, ar))},
            f"{_NAMES['special complex']}: {_line_words(rho, ar)}",
        )
    ww = ar.dot(w, w)
    h = ar.dot(w, m) / ww
    if ar.exact:
        h = sp.simplify(h)
    axis_m = m - h * w
    axis = (
        sp.Matrix.vstack(w, axis_m).applyfunc(sp.simplify)
        if ar.exact
        else np.concatenate([w, axis_m]).reshape(6, 1)
    )
    return (
        "general complex",
        {"axis": PluckerLine(_norm_line(axis, ar)), "pitch": h},
        f"{_NAMES['general complex']} of pitch {ar.fmt(h)} on {_line_words(axis, ar)}",
    )
