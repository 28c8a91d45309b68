"""screwkit.statics: joint torques by virtual work, gravity, wrenches between
frames, transmission indices, stiffness and eigenscrews.

References are independent of the code under test: finite differences of the forward
kinematics (virtual work tau_i = f . dp/dq_i + c . omega_i), of the potential energy,
of the legs' inverse and forward kinematics; closed forms derived in the docstrings."""

import functools

import numpy as np
import pytest
from builders import delta, puma, rpr, stewart, ur5e

import screwkit as sk
from screwkit import statics as st

#: Central differences with h = 1e-6 on arms about 1 m across: truncation ~1e-12,
#: round-off ~1e-10 per unit force.
FD_TOL = 1e-7
H = 1e-6


@functools.cache
def random_arm():
    """A 7-joint arm from random screws (revolute, prismatic and helical), with a
    base and a tool: no structure for a special case to hide in."""
    rng = np.random.default_rng(40)
    axes = []
    for pitch in (0.0, 0.0, np.inf, 0.0, 0.05, 0.0, 0.0):
        s = rng.normal(size=3)
        s /= np.linalg.norm(s)
        if np.isinf(pitch):
            axes.append([0, 0, 0, *s])
        else:
            r = rng.uniform(-0.5, 0.5, 3)
            axes.append([*s, *(np.cross(r, s) + pitch * s)])
    M = sk.transl(0.3, 0.2, 0.8) @ sk.homogeneous(sk.rotx(0.4))
    return (
        sk.Chain.from_screws(axes, M)
        .with_base(sk.transl(0.1, -0.2, 0.3) @ sk.homogeneous(sk.rotz(0.7)))
        .with_tool(sk.transl(0.0, 0.05, 0.12))
    )


ARMS = {"puma": puma, "ur5e": ur5e, "random": random_arm}


def vee(W):
    return np.array([W[2, 1], W[0, 2], W[1, 0]])


def virtual_work(chain, q, f_s, c_s, point_b):
    """tau_i = f . d(point)/dq_i + c . omega_i by central differences of FK alone."""
    T = chain.fk(q)
    tau = np.zeros(chain.n)
    for i in range(chain.n):
        step = np.zeros(chain.n)
        step[i] = H
        Tp, Tm = chain.fk(q + step), chain.fk(q - step)
        dp = (Tp[:3, :3] @ point_b + Tp[:3, 3] - Tm[:3, :3] @ point_b - Tm[:3, 3]) / (
            2 * H
        )
        omega = vee((Tp[:3, :3] - Tm[:3, :3]) / (2 * H) @ T[:3, :3].T)
        tau[i] = f_s @ dp + c_s @ omega
    return tau


def configurations(chain, count=4, seed=0):
    return np.random.default_rng(seed).uniform(-2.5, 2.5, (count, chain.n))


@pytest.mark.parametrize("name", ARMS)
@pytest.mark.parametrize("frame", ["space", "body"])
def test_joint_torques_equal_virtual_work(name, frame):
    chain = ARMS[name]()
    rng = np.random.default_rng(1)
    for q in configurations(chain):
        R = chain.fk(q)[:3, :3]
        f, c = rng.normal(size=3) * 20, rng.normal(size=3) * 5
        to_space = R if frame == "body" else np.eye(3)
        offset = rng.uniform(-0.1, 0.1, 3)
        for force, moment, point in (
            (f, None, "tool"),  # a force at the tool point
            (None, c, "tool"),  # a pure couple
            (f, c, offset),  # a force at a point of the tool, and a couple
        ):
            tau = st.joint_torques(
                chain, q, force=force, moment=moment, point=point, frame=frame
            )
            f_s = to_space @ (np.zeros(3) if force is None else force)
            c_s = to_space @ (np.zeros(3) if moment is None else moment)
            at = np.zeros(3) if isinstance(point, str) else point
            np.testing.assert_allclose(
                tau, virtual_work(chain, q, f_s, c_s, at), atol=FD_TOL * 100
            )


