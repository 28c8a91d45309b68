"""PUMA 560 closed-form IK (round trips, labels, singularities, reach, limits) and numeric IK."""
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

import screwkit as sk
from screwkit.ik import CONFIGURATIONS, puma560_config, puma560_ik, puma560_ik_all

PUMA = sk.robots.puma560()


def wrapped(angle):
    return np.pi - np.mod(np.pi - angle, 2 * np.pi)


# joint vectors away from the singularities, where the eight solutions are distinct
generic = arrays(float, 6, elements=st.floats(-np.pi, np.pi, allow_nan=False)).filter(
    lambda q: abs(np.sin(q[4])) > 1e-3
    and abs(0.4318 * np.cos(q[1]) + 0.0203 * np.cos(q[1] + q[2]) - 0.4318 * np.sin(q[1] + q[2])) > 1e-3
    and abs(0.0203 * np.sin(q[2]) + 0.4318 * np.cos(q[2])) > 1e-3)


@settings(max_examples=2000, deadline=None)
@given(generic)
def test_round_trip(q):
    T = PUMA.fk(q)
    solutions = puma560_ik(T)
    assert [s.config for s in solutions] == list(CONFIGURATIONS)
    Q = np.array([s.q for s in solutions])
    assert np.max(np.abs(PUMA.fk(Q) - T)) < 1e-10  # every solution reaches the pose
    distances = np.abs(wrapped(Q[:, None] - Q[None])).max(axis=-1) + np.eye(8)
    assert distances.min() > 1e-6  # eight distinct solutions
    generating = np.abs(wrapped(Q - q)).max(axis=-1)
    assert generating.min() < 1e-7  # the configuration we started from is among them
    assert solutions[int(np.argmin(generating))].config == puma560_config(q)
    for s in solutions:  # each label agrees with its geometric definition
        assert puma560_config(s.q) == s.config


def test_batch_matches_single_and_marks_unreachable_with_nan():
    rng = np.random.default_rng(11)
    Q = rng.uniform(-np.pi, np.pi, (50, 6))
    Ts = PUMA.fk(Q)
    Ts[7, :3, 3] = [2.0, 0.0, 0.0]  # out of reach
    batch = puma560_ik_all(Ts)
    assert batch.shape == (50, 8, 6)
    assert np.all(np.isnan(batch[7]))
    for i in (0, 1, 20):
        single = np.array([s.q for s in puma560_ik(Ts[i])])
        assert np.allclose(wrapped(single - batch[i]), 0, atol=1e-12)


def test_wrist_singularity_is_reported_with_a_convention():
    q = np.array([0.2, 0.4, -1.0, 0.7, 0.0, 0.3])  # q5 = 0: joints 4 and 6 aligned
    solutions = puma560_ik(PUMA.fk(q))
    arm_elbow = puma560_config(q)[:2]
    singular = {s.config for s in solutions if "wrist" in s.singular}
    assert singular == {arm_elbow + "n", arm_elbow + "f"}
    for s in solutions:
        assert np.allclose(PUMA.fk(s.q), PUMA.fk(q), atol=1e-10)
    # only q4 + q6 = 1.0 is fixed; the convention q4 = 0 puts it all in q6 (the flip: q4 = pi)
    no_flip, flip = solutions.by_config(arm_elbow + "n"), solutions.by_config(arm_elbow + "f")
    assert np.allclose(no_flip.q, [0.2, 0.4, -1.0, 0.0, 0.0, 1.0], atol=1e-9)
    assert np.allclose(np.abs(flip.q[3]), np.pi) and np.isclose(flip.q[5], 1.0 - np.pi)


def test_out_of_reach_has_a_reason():
    far = puma560_ik(sk.transl(1.0, 0.5, 0.3))
    assert far == [] and "arm reaches from" in far.reason and "0.8641 m" in far.reason
    inside = puma560_ik(sk.transl(0.05, 0.0, 0.3))
    assert inside == [] and "closer than the shoulder offset d3" in inside.reason


def test_limits_and_nearest():
    q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
    solutions = puma560_ik(PUMA.fk(q))
    allowed = puma560_ik(PUMA.fk(q), within_limits=True)
    assert 0 < len(allowed) < len(solutions)
    assert all(PUMA.within_limits(s.q) for s in allowed)
    assert {s.config for s in allowed} == {s.config for s in solutions if PUMA.within_limits(s.q)}
    assert solutions.nearest(q + 0.01).config == "ruf"
    assert puma560_ik(PUMA.fk(q), near=q + 0.01)[0].config == "ruf"


def test_q2_shifted_by_a_turn_into_its_limits():
    # q2 = -170 deg is outside [-45, 225] but q2 = 190 deg is the same angle and inside
    q = np.radians([10, -170, -60, 20, 30, 40])
    ruf = puma560_ik(PUMA.fk(q)).by_config(puma560_config(q))
    assert ruf.within_limits and np.isclose(ruf.q[1], np.radians(190))


def test_numeric_ik_single_and_batch():
    q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
    T = PUMA.fk(q)
    result = sk.ik.numeric_ik(PUMA, T, q + 0.2)
    assert result.success and result.error < 1e-10 and result.iterations < 50
    assert np.allclose(wrapped(result.q - q), 0, atol=1e-8)
    starts = np.random.default_rng(2).uniform(-np.pi, np.pi, (40, 6))
    batch = sk.ik.numeric_ik(PUMA, T, starts)
    assert batch.q.shape == (40, 6) and batch.success.mean() > 0.8
    closed = np.array([s.q for s in puma560_ik(T)])
    for qk in batch.q[batch.success]:  # every converged start lands on one of the eight
        assert np.abs(wrapped(closed - qk)).max(axis=-1).min() < 1e-6


def test_pose_error_of_a_half_turn():
    target = sk.homogeneous(sk.rotz(np.pi))
    error = sk.ik.pose_error(np.eye(4), target)
    assert np.allclose(np.abs(error), [0, 0, 0, 0, 0, np.pi])


def test_bad_input():
    with pytest.raises(ValueError, match="rotation matrix"):
        puma560_ik(np.diag([1.0, 2.0, 1.0, 1.0]))
    with pytest.raises(ValueError, match=r"T must be one pose of shape \(4, 4\)"):
        puma560_ik(np.stack([np.eye(4)] * 2))
    with pytest.raises(ValueError, match="T must be finite"):
        puma560_ik(np.full((4, 4), np.nan))
    with pytest.raises(ValueError, match="PUMA 560's standard-DH structure"):
        puma560_ik(np.eye(4), robot=sk.Chain([sk.Link.revolute(a=1.0)] * 6))
    with pytest.raises(ValueError, match="near must be a joint vector of 6 entries"):
        puma560_ik(PUMA.fk(np.zeros(6)), near=[0, 0])
    with pytest.raises(ValueError, match="q0 must have 6 entries"):
        sk.ik.numeric_ik(PUMA, np.eye(4), np.zeros(4))
    with pytest.raises(TypeError, match="chain must be a Chain"):
        sk.ik.numeric_ik("puma", np.eye(4), np.zeros(6))
