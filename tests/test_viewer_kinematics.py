"""The kinematics the viewers compute in the page (``screwkit/static/viewer/
kinematics.js``) agree with screwkit's, run in Node without three.js or a DOM.

Each test hands the page's functions the very parameters ``screwkit.viewer`` writes
into the page (the figure's model) and compares what they compute with screwkit at
seeded random configurations: a chain's tool pose with ``chain.fk``, its joint axes with
``chain.joint_axes``, the position Jacobian with the rows v of
``chain.geometric_jacobian`` and the manipulability ellipsoid with their singular
values; the exponential of a twist with ``exp_twist`` and ``screw_motion``; a parallel
platform's pose with the composition the sliders promise, its legs with ``pm.ik``; the
readout's roll, pitch, yaw with ``rpy_from_rotation``; a trajectory's joint values
between samples with ``np.interp`` and its tool path with ``chain.fk``.
"""

import json
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import screwkit as sk
from screwkit import viewer

NODE = shutil.which("node")
KINEMATICS = (
    pathlib.Path(viewer.__file__).parent / "static" / "viewer" / "kinematics.js"
)
# The page computes in double precision from parameters rounded to 12 significant
# digits (viewer._numbers): agreement to 1e-9 of the instance's size (m) leaves room
# for that rounding and a chain's products, and still catches any wrong formula.
TOL = 1e-9
SAMPLES = 25

# Node runs kinematics.js as a script in a fresh context: its function declarations
# become that context's globals; then it answers each request [function, args].
DRIVER = """
const vm = require("vm"), fs = require("fs");
const page = vm.createContext({});
vm.runInContext(fs.readFileSync(process.argv[1], "utf8"), page);
const requests = JSON.parse(fs.readFileSync(0, "utf8"));
const answers = requests.map(function (r) { return page[r[0]].apply(null, r[1]); });
process.stdout.write(JSON.stringify(answers));
"""

pytestmark = pytest.mark.skipif(NODE is None, reason="needs Node.js")


def run_page(requests):
    """What the page's functions return for ``requests``, a list of [name, args]."""
    result = subprocess.run(
        [NODE, "-e", DRIVER, str(KINEMATICS)],
        input=json.dumps(requests),
        capture_output=True,
        text=True,
        timeout=60,
        check=True,
    )
    return json.loads(result.stdout)


def matrix(flat):
    """A (4, 4) array from the page's row-major list of 16 numbers."""
    return np.asarray(flat, dtype=float).reshape(4, 4)


def random_configurations(model, rng):
    """SAMPLES configurations (SAMPLES, n) in SI units, inside the sliders' ranges."""
    low = np.array([s["min"] * s["scale"] for s in model["sliders"]])
    high = np.array([s["max"] * s["scale"] for s in model["sliders"]])
    return rng.uniform(low, high, size=(SAMPLES, low.size))


CHAINS = {
    "PUMA 560": sk.robots.puma560,
    "UR5e": sk.robots.ur5e,
    "Kawasaki CX210L": sk.robots.kawasaki_cx210l,
    "planar 4R": lambda: sk.robots.planar([0.4, 0.3, 0.25, 0.1]),
}


