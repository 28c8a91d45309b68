"""Trajectories (screwkit.motion.trajectory): time scalings against their closed forms
and limits, derivatives against differences, screw and Cartesian paths by their
properties (ends, constant twist, straight line), SE(2) against SE(3), slerp, via
points, a path through the IK, bad input. Modern Robotics and SciPy are compared in
tests/test_motion_references.py."""

import numpy as np
import pytest

import screwkit as sk
from screwkit.motion import trajectory as tr

PROFILES = [tr.cubic, tr.quintic]


def pose(seed):
    rng = np.random.default_rng(seed)
    return sk.exp_twist(rng.normal(size=6), 1.0)


@pytest.mark.parametrize("profile", PROFILES)
def test_polynomial_scalings_start_and_end_at_rest(profile):
    scaling = profile(2.5)
    s, ds, dds = scaling.evaluate([0.0, 2.5])
    np.testing.assert_allclose(s, [0, 1], atol=1e-15)
    np.testing.assert_allclose(ds, [0, 0], atol=1e-15)
    if profile is tr.quintic:
        np.testing.assert_allclose(dds, [0, 0], atol=1e-15)
    else:  # the cubic starts with d2s/dt2 = 6 / T^2
        np.testing.assert_allclose(dds, [6 / 2.5**2, -6 / 2.5**2])


@pytest.mark.parametrize(
    "scaling",
    [
        tr.cubic(1.7),
        tr.quintic(1.7),
        tr.trapezoidal(v_max=1.2, a_max=3.0),
        tr.trapezoidal(1.5, v_max=1.0),
    ],
)
def test_derivatives_equal_differences(scaling):
    h = 1e-6
    t = np.linspace(0.01, scaling.duration - 0.01, 37)
    s, ds, dds = scaling.evaluate(t)
    np.testing.assert_allclose(
        ds, (scaling(t + h) - scaling(t - h)) / (2 * h), atol=1e-8
    )
    # a trapezoid's acceleration jumps: compare away from its two switches
    ramp = scaling.peak_velocity / scaling.peak_acceleration
    away = (np.abs(t - ramp) > 1e-3) & (np.abs(t - (scaling.duration - ramp)) > 1e-3)
    difference = (scaling.evaluate(t + h)[1] - scaling.evaluate(t - h)[1]) / (2 * h)
    np.testing.assert_allclose(dds[away], difference[away], atol=1e-6)


@pytest.mark.parametrize("profile", PROFILES)
def test_the_fastest_polynomial_meets_its_binding_limit(profile):
    scaling = profile(v_max=2.0, a_max=50.0)
    t = np.linspace(0, scaling.duration, 100001)
    s, ds, dds = scaling.evaluate(t)
    # the velocity limit binds here: peak ds/dt is 2.0, reached at t = T/2
    np.testing.assert_allclose(ds.max(), 2.0, rtol=1e-12)
    assert np.abs(dds).max() <= 50.0
    # hand values: T = 1.5 / v for the cubic, 15 / (8 v) for the quintic
    expected = 1.5 / 2.0 if profile is tr.cubic else 15 / 16
    assert scaling.duration == pytest.approx(expected, rel=1e-15)
    slow = profile(v_max=100.0, a_max=2.0)
    t = np.linspace(0, slow.duration, 100001)
    np.testing.assert_allclose(np.abs(slow.evaluate(t)[2]).max(), 2.0, rtol=1e-8)


def test_trapezoid_minimum_time_and_triangle():
    # v = 0.5, a = 2: ramps of 0.25 s covering 1/16 each, cruise 0.875 of s at 0.5
    scaling = tr.trapezoidal(v_max=0.5, a_max=2.0)
    assert scaling.duration == pytest.approx(1 / 0.5 + 0.5 / 2.0, rel=1e-15)
    s, ds, dds = scaling.evaluate([0.25, 1.125, scaling.duration])  # 1.125 = T / 2
    np.testing.assert_allclose(s, [1 / 16, 0.5, 1.0], atol=1e-15)
    np.testing.assert_allclose(ds, [0.5, 0.5, 0.0], atol=1e-15)
    # v^2 > a: the ramps meet, a triangle of duration 2 / sqrt(a) peaking at sqrt(a)
    triangle = tr.trapezoidal(v_max=5.0, a_max=4.0)
    assert triangle.duration == pytest.approx(1.0)
    assert triangle.evaluate(0.5)[1] == pytest.approx(2.0)
    assert triangle(1.0) == pytest.approx(1.0)


