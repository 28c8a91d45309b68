"""Exact linear algebra on symbolic screw coordinates, fast enough for mobility
analysis.

Three ideas keep it exact and fast (the pyScrew4Mobility paper spends its time
simplifying trigonometric expressions inside ``Matrix.nullspace``):

* **Rank is decided generically and exactly, over the field the entries generate.**
  Every entry is a rational function of generators: the symbols, pi and E, the
  sin/cos/tan atoms and the algebraic atoms (sqrt(3), sqrt(2 + sqrt(2)), 2**(1/3),
  CRootOf). The rank is computed exactly, modulo a large prime, at sample points that
  keep every relation among the generators (a ring homomorphism onto the prime field):
  the angles are split into units with one base angle each, so sin(2a) = 2 sin(a)
  cos(a), cos(a + b) expanded and cos(2 pi/7) = 2 cos(pi/7)^2 - 1 hold there; multiples
  of pi use roots of unity, the algebraic atoms a root of their number field's minimal
  polynomial modulo the prime (see :func:`_sample_points`). A minor that is nonzero
  there is nonzero in the field (Schwartz–Zippel for the transcendental generators), and
  a zero minor at random points of a 61-bit field means zero with overwhelming
  probability. What cannot be decided (pi beside sin(1), whose algebraic independence is
  Schanuel's conjecture; sin(e)) is refused with the reason. No floating-point round-off
  is involved, and the seed is fixed, so runs are identical.
* **Bases are computed in the field of rational functions** of those generators, from
  rows that are independent at the sample points: those rows have full rank in the
  field, so no identity such as sin^2 + cos^2 = 1 or sqrt(3)^2 = 3 is ever needed, and
  none of SymPy's trigonometric simplification runs.
* **Bases come from minors, not elimination.** The canonical basis of a null space or a
  row space is A_P^-1 times some columns of A, for the pivot columns P (found at the
  sample points). Cramer's rule gives each entry as a ratio of minors of A, and the
  minors of these sparse 6-column matrices are computed by Laplace expansion with
  memoisation, with no division until the last: far cheaper than fraction-free
  elimination, whose intermediate polynomials grow with a poor pivot order.
"""

import functools
import math
import random

import sympy as sp
from sympy import GF, QQ, ZZ
from sympy.ntheory import sqrt_mod
from sympy.ntheory.modular import crt
from sympy.polys import galoistools as _gf
from sympy.polys.matrices import DomainMatrix
from sympy.polys.numberfields import primitive_element

_TRIG = (sp.sin, sp.cos, sp.tan)
_TRANSCENDENTAL = (sp.pi, sp.E)
_SAMPLE_POINTS = 2
_SEED = 20201
_PRIME = 2**61 - 1  # a Mersenne prime: arithmetic modulo it is exact and fast


