"""Proofs of exact ranks: a nonzero minor and a kernel that vanishes identically.

:mod:`._exact` finds the rank of exact screws at sample points modulo a prime: a
minor nonzero there is nonzero, but a minor zero there is zero only with
overwhelming probability. A :class:`RankCertificate` removes the chance. With M the
m x 6 matrix whose rows are the screws, it holds

- ``rows`` and ``cols``: M[rows, cols] is an r x r minor that is not identically
  zero, so rank M >= r;
- ``kernel``: 6 - r independent exact 6-vectors k with M k = 0 identically, so
  rank M <= 6 - (6 - r) = r.

Both facts are checked here without sampling, in a field where equality is decided
exactly and every relation among the entries holds:

- an angle that occurs in sin, cos or tan is split into units (a symbol, or a
  number of radians such as 1) and a rational multiple of pi; the units are divided
  by the least common multiple L of their denominators, so that every sine and
  cosine is a polynomial in sin w and cos w, w = unit / L;
- sin w, cos w and tan w become 2t/(1 + t^2), (1 - t^2)/(1 + t^2) and 2t/(1 - t^2),
  t = tan(w/2): a rational parametrisation of the circle, so an identity in sin w and
  cos w holds exactly when it holds for rational functions of t;
- algebraic numbers (roots, nested roots, CRootOf, sin and cos of rational multiples
  of pi) are elements of one algebraic number field (exact arithmetic modulo a
  minimal polynomial);
- the other symbols, and pi where it stands outside a sine, stay free variables.

A reader can check a certificate with any exact tool: expand the minor and M k, or
substitute the half-angle tangents by hand, as the mobility chapter does.
"""

import math
import random
import time

import sympy as sp
from sympy import QQ

from . import _exact

__all__ = ["RankCertificate", "certify"]

_TRIG = (sp.sin, sp.cos, sp.tan)


class RankCertificate:
    """A proof that an exact matrix of screws has rank r.

    Unpacks as ``rows, cols, kernel = certificate``.

    Attributes
    ----------
    rows, cols : tuple of int, length r
        M[rows, cols] is a nonzero r x r minor of the m x 6 matrix M whose rows are
        the screws (so rank M >= r).
    kernel : list of sympy.Matrix, shape (6, 1) each, 6 - r of them
        Independent exact vectors with M k = 0 identically (so rank M <= r).
    rank : int
        r.
    proven : bool
        True when both facts were checked exactly; False when the check was not
        finished (``reason`` says why: a time limit, or entries no proof here
        covers), and then the rank is the sampled one.
    reason : str
        How the facts were checked, or why they were not.
    """

    def __init__(self, rows, cols, kernel, proven, reason):
        self.rows, self.cols = tuple(rows), tuple(cols)
        self.kernel = list(kernel)
        self.rank = len(self.rows)
        self.proven, self.reason = proven, reason

    def __iter__(self):
        return iter((self.rows, self.cols, self.kernel))

    def __repr__(self):
        state = "proven" if self.proven else "not proven"
        return (
            f"RankCertificate(rank {self.rank}, {state}: rows {list(self.rows)}, "
            f"cols {list(self.cols)}, {len(self.kernel)} kernel vectors)"
        )


