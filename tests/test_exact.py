"""screwkit._exact: exact generic ranks and bases over the field the entries generate.

References are independent of the code under test: a 60-digit mpmath SVD
(``reference_rank``) on generated matrices whose entries are related by trigonometric
and algebraic identities, and SymPy's own ``Matrix.rank`` and ``nullspace`` on small
systems.
"""

import random

import pytest
import reference_rank
import sympy as sp
from sympy import QQ, ZZ
from sympy.simplify.fu import TR8

from screwkit import _exact

x, y, theta, phi = sp.symbols("x y theta phi")


def exact_rank(rows):
    return _exact.generic_rank([list(r) for r in rows])


# ---- the adapter: each SymPy internal the module relies on ---------------------------


def test_adapter_flat_entries_reads_every_entry_row_by_row():
    M = sp.Matrix([[sp.sin(x), 2], [sp.sqrt(3), x * y]])
    assert _exact._SymPy.flat_entries(M) == [sp.sin(x), 2, sp.sqrt(3), x * y]
    assert _exact._SymPy.flat_entries(sp.Matrix([[1, 2], [3, 4]])) == [1, 2, 3, 4]


def test_adapter_builds_field_elements_without_cancelling():
    K, ring = _exact._SymPy.fraction_field((x, y))
    assert K == QQ.frac_field(x, y) and ring.domain == ZZ
    element = _exact._SymPy.field_polynomial(K, {(1, 0): QQ(1, 2), (0, 2): QQ(3)})
    assert K.to_sympy(element) == x / 2 + 3 * y**2
    numerator = _exact._SymPy.ring_polynomial(ring, {(1, 0): 2, (0, 0): 1})
    denominator = _exact._SymPy.ring_polynomial(ring, {(0, 1): 3})
    fraction = _exact._SymPy.field_fraction(K, numerator, denominator)
    assert sp.simplify(K.to_sympy(fraction) - (2 * x + 1) / (3 * y)) == 0


def test_adapter_number_field_represents_each_atom_in_its_primitive_element():
    atoms = [sp.sqrt(2), sp.sqrt(2 + sp.sqrt(2))]
    minpoly, reps = _exact._SymPy.number_field(atoms)
    assert all(isinstance(c, int) for c in minpoly) and len(minpoly) == 5  # degree 4
    t = sp.Dummy("t")
    m = sp.Poly(minpoly, t)
    roots = [r for r in sp.Poly(m, t).nroots(n=40)]
    for root in roots:  # at one of the roots, every representation gives its atom
        values = [sp.Poly(rep, t).eval(root) for rep in reps]
        if all(abs(v - sp.N(a, 40)) < 1e-30 for v, a in zip(values, atoms)):
            break
    else:
        pytest.fail("no root of the minimal polynomial gives the atoms")


