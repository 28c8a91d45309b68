"""The same mechanism or arm in any unit gives the same answers, scaled (tolerances are
relative to the instance's size).

Every catalogue mechanism (Stewart-Gough, 3-RPR, 3-RRR, delta, Tripteron) is built
with all its lengths times 1000 (millimetres) and times 1/100 (hectometres, a
mechanism a hundred times smaller than a metre in the unit's terms), and every answer
is compared with the one in metres: IK (lengths scale, angles do not), FK from a
guess, every assembly mode, singularity types and workspace membership. The delta
with a commercial robot's published geometry in mm (Williams' ABB FlexPicker
figures) runs forward kinematics from home on a thousand poses, and its assembly
modes are compared with a trilateration written out here. The serial arms of the
catalogue (PUMA 560, Kawasaki CX210L, UR5e) scaled alike keep their closed-form IK
labels and forward kinematics.
"""

import functools
import math

import numpy as np
import pytest
import sympy as sp
from builders import kawasaki, puma, ur5e

import screwkit as sk
from screwkit import parallel
from screwkit.ik import analytic_ik, analytic_ik_all, configuration

FACTORS = [sp.Integer(1000), sp.Rational(1, 100)]
MECHANISMS = ["stewart", "3-RPR", "3-RRR", "delta", "tripteron"]


@functools.cache
def build(name, f=sp.Integer(1)):
    """A catalogue mechanism with every length times f (exact)."""
    if name == "stewart":
        base = sp.Matrix(parallel.STEWART_BASE) * f
        platform = sp.Matrix(parallel.STEWART_PLATFORM) * f
        limits = ((sp.Rational(9, 10) * f, sp.Rational(8, 5) * f),) * 6
        return parallel.stewart_gough(base, platform, height=f, leg_limits=limits)
    if name == "3-RPR":
        home = parallel.planar_3rpr().home_exact()
        home[:3, 3] *= f
        return parallel.planar_3rpr(
            sp.Matrix(parallel.RPR_BASE) * f,
            sp.Matrix(parallel.RPR_PLATFORM) * f,
            home=home,
            leg_limits=((sp.Rational(1, 2) * f, sp.Rational(3, 2) * f),) * 3,
        )
    if name == "3-RRR":
        return parallel.planar_3rrr(
            f, sp.Rational(1, 4) * f, sp.Rational(3, 5) * f, sp.Rational(1, 2) * f
        )
    if name == "delta":
        r = sp.Rational
        return parallel.delta(
            r(1, 5) * f, r(1, 20) * f, r(1, 5) * f, r(9, 20) * f, r(-7, 20) * f
        )
    home = sp.eye(4)
    home[:3, 3] = sp.Matrix([sp.Rational(7, 20) * f] * 3)
    r = sp.Rational
    return parallel.tripteron(r(9, 20) * f, r(9, 20) * f, f, r(1, 10) * f, home)