@pytest.mark.parametrize("name", ARMS)
def test_the_wrench_order_is_f_then_m_and_tau_is_js_transpose_pi_w(name):
    """tau = J_s^T Pi w with w = (f; m): J_s^T applied to (f; m) unswapped is wrong."""
    chain = ARMS[name]()
    rng = np.random.default_rng(2)
    for q in configurations(chain, 3, seed=3):
        w = rng.normal(size=6)
        J = chain.space_jacobian(q)
        tau = st.joint_torques(chain, q, wrench=w)
        np.testing.assert_allclose(tau, J.T @ np.r_[w[3:], w[:3]], atol=1e-12)
        assert not np.allclose(tau, J.T @ w)
        as_force = st.joint_torques(
            chain, q, force=w[:3], moment=w[3:] - np.cross(chain.fk(q)[:3, 3], w[:3])
        )
        np.testing.assert_allclose(tau, as_force, atol=1e-10)
        # a Wrench object, and the body frame: J_b^T Pi w_b
        np.testing.assert_allclose(
            st.joint_torques(chain, q, wrench=sk.Wrench(list(w))), tau, atol=1e-10
        )
        w_b = rng.normal(size=6)
        Jb = chain.body_jacobian(q)
        np.testing.assert_allclose(
            st.joint_torques(chain, q, wrench=w_b, frame="body"),
            Jb.T @ np.r_[w_b[3:], w_b[:3]],
            atol=1e-10,
        )


def test_joint_torques_take_a_batch():
    chain = puma()
    Q = configurations(chain, 5, seed=4)
    f = [1.0, -2.0, 3.0]
    batch = st.joint_torques(chain, Q, force=f, frame="body")
    for q, tau in zip(Q, batch):
        np.testing.assert_allclose(
            tau, st.joint_torques(chain, q, force=f, frame="body"), atol=1e-12
        )


def test_a_planar_arm_by_hand():
    """Two links of 1 m along x, q = (0, pi/2): tip at (1, 1). 1 N along +x at the tip:
    tau_1 = (r x f)_z = -1 * 1 = -1 N m; tau_2 about (1, 0): -(1)(1) = -1 N m."""
    arm = sk.robots.planar([1.0, 1.0])
    tau = st.joint_torques(arm, [0.0, np.pi / 2], force=[1.0, 0, 0])
    np.testing.assert_allclose(tau, [-1.0, -1.0], atol=1e-12)


def test_wrench_at_is_the_direct_formula_and_keeps_the_power():
    rng = np.random.default_rng(5)
    for _ in range(20):
        R = sk.rot_axis(rng.normal(size=3), rng.uniform(-3, 3))
        p = rng.normal(size=3)
        T = sk.homogeneous(R, p)
        w = rng.normal(size=6)
        moved = st.wrench_at(w, T)
        np.testing.assert_allclose(moved[:3], R.T @ w[:3], atol=1e-12)
        np.testing.assert_allclose(
            moved[3:], R.T @ (w[3:] - np.cross(p, w[:3])), atol=1e-12
        )
        V_b = rng.normal(size=6)  # a twist in {b}, and in {a}: Ad(T) V_b
        V_a = sk.adjoint(T) @ V_b
        power_a = V_a[:3] @ w[3:] + V_a[3:] @ w[:3]
        power_b = V_b[:3] @ moved[3:] + V_b[3:] @ moved[:3]
        assert power_a == pytest.approx(power_b, abs=1e-10)
        np.testing.assert_allclose(st.wrench_at(moved, sk.inv(T)), w, atol=1e-12)


def potential(chain, q, masses, g):
    frames = chain.frames(q)
    total = 0.0
    for link, m, r in masses:
        F = frames[link]
        total -= m * g @ (F[:3, :3] @ r + F[:3, 3])
    return total


