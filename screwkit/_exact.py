"""Exact linear algebra on symbolic screw coordinates, fast enough for mobility analysis.

Three ideas keep it exact and fast (the pyScrew4Mobility paper spends its time
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
* **Bases come from minors, not elimination.** The canonical basis of a null space or a row
  space is A_P^-1 times some columns of A, for the pivot columns P (found at the sample
  points). Cramer's rule gives each entry as a ratio of minors of A, and the minors of these
  sparse 6-column matrices are computed by Laplace expansion with memoisation, with no
  division until the last: far cheaper than fraction-free elimination, whose intermediate
  polynomials grow with a poor pivot order.
"""
import functools
import math
import random

import sympy as sp
from sympy import GF, QQ, ZZ
from sympy.ntheory import sqrt_mod
from sympy.polys.matrices import DomainMatrix

_TRIG = (sp.sin, sp.cos, sp.tan)
_TRANSCENDENTAL = (sp.pi, sp.E)
_SAMPLE_POINTS = 2
_SEED = 20201
_PRIME = 2**61 - 1  # a Mersenne prime: arithmetic modulo it is exact and fast


def entries(matrix):
    """The entries of a SymPy matrix as a flat list, row by row.

    SymPy's ``flat()`` and iteration convert entry by entry; a matrix of expressions holds
    them as they are in its EXRAW representation, read here in one call.
    """
    rep = matrix._rep
    return rep.to_list_flat() if rep.domain.is_EXRAW else matrix.flat()


def _exact_numbers(e):
    """Floats become the exact rationals they stand for, so exact arithmetic applies."""
    return e.xreplace({f: sp.Rational(f) for f in e.atoms(sp.Float)}) if e.has(sp.Float) else e


def _is_root(e):
    """True for a numeric root such as sqrt(3) = 3**(1/2)."""
    return e.is_Pow and e.base.is_Rational and e.exp.is_Rational and not e.exp.is_Integer


def _scan(e, found, seen):
    """Collect, in one walk of the tree, the generators of ``e``: trig atoms, numeric roots, and the
    symbols outside them; other functions go to found['other'], and Floats set found['float']."""
    if e in seen:
        return
    seen.add(e)
    if isinstance(e, _TRIG):
        found["trig"].add(e)
    elif e.is_Symbol:
        found["symbols"].add(e)
    elif e.is_Float:
        found["float"] = True
    elif e in _TRANSCENDENTAL:  # pi and E: generators like symbols (no algebraic relation)
        found["symbols"].add(e)
    elif e is sp.I or _is_root(e):
        found["roots"].add(e)
    elif e.is_Pow and not e.exp.is_Integer:  # a nested or symbolic root: no polynomial generator
        found["other"].add(e)
    else:
        if isinstance(e, sp.Function):
            found["other"].add(e)
        for a in e.args:
            _scan(a, found, seen)