def test_trapezoid_from_duration_and_one_limit():
    with_v = tr.trapezoidal(2.0, v_max=0.75)
    assert with_v(2.0) == pytest.approx(1.0, abs=1e-15)
    with_a = tr.trapezoidal(2.0, a_max=2.0)
    assert with_a(2.0) == pytest.approx(1.0, abs=1e-15)
    assert with_a.peak_velocity <= 2.0 * 2.0 / 2


def test_fastest_joint_scaling_is_bound_by_the_slowest_joint():
    q0, q1 = np.zeros(3), np.array([1.0, -2.0, 0.5])
    scaling = tr.fastest_joint_scaling(tr.quintic, q0, q1, [1.0, 1.0, 1.0], 100.0)
    # joint 2 moves 2 rad at 1 rad/s: ds/dt <= 0.5, T = 15/8 / 0.5
    assert scaling.duration == pytest.approx(15 / 8 / 0.5)
    _, dq, _ = tr.joint_path(q0, q1, scaling, np.linspace(0, scaling.duration, 2001))
    assert np.abs(dq).max() == pytest.approx(1.0, rel=1e-6)


def test_screw_path_ends_and_moves_with_one_constant_twist():
    T0, T1 = pose(1), pose(2)
    s = np.linspace(0, 1, 11)
    path = tr.screw_path(T0, T1, s)
    assert path.shape == (11, 4, 4)
    np.testing.assert_allclose(path[0], T0, atol=1e-14)
    np.testing.assert_allclose(path[-1], T1, atol=1e-13)
    # each step is the same body motion: T_k^-1 T_{k+1} is one constant pose
    steps = [sk.inv(path[k]) @ path[k + 1] for k in range(10)]
    for step in steps[1:]:
        np.testing.assert_allclose(step, steps[0], atol=1e-13)
    assert tr.screw_path(T0, T1, 0.5).shape == (4, 4)


def test_cartesian_path_moves_the_origin_on_a_line_and_turns_like_the_screw():
    T0, T1 = pose(3), pose(4)
    s = np.linspace(0, 1, 9)
    line, screw = tr.cartesian_path(T0, T1, s), tr.screw_path(T0, T1, s)
    expected = T0[:3, 3] + s[:, None] * (T1[:3, 3] - T0[:3, 3])
    np.testing.assert_allclose(line[:, :3, 3], expected, atol=1e-14)
    np.testing.assert_allclose(line[:, :3, :3], screw[:, :3, :3], atol=1e-13)
    np.testing.assert_allclose(line[-1], T1, atol=1e-13)


def test_pure_translation_paths_are_equal():
    T0, T1 = sk.transl(0, 0, 0), sk.transl(1, 2, 3)
    s = np.linspace(0, 1, 5)
    np.testing.assert_allclose(tr.screw_path(T0, T1, s), tr.cartesian_path(T0, T1, s))


def planar(angle, x, y):
    c, s = np.cos(angle), np.sin(angle)
    return np.array([[c, -s, x], [s, c, y], [0, 0, 1.0]])


def embed(P):
    """An SE(2) pose as the SE(3) pose that turns about z."""
    T = np.eye(4)
    T[:2, :2], T[:2, 3] = P[:2, :2], P[:2, 2]
    return T


@pytest.mark.parametrize("angles", [(0.3, 2.5), (-2.9, 2.9), (1.0, 1.0)])
def test_se2_paths_equal_the_se3_paths_of_the_same_planar_poses(angles):
    P0, P1 = planar(angles[0], 0.5, -1.0), planar(angles[1], 2.0, 0.7)
    s = np.linspace(0, 1, 7)
    for path in (tr.screw_path, tr.cartesian_path):
        planar_path = path(P0, P1, s)
        spatial = path(embed(P0), embed(P1), s)
        np.testing.assert_allclose(
            planar_path,
            np.array(
                [[[*T[0, [0, 1, 3]]], [*T[1, [0, 1, 3]]], [0, 0, 1]] for T in spatial]
            ),
            atol=1e-13,
        )