class _SymPy:
    """The one place that touches SymPy internals (private attributes, raw constructors,
    the low-level finite-field routines). A SymPy release that changes them breaks here,
    and ``tests/test_exact.py`` tests each function on its own."""

    @staticmethod
    def flat_entries(matrix):
        """The entries of a SymPy matrix, row by row, read from its EXRAW store in one
        call (``flat()`` converts entry by entry)."""
        rep = matrix._rep
        return rep.to_list_flat() if rep.domain.is_EXRAW else matrix.flat()

    @staticmethod
    def fraction_field(symbols):
        """QQ(symbols) and the ring ZZ[symbols] of its numerators."""
        K = QQ.frac_field(*symbols)
        return K, K.field.ring.clone(domain=ZZ)

    @staticmethod
    def field_polynomial(K, terms):
        """The element of K = QQ(symbols) with the polynomial {exponents: QQ} as
        numerator and 1 as denominator, built without a gcd."""
        return K.field.raw_new(K.field.ring.dtype(terms))

    @staticmethod
    def field_fraction(K, numerator, denominator):
        """The element numerator / denominator of K from coprime ZZ[symbols]
        polynomials."""
        ring = K.field.ring
        return K.field.raw_new(numerator.set_ring(ring), denominator.set_ring(ring))

    @staticmethod
    def ring_polynomial(ring, terms):
        """The polynomial {exponents: int} of ``ring``."""
        return ring.dtype(terms)

    @staticmethod
    def number_field(atoms):
        """Q(atoms) by a primitive element: its minimal polynomial (integer
        coefficients, highest first) and each atom as a polynomial in it (rational
        coefficients)."""
        minpoly, _, reps = primitive_element(atoms, ex=True, polys=True)
        minpoly = [sp.Rational(c) for c in minpoly.all_coeffs()]
        scale = math.lcm(*(int(c.q) for c in minpoly))
        minpoly = [int(c * scale) for c in minpoly]
        reps = [
            [sp.Rational(int(c.numerator), int(c.denominator)) for c in rep]
            for rep in reps
        ]
        return minpoly, reps

    @staticmethod
    def roots_mod(coefficients, prime):
        """The roots modulo ``prime`` of an integer polynomial (coefficients highest
        first)."""
        f = _gf.gf_from_int_poly(coefficients, prime)
        if len(f) < 2:
            return []
        f = _gf.gf_monic(f, prime, ZZ)[1]
        x = [ZZ(1), ZZ(0)]
        power = _gf.gf_pow_mod(x, prime, f, prime, ZZ)
        split = _gf.gf_gcd(_gf.gf_sub(power, x, prime, ZZ), f, prime, ZZ)
        if len(split) < 2:
            return []
        factors = _gf.gf_edf_zassenhaus(split, 1, prime, ZZ)
        return sorted(int(-factor[1]) % prime for factor in factors)


def entries(matrix):
    """The entries of a SymPy matrix as a flat list, row by row."""
    return _SymPy.flat_entries(matrix)


def _exact_numbers(e):
    """Floats become the exact rationals they stand for, so exact arithmetic applies."""
    return (
        e.xreplace({f: sp.Rational(f) for f in e.atoms(sp.Float)})
        if e.has(sp.Float)
        else e
    )


def _is_root(e):
    """True for a numeric root such as sqrt(3) = 3**(1/2)."""
    return (
        e.is_Pow and e.base.is_Rational and e.exp.is_Rational and not e.exp.is_Integer
    )


def _is_algebraic(e):
    """True if ``e`` is built from rationals, I and algebraic atoms by +, *, integer
    powers."""
    if e.is_Rational or e is sp.I or _is_algebraic_atom(e):
        return True
    if e.is_Add or e.is_Mul or e.is_Pow and e.exp.is_Integer:
        return all(_is_algebraic(a) for a in e.args)
    return False


def _is_algebraic_atom(e):
    """A root of an algebraic number (sqrt(3), sqrt(2 + sqrt(2)), 2**(1/3)) or a
    polynomial's root given as CRootOf / AlgebraicNumber."""
    if isinstance(e, (sp.CRootOf, sp.AlgebraicNumber)):
        return True
    return bool(
        e.is_Pow
        and e.exp.is_Rational
        and not e.exp.is_Integer
        and _is_algebraic(e.base)
    )


def _scan(e, found, seen):
    """Collect, in one walk of the tree, the generators of ``e``: trig atoms, algebraic
    atoms, and the symbols outside them; other functions go to found['other'], Floats
    set found['float']."""
    if e in seen:
        return
    seen.add(e)
    if isinstance(e, _TRIG):
        found["trig"].add(e)
    elif e.is_Symbol:
        found["symbols"].add(e)
    elif e.is_Float:
        found["float"] = True
    elif (
        e in _TRANSCENDENTAL
    ):  # pi and E: generators like symbols (no algebraic relation)
        found["symbols"].add(e)
    elif e is sp.I or _is_algebraic_atom(e):
        found["roots"].add(e)
    elif e.is_Pow and not e.exp.is_Integer:  # a root of a symbol, of pi, of sin(x), ...
        found["other"].add(e)
    else:
        if isinstance(e, sp.Function):
            found["other"].add(e)
        for a in e.args:
            _scan(a, found, seen)