class _CircleField:
    """Exact arithmetic on expressions with sin/cos/tan, roots and symbols: each
    expression becomes a fraction of two polynomials over Q in the half-angle tangents,
    the free symbols and one primitive element theta of the algebraic numbers; a
    polynomial stands for zero when its remainder modulo theta's minimal polynomial is
    zero (module docstring). Polynomials over Q are cancelled cheaply; arithmetic in an
    algebraic number field is not, hence theta as a variable."""

    def __init__(self, exprs):
        trig = set().union(*(e.atoms(*_TRIG) for e in exprs)) if exprs else set()
        split = {atom: self._split(atom) for atom in trig if atom.free_symbols}
        split.update(
            {atom: self._split(atom) for atom in trig if self._is_radian(atom)}
        )
        units = {u for parts, _ in split.values() for u in parts}
        denominators = {u: 1 for u in units}
        for parts, _ in split.values():
            for u, c in parts.items():
                denominators[u] = math.lcm(denominators[u], int(c.q))
        ordered = sorted(units, key=sp.default_sort_key)
        self.half_angles = {u: sp.Dummy(f"t_{u}") for u in ordered}
        angle = {u: sp.Dummy(f"w_{u}") for u in ordered}
        circle = {}
        for u, t in self.half_angles.items():
            circle[sp.sin(angle[u])] = 2 * t / (1 + t**2)
            circle[sp.cos(angle[u])] = (1 - t**2) / (1 + t**2)
            circle[sp.tan(angle[u])] = 2 * t / (1 - t**2)
        self._replace = {}
        for atom, (parts, turn) in split.items():
            whole = sum(
                (c * denominators[u] * angle[u] for u, c in parts.items()), turn * sp.pi
            )
            self._replace[atom] = sp.expand_trig(atom.func(whole)).xreplace(circle)
        plain = [e.xreplace(self._replace) for e in exprs]
        symbols = set().union(*(e.free_symbols for e in plain)) if plain else set()
        for constant in (sp.pi, sp.E):  # transcendental: free variables
            if any(_has_outside_numbers(e, constant) for e in plain):
                symbols.add(constant)
        if sp.pi in symbols and sp.E in symbols:
            raise ValueError(
                "no proof covers pi beside E (their algebraic independence is open)"
            )
        algebraic = set()
        for e in plain:
            algebraic |= _algebraic_atoms(e)
        self.algebraic = sorted(algebraic, key=sp.default_sort_key)
        self.generators = sorted(symbols, key=sp.default_sort_key)
        self._theta = sp.Dummy("theta")
        gens = [*self.generators, self._theta] if algebraic else self.generators
        self.R = sp.polys.rings.ring(gens, QQ)[0] if gens else None
        if algebraic:
            self.A = QQ.algebraic_field(*self.algebraic)
            coefficients = self.A.mod.to_list()
            theta = self.R.gens[-1]
            self.minimal = sum(
                (QQ(c) * theta ** (len(coefficients) - 1 - k))
                for k, c in enumerate(coefficients)
            )
        else:
            self.A = None
        self._cache = {}

    @staticmethod
    def _is_radian(atom):
        """sin(1), cos(2/3): a number of radians (transcendental), not a multiple of
        pi."""
        units = _exact._angle_units(atom.args[0])
        return any(u is not sp.pi for u in units)

    @staticmethod
    def _split(atom):
        """sin/cos/tan(arg) -> ({unit: rational}, rational multiple of pi)."""
        try:
            units = _exact._angle_units(atom.args[0])
            turn = units.pop(sp.pi, sp.S.Zero)
            for unit in units:
                _exact._unit_kind(unit, atom.args[0])  # refuses what cannot be read
        except TypeError as error:
            raise ValueError(f"no proof covers {atom}: {error}") from None
        return units, sp.Rational(turn)

    def _number(self, e):
        """An algebraic number as a polynomial in theta (a constant if rational)."""
        if e.is_Rational:
            return self.R(QQ(int(e.p), int(e.q))) if self.R else QQ(int(e.p), int(e.q))
        coefficients = self.A.from_sympy(e).to_list()
        theta = self.R.gens[-1]
        degree = len(coefficients) - 1
        return sum(
            (QQ(c) * theta ** (degree - k) for k, c in enumerate(coefficients)),
            self.R.zero,
        )

    def fraction(self, e):
        """``e`` as (numerator, denominator), polynomials of the ring (or rationals
        when there is no variable)."""
        e = sp.sympify(e)
        if e in self._cache:
            return self._cache[e]
        value = self._fraction(e.xreplace(self._replace))
        self._cache[e] = value
        return value

    def _fraction(self, e):
        if not e.free_symbols and not (
            self.R and any(_has_outside_numbers(e, c) for c in (sp.pi, sp.E))
        ):
            if e.is_Rational or self.A is not None:
                return self._number(e), self._one()
        if e.is_Symbol or e in (sp.pi, sp.E):
            return self.R(self.R.gens[self.generators.index(e)]), self.R.one
        if e.is_Add:
            total = (self._zero(), self._one())
            for term in e.args:
                total = _add(total, self._fraction(term))
            return total
        if e.is_Mul:
            product = (self._one(), self._one())
            for factor in e.args:
                n, d = self._fraction(factor)
                product = (product[0] * n, product[1] * d)
            return product
        if e.is_Pow and e.exp.is_Integer:
            n, d = self._fraction(e.base)
            k = int(e.exp)
            return (n**k, d**k) if k >= 0 else (d ** (-k), n ** (-k))
        raise ValueError(f"no proof covers the expression {e}")

    def _zero(self):
        return self.R.zero if self.R else QQ.zero

    def _one(self):
        return self.R.one if self.R else QQ.one

    def is_zero(self, polynomial):
        """Whether a polynomial of the ring stands for zero."""
        if not polynomial:
            return True
        if self.A is None:
            return False
        return not polynomial.rem([self.minimal])

    def at(self, polynomial, point):
        """The value of a polynomial at rational values of the generators: an element
        of the algebraic number field (or a rational)."""
        if self.R is None:
            return polynomial
        value = polynomial
        if self.generators:
            value = polynomial.evaluate(list(zip(self.R.gens[: len(point)], point)))
        if self.A is None:
            return QQ(value) if not hasattr(value, "ring") else value
        coefficients = [QQ.zero] * (value.degree() + 1) if value else []
        for (k,), c in value.terms():
            coefficients[len(coefficients) - 1 - k] = c
        return self.A(coefficients) * self.A.one if coefficients else self.A.zero


