"""Exact linear algebra on symbolic screw coordinates, fast enough for mobility analysis.

Two ideas keep it exact and fast (the pyScrew4Mobility paper spends its time
simplifying trigonometric expressions inside ``Matrix.nullspace``):

* **Rank is decided generically and exactly.** Every entry is a rational function of
  generators: the symbols, the sin/cos/tan atoms and square roots such as sqrt(3). The
  rank is computed exactly, modulo a large prime, at random points that respect every
  relation: sin and cos of each angle come from the half-angle substitution
  t -> (2t/(1+t^2), (1-t^2)/(1+t^2)), and sqrt(q) is a square root of q modulo the prime.
  A minor that is nonzero there is nonzero as a function (Schwartz–Zippel), and a zero
  minor at random points of a 61-bit field means zero with overwhelming probability. No
  floating-point round-off is involved, and the seed is fixed, so runs are identical.
* **Bases are computed in the field of rational functions** of those generators, from
  rows that are independent at the sample points: those rows have full rank in the field,
  so no identity such as sin^2 + cos^2 = 1 or sqrt(3)^2 = 3 is ever needed, and none of
  SymPy's trigonometric simplification runs.
"""
import random

import sympy as sp
from sympy import GF, QQ
from sympy.ntheory import sqrt_mod
from sympy.polys.matrices import DomainMatrix

_TRIG = (sp.sin, sp.cos, sp.tan)
_SAMPLE_POINTS = 2
_SEED = 20201
_PRIME = 2**61 - 1  # a Mersenne prime: arithmetic modulo it is exact and fast


def _exact_numbers(e):
    """Floats become the exact rationals they stand for, so exact arithmetic applies."""
    return e.xreplace({f: sp.Rational(f) for f in e.atoms(sp.Float)}) if e.has(sp.Float) else e


def _roots(exprs):
    """The numeric roots, such as sqrt(3), that occur in the expressions."""
    roots = set()
    for e in exprs:
        for p in e.atoms(sp.Pow):
            if p.base.is_Rational and p.exp.is_Rational and not p.exp.is_Integer:
                roots.add(p)
    return roots


class Field:
    """The field QQ(generators) that holds every entry of one problem, and its sample points."""

    def __init__(self, exprs):
        exprs = [_exact_numbers(sp.sympify(e)) for e in exprs]
        trig = set().union(*(e.atoms(*_TRIG) for e in exprs)) if exprs else set()
        self.expand = any(not a.args[0].is_Symbol for a in trig)
        if self.expand:  # sin(a + b) and the like: write in sin/cos of single symbols
            exprs = [sp.expand_trig(e) for e in exprs]
            trig = set().union(*(e.atoms(*_TRIG) for e in exprs))
        for e in exprs:
            other = {f for f in e.atoms(sp.Function) if not isinstance(f, _TRIG)}
            if other:
                raise TypeError(f"screw coordinates may use sin, cos and tan only, got {sorted(map(str, other))}")
        atoms = sorted(trig | _roots(exprs), key=sp.default_sort_key)
        self.dummy = {a: sp.Dummy(f"g{k}") for k, a in enumerate(atoms)}
        self.atom = {d: a for a, d in self.dummy.items()}
        symbols = set().union(*(e.xreplace(self.dummy).free_symbols for e in exprs)) if exprs else set()
        self.symbols = sorted(symbols, key=sp.default_sort_key)
        self.K = QQ.frac_field(*self.symbols) if self.symbols else QQ
        self._cache = {}
        self.prime, self._points = self._sample_points()
        self.GF = GF(self.prime)

    def element(self, e):
        e = _exact_numbers(sp.sympify(e))
        if e not in self._cache:
            plain = sp.expand_trig(e) if self.expand and e.has(*_TRIG) else e
            self._cache[e] = self.K.from_sympy(plain.xreplace(self.dummy))
        return self._cache[e]

    def matrix(self, rows):
        """A DomainMatrix over this field from rows of SymPy expressions."""
        rows = [list(r) for r in rows]
        return DomainMatrix([[self.element(e) for e in r] for r in rows], (len(rows), len(rows[0])), self.K)

    def to_sympy(self, element):
        if self.symbols and not (element.numer.is_ground and element.denom.is_ground):
            return sp.factor(self.K.to_sympy(element)).xreplace(self.atom)
        return self.K.to_sympy(element)

    def _sample_points(self):
        """A prime, and exact random values of the generators modulo it that keep every relation."""
        rng = random.Random(_SEED)
        roots = [a for a in self.atom.values() if isinstance(a, sp.Pow)]
        prime = _PRIME
        while True:  # the prime must have the square roots we need
            root_values = {}
            for r in roots:
                q = r.base ** r.exp.p  # r = q**(1/n) with q rational
                values = sqrt_mod(int(q.p) * pow(int(q.q), -1, prime) % prime, prime, all_roots=False) \
                    if r.exp.q == 2 else None
                if values is None:
                    break
                root_values[r] = values
            if len(root_values) == len(roots):
                break
            prime = int(sp.prevprime(prime))
        angles = sorted({a.args[0] for a in self.atom.values() if isinstance(a, _TRIG)}, key=sp.default_sort_key)
        points = []
        for _ in range(_SAMPLE_POINTS):
            value = dict(root_values)
            for angle in angles:
                t = rng.randrange(2, prime - 1)
                inverse = pow(1 + t * t, -1, prime)
                sin, cos = 2 * t * inverse % prime, (1 - t * t) * inverse % prime
                value[sp.sin(angle)], value[sp.cos(angle)] = sin, cos
                value[sp.tan(angle)] = sin * pow(cos, -1, prime) % prime if cos else 0
            points.append([value[self.atom[g]] if g in self.atom else rng.randrange(1, prime)
                           for g in self.symbols])
        return prime, points

    def independent_rows(self, M):
        """Indices of a largest set of rows of M that are independent for generic values."""
        rows, cols = M.shape
        if rows == 0:
            return []
        if not self.symbols:
            return list(M.transpose().rref()[1])
        best = []
        entries = M.to_list()
        for values in self._points:
            numbers = [[self._evaluate(e, values) for e in row] for row in entries]
            if any(n is None for row in numbers for n in row):
                continue  # a denominator vanishes at this point: use the other one
            pivots = DomainMatrix(numbers, (rows, cols), self.GF).transpose().rref()[1]
            if len(pivots) > len(best):
                best = list(pivots)
            if len(best) == min(rows, cols):
                break
        return best

    def rank(self, M):
        """The generic rank of a DomainMatrix over this field."""
        return len(self.independent_rows(M))

    def _evaluate(self, element, values):
        """element(values) modulo the prime, or None where its denominator vanishes."""
        if not element:
            return self.GF.zero
        numerator = _evaluate_polynomial(element.numer, values, self.prime)
        denominator = _evaluate_polynomial(element.denom, values, self.prime)
        if denominator == 0:
            return None
        return self.GF(numerator * pow(denominator, -1, self.prime))


