"""Redundancy resolution: paths, planar kinematics against the general chain, the exact
manipulability gradient, the null-space projector, tracking accuracy, joint limits, bad
input."""

import functools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import screwkit as sk
from screwkit import redundancy as rd

LENGTHS = np.array([0.3, 0.25, 0.2, 0.15, 0.1])


@functools.cache
def five_link():
    return sk.robots.planar(LENGTHS)


@functools.cache
def circle_path():
    return rd.circle((0.45, 0.25), 0.15, duration=10.0, dt=0.01)


@functools.cache
def start_q():
    return rd.start_configuration(
        five_link(), circle_path().position[0], np.radians([30, -30, -30, -30, -30])
    )


angles = arrays(float, 5, elements=st.floats(-np.pi, np.pi))


def test_circle_starts_at_center_plus_radius_and_runs_counter_clockwise_once():
    p, v = circle_path().position, circle_path().velocity
    assert p.shape == v.shape == (1001, 2) and circle_path().t[-1] == pytest.approx(
        10.0
    )
    assert np.allclose(p[0], [0.6, 0.25]) and np.allclose(p[-1], [0.6, 0.25])
    assert np.allclose(np.linalg.norm(p - [0.45, 0.25], axis=1), 0.15)
    relative = p - [0.45, 0.25]
    assert np.all(
        relative[1:-1, 0] * v[1:-1, 1] - relative[1:-1, 1] * v[1:-1, 0] > 0
    )  # counter-clockwise
    swept = np.unwrap(np.arctan2(relative[:, 1], relative[:, 0]))
    assert swept[-1] - swept[0] == pytest.approx(2 * np.pi)
    # smooth timing: at rest at both ends, and the velocity is the derivative of the
    # position
    assert np.allclose(v[[0, -1]], 0)
    assert np.allclose(
        np.gradient(p, circle_path().t, axis=0)[1:-1], v[1:-1], atol=2e-4
    )


def test_line_runs_from_start_to_end():
    path = rd.line(
        (0.6, -0.2), (0.6, 0.4), duration=4.0, dt=0.01, timing_kind="constant"
    )
    assert np.allclose(path.position[[0, -1]], [[0.6, -0.2], [0.6, 0.4]])
    assert np.allclose(path.velocity, [0, 0.15])
    assert np.allclose(path.position[:, 0], 0.6)


@settings(max_examples=50, deadline=None)
@given(angles)
def test_planar_kinematics_equals_the_general_chain(q):
    points, J = rd.planar_kinematics(LENGTHS, q)
    assert np.allclose(points[-1], five_link().fk(q)[:2, 3], atol=1e-12)
    assert np.allclose(J, five_link().geometric_jacobian(q)[:2], atol=1e-12)


@settings(max_examples=50, deadline=None)
@given(angles)
def test_manipulability_gradient_is_exact(q):
    w, gradient = rd.manipulability_gradient(LENGTHS, q)
    assert np.isclose(
        w, five_link().manipulability(q, rows="planar"), atol=1e-12
    )  # by singular values
    if (
        w > 0.05
    ):  # central differences of sqrt(det) lose accuracy like 1/w^5 near a singularity
        h = 1e-6
        central = [
            (
                rd.manipulability_gradient(LENGTHS, q + h * e)[0]
                - rd.manipulability_gradient(LENGTHS, q - h * e)[0]
            )
            / (2 * h)
            for e in np.eye(5)
        ]
        assert np.allclose(gradient, central, atol=1e-7)


@settings(max_examples=50, deadline=None)
@given(angles)
def test_null_space_motion_never_moves_the_end_effector(q):
    _, J = rd.planar_kinematics(LENGTHS, q)
    # the identity is exact; J^T (J J^T)^-1 squares the condition number, and so does
    # its round-off
    condition = np.linalg.cond(J)
    if condition < 100:
        tolerance = 1e-14 * condition**2
        J_plus = rd.pseudo_inverse(J)
        assert np.allclose(
            J_plus, np.linalg.pinv(J), rtol=0, atol=tolerance * np.abs(J_plus).max()
        )
        assert np.allclose(J @ (np.eye(5) - J_plus @ J), 0, atol=tolerance)
        phi = rd.manipulability_gradient(LENGTHS, q)[1]
        assert np.allclose(
            J @ (np.eye(5) - J_plus @ J) @ phi,
            0,
            atol=tolerance * (1 + np.abs(phi).max()),
        )


