"""Principal screws, pitches and the classification of a screw system.

The kernel of :meth:`ScrewSystem.principal_screws`, ``pitch_of`` and ``classify``. A
member x = B c of the span (B: 6 x n, a basis as columns, W its direction rows and V its
moment rows) has pitch

    h(c) = (c^T A c) / (c^T D c),   A = (W^T V + V^T W) / 2,   D = W^T W,

a ratio of two quadratic forms (A is half the reciprocal product of x with itself). The
principal screws are the stationary members of h: the generalised eigenvectors of
A c = h D c, the principal pitches its eigenvalues. D is singular when the system holds
translations (D c = 0: pitch infinity); these are principal with pitch oo, and the
finite principal screws are sought among the members conjugate to all of them
(n^T A c = 0), where h does not run off to every real value.

Exact bases are solved exactly (the roots of det(A - h D) = 0, algebraic numbers); float
bases with unit-balanced coordinates (moments divided by the system's size) and the
relative tolerance ``PITCH_TOL``, so the answers are the same in m and mm.
"""

from typing import NamedTuple

import numpy as np
import sympy as sp

from ._checks import describe
from .screws import Screw
from .tolerances import PITCH_TOL


class PrincipalScrews(NamedTuple):
    """The principal screws and pitches of a 1-, 2- or 3-system.

    Parameters
    ----------
    screws : list of Screw
        The principal screws (unit direction; unit moment for a translation or
        couple), finite pitches ascending, then the infinite ones.
    pitches : list
        Their pitches (m/rad; ``sympy.oo`` for a translation). Exact for exact input.
    unique : bool
        Whether the principal screws are determined (up to sign).
    reason : str
        Why not, in words ('' when unique).

    Examples
    --------
    A rotation about z and a screw of pitch 1 along z through the origin span the
    screws along z of every pitch; the translation along z is the one of pitch oo:

    >>> from screwkit.systems import ScrewSystem
    >>> along_z = ScrewSystem([[0, 0, 1, 0, 0, 0], [0, 0, 1, 0, 0, 1]])
    >>> along_z.principal_screws().screws, along_z.principal_screws().pitches
    ([Twist([0, 0, 0, 0, 0, 1])], [oo])
    """

    screws: list
    pitches: list
    unique: bool
    reason: str


class Classification(NamedTuple):
    """The type of a screw system and its invariants.

    Parameters
    ----------
    order : int
        The number of independent screws.
    type : str
        The order and the type, ``'<order>-<gibson_hunt>'``: '2-IA' the general
        cylindroid, '3-IIA' spherical motion, '3-IIC' planar motion.
    translations : int
        The number of independent infinite-pitch members (of the reciprocal for order
        4 and 5).
    pitches : list
        The principal pitches (of the reciprocal for order 4 and 5), m/rad.
    name : str
        The familiar name when there is one ('planar motion', 'spherical motion',
        'Schoenflies motion', 'spatial translations', 'general cylindroid', ...), else
        ''; for a wrench system couples stand for translations ('planar couples',
        'planar-motion type').
    description : str
        The special geometry in words.
    gibson_hunt : str
        The type in Gibson and Hunt's two projective features (Mech. Mach. Theory 25,
        1990): a letter for the number of independent members of infinite pitch, A
        none, B one, C two, D three; before it II when every member of finite pitch
        has one and the same pitch h (the system lies on the quadric of the screws of
        pitch h; a system of translations only counts as II), else I. 'IA' a general
        cylindroid, 'IIA' spherical motion (h = 0), 'IIC' planar motion (h = 0),
        'IID' spatial translations. A 4- or 5-system carries its reciprocal's type.
        Gibson and Hunt's numbered subtypes are not coded here; ``pitches`` and
        ``description`` tell the finer cases (equal principal pitches, a translation
        along a finite screw or skew to it). '' for order 0 and 6.

    Examples
    --------
    The rotations about the origin (a ball joint): order 3, no translation, every
    principal pitch 0.

    >>> from screwkit.systems import ScrewSystem
    >>> axes = ([1, 0, 0], [0, 1, 0], [0, 0, 1])
    >>> c = ScrewSystem([(d, [0, 0, 0], 0) for d in axes]).classify()
    >>> c.order, c.type, c.translations, c.pitches, c.name, c.gibson_hunt
    (3, '3-IIA', 0, [0, 0, 0], 'spherical motion', 'IIA')
    """

    order: int
    type: str
    translations: int
    pitches: list
    name: str
    description: str
    gibson_hunt: str = ""


