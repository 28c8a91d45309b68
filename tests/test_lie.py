"""The adjoint, the Lie bracket and the logarithms, against hand derivations and the
identities they must satisfy; numbers from the Modern Robotics library's documented
examples."""

import numpy as np
import pytest
import sympy as sp
from builders import refusals
from hypothesis import given, settings
from hypothesis import strategies as st

import screwkit as sk
from screwkit.screws import Twist, Wrench
from screwkit.transforms import rot_axis

# Modern Robotics (Lynch & Park) library, Adjoint and MatrixLog6 examples: Rx(90 deg), p
# = (0, 0, 3).
T_MR = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 3], [0, 0, 0, 1]])


def random_pose(rng, angle):
    w = rng.normal(size=3)
    T = np.eye(4)
    T[:3, :3] = rot_axis(w / np.linalg.norm(w), angle)
    T[:3, 3] = rng.normal(size=3)
    return T


def test_adjoint_of_the_modern_robotics_example_by_hand():
    # [p] R with p = (0, 0, 3): rows (0, 0, 3), (3, 0, 0), (0, 0, 0)
    expected = np.array(
        [
            [1, 0, 0, 0, 0, 0],
            [0, 0, -1, 0, 0, 0],
            [0, 1, 0, 0, 0, 0],
            [0, 0, 3, 1, 0, 0],
            [3, 0, 0, 0, 0, -1],
            [0, 0, 0, 0, 1, 0],
        ]
    )
    assert np.array_equal(sk.adjoint(T_MR), expected)
    assert sk.adjoint(sp.Matrix(T_MR)) == sp.Matrix(expected)


def test_log_of_the_modern_robotics_example_exactly():
    # omega theta = (pi/2, 0, 0); v theta = (I - [phi]/2 + k [phi]^2) p = (0, 3 pi/4, 3
    # pi/4)
    assert sk.log_transform(sp.Matrix(T_MR)) == sp.Matrix(
        [sp.pi / 2, 0, 0, 0, 3 * sp.pi / 4, 3 * sp.pi / 4]
    )
    assert np.allclose(
        sk.log_transform(T_MR),
        [np.pi / 2, 0, 0, 0, 3 * np.pi / 4, 3 * np.pi / 4],
        atol=1e-15,
    )


def test_ad_is_the_lie_bracket_matrix():
    V1, V2 = np.array([1, 2, 3, 4, 5, 6.0]), np.array([0.3, -1, 2, 0.5, 0, -2])
    # [V1, V2] = (w1 x w2; w1 x v2 - w2 x v1)
    bracket = np.r_[
        np.cross(V1[:3], V2[:3]), np.cross(V1[:3], V2[3:]) - np.cross(V2[:3], V1[3:])
    ]
    assert np.allclose(sk.ad(V1) @ V2, bracket)
    # and it is the derivative of Ad(exp([V1] t)) at t = 0
    h = 1e-6
    derivative = (
        sk.adjoint(sk.exp_twist(V1, h)) - sk.adjoint(sk.exp_twist(V1, -h))
    ) / (2 * h)
    assert np.allclose(derivative, sk.ad(V1), atol=1e-8)
    assert sk.ad(sp.Matrix([1, 2, 3, 4, 5, 6])) == sp.Matrix(sk.ad(V1).astype(int))


@pytest.mark.parametrize(
    "angle",
    [
        0.0,
        1e-12,
        1e-8,
        1e-5,
        1e-4,
        0.3,
        1.0,
        2.0,
        2.5,
        3.0,
        np.pi - 1e-4,
        np.pi - 1e-8,
        np.pi - 1e-12,
        np.pi,
    ],
)
def test_exp_of_log_is_the_pose_at_every_angle(angle):
    rng = np.random.default_rng(int(angle * 1e6) % 1000)
    for _ in range(40):
        T = random_pose(rng, angle)
        V = sk.log_transform(T)
        assert np.linalg.norm(V[:3]) <= np.pi + 1e-15
        assert np.allclose(sk.exp_twist(V, 1.0), T, atol=1e-12)
        assert np.allclose(
            sk.exp_twist(sk.log_rotation(T[:3, :3]).tolist() + [0, 0, 0], 1.0)[:3, :3],
            T[:3, :3],
            atol=1e-12,
        )


@settings(max_examples=200, deadline=None)
@given(
    st.lists(st.floats(-1, 1), min_size=3, max_size=3),
    st.floats(1e-3, np.pi - 1e-3),
    st.lists(st.floats(-2, 2), min_size=3, max_size=3),
)
def test_log_of_exp_is_the_twist(w, theta, v):
    w = np.array(w)
    if np.linalg.norm(w) < 1e-3:
        w = np.array([0.0, 0.0, 1.0])
    xi = np.r_[w / np.linalg.norm(w) * theta, v]
    assert np.allclose(sk.log_transform(sk.exp_twist(xi, 1.0)), xi, atol=1e-10)