class Field:
    """The field QQ(generators) that holds every entry of one problem, and its sample points.

    The generators are the symbols, the sin/cos/tan atoms and the numeric roots themselves
    (SymPy's polynomial rings accept sin(theta) as a generator), so no substitution is needed.
    """

    def __init__(self, exprs):
        exprs = [sp.sympify(e) for e in exprs]
        found = self._generators(exprs)
        self._floats = found["float"]
        if self._floats:
            exprs = [_exact_numbers(e) for e in exprs]
        self.expand = any(not a.args[0].is_Symbol for a in found["trig"])
        if self.expand:  # sin(a + b) and the like: write in sin/cos of single symbols
            exprs = [sp.expand_trig(e) for e in exprs]
            found = self._generators(exprs)
        if found["other"]:
            raise TypeError("screw coordinates may hold numbers, symbols, pi, square roots of rational "
                            f"numbers and sin, cos, tan of expressions, got {sorted(map(str, found['other']))}")
        self.symbols = sorted(found["trig"] | found["roots"] | found["symbols"], key=sp.default_sort_key)
        # the minors are computed with integer coefficients (see _polynomial_rows)
        self.K, self.integer_ring = _domains(tuple(self.symbols))
        self._cache = {}
        self._polynomials = {}
        self._generator_index = {g: k for k, g in enumerate(self.symbols)}
        self.prime, self._points = self._sample_points()
        self.GF = GF(self.prime)

    @staticmethod
    def _generators(exprs):
        found = {"trig": set(), "roots": set(), "symbols": set(), "other": set(), "float": False}
        seen = set()
        for e in exprs:
            _scan(e, found, seen)
        return found

    def element(self, e):
        e = e if isinstance(e, sp.Basic) else sp.sympify(e)
        if self._floats:
            e = _exact_numbers(e)
        value = self._cache.get(e)
        if value is None:
            plain = sp.expand_trig(e) if self.expand and e.has(*_TRIG) else e
            # most screw coordinates are polynomials: build their terms directly, no cancelling
            terms = self._terms(plain)
            if terms is None:
                value = self.K.from_sympy(plain)
            elif self.symbols:
                value = self.K.field.raw_new(self.K.field.ring.dtype(terms))
            else:
                value = terms.get((), QQ.zero)
            self._cache[e] = value
        return value

    def _terms(self, e):
        """``e`` as a polynomial in the generators, {exponents: QQ coefficient}, or None if it
        is not one. Subexpressions are memoised: the joint screws of one mechanism share many
        products such as a*sin(theta)*cos(alpha)."""
        if e in self._polynomials:
            return self._polynomials[e]
        n = len(self.symbols)
        if e in self._generator_index:
            k = self._generator_index[e]
            value = {tuple(int(i == k) for i in range(n)): QQ.one}
        elif e.is_Rational:
            value = {(0,) * n: QQ(int(e.p), int(e.q))} if e else {}
        elif e.is_Add:
            value = {}
            for term in e.args:
                part = self._terms(term)
                if part is None:
                    value = None
                    break
                for monomial, c in part.items():
                    c += value.get(monomial, QQ.zero)
                    if c:
                        value[monomial] = c
                    else:
                        del value[monomial]
        elif e.is_Mul or e.is_Pow and e.exp.is_Integer and e.exp > 0:
            factors = e.args if e.is_Mul else [e.base] * int(e.exp)
            value = {(0,) * n: QQ.one}
            for factor in factors:
                part = self._terms(factor)
                if part is None:
                    value = None
                    break
                value = _product(value, part)
        else:
            value = None
        self._polynomials[e] = value
        return value

    def matrix(self, rows):
        """A DomainMatrix over this field from rows of SymPy expressions."""
        rows = [list(r) for r in rows]
        return DomainMatrix([[self.element(e) for e in r] for r in rows], (len(rows), len(rows[0])), self.K)

    def to_sympy(self, element):
        if not self.symbols:
            return self.K.to_sympy(element)
        numerator, denominator = element.numer, element.denom
        if numerator.is_ground and denominator.is_ground:  # a number: no printing, no factoring
            a, b = numerator.LC, denominator.LC
            return sp.Rational(int(a.numerator) * int(b.denominator), int(a.denominator) * int(b.numerator))
        return sp.factor(self.K.to_sympy(element))

    def _sample_points(self):
        """A prime, and exact random values of the generators modulo it that keep every relation."""
        rng = random.Random(_SEED)
        roots = [g for g in self.symbols if g is sp.I or _is_root(g)]
        for r in roots:
            if r is not sp.I and r.exp.q != 2:
                raise TypeError(f"screw coordinates may use square roots only, got {r}")
        # sqrt(6) must be sqrt(2) sqrt(3) at the sample points too: every root is built from the
        # square roots of the primes (and of -1) that divide its radicand, each chosen once
        radicands = {r: sp.Integer(-1) if r is sp.I else r.base for r in roots}
        primes = sorted({p for q in radicands.values() for n in (q.p, q.q) for p in sp.factorint(abs(n))}
                        | ({-1} if any(q < 0 for q in radicands.values()) else set()))
        prime = _PRIME
        while True:  # the prime must have the square roots we need
            prime_roots = {p: _sqrt_mod(p % prime, prime) for p in primes}
            if all(v is not None for v in prime_roots.values()):
                break
            prime = int(sp.prevprime(prime))
        root_values = {}
        for r, q in radicands.items():
            value = _root_of_rational(q, prime_roots, prime)
            exponent = 1 if r is sp.I else int(r.exp.p)  # r = sqrt(q) ** exponent
            root_values[r] = pow(value, exponent, prime)
        angles = sorted({g.args[0] for g in self.symbols if isinstance(g, _TRIG)}, key=sp.default_sort_key)
        points = []
        for _ in range(_SAMPLE_POINTS):
            value = dict(root_values)
            for angle in angles:
                t = rng.randrange(2, prime - 1)
                inverse = pow(1 + t * t, -1, prime)
                sin, cos = 2 * t * inverse % prime, (1 - t * t) * inverse % prime
                value[sp.sin(angle)], value[sp.cos(angle)] = sin, cos
                value[sp.tan(angle)] = sin * pow(cos, -1, prime) % prime if cos else 0
            points.append([value[g] if g in value else rng.randrange(1, prime) for g in self.symbols])
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


