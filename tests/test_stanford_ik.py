"""Closed-form IK of the Stanford arm (RRP and a spherical wrist): the generating
configuration among the solutions, four within the boom's travel, a hand-derived boom
length, singular and unreachable poses."""

import numpy as np
import pytest
from builders import stanford

import screwkit as sk
from screwkit import ik
from screwkit.ik.stanford import STRUCTURE

ANGLES = [0, 1, 3, 4, 5]
RNG = np.random.default_rng(1981)


def difference(a, b):
    d = np.array(a, dtype=float) - b
    d[..., ANGLES] = sk.wrap_angle(d[..., ANGLES])
    return np.abs(d).max(-1)


def random_configurations(n):
    low, high = np.full(6, -np.pi), np.full(6, np.pi)
    low[2], high[2] = stanford().qlim[2]
    return RNG.uniform(low, high, (n, 6))


def test_generating_configuration_among_four_within_the_travel():
    for q in random_configurations(200):
        T = stanford().fk(q)
        every = ik.analytic_ik(stanford(), T)
        assert every.structure == STRUCTURE and len(every) == 8
        inside = ik.analytic_ik(stanford(), T, within_limits=True)
        assert len(inside) == 4 and all(s.config[1] == "u" for s in inside)
        for s in every:
            assert np.abs(stanford().fk(s.q) - T).max() <= 1e-9
            assert ik.configuration(stanford(), s.q) == s.config
        assert min(difference(s.q, q) for s in inside) < 1e-9


def test_boom_length_by_hand():
    # every a_i = 0: the wrist centre is at distance sqrt(d2^2 + q3^2) from the shoulder
    # point (0, 0, d1), so q3 = sqrt(|w - o|^2 - d2^2) for the boom pointing forward
    q = np.array([0.4, 1.1, 0.8, 0.3, -0.7, 0.2])
    T = stanford().fk(q)
    wrist = T[:3, 3] - 0.263 * T[:3, 2]
    q3 = np.sqrt(np.sum((wrist - [0, 0, 0.412]) ** 2) - 0.154**2)
    inside = ik.analytic_ik(stanford(), T, within_limits=True)
    assert np.allclose([s.q[2] for s in inside], q3, atol=1e-12)
    assert np.isclose(q3, 0.8, atol=1e-12)


def test_batch_and_prismatic_joint_not_wrapped():
    Q = random_configurations(500)
    S = ik.analytic_ik_all(stanford(), stanford().fk(Q))
    assert S.shape == (500, 8, 6) and not np.isnan(S).any()
    assert np.all(difference(S, Q[:, None]).min(axis=1) < 1e-9)
    assert np.all(S[:, [0, 1, 4, 5], 2] > 0) and np.all(S[:, [2, 3, 6, 7], 2] < 0)


def test_wrist_singularity_is_an_answer():
    q = np.array([0.4, 1.1, 0.8, 0.3, 0.0, 0.2])  # q5 = 0: axes 4 and 6 aligned
    T = stanford().fk(q)
    solutions = ik.analytic_ik(stanford(), T, within_limits=True)
    assert solutions and all(
        np.abs(stanford().fk(s.q) - T).max() <= 1e-9 for s in solutions
    )
    assert all("wrist" in s.singular for s in solutions if abs(s.q[4]) < 1e-9)
    close = [s for s in solutions if np.allclose(s.q[:3], q[:3], atol=1e-9)]
    assert close and all(
        abs(sk.wrap_angle(s.q[3] + s.q[5] - 0.5)) < 1e-9 for s in close
    )


def test_too_close_to_the_shoulder_is_an_empty_answer():
    # the boom's line passes d2 = 0.154 m from the shoulder point: nothing nearer
    T = sk.transl(0.0, 0.05, 0.412) @ sk.homogeneous(sk.rotx(0.0))
    T = T @ sk.transl(0, 0, 0.263)  # wrist centre at 0.05 m from the shoulder
    answer = ik.analytic_ik(stanford(), T)
    assert answer == [] and "closer than the boom's line" in answer.reason


def test_a_prismatic_arm_without_a_wrist_is_refused():
    links = list(stanford().links)
    links[4] = sk.Link.revolute(a=0.1, alpha=np.pi / 2)
    with pytest.raises(ValueError, match="joints 4, 5 and 6 meeting in one point"):
        ik.analytic_ik(sk.Chain(links), np.eye(4))
