"""Closed-form IK of arms with a spherical wrist (PUMA 560 of any size, with base and
tool; the Kawasaki CX210L): round trips, labels, singular configurations, reach, limits;
numeric IK."""

import ast
import functools
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import sympy as sp
from builders import kawasaki, planar, puma
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from references import A2, A3, D4

import screwkit as sk
from screwkit.ik import (
    CONFIGURATIONS,
    analytic_ik,
    analytic_ik_all,
    configuration,
    puma560_config,
    puma560_ik,
    puma560_ik_all,
)


def puma_with(d1=0.0, d6=0.0):
    """The PUMA 560 with a pedestal d1 and a flange d6 (the Robotics Toolbox has d1 =
    0.672)."""
    links = list(puma().links)
    links[0] = sk.Link.revolute(d=d1, alpha=sp.pi / 2, qlim=links[0].qlim)
    links[5] = sk.Link.revolute(d=d6, qlim=links[5].qlim)
    return sk.Chain(links, name="PUMA 560 with d1")


@functools.cache
def pedestal():
    return puma_with(d1=0.6718, d6=0.0562)


@functools.cache
def mounted():
    return (
        puma()
        .with_base(sk.transl(0.2, -0.1, 0.6) @ sk.homogeneous(sk.rotx(0.4)))
        .with_tool(sk.transl(0.0, 0.02, 0.15) @ sk.homogeneous(sk.roty(0.3)))
    )


ARMS = {
    "puma": puma,
    "puma_d1": pedestal,
    "puma_base_tool": mounted,
    "kawasaki": kawasaki,
}


def wrapped(angle):
    return np.pi - np.mod(np.pi - angle, 2 * np.pi)


def corke_label(q):
    """Corke's PUMA label from the DH geometry (the definition checked against the
    Robotics Toolbox's ikine_a): arm 'r' if the wrist centre is in front along x1, elbow
    'u' if the elbow is above the shoulder-wrist line seen with the arm forward, wrist
    'f' if q5 > 0."""
    q2, q3, q5 = q[1], q[2], q[4]
    forward = A2 * np.cos(q2) + A3 * np.cos(q2 + q3) - D4 * np.sin(q2 + q3)
    up = A2 * np.sin(q2) + A3 * np.sin(q2 + q3) + D4 * np.cos(q2 + q3)
    cross = forward * A2 * np.sin(q2) - up * A2 * np.cos(q2)
    return (
        ("r" if forward > 0 else "l")
        + ("u" if np.sign(forward) * cross > 0 else "d")
        + ("f" if q5 > 0 else "n")
    )


def far_from_singular(q):
    forward = A2 * np.cos(q[1]) + A3 * np.cos(q[1] + q[2]) - D4 * np.sin(q[1] + q[2])
    return (
        abs(np.sin(q[4])) > 1e-3
        and abs(forward) > 1e-3
        and abs(A3 * np.sin(q[2]) + D4 * np.cos(q[2])) > 1e-3
    )


generic = arrays(float, 6, elements=st.floats(-np.pi, np.pi, allow_nan=False)).filter(
    far_from_singular
)


@settings(max_examples=300, deadline=None)
@given(generic)
def test_puma_round_trip_and_corke_labels(q):
    T = puma().fk(q)
    solutions = puma560_ik(T)
    assert [s.config for s in solutions] == list(CONFIGURATIONS)
    Q = np.array([s.q for s in solutions])
    assert np.max(np.abs(puma().fk(Q) - T)) < 1e-10  # every solution reaches the pose
    distances = np.abs(wrapped(Q[:, None] - Q[None])).max(axis=-1) + np.eye(8)
    assert distances.min() > 1e-6  # eight distinct solutions
    assert puma560_config(q) == corke_label(q)
    assert np.allclose(wrapped(solutions.by_config(corke_label(q)).q - q), 0, atol=1e-7)
    for s in solutions:  # each label agrees with Corke's definition
        assert corke_label(s.q) == s.config


