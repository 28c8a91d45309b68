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
    subproblem5,
    subproblem6,
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


# ---- subproblems 5 and 6 (Elias and Wen 2022): random instances built around a known
# solution; every returned solution checked in the equations; the count against a
# brute-force search (a grid of starts, Newton, distinct roots) written here.


def _rot(k, t):
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


def _rot_batch(k, t):
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    t = t[:, None, None]
    return np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * K @ K


def _wrapped(a):
    return np.angle(np.exp(1j * np.asarray(a)))


def _distinct(roots, tol=1e-6):
    kept = []
    for r in roots:
        if all(np.abs(_wrapped(r - k)).max() > tol for k in kept):
            kept.append(r)
    return kept


def _newton_roots(F, n, grid, iterations=40):
    """Distinct roots of F (batch of angle vectors (m, n) -> residuals (m, n)) from a
    grid of starts, by Newton with a central-difference Jacobian."""
    axes = np.meshgrid(*[np.linspace(-np.pi, np.pi, grid, endpoint=False)] * n)
    X = np.stack([a.ravel() for a in axes], -1)
    h = 1e-7
    for _ in range(iterations):
        R = F(X)
        J = np.stack(
            [
                (F(X + h * np.eye(n)[i]) - F(X - h * np.eye(n)[i])) / (2 * h)
                for i in range(n)
            ],
            -1,
        )
        JtJ = np.swapaxes(J, 1, 2) @ J + 1e-12 * np.eye(n)
        X = X - np.linalg.solve(JtJ, np.swapaxes(J, 1, 2) @ R[..., None])[..., 0]
    good = np.abs(F(X)).max(1) < 1e-11
    return _distinct(_wrapped(X[good]))


def _nearest(solutions, angles):
    """The largest wrapped angle gap from ``angles`` to the nearest of ``solutions``."""
    return min(np.abs(_wrapped(np.array(s) - angles)).max() for s in solutions)


def _assert_brute_force_agrees(F, n, grid, solutions):
    """The brute-force search finds as many roots as ``solutions``, each one of them."""
    brute = _newton_roots(F, n, grid)
    assert len(brute) == len(solutions)
    for root in brute:
        assert _nearest(solutions, root) < 1e-6


def _unit(v):
    return v / np.linalg.norm(v)


def _check_subproblem5(rng):
    k1, k2, k3 = (_unit(rng.normal(size=3)) for _ in range(3))
    p1, p2, p3 = (rng.normal(size=3) for _ in range(3))
    t = rng.uniform(-np.pi, np.pi, 3)
    p0 = _rot(k2, t[1]) @ (p2 + _rot(k3, t[2]) @ p3) - _rot(k1, t[0]) @ p1
    solutions = subproblem5(k1, k2, k3, p0, p1, p2, p3)
    assert 1 <= len(solutions) <= 4 and not solutions.free
    for a, b, c in solutions:
        gap = p0 + _rot(k1, a) @ p1 - _rot(k2, b) @ (p2 + _rot(k3, c) @ p3)
        assert np.linalg.norm(gap) <= 1e-10
    assert _nearest(solutions, t) < 1e-8

    def F(X):
        R1, R2 = _rot_batch(k1, X[:, 0]), _rot_batch(k2, X[:, 1])
        R3 = _rot_batch(k3, X[:, 2])
        return p0 + R1 @ p1 - (R2 @ (p2 + R3 @ p3)[..., None])[..., 0]

    _assert_brute_force_agrees(F, 3, 14, solutions)
    return len(solutions)


def test_subproblem5_random_instances():
    rng = np.random.default_rng(55)
    counts = [_check_subproblem5(rng) for _ in range(12)]
    assert 4 in counts  # the quartic's four real roots happen


def test_subproblem5_no_solution_and_bad_axes():
    z = [0.0, 0.0, 1.0]
    far = subproblem5(
        z, [1.0, 0, 0], z, [100.0, 0, 0], [1.0, 0, 0], [0, 1.0, 0], [1.0, 0, 0]
    )
    assert far == [] and "never" in far.reason
    with pytest.raises(ValueError, match="k2 must be a unit direction"):
        subproblem5(z, [0, 0, 2.0], z, z, z, z, z)


def _check_subproblem6(rng):
    h = np.array([_unit(rng.normal(size=3)) for _ in range(4)])
    k = np.array([_unit(rng.normal(size=3)) for _ in range(4)])
    p = rng.normal(size=(4, 3))
    t = rng.uniform(-np.pi, np.pi, 2)

    def lhs(a, b):
        return np.array(
            [
                h[0] @ _rot(k[0], a) @ p[0] + h[1] @ _rot(k[1], b) @ p[1],
                h[2] @ _rot(k[2], a) @ p[2] + h[3] @ _rot(k[3], b) @ p[3],
            ]
        )

    d = lhs(*t)
    solutions = subproblem6(h, k, p, d)
    assert 1 <= len(solutions) <= 4
    for a, b in solutions:
        assert np.abs(lhs(a, b) - d).max() <= 1e-10
    assert _nearest(solutions, t) < 1e-8

    def F(X):
        terms = [
            np.einsum("j,njk,k->n", h[i], _rot_batch(k[i], X[:, i % 2]), p[i])
            for i in range(4)
        ]
        return np.stack([terms[0] + terms[1], terms[2] + terms[3]], -1) - d

    _assert_brute_force_agrees(F, 2, 40, solutions)
    return len(solutions)


def test_subproblem6_random_instances():
    rng = np.random.default_rng(66)
    counts = [_check_subproblem6(rng) for _ in range(12)]
    assert 4 in counts


def test_subproblem6_rank_one_block_and_free():
    """Axis k1 = k3 = h1 = h3 makes the theta1 block vanish from both equations: theta1
    is free, and theta2 solves the two equations alone."""
    z = np.array([0.0, 0.0, 1.0])
    h = np.array([z, [1.0, 0, 0], z, [0, 1.0, 0]])
    k = np.array([z, z, z, z])
    p = np.array([[0, 0, 0.5], [1.0, 0, 0], [0, 0, 0.2], [1.0, 0, 0]])
    # 0.5 + cos(b) = d1, 0.2 + sin(b) = d2: b = 0.7
    d = [0.5 + np.cos(0.7), 0.2 + np.sin(0.7)]
    solutions = subproblem6(h, k, p, d)
    assert solutions.free
    assert len(solutions) == 1 and abs(solutions[0][1] - 0.7) < 1e-12
