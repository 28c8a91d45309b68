"""The kinematics the viewers compute in the page (``screwkit/static/viewer/
kinematics.js``) agree with screwkit's, run in Node without three.js or a DOM.

Each test hands the page's functions the very parameters ``screwkit.viewer`` writes
into the page (the figure's model) and compares what they compute with screwkit at
seeded random configurations: a chain's tool pose with ``chain.fk``, its joint axes with
``chain.joint_axes``, the position Jacobian with the rows v of
``chain.geometric_jacobian`` and the manipulability ellipsoid with their singular
values; the exponential of a twist with ``exp_twist`` and ``screw_motion``; a parallel
platform's pose with the composition the sliders promise, its legs with ``pm.ik``.
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
    """The pose the sliders promise (viewer.show_platform): Trans(p_home + d) Rz(yaw)
    Ry(pitch) Rx(roll) R_home, or Trans(p_home + (x, y, 0)) Rz(phi) R_home if planar."""
    home = np.asarray(model["home"])
    if model["planar"]:
        d, R = [values[0], values[1], 0.0], sk.rotz(values[2])
    else:
        d = values[:3]
        R = sk.rotz(values[5]) @ sk.roty(values[4]) @ sk.rotx(values[3])
    return sk.homogeneous(R @ home[:3, :3], home[:3, 3] + np.asarray(d))


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