def test_log_at_a_half_turn_returns_the_documented_axis():
    assert np.allclose(sk.log_rotation(np.diag([-1.0, -1.0, 1.0])), [0, 0, np.pi])
    assert np.allclose(sk.log_rotation(np.diag([1.0, -1.0, -1.0])), [np.pi, 0, 0])
    # (1, -1, 0)/sqrt(2): the largest-magnitude component positive
    R = rot_axis([1.0, -1.0, 0.0], np.pi)
    assert np.allclose(sk.log_rotation(R), np.pi * np.array([1, -1, 0]) / np.sqrt(2))
    assert sk.log_rotation(sp.Matrix(np.diag([-1, -1, 1]))) == sp.Matrix([0, 0, sp.pi])
    # a batch mixing small, generic and half turns
    Rs = np.stack(
        [rot_axis([0, 1.0, 0], a) for a in (0.0, 1e-9, 1.0, np.pi - 1e-9, np.pi)]
    )
    assert np.allclose(
        sk.log_rotation(Rs)[:, 1], [0, 1e-9, 1.0, np.pi - 1e-9, np.pi], atol=1e-15
    )


def test_adjoint_is_a_homomorphism_and_inverts():
    rng = np.random.default_rng(3)
    T1, T2 = random_pose(rng, 1.1), random_pose(rng, 2.9)
    assert np.allclose(sk.adjoint(T1 @ T2), sk.adjoint(T1) @ sk.adjoint(T2), atol=1e-12)
    assert np.allclose(
        sk.adjoint(sk.inv(T1)), np.linalg.inv(sk.adjoint(T1)), atol=1e-12
    )
    batch = np.stack([T1, T2])
    assert np.allclose(sk.adjoint(batch)[1], sk.adjoint(T2))


def test_a_twist_moves_frames_as_its_exponential_says():
    # Ad(T) V written in the new frame exponentiates to T exp(V) T^-1
    rng = np.random.default_rng(5)
    T = random_pose(rng, 0.7)
    V = np.array([0.2, -0.5, 0.8, 0.3, 0.1, -0.4])
    assert np.allclose(
        sk.exp_twist(sk.adjoint(T) @ V, 0.9),
        T @ sk.exp_twist(V, 0.9) @ sk.inv(T),
        atol=1e-12,
    )


def test_wrenches_change_frame_so_that_power_is_kept():
    rng = np.random.default_rng(8)
    T_ab = random_pose(rng, 1.3)
    twist_b = Twist(sp.Matrix([1, 2, 0, 0, 1, 3]) / 7)
    wrench_b = Wrench(sp.Matrix([0, 1, 1, 2, -1, 0]) / 5)
    twist_a, wrench_a = twist_b.transform(T_ab), wrench_b.transform(T_ab)
    assert abs(float(twist_a @ wrench_a) - float(twist_b @ wrench_b)) < 1e-12
    # Modern Robotics' rule in its (m; f) order: F_b = Ad(T_ab)^T F_a
    swap = np.r_[3:6, 0:3]
    F_a = np.array(wrench_a.vector, dtype=float).ravel()[swap]
    F_b = np.array(wrench_b.vector, dtype=float).ravel()[swap]
    assert np.allclose(sk.adjoint(T_ab).T @ F_a, F_b, atol=1e-12)


def test_twist_exp_is_exact_or_numeric():
    a = sp.Symbol("a", real=True)
    spin = Twist.from_axis([0, 0, 1], [1, 0, 0], 0)
    assert spin.exp(sp.pi)[:3, 3] == sp.Matrix([2, 0, 0])
    assert isinstance(spin.exp(a), sp.MatrixBase)
    assert spin.exp(np.array([0.0, np.pi])).shape == (2, 4, 4)
    # helical: pitch h along z through the origin moves (1, 0, 0) on a helix
    screw = Twist.from_axis([0, 0, 1], [0, 0, 0], sp.Rational(1, 10))
    T = screw.exp(sp.pi / 2)
    assert T * sp.Matrix([1, 0, 0, 1]) == sp.Matrix([0, 1, sp.pi / 20, 1])


test_bad_input_names_the_argument = refusals(
    [
        (
            lambda: sk.log_rotation(np.diag([1.0, 1.0, -1.0])),
            ValueError,
            "R must be a rotation",
        ),
        (lambda: sk.log_rotation(np.eye(3) * 2), ValueError, "R must be a rotation"),
        (lambda: sk.log_rotation(np.eye(4)), ValueError, "R must have shape"),
        (
            lambda: sk.log_transform(np.diag([2.0, 1, 1, 1])),
            ValueError,
            "rotation block of T",
        ),
        (lambda: sk.log_transform(np.ones((4, 4))), ValueError, "T must have last row"),
        (lambda: sk.log_transform("pose"), TypeError, "T must be"),
        (lambda: sk.adjoint(np.eye(3)), ValueError, "T must have shape"),
        (lambda: sk.ad([1, 2, 3]), ValueError, "twist must have shape"),
        (lambda: sk.vee(np.eye(4)), ValueError, "W must have shape"),
    ]
)