# ---- the two forms -------------------------------------------------------------------


def _float_basis(system):
    """An orthonormal basis of the span in balanced coordinates, and the size L."""
    X = np.array(system._array, dtype=float)
    sizes = [
        np.linalg.norm(x[3:]) / np.linalg.norm(x[:3])
        for x in X
        if np.linalg.norm(x[:3]) > 0
    ]
    L = max(sizes + [0.0]) or 1.0
    Xb = np.hstack([X[:, :3], X[:, 3:] / L])
    Xb = Xb / np.linalg.norm(Xb, axis=1, keepdims=True).clip(min=np.finfo(float).tiny)
    _, _, Vt = np.linalg.svd(Xb)
    return Vt[: system.rank].T, L


def _forms(B, exact):
    W, V = B[:3, :], B[3:, :]
    if exact:
        A = ((W.T * V + V.T * W) / 2).applyfunc(sp.simplify)
        return A, (W.T * W).applyfunc(sp.simplify), W
    return (W.T @ V + V.T @ W) / 2, W.T @ W, W


def _exact_null(M):
    return [v.applyfunc(sp.simplify) for v in M.nullspace(simplify=True)]


def _float_null(M, n):
    if M.shape[0] == 0:
        return np.eye(n)
    _, s, Vt = np.linalg.svd(M)
    r = int(np.sum(s > PITCH_TOL * max(1.0, s[0] if s.size else 0.0)))
    return Vt[r:].T


def _complement(span, N, exact):
    """Columns of ``span`` (a basis, columns) completing N to it, orthogonalised
    against N."""
    if exact:
        chosen = list(N)
        out = []
        for v in span:
            M = sp.Matrix.hstack(*(chosen + [v]))
            if M.rank(simplify=True) == len(chosen) + 1:
                chosen.append(v)
                out.append(v)
        return out
    if N.shape[1]:
        P = span - N @ (N.T @ span)
    else:
        P = span
    if P.shape[1] == 0:
        return P
    U, s, _ = np.linalg.svd(P, full_matrices=False)
    r = int(np.sum(s > PITCH_TOL))
    return U[:, :r]


def _eigen_exact(A, D):
    """[(pitch, multiplicity, [vectors])] of A c = h D c, D positive definite."""
    h = sp.Symbol("h", real=True)
    poly = sp.Poly((A - h * D).det(), h)
    if poly.get_domain().is_ZZ or poly.get_domain().is_QQ:
        # real_roots: rationals and radicals where they exist, CRootOf (exact, and
        # ordered) for an irreducible cubic, whose radicals would hold i
        found = poly.real_roots()
    else:  # algebraic coefficients (sqrt(3), ...): radicals; their real part
        found = []
        for root, mult in sp.roots(poly).items():
            if abs(sp.N(sp.im(root), 60)) > sp.Rational(1, 10**40):
                raise ArithmeticError(f"a principal pitch came out complex: {root}")
            found += [sp.simplify(sp.re(root))] * mult
    roots = {}
    for root in found:
        roots[root] = roots.get(root, 0) + 1
    out = []
    for root, mult in roots.items():
        root = sp.simplify(root)
        M = (A - root * D).applyfunc(sp.expand)
        if mult == 1:
            adj = M.adjugate()
            column = max(
                range(adj.shape[1]),
                key=lambda j: float(sum(abs(sp.N(e)) for e in adj[:, j])),
            )
            vectors = [adj[:, column].applyfunc(sp.simplify)]
        else:
            vectors = _exact_null(M)
        out.append((root, mult, vectors))
    return sorted(out, key=lambda item: float(sp.N(item[0])))