def test_slerp_keeps_unit_norm_and_constant_angular_speed():
    a = sk.quaternion_from_rotation(pose(5)[:3, :3])
    b = sk.quaternion_from_rotation(pose(6)[:3, :3])
    s = np.linspace(0, 1, 21)
    out = tr.slerp(a, b, s)
    np.testing.assert_allclose(np.linalg.norm(out, axis=1), 1.0, atol=1e-15)
    angles = [2 * np.arccos(min(1.0, abs(out[k] @ out[k + 1]))) for k in range(20)]
    np.testing.assert_allclose(angles, angles[0], atol=1e-12)
    # the shorter way: b and -b give the same path
    np.testing.assert_allclose(tr.slerp(a, -b, s), out, atol=1e-15)


def test_via_points_pass_through_and_keep_velocity_continuous():
    times = [0.0, 1.0, 2.5, 3.0]
    points = [[0.0, 1.0], [1.0, 0.0], [2.0, 0.5], [1.5, 0.5]]
    motion = tr.via_points(times, points)
    q, dq, _ = motion.evaluate(times)
    np.testing.assert_allclose(q, points, atol=1e-15)
    np.testing.assert_allclose(dq[[0, -1]], 0.0, atol=1e-15)
    # coordinate 0 rises then falls at t = 2.5: it stops there (Craig's rule)
    assert dq[2, 0] == 0.0 and dq[1, 0] == pytest.approx((1.0 + 1.0 / 1.5) / 2)
    for t in times[1:-1]:
        left, right = motion.evaluate([t - 1e-9, t + 1e-9])[1]
        np.testing.assert_allclose(left, right, atol=1e-7)


def test_a_line_through_the_pumas_wrist_singularity_is_named():
    """The PUMA at q5 = 0 has joints 4 and 6 aligned: a straight line of the tool
    through that pose meets the wrist singularity; the IK path says where and stays on
    its branch."""
    puma = sk.robots.puma560()
    qa = np.array([0.2, -0.6, 0.3, 0.4, 0.3, -0.2])
    qb = np.array([0.2, -0.6, 0.3, 0.4, -0.3, -0.2])
    s = np.linspace(0, 1, 41)
    poses = tr.cartesian_path(puma.fk(qa), puma.fk(qb), s)
    result = tr.follow_path(puma, poses, q_start=qa)
    assert result.reached.all()
    np.testing.assert_allclose(puma.fk(result.q), poses, atol=1e-10)
    assert result.singular[20] and not result.singular[0] and not result.singular[-1]
    assert np.all(np.abs(np.diff(result.q, axis=0)) < 1.0)  # no jump of a whole turn
    numeric = tr.follow_path(puma, poses[:5], q_start=qa, method="numeric")
    np.testing.assert_allclose(numeric.q, result.q[:5], atol=1e-8)