class Field:
    """The field QQ(generators) that holds every entry of one problem, and its sample
    points.

    The generators are the symbols, the sin/cos/tan atoms and the algebraic atoms
    themselves (SymPy's polynomial rings accept sin(theta) as a generator), so no
    substitution is needed; the relations among them (sin(2a) = 2 sin(a) cos(a), sqrt(2
    + sqrt(2)) sqrt(2 - sqrt(2)) = sqrt(2), cos(pi/7) a root of 8x^3 - 4x^2 - 4x + 1,
    ...) are kept by the sample points (:func:`_sample_points`).
    """

    def __init__(self, exprs):
        exprs = [sp.sympify(e) for e in exprs]
        found = self._generators(exprs)
        self._floats = found["float"]
        if self._floats:  # sin(0.5) becomes sin(1/2): read the generators again
            exprs = [_exact_numbers(e) for e in exprs]
            found = self._generators(exprs)
        self.expand = any(not a.args[0].is_Symbol for a in found["trig"])
        if self.expand:  # sin(a + b) and the like: write in sin/cos of single symbols
            exprs = [sp.expand_trig(e) for e in exprs]
            found = self._generators(exprs)
        if found["other"]:
            raise TypeError(
                "screw coordinates may hold numbers, symbols, pi, algebraic numbers "
                "(roots of rational numbers, nested roots, CRootOf) and sin, cos, tan "
                f"of expressions, got {sorted(map(str, found['other']))}"
            )
        self.symbols = sorted(
            found["trig"] | found["roots"] | found["symbols"], key=sp.default_sort_key
        )
        # the minors are computed with integer coefficients (see _polynomial_rows)
        self.K, self.integer_ring = _domains(tuple(self.symbols))
        self._cache = {}
        self._polynomials = {}
        self._generator_index = {g: k for k, g in enumerate(self.symbols)}
        self.prime, self._points = _sample_points(tuple(self.symbols))
        self.GF = GF(self.prime)

    @staticmethod
    def _generators(exprs):
        found = {
            "trig": set(),
            "roots": set(),
            "symbols": set(),
            "other": set(),
            "float": False,
        }
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
            # most screw coordinates are polynomials: build their terms directly, no
            # cancelling
            terms = self._terms(plain)
            if terms is None:
                value = self.K.from_sympy(plain)
            elif self.symbols:
                value = _SymPy.field_polynomial(self.K, terms)
            else:
                value = terms.get((), QQ.zero)
            self._cache[e] = value
        return value

    def _terms(self, e):
        """``e`` as a polynomial in the generators, {exponents: QQ coefficient}, or None
        if it is not one. Subexpressions are memoised: the joint screws of one mechanism
        share many products such as a*sin(theta)*cos(alpha)."""
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
        return DomainMatrix(
            [[self.element(e) for e in r] for r in rows],
            (len(rows), len(rows[0])),
            self.K,
        )

    def to_sympy(self, element):
        if not self.symbols:
            return self.K.to_sympy(element)
        numerator, denominator = element.numer, element.denom
        if (
            numerator.is_ground and denominator.is_ground
        ):  # a number: no printing, no factoring
            a, b = numerator.LC, denominator.LC
            return sp.Rational(
                int(a.numerator) * int(b.denominator),
                int(a.denominator) * int(b.numerator),
            )
        return sp.factor(self.K.to_sympy(element))

    def independent_rows(self, M):
        """Indices of a largest set of rows of M that are independent for generic
        values."""
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