def _evaluate_polynomial(polynomial, values, prime):
    total = 0
    for monomial, coefficient in polynomial.terms():
        term = int(coefficient.numerator) * pow(int(coefficient.denominator), -1, prime)
        for value, exponent in zip(values, monomial):
            if exponent:
                term = term * pow(value, exponent, prime)
        total = (total + term) % prime
    return total


def _polynomial_rows(field, M, rows):
    """The chosen rows of M with their denominators cleared: a matrix over the polynomial ring."""
    K = field.K
    if K is QQ:
        return M.extract(rows, list(range(M.shape[1])))
    ring = K.get_ring()
    polynomial = []
    for i in rows:
        row = M.to_list()[i]
        denominator = ring.one
        for e in row:
            denominator = denominator.lcm(e.denom) if e else denominator
        cleared = [(e.numer * denominator.exquo(e.denom)) if e else ring.zero for e in row]
        content = ring.zero
        for e in cleared:  # divide out the row's common factor to keep the entries small
            if e:
                content = e if not content else content.gcd(e)
        polynomial.append([e.exquo(content) if e else e for e in cleared])
    return DomainMatrix(polynomial, (len(rows), M.shape[1]), ring)


def _normalised(field, R, pivots):
    """Rows of a fraction-free echelon form divided by their pivots, over the field."""
    K = field.K
    out = []
    for i, j in enumerate(pivots):
        row = R.to_list()[i]
        pivot = K.convert(row[j])
        out.append([K.one if k == j else K.quo(K.convert(e), pivot) if e else K.zero
                    for k, e in enumerate(row)])
    return DomainMatrix(out, (len(out), R.shape[1]), K)


def reduced_basis(field, M, rows=None):
    """A canonical basis of the row space of M (DomainMatrix over ``field``), as a DomainMatrix.

    ``rows``: indices of generically independent rows (found if not given). Reduced from
    the right: each row has a 1 at its last nonzero coordinate and zeros in the other rows
    there, so couples and forces read like (0, 0, 0, 0, 0, 1). Elimination is fraction-free
    over the polynomial ring (no gcds); the single division by each pivot comes last.
    """
    cols = M.shape[1]
    rows = field.independent_rows(M) if rows is None else rows
    if not rows:
        return DomainMatrix.zeros((0, cols), field.K)
    if len(rows) == cols:  # the whole space: the identity is its reduced basis
        return DomainMatrix.eye(cols, field.K)
    flip = list(reversed(range(cols)))
    P = _polynomial_rows(field, M, rows).extract(list(range(len(rows))), flip)
    R, _, pivots = P.rref_den()
    R = _normalised(field, R, pivots)
    order = sorted(range(len(pivots)), key=lambda i: -pivots[i])
    return R.extract(order, flip)


def null_space(field, M, rows=None):
    """A canonical basis of {x : M x = 0} for generic values, as DomainMatrix rows."""
    cols = M.shape[1]
    rows = field.independent_rows(M) if rows is None else rows
    if not rows:
        return DomainMatrix.eye(cols, field.K)
    if len(rows) == cols:  # full rank: only the zero vector
        return DomainMatrix.zeros((0, cols), field.K)
    N = _polynomial_rows(field, M, rows).nullspace(divide_last=False)
    N = DomainMatrix([[field.K.convert(e) for e in row] for row in N.to_list()], N.shape, field.K)
    return reduced_basis(field, N, list(range(N.shape[0])))
