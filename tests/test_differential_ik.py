"""Differential IK with limits (screwkit.motion.differential_ik): the QP equals the
(damped) pseudo-inverse when no limit binds, keeps the limits when one does (checked
by the optimality conditions of the box-constrained least squares, not by the
solver's own output), says why a step is infeasible, and refuses bad input."""

import numpy as np
import pytest

import screwkit as sk
from screwkit.motion import differential_ik as dik


def redundant():
    """A planar 4R arm with joint limits (redundant for the 2 rows 'planar')."""
    return sk.robots.planar([1.0, 0.8, 0.6, 0.4], qlim=[(-2.0, 2.0)] * 4)


def test_without_binding_limits_the_qp_is_the_pseudo_inverse_on_a_6_joint_arm():
    puma = sk.robots.puma560()
    q = np.array([0.1, -0.5, 0.3, 0.2, 0.5, 0.1])
    V = np.array([0.1, 0.05, -0.02, 0.1, 0.0, 0.2])
    qp = dik.qp_step(puma, q, V, 0.01, damping=0.0)
    pinv = dik.pseudo_inverse_step(puma, q, V, 0.01)
    assert qp.feasible and qp.tracked and pinv.feasible and pinv.tracked
    np.testing.assert_allclose(
        qp.dq, np.linalg.solve(puma.geometric_jacobian(q), V), atol=1e-12
    )
    np.testing.assert_allclose(qp.dq, pinv.dq, atol=1e-12)


@pytest.mark.parametrize("damping", [1e-3, 0.1])
def test_on_a_redundant_arm_the_qp_is_the_damped_least_squares(damping):
    arm = redundant()
    q, V = np.array([0.2, 0.4, 0.3, 0.1]), np.array([0.3, -0.2])
    qp = dik.qp_step(arm, q, V, 0.01, rows="planar", damping=damping)
    J = arm.jacobian_rows(q, "planar")
    expected = J.T @ np.linalg.solve(J @ J.T + damping**2 * np.eye(2), V)
    np.testing.assert_allclose(qp.dq, expected, atol=1e-12)
    np.testing.assert_allclose(
        dik.pseudo_inverse_step(arm, q, V, 0.01, rows="planar", damping=damping).dq,
        expected,
        atol=1e-12,
    )


def kkt_residual(J, V, damping, dq, low, high):
    """How far dq is from the optimum of min |J dq - V|^2 + damping^2 |dq|^2 on the
    box: the gradient must vanish on free joints and point outwards on bound ones."""
    g = J.T @ (J @ dq - V) + damping**2 * dq
    free = (dq > low + 1e-12) & (dq < high - 1e-12)
    at_low, at_high = dq <= low + 1e-12, dq >= high - 1e-12
    return max(
        np.abs(g[free]).max(initial=0.0),
        np.maximum(-g[at_low], 0).max(initial=0.0),
        np.maximum(g[at_high], 0).max(initial=0.0),
        np.maximum(low - dq, 0).max(),
        np.maximum(dq - high, 0).max(),
    )


def test_at_a_joint_limit_the_pseudo_inverse_says_it_breaks_it_and_the_qp_keeps_it():
    arm = redundant()
    q = np.array([1.999, 0.4, 0.3, 0.1])  # joint 1 a milliradian below its limit
    V, dt = np.array([-0.5, 0.4]), 0.01
    pinv = dik.pseudo_inverse_step(arm, q, V, dt, rows="planar")
    assert not pinv.feasible and "joint 1 upper position" in pinv.reason
    # undamped: the QP is only convex, DAQP's proximal iterations solve it exactly
    qp = dik.qp_step(arm, q, V, dt, rows="planar", damping=0.0)
    assert qp.feasible and qp.tracked  # the other joints make up for joint 1
    assert q[0] + qp.dq[0] * dt <= 2.0 + 1e-12
    J = arm.jacobian_rows(q, "planar")
    low, high = (arm.qlim[:, 0] - q) / dt, (arm.qlim[:, 1] - q) / dt
    assert kkt_residual(J, V, 0.0, qp.dq, low, high) < 1e-10
    assert "joint 1 upper position" in qp.limited


def test_rate_limits_bind_and_the_step_says_it_tracks_only_part():
    arm = redundant()
    q, V = np.array([0.2, 0.4, 0.3, 0.1]), np.array([0.3, -0.2])
    step = dik.qp_step(arm, q, V, 0.01, rows="planar", v_max=0.05, damping=1e-3)
    assert step.feasible and not step.tracked
    assert np.all(np.abs(step.dq) <= 0.05 + 1e-12)
    assert "velocity" in step.reason
    J = arm.jacobian_rows(q, "planar")
    assert kkt_residual(J, V, 1e-3, step.dq, -0.05, 0.05) < 1e-10


def test_an_infeasible_step_is_an_answer_with_its_reason():
    arm = redundant()
    q, V = np.array([0.2, 0.4, 0.3, 0.1]), np.array([0.3, -0.2])
    exact = dik.qp_step(arm, q, V, 0.01, rows="planar", v_max=0.05, exact=True)
    assert not exact.feasible and np.isnan(exact.dq).all()
    assert "no joint rates give the twist" in exact.reason
    outside = np.array([2.5, 0.4, 0.3, 0.1])  # 0.5 rad past the limit
    stuck = dik.qp_step(arm, outside, V, 0.01, rows="planar", v_max=1.0)
    assert (
        not stuck.feasible and "joint 1 is at 2.5, outside its limits" in stuck.reason
    )


def test_bad_input_is_a_clear_error():
    arm = redundant()
    q = np.zeros(4)
    with pytest.raises(ValueError, match="twist must have 2 entries for rows='planar'"):
        dik.qp_step(arm, q, [1.0, 2.0, 3.0], 0.01, rows="planar")
    with pytest.raises(ValueError, match="dt must be a positive number"):
        dik.qp_step(arm, q, [1.0, 2.0], -0.01, rows="planar")
    with pytest.raises(ValueError, match="v_max must be positive"):
        dik.qp_step(arm, q, [1.0, 2.0], 0.01, rows="planar", v_max=-1.0)
    with pytest.raises(ValueError, match="damping must be a number >= 0"):
        dik.pseudo_inverse_step(arm, q, [1.0, 2.0], 0.01, rows="planar", damping=-1)
    with pytest.raises(TypeError, match="exact must be True or False"):
        dik.qp_step(arm, q, [1.0, 2.0], 0.01, rows="planar", exact="yes")
    with pytest.raises(ValueError, match="q must have 4 entries"):
        dik.qp_step(arm, np.zeros(3), [1.0, 2.0], 0.01, rows="planar")


def test_an_infeasible_qp_step_is_an_answer_not_an_error():
    # joint 1 at 2.5 rad, half a radian past its limit, at most 1 rad/s for 0.01 s
    step = dik.qp_step(
        planar_arm_with_limits(), [2.5, 0.0], [1.0, 0.0], 0.01, rows="planar", v_max=1.0
    )
    assert not step.feasible and "outside its limits" in step.reason


def planar_arm_with_limits():
    return sk.robots.planar([1.0, 1.0], qlim=[(-2.0, 2.0)] * 2)
