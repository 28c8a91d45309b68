"""Orientation parametrisations against hand-written matrices and independent checks.

References: elementary rotations and their products written out entry by entry here
(not screwkit's rotx/roty/rotz), round trips on random rotations, the gimbal-lock
answers stated in the module's docstring, the double cover of the quaternions, and
the Euler-rate matrix B against a finite difference of R(phi(t)).
"""

import math

import numpy as np
import pytest
import sympy as sp
from references import Rx, Ry, Rz

import screwkit as sk


def random_rotations(n, seed):
    rng = np.random.default_rng(seed)
    q = rng.normal(size=(n, 4))
    q /= np.linalg.norm(q, axis=1, keepdims=True)
    w, x, y, z = q.T
    # the unit-quaternion matrix written out (Shoemake), independent of screwkit
    return np.stack(
        [
            np.stack(
                [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)], -1
            ),
            np.stack(
                [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)], -1
            ),
            np.stack(
                [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)], -1
            ),
        ],
        -2,
    ), q


# ---- Euler angles and roll-pitch-yaw -----------------------------------------------


def test_zyz_matrix_written_out():
    a, b, g = 0.3, 1.1, -2.0
    ca, sa, cb, sb, cg, sg = (
        math.cos(a),
        math.sin(a),
        math.cos(b),
        math.sin(b),
        math.cos(g),
        math.sin(g),
    )
    expected = np.array(
        [
            [ca * cb * cg - sa * sg, -ca * cb * sg - sa * cg, ca * sb],
            [sa * cb * cg + ca * sg, -sa * cb * sg + ca * cg, sa * sb],
            [-sb * cg, sb * sg, cb],
        ]
    )
    np.testing.assert_allclose(
        sk.rotation_from_euler([a, b, g], "ZYZ"), expected, atol=1e-15
    )


def test_rpy_is_fixed_axes_x_then_y_then_z():
    roll, pitch, yaw = 0.4, -0.7, 2.5
    expected = Rz(yaw) @ Ry(pitch) @ Rx(roll)
    np.testing.assert_allclose(
        sk.rotation_from_rpy([roll, pitch, yaw]), expected, atol=1e-15
    )
    np.testing.assert_allclose(
        sk.rotation_from_euler([yaw, pitch, roll], "ZYX"), expected, atol=1e-15
    )


@pytest.mark.parametrize("convention", ["ZYZ", "ZYX"])
def test_round_trip_batched(convention):
    R, _ = random_rotations(500, seed=1)
    angles = sk.euler_from_rotation(R, convention)
    assert angles.shape == (500, 3)
    np.testing.assert_allclose(
        sk.rotation_from_euler(angles, convention), R, atol=1e-12
    )
    beta = angles[:, 1]
    if convention == "ZYZ":
        assert np.all((beta >= 0) & (beta <= np.pi))
    else:
        assert np.all(np.abs(beta) <= np.pi / 2)


def test_rpy_round_trip_and_known_angles():
    R = Rz(math.pi / 6) @ Ry(math.pi / 4) @ Rx(math.pi / 3)
    np.testing.assert_allclose(
        sk.rpy_from_rotation(R), [math.pi / 3, math.pi / 4, math.pi / 6], atol=1e-14
    )
    Rs, _ = random_rotations(200, seed=2)
    np.testing.assert_allclose(
        sk.rotation_from_rpy(sk.rpy_from_rotation(Rs)), Rs, atol=1e-12
    )


def test_exact_input_gives_exact_angles():
    R = sk.rotz(sp.pi / 6) * sk.roty(sp.pi / 4) * sk.rotx(sp.pi / 3)
    assert list(sk.rpy_from_rotation(R)) == [sp.pi / 3, sp.pi / 4, sp.pi / 6]
    R = sk.rotz(sp.pi / 3) * sk.roty(sp.pi / 2) * sk.rotz(-sp.pi / 4)
    assert list(sk.euler_from_rotation(R, "ZYZ")) == [sp.pi / 3, sp.pi / 2, -sp.pi / 4]
    t = sp.Symbol("t", real=True)
    assert sk.rotation_from_euler([t, 0, 0], "ZYZ") == sk.rotz(t)