def test_gravity_torques_are_the_gradient_of_the_potential():
    g = np.array([0.0, 0.0, -9.81])
    for chain in (puma(), random_arm()):
        rng = np.random.default_rng(6)
        masses = [
            (k, float(rng.uniform(0.5, 10)), rng.uniform(-0.2, 0.2, 3))
            for k in range(chain.n + 1)
        ]
        for q in configurations(chain, 3, seed=7):
            tau = st.gravity_torques(chain, q, masses, g)
            fd = [
                (
                    potential(chain, q + H * e, masses, g)
                    - potential(chain, q - H * e, masses, g)
                )
                / (2 * H)
                for e in np.eye(chain.n)
            ]
            np.testing.assert_allclose(tau, fd, atol=1e-6)


def test_holding_a_load_is_pushing_up_with_its_weight():
    """A load M at the tool: 'holds' (gravity_torques) = the arm applies +M g0 up."""
    chain = puma()
    M, g0 = 2.5, 9.81
    for q in configurations(chain, 3, seed=8):
        holds = st.gravity_torques(chain, q, [(6, M, [0, 0, 0.1])], [0, 0, -g0])
        pushes_up = st.joint_torques(
            chain, q, force=[0, 0, M * g0], point=[0, 0, 0.1], frame="space"
        )
        np.testing.assert_allclose(holds, pushes_up, atol=1e-10)
        pushes_down = st.joint_torques(
            chain, q, force=[0, 0, -M * g0], point=[0, 0, 0.1]
        )
        np.testing.assert_allclose(pushes_down, -holds, atol=1e-10)
    assert not np.any(st.gravity_torques(chain, q, [(0, 5.0, [1, 2, 3])]))


# ---- stiffness ----------------------------------------------------------------------


def test_stiffness_is_the_inverse_compliance_and_mr_formula():
    chain = puma()
    q = np.array([0.2, -0.5, 0.4, 0.3, 0.9, -0.2])
    K_q = np.array([2e4, 3e4, 1e4, 500.0, 400.0, 300.0])
    for frame in ("space", "body"):
        K = st.stiffness_at_tool(chain, q, K_q, frame=frame)
        C = st.compliance_at_tool(chain, q, K_q, frame=frame)
        np.testing.assert_allclose(K @ C, np.eye(6), atol=1e-8)
        J = chain.space_jacobian(q) if frame == "space" else chain.body_jacobian(q)
        Jinv = np.linalg.inv(J)
        S = Jinv.T @ np.diag(K_q) @ Jinv  # Modern Robotics' order (m; f)
        Pi = st.swap(np.eye(6))
        np.testing.assert_allclose(Pi @ K, S, rtol=1e-9, atol=1e-6)
        # energy: dX^T Pi K dX = dq^T K_q dq for dX = J dq
        dq = np.random.default_rng(9).normal(size=6)
        dX = J @ dq
        assert dX @ Pi @ K @ dX == pytest.approx(dq @ (K_q * dq), rel=1e-9)


def test_stiffness_where_j_is_singular_is_a_clear_error():
    chain = puma()
    q = np.array([0.3, -0.4, 0.2, 0.5, 0.0, 0.1])  # q5 = 0: the wrist singularity
    with pytest.raises(ValueError, match=r"rank 5 < 6.*compliance_at_tool"):
        st.stiffness_at_tool(chain, q, [1e3] * 6)
    C = st.compliance_at_tool(chain, q, [1e3] * 6)
    assert np.linalg.matrix_rank(C, tol=1e-9 * np.abs(C).max()) == 5
    with pytest.raises(ValueError, match="rank 2 < 6"):
        st.stiffness_at_tool(sk.robots.planar([1.0, 1.0]), [0.1, 0.2], [1.0, 1.0])