def test_circle_is_tracked_to_a_tenth_of_a_mm_and_null_space_raises_manipulability():
    plain = rd.resolve(five_link(), circle_path(), start_q())
    climbing = rd.resolve(five_link(), circle_path(), start_q(), null_space_gain=5.0)
    for run in (plain, climbing):
        assert run.q.shape == (1001, 5) and run.error.max() < 1e-4
        # the reported position and manipulability belong to the reported q
        assert np.allclose(run.position, five_link().fk(run.q)[:, :2, 3], atol=1e-12)
        assert np.allclose(
            run.manipulability,
            five_link().manipulability(run.q, rows="planar"),
            atol=1e-12,
        )
    assert climbing.manipulability.mean() > plain.manipulability.mean() + 0.01
    assert climbing.manipulability.min() > plain.manipulability.min() + 0.01
    # without the feedback term, Euler integration drifts off the path
    open_loop = rd.resolve(five_link(), circle_path(), start_q(), feedback_gain=0.0)
    assert open_loop.error.max() > 10 * plain.error.max()


def test_joint_limits_clamping_costs_accuracy_and_avoidance_recovers_it():
    limits = np.radians([[-180, 180]] + [[-60, 60]] * 4)
    arm = sk.robots.planar(LENGTHS, qlim=limits)
    assert arm.within_limits(start_q())
    free = rd.resolve(arm, circle_path(), start_q(), null_space_gain=5.0)
    assert np.any(~arm.within_limits(free.q))  # the limits matter on this path
    clamped = rd.resolve(arm, circle_path(), start_q(), joint_limits="clamp")
    avoided = rd.resolve(
        arm, circle_path(), start_q(), null_space_gain=5.0, joint_limits="avoid"
    )
    for run in (clamped, avoided):
        assert np.all((run.q >= limits[:, 0] - 1e-12) & (run.q <= limits[:, 1] + 1e-12))
    assert (
        clamped.limited.any() and clamped.error.max() > 1e-3
    )  # a clamped joint leaves the path
    assert (
        not avoided.limited.any() and avoided.error.max() < 1e-4
    )  # the null space kept clear


def test_two_arm_robot_tracks_two_paths_at_once():
    left, right = sk.robots.two_arm_planar(LENGTHS, separation=0.4)
    assert np.allclose(left.fk(np.zeros(5))[:2, 3], [-0.2 + LENGTHS.sum(), 0])
    paths = [
        rd.circle((-0.4, 0.45), 0.1, 5.0, 0.01),
        rd.line((0.3, 0.3), (0.3, 0.6), 5.0, 0.01),
    ]
    for arm, path, guess in zip(
        (left, right), paths, ([2.0, -0.5, -0.5, -0.5, -0.5], [1.0, 0.5, 0.5, 0.5, 0.5])
    ):
        q0 = rd.start_configuration(arm, path.position[0], guess)
        run = rd.resolve(arm, path, q0, null_space_gain=1.0)
        assert run.error.max() < 1e-4
        assert np.allclose(run.position, arm.fk(run.q)[:, :2, 3], atol=1e-12)


def test_bad_input_is_refused_with_a_clear_message():
    far = rd.circle((0.8, 0.0), 0.3, duration=1.0, dt=0.01)
    with pytest.raises(
        ValueError, match=r"reachable annulus 0.0000 m <= \|p\| <= 1.0000 m"
    ):
        rd.resolve(five_link(), far, start_q())
    with pytest.raises(ValueError, match=r"q0 must have 5 entries"):
        rd.resolve(five_link(), circle_path(), start_q()[:4])
    with pytest.raises(ValueError, match=r"from the path's start"):
        rd.resolve(five_link(), circle_path(), start_q() + 0.1)
    with pytest.raises(ValueError, match="planar arm"):
        rd.resolve(sk.robots.puma560(), circle_path(), np.zeros(6))
    with pytest.raises(TypeError, match="path must be a Path"):
        rd.resolve(five_link(), circle_path().position, start_q())
    with pytest.raises(ValueError, match="stable loop"):
        rd.resolve(five_link(), circle_path(), start_q(), feedback_gain=500.0)
    with pytest.raises(ValueError, match="joint_limits must be"):
        rd.resolve(five_link(), circle_path(), start_q(), joint_limits="soft")
    with pytest.raises(ValueError, match="whole number of steps"):
        rd.circle((0, 0), 0.1, duration=1.0, dt=0.3)
    with pytest.raises(ValueError, match="radius must be a positive number"):
        rd.circle((0, 0), -0.1, duration=1.0, dt=0.01)
    with pytest.raises(ValueError, match=r"center must be a planar point"):
        rd.circle((0, 0, 0), 0.1, duration=1.0, dt=0.01)
    with pytest.raises(ValueError, match="start and end must differ"):
        rd.line((0, 0), (0, 0), duration=1.0, dt=0.01)