def rotation(w):
    """exp([w]) by Rodrigues' formula, written out."""
    theta = np.linalg.norm(w)
    if theta == 0:
        return np.eye(3)
    k = np.asarray(w) / theta
    K = np.array([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    return np.eye(3) + math.sin(theta) * K + (1 - math.cos(theta)) * K @ K


def sample_poses(pm, count=12, seed=5):
    """Poses near home in the mechanism's own motion type (m)."""
    rng = np.random.default_rng(seed)
    home, poses = pm.home(), []
    for _ in range(count):
        T = home.copy()
        dp = rng.uniform(-0.04, 0.04, 3) * pm.scale
        if pm.motion == "spatial":
            T[:3, :3] = rotation(rng.uniform(-0.15, 0.15, 3)) @ home[:3, :3]
        elif pm.motion == "planar":
            dp[2] = 0.0
            T[:3, :3] = rotation([0, 0, rng.uniform(-0.15, 0.15)]) @ home[:3, :3]
        T[:3, 3] += dp
        poses.append(T)
    return np.array(poses)


def scaled_pose(T, f):
    T = np.array(T, dtype=float).copy()
    T[..., :3, 3] *= float(f)
    return T


def rho_unit(pm, f):
    """How the actuated values scale: lengths with f, crank angles not."""
    return float(f) if pm.prismatic else 1.0


def same_poses(A, B, f):
    """Every pose of A has one in B (and back) with the same rotation and the
    translation times f."""
    if len(A) != len(B):
        return False
    for P in A:
        gaps = [
            max(
                np.max(np.abs(P[:3, :3] - Q[:3, :3])),
                np.max(np.abs(P[:3, 3] - Q[:3, 3] / float(f))),
            )
            for Q in B
        ]
        if min(gaps) > 1e-8:
            return False
    return True


@pytest.mark.parametrize("f", FACTORS, ids=["x1000", "x0.01"])
@pytest.mark.parametrize("name", MECHANISMS)
def test_ik_and_fk_from_a_guess_scale(name, f):
    metres, other = build(name), build(name, f)
    assert other.scale == pytest.approx(float(f) * metres.scale, rel=1e-12)
    T = sample_poses(metres)
    rho = metres.ik(T)
    rho_f = other.ik(scaled_pose(T, f))
    assert np.array_equal(np.isnan(rho), np.isnan(rho_f))
    assert np.isfinite(rho).any(axis=1).sum() >= 6  # most of the poses are reached
    u = rho_unit(metres, f)
    assert np.allclose(rho_f / u, rho, rtol=1e-12, atol=1e-12, equal_nan=True)
    ok = np.isfinite(rho).all(axis=1)
    fk = metres.fk(rho[ok], guess=metres.home())
    fk_f = other.fk(rho_f[ok], guess=other.home())
    assert np.array_equal(fk.success, fk_f.success) and fk.success.all()
    assert np.allclose(fk_f.T[:, :3, :3], fk.T[:, :3, :3], atol=1e-9)
    assert np.allclose(fk_f.T[:, :3, 3] / float(f), fk.T[:, :3, 3], atol=1e-9)
    assert np.allclose(fk.T, T[ok], atol=1e-9)  # from home: the sampled mode
    assert np.allclose(fk_f.error / float(f), fk.error, atol=1e-12)


@pytest.mark.parametrize("f", FACTORS, ids=["x1000", "x0.01"])
@pytest.mark.parametrize("name", MECHANISMS)
def test_every_assembly_mode_scales(name, f):
    metres, other = build(name), build(name, f)
    T = sample_poses(metres, count=1, seed=9)[0]
    modes = metres.fk_all(metres.ik(T))
    modes_f = other.fk_all(other.ik(scaled_pose(T, f)))
    assert len(modes) >= 1 and same_poses(modes, modes_f, f)
    assert (modes.complete, modes.method, modes.continuum) == (
        modes_f.complete,
        modes_f.method,
        modes_f.continuum,
    )
    assert min(np.max(np.abs(P - T)) for P in modes) < 1e-9  # the pose it came from


def singular_poses(name):
    """(exact pose, working mode) pairs: one regular (home) and one on a singularity
    of each kind the mechanism shows."""
    home = (build(name).home_exact(), None)
    if name == "stewart":  # Fichter's: the platform turned 90 degrees
        return [home, (sk.homogeneous(sk.rotz(sp.pi / 2), [0, 0, 1]), None)]
    if name == "3-RRR":  # a limb stretched straight (l1 + l2 = 1.1 m from its axis)
        stretched = sp.eye(4)
        stretched[0, 3] = sp.Rational(-7, 20)
        return [home, (stretched, None)]
    if name == "delta":  # the forearms vertical: a constraint singularity
        vertical = sp.eye(4)
        vertical[2, 3] = -sp.sqrt(7) / 20 - sp.Rational(9, 20)
        return [home, (vertical, "+++")]
    return [home]


@pytest.mark.parametrize("f", FACTORS, ids=["x1000", "x0.01"])
@pytest.mark.parametrize("name", MECHANISMS)
def test_singularity_types_scale_and_floats_agree_with_exact(name, f):
    metres, other = build(name), build(name, f)
    kinds = set()
    for exact_pose, mode in singular_poses(name):
        exact = metres.singularities(exact_pose, mode)
        T = np.array(exact_pose.evalf(), dtype=float)
        assert metres.singularities(T, mode) == exact
        assert other.singularities(scaled_pose(T, f), mode) == exact
        kinds |= exact
    expected = {"stewart": {"direct"}, "3-RRR": {"inverse"}, "delta": {"constraint"}}
    assert expected.get(name, set()) <= kinds


@pytest.mark.parametrize("f", FACTORS, ids=["x1000", "x0.01"])
@pytest.mark.parametrize("name", MECHANISMS)
def test_workspace_membership_scales(name, f):
    metres, other = build(name), build(name, f)
    home = metres.home()
    half = 2.0 if name == "delta" else 0.6  # the delta's scale is its base radius
    x = home[0, 3] + np.linspace(-half, half, 41) * metres.scale
    y = home[1, 3] + np.linspace(-half, half, 37) * metres.scale
    w = metres.workspace(x, y, z=home[2, 3])
    w_f = other.workspace(float(f) * x, float(f) * y, z=float(f) * home[2, 3])
    assert 0 < w.inside.sum() < w.inside.size  # the grid crosses the boundary
    assert np.array_equal(w.inside, w_f.inside)
    strong = w.inside & (np.abs(w.det) > 1e-6 * np.nanmax(np.abs(w.det)))
    assert np.array_equal(np.sign(w.det[strong]), np.sign(w_f.det[strong]))


# ---- the delta of a commercial robot, in millimetres --------------------------------

#: Williams, "The Delta Parallel Robot: Kinematics Solutions" (2016), the ABB
#: FlexPicker IRB 360-1/1600: base triangle side s_B = 567 mm, platform side
#: s_P = 76 mm, upper arm L = 524 mm, lower arm l = 1244 mm. The cranks' pivots sit at
#: the base triangle's side midpoints, w_B = sqrt(3) / 6 s_B from its centre, the
#: platform's joints at its vertices, u_P = sqrt(3) / 3 s_P.
S_B, S_P, L_UPPER, L_LOWER = 567, 76, 524, 1244


def flexpicker(unit=1):
    """The published delta, lengths in mm times ``unit`` (1/1000: metres)."""
    u = sp.nsimplify(unit)
    return parallel.delta(
        sp.sqrt(3) / 6 * S_B * u,
        sp.sqrt(3) / 3 * S_P * u,
        L_UPPER * u,
        L_LOWER * u,
        height=-1000 * u,
    )


def trilaterate(centres, radius):
    """The points at ``radius`` from three centres (written out: the frame of the
    first centre, x towards the second, y in their plane; Wikipedia's trilateration)."""
    p1, p2, p3 = centres
    d = np.linalg.norm(p2 - p1)
    ex = (p2 - p1) / d
    i = ex @ (p3 - p1)
    ey = p3 - p1 - i * ex
    ey /= np.linalg.norm(ey)
    ez = np.cross(ex, ey)
    j = ey @ (p3 - p1)
    x = d / 2  # equal radii
    y = (i * i + j * j) / (2 * j) - i * x / j
    z2 = radius**2 - x * x - y * y
    if z2 < 0:
        return []
    z = math.sqrt(z2)
    return [p1 + x * ex + y * ey + s * z * ez for s in (1, -1)]


def delta_modes_written_out(theta, unit=1.0):
    """The FlexPicker's modes for crank angles theta: the elbows from the published
    geometry (theta > 0 lowers a crank about its tangent), then three spheres."""
    wb, up = math.sqrt(3) / 6 * S_B * unit, math.sqrt(3) / 3 * S_P * unit
    centres = []
    for k, t in enumerate(theta):
        a = math.radians(120 * k)
        radial = np.array([math.cos(a), math.sin(a), 0.0])
        elbow = (wb + L_UPPER * unit * math.cos(t)) * radial
        elbow[2] = -L_UPPER * unit * math.sin(t)
        centres.append(elbow - up * radial)
    return trilaterate(centres, L_LOWER * unit)


def test_the_published_delta_with_equal_cranks_has_both_modes():
    # a delta with equal cranks has two assembly modes in any unit: cranks at -20.5
    # degrees put the platform 0.900 m below the base and, the mirror mode, 1.267 m
    # above it
    for unit in (1 / 1000, 1):  # m, mm
        pm = flexpicker(unit)
        modes = pm.fk_all(np.full(3, math.radians(-20.5)))
        assert modes.complete and not modes.continuum and modes.reason is None
        heights = sorted(T[2, 3] * (1 if unit < 1 else 1e-3) for T in modes)
        assert np.round(heights, 3).tolist() == [-0.900, 1.267]
        expected = delta_modes_written_out([math.radians(-20.5)] * 3, unit)
        assert same_poses(modes, [sk.homogeneous(np.eye(3), p) for p in expected], 1)


def test_the_published_delta_in_mm_closes_from_home_on_a_thousand_poses():
    pm, rng = flexpicker(), np.random.default_rng(31)
    T = np.repeat(np.eye(4)[None], 1000, axis=0)
    T[:, :3, 3] = rng.uniform([-300, -300, -1300], [300, 300, -800], (1000, 3))
    theta = pm.ik(T)
    reached = np.isfinite(theta).all(axis=1)
    assert reached.sum() > 900
    fk = pm.fk(theta[reached])  # from home, 1 m below the base
    assert fk.success.all()
    assert np.max(np.abs(fk.T - T[reached])) < 1e-7  # mm: the pose we came from
    for angles, pose in zip(theta[reached][:50], T[reached][:50]):
        modes = pm.fk_all(angles)
        expected = delta_modes_written_out(angles)
        assert len(modes) == len(expected) == 2
        assert same_poses(modes, [sk.homogeneous(np.eye(3), p) for p in expected], 1)
        assert min(np.max(np.abs(P - pose)) for P in modes) < 1e-7


# ---- the serial arms of the catalogue, scaled ---------------------------------------

ARMS = {"puma": puma, "kawasaki": kawasaki, "ur5e": ur5e}


def scaled_arm(chain, f):
    """The same arm with every length times f: its screws' linear parts and its home
    position."""
    S = chain.screw_axes().copy()
    S[:, 3:] *= f
    M = chain.home().copy()
    M[:3, 3] *= f
    return sk.Chain.from_screws(S, M, qlim=chain.qlim)


@pytest.mark.parametrize("f", [1000.0, 0.01], ids=["x1000", "x0.01"])
@pytest.mark.parametrize("name", sorted(ARMS))
def test_a_serial_arm_scaled_keeps_its_ik_labels_and_fk(name, f):
    arm = ARMS[name]()
    other = scaled_arm(arm, f)
    rng = np.random.default_rng(7)
    q = rng.uniform(-2.5, 2.5, (20, 6))
    q[0, 4] = 0.0  # a wrist singularity (PUMA, Kawasaki); UR: q5 = 0 too
    T = arm.fk(q)
    T_f = other.fk(q)
    assert np.allclose(T_f[:, :3, :3], T[:, :3, :3], atol=1e-12)
    assert np.allclose(T_f[:, :3, 3] / f, T[:, :3, 3], atol=1e-12)
    metres, scaled = analytic_ik_all(arm, T), analytic_ik_all(other, T_f)
    assert np.array_equal(np.isnan(metres), np.isnan(scaled))
    turn = np.angle(np.exp(1j * (metres - scaled)))  # pi and -pi are one angle
    # q5 = 0: the split of q4 + q6 comes from a square root of round-off (sqrt(eps))
    assert np.nanmax(np.abs(turn[1:])) < 1e-9 and np.nanmax(np.abs(turn)) < 1e-7
    assert configuration(arm, q) == configuration(other, q)
    for a, b in zip(analytic_ik(arm, T), analytic_ik(other, T_f)):
        assert [s.config for s in a] == [s.config for s in b]
        assert [s.singular for s in a] == [s.singular for s in b]
