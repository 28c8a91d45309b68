"""screwkit.systems.ScrewSystem: exact ranks, reciprocal systems and refusals, checked
against a 60-digit mpmath rank (``reference_rank``) and against hand derivations."""

import itertools
import random

import pytest
import reference_rank
import sympy as sp

import screwkit as sk
from screwkit import ScrewSystem, Twist

a, b = sp.symbols("a b", real=True)


def rows_of(system):
    return [list(s.vector) for s in system.screws]


def reciprocal_products_vanish(system):
    """Every screw of the reciprocal system has a zero reciprocal product with every
    screw of the system, to 50 digits."""
    for w in system.reciprocal().screws:
        for t in system.screws:
            product = sum(w.vector[k] * t.vector[(k + 3) % 6] for k in range(6))
            assert abs(sp.N(product, 60)) < 1e-50


@pytest.mark.parametrize("angle", [sp.Rational(1, 3), sp.pi / 7, a])
def test_cos_2a_and_its_chebyshev_form_are_one_screw(angle):
    system = ScrewSystem(
        [
            [sp.cos(2 * angle), 1, 0, 0, 0, 0],
            [2 * sp.cos(angle) ** 2 - 1, 1, 0, 0, 0, 0],
        ]
    )
    assert system.rank == 1
    assert system.reciprocal().rank == 5
    double = ScrewSystem(
        [
            [sp.sin(2 * angle), 0, 1, 0, 0, 0],
            [2 * sp.sin(angle) * sp.cos(angle), 0, 1, 0, 0, 0],
        ]
    )
    assert double.rank == 1


def test_a_sum_of_angles_and_its_expansion_are_one_screw():
    for p, q in (
        (sp.Rational(1, 3), sp.Rational(2, 5)),
        (sp.pi / 7, 2 * sp.pi / 7),
        (a, b),
    ):
        expanded = sp.sin(p) * sp.cos(q) + sp.cos(p) * sp.sin(q)
        assert (
            ScrewSystem(
                [[sp.sin(p + q), 0, 0, 1, 0, 0], [expanded, 0, 0, 1, 0, 0]]
            ).rank
            == 1
        )


PUMA_ANGLES = [
    0,
    sp.pi / 2,
    -sp.pi / 2,
    sp.pi / 7,
    2 * sp.pi / 7,
    -3 * sp.pi / 7,
    sp.Rational(1, 5),
    sp.Rational(2, 5),
    -sp.Rational(3, 5),
    sp.pi / 6,
    -sp.pi / 4,
]


def puma_configurations(rng, count):
    """Random PUMA configurations over related angles; every third one wrist-singular
    (q5 = 0), every fifth elbow-singular (tan q3 = -d4/a3, q3 = pi - atan(d4/a3): the
    wrist centre on the line of the upper arm, found by a sweep of det J), some both."""
    d4, a3 = sp.Rational("0.4318"), sp.Rational("0.0203")
    elbow = sp.pi - sp.atan(d4 / a3)
    for k in range(count):
        q = [rng.choice(PUMA_ANGLES) for _ in range(6)]
        if k % 3 == 0:
            q[4] = 0
        if k % 5 == 0:
            q[2] = elbow
        yield q


def test_puma_joint_twists_agree_with_a_60_digit_rank():
    puma = sk.robots.puma560()
    ranks = []
    for q in puma_configurations(random.Random(23), 16):
        system = puma.joint_twists(q)
        expected = reference_rank.rank(rows_of(system))
        assert system.rank == expected, q
        assert system.reciprocal().rank == 6 - expected
        ranks.append(expected)
    assert (
        min(ranks) <= 4 and ranks.count(6) >= 3
    )  # singular ones (wrist and elbow) included


def test_puma_at_textbook_angles_is_no_longer_refused():
    # sin(pi/5) and cos(pi/8) are nested roots:
    # sqrt(5/8 - sqrt(5)/8) and sqrt(sqrt(2)/4 + 1/2)
    puma = sk.robots.puma560()
    q = [0, sp.pi / 5, -sp.pi / 8, sp.pi / 7, 0, 2 * sp.pi / 7]
    system = puma.joint_twists(q)
    assert system.rank == reference_rank.rank(rows_of(system)) == 5  # q5 = 0: the wrist
    reciprocal_products_vanish(system)


def test_a_wrist_singular_puma_loses_exactly_the_twist_along_the_aligned_axes():
    # q5 = 0: axes 4 and 6 coincide (by hand: the wrist's two rolls are one screw)
    puma = sk.robots.puma560()
    system = puma.joint_twists(
        [
            sp.Rational(1, 5),
            sp.Rational(2, 5),
            -sp.Rational(3, 5),
            sp.pi / 7,
            0,
            2 * sp.pi / 7,
        ]
    )
    assert system.rank == 5
    fourth, sixth = system.screws[3].vector, system.screws[5].vector
    assert ScrewSystem([Twist(fourth), Twist(sixth)]).rank == 1


def test_each_pair_of_related_multiples_of_pi_over_7():
    for i, j in itertools.combinations(range(1, 7), 2):
        p, q = i * sp.pi / 7, j * sp.pi / 7
        # cos(j t) as a polynomial in cos(t) and sin(t) (expand_trig of the same angle)
        t = sp.Symbol("t")
        expanded = sp.expand_trig(sp.cos(j * t)).subs(t, sp.pi / 7)
        assert (
            ScrewSystem([[sp.cos(q), 1, 0, 0, 0, 0], [expanded, 1, 0, 0, 0, 0]]).rank
            == 1
        )
        assert (
            ScrewSystem([[sp.cos(p), 1, 0, 0, 0, 0], [sp.cos(q), 1, 0, 0, 0, 0]]).rank
            == 2
        )


def test_refusals_say_why():
    with pytest.raises(TypeError, match="Schanuel"):
        _ = ScrewSystem([[sp.pi, sp.sin(1), 0, 0, 0, 0]]).rank
    with pytest.raises(TypeError, match="cannot decide exactly"):
        _ = ScrewSystem([[sp.cos(sp.E), 1, 0, 0, 0, 0]]).rank


def test_reduced_is_the_same_span_written_by_its_basis():
    # three planar twists about parallel z axes through (0,0), (1,0), (0,1): rank 3,
    # spanned by Rz, Tx, Ty (by hand: the differences of the axes' twists are Ty, -Tx)
    system = ScrewSystem([([0, 0, 1], r, 0) for r in ([0, 0, 0], [1, 0, 0], [0, 1, 0])])
    reduced = system.reduced()
    assert reduced.screws == system.basis() and reduced.rank == system.rank == 3
    assert reduced.reciprocal().rank == system.reciprocal().rank == 3
    for screw in system.screws:
        assert reduced.contains(screw)
    assert reduced.kind is Twist and reduced.noun == "twist"
    assert system.reciprocal().noun == "wrench"
