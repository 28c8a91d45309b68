"""The answer keys of the first chapters (rigid motions, screws, PoE, PUMA FK and IK),
each recomputed another way: a formula written out here, a finite difference, or
screwkit on the problem as stated."""

import math

import numpy as np
from builders import puma
from references import A2, A3, D3, D4, PUMA_TABLE, dh_fk, rot

import screwkit as sk

from .registry import reference

# ---- rigid_motions -----------------------------------------------------------------


@reference("rigid_motions", 2)
def _():
    # rotate the origin by pi about the z-line through (1, 0, 0): p' = c + Rz(pi)(p - c)
    c = np.array([1.0, 0.0, 0.0])
    return c + rot("z", math.pi) @ (np.zeros(3) - c)


@reference("rigid_motions", 5)
def _():
    # x -> y -> z -> x: the columns of R are e_y, e_z, e_x
    R = np.array([[0.0, 0, 1], [1, 0, 0], [0, 1, 0]])
    np.testing.assert_allclose(
        sk.rot_axis([1.0, 1.0, 1.0], 2 * math.pi / 3), R, atol=1e-12
    )
    return math.acos((np.trace(R) - 1) / 2)


@reference("rigid_motions", 6)
def _():
    R = rot("z", math.pi / 6) @ rot("y", math.pi / 4) @ rot("x", math.pi / 3)
    roll = math.atan2(R[2, 1], R[2, 2])
    pitch = -math.asin(R[2, 0])
    yaw = math.atan2(R[1, 0], R[0, 0])
    return [roll, pitch, yaw]


@reference("rigid_motions", 7)
def _():
    q = np.array([math.cos(math.pi / 4), 0, 0, math.sin(math.pi / 4)])
    # the Hamilton product q v q* rotates v = e_x into Rz(pi/2) e_x = e_y
    w, u = q[0], q[1:]
    v = np.array([1.0, 0, 0])
    rotated = v + 2 * w * np.cross(u, v) + 2 * np.cross(u, np.cross(u, v))
    np.testing.assert_allclose(rotated, [0, 1, 0], atol=1e-12)
    return q


@reference("rigid_motions", 10)
def _():
    # T(t): spin at 2 rad/s about the z-line through (1, 0, 0); twist from Tdot T^-1
    def pose(t):
        T = np.eye(4)
        T[:3, :3] = rot("z", 2 * t)
        T[:3, 3] = np.array([1.0, 0, 0]) - rot("z", 2 * t) @ np.array([1.0, 0, 0])
        return T

    t, h = 0.3, 1e-6
    Tdot = (pose(t + h) - pose(t - h)) / (2 * h)
    V = Tdot @ np.linalg.inv(pose(t))
    return [V[2, 1], V[0, 2], V[1, 0], *V[:3, 3]]


@reference("rigid_motions", 11)
def _():
    # {b}'s axes in {s} as drawn: x_b = y_s, y_b = -x_s, z_b = z_s; p_s = sum of
    # p_b's coordinates times those axes, plus {b}'s origin
    x_b, y_b, z_b = np.array([0, 1.0, 0]), np.array([-1.0, 0, 0]), np.array([0, 0, 1.0])
    return np.array([1.0, 2, 0]) + 0.5 * x_b + 0 * y_b + 0.3 * z_b


@reference("rigid_motions", 13)
def _():
    # the origin of {s} seen from {b}: project -p on {b}'s axes (at 30 deg)
    p = np.array([2.0, 1.0])
    a = math.radians(30)
    x_b, y_b = (
        np.array([math.cos(a), math.sin(a)]),
        np.array([-math.sin(a), math.cos(a)]),
    )
    return [(-p) @ x_b, (-p) @ y_b]


@reference("rigid_motions", 15)
def _():
    # the centre of the circle through nothing but equal distances: intersect the
    # perpendicular bisectors of P1 -> P1' and P3 -> P3'
    pairs = [((2.0, 1.0), (1.0, 2.0)), ((2.0, 1.5), (0.5, 2.0))]
    A = np.array([np.subtract(q, p) for p, q in pairs])
    b = np.array([np.subtract(q, p) @ np.add(p, q) / 2 for p, q in pairs])
    c = np.linalg.solve(A, b)
    # and it turns P2 = (3, 1) into (1, 3) by a quarter turn
    np.testing.assert_allclose(c + rot("z", math.pi / 2)[:2, :2] @ ([3, 1] - c), [1, 3])
    return c