def test_a_redundant_arm_has_a_stiffness():
    chain = random_arm()
    q = configurations(chain, 1, seed=10)[0]
    K_q = np.linspace(100, 700, 7)
    K = st.stiffness_at_tool(chain, q, K_q)
    C = st.compliance_at_tool(chain, q, K_q)
    np.testing.assert_allclose(K @ C, np.eye(6), atol=1e-8)


def test_leg_stiffness_matches_the_legs_energy():
    """Legs as springs: energy sum k_i drho_i^2 with drho from the legs' IK (FD)."""
    pm = stewart()
    T = pm.home() @ sk.homogeneous(sk.rotx(0.05), [0.02, -0.01, 0.05])
    k = np.array([1.0, 2.0, 3.0, 1.5, 2.5, 0.5]) * 1e5
    K = st.leg_stiffness(pm, T, k)
    Pi = st.swap(np.eye(6))
    rng = np.random.default_rng(11)
    for _ in range(3):
        dX = rng.normal(size=6)
        drho = (pm.ik(sk.exp_twist(dX, H) @ T) - pm.ik(sk.exp_twist(dX, -H) @ T)) / (
            2 * H
        )
        assert dX @ Pi @ K @ dX == pytest.approx(k @ drho**2, rel=1e-6)
    np.testing.assert_allclose(Pi @ K, (Pi @ K).T, atol=1e-6 * np.abs(K).max())


# ---- eigenscrews --------------------------------------------------------------------


def test_eigenscrews_of_a_decoupled_stiffness():
    """m = kr dtheta, f = kt dx: on (s; h s), kt h = lambda and kr = lambda h, so
    lambda = +-sqrt(kr kt) and h = +-sqrt(kr / kt) (derived in eigenscrews' doc)."""
    kr, kt = 900.0, 4.0e4  # N m/rad, N/m
    Z, I = np.zeros((3, 3)), np.eye(3)
    e = st.eigenscrews(np.block([[Z, kt * I], [kr * I, Z]]))
    root, pitch = np.sqrt(kr * kt), np.sqrt(kr / kt)
    np.testing.assert_allclose(e.values, [root] * 3 + [-root] * 3, rtol=1e-12)
    np.testing.assert_allclose(e.pitches, [pitch] * 3 + [-pitch] * 3, rtol=1e-10)


def test_eigenscrews_of_an_arm_solve_patterson_lipkin():
    chain = puma()
    q = np.array([0.2, -0.5, 0.4, 0.3, 0.9, -0.2])
    K_q = [2e4, 3e4, 1e4, 500.0, 400.0, 300.0]
    K = st.stiffness_at_tool(chain, q, K_q)
    e = st.eigenscrews(K)
    Pi = st.swap(np.eye(6))
    S = Pi @ K
    for lam, x in zip(e.values, e.screws.T):
        np.testing.assert_allclose(K @ x, lam * x, atol=1e-7 * np.abs(lam))
        np.testing.assert_allclose(S @ x, lam * Pi @ x, atol=1e-7 * np.abs(lam))
    assert (e.values > 0).sum() == 3 and (e.values < 0).sum() == 3
    # the compliance has the same screws, eigenvalues 1 / lambda
    c = st.eigenscrews(st.compliance_at_tool(chain, q, K_q))
    np.testing.assert_allclose(np.sort(c.values), np.sort(1 / e.values), rtol=1e-6)


def test_a_matrix_with_complex_eigenvalues_is_not_a_stiffness():
    R = np.zeros((6, 6))
    R[0, 1], R[1, 0] = -1.0, 1.0
    with pytest.raises(ValueError, match="complex eigenvalues"):
        st.eigenscrews(R + np.eye(6))


# ---- transmission -------------------------------------------------------------------


