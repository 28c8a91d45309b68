"""The Paden–Kahan subproblems: hand-built cases with known answers (exact), random
round trips (float), and the empty answers with their reasons."""

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit.ik import (
    subproblem1,
    subproblem1_prismatic,
    subproblem2,
    subproblem3,
    subproblem3_prismatic,
    subproblem4,
)

Z_AXIS = [0, 0, 1, 0, 0, 0]  # rotation about z through the origin
X_AXIS = [1, 0, 0, 0, 0, 0]
half = sp.Rational(1, 2)
E = sp.Matrix  # exact input: the answer is a SymPy expression


def moved(twist, theta, p):
    return (sk.exp_twist(np.asarray(twist, float), theta) @ np.append(p, 1.0))[:3]


def test_subproblem1_exact_quarter_and_sixth_turns():
    assert subproblem1(E(Z_AXIS), [1, 0, 0], [0, 1, 0]) == [sp.pi / 2]
    assert subproblem1(Z_AXIS, [1, 0, 5], [half, sp.sqrt(3) / 2, 5]) == [sp.pi / 3]
    # an axis through (1, 0, 0): (2, 0, 0) -> (1, 1, 0) is a quarter turn
    axis = sk.twist_from_axis([0, 0, 1], [1, 0, 0], 0)
    assert subproblem1(axis, E([2, 0, 0]), [1, 1, 0]) == [sp.pi / 2]
    theta = sp.Symbol("theta", real=True)
    general = subproblem1(Z_AXIS, [1, 0, 0], [sp.cos(theta), sp.sin(theta), 0])
    assert sp.simplify(sp.cos(general[0]) - sp.cos(theta)) == 0


def test_subproblem1_no_solution_and_free():
    higher = subproblem1(Z_AXIS, [1, 0, 0], [0, 1, 1])
    assert higher == [] and "different planes" in higher.reason
    farther = subproblem1(Z_AXIS, [1, 0, 0], [0, 2, 0])
    assert farther == [] and "different distances" in farther.reason
    on_axis = subproblem1(Z_AXIS, [0, 0, 2], [0, 0, 2])
    assert on_axis == [0] and on_axis.free


def test_subproblem2_exact():
    # z -> x (about x by -pi/2, then about z by -pi/2), or the mirrored pair
    pairs = subproblem2(E(Z_AXIS), X_AXIS, [0, 0, 1], [1, 0, 0])
    assert sorted(pairs, key=str) == sorted(
        [(-sp.pi / 2, -sp.pi / 2), (sp.pi / 2, sp.pi / 2)], key=str
    )
    for theta1, theta2 in pairs:
        assert np.allclose(
            moved(Z_AXIS, float(theta1), moved(X_AXIS, float(theta2), [0, 0, 1])),
            [1, 0, 0],
        )


def test_subproblem2_one_none_and_free():
    # q on axis 1: theta1 is free (0 returned), theta2 turns p onto q
    free = subproblem2(Z_AXIS, X_AXIS, [0, 1, 0], [0, 0, 1])
    assert free.free and len(free) == 1 and np.isclose(free[0][1], np.pi / 2)
    # orthogonal axes: z = alpha w1 + beta w2 + gamma w1 x w2 with alpha = q_z, beta =
    # p_x, gamma^2 = 1 - alpha^2 - beta^2. Tangent circles (gamma = 0): p = (0.6, 0.8,
    # 0), q = (0.6, 0, 0.8) give z = q, theta1 = 0 and a quarter turn about x
    one = subproblem2(Z_AXIS, X_AXIS, [0.6, 0.8, 0], [0.6, 0, 0.8])
    assert len(one) == 1 and np.allclose(one[0], (0, np.pi / 2))
    # q_z = 0.96: gamma^2 = 1 - 0.9216 - 0.36 < 0
    none = subproblem2(Z_AXIS, X_AXIS, [0.6, 0.8, 0], [0, 0.28, 0.96])
    assert none == [] and "do not meet" in none.reason


def test_subproblem2_random_round_trips():
    rng = np.random.default_rng(0)
    for _ in range(200):
        r = rng.normal(size=3)
        w1, w2 = (v / np.linalg.norm(v) for v in rng.normal(size=(2, 3)))
        xi1, xi2 = sk.twist_from_axis(w1, r, 0), sk.twist_from_axis(w2, r, 0)
        p = r + rng.normal(size=3)
        t1, t2 = rng.uniform(-np.pi, np.pi, 2)
        q = moved(xi1, t1, moved(xi2, t2, p))
        pairs = subproblem2(xi1, xi2, p, q)
        assert 1 <= len(pairs) <= 2
        assert (
            min(
                np.abs(np.angle(np.exp(1j * (np.array(pair) - (t1, t2))))).max()
                for pair in pairs
            )
            < 1e-7
        )
        for a, b in pairs:
            assert np.allclose(moved(xi1, a, moved(xi2, b, p)), q, atol=1e-9)