def _algebraic_atoms(e):
    """The algebraic numbers of ``e`` that the number field must hold: roots, CRootOf,
    I, and sin/cos/tan of rational multiples of pi that SymPy keeps unevaluated."""
    found = set()
    for node in sp.preorder_traversal(e):
        if isinstance(node, _TRIG) and not node.free_symbols:
            found.add(node)
        elif node is sp.I or _exact._is_algebraic_atom(node):
            found.add(node)
    return found


def _cleared(field, fractions):
    """Numerators of the fractions over their least common denominator: the same
    vector times a nonzero polynomial."""
    if field.R is None:  # rational numbers: nothing grows
        return [n / d for n, d in fractions]
    common = field.R.one
    for _, d in fractions:
        if d != common:
            common = common.lcm(d)
    return [n * common.exquo(d) if n else n for n, d in fractions]


def _add(a, b):
    (n1, d1), (n2, d2) = a, b
    if not n1:
        return b
    if not n2:
        return a
    if d1 == d2:
        return n1 + n2, d1
    return n1 * d2 + n2 * d1, d1 * d2


def _has_outside_numbers(e, constant):
    """Whether ``constant`` (pi, E) occurs in ``e`` other than inside an algebraic atom
    (sin(pi/7) is algebraic, pi * x is not)."""
    if e == constant:
        return True
    if isinstance(e, _TRIG) and not e.free_symbols:
        return False
    return any(_has_outside_numbers(a, constant) for a in e.args)