@pytest.mark.parametrize("name", sorted(ARMS))
def test_round_trip_on_random_poses(name):
    robot = ARMS[name]()
    q = np.random.default_rng(5).uniform(-np.pi, np.pi, (3000, 6))
    T = robot.fk(q)
    Q = analytic_ik_all(robot, T)
    found = ~np.isnan(Q[..., 0])
    assert found.sum(axis=1).min() >= 4  # every pose made by the arm is reached
    poses, branches = np.nonzero(found)
    assert np.max(np.abs(robot.fk(Q[poses, branches]) - T[poses])) < 1e-10
    labels = np.array(configuration(robot, q))
    k = np.array([CONFIGURATIONS.index(label) for label in labels])
    assert np.abs(wrapped(Q[np.arange(len(q)), k] - q)).max() < 1e-6  # its own label
    if (
        name == "kawasaki"
    ):  # reaching back past axis 1 needs the other arm: not always possible
        assert 0 < found[:, :4].mean() < 1
    else:
        assert found.all()


def test_labels_of_solutions_are_their_branches():
    q = np.random.default_rng(8).uniform(-np.pi, np.pi, (500, 6))
    for robot in (pedestal(), kawasaki()):
        Q = analytic_ik_all(robot, robot.fk(q))
        poses, branches = np.nonzero(~np.isnan(Q[..., 0]))
        labels = configuration(robot, Q[poses, branches])
        assert labels == [CONFIGURATIONS[b] for b in branches]


def test_kawasaki_paper_poses():
    for q in kawasaki().configurations.values():
        solutions = analytic_ik(kawasaki(), kawasaki().fk(q))
        assert 4 <= len(solutions) <= 8
        same = solutions.by_config(configuration(kawasaki(), q))
        assert np.allclose(
            same.q[:3], q[:3], atol=1e-10
        )  # q5 = 0: the wrist rule sets q4
        assert np.allclose(kawasaki().fk(same.q), kawasaki().fk(q), atol=1e-10)


def test_rtb_pedestal_pose_needs_its_robot():
    """The Robotics Toolbox's PUMA has d1 = 0.672 m: its poses are solved with that
    robot."""
    q = np.radians([10, 30, -80, 20, 40, 60])
    T = pedestal().fk(q)
    with_robot = puma560_ik(T, robot=pedestal())
    assert np.allclose(with_robot.by_config(corke_label(q)).q, q, atol=1e-9)
    for s in puma560_ik(T):  # the d1 = 0 model answers for its own pose, 0.67 m lower
        assert not np.allclose(pedestal().fk(s.q), T, atol=1e-3)


def test_shoulder_singularity_issue_16():
    """Wrist centre at exactly the shoulder offset: r^2 - d3^2 is 0 up to round-off (and
    the arm points straight up: the elbow is stretched too)."""
    q1 = np.linspace(-np.pi, np.pi, 200)
    q = np.column_stack(
        [
            q1,
            np.full(200, np.pi / 2),
            np.full(200, np.arctan2(A3, D4) - np.pi / 2),
            np.full(200, 0.4),
            np.full(200, 0.5),
            np.full(200, 0.6),
        ]
    )
    T = puma().fk(q)
    Q = puma560_ik_all(T)
    assert not np.any(np.isnan(Q))
    assert np.max(np.abs(puma().fk(Q.reshape(-1, 6)) - np.repeat(T, 8, axis=0))) < 1e-10
    for k in range(0, 200, 7):
        solutions = puma560_ik(T[k])
        assert len(solutions) == 8
        assert all({"shoulder", "elbow"} <= set(s.singular) for s in solutions)
        assert puma560_config(q[k])[0] == "r"  # the rule: a tie is 'r'
        assert np.allclose(
            wrapped(solutions.by_config(puma560_config(q[k])).q - q[k]), 0, atol=1e-7
        )
        # the two arms coincide: 'lu' is 'rd' and 'ld' is 'ru'
        assert np.allclose(solutions.by_config("lun").q, solutions.by_config("rdn").q)


@pytest.mark.parametrize("name", ["zero", "ready", "stretch"])
def test_named_wrist_singular_poses_round_trip(name):
    q = puma().configurations[name]
    assert q[3] == q[4] == 0
    solutions = puma560_ik(puma().fk(q))
    label = puma560_config(q)
    assert label.endswith("f")  # q5 = 0 and cos q4 >= 0
    assert np.allclose(wrapped(solutions.by_config(label).q - q), 0, atol=1e-12)