def test_damping_slows_the_joints_near_a_singularity():
    arm = sk.robots.planar([0.5, 0.4, 0.3])
    # straight out to full reach at constant speed: the arm ends stretched, J loses rank
    path = rd.line(
        (0.9, 0.0), (1.2, 0.0), duration=1.0, dt=0.01, timing_kind="constant"
    )
    q0 = rd.start_configuration(arm, path.position[0], [0.3, -0.3, -0.3])
    exact = rd.resolve(arm, path, q0)
    damped = rd.resolve(arm, path, q0, damping=0.1)
    largest_step = [np.abs(np.diff(run.q, axis=0)).max() for run in (exact, damped)]
    assert largest_step[1] < 0.8 * largest_step[0]
    assert np.all(np.isfinite(damped.q)) and damped.error.max() < 5e-3


def test_a_negative_null_space_gain_lowers_manipulability():
    # the null-space term follows k grad w: with k < 0 it descends, so w falls below the
    # plain run
    plain = rd.resolve(five_link(), circle_path(), start_q())
    lowering = rd.resolve(five_link(), circle_path(), start_q(), null_space_gain=-2.0)
    assert (
        lowering.error.max() < 1e-3
        and lowering.manipulability.mean() < plain.manipulability.mean() - 0.005
    )


def test_q0_outside_the_limits_is_refused_only_where_the_limits_are_used():
    limits = np.radians([[-180, 180]] + [[-60, 60]] * 4)
    arm = sk.robots.planar(LENGTHS, qlim=limits)
    q0 = rd.start_configuration(
        arm, circle_path().position[0], np.radians([30, 70, -30, -30, -30])
    )
    assert not arm.within_limits(q0)
    joint = int(np.flatnonzero((q0 < limits[:, 0]) | (q0 > limits[:, 1]))[0]) + 1
    for mode in ("clamp", "avoid"):
        with pytest.raises(
            ValueError, match=rf"q0 must lie within .* joint {joint} is"
        ):
            rd.resolve(arm, circle_path(), q0, joint_limits=mode)
    assert (
        rd.resolve(arm, circle_path(), q0).error.max() < 1e-4
    )  # joint_limits=None ignores them


def test_start_configuration_needs_one_iteration_and_reports_its_budget():
    with pytest.raises(
        ValueError, match="max_iterations must be an integer >= 1, got 0"
    ):
        rd.start_configuration(
            five_link(), circle_path().position[0], start_q(), max_iterations=0
        )
    # from the answer itself, no step is needed; from a guess, one Newton step is not
    # enough
    assert np.array_equal(
        rd.start_configuration(
            five_link(), circle_path().position[0], start_q(), max_iterations=1
        ),
        start_q(),
    )
    with pytest.raises(ValueError, match=r"in 1 iterations, got a residual of"):
        rd.start_configuration(
            five_link(), circle_path().position[0], start_q() + 0.3, max_iterations=1
        )


def test_paths_must_be_uniform_in_time_with_two_samples_or_more():
    position = np.zeros((3, 2))
    assert rd.Path([0.0, 0.5, 1.0], position, position).dt == 0.5
    for t, message in [
        ([0.0, 0.5, 1.5], "t must be uniform"),
        ([0.0, 0.0, 0.0], "dt must be positive"),
        ([1.0, 0.5, 0.0], "dt must be positive"),
    ]:
        with pytest.raises(ValueError, match=message):
            rd.Path(t, position, position)
    with pytest.raises(ValueError, match="at least two sample times"):
        rd.Path([0.0], position[:1], position[:1])


def test_timing_ends_at_one_and_refuses_a_zero_duration():
    s, ds = rd.timing(np.array([0.0, 1.0, 2.0]), 2.0)
    assert np.allclose(s, [0.0, 0.5, 1.0]) and np.allclose(
        ds, [0.0, 30 / 16 / 2, 0.0]
    )  # quintic by hand
    with pytest.raises(ValueError, match="duration must be a positive number, got 0.0"):
        rd.timing(np.array([0.0]), 0)