@reference("rigid_motions", 16)
def _():
    # body twist of the cart from T^-1 Tdot, T(t) = (Rz(t / 2 + 90 deg), 2 (cos, sin))
    def pose(t):
        T = np.eye(4)
        T[:3, :3] = rot("z", t / 2 + math.pi / 2)
        T[:3, 3] = [2 * math.cos(t / 2), 2 * math.sin(t / 2), 0]
        return T

    t, h = 0.7, 1e-6
    V = np.linalg.inv(pose(t)) @ (pose(t + h) - pose(t - h)) / (2 * h)
    return [V[2, 1], V[0, 2], V[1, 0], *V[:3, 3]]


@reference("rigid_motions", 22)
def _():
    # the screw's pitch from the twist's log: h = omega . v / |omega|^2 for the twist
    # of T01 = (Rz(90 deg), (0.5, -0.5, 0.2)), theta = pi / 2
    T = np.eye(4)
    T[:3, :3] = rot("z", math.pi / 2)
    T[:3, 3] = [0.5, -0.5, 0.2]
    log = sk.log_transform(T)
    omega, v = log[:3], log[3:]
    return omega @ v / (omega @ omega)


# ---- screws ------------------------------------------------------------------------

SCREW = np.array([0, 0, 1, 1, 2, 0.5])


@reference("screws", 4)
def _():
    s, s0 = SCREW[:3], SCREW[3:]
    return s @ s0 / (s @ s)


@reference("screws", 5)
def _():
    s, s0 = SCREW[:3], SCREW[3:]
    r0 = np.cross(s, s0) / (s @ s)
    # the axis through r0 with the pitch of exercise 4 gives the screw back
    np.testing.assert_allclose(np.cross(r0, s) + 0.5 * s, s0, atol=1e-15)
    return r0


@reference("screws", 6)
def _():
    f, r = np.array([0.0, 10, 0]), np.array([0.5, 0, 0])
    omega, v = np.array([0.0, 0, 2]), np.zeros(3)
    power = omega @ np.cross(r, f) + v @ f
    # the lever arm: torque 0.5 m x 10 N about z, times 2 rad/s
    assert power == 0.5 * 10 * 2
    return power


@reference("screws", 10)
def _():
    twists = np.array([[1.0, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0]])  # axes x, y at 0
    rank = np.linalg.matrix_rank(twists)
    assert (
        sk.ScrewSystem([([1, 0, 0], [0, 0, 0], 0), ([0, 1, 0], [0, 0, 0], 0)]).rank == 2
    )
    return 6 - rank


@reference("screws", 11)
def _():
    # the line through two of its points, (-1, 1, 0.5) and (2, 1, 0.5); its moment from
    # the second point (any point of the line gives the same), plus the pitch term
    p1, p2 = np.array([-1.0, 1, 0.5]), np.array([2.0, 1, 0.5])
    s = (p2 - p1) / np.linalg.norm(p2 - p1)
    return [*s, *(np.cross(p2, s) + 0.2 * s)]


@reference("screws", 12)
def _():
    # the moment from another point of the line of action, 5 m above the plate
    f = np.array([0.0, 0, -20])
    return [*f, *np.cross([0.4, 0.3, 5.0], f)]


@reference("screws", 13)
def _():
    # a turn of 2 pi about z along a screw of pitch h lifts by 2 pi h: the lead
    h = 0.002 / (2 * math.pi)
    lift = sk.screw_motion([0, 0, 1], [0, 0, 0], h, 2 * math.pi)[2, 3]
    assert math.isclose(lift, 0.002, abs_tol=1e-15)
    return h


@reference("screws", 14)
def _():
    # the force times the velocity of its point of application, omega x r
    f = 10 * np.array([0, math.cos(math.pi / 3), math.sin(math.pi / 3)])
    return f @ np.cross([0, 0, 3.0], [0.2, 0, 0])


