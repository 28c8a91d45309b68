"""The zoo against its published tables, written out here independently of screwkit's DH
code, and against example-robot-data's URDFs through Pinocchio where they exist (the
Panda; the UR5 for the UR's DH frames, as the package ships no UR5e)."""

import os

import numpy as np
import pinocchio_models
import pytest
from pinocchio_models import INSTALL
from references import dh_modified, dh_standard

import screwkit as sk

try:
    import pinocchio as pin
except ImportError:  # a reference package (tests/reference-requirements.txt)
    pin = None

REQUIRED = os.environ.get("SCREWKIT_REFERENCES") == "required"
H = np.pi / 2


# The published tables. UR5e: Universal Robots' DH page; (theta offset, d, a, alpha).
UR5E = [
    (0, 0.1625, 0, H),
    (0, 0, -0.425, 0),
    (0, 0, -0.3922, 0),
    (0, 0.1333, 0, H),
    (0, 0.0997, 0, -H),
    (0, 0.0996, 0, 0),
]
# Panda: Franka's documentation, (a_{i-1}, alpha_{i-1}, d_i), then the flange d = 0.107.
PANDA = [
    (0, 0, 0.333),
    (0, -H, 0),
    (0, H, 0.316),
    (0.0825, H, 0),
    (-0.0825, -H, 0.384),
    (0, H, 0),
    (0.088, H, 0),
]
# iiwa 14 R820 (Faria et al. 2018): (d, alpha), a = 0.
IIWA = [(0.36, -H), (0, H), (0.42, H), (0, -H), (0.4, -H), (0, H), (0.126, 0)]
# Stanford arm (Corke's mdl_stanford): (theta, d, a, alpha); joint 3 is d = q3.
STANFORD = [
    (0, 0.412, 0, -H),
    (0, 0.154, 0, H),
    (-H, None, 0, 0),
    (0, 0, 0, -H),
    (0, 0, 0, H),
    (0, 0.263, 0, 0),
]
# UR5 (for the URDF check): Universal Robots' DH page, UR5 row.
UR5 = [
    (0, 0.089159, 0, H),
    (0, 0, -0.425, 0),
    (0, 0, -0.39225, 0),
    (0, 0.10915, 0, H),
    (0, 0.09465, 0, -H),
    (0, 0.0823, 0, 0),
]


def table_fk(q, kind):
    T = np.eye(4)
    if kind == "ur5e":
        for qi, (offset, d, a, alpha) in zip(q, UR5E):
            T = T @ dh_standard(qi + offset, d, a, alpha)
    elif kind == "panda":
        for qi, (a, alpha, d) in zip(q, PANDA):
            T = T @ dh_modified(qi, d, a, alpha)
        T = T @ dh_modified(0, 0.107, 0, 0)
    elif kind == "iiwa14":
        for qi, (d, alpha) in zip(q, IIWA):
            T = T @ dh_standard(qi, d, 0, alpha)
    elif kind == "stanford":
        for qi, (theta, d, a, alpha) in zip(q, STANFORD):
            T = T @ (
                dh_standard(theta, qi, a, alpha)
                if d is None
                else dh_standard(theta + qi, d, a, alpha)
            )
    return T


@pytest.mark.parametrize("kind", ["ur5e", "panda", "iiwa14", "stanford"])
def test_zoo_matches_its_published_table(kind):
    chain = getattr(sk.robots, kind)()
    rng = np.random.default_rng(7)
    low, high = (
        np.maximum(chain.qlim[:, 0], -np.pi),
        np.minimum(chain.qlim[:, 1], np.pi),
    )
    Q = rng.uniform(low, high, (50, chain.n))
    T = chain.fk(Q)
    for k, q in enumerate(Q):
        np.testing.assert_allclose(T[k], table_fk(q, kind), rtol=0, atol=1e-12)
    assert chain.within_limits(Q).all()


def test_published_poses_at_zero():
    # UR5e stretched out along -x of the base; the iiwa standing straight up (1.306 m)
    p = sk.robots.ur5e().fk(np.zeros(6))[:3, 3]
    np.testing.assert_allclose(p, [-0.8172, -0.2329, 0.0628], atol=1e-15)
    p = sk.robots.iiwa14().fk(np.zeros(7))[:3, 3]
    np.testing.assert_allclose(p, [0, 0, 1.306], atol=1e-15)
    # the Panda's flange at its published zero pose: x = a3 + a4... = 0.088, z = 0.926
    p = sk.robots.panda().fk(np.zeros(7))[:3, 3]
    np.testing.assert_allclose(p, [0.088, 0, 0.333 + 0.316 + 0.384 - 0.107], atol=1e-15)


def robots_folder():
    """example-robot-data's robots/ folder, with Pinocchio to read its URDFs."""
    if pin is None:
        message = f"Pinocchio is not installed: {INSTALL}"
        if REQUIRED:
            pytest.fail(message)
        pytest.skip(message)
    return pinocchio_models.robots_folder()