def test_wrist_singularity_rule():
    q = np.array([0.2, 0.4, -1.0, 0.7, 0.0, 0.3])  # q5 = 0: only q4 + q6 = 1.0 is fixed
    solutions = puma560_ik(puma().fk(q))
    arm_elbow = corke_label(q)[:2]
    assert {s.config for s in solutions if "wrist" in s.singular} == {
        arm_elbow + "n",
        arm_elbow + "f",
    }
    flip, no_flip = (
        solutions.by_config(arm_elbow + "f"),
        solutions.by_config(arm_elbow + "n"),
    )
    assert np.allclose(flip.q, [0.2, 0.4, -1.0, 0.0, 0.0, 1.0], atol=1e-12)  # q4 = 0
    assert np.allclose(no_flip.q, [0.2, 0.4, -1.0, np.pi, 0.0, 1.0 - np.pi], atol=1e-12)
    for s in solutions:
        assert np.allclose(puma().fk(s.q), puma().fk(q), atol=1e-10)
        assert puma560_config(s.q) == s.config  # the tie rule labels both


def test_a_singular_answer_says_so_in_its_reason():
    # the docstring promises `reason` for a continuum, but a named
    # structure flagged it only per solution; a regular pose keeps reason None
    q = np.array([0.2, 0.4, -1.0, 0.7, 0.0, 0.3])  # q5 = 0: q4 + q6 fixed
    solutions = puma560_ik(puma().fk(q))
    assert "continuum" in solutions.reason and "wrist" in solutions.reason
    assert analytic_ik(puma(), puma().fk(q)).reason == solutions.reason
    q3 = np.arctan2(-D4, A3)  # the elbow stretched: solutions coincide in pairs
    stretched = puma560_ik(puma().fk(np.array([0.3, 0.5, q3, 0.4, 0.7, 0.2])))
    assert "elbow" in stretched.reason and "coincide" in stretched.reason
    regular = puma560_ik(puma().fk(np.array([0.2, 0.4, -1.0, 0.7, 0.5, 0.3])))
    assert regular.reason is None and not any(s.singular for s in regular)


def test_elbow_singularity():
    """a3 sin q3 + d4 cos q3 = 0: the forearm in line with the upper arm (stretched or
    folded)."""
    for q3 in (np.arctan2(-D4, A3), np.arctan2(D4, -A3)):
        q = np.array([0.3, 0.5, q3, 0.4, 0.7, 0.2])
        solutions = puma560_ik(puma().fk(q))
        assert len(solutions) == 8 and all("elbow" in s.singular for s in solutions)
        assert np.allclose(
            wrapped(solutions.by_config(puma560_config(q)).q - q), 0, atol=1e-6
        )
        for s in solutions:
            assert np.allclose(puma().fk(s.q), puma().fk(q), atol=1e-10)


def test_kawasaki_wrist_centre_on_axis_1():
    """No shoulder offset: the wrist centre can be on axis 1, q1 is free; the rule is q1
    = 0."""
    q2 = 1.2

    # the wrist centre (the origin of frame 4) is on axis 1 where its x in frame 1 is 0:
    # bisect
    def x4(q3):
        return kawasaki().frames(np.array([0, q2, q3, 0, 0, 0]))[4, 0, 3]

    low, high = -1.5, 1.5
    assert np.sign(x4(low)) != np.sign(x4(high))
    for _ in range(80):
        middle = (low + high) / 2
        low, high = (
            (middle, high) if np.sign(x4(middle)) == np.sign(x4(low)) else (low, middle)
        )
    q = np.array([0.0, q2, low, 0.3, 0.6, 0.9])
    solutions = analytic_ik(kawasaki(), kawasaki().fk(q))
    assert solutions and all(s.q[0] == 0 for s in solutions)
    assert all("shoulder" in s.singular for s in solutions)
    assert np.allclose(
        wrapped(solutions.by_config(configuration(kawasaki(), q)).q - q), 0, atol=1e-6
    )
    for s in solutions:
        assert np.allclose(kawasaki().fk(s.q), kawasaki().fk(q), atol=1e-9)