@reference("screws", 16)
def _():
    # the four joint twists written out, their numerical rank
    twists = np.array(
        [
            [0, 0, 1, 0, 0, 0],
            [0, 0, 1, 0, -0.4, 0],
            [0, 0, 0, 0, 0, 1],
            [0, 0, 1, 0.25, -0.4, 0],
        ]
    )
    return 6 - np.linalg.matrix_rank(twists)


@reference("screws", 22)
def _():
    # move the wrench to a point c of its axis, where the moment is parallel to f
    f, m = np.array([0.0, 0, 10]), np.array([0.0, -1, 2])
    c = np.array([0.1, 0, 0])  # the drill's line
    m_c = m - np.cross(c, f)
    assert np.allclose(np.cross(m_c, f), 0)
    return m_c @ f / (f @ f)


# ---- poe ---------------------------------------------------------------------------


@reference("poe", 2)
def _():
    # B = Ad(M^-1) S, M a translation by p = (2, 0, 0): same omega, v = v_s + omega x p
    p = np.array([2.0, 0, 0])
    rows = []
    for w, v in (([0, 0, 1.0], [0, 0, 0.0]), ([0, 0, 1.0], [0, -1.0, 0])):
        rows.append([*w, *(np.array(v) + np.cross(w, p))])
    return rows


@reference("poe", 3)
def _():
    # the logarithm of a translation by the series log(I + N) = N - N^2/2 ..., N^2 = 0
    T = np.eye(4)
    T[:3, 3] = [1, 2, 2]
    N = T - np.eye(4)
    assert np.allclose(N @ N, 0)
    return [0, 0, 0, *N[:3, 3]]


@reference("poe", 7)
def _():
    # turn the tool point about the line x = 0, y = 6 (along -z), slide h q along -z
    p, c, q, h = np.array([0.0, 6, 2]), np.array([0.0, 6, 0]), math.pi / 2, 0.1
    p_new = c + rot("z", -q) @ (p - c) + h * q * np.array([0, 0, -1.0])
    M = np.array([[-1, 0, 0, 0], [0, 1, 0, 6], [0, 0, -1, 2], [0, 0, 0, 1.0]])
    arm = sk.Chain.from_screws(
        [[0, 0, 1, 4, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, -1, -6, 0, -0.1]], M
    )
    np.testing.assert_allclose(arm.fk([0, 0, q])[:3, 3], p_new, atol=1e-12)
    return p_new


@reference("poe", 8)
def _():
    q = 2 * math.pi / 3
    c = np.array([1.0, 0, 0])
    return c + rot("z", q) @ (np.array([2.0, 0, 0]) - c) + [0, 0, 0.05 * q]


@reference("poe", 10)
def _():
    # T [V_b] T^-1 for T a translation by (0, 2, 0), then read the twist off the matrix
    T = np.eye(4)
    T[:3, 3] = [0, 2, 0]
    V_b = np.zeros((4, 4))
    V_b[0, 1], V_b[1, 0] = -1, 1  # [omega] for omega = (0, 0, 1), v = 0
    V_a = T @ V_b @ np.linalg.inv(T)
    return [V_a[2, 1], V_a[0, 2], V_a[1, 0], *V_a[:3, 3]]


# ---- puma_fk -----------------------------------------------------------------------


@reference("puma_fk", 2)
def _():
    ready = [0, math.pi / 2, -math.pi / 2, 0, 0, 0]
    x, y, _ = dh_fk(PUMA_TABLE, ready)[:3, 3]
    return math.hypot(x, y)


@reference("puma_fk", 3)
def _():
    ready = [0, math.pi / 2, -math.pi / 2, 0, 0, 0]
    x, y, _ = dh_fk(PUMA_TABLE, ready)[:3, 3]
    return (math.hypot(x, y) - D3) * 1000


@reference("puma_fk", 5)
def _():
    return dh_fk(PUMA_TABLE, np.zeros(6))[:3, 3]


@reference("puma_fk", 9)
def _():
    table = [(0.4, 0.1, -math.pi / 2), (0, 0.4, 0), (0, 0.3, 0)]
    return dh_fk(table, [0, -math.pi / 2, 0])[:3, 3]