# ---- sample points: the generators' values modulo a prime, every relation kept -------
#
# A sample point is a ring homomorphism from the ring the entries generate onto
# GF(prime): a minor that vanishes there vanishes on the real configuration only if it
# is zero (with a probability of error below 1e-15 for each transcendental generator,
# Schwartz-Zippel).
#
# * Angles. The argument of every sin/cos/tan is split into units over QQ: pi, 1 (a
#   radian), square roots of integers, and symbolic terms (theta, pi*theta,
#   sqrt(2)*theta). Each unit u gets one base angle u/L (L the lcm of its coefficients'
#   denominators), so sin(2/3) and cos(1/3), or cos(2 pi/7) and cos(pi/7), are the sin
#   and cos of multiples of one angle. The base of pi is exp(i pi/L) = z**(N/2L) for a
#   primitive N-th root of unity z modulo a prime = 1 (mod N), N = lcm(2L, 4); the other
#   bases are generic points ((1 - t^2)/(1 + t^2), 2t/(1 + t^2)) of the circle: e^{iu}
#   for algebraic u linearly independent over QQ are algebraically independent
#   (Lindemann-Weierstrass), and so are e^{iu} for symbolic u (as functions; Ax).
# * Algebraic atoms. Square roots of rationals (and I) get square roots of their prime
#   factors modulo the prime, chosen once each (Kummer: sqrt(6) = sqrt(2) sqrt(3)). Any
#   other algebraic atom (nested roots such as sin(pi/5) = sqrt(5/8 - sqrt(5)/8), cube
#   roots, CRootOf) puts all of them in one number field Q(theta) (a primitive element),
#   evaluated at a root of theta's minimal polynomial modulo the prime.
# * The two together. Q(algebraic atoms) = F and Q(z) meet only in a field unramified
#   outside the primes S ramified in both (Minkowski); it lies in Q(zeta_M), M the
#   S-part of N, and in its real subfield when F is real. When that is QQ the two
#   choices are independent; otherwise zeta_M (2 cos(2 pi/M) for a real F) joins F, and
#   z is taken among its conjugates so that both agree on it.


def _primes(n):
    return set(sp.factorint(abs(int(n)))) - {1, -1} if n else set()


def _angle_units(arg):
    """The argument of a trig atom as {unit: rational coefficient}."""
    units = {}
    for term in sp.Add.make_args(sp.expand(arg)):
        coefficient, unit = term.as_coeff_Mul()
        if not coefficient.is_Rational:
            raise TypeError(
                f"cannot read the angle {arg} exactly: its term {term} has the "
                f"coefficient {coefficient}"
            )
        units[unit] = units.get(unit, 0) + coefficient
    return {u: c for u, c in units.items() if c}


def _unit_kind(unit, arg):
    if unit.free_symbols:
        return "symbolic"
    if unit is sp.pi:
        return "pi"
    if (
        unit == 1
        or unit.is_Pow
        and unit.base.is_Integer
        and unit.base > 0
        and unit.exp == sp.S.Half
    ):
        return "radian"  # 1, sqrt(n): exponentials independent (Lindemann-Weierstrass)
    raise TypeError(
        f"cannot decide exactly how sin/cos of {arg} relate to the other entries: an "
        "angle may be a rational multiple of pi, a rational number (of radians) or a "
        "rational multiple of a square root of an integer, plus symbolic terms; got "
        f"the term {unit}"
    )


def _ramified(atom, kummer):
    """A set of primes holding every prime ramified in Q(atom)."""
    if atom is sp.I:
        return {2}
    if kummer:
        return {2} | _primes(atom.base.p) | _primes(atom.base.q)
    x = sp.Dummy("x")
    m = sp.Poly(sp.minimal_polynomial(atom, x), x)
    return _primes(sp.discriminant(m)) | _primes(m.LC())