@pytest.mark.parametrize("name", CHAINS)
def test_chain_pose_jacobian_and_ellipsoid_equal_screwkits(name):
    chain = CHAINS[name]()
    model = viewer.robot_viewer(chain, ellipsoid=True).model
    Q = random_configurations(model, np.random.default_rng(32))
    poses = run_page([["chainPose", [model, q.tolist()]] for q in Q])
    requests = []
    for pose in poses:
        requests.append(["positionJacobian", [model, pose]])
        requests.append(["ellipsoid", [model, pose]])
    answers = run_page(requests)
    scale = max(model["radius"], 1.0)
    for q, pose, J_page, e in zip(Q, poses, answers[::2], answers[1::2]):
        np.testing.assert_allclose(
            matrix(pose["tool"]), chain.fk(q), rtol=0, atol=TOL * scale
        )
        axes, _ = chain.joint_axes(q)
        page_axes = [
            matrix(before)[:3, :3] @ np.asarray(axis)
            for before, axis in zip(pose["before"], model["axes"])
        ]
        np.testing.assert_allclose(page_axes, axes, rtol=0, atol=TOL)
        Jv = chain.geometric_jacobian(q)[:3]
        np.testing.assert_allclose(np.asarray(J_page).T, Jv, rtol=0, atol=TOL * scale)
        singular = np.linalg.svd(Jv, compute_uv=False)
        np.testing.assert_allclose(
            sorted(e["radii"], reverse=True), singular, rtol=0, atol=TOL * scale
        )
        np.testing.assert_allclose(
            e["w"], np.sqrt(np.linalg.det(Jv @ Jv.T)), rtol=0, atol=TOL * scale**3
        )
        V = np.asarray(e["axes"]).reshape(3, 3)
        radii = np.asarray(e["radii"])
        np.testing.assert_allclose(
            V @ np.diag(radii**2) @ V.T, Jv @ Jv.T, rtol=0, atol=TOL * scale**2
        )


# (s, r, h): a pure rotation, a right- and a left-handed screw, a translation (h = inf)
SCREWS = [
    ([0, 0, 1], [0.3, -0.2, 0], 0.0),
    ([1, 2, 2], [0.1, 0.5, -0.4], 0.05),
    ([-0.6, 0, 0.8], [0, 0.2, 0.7], -0.12),
    ([0.2, -0.3, 0.9], [0.4, 0.4, 0.1], np.inf),
]


@pytest.mark.parametrize("s, r, h", SCREWS)
def test_exponential_of_a_twist_equals_screwkits(s, r, h):
    model = viewer.screw_motion_viewer(s, r, h, start=sk.transl(0.2, -0.1, 0.3)).model
    twist = sk.twist_from_axis(model["s"], model["r"], np.inf if h == np.inf else h)
    thetas = np.random.default_rng(33).uniform(-2 * np.pi, 2 * np.pi, SAMPLES)
    page = run_page([["expTwist", [np.asarray(twist).tolist(), t]] for t in thetas])
    for theta, T in zip(thetas, page):
        np.testing.assert_allclose(
            matrix(T), sk.exp_twist(twist, theta), rtol=0, atol=TOL
        )
        np.testing.assert_allclose(
            matrix(T), sk.screw_motion(s, r, h, theta), rtol=0, atol=TOL
        )


def platform_pose(model, values):
    """The pose the sliders promise (viewer.show_platform), absolute: Trans(x, y, z)
    Rz(yaw) Ry(pitch) Rx(roll), or Trans(x, y, z_home) Rz(phi) if planar."""
    if model["planar"]:
        z = np.asarray(model["home"])[2, 3]
        return sk.homogeneous(sk.rotz(values[2]), [values[0], values[1], z])
    R = sk.rotz(values[5]) @ sk.roty(values[4]) @ sk.rotx(values[3])
    return sk.homogeneous(R, values[:3])


# Without leg limits, so that pm.ik answers at every pose the sliders reach (the page
# computes every leg's length, and marks those outside the limits)
PLATFORMS = {
    "Stewart-Gough": lambda: sk.robots.stewart_gough(leg_limits=None),
    "3-RPR": sk.robots.planar_3rpr,
}


@pytest.mark.parametrize("name", PLATFORMS)
def test_platform_pose_and_legs_equal_screwkits(name):
    pm = PLATFORMS[name]()
    model = viewer.show_platform(pm).model
    values = random_configurations(model, np.random.default_rng(34))
    poses = run_page([["platformPose", [model, v.tolist()]] for v in values])
    legs = run_page([["legLengths", [model, T]] for T in poses])
    for v, T, rho in zip(values, poses, legs):
        want = platform_pose(model, v)
        np.testing.assert_allclose(matrix(T), want, rtol=0, atol=TOL)
        np.testing.assert_allclose(rho, pm.ik(want), rtol=0, atol=TOL)