@pytest.mark.parametrize("beta", [0.0, math.pi])
def test_zyz_gimbal_lock_answer(beta):
    # only alpha + gamma (beta = 0) or alpha - gamma (beta = pi) is determined
    R = Rz(0.5) @ Ry(beta) @ Rz(0.9)
    assert sk.gimbal_lock(R, "ZYZ")
    angles = sk.euler_from_rotation(R, "ZYZ")
    turn = 1.4 if beta == 0 else 0.5 - 0.9
    expected_gamma = turn if beta == 0 else -turn  # alpha = 0
    np.testing.assert_allclose(angles, [0.0, beta, expected_gamma], atol=1e-12)
    np.testing.assert_allclose(sk.rotation_from_euler(angles, "ZYZ"), R, atol=1e-12)


@pytest.mark.parametrize("pitch", [math.pi / 2, -math.pi / 2])
def test_rpy_gimbal_lock_answer(pitch):
    R = Rz(0.7) @ Ry(pitch) @ Rx(0.2)
    assert sk.gimbal_lock(R, "ZYX")
    roll, p, yaw = sk.rpy_from_rotation(R)
    assert yaw == 0.0 and abs(p - pitch) < 1e-7
    # at pitch = +pi/2 roll - yaw is determined, at -pi/2 roll + yaw
    expected = 0.2 - 0.7 if pitch > 0 else 0.2 + 0.7
    assert abs(roll - expected) < 1e-7
    np.testing.assert_allclose(sk.rotation_from_rpy([roll, p, yaw]), R, atol=1e-12)


def test_gimbal_lock_exact_and_batched():
    assert sk.gimbal_lock(sk.roty(sp.pi / 2), "ZYX")
    assert not sk.gimbal_lock(sk.roty(sp.pi / 3), "ZYX")
    angles = sk.euler_from_rotation(sk.rotz(sp.pi / 3) * sk.rotz(sp.pi / 6), "ZYZ")
    assert list(angles) == [0, 0, sp.pi / 2]
    Rs = np.stack([Ry(0.0), Ry(0.3), Ry(math.pi)])
    assert sk.gimbal_lock(Rs, "ZYZ").tolist() == [True, False, True]


# ---- quaternions -------------------------------------------------------------------


def test_quaternion_to_rotation_matches_written_out_formula():
    R, q = random_rotations(300, seed=3)
    np.testing.assert_allclose(sk.rotation_from_quaternion(q), R, atol=1e-12)
    np.testing.assert_allclose(sk.rotation_from_quaternion(-q), R, atol=1e-12)


def test_rotation_to_quaternion_double_cover_and_sign():
    R, q = random_rotations(300, seed=4)
    got = sk.quaternion_from_rotation(R)
    assert np.all(got[:, 0] >= 0)
    # equal to q or to -q, the other sheet of the double cover
    same = np.minimum(np.abs(got - q).max(1), np.abs(got + q).max(1))
    assert same.max() < 1e-12


@pytest.mark.parametrize(
    "axis", [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 0], [1, -2, 2]]
)
def test_half_turns(axis):
    u = np.array(axis, float) / np.linalg.norm(axis)
    R = 2 * np.outer(u, u) - np.eye(3)  # a half turn about u
    q = sk.quaternion_from_rotation(R)
    lead = u[np.nonzero(np.abs(u) > 1e-12)[0][0]]
    np.testing.assert_allclose(q, [0, *(u * np.sign(lead))], atol=1e-12)


def test_half_turns_in_floats_keep_the_sign_promise_literally():
    # a half turn of pi in floats: sin(-pi) = -1.2e-16 makes w = -6.1e-17 before the
    # sign is chosen; the promise is w >= 0, and where w == 0 the first non-zero
    # component positive (the rotations written out here, not screwkit's rotx)
    c, s = math.cos(-math.pi), math.sin(-math.pi)
    turns = [Rx(-math.pi), Ry(-math.pi), Rz(-math.pi)]
    turns += [np.array([[1, 0, 0], [0, c, -s], [0, s, c]]) @ Rz(1e-3)]
    rng = np.random.default_rng(11)
    for axis in rng.normal(size=(200, 3)):
        u = axis / np.linalg.norm(axis)
        K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
        turns.append(np.eye(3) + math.sin(math.pi) * K + 2 * K @ K)  # Rodrigues
    q = sk.quaternion_from_rotation(np.array(turns))
    assert np.all(q[:, 0] >= 0)
    for row in q[q[:, 0] == 0]:
        assert row[np.flatnonzero(row)[0]] > 0
    assert np.sum(q[:, 0] == 0) >= len(turns) - 1  # every exact half turn: w is 0


