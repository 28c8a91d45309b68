"""Rank certificates (ScrewSystem.certificate): each is checked here independently of
screwkit's own proof, by exact SymPy where it is quick and otherwise by evaluation at
random real points with 60 significant digits: the minor must be far from zero, M k
must vanish to that precision. Wrong certificates must be refused."""

import functools
import random

import pytest
import sympy as sp

import screwkit as sk
from screwkit import _certificates

DIGITS = 60


def screw_matrix(system):
    """M: one row per screw, [angular; linear]."""
    if not system.screws:
        return sp.zeros(0, 6)
    return sp.Matrix([list(s.vector.T) for s in system.screws])


def random_point(exprs, seed):
    rng = random.Random(seed)
    symbols = set().union(*(sp.sympify(e).free_symbols for e in exprs))
    return {x: sp.Rational(rng.randint(-2000, 2000), 997) for x in symbols}


def check_independently(system, certificate, points=3):
    """The certificate's two claims, evaluated at random rational points to 60 digits
    (exact SymPy evaluation of each entry first, then numerical)."""
    M = screw_matrix(system)
    rows, cols, kernel = certificate
    r = len(rows)
    assert r == system.rank
    assert len(kernel) == 6 - r
    K = sp.Matrix.hstack(*kernel) if kernel else sp.zeros(6, 0)
    free = [j for j in range(6) if j not in cols]
    exprs = list(M) + list(K)
    minor_seen = independent_seen = False
    for seed in range(points):
        at = random_point(exprs, seed)
        Mv = M.subs(at).evalf(DIGITS)
        Kv = K.subs(at).evalf(DIGITS)
        scale = max([1] + [abs(v) for v in Mv]) * max([1] + [abs(v) for v in Kv])
        residual = Mv * Kv
        assert all(abs(v) < scale * sp.Float(10) ** (10 - DIGITS) for v in residual)
        minor = Mv.extract(list(rows), list(cols)).det() if r else 1
        minor_seen |= abs(minor) > sp.Float(10) ** (20 - DIGITS)
        if kernel:
            block = Kv.extract(free, list(range(len(kernel)))).det()
            independent_seen |= abs(block) > sp.Float(10) ** (20 - DIGITS)
    assert minor_seen, "the minor vanished at every point tried"
    assert independent_seen or not kernel


@functools.cache
def mobility_of(name):
    return sk.mobility(getattr(sk.robots, name)())


def systems_of(mobility):
    return [
        *mobility.limb_twist_systems,
        *mobility.limb_wrench_systems,
        mobility.platform_wrench_system,
        mobility.platform_twist_system,
    ]


@pytest.mark.parametrize(
    "name", ["pm_3prrr", "pm_3prpar", "pm_4prru", "pm_6ups", "pm_3ruu", "pm_3rps"]
)
def test_the_mobility_chapters_systems_have_proven_ranks(name):
    # the 3-RPS's platform twists take 9 s alone: a busy machine must not turn the
    # default 30 s limit into a failure of the proof (speed is benchmarks' business)
    for system in systems_of(mobility_of(name)):
        certificate = system.certificate(timeout=300)
        assert certificate.proven, certificate.reason
        check_independently(system, certificate)


def test_a_rank_deficiency_with_related_angles_is_proven():
    # the third screw is cos(a) s1 - sin(a) s2, written with double angles: it is
    # dependent only through sin(2a) = 2 sin(a) cos(a), cos(2a) = 1 - 2 sin(a)^2 and
    # sin^2 + cos^2 = 1
    a, b = sp.symbols("a b")
    s1 = [sp.cos(a), sp.sin(a), 0, 0, 0, b]
    s2 = [-sp.sin(a), sp.cos(a), 0, b, 0, 0]
    s3 = [  # cos(a) s1 - sin(a) s2, written with double angles
        sp.cos(2 * a) + 2 * sp.sin(a) ** 2,
        sp.sin(2 * a) - 2 * sp.sin(a) * sp.cos(a),
        0,
        -b * sp.sin(a),
        0,
        b * sp.cos(a),
    ]
    system = sk.ScrewSystem([s1, s2, s3])
    assert system.rank == 2
    certificate = system.certificate()
    assert certificate.proven, certificate.reason
    check_independently(system, certificate)


def test_a_rank_deficiency_with_nested_radicals_is_proven():
    # sqrt(2 + sqrt(2)) sqrt(2 - sqrt(2)) = sqrt(2): the third row is the sum of the
    # first two only through that identity
    r = sp.sqrt(2 + sp.sqrt(2)) * sp.sqrt(2 - sp.sqrt(2))
    s1 = [1, 0, 0, 0, sp.sqrt(2), 0]
    s2 = [0, 1, 0, 0, 0, 1]
    s3 = [1, 1, 0, 0, r, 1]
    system = sk.ScrewSystem([s1, s2, s3])
    assert system.rank == 2
    certificate = system.certificate()
    assert certificate.proven, certificate.reason
    assert "sqrt" in certificate.reason
    check_independently(system, certificate)


def test_a_symbolic_full_rank_system_and_the_zero_system():
    x, y = sp.symbols("x y")
    system = sk.ScrewSystem(
        [
            [1, 0, 0, 0, x, 0],
            [0, 1, 0, y, 0, 0],
            [0, 0, 1, 0, 0, 0],
            [0, 0, 0, 1, 0, 0],
            [0, 0, 0, 0, 1, x * y],
            [0, 0, 0, 0, 0, 1],
        ]
    )
    certificate = system.certificate()
    assert certificate.proven and certificate.kernel == []
    check_independently(system, certificate)
    empty = sk.ScrewSystem([]).certificate()
    assert empty.proven and len(empty.kernel) == 6


def test_a_wrong_certificate_is_refused():
    a = sp.Symbol("a")
    M = [[sp.cos(a), sp.sin(a), 0, 0, 0, 0], [0, 0, 1, 0, 0, 0]]
    good = [sp.Matrix([-sp.sin(a), sp.cos(a), 0, 0, 0, 0])] + [
        sp.Matrix([0, 0, 0, *e]) for e in ([1, 0, 0], [0, 1, 0], [0, 0, 1])
    ]
    assert _certificates.certify(M, [0, 1], [0, 2], good)[0] is True
    bad = [sp.Matrix([sp.sin(a), sp.cos(a), 0, 0, 0, 0])] + good[1:]
    verdict, reason = _certificates.certify(M, [0, 1], [0, 2], bad)
    assert verdict is False and "row 0" in reason
    verdict, reason = _certificates.certify(M, [0, 1], [1, 0], good[:3])
    assert verdict is False  # 2 + 3 vectors do not make 6
    verdict, reason = _certificates.certify(M, [0, 1], [3, 4], good)
    assert verdict is False and "minor" in reason


def test_float_screws_have_no_certificate_and_bad_timeouts_are_refused():
    system = sk.ScrewSystem([[1.0, 0, 0, 0, 0, 0.5]])
    with pytest.raises(TypeError, match="hold floats"):
        system.certificate()
    exact = sk.ScrewSystem([[1, 0, 0, 0, 0, 0]])
    with pytest.raises(TypeError, match="timeout"):
        exact.certificate(timeout="1")
    with pytest.raises(ValueError, match="timeout"):
        exact.certificate(timeout=-1)


def test_an_unfinished_proof_says_so():
    system = systems_of(mobility_of("pm_3prpar"))[0]
    certificate = system.certificate(timeout=1e-9)
    assert not certificate.proven
    assert "longer than" in certificate.reason