def test_bad_input_is_a_clear_error():
    with pytest.raises(ValueError, match="v_max must be a positive number"):
        tr.cubic(v_max=-1.0)
    with pytest.raises(ValueError, match="duration must be at least the 1.875 s"):
        tr.quintic(0.5, v_max=1.0)
    with pytest.raises(ValueError, match="needs a duration or a limit"):
        tr.cubic()
    with pytest.raises(ValueError, match="two of duration, v_max and a_max"):
        tr.trapezoidal(1.0, v_max=1.0, a_max=1.0)
    with pytest.raises(ValueError, match=r"v_max \* duration must lie in \(1, 2\]"):
        tr.trapezoidal(3.0, v_max=1.0)
    with pytest.raises(ValueError, match="a_max \\* duration\\^2 must be at least 4"):
        tr.trapezoidal(1.0, a_max=1.0)
    with pytest.raises(ValueError, match=r"t must lie in \[0, 2\]"):
        tr.cubic(2.0).evaluate([0.0, 2.5])
    with pytest.raises(ValueError, match="times must increase strictly"):
        tr.via_points([0.0, 2.0, 1.0], [0.0, 1.0, 2.0])
    with pytest.raises(ValueError, match="points must have 3 rows"):
        tr.via_points([0.0, 1.0, 2.0], [0.0, 1.0])
    with pytest.raises(ValueError, match="rotation block of T_end"):
        tr.screw_path(np.eye(4), 2 * np.eye(4) - np.diag([0, 0, 0, 1.0]), 0.5)
    with pytest.raises(ValueError, match="T_start must have last row"):
        tr.cartesian_path(np.ones((3, 3)), np.eye(3), 0.5)
    with pytest.raises(ValueError, match="q_end must be a unit quaternion"):
        tr.slerp([1.0, 0, 0, 0], [2.0, 0, 0, 0], 0.5)
    with pytest.raises(TypeError, match="profile must be"):
        tr.fastest_joint_scaling(max, [0.0], [1.0], 1.0, 1.0)
    with pytest.raises(ValueError, match="a_max must be positive"):
        tr.fastest_joint_scaling(tr.cubic, [0.0], [1.0], 1.0, -1.0)
    with pytest.raises(TypeError, match="scaling must be a TimeScaling"):
        tr.joint_path([0.0], [1.0], 2.0, 0.5)
    with pytest.raises(ValueError, match="q_start is needed"):
        tr.follow_path(sk.robots.puma560(), np.eye(4)[None], method="numeric")


# ---- sizes and shapes refused clearly -------------------------------------


def test_too_many_times_are_refused_before_the_array_is_built():
    # 10^10 times are 80 GB of floats (NumPy's MemoryError before)
    with pytest.raises(ValueError, match=r"count=10000000000 times.*80 GB.*fewer"):
        tr.quintic(2.0).times(10**10)
    assert tr.quintic(2.0).times(5).tolist() == [0.0, 0.5, 1.0, 1.5, 2.0]


def test_too_many_path_samples_are_refused_before_the_poses_are_built():
    # 2 x 10^8 samples (a broadcast view, no memory) would be 25.6 GB of 4 x 4 poses
    s = np.broadcast_to(0.5, (2 * 10**8,))
    for path in (tr.screw_path, tr.cartesian_path):
        with pytest.raises(ValueError, match="200000000 samples of s.*fewer s"):
            path(np.eye(4), pose(1), s)
    with pytest.raises(ValueError, match="200000000 samples"):
        tr.slerp([1.0, 0, 0, 0], [0.0, 1.0, 0, 0], s)
    with pytest.raises(ValueError, match="200000000 times t"):
        tr.joint_path([0.0] * 6, [1.0] * 6, tr.cubic(1.0), s)
    motion = tr.via_points([0.0, 1.0], [[0.0] * 6, [1.0] * 6])
    with pytest.raises(ValueError, match="200000000 times t"):
        motion.evaluate(s)


def test_via_point_velocities_must_have_the_shape_of_the_points():
    times, points = [0.0, 1.0, 2.0], np.zeros((3, 2))
    # the wrong size: NumPy's "cannot reshape array of size 3 into shape (3,2)" before
    with pytest.raises(ValueError, match=r"velocities must have the shape of points"):
        tr.via_points(times, points, velocities=[1.0, 2.0, 3.0])
    # the same size, another shape: each velocity went to the wrong point before
    with pytest.raises(ValueError, match=r"\(3, 2\).*got shape \(2, 3\)"):
        tr.via_points(times, points, velocities=np.ones((2, 3)))
    # one coordinate: the shape of the points, (M,)
    motion = tr.via_points(times, [0.0, 1.0, 0.0], velocities=[0.0, 0.5, 0.0])
    assert motion.evaluate(1.0)[1].tolist() == [0.5]


def test_an_out_of_range_time_is_named_not_printed_with_the_whole_array():
    # the message quoted every time given before (some MB here); t[k] = 2 k / 999999
    # passes 1 first at k = 500000, and k = 500000 ... 999999 are outside
    motion = tr.via_points([0.0, 1.0], [0.0, 1.0])
    t = np.linspace(0.0, 2.0, 10**6)
    with pytest.raises(ValueError, match=r"t\[500000\] = 1\.000001") as e:
        motion.evaluate(t)
    assert len(str(e.value)) < 200 and "500000 of 1000000 outside" in str(e.value)