def test_out_of_reach_has_a_reason():
    far = puma560_ik(sk.transl(1.0, 0.5, 0.3))
    # a2 + sqrt(a3^2 + d4^2) = 0.4318 + 0.43228 = 0.8641 m
    assert (
        far == [] and "the arm reaches from" in far.reason and "0.8641 m" in far.reason
    )
    inside = puma560_ik(sk.transl(0.05, 0.0, 0.3))
    assert inside == [] and "closer than the shoulder offset 0.15005 m" in inside.reason
    assert np.all(np.isnan(puma560_ik_all(sk.transl(1.0, 0.5, 0.3))))


def test_one_angle_convention_and_limits_as_an_option():
    # q2 = -170 deg is outside [-45, 225] deg but 190 deg is the same angle and inside
    q = np.radians([10, -170, -60, 20, 30, 40])
    label = puma560_config(q)
    default = puma560_ik(puma().fk(q)).by_config(label)
    moved = puma560_ik(puma().fk(q), within_limits=True).by_config(label)
    batch = puma560_ik_all(puma().fk(q))[CONFIGURATIONS.index(label)]
    assert np.allclose(default.q, batch) and np.isclose(default.q[1], np.radians(-170))
    assert default.within_limits and moved.within_limits
    assert np.isclose(moved.q[1], np.radians(190)) and puma().within_limits(moved.q)


def test_within_limits_filters_and_explains():
    q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
    solutions = puma560_ik(puma().fk(q))
    allowed = puma560_ik(puma().fk(q), within_limits=True)
    assert 0 < len(allowed) < len(solutions)
    assert all(puma().within_limits(s.q) for s in allowed)
    assert solutions.nearest(q + 0.01).config == "ruf"
    assert puma560_ik(puma().fk(q), near=q + 0.01)[0].config == "ruf"
    # joint 1 limited to +-10 deg and a pose at q1 = 90 deg: the arms have q1 = 90 deg
    # and about -90 deg, so nothing is left, and the reason says so
    tight = sk.Chain(
        [sk.Link.revolute(alpha=sp.pi / 2, qlim=np.radians([-10, 10]))]
        + list(puma().links[1:])
    )
    T = tight.fk(np.radians([90, 60, -100, 0, 40, 0]))
    assert len(puma560_ik(T, robot=tight)) == 8
    none = puma560_ik(T, robot=tight, within_limits=True)
    assert none == [] and none.reason.startswith(
        "every solution violates a joint limit"
    )


def test_batch_answers_and_chunks():
    q = np.random.default_rng(3).uniform(
        -np.pi, np.pi, (9000, 6)
    )  # more than one chunk
    T = kawasaki().fk(q)
    Q = analytic_ik_all(kawasaki(), T)
    answers = analytic_ik(kawasaki(), T[[0, 8999]])
    for answer, row in zip(answers, Q[[0, 8999]]):
        assert [s.config for s in answer] == [
            c for c, r in zip(CONFIGURATIONS, row) if not np.isnan(r[0])
        ]


# ---- numeric -------------------------------------------------------------------------


def planar_2r():
    return planar(1.0, 1.0)


def body_jacobian_2r(theta2):
    """Lynch and Park's 2R arm, L1 = L2 = 1: body Jacobian columns [omega; v] (derived
    by hand: joint 2 is 1 m behind the tool along x, joint 1 is reached through both
    links)."""
    return np.array(
        [[0, 0], [0, 0], [1, 1], [np.sin(theta2), 0], [1 + np.cos(theta2), 1], [0, 0]]
    )


def test_newton_raphson_example_6_1():
    """Lynch and Park, Example 6.1: T_sd puts the tool at (0.366, 1.366) turned by 120
    deg; from theta0 = (0, 30 deg) Newton-Raphson converges to (30, 90) deg."""
    target = sk.transl(
        np.cos(np.pi / 6) - 0.5, 0.5 + np.cos(np.pi / 6), 0
    ) @ sk.homogeneous(sk.rotz(2 * np.pi / 3))
    assert np.allclose(target, planar_2r().fk(np.radians([30, 90])))
    theta0 = np.radians([0.0, 30.0])
    # the first error twist by hand: the rotation left is 90 deg about z, and v follows
    # from exp_twist; check the solver's first step against pinv(J_b) V_b
    V = sk.ik.pose_error(planar_2r().fk(theta0), target)
    assert np.allclose(V[:3], [0, 0, np.pi / 2])
    assert np.allclose(
        sk.exp_twist(V, 1.0), np.linalg.inv(planar_2r().fk(theta0)) @ target
    )
    one = sk.ik.numeric_ik(
        planar_2r(), target, theta0, damping=0, max_iterations=1, within_limits=False
    )
    expected = theta0 + np.linalg.pinv(body_jacobian_2r(theta0[1])) @ V
    assert np.allclose(one.q, expected, atol=1e-12)
    result = sk.ik.numeric_ik(planar_2r(), target, theta0, damping=0)
    assert result.success and np.allclose(result.q, np.radians([30, 90]), atol=1e-9)
    assert result.iterations <= 6