def _primitive_root_of_unity(order, prime, rng):
    """A primitive root of unity of the given order modulo the prime (order | prime -
    1)."""
    factors = _primes(order)
    while True:
        z = pow(rng.randrange(2, prime - 1), (prime - 1) // order, prime)
        if all(pow(z, order // q, prime) != 1 for q in factors):
            return z


def _turn(c, s, n, prime):
    """(cos, sin) of n times the angle whose (cos, sin) is (c, s), modulo the prime."""
    if n < 0:
        s, n = -s % prime, -n
    rc, rs = 1, 0
    while n:
        if n & 1:
            rc, rs = (rc * c - rs * s) % prime, (rc * s + rs * c) % prime
        c, s = (c * c - s * s) % prime, 2 * c * s % prime
        n >>= 1
    return rc, rs


def _evaluate_rep(rep, root, prime):
    """A polynomial with rational coefficients (highest first) at ``root`` modulo the
    prime."""
    value = 0
    for c in rep:
        value = (value * root + int(c.p) * pow(int(c.q), -1, prime)) % prime
    return value


class _Plan:
    """What the sample points need: the angle units, the algebraic atoms and how they
    meet."""

    def __init__(self, generators):
        trig = [g for g in generators if isinstance(g, _TRIG)]
        self.atoms = [g for g in generators if g is sp.I or _is_algebraic_atom(g)]
        values = [g for g in generators if g in _TRANSCENDENTAL]
        self.angles = {g: _angle_units(g.args[0]) for g in trig}
        kinds = {}
        for g, units in self.angles.items():
            for u in units:
                kinds[u] = _unit_kind(u, g.args[0])
        self.units = sorted(kinds, key=sp.default_sort_key)
        self.kinds = kinds
        self.base = {
            u: math.lcm(
                *(int(units[u].q) for units in self.angles.values() if u in units)
            )
            for u in self.units
        }
        if sp.pi in values and (sp.E in values or "radian" in kinds.values()):
            raise TypeError(
                "cannot decide exactly: whether pi is algebraically independent of e "
                "or of sin/cos of a rational number of radians is not known "
                "(Schanuel's conjecture); write pi, e or the angle as a symbol"
            )
        self.order = math.lcm(2 * self.base[sp.pi], 4) if sp.pi in kinds else 1
        self.kummer = all(a is sp.I or _is_root(a) and a.exp.q == 2 for a in self.atoms)
        self.meet = None  # (M, real) when the atoms' field and Q(z) share more than QQ
        if self.atoms and self.order > 1 and not self.kummer:  # roots: _cyclotomic_sqrt
            ramified = set().union(*(_ramified(a, self.kummer) for a in self.atoms))
            shared = ramified & _primes(self.order)
            M = math.prod(p ** sp.multiplicity(p, self.order) for p in shared)
            real = all(a.is_extended_real for a in self.atoms)
            if M > 1 and not (real and M in (3, 4, 6)):
                self.meet = (M, real)
        self.fields = []  # (atoms, minimal polynomial, representations) for each group
        if self.atoms and not self.kummer:
            if self.meet:
                M, real = self.meet
                eta = (
                    2 * sp.cos(2 * sp.pi / M) if real else sp.exp(2 * sp.pi * sp.I / M)
                )
                groups = [list(self.atoms) + [eta]]
            else:
                groups = _coprime_groups(self.atoms)
            self.fields = [(group, *_SymPy.number_field(group)) for group in groups]

    def prime(self):
        """The largest prime below 2^61 that is 1 modulo the order of z and gives the
        atoms their values."""
        step = self.order
        candidate = (_PRIME - 1) // step * step + 1 if step > 1 else _PRIME
        while True:
            if candidate < 2**40:
                raise ArithmeticError(
                    "no prime below 2^61 serves these algebraic numbers"
                )
            if (candidate == _PRIME or sp.isprime(candidate)) and self._serves(
                candidate
            ):
                return candidate
            candidate = candidate - step if step > 1 else int(sp.prevprime(candidate))

    def _serves(self, prime):
        self.field_roots = []
        if self.kummer and self.atoms:
            self.kummer_primes = sorted(
                {
                    p
                    for a in self.atoms
                    if a is not sp.I
                    for n in (a.base.p, a.base.q)
                    for p in _primes(n)
                }
                | ({-1} if any(a is sp.I or a.base < 0 for a in self.atoms) else set())
            )
            self.kummer_roots = {
                p: _sqrt_mod(p % prime, prime) for p in self.kummer_primes
            }
            return all(v is not None for v in self.kummer_roots.values())
        for _, minpoly, reps in self.fields:
            if minpoly[0] % prime == 0 or any(
                c.q % prime == 0 for rep in reps for c in rep
            ):
                return False
            roots = _SymPy.roots_mod(minpoly, prime)
            if not roots:
                return False
            self.field_roots.append(roots)
        return True


def _degree(atom):
    if atom is sp.I or _is_root(atom) and atom.exp.q == 2:
        return 2
    return sp.degree(sp.minimal_polynomial(atom, sp.Dummy("x")))


def _coprime_groups(atoms):
    """The atoms in groups whose fields have pairwise coprime degrees, so that the
    fields are linearly disjoint and each can be evaluated on its own: atoms join a
    group when their degrees share a factor (the degree of a group's field divides the
    product of its atoms')."""
    groups = []  # [atoms, product of their degrees]
    for atom in atoms:
        d = _degree(atom)
        joined = [g for g in groups if math.gcd(g[1], d) > 1]
        merged = [atom] + [a for g in joined for a in g[0]]
        groups = [g for g in groups if g not in joined]
        groups.append([merged, d * math.prod(g[1] for g in joined)])
    return [g[0] for g in groups]


@functools.lru_cache(maxsize=64)
def _sample_points(generators):
    """A prime, and exact random values of the generators modulo it that keep every
    relation among them (see the comment above)."""
    rng = random.Random(_SEED)
    plan = _Plan(generators)
    prime = plan.prime()
    points = []
    for k in range(_SAMPLE_POINTS):
        value = {}
        z = _primitive_root_of_unity(plan.order, prime, rng) if plan.order > 1 else None
        if plan.kummer and plan.atoms:
            roots = dict(plan.kummer_roots)
            if z is not None:  # the square roots that Q(zeta_N) holds: Gauss sums in z
                for p in roots:
                    root = _cyclotomic_sqrt(p, z, plan.order, prime)
                    roots[p] = roots[p] if root is None else root
            for a in plan.atoms:
                radicand = sp.Integer(-1) if a is sp.I else a.base
                root = _root_of_rational(radicand, roots, prime)
                value[a] = root if a is sp.I else pow(root, int(a.exp.p), prime)
        eta = None
        for (group, _, reps), roots in zip(plan.fields, plan.field_roots):
            theta = roots[k % len(roots)]
            for a, rep in zip(group, reps):
                value[a] = _evaluate_rep(rep, theta, prime)
            eta = _evaluate_rep(reps[-1], theta, prime)
        bases = {}
        for u in plan.units:
            if plan.kinds[u] == "pi":
                if plan.meet:
                    z = _agree(z, plan, eta, prime)  # the one group ends with zeta_M
                w = pow(z, plan.order // (2 * plan.base[u]), prime)
                i = pow(z, plan.order // 4, prime)
                w_inverse = pow(w, -1, prime)
                bases[u] = (
                    (w + w_inverse) * pow(2, -1, prime) % prime,
                    (w - w_inverse) * pow(2 * i, -1, prime) % prime,
                )
            else:
                while True:
                    t = rng.randrange(2, prime - 1)
                    if (1 + t * t) % prime:
                        break
                inverse = pow(1 + t * t, -1, prime)
                bases[u] = ((1 - t * t) * inverse % prime, 2 * t * inverse % prime)
        for g, units in plan.angles.items():
            c, s = 1, 0
            for u, coefficient in units.items():
                cu, su = _turn(*bases[u], int(coefficient * plan.base[u]), prime)
                c, s = (c * cu - s * su) % prime, (c * su + s * cu) % prime
            if isinstance(g, sp.tan):
                if c == 0:
                    raise ArithmeticError(f"{g} has no value at a sample point")
                value[g] = s * pow(c, -1, prime) % prime
            else:
                value[g] = s if isinstance(g, sp.sin) else c
        points.append(
            [value[g] if g in value else rng.randrange(1, prime) for g in generators]
        )
    return prime, points


def _cyclotomic_sqrt(p, z, N, prime):
    """The value of sqrt(p) (p a prime or -1) in Q(zeta_N) at zeta_N -> z, or None when
    Q(zeta_N) does not hold it (then its square root is independent of z: Kummer).

    sqrt(-1) = zeta_4, sqrt(2) = zeta_8 + 1/zeta_8, and for an odd prime the Gauss sum
    g = sum (a/p) zeta_p^a is sqrt(p) (p = 1 mod 4) or i sqrt(p) (p = 3 mod 4).
    """
    i = pow(z, N // 4, prime)
    if p == -1:
        return i
    if p == 2:
        if N % 8:
            return None
        w = pow(z, N // 8, prime)
        return (w + pow(w, -1, prime)) % prime
    if N % p:
        return None
    zeta = pow(z, N // p, prime)
    g, power = 0, 1
    for a in range(1, p):
        power = power * zeta % prime
        g += power if pow(a, (p - 1) // 2, p) == 1 else -power
    g %= prime
    return g if p % 4 == 1 else -i * g % prime


def _agree(z, plan, target, prime):
    """The conjugate z**k of the root of unity z that gives zeta_M (or 2 cos(2 pi/M))
    the value ``target`` it has in the atoms' field."""
    M, real = plan.meet
    N = plan.order
    w = pow(z, N // M, prime)
    for j in range(1, M):
        if math.gcd(j, M) != 1:
            continue
        wj = pow(w, j, prime)
        if (wj + pow(wj, -1, prime)) % prime == target if real else wj == target:
            k = int(crt([M, N // M], [j, 1])[0]) if N > M else j
            return pow(z, k, prime)
    raise ArithmeticError(
        "the root of unity and the algebraic numbers do not agree at any conjugate"
    )


def _root_of_rational(q, prime_roots, prime):
    """sqrt(q) modulo the prime for a rational q, from the chosen roots of its prime
    factors."""
    value = prime_roots[-1] if q < 0 else 1
    for n, sign in ((abs(q.p), 1), (q.q, -1)):
        for p, k in sp.factorint(n).items():
            part = pow(p, k // 2, prime) * (prime_roots[p] if k % 2 else 1)
            value = value * pow(part, sign, prime) % prime
    return value


@functools.lru_cache(maxsize=256)
def _sqrt_mod(a, prime):
    """A square root of a modulo the prime, or None (the same few roots, such as
    sqrt(3), recur)."""
    return sqrt_mod(a, prime, all_roots=False)


def _domains(symbols):
    """QQ(symbols) and ZZ[symbols], built once per set of generators (SymPy rebuilds
    them)."""
    if not symbols:
        return QQ, None
    if symbols not in _DOMAINS:
        _DOMAINS[symbols] = _SymPy.fraction_field(symbols)
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
    """The rank, for generic values of the symbols, of a matrix given as rows of SymPy
    expressions."""
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
    """The chosen rows of M, each multiplied by a nonzero factor that clears its
    denominators: rows of polynomials with integer coefficients (over QQ when there are
    no symbols).

    Scaling a row changes neither its null space nor its row space, nor the ratios of
    minors that Cramer's rule takes; integer coefficients make the minors plain ``int``
    arithmetic.
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
                denominator = (
                    e.denom if denominator is None else denominator.lcm(e.denom)
                )
        if denominator is None:
            cleared = [
                e.numer.quo_ground(e.denom.LC) if e and e.denom != 1 else e.numer
                for e in row
            ]
        else:
            cleared = [
                e.numer * denominator.exquo(e.denom) if e else e.numer for e in row
            ]
        scale = 1
        for p in cleared:
            for c in p.values():
                scale = math.lcm(scale, int(c.denominator))
        polynomial.append(
            [
                _SymPy.ring_polynomial(
                    integer_ring,
                    {
                        m: int(c.numerator) * (scale // int(c.denominator))
                        for m, c in p.items()
                    },
                )
                for p in cleared
            ]
        )
    return polynomial


def _determinants(rows, zero, one):
    """det of the square submatrix of ``rows`` on an ordered list of columns, memoised.

    Laplace expansion along the rows in turn, skipping zero entries: the matrices of
    joint screws are sparse, and the minors that the columns share are computed once. No
    division happens, so the entries may be polynomials.
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
                    minor = sorted_det(
                        depth + 1, cols[:position] + cols[position + 1 :]
                    )
                    if minor:
                        term = rows[depth][c] * minor
                        total = total + term if position % 2 == 0 else total - term
            memo[key] = total
        return memo[key]

    def det(cols):
        if len(set(cols)) < len(cols):
            return zero
        order = sorted(range(len(cols)), key=lambda k: cols[k])
        inversions = sum(
            1
            for a in range(len(order))
            for b in range(a + 1, len(order))
            if order[a] > order[b]
        )
        value = sorted_det(0, tuple(sorted(cols)))
        return -value if inversions % 2 else value

    return det


def _pivot_columns(field, rows, columns):
    """The pivot columns (taken in the order ``columns``) of independent rows, for
    generic values."""
    if field.symbols:
        for values in field._points:
            numbers = [
                [
                    field.GF(_evaluate_polynomial(row[j], values, field.prime))
                    if row[j]
                    else field.GF.zero
                    for j in columns
                ]
                for row in rows
            ]
            pivots = DomainMatrix(numbers, (len(rows), len(columns)), field.GF).rref()[
                1
            ]
            if len(pivots) == len(rows):
                return [columns[k] for k in pivots]
        raise ArithmeticError(
            "no sample point gives the generic rank: the sample points are not generic"
        )
    M = DomainMatrix(
        [[row[j] for j in columns] for row in rows], (len(rows), len(columns)), QQ
    )
    return [columns[k] for k in M.rref()[1]]


def _solve_by_minors(field, rows, pivots, others):
    """Cramer's rule on A = rows with det(A_pivots) != 0: for each column j in
    ``others``, the solution x of A_pivots x = A_j, as {pivot: K element}, each x_k =
    det(A_pivots, column k replaced by column j) / det(A_pivots)."""
    K = field.K
    if not field.symbols:
        det = _determinants(rows, K.zero, K.one)
        denominator = det(pivots)
        return [
            {
                p: K.quo(det(pivots[:k] + [j] + pivots[k + 1 :]), denominator)
                for k, p in enumerate(pivots)
            }
            for j in others
        ]
    ring = field.integer_ring
    det = _determinants(rows, ring.zero, ring.one)
    denominator = det(pivots)
    solutions = []
    for j in others:
        x = {}
        for k, p in enumerate(pivots):
            value = det(pivots[:k] + [j] + pivots[k + 1 :])
            x[p] = _fraction(K, *_cancel(value, denominator)) if value else K.zero
        solutions.append(x)
    return solutions


def _cancel(numerator, denominator):
    """numerator / denominator in lowest terms, the denominator's leading coefficient
    positive. Most ratios of minors here are polynomials (often numbers): an exact
    division is tried before the gcd."""
    quotient, remainder = numerator.div(denominator)
    if not remainder:
        return quotient, quotient.ring.one
    return numerator.cancel(denominator)


def _fraction(K, numerator, denominator):
    """The element numerator / denominator of K from coprime integer polynomials."""
    return _SymPy.field_fraction(K, numerator, denominator)


def reduced_basis(field, M, rows=None):
    """A canonical basis of the row space of M (DomainMatrix over ``field``), as a
    DomainMatrix.

    ``rows``: indices of generically independent rows (found if not given). Reduced from
    the right: each row has a 1 at its last nonzero coordinate and zeros in the other
    rows there, so couples and forces read like (0, 0, 0, 0, 0, 1). That is B = A_P^-1 A
    for the pivot columns P found from the right; its entries are ratios of minors of A
    (Cramer's rule), computed without fractions until the one division each.
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


def pivot_columns(field, M, rows):
    """The pivot columns (from the left) of the independent ``rows`` of M, for generic
    values: M[rows, pivots] is a nonzero minor."""
    if not rows:
        return []
    return _pivot_columns(
        field, _polynomial_rows(field, M, rows), list(range(M.shape[1]))
    )


def null_space(field, M, rows=None):
    """A canonical basis of {x : M x = 0} for generic values, as DomainMatrix rows.

    With the pivot columns P of M (from the left) and the free columns F, basis vector f
    has x_f = 1, zeros at the other free columns and x_P = -A_P^-1 A_f (Cramer's rule):
    its last nonzero coordinate is that 1, so the basis is already reduced from the
    right.
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
        basis.append(
            [
                K.one if j == f else K.zero if j in free else K.neg(x[j])
                for j in range(cols)
            ]
        )
    return DomainMatrix(basis, (len(basis), cols), K)