@reference("puma_fk", 10)
def _():
    # the distance between the elbow and forearm-roll axes, from screwkit's joint screws
    axes = puma().screw_axes()
    z, points = axes[:, :3], np.cross(axes[:, :3], axes[:, 3:])
    n = np.cross(z[2], z[3])
    return abs((points[3] - points[2]) @ n) / np.linalg.norm(n) * 1000


# ---- puma_ik -----------------------------------------------------------------------


def elbow_grid():
    """The squared shoulder-to-wrist distance in the arm's plane on a grid of q3."""
    q3 = np.linspace(-math.pi, math.pi, 2_000_001)
    c3, s3 = np.cos(q3), np.sin(q3)
    return q3, (A2 + A3 * c3 - D4 * s3) ** 2 + (A3 * s3 + D4 * c3) ** 2


@reference("puma_ik", 4)
def _():
    q3, distance2 = elbow_grid()
    return q3[np.argmax(distance2)]


@reference("puma_ik", 5)
def _():
    q3, distance2 = elbow_grid()
    best = q3[np.argmax(distance2)]
    # the same through the DH table: at full stretch the wrist centre is that far from
    # the shoulder in the arm's plane, which is d3 to the side of the base origin
    p = dh_fk(PUMA_TABLE, [0.2, 0.3, best, 0, 0, 0])[:3, 3]
    np.testing.assert_allclose(
        math.sqrt(p @ p - D3**2), math.sqrt(distance2.max()), atol=1e-9
    )
    return math.sqrt(distance2.max())


def puma_limits_ok(q):
    low = np.radians([-160, -45, -225, -110, -100, -266])
    high = np.radians([160, 225, 45, 170, 100, 266])
    shifts = 2 * math.pi * np.arange(-2, 3)
    return all(
        np.any((v + shifts >= lo) & (v + shifts <= hi))
        for v, lo, hi in zip(q, low, high)
    )


@reference("puma_ik", 9)
def _():
    # the chapter's eight solutions by its own formulas, written again here
    q_true = np.radians([20, 40, -110, 30, 50, -20])
    T = dh_fk(PUMA_TABLE, q_true)
    wx, wy, wz = T[:3, 3]
    r, phi = math.hypot(wx, wy), math.atan2(wy, wx)
    rho, beta = math.hypot(A3, D4), math.atan2(D4, A3)
    count, found = 0, 0
    for arm in (1, -1):
        q1 = phi + math.asin(D3 / r) if arm == 1 else phi + math.pi - math.asin(D3 / r)
        V = arm * math.sqrt(r**2 - D3**2)
        cosine = (V**2 + wz**2 - A2**2 - rho**2) / (2 * A2 * rho)
        for elbow in (1, -1):
            q3 = elbow * math.acos(cosine) - beta
            c3, s3 = math.cos(q3), math.sin(q3)
            q2 = math.atan2(wz, V) - math.atan2(
                A3 * s3 + D4 * c3, A2 + A3 * c3 - D4 * s3
            )
            R03 = dh_fk(PUMA_TABLE[:3], [q1, q2, q3])[:3, :3]
            R36 = R03.T @ T[:3, :3]
            m5 = math.atan2(math.hypot(R36[0, 2], R36[1, 2]), R36[2, 2])
            q4, q6 = math.atan2(R36[1, 2], R36[0, 2]), math.atan2(R36[2, 1], -R36[2, 0])
            for q in (
                [q1, q2, q3, q4, -m5, q6],
                [q1, q2, q3, q4 + math.pi, m5, q6 + math.pi],
            ):
                np.testing.assert_allclose(dh_fk(PUMA_TABLE, q), T, atol=1e-9)
                found += 1
                count += puma_limits_ok(q)
    assert found == 8
    return count


@reference("puma_ik", 10)
def _():
    twin = [0.3 + math.pi, -0.5, 0.2 + math.pi]
    wrist = lambda q4, q5, q6: rot("z", q4) @ rot("y", -q5) @ rot("z", q6)  # noqa: E731
    np.testing.assert_allclose(wrist(*twin), wrist(0.3, 0.5, 0.2), atol=1e-12)
    return twin