@pytest.mark.parametrize("frame", ["body", "space"])
def test_numeric_ik_puma(frame):
    q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
    T = puma().fk(q)
    result = sk.ik.numeric_ik(puma(), T, q + 0.2, frame=frame)
    assert result.success and result.error < 1e-10 and result.iterations < 50
    assert np.allclose(wrapped(result.q - q), 0, atol=1e-8)
    starts = np.random.default_rng(2).uniform(-np.pi, np.pi, (40, 6))
    batch = sk.ik.numeric_ik(puma(), T, starts, frame=frame, within_limits=False)
    assert batch.q.shape == (40, 6) and batch.success.mean() > 0.7
    closed = np.array([s.q for s in puma560_ik(T)])
    for qk in batch.q[batch.success]:  # every converged start lands on one of the eight
        assert np.abs(wrapped(closed - qk)).max(axis=-1).min() < 1e-6


def test_numeric_ik_unreachable_never_succeeds():
    result = sk.ik.numeric_ik(
        puma(), sk.transl(1.5, 0.0, 0.2), np.zeros(6), max_iterations=100
    )
    assert not result.success and result.error > 0.5  # 1.5 m is 0.64 m beyond the reach
    batch = sk.ik.numeric_ik(
        planar_2r(),
        sk.transl(2.5, 0, 0),
        np.random.default_rng(0).uniform(-3, 3, (10, 2)),
    )
    assert not np.any(batch.success)


def test_numeric_ik_respects_limits():
    q = np.radians([10, 30, -60, 20, 40, 60])
    T = puma().fk(q)
    start = np.radians([150, 200, -200, 160, 90, 250])
    result = sk.ik.numeric_ik(puma(), T, start, max_iterations=300)
    assert puma().within_limits(result.q)
    if result.success:
        assert np.allclose(puma().fk(result.q), T, atol=1e-9)
    # a 2R arm reaches a planar pose (x, y, angle) with one q only; with the elbow
    # limited to [0.1, 3.0] rad the pose made by q2 = -1.0 is out of reach, and the
    # answer says so
    arm = sk.robots.planar([1.0, 1.0], qlim=[[-np.pi, np.pi], [0.1, 3.0]])
    target = arm.fk(np.array([0.4, -1.0]))
    out = sk.ik.numeric_ik(arm, target, np.array([0.4, 0.5]))
    assert not out.success and arm.within_limits(out.q)
    free = sk.ik.numeric_ik(arm, target, np.array([0.4, 0.5]), within_limits=False)
    assert free.success and np.allclose(free.q, [0.4, -1.0])


def test_numeric_ik_helical_chain():
    """A product-of-exponentials chain with a helical joint (pitch 0.1 m/rad) and a
    prismatic one: the answer reaches the pose made by a known q."""
    axes = [
        sk.twist_from_axis([0, 0, 1], [0, 0, 0], 0.1),
        sk.twist_from_axis([0, 1, 0], [0.5, 0, 0.3], 0),
        sk.twist_from_axis([1, 0, 0], [0, 0, 0], sp.oo),
        sk.twist_from_axis([0, 0, 1], [1.0, 0, 0.3], 0),
        sk.twist_from_axis([0, 1, 0], [1.0, 0, 0.3], 0),
        sk.twist_from_axis([1, 0, 0], [1.0, 0, 0.3], 0),
    ]
    chain = sk.Chain.from_screws(axes, sk.transl(1.2, 0, 0.3))
    q = np.array([0.4, -0.3, 0.2, 0.5, 0.6, -0.7])
    result = sk.ik.numeric_ik(chain, chain.fk(q), q + 0.15)
    assert result.success and np.allclose(chain.fk(result.q), chain.fk(q), atol=1e-9)
    assert np.isclose(result.q[0], q[0])  # a helical angle is not wrapped