def certify(M, rows, cols, kernel, timeout=None):
    """Check a rank certificate of the matrix M exactly.

    Parameters
    ----------
    M : list of lists of SymPy expressions, shape (m, n)
        One row a screw (n = 6).
    rows, cols : sequences of int, length r
        The rows and columns of the minor claimed nonzero.
    kernel : list of SymPy column vectors, shape (n, 1) each, n - r of them
        The vectors claimed to satisfy M k = 0.
    timeout : float or None
        Seconds after which the check stops (None: no limit).

    Returns
    -------
    verdict : bool or None
        True when every claim was checked exactly, False when one is false, None
        when the check was not finished (``timeout``) or no proof covers the entries.
    reason : str
        What was checked, or which claim failed or was not reached.
    """
    start = time.perf_counter()
    flat = [sp.sympify(e) for row in M for e in row]
    vectors = [[sp.sympify(x) for x in k] for k in kernel]
    n = len(M[0]) if M else len(vectors[0]) if vectors else 6
    if len(rows) + len(vectors) != n:
        return False, f"a minor of order {len(rows)} and {len(vectors)} kernel vectors"
    try:
        field = _CircleField(flat + [x for k in vectors for x in k])
        matrix = [[field.fraction(e) for e in row] for row in M]
        kernel_fractions = [[field.fraction(x) for x in k] for k in vectors]
    except (ValueError, NotImplementedError) as error:
        return None, str(error)
    minor = [[matrix[i][j] for j in cols] for i in rows]
    if not _nonzero_determinant(field, minor):
        return False, f"the minor on rows {list(rows)} and columns {list(cols)} is 0"
    free = [j for j in range(n) if j not in cols]
    if not _nonzero_determinant(
        field, [[k[j] for j in free] for k in kernel_fractions]
    ):
        return False, "the kernel vectors are not independent on the free columns"
    # M k = 0 is unchanged by scaling a row or a vector: clear their denominators, so
    # that each product is a sum of polynomial products (no fractions grow)
    rows_cleared = [_cleared(field, row) for row in matrix]
    for index, k in enumerate(kernel_fractions):
        k = _cleared(field, k)
        for i, row in enumerate(rows_cleared):
            if timeout is not None and time.perf_counter() - start > timeout:
                return None, (
                    f"the exact check took longer than {timeout} s (at kernel "
                    f"vector {index}, row {i})"
                )
            total = field._zero()
            for a, c in zip(row, k):
                if a and c:
                    total += a * c
            if not field.is_zero(total):
                return False, f"row {i} times kernel vector {index} is not 0"
    return True, (
        f"exact: the minor on rows {list(rows)} and columns {list(cols)} is nonzero "
        f"and M k = 0 for {len(vectors)} independent k, over {_describe(field)}"
    )


def _nonzero_determinant(field, fractions, tries=8):
    """Whether the determinant of a square matrix of fractions is not identically
    zero: nonzero at one rational point proves it (a point where a denominator
    vanishes is skipped); zero at every point tried, the determinant is expanded."""
    size = len(fractions)
    if size == 0:
        return True
    ground = field.A or QQ
    rng = random.Random(20261202)
    count = len(field.generators)
    for _ in range(tries):
        point = [QQ(rng.randint(-30, 30), rng.randint(1, 7)) for _ in range(count)]
        values = []
        for row in fractions:
            values.append([])
            for numerator, denominator in row:
                below = field.at(denominator, point)
                if not below:
                    break
                values[-1].append(field.at(numerator, point) / below)
            else:
                continue
            break
        else:
            if _determinant(values, ground):
                return True
    determinant = _determinant(fractions, None, add=_add, field=field)
    return not field.is_zero(determinant[0])


def _describe(field):
    roots = ", ".join(map(str, field.algebraic))
    ground = f"Q({roots})" if roots else "Q"
    names = [str(g) for g in field.generators]
    return f"{ground}({', '.join(names)})" if names else ground


def _determinant(rows, K, add=None, field=None):
    """The determinant of a small square matrix (Laplace expansion, exact): over the
    field K, or of (numerator, denominator) fractions when ``field`` is given."""
    size = len(rows)
    if field is not None:
        zero, one = (field._zero(), field._one()), (field._one(), field._one())
    else:
        zero, one = K.zero, K.one
    if size == 0:
        return one
    if size == 1:
        return rows[0][0]
    total = zero
    for j, a in enumerate(rows[0]):
        if field is not None and not a[0] or field is None and not a:
            continue
        minor = _determinant(
            [row[:j] + row[j + 1 :] for row in rows[1:]], K, add, field
        )
        if field is None:
            term = a * minor
            total = total + term if j % 2 == 0 else total - term
        else:
            sign = 1 if j % 2 == 0 else -1
            total = add(total, (sign * a[0] * minor[0], a[1] * minor[1]))
    return total
