"""An independent rank for the exact layer's tests: mpmath at 60 digits.

Every entry is evaluated by SymPy at 70 significant digits, the matrix's singular
values are computed by mpmath's SVD at 60 digits, and the rank counts those above 1e-40
times the largest (at least 1). Nothing of screwkit's exact layer is used.
"""

import mpmath
import sympy as sp

DIGITS = 60
THRESHOLD = mpmath.mpf("1e-40")


def _number(e):
    value = sp.N(sp.sympify(e), DIGITS + 10)
    real, imaginary = value.as_real_imag()
    return mpmath.mpc(str(real), str(imaginary)) if imaginary else mpmath.mpf(str(real))


def rank(rows):
    """The rank of a matrix given as rows of SymPy numbers (no free symbols)."""
    rows = [list(r) for r in rows]
    if not rows:
        return 0
    with mpmath.workdps(DIGITS):
        A = mpmath.matrix([[_number(e) for e in row] for row in rows])
        if any(isinstance(x, mpmath.mpc) for x in A):
            s = mpmath.svd_c(A, compute_uv=False)
        else:
            s = mpmath.svd_r(A, compute_uv=False)
        values = [abs(x) for x in s]
        scale = max([mpmath.mpf(1)] + values)
        return sum(1 for x in values if x > THRESHOLD * scale)


def substitute(rows, rng):
    """Rows with every free symbol replaced by a random rational (generic values)."""
    symbols = sorted(
        {s for row in rows for e in row for s in sp.sympify(e).free_symbols}, key=str
    )
    values = {
        s: sp.Rational(rng.randint(-997, 997), rng.randint(1, 97)) for s in symbols
    }
    return [[sp.sympify(e).xreplace(values) for e in row] for row in rows]
