"""Motion in time against other libraries: Modern Robotics' trajectory functions and
SciPy's Slerp to 1e-12, the time derivative of the Jacobian against Pinocchio's frame
Jacobian time variation (and the Robotics Toolbox's ``jacob0_dot`` where it is
installed) to 1e-10.

``modern_robotics``, SciPy and Pinocchio are reference packages, not the course's:
``tests/reference-requirements.txt`` installs them and CI runs this file on its own
with SCREWKIT_REFERENCES=required (a missing reference then fails). The Robotics
Toolbox is a benchmark reference (benchmarks/requirements.txt): its test is skipped
where it is not installed.
"""

import importlib
import os

import numpy as np
import pytest

import screwkit as sk
from screwkit.motion import trajectory as tr

REQUIRED = os.environ.get("SCREWKIT_REFERENCES") == "required"
INSTALL = "pip install -r tests/reference-requirements.txt"


def reference(module):
    """Import a reference package: required in CI, else skipped when missing."""
    if REQUIRED:
        return importlib.import_module(module)
    return pytest.importorskip(module, reason=f"{module} is not installed: {INSTALL}")


TF, N = 2.7, 41
X_START = sk.transl(1.0, 0.0, 1.0)
X_END = np.array(
    [[0.0, 0.0, 1.0, 0.1], [1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 4.1], [0, 0, 0, 1.0]]
)
METHODS = {3: tr.cubic, 5: tr.quintic}


def test_time_scalings_equal_modern_robotics():
    mr = reference("modern_robotics")
    for t in np.linspace(0, TF, N):
        assert abs(tr.cubic(TF)(t) - mr.CubicTimeScaling(TF, t)) <= 1e-12
        assert abs(tr.quintic(TF)(t) - mr.QuinticTimeScaling(TF, t)) <= 1e-12


@pytest.mark.parametrize("method", sorted(METHODS))
def test_joint_screw_and_cartesian_trajectories_equal_modern_robotics(method):
    mr = reference("modern_robotics")
    times = np.linspace(0, TF, N)
    s = METHODS[method](TF)(times)
    q0 = np.array([1.0, 0.0, 0.0, 1.0, 1.0, 0.2, 0.0])
    q1 = np.array([1.2, 0.5, 0.6, 1.1, 2.0, 2.0, 0.9])
    got = tr.joint_path(q0, q1, METHODS[method](TF), times)[0]
    np.testing.assert_allclose(
        got, mr.JointTrajectory(q0, q1, TF, N, method), rtol=0, atol=1e-12
    )
    for ours, theirs in (
        (tr.screw_path, mr.ScrewTrajectory),
        (tr.cartesian_path, mr.CartesianTrajectory),
    ):
        np.testing.assert_allclose(
            ours(X_START, X_END, s),
            np.array(theirs(X_START, X_END, TF, N, method)),
            rtol=0,
            atol=1e-12,
        )


def test_screw_trajectory_of_random_poses_equals_modern_robotics():
    mr = reference("modern_robotics")
    rng = np.random.default_rng(3)
    for _ in range(10):
        T0 = sk.exp_twist(rng.normal(size=6), 1.0)
        T1 = sk.exp_twist(rng.normal(size=6), 1.0)
        s = tr.quintic(TF)(np.linspace(0, TF, N))
        np.testing.assert_allclose(
            tr.screw_path(T0, T1, s),
            np.array(mr.ScrewTrajectory(T0, T1, TF, N, 5)),
            rtol=0,
            atol=1e-12,
        )


def test_slerp_equals_scipys():
    transform = reference("scipy.spatial.transform")
    rotations = transform.Rotation.random(20, random_state=4)
    s = np.linspace(0, 1, 17)
    for k in range(0, 20, 2):
        pair = rotations[k : k + 2]
        expected = transform.Slerp([0, 1], pair)(s).as_quat(scalar_first=True)
        got = tr.slerp(
            pair[0].as_quat(scalar_first=True), pair[1].as_quat(scalar_first=True), s
        )
        # q and -q are one rotation: compare up to the sign of each sample
        sign = np.sign(np.sum(got * expected, axis=1))[:, None]
        np.testing.assert_allclose(got, sign * expected, rtol=0, atol=1e-12)


def _pinocchio_q(pin, model, chain, q):
    x = pin.neutral(model)
    for name, value in zip(chain.joint_names, q):
        joint = model.joints[model.getJointId(name)]
        if joint.nq == 2:  # a continuous joint: (cos, sin)
            x[joint.idx_q : joint.idx_q + 2] = np.cos(value), np.sin(value)
        else:
            x[joint.idx_q] = value
    return x


def test_jacobian_dot_equals_pinocchios_frame_jacobian_time_variation():
    pin = reference("pinocchio")
    path = sk.urdf.data_file("ur5e.urdf")
    chain = sk.Chain.from_urdf(path, tip_link="tool0")
    model = pin.buildModelFromUrdf(str(path))
    data = model.createData()
    frame = model.getFrameId("tool0")
    joints = [model.joints[model.getJointId(name)] for name in chain.joint_names]
    rng = np.random.default_rng(11)
    Q, dQ = rng.uniform(-np.pi, np.pi, (20, 6)), rng.uniform(-2, 2, (20, 6))
    ours = chain.geometric_jacobian_dot(Q, dQ)
    for k in range(20):
        x = _pinocchio_q(pin, model, chain, Q[k])
        v = np.zeros(model.nv)
        for joint, rate in zip(joints, dQ[k]):
            v[joint.idx_v] = rate
        pin.computeJointJacobiansTimeVariation(model, data, x, v)
        pin.updateFramePlacements(model, data)
        dJ = pin.getFrameJacobianTimeVariation(
            model, data, frame, pin.LOCAL_WORLD_ALIGNED
        )
        columns = [joint.idx_v for joint in joints]
        np.testing.assert_allclose(ours[k], dJ[:, columns], rtol=0, atol=1e-10)


def test_jacobian_dot_and_hessian_equal_the_robotics_toolboxs():
    rtb = pytest.importorskip(
        "roboticstoolbox",
        reason="the Robotics Toolbox is a benchmark reference "
        "(pip install -r benchmarks/requirements.txt)",
    )
    robot = rtb.models.DH.Puma560()
    robot.links[0].d = 0.0  # screwkit's PUMA has its base frame at the shoulder
    puma = sk.robots.puma560()
    rng = np.random.default_rng(12)
    for q, dq in zip(rng.uniform(-2, 2, (10, 6)), rng.uniform(-1, 1, (10, 6))):
        np.testing.assert_allclose(puma.fk(q), robot.fkine(q).A, atol=1e-12)
        np.testing.assert_allclose(
            puma.geometric_jacobian_dot(q, dq), robot.jacob0_dot(q, dq), atol=1e-10
        )
        np.testing.assert_allclose(
            puma.geometric_hessian(q), robot.hessian0(q), atol=1e-10
        )