def _eigen_float(A, D):
    C = np.linalg.cholesky(D)
    Ci = np.linalg.inv(C)
    values, Y = np.linalg.eigh(Ci @ A @ Ci.T)
    vectors = Ci.T @ Y
    groups = []
    for k, value in enumerate(values):
        if groups and abs(value - groups[-1][0]) <= PITCH_TOL * max(1.0, abs(value)):
            groups[-1][1] += 1
            groups[-1][2].append(vectors[:, [k]])
        else:
            groups.append([value, 1, [vectors[:, [k]]]])
    return [(g[0], g[1], g[2]) for g in groups]


def _analyse(system):
    """The principal structure: (pitch groups, translations N, conjugate-complete?,
    basis B, size L, exact)."""
    exact = not system.numeric
    if exact:
        B = sp.Matrix.hstack(*[s.vector for s in system.basis()])
        L = 1
    else:
        B, L = _float_basis(system)
    n = B.shape[1]
    A, D, W = _forms(B, exact)
    if exact:
        N = _exact_null(W)
        C = sp.Matrix.vstack(*[v.T * A for v in N]) if N else sp.zeros(0, n)
        conj = _exact_null(C) if N else [sp.eye(n)[:, j] for j in range(n)]
        E = _complement(conj, N, True)
        if E:
            Em = sp.Matrix.hstack(*E)
            groups = _eigen_exact(
                (Em.T * A * Em).applyfunc(sp.simplify),
                (Em.T * D * Em).applyfunc(sp.simplify),
            )
            groups = [(h, m, [Em * y for y in ys]) for h, m, ys in groups]
        else:
            groups = []
        translations = [v for v in N]
        complete = len(conj) == n
    else:
        _, s, Vt = np.linalg.svd(W)
        rank_W = int(np.sum(s > PITCH_TOL))
        N = Vt[rank_W:].T
        C = N.T @ A
        conj = _float_null(C, n) if N.shape[1] else np.eye(n)
        E = _complement(conj, N, False)
        if E.shape[1]:
            groups = _eigen_float(E.T @ A @ E, E.T @ D @ E)
            groups = [(h * L, m, [E @ y for y in ys]) for h, m, ys in groups]
        else:
            groups = []
        translations = [N[:, [j]] for j in range(N.shape[1])]
        complete = conj.shape[1] == n
    return groups, translations, complete, B, L, exact


def _screw(kind, B, c, L, exact):
    x = B * c if exact else B @ c
    if exact:
        w = x[:3, 0]
        norm = sp.sqrt(w.dot(w)) if any(sp.simplify(e) != 0 for e in w) else None
        if norm is None:
            norm = sp.sqrt(x[3:, 0].dot(x[3:, 0]))
        return kind._checked((x / norm).applyfunc(sp.simplify))
    x = np.ravel(x).copy()
    x[3:] *= L
    norm = np.linalg.norm(x[:3])
    x = x / (norm if norm > PITCH_TOL * np.linalg.norm(x) else np.linalg.norm(x[3:]))
    return kind(sp.Matrix(6, 1, [sp.Float(v) for v in x]))


def _check_order(system, what, orders):
    if system.rank not in orders:
        raise ValueError(
            f"system must be of order {', '.join(map(str, orders[:-1]))} or "
            f"{orders[-1]} for {what}, got a {system.rank}-system"
            + (
                ": take its reciprocal (system.reciprocal()), of order "
                f"{6 - system.rank}"
                if 4 <= system.rank <= 5
                else ""
            )
        )


# ---- public kernels ------------------------------------------------------------------