_DOMAINS = {}


def _root_of_rational(q, prime_roots, prime):
    """sqrt(q) modulo the prime for a rational q, from the chosen roots of its prime factors."""
    value = prime_roots[-1] if q < 0 else 1
    for n, sign in ((abs(q.p), 1), (q.q, -1)):
        for p, k in sp.factorint(n).items():
            part = pow(p, k // 2, prime) * (prime_roots[p] if k % 2 else 1)
            value = value * pow(part, sign, prime) % prime
    return value


@functools.lru_cache(maxsize=256)
def _sqrt_mod(a, prime):
    """A square root of a modulo the prime, or None (the same few roots, such as sqrt(3), recur)."""
    return sqrt_mod(a, prime, all_roots=False)


def _domains(symbols):
    """QQ(symbols) and ZZ[symbols], built once per set of generators (SymPy rebuilds them)."""
    if not symbols:
        return QQ, None
    if symbols not in _DOMAINS:
        K = QQ.frac_field(*symbols)
        _DOMAINS[symbols] = K, K.field.ring.clone(domain=ZZ)
    return _DOMAINS[symbols]


def _product(a, b):
    """The product of two polynomials held as {exponents: coefficient}."""
    product = {}
    for ma, ca in a.items():
        for mb, cb in b.items():
            monomial = tuple(x + y for x, y in zip(ma, mb))
            c = product.get(monomial, QQ.zero) + ca * cb
            if c:
                product[monomial] = c
            else:
                del product[monomial]
    return product


def generic_rank(rows):
    """The rank, for generic values of the symbols, of a matrix given as rows of SymPy expressions."""
    field = Field([e for row in rows for e in row])
    return field.rank(field.matrix(rows))


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
    """The chosen rows of M, each multiplied by a nonzero factor that clears its denominators:
    rows of polynomials with integer coefficients (over QQ when there are no symbols).

    Scaling a row changes neither its null space nor its row space, nor the ratios of minors
    that Cramer's rule takes; integer coefficients make the minors plain ``int`` arithmetic.
    """
    K = field.K
    if K is QQ:
        return M.extract(rows, list(range(M.shape[1]))).to_list()
    integer_ring = field.integer_ring
    entries = M.to_list()
    polynomial = []
    for i in rows:
        row = entries[i]
        denominator = None
        for e in row:
            if e and not e.denom.is_ground:
                denominator = e.denom if denominator is None else denominator.lcm(e.denom)
        if denominator is None:
            cleared = [e.numer.quo_ground(e.denom.LC) if e and e.denom != 1 else e.numer for e in row]
        else:
            cleared = [e.numer * denominator.exquo(e.denom) if e else e.numer for e in row]
        scale = 1
        for p in cleared:
            for c in p.values():
                scale = math.lcm(scale, int(c.denominator))
        polynomial.append([integer_ring.dtype({m: int(c.numerator) * (scale // int(c.denominator))
                                               for m, c in p.items()}) for p in cleared])
    return polynomial


def _determinants(rows, zero, one):
    """det of the square submatrix of ``rows`` on an ordered list of columns, memoised.

    Laplace expansion along the rows in turn, skipping zero entries: the matrices of joint
    screws are sparse, and the minors that the columns share are computed once. No division
    happens, so the entries may be polynomials.
    """
    memo = {}

    def sorted_det(depth, cols):
        if depth == len(rows):
            return one
        key = (depth, cols)
        if key not in memo:
            total = zero
            for position, c in enumerate(cols):
                if rows[depth][c]:
                    minor = sorted_det(depth + 1, cols[:position] + cols[position + 1:])
                    if minor:
                        term = rows[depth][c] * minor
                        total = total + term if position % 2 == 0 else total - term
            memo[key] = total
        return memo[key]

    def det(cols):
        if len(set(cols)) < len(cols):
            return zero
        order = sorted(range(len(cols)), key=lambda k: cols[k])
        inversions = sum(1 for a in range(len(order)) for b in range(a + 1, len(order)) if order[a] > order[b])
        value = sorted_det(0, tuple(sorted(cols)))
        return -value if inversions % 2 else value

    return det


def _pivot_columns(field, rows, columns):
    """The pivot columns (taken in the order ``columns``) of independent rows, for generic values."""
    if field.symbols:
        for values in field._points:
            numbers = [[field.GF(_evaluate_polynomial(row[j], values, field.prime)) if row[j] else field.GF.zero
                        for j in columns] for row in rows]
            pivots = DomainMatrix(numbers, (len(rows), len(columns)), field.GF).rref()[1]
            if len(pivots) == len(rows):
                return [columns[k] for k in pivots]
        raise ArithmeticError("no sample point gives the generic rank: the sample points are not generic")
    M = DomainMatrix([[row[j] for j in columns] for row in rows], (len(rows), len(columns)), QQ)
    return [columns[k] for k in M.rref()[1]]


def _solve_by_minors(field, rows, pivots, others):
    """Cramer's rule on A = rows with det(A_pivots) != 0: for each column j in ``others``, the
    solution x of A_pivots x = A_j, as {pivot: K element}, each x_k = det(A_pivots, column k
    replaced by column j) / det(A_pivots)."""
    K = field.K
    if not field.symbols:
        det = _determinants(rows, K.zero, K.one)
        denominator = det(pivots)
        return [{p: K.quo(det(pivots[:k] + [j] + pivots[k + 1:]), denominator)
                 for k, p in enumerate(pivots)} for j in others]
    ring = field.integer_ring
    det = _determinants(rows, ring.zero, ring.one)
    denominator = det(pivots)
    solutions = []
    for j in others:
        x = {}
        for k, p in enumerate(pivots):
            value = det(pivots[:k] + [j] + pivots[k + 1:])
            x[p] = _fraction(K, *_cancel(value, denominator)) if value else K.zero
        solutions.append(x)
    return solutions


def _cancel(numerator, denominator):
    """numerator / denominator in lowest terms, the denominator's leading coefficient positive.
    Most ratios of minors here are polynomials (often numbers): an exact division is tried
    before the gcd."""
    quotient, remainder = numerator.div(denominator)
    if not remainder:
        return quotient, quotient.ring.one
    return numerator.cancel(denominator)


def _fraction(K, numerator, denominator):
    """The element numerator / denominator of K from coprime integer polynomials."""
    ring = K.field.ring
    return K.field.raw_new(numerator.set_ring(ring), denominator.set_ring(ring))


def reduced_basis(field, M, rows=None):
    """A canonical basis of the row space of M (DomainMatrix over ``field``), as a DomainMatrix.

    ``rows``: indices of generically independent rows (found if not given). Reduced from
    the right: each row has a 1 at its last nonzero coordinate and zeros in the other rows
    there, so couples and forces read like (0, 0, 0, 0, 0, 1). That is B = A_P^-1 A for the
    pivot columns P found from the right; its entries are ratios of minors of A (Cramer's
    rule), computed without fractions until the one division each.
    """
    cols = M.shape[1]
    rows = field.independent_rows(M) if rows is None else rows
    if not rows:
        return DomainMatrix.zeros((0, cols), field.K)
    if len(rows) == cols:  # the whole space: the identity is its reduced basis
        return DomainMatrix.eye(cols, field.K)
    A = _polynomial_rows(field, M, rows)
    pivots = sorted(_pivot_columns(field, A, list(reversed(range(cols)))))
    K = field.K
    basis = [[K.one if j == p else K.zero for j in range(cols)] for p in pivots]
    others = [j for j in range(cols) if j not in pivots]
    for j, x in zip(others, _solve_by_minors(field, A, pivots, others)):
        for k, p in enumerate(pivots):
            basis[k][j] = x[p]
    return DomainMatrix(basis, (len(basis), cols), K)


def null_space(field, M, rows=None):
    """A canonical basis of {x : M x = 0} for generic values, as DomainMatrix rows.

    With the pivot columns P of M (from the left) and the free columns F, basis vector f has
    x_f = 1, zeros at the other free columns and x_P = -A_P^-1 A_f (Cramer's rule): its last
    nonzero coordinate is that 1, so the basis is already reduced from the right.
    """
    cols = M.shape[1]
    rows = field.independent_rows(M) if rows is None else rows
    if not rows:
        return DomainMatrix.eye(cols, field.K)
    if len(rows) == cols:  # full rank: only the zero vector
        return DomainMatrix.zeros((0, cols), field.K)
    A = _polynomial_rows(field, M, rows)
    pivots = _pivot_columns(field, A, list(range(cols)))
    free = [j for j in range(cols) if j not in pivots]
    K = field.K
    basis = []
    for f, x in zip(free, _solve_by_minors(field, A, pivots, free)):
        basis.append([K.one if j == f else K.zero if j in free else K.neg(x[j]) for j in range(cols)])
    return DomainMatrix(basis, (len(basis), cols), K)