def test_subproblem2_needs_meeting_axes():
    with pytest.raises(
        ValueError, match="twist1 and twist2 must have axes that meet.*parallel"
    ):
        subproblem2(Z_AXIS, Z_AXIS, [1, 0, 0], [0, 1, 0])
    skew = sk.twist_from_axis([1, 0, 0], [0, 1, 0], 0)  # the line y = 1, z = 0
    with pytest.raises(ValueError, match="skew axes 1 m apart"):
        subproblem2(Z_AXIS, skew, [1, 0, 0], [0, 1, 0])


def test_subproblem3_law_of_cosines():
    # p = (1, 0, 0) about z, q = (2, 0, 0): |p' - q|^2 = 5 - 4 cos(theta) = delta^2
    exact = subproblem3(Z_AXIS, [1, 0, 0], [2, 0, 0], sp.sqrt(3))
    assert sorted(exact, key=float) == [-sp.acos(half), sp.acos(half)]  # +-pi/3
    assert subproblem3(E(Z_AXIS), [1, 0, 0], [2, 0, 0], 3) == [
        sp.pi
    ]  # touching: one solution
    assert subproblem3(Z_AXIS, [1, 0, 0], [2, 0, 0], 3.0) == [pytest.approx(np.pi)]
    far = subproblem3(Z_AXIS, [1, 0, 0], [2, 0, 0], 5.0)
    assert far == [] and "1.0000 to 3.0000 m" in far.reason
    # a height difference adds in quadrature: p at z = 1, delta = 2 -> in-plane distance
    # sqrt 3
    tall = subproblem3(Z_AXIS, [1, 0, 1], [2, 0, 0], 2.0)
    assert np.allclose(sorted(tall), [-np.pi / 3, np.pi / 3])


def test_subproblem3_random_round_trips():
    rng = np.random.default_rng(1)
    for _ in range(200):
        w = rng.normal(size=3)
        xi = sk.twist_from_axis(w, rng.normal(size=3), 0)
        p, q = rng.normal(size=(2, 3))
        theta = rng.uniform(-np.pi, np.pi)
        delta = np.linalg.norm(moved(xi, theta, p) - q)
        angles = subproblem3(xi, p, q, delta)
        assert min(abs(np.angle(np.exp(1j * (a - theta)))) for a in angles) < 1e-6
        for a in angles:
            assert np.isclose(np.linalg.norm(moved(xi, a, p) - q), delta, atol=1e-9)


def test_subproblem4_plane():
    # (1, 0, 0) about z onto the plane y = 1/2: sin(theta) = 1/2
    assert subproblem4(Z_AXIS, [1, 0, 0], [0, 1, 0], half) == [sp.pi / 6, 5 * sp.pi / 6]
    assert subproblem4(E(Z_AXIS), [1, 0, 0], [0, 1, 0], 1) == [sp.pi / 2]
    beyond = subproblem4(Z_AXIS, [1, 0, 0], [0, 1, 0], 2.0)
    assert beyond == [] and "not 2.0000" in beyond.reason
    rng = np.random.default_rng(2)
    for _ in range(100):
        xi = sk.twist_from_axis(rng.normal(size=3), rng.normal(size=3), 0)
        p, n = rng.normal(size=3), rng.normal(size=3)
        n /= np.linalg.norm(n)
        theta = rng.uniform(-np.pi, np.pi)
        d = n @ moved(xi, theta, p)
        angles = subproblem4(xi, p, n, d)
        assert min(abs(np.angle(np.exp(1j * (a - theta)))) for a in angles) < 1e-6
        assert all(np.isclose(n @ moved(xi, a, p), d) for a in angles)


def test_prismatic_variants():
    assert subproblem1_prismatic([1, 0, 0], [0, 0, 0], [3, 0, 0]) == [3]
    off = subproblem1_prismatic([1, 0, 0], [0, 0, 0], [3, 4, 0])
    assert off == [] and "4.0000 m off the line" in off.reason
    # the x axis meets the sphere of radius 5 about (0, 3, 0) at x = +-4
    assert sorted(subproblem3_prismatic([1, 0, 0], [0, 0, 0], [0, 3, 0], 5)) == [-4, 4]
    assert subproblem3_prismatic(E([1, 0, 0]), [0, 0, 0], [0, 3, 0], 3) == [0]
    miss = subproblem3_prismatic([1, 0, 0], [0, 0, 0], [0, 3, 0], 2.0)
    assert miss == [] and "3.0000 m from q" in miss.reason


def test_float_input_gives_floats_and_symbolic_gives_sympy():
    assert isinstance(subproblem1(Z_AXIS, [1.0, 0, 0], [0, 1.0, 0])[0], float)
    assert isinstance(
        subproblem1(Z_AXIS, [1, 0, 0], [0, sp.Integer(1), 0])[0], sp.Basic
    )