def principal_screws(system):
    """The principal screws of a 1-, 2- or 3-system (ScrewSystem.principal_screws)."""
    _check_order(system, "principal screws", (1, 2, 3))
    groups, translations, complete, B, L, exact = _analyse(system)
    screws, pitches, reasons = [], [], []
    for h, mult, vectors in groups:
        for v in vectors:
            screws.append(_screw(system.kind, B, v, L, exact))
            pitches.append(sp.simplify(h) if exact else float(h))
        if mult > 1:
            reasons.append(
                f"{mult} principal pitches equal {_fmt(h, exact)}: every member of "
                "their span has that pitch, so any independent members of it are "
                "principal"
            )
    for v in translations:
        screws.append(_screw(system.kind, B, v, L, exact))
        pitches.append(sp.oo if exact else np.inf)
    if len(translations) > 1:
        reasons.append(
            f"{len(translations)} independent members have infinite pitch: any "
            "independent translations of their span are principal"
        )
    if translations and groups:
        reasons.append(
            "adding a translation of the system to a finite principal screw keeps its "
            "pitch and moves its axis, so those axes are not unique"
        )
    if not complete:
        reasons.append(
            "members not conjugate to the translations take every real pitch: "
            "they have no stationary pitch and are not principal"
        )
    return PrincipalScrews(screws, pitches, not reasons, "; ".join(reasons))


def _fmt(h, exact):
    return str(sp.simplify(h)) if exact else f"{float(h):.6g}"


def pitch_of(system, x):
    """The pitch of the member x of the span (ScrewSystem.pitch_of)."""
    if not isinstance(x, Screw):
        if isinstance(x, (str, bytes)) or x is None:
            raise TypeError(
                f"x must be a screw or 6 coordinates of a member of the system, got "
                f"{describe(x)}"
            )
        try:
            x = system.kind(x)
        except (TypeError, ValueError) as error:
            raise type(error)(str(error).replace("vector", "x", 1)) from None
    if all(sp.simplify(e) == 0 for e in x.vector):
        raise ValueError("x must not be the zero screw: it has no pitch")
    if not system.contains(type(system.screws[0])(x.vector) if system.screws else x):
        raise ValueError(
            f"x must lie in the span of the system, got {list(x.vector)}, which "
            "raises its rank"
        )
    if system.numeric or x.vector.has(sp.Float):
        v = np.array([float(e) for e in x.vector])
        ww = float(v[:3] @ v[:3])
        scale = float(v @ v)
        return np.inf if ww <= PITCH_TOL**2 * scale else float(v[:3] @ v[3:] / ww)
    return x.pitch


def classify(system):
    """The type of the system (ScrewSystem.classify)."""
    n = system.rank
    if n == 0:
        return Classification(
            0, "0", 0, [], "zero system", "the zero system: no screw", ""
        )
    if n == 6:
        return Classification(
            6,
            "6",
            0,
            [],
            "every screw",
            "every screw: the whole six-dimensional space",
            "",
        )
    target = system if n <= 3 else system.reciprocal()
    groups, translations, complete, B, _, exact = _analyse(target)
    k = len(translations)
    gibson_hunt = _gibson_hunt(target.rank, k, groups, complete)
    coaxial = target.rank == 2 and k == 1 and _along_the_axis(B, translations, exact)
    pitches = [
        sp.simplify(h) if exact else float(h) for h, m, _ in groups for _ in range(m)
    ]
    pitches += [sp.oo if exact else np.inf] * k
    name, words = _words(target.rank, k, groups, complete, exact, coaxial)
    if target.kind.noun == "wrench":  # a wrench of infinite pitch is a couple
        words = _as_wrenches(words)
    if n >= 4:
        name = _RECIPROCAL_NAMES.get(name, "")
        words = (
            f"the screws reciprocal to a {target.rank}-system ({words}); its "
            "principal pitches are listed"
        )
    if system.kind.noun == "wrench":
        name = _as_wrenches(name)
    return Classification(n, f"{n}-{gibson_hunt}", k, pitches, name, words, gibson_hunt)


def _along_the_axis(B, translations, exact):
    """Whether a 2-system's one translation is parallel to its finite members' common
    direction (the screws on one axis, of every pitch): every basis column's direction
    (parallel to it, or zero) crosses the translation to zero."""
    t = B * translations[0] if exact else B @ translations[0]
    W = B[:3, :]
    if exact:
        return all(
            sp.simplify(e) == 0
            for j in range(W.shape[1])
            for e in W[:, j].cross(t[3:, 0])
        )
    moment = np.ravel(t[3:]) / np.linalg.norm(t[3:])
    return bool(np.all(np.linalg.norm(np.cross(W.T, moment), axis=1) <= PITCH_TOL))