def test_the_home_sliders_give_the_home_pose():
    # The sliders start at the home pose's own values (absolute, not offsets): the
    # Stewart-Gough platform at z = 1 m, the 3-RPR turned by 90 deg about z.
    for pm in PLATFORMS.values():
        pm = pm()
        model = viewer.show_platform(pm).model
        start = [s["value"] * s["scale"] for s in model["sliders"]]
        (T,) = run_page([["platformPose", [model, start]]])
        np.testing.assert_allclose(matrix(T), pm.home(), rtol=0, atol=TOL)


def test_roll_pitch_yaw_equal_screwkits():
    # random rotations, and the two gimbal locks (pitch +-90 deg), where screwkit sets
    # yaw = 0 and roll carries the turn
    rng = np.random.default_rng(35)
    angles = rng.uniform(-np.pi, np.pi, size=(SAMPLES, 3))
    angles[:, 1] /= 2
    angles[:2, 1] = [np.pi / 2, -np.pi / 2]
    rotations = sk.orientation.rotation_from_rpy(angles)
    poses = [sk.homogeneous(R, [0.1, 0.2, 0.3]) for R in rotations]
    page = np.array(run_page([["rollPitchYaw", [T.ravel().tolist()]] for T in poses]))
    np.testing.assert_allclose(
        page, sk.orientation.rpy_from_rotation(rotations), rtol=0, atol=TOL
    )
    np.testing.assert_allclose(
        sk.orientation.rotation_from_rpy(page), rotations, rtol=0, atol=TOL
    )


def test_a_trajectory_between_samples_is_the_linear_interpolation():
    # np.interp per joint, at times inside, at the samples and outside (held at the
    # ends), with uneven sample times
    rng = np.random.default_rng(36)
    times = np.cumsum(rng.uniform(0.05, 0.3, 12))
    Q = rng.uniform(-2, 2, size=(12, 3))
    queries = np.concatenate(
        [rng.uniform(times[0] - 0.5, times[-1] + 0.5, SAMPLES), times]
    )
    page = run_page(
        [["sampleAt", [times.tolist(), Q.tolist(), float(t)]] for t in queries]
    )
    expected = np.array(
        [[np.interp(t, times, Q[:, j]) for j in range(3)] for t in queries]
    )
    np.testing.assert_allclose(page, expected, rtol=0, atol=1e-14)


def test_a_trajectorys_tool_path_and_drawn_points_equal_screwkits():
    ur5e = sk.robots.ur5e()
    Q = np.random.default_rng(37).uniform(-np.pi, np.pi, size=(SAMPLES, 6))
    model = viewer.trajectory_viewer(ur5e, Q).model
    sent = np.array(model["paths"][0]["q"])
    (path,) = run_page([["toolPath", [model, sent.tolist()]]])
    np.testing.assert_allclose(path, ur5e.fk(sent)[:, :3, 3], rtol=0, atol=TOL)
    pose = run_page([["chainPose", [model, sent[3].tolist()]]])[0]
    (points,) = run_page([["chainPoints", [model, pose]]])
    _, joint_points = ur5e.joint_axes(sent[3])
    expected = np.vstack([[0, 0, 0], joint_points, ur5e.fk(sent[3])[:3, 3]])
    np.testing.assert_allclose(points, expected, rtol=0, atol=TOL)


def test_the_kinematics_module_needs_no_browser():
    """kinematics.js names neither three.js nor the page: Node runs it as it is."""
    text = KINEMATICS.read_text(encoding="utf-8")
    for name in ("window", "document", "THREE"):
        assert name not in text, name
    assert run_page([["identity", []]]) == [np.eye(4).ravel().tolist()]


def test_the_page_script_is_its_parts_joined_in_order():
    folder = KINEMATICS.parent
    parts = [(folder / p).read_text(encoding="utf-8") for p in viewer.VIEWER_PARTS]
    assert viewer.viewer_script() == "".join(parts)
    assert sorted(viewer.VIEWER_PARTS) == sorted(p.name for p in folder.glob("*.js"))
    subprocess.run(
        [NODE, "--check"], input=viewer.viewer_script(), text=True, check=True
    )
