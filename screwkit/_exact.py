"""Exact linear algebra on symbolic screw coordinates, fast enough for mobility analysis.

Two ideas keep it exact and fast (the pyScrew4Mobility paper spends its time
simplifying trigonometric expressions inside ``Matrix.nullspace``):

* **Rank is decided generically and exactly.** Entries are evaluated at random
  rational points (sin and cos of each angle from the rational half-angle
  substitution t -> (2t/(1+t^2), (1-t^2)/(1+t^2)), so sin^2 + cos^2 = 1 holds) and
  the rank is computed in exact arithmetic over Q or Q(sqrt(3), ...). No
  floating-point round-off is involved; the seed is fixed, so runs are identical.
* **Bases are computed in a field of rational functions** whose generators are the
  symbols and the sin/cos/tan atoms, without trigonometric simplification, from a set
  of rows that is independent at the random points. Those rows have the generic rank in
  the field too, so no identity such as sin^2 + cos^2 = 1 is ever needed.
"""
import random

import sympy as sp
from sympy import QQ
from sympy.polys.matrices import DomainMatrix

_TRIG = (sp.sin, sp.cos, sp.tan)
_SAMPLE_POINTS = 2
_SEED = 20201


def _exact_numbers(e):
    """Floats become the exact rationals they stand for, so exact arithmetic applies."""
    return e.xreplace({f: sp.Rational(f) for f in e.atoms(sp.Float)}) if e.has(sp.Float) else e


def _square_roots(exprs):
    roots = set()
    for e in exprs:
        for p in e.atoms(sp.Pow):
            if p.base.is_Rational and p.exp.is_Rational and not p.exp.is_Integer:
                roots.add(p.base ** sp.Rational(1, p.exp.q))
    return sorted(roots, key=sp.default_sort_key)


class Field:
    """The field QQ<roots>(symbols, trig atoms) that holds every entry of one problem."""

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
        self.trig = sorted(trig, key=sp.default_sort_key)
        self.dummy = {a: sp.Dummy(f"g{k}") for k, a in enumerate(self.trig)}
        self.atom = {d: a for a, d in self.dummy.items()}
        symbols = set().union(*(e.xreplace(self.dummy).free_symbols for e in exprs)) if exprs else set()
        self.symbols = sorted(symbols, key=sp.default_sort_key)
        roots = _square_roots(exprs)
        self.ground = QQ.algebraic_field(*roots) if roots else QQ
        self.K = self.ground.frac_field(*self.symbols) if self.symbols else self.ground
        self._cache = {}
        self._points = self._sample_points()

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
        """Exact random values of the generators, with sin^2 + cos^2 = 1 for each angle."""
        rng = random.Random(_SEED)
        angles = {a.args[0] for a in self.trig}
        points = []
        for _ in range(_SAMPLE_POINTS):
            trig_values = {}
            for angle in sorted(angles, key=sp.default_sort_key):
                t = sp.Rational(rng.randint(1, 97), rng.randint(98, 211)) * rng.choice((1, -1))
                s, c = 2 * t / (1 + t**2), (1 - t**2) / (1 + t**2)
                trig_values.update({sp.sin(angle): s, sp.cos(angle): c, sp.tan(angle): s / c})
            values = []
            for g in self.symbols:
                if g in self.atom:
                    values.append(self.ground.from_sympy(trig_values[self.atom[g]]))
                else:
                    values.append(self.ground.from_sympy(sp.Rational(rng.randint(-500, 500), rng.randint(7, 101))))
            points.append(values)
        return points

    def independent_rows(self, M):
        """Indices of a largest set of rows of M that are independent for generic values.

        Found exactly at random rational points; using only these rows, the field never
        needs an identity such as sin^2 + cos^2 = 1 to see the true rank.
        """
        rows, cols = M.shape
        if rows == 0:
            return []
        if not self.symbols:
            return list(M.transpose().rref()[1])
        best = []
        entries = M.to_list()
        for values in self._points:
            numbers = [[self._evaluate(e, values) for e in row] for row in entries]
            pivots = DomainMatrix(numbers, (rows, cols), self.ground).transpose().rref()[1]
            if len(pivots) > len(best):
                best = list(pivots)
            if len(best) == min(rows, cols):
                break
        return best

    def rank(self, M):
        """The generic rank of a DomainMatrix over this field (exact, at random points)."""
        return len(self.independent_rows(M))

    def _evaluate(self, element, values):
        if not element:
            return self.ground.zero
        return self.ground.quo(element.numer(*values), element.denom(*values))


def reduced_basis(field, M, rows=None):
    """A canonical basis of the row space of M (DomainMatrix over ``field``), as a DomainMatrix.

    ``rows``: indices of generically independent rows (found if not given). Reduced from
    the right: each row has a 1 at its last nonzero coordinate and zeros in the other rows
    there, so couples and forces read like (0, 0, 0, 0, 0, 1).
    """
    cols = M.shape[1]
    rows = field.independent_rows(M) if rows is None else rows
    if not rows:
        return DomainMatrix.zeros((0, cols), field.K)
    if len(rows) == cols:  # the whole space: the identity is its reduced basis
        return DomainMatrix.eye(cols, field.K)
    flip = list(reversed(range(cols)))
    R, pivots = M.extract(rows, flip).rref()
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
    N = M.extract(rows, list(range(cols))).nullspace()
    return reduced_basis(field, N, list(range(N.shape[0])))