def test_adapter_roots_mod_finds_every_root_and_none_when_there_is_none():
    p = 1_000_003
    assert _exact._SymPy.roots_mod([1, 0, -4], p) == sorted([2, p - 2])
    assert _exact._SymPy.roots_mod([1, -6, 11, -6], p) == [1, 2, 3]
    non_residue = next(a for a in range(2, 100) if pow(a, (p - 1) // 2, p) == p - 1)
    assert _exact._SymPy.roots_mod([1, 0, -non_residue], p) == []


# ---- generated cases against a 60-digit rank -----------------------------------------

ANGLES = [
    sp.Rational(1, 3),
    sp.Rational(2, 5),
    sp.Rational(-3, 7),
    sp.Rational(5, 4),
    sp.pi / 7,
    2 * sp.pi / 9,
    sp.pi / 11,
    3 * sp.pi / 16,
    sp.pi / 13,
    sp.Rational(1, 5) + sp.pi / 7,
    sp.sqrt(2) / 3,
]


def _trig_case(rng, angles=ANGLES):
    """Rows that are integer combinations of k basis rows of polynomials in sin and cos
    of two angles, each entry then written with multiple angles (TR8: cos(a)^2 ->
    cos(2a)/2 + 1/2, cos(a) cos(b) -> cos(a + b)/2 + cos(a - b)/2): related atoms."""
    a, b = rng.choice(angles), rng.choice(angles)
    monomials = [sp.Integer(1), sp.cos(a), sp.sin(a), sp.cos(b), sp.sin(b)]
    monomials += [u * v for i, u in enumerate(monomials[1:], 1) for v in monomials[i:]]
    k, m = rng.randint(1, 5), rng.randint(2, 7)
    basis = [
        [
            sum(rng.randint(-2, 2) * rng.choice(monomials) for _ in range(2))
            for _ in range(6)
        ]
        for _ in range(k)
    ]
    rows = []
    for _ in range(m):
        weights = [rng.randint(-2, 2) for _ in range(k)]
        row = [
            sp.expand(sum(w * basis[j][c] for j, w in enumerate(weights)))
            for c in range(6)
        ]
        rows.append([TR8(e) if rng.random() < 0.6 else e for e in row])
    return rows


def test_related_angles_agree_with_a_60_digit_rank():
    rng = random.Random(7)
    seen, deficient = 0, 0
    for _ in range(240):
        rows = _trig_case(rng)
        expected = reference_rank.rank(rows)
        assert exact_rank(rows) == expected, rows
        seen += 1
        deficient += expected < min(len(rows), 6)
    assert seen == 240 and deficient > 80  # singular cases are well represented


RADICALS = [
    sp.sqrt(2),
    sp.sqrt(5),
    sp.sqrt(2 + sp.sqrt(2)),
    sp.sqrt(2 - sp.sqrt(2)),
    sp.sqrt(5 - sp.sqrt(5)),
    sp.cos(sp.pi / 8),
    sp.sin(sp.pi / 5),
    sp.cbrt(2),
]


def _radical_case(rng):
    """Rows that are algebraic combinations of others, expanded, where the weights and
    the entries are nested roots (products such as sqrt(2 + sqrt 2) sqrt(2 - sqrt 2) =
    sqrt 2 stay unsimplified)."""
    pool = rng.sample(RADICALS, 3)
    k, m = rng.randint(1, 4), rng.randint(2, 6)
    basis = [
        [rng.randint(-3, 3) + rng.randint(-2, 2) * rng.choice(pool) for _ in range(6)]
        for _ in range(k)
    ]
    rows = []
    for _ in range(m):
        weights = [
            rng.randint(-2, 2) + rng.randint(-1, 1) * rng.choice(pool) for _ in range(k)
        ]
        rows.append(
            [
                sp.expand(sum(w * basis[j][c] for j, w in enumerate(weights)))
                for c in range(6)
            ]
        )
    return rows


def test_nested_radicals_agree_with_a_60_digit_rank():
    rng = random.Random(11)
    deficient = 0
    for _ in range(80):
        rows = _radical_case(rng)
        expected = reference_rank.rank(rows)
        assert exact_rank(rows) == expected, rows
        deficient += expected < min(len(rows), 6)
    assert deficient > 20


def test_symbolic_systems_agree_with_the_rank_at_random_values():
    rng = random.Random(3)
    for _ in range(60):
        angles = [
            theta,
            2 * theta,
            theta + phi,
            theta - sp.pi / 7,
            theta / 3,
            sp.pi / 7,
        ]
        rows = _trig_case(rng, angles)
        expected = reference_rank.rank(reference_rank.substitute(rows, rng))
        assert exact_rank(rows) == expected


def test_the_issue_cases_multiple_angles_and_sums():
    for a in (sp.Rational(1, 3), sp.pi / 7, theta):
        assert (
            exact_rank(
                [
                    [sp.cos(2 * a), 1, 0, 0, 0, 0],
                    [2 * sp.cos(a) ** 2 - 1, 1, 0, 0, 0, 0],
                ]
            )
            == 1
        )
        assert (
            exact_rank(
                [
                    [sp.sin(2 * a), 1, 0, 0, 0, 0],
                    [2 * sp.sin(a) * sp.cos(a), 1, 0, 0, 0, 0],
                ]
            )
            == 1
        )
    for a, b in (
        (sp.Rational(1, 3), sp.Rational(1, 5)),
        (sp.pi / 7, sp.Rational(2, 3)),
        (theta, phi),
    ):
        expanded = sp.cos(a) * sp.cos(b) - sp.sin(a) * sp.sin(b)
        assert (
            exact_rank([[sp.cos(a + b), 1, 0, 0, 0, 0], [expanded, 1, 0, 0, 0, 0]]) == 1
        )
    # pi/7, 2 pi/7 and 3 pi/7 share one base angle: cos(3t) = 4 cos(t)^3 - 3 cos(t)
    t = sp.pi / 7
    assert (
        exact_rank([[sp.cos(3 * t), 1], [4 * sp.cos(t) ** 3 - 3 * sp.cos(t), 1]]) == 1
    )
    # sin(pi/7) sin(2 pi/7) sin(3 pi/7) = sqrt(7)/8: a root of unity meets a square root
    product = sp.sin(t) * sp.sin(2 * t) * sp.sin(3 * t)
    assert exact_rank([[product, 1], [sp.sqrt(7) / 8, 1]]) == 1
    assert exact_rank([[product, 1], [sp.sqrt(7) / 9, 1]]) == 2


def test_what_cannot_be_decided_is_refused_with_the_reason():
    with pytest.raises(TypeError, match="Schanuel"):
        exact_rank([[sp.pi, sp.sin(sp.Rational(1, 3))]])
    with pytest.raises(TypeError, match="cannot decide exactly how sin/cos of E"):
        exact_rank([[sp.sin(sp.E), 1]])
    with pytest.raises(TypeError, match="algebraic numbers"):
        exact_rank([[sp.sqrt(x), 1]])


# ---- against SymPy's own rank and null space on small systems ------------------------


def _small(rng, radicals):
    pool = [sp.Integer(1)] + ([sp.sqrt(2), sp.sqrt(3), sp.sqrt(6)] if radicals else [])
    r, c = rng.randint(1, 4), rng.randint(2, 5)
    rows = [[rng.randint(-3, 3) * rng.choice(pool) for _ in range(c)] for _ in range(r)]
    if r > 1 and rng.random() < 0.5:  # a dependent row
        rows[-1] = [
            sp.expand(rows[0][j] * rng.choice(pool) - rows[1 % r][j]) for j in range(c)
        ]
    return rows


@pytest.mark.parametrize("radicals", [False, True])
def test_rank_and_null_space_agree_with_sympy(radicals):
    rng = random.Random(5 + radicals)
    for _ in range(60):
        rows = _small(rng, radicals)
        M = sp.Matrix(rows)
        field = _exact.Field([e for row in rows for e in row])
        D = field.matrix(rows)
        assert field.rank(D) == M.rank(simplify=True)
        N = [
            sp.Matrix([field.to_sympy(e) for e in row])
            for row in _exact.null_space(field, D).to_list()
        ]
        expected = M.nullspace(simplify=True)
        assert len(N) == len(expected)
        for v in N:
            assert (M * v).applyfunc(lambda e: sp.expand(sp.radsimp(e))) == sp.zeros(
                M.rows, 1
            )
        if N:  # the same space: stacking both bases adds nothing
            assert sp.Matrix.hstack(*N, *expected).rank(simplify=True) == len(N)


CYCLOTOMIC = [
    sp.I,
    sp.sqrt(2),
    sp.sqrt(7),
    sp.sqrt(3),
    sp.cos(sp.pi / 16),
    sp.sin(sp.pi / 7),
    sp.cos(sp.pi / 7),
    sp.sqrt(2 + sp.sqrt(2)),
    sp.cos(sp.pi / 12),
]


def test_square_roots_beside_multiples_of_pi_agree_with_a_60_digit_rank():
    # sqrt(7) and sqrt(-1) lie in Q(exp(i pi/7), i): their sample values must be the
    # Gauss sums of the root of unity that sin(pi/7) and cos(pi/7) come from
    t = sp.pi / 7
    product = sp.I * sp.sin(t) * sp.sin(2 * t) * sp.sin(3 * t)
    assert exact_rank([[product, 1], [sp.sqrt(-7) / 8, 1]]) == 1
    assert (
        exact_rank(
            [[sp.cos(sp.pi / 16) ** 2, 1], [(1 + sp.sqrt(2 + sp.sqrt(2)) / 2) / 2, 1]]
        )
        == 1
    )
    rng = random.Random(1)
    deficient = 0
    for _ in range(40):
        pool = rng.sample(CYCLOTOMIC, 3)
        row = [
            rng.randint(-2, 2) + rng.choice(pool) * rng.choice(pool) for _ in range(3)
        ]
        weight = rng.choice(pool) * rng.choice(pool) + rng.randint(-1, 1)
        rows = [row, [sp.expand(weight * e) for e in row], [rng.choice(pool), 1, 0]]
        expected = reference_rank.rank(rows)
        assert exact_rank(rows) == expected, rows
        deficient += expected < 3
    assert deficient > 10