def pinocchio_poses(path, Q, frame, base_frame=None):
    model = pin.buildModelFromUrdf(path)
    data = model.createData()
    poses = []
    for q in Q:
        x = pin.neutral(model)
        x[: len(q)] = q
        pin.framesForwardKinematics(model, data, x)
        T = data.oMf[model.getFrameId(frame)].homogeneous
        if base_frame is not None:
            T = np.linalg.inv(data.oMf[model.getFrameId(base_frame)].homogeneous) @ T
        poses.append(T)
    return np.array(poses)


def test_panda_matches_frankas_urdf():
    path = os.path.join(robots_folder(), "panda_description/urdf/panda.urdf")
    panda = sk.robots.panda()
    Q = np.random.default_rng(3).uniform(*panda.qlim.T, (30, 7))
    np.testing.assert_allclose(
        panda.fk(Q), pinocchio_poses(path, Q, "panda_link8"), rtol=0, atol=1e-12
    )


def test_ur_dh_frames_match_the_ur5_urdf():
    # ROS's UR description: frame 'base' is the DH base frame, 'tool0' the flange. The
    # file writes pi/2 as 1.57079632679 (4.9e-12 rad short) in three places: over the
    # arm's 1 m that moves the flange by up to about 1.5e-11 m, hence the tolerance
    path = os.path.join(robots_folder(), "ur_description/urdf/ur5_robot.urdf")
    ur5 = sk.Chain.from_table([[o, d, a, al] for o, d, a, al in UR5])
    Q = np.random.default_rng(5).uniform(-np.pi, np.pi, (30, 6))
    np.testing.assert_allclose(
        ur5.fk(Q), pinocchio_poses(path, Q, "tool0", "base"), rtol=0, atol=3e-11
    )


def test_the_shipped_ur5e_urdf_is_the_published_table():
    chain = sk.Chain.from_urdf(sk.urdf.data_file("ur5e.urdf"))
    Q = np.random.default_rng(11).uniform(-np.pi, np.pi, (30, 6))
    for T, q in zip(chain.fk(Q), Q):
        np.testing.assert_allclose(T, table_fk(q, "ur5e"), rtol=0, atol=1e-12)
    with pytest.raises(ValueError, match="one of the shipped files"):
        sk.urdf.data_file("ur5.urdf")


def test_stanford_matches_corkes_toolbox():
    # The Robotics Toolbox for MATLAB, mdl_stanford: stanf.jacob0(q) at this q, printed
    # (4 decimals, rows [v; omega]), and its space screws as a course writes them out
    q = [0.6, 0.19, 0.75, 0.91, 0.11, 0.71]
    jacob0 = [
        [-0.2330, 0.8162, 0.1559, 0.0015, 0.2534, 0],
        [0.0992, 0.5584, 0.1066, 0.0286, -0.0211, 0],
        [0, -0.2134, 0.9820, -0.0033, -0.0673, 0],
        [0, -0.5646, 0, 0.1559, 0.0516, 0.2632],
        [0, 0.8253, 0, 0.1066, 0.9919, 0.0984],
        [1.0, 0, 0, 0.9820, -0.1159, 0.9597],
    ]
    stanford = sk.robots.stanford()
    np.testing.assert_allclose(stanford.geometric_jacobian(q), jacob0, atol=5.1e-5)
    space = [
        [0, 0, 1, 0, 0, 0],
        [0, 1, 0, -0.412, 0, 0],
        [0, 0, 0, 0, 0, 1],
        [0, 0, 1, 0.154, 0, 0],
        [1, 0, 0, 0, 0.412, -0.154],
        [0, 0, 1, 0.154, 0, 0],
    ]
    np.testing.assert_allclose(stanford.screw_axes(), space, atol=1e-15)


def test_panda_link_frames_are_frankas():
    # frames 1..6 are panda_link1..6; the last frame carries the flange: panda_link8
    path = os.path.join(robots_folder(), "panda_description/urdf/panda.urdf")
    panda = sk.robots.panda()
    Q = np.random.default_rng(4).uniform(*panda.qlim.T, (10, 7))
    frames = panda.frames(Q)
    for k, link in [(k, f"panda_link{k}") for k in range(1, 7)] + [(7, "panda_link8")]:
        reference = pinocchio_poses(path, Q, link)
        np.testing.assert_allclose(frames[:, k], reference, rtol=0, atol=1e-12)


def test_panda_limits_match_frankas_urdf():
    path = os.path.join(robots_folder(), "panda_description/urdf/panda.urdf")
    urdf = sk.Chain.from_urdf(path, tip_link="panda_link8")
    np.testing.assert_array_equal(urdf.qlim, sk.robots.panda().qlim)