def _gibson_hunt(m, k, groups, complete):
    """II when every finite member of the m-system has one pitch, else I; then A to D
    for its k independent translations.

    The finite members have one pitch h exactly when the translations are reciprocal
    to every member (``complete``: adding one then keeps the pitch) and the finite
    principal pitches are all h (one group); with no finite member (k = m) the
    condition holds vacuously.
    """
    one_pitch = k == m or (complete and len(groups) == 1)
    return ("II" if one_pitch else "I") + "ABCD"[k]


def _as_wrenches(text):
    """The words of a twist system said of wrenches: couples for translations, and a
    motion's name as the name of the type."""
    text = text.replace("translations", "couples").replace("translation", "couple")
    for twist, wrench in (
        ("rotations about", "forces along"),
        ("a rotation about", "a force through"),
        ("(a rotation)", "(a force)"),
    ):
        text = text.replace(twist, wrench)
    return text.replace(" motion", "-motion type")


_RECIPROCAL_NAMES = {
    "planar translations": "Schoenflies motion",
    "single translation": "",
    "spherical motion": "",
    "planar motion": "",
}


def _words(m, k, groups, complete, exact, coaxial):
    finite = [(h, mult) for h, mult, _ in groups]

    def zero(h):
        return sp.simplify(h) == 0 if exact else abs(h) <= PITCH_TOL

    if m == 1:
        if k:
            return "single translation", "one screw of infinite pitch (a translation)"
        h = finite[0][0]
        return (
            "single screw",
            f"one screw of pitch {_fmt(h, exact)}"
            + (" (a rotation)" if zero(h) else ""),
        )
    if k == m:
        return (
            {2: "planar translations", 3: "spatial translations"}[m],
            f"{m} independent translations",
        )
    if m == 2:
        if k == 0:
            if len(finite) == 2:
                return (
                    "general cylindroid",
                    f"a cylindroid: principal pitches {_fmt(finite[0][0], exact)} and "
                    f"{_fmt(finite[1][0], exact)}, axes meeting their common normal at "
                    "right angles",
                )
            return (
                "flat pencil of screws",
                f"every member has pitch {_fmt(finite[0][0], exact)}: the axes form a "
                "flat pencil (one plane, one point)",
            )
        if complete:
            return (
                "parallel screws and a translation",
                f"a screw of pitch {_fmt(finite[0][0], exact)} and the translations "
                "normal to it: parallel axes of one pitch in a plane",
            )
        if coaxial:
            return (
                "coaxial screws",
                "a screw and the translation along its axis: every real pitch on one "
                "axis",
            )
        return (
            "screw and skew translation",
            "a screw and a translation skew to its axis (neither along nor normal to "
            "it): parallel axes in one plane, every real pitch once",
        )
    # m == 3
    if k == 0:
        if len(finite) == 1:
            h = finite[0][0]
            if zero(h):
                return "spherical motion", "every member a rotation about one point"
            return (
                "pitch-h star",
                f"every member has pitch {_fmt(h, exact)}: axes through one point",
            )
        pattern = ", ".join(_fmt(h, exact) for h, mult in finite for _ in range(mult))
        return "general 3-system", f"principal pitches {pattern}"
    if k == 2 and complete:
        h = finite[0][0]
        if zero(h):
            return (
                "planar motion",
                "rotations about parallel axes and the translations normal to them",
            )
        return (
            "planar helical motion",
            f"screws of pitch {_fmt(h, exact)} on parallel axes and translations "
            "normal "
            "to them",
        )
    if k == 1 and complete and len(finite) == 1:
        h = finite[0][0]
        if zero(h):
            return (
                "planar field of lines",
                "rotations about the lines of one plane and the translation normal "
                "to it",
            )
        return (
            "planar field of screws",
            f"screws of pitch {_fmt(h, exact)} on the lines of one plane and the "
            "translation normal to it",
        )
    return (
        f"{k}-translation 3-system",
        f"{k} independent translations with finite principal pitches "
        + ", ".join(_fmt(h, exact) for h, _ in finite)
        + ("" if complete else "; other members take every real pitch"),
    )