def test_quaternion_exact():
    q = sk.quaternion_from_rotation(sk.rotz(sp.pi / 2))
    assert list(q) == [sp.sqrt(2) / 2, 0, 0, sp.sqrt(2) / 2]
    q = sk.quaternion_from_rotation(sk.rotx(sp.pi))
    assert list(q) == [0, 1, 0, 0]
    half = sp.Rational(1, 2)
    R = sk.rotation_from_quaternion(
        [half, half, half, half]
    )  # third turn about (1,1,1)
    assert R == sp.Matrix([[0, 0, 1], [1, 0, 0], [0, 1, 0]])


def test_quaternion_product_composes_rotations():
    R, q = random_rotations(100, seed=5)
    pq = sk.quaternion_multiply(q[:50], q[50:])
    np.testing.assert_allclose(
        sk.rotation_from_quaternion(pq), R[:50] @ R[50:], atol=1e-12
    )
    # a full turn is -1: the double cover
    quarter = [math.cos(math.pi / 4), 0, 0, math.sin(math.pi / 4)]
    full = quarter
    for _ in range(3):
        full = sk.quaternion_multiply(full, quarter)
    np.testing.assert_allclose(full, [-1, 0, 0, 0], atol=1e-15)


def test_non_unit_quaternion_is_refused():
    with pytest.raises(ValueError, match="q must be a unit quaternion"):
        sk.rotation_from_quaternion([1.0, 1.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="q must have shape"):
        sk.rotation_from_quaternion([1.0, 0.0, 0.0])
    with pytest.raises(ValueError, match="unit quaternion"):
        sk.rotation_from_quaternion(sp.Matrix([1, 1, 0, 0]))


# ---- the Euler-rate matrix ---------------------------------------------------------


def vee(W):
    return np.array([W[2, 1], W[0, 2], W[1, 0]])


@pytest.mark.parametrize("convention", ["ZYZ", "ZYX", "RPY"])
@pytest.mark.parametrize("frame", ["space", "body"])
def test_euler_rates_against_finite_differences(convention, frame):
    rng = np.random.default_rng(6)
    build = (
        sk.rotation_from_rpy
        if convention == "RPY"
        else lambda a: sk.rotation_from_euler(a, convention)
    )
    for _ in range(20):
        phi, rate = rng.uniform(-1.2, 1.2, 3), rng.normal(size=3)
        h = 1e-6
        R = build(phi)
        Rdot = (build(phi + h * rate) - build(phi - h * rate)) / (2 * h)
        omega = vee(Rdot @ R.T) if frame == "space" else vee(R.T @ Rdot)
        B = sk.euler_rate_matrix(phi, convention, frame)
        np.testing.assert_allclose(B @ rate, omega, atol=1e-8)


def test_euler_rate_matrix_is_singular_at_gimbal_lock():
    a = 0.4
    assert abs(np.linalg.det(sk.euler_rate_matrix([a, 0.0, 0.3], "ZYZ"))) < 1e-15
    assert (
        abs(np.linalg.det(sk.euler_rate_matrix([0.1, math.pi / 2, a], "RPY"))) < 1e-15
    )
    b = sp.Symbol("beta", real=True)
    B = sk.euler_rate_matrix([sp.Symbol("alpha", real=True), b, 0], "ZYZ")
    assert sp.simplify(B.det() + sp.sin(b)) == 0
    Bs = sk.euler_rate_matrix(np.zeros((7, 3)), "ZYX")
    assert Bs.shape == (7, 3, 3)


@pytest.mark.parametrize(
    "call, match",
    [
        (lambda: sk.rotation_from_euler([0, 0], "ZYZ"), "angles must have shape"),
        (lambda: sk.rotation_from_euler([0, 0, 0], "XYZ"), "convention"),
        (lambda: sk.euler_from_rotation(np.diag([1.0, 1, -1])), "determinant"),
        (lambda: sk.rpy_from_rotation("R"), "R must"),
        (lambda: sk.euler_rate_matrix([0, 0, 0], "ZYZ", frame="world"), "frame"),
    ],
)
def test_bad_input_is_refused_with_a_sentence(call, match):
    with pytest.raises((ValueError, TypeError), match=match):
        call()
