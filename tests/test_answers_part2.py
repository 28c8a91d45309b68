"""The answer keys of the Jacobian, Kawasaki, redundancy and mobility chapters, each
recomputed independently: a screwkit computation that does not read the key's formula
(a root found by bisection, a maximum over a grid, a mobility analysis) or a formula
written here.
"""

import math
import tomllib
from importlib import resources

import numpy as np
import pytest
import sympy as sp

import screwkit as sk


def key(chapter, number):
    path = resources.files("screwkit") / "answers" / f"{chapter}.toml"
    return tomllib.loads(path.read_text(encoding="utf-8"))["exercise"][str(number)]


def value(chapter, number):
    """The key's answer as a float, in the key's unit."""
    return float(sp.sympify(key(chapter, number)["answer"]))


def bisect(f, low, high, steps=80):
    """A root of f in [low, high], where f changes sign."""
    f_low = f(low)
    assert f_low * f(high) < 0, "the bracket must hold a sign change"
    for _ in range(steps):
        middle = (low + high) / 2
        if f_low * f(middle) <= 0:
            high = middle
        else:
            low, f_low = middle, f(middle)
    return (low + high) / 2


def assert_key(chapter, number, expected):
    entry = key(chapter, number)
    assert abs(value(chapter, number) - expected) <= entry["tolerance"] / 10, (
        f"{chapter} exercise {number}: key {value(chapter, number)}, "
        f"computed {expected}"
    )


# --- jacobians ---


def test_jacobians_1_largest_manipulability_of_two_links():
    arm = sk.robots.planar([0.7, 0.4])
    q2 = np.linspace(0.01, np.pi - 0.01, 100_001)
    Q = np.column_stack([np.full_like(q2, 0.3), q2])
    assert_key("jacobians", 1, q2[np.argmax(arm.manipulability(Q, rows="planar"))])


def test_jacobians_4_elbow_singularity_is_where_det_J_vanishes():
    puma = sk.robots.puma560()

    def det(q3):
        return np.linalg.det(
            puma.geometric_jacobian(np.array([0.3, 0.5, q3, 0.2, 0.9, 0]))
        )

    assert_key("jacobians", 4, bisect(det, -1.6, -1.45))
    q3_folded = float(sp.sympify(key("jacobians", 4)["alternatives"][0]))
    assert abs(det(q3_folded)) < 1e-12


def test_jacobians_5_joint_torque_holding_a_weight():
    two_link = sk.robots.planar([0.5, 0.3])
    J = two_link.geometric_jacobian(np.array([0, np.pi / 2]))[:2]
    assert_key("jacobians", 5, (J.T @ np.array([0.0, -10.0]))[0])


def test_jacobians_6_largest_force_by_sampling_directions():
    two_link = sk.robots.planar([0.5, 0.3])
    J = two_link.geometric_jacobian(np.array([0, np.pi / 2]))[:2]
    angles = np.linspace(0, 2 * np.pi, 200_001)
    u = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    # the force of unit torque norm in direction u is u / |J^T u|
    assert_key("jacobians", 6, (1 / np.linalg.norm(u @ J, axis=1)).max())


# --- kawasaki_workspace ---

KAWASAKI = sk.robots.kawasaki_cx210l()
SHOULDER = np.array([0.3, 0, 0.55])


def test_kawasaki_3_shoulder_singularity_puts_the_wrist_centre_on_z0():
    def wrist_x(theta2):
        return KAWASAKI.frames(np.array([0, theta2, 0, 0, 0, 0]))[4, 0, 3]

    assert_key("kawasaki_workspace", 3, bisect(wrist_x, np.radians(30), np.radians(60)))


def _reach():
    theta3 = np.linspace(-np.pi, np.pi, 400_001)
    Q = np.zeros((theta3.size, 6))
    Q[:, 1], Q[:, 2] = np.radians(100), theta3
    distance = np.linalg.norm(KAWASAKI.fk(Q)[:, :3, 3] - SHOULDER, axis=1)
    return theta3, distance


def test_kawasaki_4_farthest_tool_point_from_the_shoulder():
    _, distance = _reach()
    assert_key("kawasaki_workspace", 4, distance.max())


def test_kawasaki_8_two_link_model_lines_up_where_the_reach_is_largest():
    theta3, distance = _reach()
    assert_key("kawasaki_workspace", 8, theta3[np.argmax(distance)])


