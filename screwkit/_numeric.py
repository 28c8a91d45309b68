"""Screw systems of floating-point numbers: ranks by SVD with a stated tolerance.

Exact input (integers, rationals, symbols, pi, square roots) is handled by
:mod:`._exact`. Floats are measurements or the result of float arithmetic
(a frame tilted with NumPy): two axes meant to be parallel differ in their last bits,
and an exact rank would count them as independent. Here a matrix's rank is the number of
its singular values above ``tol * max(1, largest singular value)``, with ``tol =
RANK_TOL`` (1e-9, :mod:`screwkit.tolerances`) unless the caller says otherwise, and
bases are reduced as in the exact layer (each row ends in a 1 at its own pivot column,
found from the right), with entries within ``tol`` of an integer set to that integer.
"""

import numpy as np
import sympy as sp

from .tolerances import RANK_TOL

#: The default relative tolerance of float ranks (the old name of
#: :data:`screwkit.tolerances.RANK_TOL`).
TOL = RANK_TOL


def has_floats(exprs):
    """True if any of the SymPy expressions holds a (non-integral) Float."""
    return any(e.has(sp.Float) for e in exprs)


def check_tol(tol):
    """``tol`` as a positive float below 1; a clear error otherwise."""
    if isinstance(tol, bool) or not isinstance(tol, (int, float, np.floating)):
        raise TypeError(
            f"tol must be a positive number below 1, got {tol!r} ({type(tol).__name__})"
        )
    if not 0 < tol < 1:
        raise ValueError(f"tol must be a positive number below 1, got {tol!r}")
    return float(tol)


def to_array(rows, name="screws"):
    """Rows of SymPy numbers as a float array; a clear error if a symbol is left in
    them."""
    symbols = sorted(
        {str(s) for row in rows for e in row for s in sp.sympify(e).free_symbols}
    )
    if symbols:
        raise ValueError(
            f"{name} mix floats with the symbols {symbols}: pass exact numbers instead "
            "of floats (sympy.Rational('0.3'), sympy.sqrt(3)/2, sympy.pi/6) to keep "
            "the symbols, or give every symbol a number"
        )
    return np.array([[float(e) for e in row] for row in rows], dtype=float).reshape(
        len(rows), -1
    )


def lost_rank(sigma, m, n):
    """True where an m x n matrix with singular values ``sigma`` (..., k), largest
    first, has lost rank: NumPy's rank rule (``matrix_rank``) on the smallest one."""
    return sigma[..., -1] <= sigma[..., 0] * max(m, n) * np.finfo(float).eps


def _threshold(singular_values, tol):
    return tol * max(1.0, float(singular_values[0])) if singular_values.size else tol


def rank(A, tol=TOL):
    """The number of singular values of A above tol * max(1, the largest)."""
    if A.size == 0:
        return 0
    s = np.linalg.svd(A, compute_uv=False)
    return int(np.sum(s > _threshold(s, tol)))


def _clean(A, tol):
    """Entries within tol of an integer become that integer
    (so axes read as 1, 0, -1)."""
    A = np.where(np.abs(A) < tol, 0.0, A)
    nearest = np.round(A)
    return np.where(np.abs(A - nearest) < tol, nearest, A)


def reduced_basis(A, tol=TOL):
    """A canonical basis of the row space of A (rows), as in the exact layer: pivot
    columns chosen from the right, each basis row 1 at its own pivot and 0 at the
    others'."""
    A = np.asarray(A, dtype=float).reshape(-1, 6)
    if rank(A, tol) == 0:
        return np.zeros((0, A.shape[1]))
    u, s, vt = np.linalg.svd(A)
    basis = vt[
        : int(np.sum(s > _threshold(s, tol)))
    ]  # orthonormal rows spanning the same space
    pivots = []
    for column in reversed(range(A.shape[1])):
        if rank(basis[:, pivots + [column]], tol) > len(pivots):
            pivots.append(column)
        if len(pivots) == len(basis):
            break
    pivots.sort()
    return _clean(np.linalg.solve(basis[:, pivots], basis), tol)


def null_space(A, tol=TOL):
    """A canonical basis (rows) of {x : A x = 0}, reduced as :func:`reduced_basis`."""
    A = np.asarray(A, dtype=float).reshape(-1, 6)
    if A.shape[0] == 0:
        return np.eye(A.shape[1])
    u, s, vt = np.linalg.svd(A)
    r = int(np.sum(s > _threshold(s, tol)))
    kernel = vt[r:]
    return reduced_basis(kernel, tol) if len(kernel) else np.zeros((0, A.shape[1]))


def as_sympy_rows(A):
    """Float rows as SymPy rows: integers stay integers, the rest become Floats."""
    return [
        [sp.Integer(int(x)) if float(x).is_integer() else sp.Float(x) for x in row]
        for row in A
    ]
