"""Chain.from_urdf against Pinocchio on example-robot-data's URDFs: FK and the geometric
Jacobian at random joint vectors within the limits, to 1e-12.

Pinocchio (``pin``) and ``example-robot-data`` are reference packages, not the course's:
``tests/reference-requirements.txt`` installs them and CI runs this file on its own.
"""

import os

import numpy as np
import pytest
from pinocchio_models import INSTALL, REQUIRED, pinocchio_q, robots_folder

import screwkit as sk
import screwkit.ik.ur  # noqa: F401  (sk.ik.ur)

if REQUIRED:
    import pinocchio as pin
else:
    pin = pytest.importorskip(
        "pinocchio", reason=f"Pinocchio is not installed: {INSTALL}"
    )


# (file under robots/, tip link): the four arms of the issue (UR5, not UR5e: the package
# ships the UR5 and the UR10)
ARMS = {
    "panda": ("panda_description/urdf/panda.urdf", "panda_hand_tcp"),
    "ur5": ("ur_description/urdf/ur5_robot.urdf", "tool0"),
    "so101": ("so_arm_description/urdf/so101.urdf", "gripper_frame_link"),
    "z1": ("z1_description/urdf/z1.urdf", "link06"),
}


def _arm_and_model(relative, tip):
    """screwkit's chain of a URDF of example-robot-data, Pinocchio's model and data of
    it, the tip's frame id, and the velocity index of each of the chain's joints."""
    path = os.path.join(robots_folder(), relative)
    chain = sk.Chain.from_urdf(path, tip_link=tip)
    model = pin.buildModelFromUrdf(path)
    columns = [model.joints[model.getJointId(name)].idx_v for name in chain.joint_names]
    return chain, model, model.createData(), model.getFrameId(tip), columns


def _limits_within_a_turn(chain):
    """The joint limits (low, high), each clipped to [-pi, pi]."""
    low, high = chain.qlim.T
    return np.maximum(low, -np.pi), np.minimum(high, np.pi)


@pytest.mark.parametrize("arm", sorted(ARMS))
def test_fk_and_jacobian_agree_with_pinocchio(arm):
    chain, model, data, frame, columns = _arm_and_model(*ARMS[arm])
    low, high = _limits_within_a_turn(chain)
    rng = np.random.default_rng(22)
    Q = rng.uniform(low, high, (25, chain.n))
    T, J = chain.fk(Q), chain.geometric_jacobian(Q)
    for k, q in enumerate(Q):
        x = pinocchio_q(pin, model, chain, q)
        pin.framesForwardKinematics(model, data, x)
        reference = data.oMf[frame].homogeneous
        np.testing.assert_allclose(T[k], reference, rtol=0, atol=1e-12)
        J_pin = pin.computeFrameJacobian(model, data, x, frame, pin.LOCAL_WORLD_ALIGNED)
        np.testing.assert_allclose(J[k], J_pin[:, columns], rtol=0, atol=1e-12)


@pytest.mark.parametrize(
    "relative, tip",
    [
        ("ur_description/urdf/ur5_robot.urdf", "tool0"),
        ("ur_description/urdf/ur10_robot.urdf", "tool0"),
        ("z1_description/urdf/z1.urdf", "link06"),
    ],
)
def test_vendor_urdfs_of_ur_type_arms_are_solved_in_closed_form(relative, tip):
    chain = sk.Chain.from_urdf(os.path.join(robots_folder(), relative), tip_link=tip)
    assert sk.ik.structure(chain) == sk.ik.ur.STRUCTURE
    low, high = (
        np.maximum(chain.qlim[:, 0], -np.pi),
        np.minimum(chain.qlim[:, 1], np.pi),
    )
    for q in np.random.default_rng(8).uniform(low, high, (20, 6)):
        T = chain.fk(q)
        solutions = sk.ik.analytic_ik(chain, T)
        assert max(np.abs(chain.fk(s.q) - T).max() for s in solutions) <= 1e-9
        assert min(np.abs(sk.wrap_angle(s.q - q)).max() for s in solutions) < 1e-9


@pytest.mark.parametrize(
    "relative, tip, fixed",
    [
        ("kinova_description/robots/kinova.urdf", "j2s6s200_end_effector", None),
        ("xarm_description/urdf/xarm7.urdf", "link7", 2),
        ("panda_description/urdf/panda.urdf", "panda_hand_tcp", 2),
    ],
)
def test_vendor_arms_get_every_ik_solution(relative, tip, fixed):
    """Every IK solution of any 6R arm, on vendor URDFs: the Kinova Jaco 2 (6R) and,
    with joint 3 held, the xArm 7 and the Panda (general 6R arms left). Everything is
    checked by Pinocchio: the poses are its forward kinematics, each solution must meet
    its pose there, the generating configuration must be among them, and no solution
    that Newton on Pinocchio's kinematics reaches from 30 random starts may be
    missing."""
    chain, model, data, frame, columns = _arm_and_model(relative, tip)
    free = [j for j in range(chain.n) if j != fixed]

    def pose(q):
        pin.framesForwardKinematics(model, data, pinocchio_q(pin, model, chain, q))
        return data.oMf[frame].homogeneous.copy()

    def newton(q, T):
        """Gauss-Newton on the body error twist log(T(q)^-1 T), the held joint
        kept; the solution, or None."""
        q = q.copy()
        for _ in range(100):
            x = pinocchio_q(pin, model, chain, q)
            pin.framesForwardKinematics(model, data, x)
            error = pin.log6(data.oMf[frame].inverse() * pin.SE3(T)).vector
            if np.linalg.norm(error) < 1e-13:
                return q
            J = pin.computeFrameJacobian(model, data, x, frame, pin.LOCAL)
            step = np.linalg.lstsq(J[:, columns][:, free], error, rcond=None)[0]
            q[free] += step / max(1.0, np.abs(step).max() / 0.5)
        return None

    low, high = _limits_within_a_turn(chain)
    rng = np.random.default_rng(34)
    for q in rng.uniform(low, high, (4, chain.n)):
        T = pose(q)
        held = None if fixed is None else {fixed: q[fixed]}
        solutions = sk.ik.analytic_ik(chain, T, fixed=held)
        assert solutions.reason is None and len(solutions) >= 2
        Q = np.array([s.q for s in solutions])
        for s in Q:
            np.testing.assert_allclose(pose(s), T, rtol=0, atol=1e-9)
        assert np.abs(sk.wrap_angle(Q - q)).max(axis=1).min() < 1e-9
        for start in rng.uniform(-np.pi, np.pi, (30, chain.n)):
            if fixed is not None:
                start[fixed] = q[fixed]
            found = newton(start, T)
            if found is not None:
                gap = np.abs(sk.wrap_angle(Q - found)).max(axis=1).min()
                assert gap < 1e-6, f"Newton found {found}, missing"