def test_kawasaki_5_elbow_singularity_of_the_6r_arm():
    def det(theta3):
        q = np.array([0, np.radians(60), theta3, 0, np.pi / 2, 0])
        return np.linalg.det(KAWASAKI.geometric_jacobian(q))

    assert_key("kawasaki_workspace", 5, bisect(det, np.radians(-80), np.radians(-72)))


def test_kawasaki_6_highest_wrist_centre():
    # theta3 over a fine grid, for theta2 near the vertical upper arm (90 deg)
    best = -np.inf
    for theta2 in np.radians(np.linspace(80, 100, 201)):
        theta3 = np.linspace(-np.pi, np.pi, 20_001)
        Q = np.zeros((theta3.size, 6))
        Q[:, 1], Q[:, 2] = theta2, theta3
        best = max(best, KAWASAKI.frames(Q)[:, 4, 2, 3].max())
    assert_key("kawasaki_workspace", 6, best)


# --- redundancy ---


def test_redundancy_4_least_norm_rates():
    rates = np.linalg.pinv(np.array([[1.0, 1.0, 1.0]])) @ np.array([0.3])
    assert np.allclose(rates, rates[0])
    assert_key("redundancy", 4, rates[0])


THREE = sk.robots.planar([1, 1, 1])
Q_THREE = np.radians([0, 90, -90])


def test_redundancy_5_manipulability_of_three_links():
    assert_key("redundancy", 5, THREE.manipulability(Q_THREE, rows="planar"))


def test_redundancy_6_null_space_rate_of_joint_3():
    J = THREE.geometric_jacobian(Q_THREE)[:2]
    null = np.linalg.svd(J)[2][
        -1
    ]  # the right singular vector of the zero singular value
    assert np.allclose(J @ null, 0, atol=1e-12)
    assert_key("redundancy", 6, (0.1 / null[0] * null)[2])


def test_redundancy_7_largest_stable_feedback_gain():
    dt = 0.01

    def stable(K):
        e = 1.0
        for _ in range(200):
            e = e - K * dt * e
        return abs(e) < 1

    gains = np.arange(1.0, 300.0, 0.25)
    largest = max(K for K in gains if stable(K))
    assert largest < value("redundancy", 7) <= largest + 0.25
    assert_key("redundancy", 7, math.floor(largest) + 1)


# --- mobility ---


def test_mobility_3_the_4prru_with_alpha_zero():
    m = sk.mobility(sk.robots.pm_4prru(), at={sp.Symbol("alpha"): 0})
    assert_key("mobility", 3, m.number)


def test_mobility_4_grubler_kutzbach_of_the_3rps():
    m = sk.mobility(sk.robots.pm_3rps())
    assert_key("mobility", 4, m.number)
    assert_key("mobility", 4, 6 * (8 - 9 - 1) + 3 * (1 + 1 + 3))


def test_mobility_5_redundant_constraints_of_the_planar_3rrr():
    m = sk.mobility(sk.robots.planar_3rrr())
    assert_key("mobility", 5, m.redundant_constraints)
    assert m.grubler_kutzbach + m.redundant_constraints - m.idle_mobility == m.number


def test_mobility_6_order_of_a_tripteron_limb_wrench_system():
    m = sk.mobility(sk.robots.pm_3prrr())
    assert {s.rank for s in m.limb_wrench_systems} == {int(value("mobility", 6))}


TESTED = {
    "jacobians": {1, 4, 5, 6},
    "kawasaki_workspace": {3, 4, 5, 6, 8},
    "redundancy": {4, 5, 6, 7},
    "mobility": {3, 4, 5, 6},
}


@pytest.mark.parametrize("chapter", sorted(TESTED))
def test_every_key_of_these_chapters_is_recomputed_here(chapter):
    path = resources.files("screwkit") / "answers" / f"{chapter}.toml"
    keys = tomllib.loads(path.read_text(encoding="utf-8"))["exercise"]
    assert {int(n) for n in keys} == TESTED[chapter]


@pytest.mark.parametrize("chapter", sorted(TESTED))
def test_every_key_accepts_its_own_answer_and_refuses_a_wrong_one(chapter):
    for number in TESTED[chapter]:
        entry = key(chapter, number)
        right = value(chapter, number)
        assert sk.exercises.check(chapter, number, repr(right)).correct
        wrong = right + 10 * entry["tolerance"] + 1
        assert not sk.exercises.check(chapter, number, repr(wrong)).correct
