"""Independent references for the parametrised exercises of puma_ik: exercise number
-> a function of the statement's numbers ({name: (value, unit)}) giving the key,
written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def offset_arm_wrist_centre(n):
    # the chapter's geometric derivation: q1 faces the wrist centre; in the arm's
    # plane the forearm is one link of length l at beta above the upper arm's line;
    # the law of cosines gives the elbow's angle gamma, and q3 = beta - gamma with
    # gamma in (0, pi) is the solution with abs(q3) < 90 deg
    x, y, z = n["x"][0], n["y"][0], n["z"][0]
    a1, d1, a2, a3, d4 = 0.15, 0.45, 0.6, 0.12, 0.72
    r, s = math.hypot(x, y) - a1, z - d1
    ell, beta = math.hypot(a3, d4), math.atan2(d4, a3)
    gamma = math.acos((r**2 + s**2 - a2**2 - ell**2) / (2 * a2 * ell))
    rise = math.atan2(s, r) - math.atan2(
        ell * math.sin(gamma), a2 + ell * math.cos(gamma)
    )
    return [
        math.degrees(math.atan2(y, x)),
        -math.degrees(rise),
        math.degrees(beta - gamma),
    ]


def spherical_arm_inverse(n):
    # from above, the horizontal distance splits into the 0.15 m offset and the boom's
    # horizontal part rho; in the boom's plane q3 sin q2 = rho, q3 cos q2 = z - 0.4
    x, y, z = n["x"][0], n["y"][0], n["z"][0]
    rho = math.sqrt(x**2 + y**2 - 0.15**2)
    q1 = math.atan2(y, x) - math.atan2(0.15, rho)
    q1 = math.remainder(q1, 2 * math.pi)
    return [math.degrees(q1), math.degrees(math.atan2(rho, z - 0.4))]


def subproblem_one(n):
    # the angle from the direction of p - r to that of q - r, both across the axis
    a, b = n["a"][0], n["b"][0]
    start = math.atan2(n["py"][0] - b, n["px"][0] - a)
    end = math.atan2(n["qy"][0] - b, n["qx"][0] - a)
    return math.degrees(math.remainder(end - start, 2 * math.pi))


def subproblem_three(n):
    # the law of cosines: p_r^2 + q_r^2 - 2 p_r q_r cos(theta) = delta^2
    p, q, delta = n["p"][0], n["q"][0], n["delta"][0]
    return math.degrees(math.acos((p**2 + q**2 - delta**2) / (2 * p * q)))


INDEPENDENT[16] = offset_arm_wrist_centre
INDEPENDENT[18] = spherical_arm_inverse
INDEPENDENT[21] = subproblem_one
INDEPENDENT[22] = subproblem_three