def test_numeric_ik_takes_a_numpy_tolerance():
    """tol=np.float32(1e-6) is a positive number like any other (the checks of
    _checks)."""
    puma = sk.robots.puma560()
    q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
    result = sk.ik.numeric_ik(puma, puma.fk(q), q + 0.05, tol=np.float32(1e-6))
    assert result.success and result.error < 1e-6
    assert np.allclose(puma.fk(result.q), puma.fk(q), atol=1e-5)


# ---- the family as a folder: old paths, names, kernels, tolerances -------------------


def test_the_closed_form_loads_on_first_use():
    """Importing screwkit (chains and Chain.numeric_ik included) loads the subproblems
    and Newton, not the dispatcher; its names load when first asked for."""
    code = (
        "import sys, numpy as np, screwkit as sk\n"
        "arm = sk.robots.planar([1.0, 0.5])\n"
        "arm.numeric_ik(arm.fk(np.array([0.3, 0.4])), np.array([0.2, 0.5]))\n"
        "print('screwkit.ik.dispatch' in sys.modules)\n"
        "sk.ik.analytic_ik\n"
        "print('screwkit.ik.dispatch' in sys.modules)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    ).stdout.split()
    assert out == ["False", "True"]


def test_every_name_of_sk_ik_is_there():
    names = set(sk.ik.__all__)
    assert {"analytic_ik", "analytic_ik_all", "numeric_ik", "CONFIGURATIONS"} <= names
    assert set(sk.ik.subproblems.__all__) <= names
    assert all(getattr(sk.ik, name) is not None for name in names)
    assert names | {"dispatch", "ur", "stanford", "spherical_wrist"} <= set(dir(sk.ik))
    assert sk.ik.analytic_ik is sk.ik.dispatch.analytic_ik
    assert sk.ik.numeric_ik is sk.ik.newton.numeric_ik is sk.Chain.numeric_ik
    with pytest.raises(AttributeError, match="no_such_name"):
        sk.ik.no_such_name  # noqa: B018


def test_the_engines_share_one_kernel_for_each_idea():
    from screwkit.ik import _closed_form, spherical_wrist, stanford, subproblems, ur

    assert stanford.rotation_angles is ur.rotation_angles is subproblems.rotation_angles
    assert stanford.meeting_points is subproblems.meeting_points
    assert ur.sinusoid_angles is subproblems.sinusoid_angles
    assert spherical_wrist.plane_angles is ur.plane_angles is subproblems.plane_angles
    assert spherical_wrist.Turn is ur.Turn is _closed_form.Turn
    assert spherical_wrist.branches is ur.branches is stanford.branches
    assert spherical_wrist.flip_measure is stanford.flip_measure
    assert spherical_wrist.arm_scale is ur.arm_scale is stanford.arm_scale
    for engine in (spherical_wrist, ur, stanford):  # tolerances from one place
        assert not {"CLIP_TOL", "SINGULAR_TOL"} & set(vars(engine))


def test_no_bare_tolerance_in_the_family():
    """Every small float of screwkit/ik is a named constant of screwkit.tolerances."""
    folder = Path(sk.ik.__file__).parent
    small = [
        f"{path.name}:{node.lineno}: {node.value}"
        for path in folder.glob("*.py")
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8")))
        if isinstance(node, ast.Constant)
        and isinstance(node.value, float)
        and 0 < abs(node.value) < 1e-3
    ]
    assert not small


def rotation(w, theta):
    """R(w, theta) by sk.rot_axis, independent of the kernels under test."""
    return np.asarray(sk.rot_axis(w, theta), dtype=float)


def unit(v):
    return v / np.linalg.norm(v)


def test_sinusoid_angles_solve_their_equation():
    rng = np.random.default_rng(3)
    A, B = rng.normal(size=(2, 50))
    theta = rng.uniform(-np.pi, np.pi, 50)
    C = A * np.cos(theta) + B * np.sin(theta)  # reachable by construction
    phi, half, excess, radius2 = sk.ik.subproblems.sinusoid_angles(A, B, C)
    assert np.all(excess >= -1e-12) and np.allclose(radius2, A**2 + B**2)
    for angle in (phi - half, phi + half):
        assert np.allclose(A * np.cos(angle) + B * np.sin(angle), C, atol=1e-12)
    assert np.allclose(
        np.minimum(*(np.abs(wrapped(a - theta)) for a in (phi - half, phi + half))),
        0,
        atol=1e-7,
    )
    _, _, excess, _ = sk.ik.subproblems.sinusoid_angles(3.0, 4.0, 5.5)  # |C| > 5
    assert excess == 25.0 - 5.5**2


def test_rotation_angles_recover_a_rotation():
    rng = np.random.default_rng(4)
    for _ in range(20):
        w, a = unit(rng.normal(size=3)), rng.normal(size=3)
        theta = rng.uniform(-3, 3)
        b = 1.7 * rotation(w, theta) @ a + 0.4 * w  # scaled and moved along w
        assert np.isclose(sk.ik.subproblems.rotation_angles(w, a, b), theta)


def test_meeting_points_are_the_middle_point_of_two_rotations():
    rng = np.random.default_rng(5)
    for _ in range(20):
        w1, w2, x = (
            unit(rng.normal(size=3)),
            unit(rng.normal(size=3)),
            rng.normal(size=3),
        )
        theta1, theta2 = rng.uniform(-3, 3, 2)
        middle = rotation(w2, theta2) @ x
        y = rotation(w1, theta1) @ middle
        z, gamma2 = sk.ik.subproblems.meeting_points(w1, w2, x, y)
        assert gamma2 >= -1e-12 and z.shape == (2, 3)
        assert min(np.linalg.norm(z - middle, axis=1)) < 1e-9
        assert np.allclose(z @ w2, x @ w2) and np.allclose(z @ w1, y @ w1)


def in_millimetres(chain):
    """The same arm with every length times 1000: its screws' linear parts and its
    home position."""
    S = chain.screw_axes().copy()
    S[:, 3:] *= 1000
    M = chain.home().copy()
    M[:3, 3] *= 1000
    return sk.Chain.from_screws(S, M, qlim=chain.qlim)


@pytest.mark.parametrize("name", ["puma", "kawasaki"])
def test_an_arm_in_millimetres_gets_the_same_answers(name):
    """The tolerances are relative to the arm's size: the same arm in mm gives the same
    angles and labels, at generic poses and on the shoulder and wrist singularities."""
    arm = ARMS[name]()
    mm = in_millimetres(arm)
    q = np.array(
        [
            [0.3, 0.5, -2.0, 0.4, 0.7, 0.2],
            [-1.0, 0.9, 0.5, -0.3, 1.2, 2.0],
            [0.2, 0.4, -1.1, 0.7, 0.0, 0.3],  # the wrist singular: q5 = 0
            [0.3, np.pi / 2, np.arctan2(A3, D4) - np.pi / 2, 0.4, 0.5, 0.6],  # PUMA:
        ]  # the shoulder singular (test_shoulder_singularity_issue_16)
    )
    T = arm.fk(q)
    T_mm = T.copy()
    T_mm[:, :3, 3] *= 1000
    assert np.allclose(mm.fk(q)[:, :3, 3], T_mm[:, :3, 3], atol=1e-9)
    metres, millimetres = analytic_ik_all(arm, T), analytic_ik_all(mm, T_mm)
    assert np.array_equal(np.isnan(metres), np.isnan(millimetres))
    # the same angles as joint values: pi and -pi are one (round-off picks the sign of
    # q4 = pi on the wrist singularity, differently in m and mm on some NumPy versions)
    turn = np.angle(np.exp(1j * (metres - millimetres)))
    assert np.allclose(metres - turn, metres, atol=1e-9, equal_nan=True)
    assert configuration(arm, q) == configuration(mm, q)
    for m, millimetres in zip(analytic_ik(arm, T), analytic_ik(mm, T_mm)):
        assert [s.config for s in m] == [s.config for s in millimetres]
        assert [s.singular for s in m] == [s.singular for s in millimetres]