def fd_transmission(pm, T, leg):
    """|cos| of the angle between leg i's force line (A_i -> C_i for a prismatic leg,
    the distal link elbow -> C_i for a crank) and the velocity of C_i when only rho_i
    changes, by the forward kinematics."""
    solution = pm.ik(T, passive=True)
    rho = solution.rho
    step = np.zeros(pm.m)
    step[leg] = H
    Tp = pm.fk(rho + step, guess=T).T
    Tm = pm.fk(rho - step, guess=T).T
    b = pm.platform_points[leg]
    velocity = (Tp[:3, :3] @ b + Tp[:3, 3] - Tm[:3, :3] @ b - Tm[:3, 3]) / (2 * H)
    C = T[:3, :3] @ b + T[:3, 3]
    start = solution.passive["elbow"][leg] if "elbow" in solution.passive else None
    u = C - (pm.base_points[leg] if start is None else start)
    return abs(u @ velocity) / (np.linalg.norm(u) * np.linalg.norm(velocity))


@pytest.mark.parametrize("build", [rpr, stewart, delta])
def test_transmission_index_is_the_pressure_angle_by_fk(build):
    pm = build()
    home = pm.home()
    poses = [home]
    if pm.planar:
        poses.append(home @ sk.homogeneous(sk.rotz(0.2), [0.05, -0.04, 0.0]))
    elif pm.motion == "translational":
        poses.append(sk.transl(0.04, -0.03, 0.02) @ home)
    else:
        poses.append(home @ sk.homogeneous(sk.roty(0.1), [0.03, 0.02, 0.05]))
    for T in poses:
        eta = st.transmission_index(pm, T)
        expected = [fd_transmission(pm, T, i) for i in range(pm.m)]
        np.testing.assert_allclose(eta, expected, atol=1e-6)
        batch = st.transmission_index(pm, np.array([T, T]))
        np.testing.assert_allclose(batch, [eta, eta], atol=1e-15)


def test_transmission_index_is_unit_free():
    pm, big = (
        rpr(),
        sk.parallel.planar_3rpr(
            base=np.array(sk.parallel.catalogue.RPR_BASE, dtype=float) * 1000,
            platform=np.array(sk.parallel.catalogue.RPR_PLATFORM, dtype=float) * 1000,
        ),
    )
    T = pm.home()
    T_mm = T.copy()
    T_mm[:3, 3] *= 1000
    np.testing.assert_allclose(
        st.transmission_index(big, T_mm), st.transmission_index(pm, T), atol=1e-9
    )


def test_transmission_index_vanishes_at_a_direct_singularity():
    """Across a direct singularity of the 3-RPR det J_p changes sign; bisected to it,
    the smallest index falls to 0 (the actuators cannot hold the platform)."""
    pm = rpr()

    def pose(y):  # along the line x = 0.5 m, at the home orientation
        T = pm.home().copy()
        T[0, 3], T[1, 3] = 0.5, y
        return T

    def det(y):
        return np.linalg.det(pm.jacobian(pose(y))[:, [2, 3, 4]])

    ys = np.linspace(-0.6, 1.4, 201)
    values = np.array([det(y) for y in ys])
    assert np.all(np.isfinite(values))
    k = int(np.flatnonzero(np.diff(np.sign(values)))[0])
    low, high = ys[k], ys[k + 1]
    for _ in range(60):
        middle = (low + high) / 2
        if np.sign(det(middle)) == np.sign(values[k]):
            low = middle
        else:
            high = middle
    assert st.transmission_index(pm, pose(low)).min() < 1e-6
    assert st.transmission_index(pm, pose(low + 0.05)).min() > 1e-2
    assert st.transmission_index(pm, pose(low - 0.05)).min() > 1e-2


def test_gravity_torques_take_a_batch():
    chain = puma()
    Q = configurations(chain, 4, seed=12)
    masses = [(3, 4.0, [0.1, 0.0, 0.0]), (6, 2.0, [0.0, 0.0, 0.1])]
    batch = st.gravity_torques(chain, Q, masses)
    for q, tau in zip(Q, batch):
        np.testing.assert_allclose(
            tau, st.gravity_torques(chain, q, masses), atol=1e-12
        )
