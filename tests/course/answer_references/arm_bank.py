"""The answer keys of the problem bank's arms in the PoE, PUMA FK and PUMA
IK chapters, each recomputed another way than the chapter's solution: a joint's twist
as the velocity field of a small turn about its line, a pose by turning points with
elementary rotations, a DH pose by the hand-multiplied link matrices of
tests/references.py, an IK answer by bisection or by the forward kinematics."""

import math

import numpy as np
from references import dh_fk, dh_standard, rot

from .registry import reference


def _turn_twist(direction, point, eps=1e-7):
    """The twist (omega; v) of a unit turn about a line: the velocity of the body
    point at the origin, by a central difference of a turn by +-eps about the line."""
    w = np.asarray(direction, float)
    c = np.asarray(point, float)

    def moved(angle):
        # Rodrigues' rotation of the origin about the line through c along w
        u = -c
        R_u = (
            u * math.cos(angle)
            + np.cross(w, u) * math.sin(angle)
            + w * (w @ u) * (1 - math.cos(angle))
        )
        return c + R_u

    return np.r_[w, (moved(eps) - moved(-eps)) / (2 * eps)]


# ---- poe -----------------------------------------------------------------------------


@reference("poe", 12)
def _():
    return _turn_twist([0, 0, 1.0], [0.7, 0, 0.2])


@reference("poe", 14)
def _():
    # turn the forearm, then the whole arm, as point rotations about their axes
    shoulder, elbow, tool = (
        np.array(p) for p in ([0, 0, 0.3], [0.35, 0, 0.3], [0.65, 0, 0.3])
    )
    tool = elbow + rot("y", math.pi / 2) @ (tool - elbow)
    return shoulder + rot("y", -math.pi / 2) @ (tool - shoulder)


@reference("poe", 15)
def _():
    return _turn_twist([0, 1.0, 0], [0.815, -0.3, 0.16])


@reference("poe", 16)
def _():
    return rot("z", math.pi / 2) @ (np.array([0.6, 0, 0.4]) + [0.2, 0, 0])


@reference("poe", 17)
def _():
    # the waist's turn as seen from the tool: the velocity of the tool's origin
    return _turn_twist([0, 0, 1.0], [-0.3, 0, -0.5])


# ---- puma_fk -------------------------------------------------------------------------


@reference("puma_fk", 12)
def _():
    # the angle at joint 2 between the link's first part and the line to the tool
    return math.degrees(math.asin(0.1 / math.hypot(0.4, 0.1)))


@reference("puma_fk", 15)
def _():
    # the hand-multiplied DH links, joint 3 prismatic (its d is q3)
    T = np.eye(4)
    for row in (
        (math.pi / 2, 0.4, 0, -math.pi / 2),
        (math.pi / 2, 0.15, 0, math.pi / 2),
        (0, 0.5, 0, 0),
    ):
        T = T @ dh_standard(*row)
    return T[:3, 3]


@reference("puma_fk", 18)
def _():
    # the closest points of p1 + t z1 and p2 + u z2 by least squares on (t, u)
    p1, z1 = np.zeros(3), np.array([0, 0, 1.0])
    p2, z2 = np.array([0.3, 0.2, 0.5]), np.array([1.0, 0, 0])
    (t, u), *_ = np.linalg.lstsq(np.column_stack([z1, -z2]), p2 - p1, rcond=None)
    a = np.linalg.norm(p2 + u * z2 - (p1 + t * z1))
    return [a, t]


@reference("puma_fk", 22)
def _():
    return rot("z", math.pi / 2) @ np.array([0, 0.3, 0.3 + 0.2])


# ---- puma_ik -------------------------------------------------------------------------


def _bisect(f, low, high):
    """A root of f in [low, high], where f changes sign."""
    for _ in range(60):
        middle = (low + high) / 2
        if (f(low) > 0) == (f(middle) > 0):
            low = middle
        else:
            high = middle
    return (low + high) / 2


def _two_link_root(l1, l2, x, y):
    """(q1, q2) in degrees with q2 in (0, pi) that reach (x, y): q2 by bisection on the
    reach, q1 by the angle between the target and the arm's tip at q1 = 0."""
    reach = math.hypot(x, y)
    q2 = _bisect(
        lambda q: math.hypot(l1 + l2 * math.cos(q), l2 * math.sin(q)) - reach,
        1e-9,
        math.pi - 1e-9,
    )
    tip = complex(l1 + l2 * math.cos(q2), l2 * math.sin(q2))
    q1 = math.atan2(y, x) - math.atan2(tip.imag, tip.real)
    return [math.degrees(q1), math.degrees(q2)]


@reference("puma_ik", 13)
def _():
    return _two_link_root(0.5, 0.4, 0.6, 0.3)


@reference("puma_ik", 14)
def _():
    return _two_link_root(0.4, 0.3, 0.5, 0.2)


@reference("puma_ik", 16)
def _():
    # q2, q3 by bisection on the wrist centre of the arm's own DH table, in its plane
    table = [
        (0.45, 0.15, -math.pi / 2),
        (0, 0.6, 0),
        (0, 0.12, math.pi / 2),
        (0.72, 0, -math.pi / 2),
    ]
    q1 = math.atan2(0.3, 0.7)
    target = np.array([0.7, 0.3, 1.0])

    def wrist(q2, q3):
        return dh_fk(table, [q1, q2, q3, 0])[:3, 3]

    def q3_for(q2):  # the q3 in (-pi/2, pi/2) that puts the wrist at the target's reach
        shoulder = np.array([0.15 * math.cos(q1), 0.15 * math.sin(q1), 0.45])
        reach = np.linalg.norm(target - shoulder)
        return _bisect(
            lambda q3: np.linalg.norm(wrist(q2, q3) - shoulder) - reach,
            -math.pi / 2,
            math.pi / 2,
        )

    q2 = _bisect(lambda q2: wrist(q2, q3_for(q2))[2] - target[2], -0.5, 1.0)
    q3 = q3_for(q2)
    np.testing.assert_allclose(wrist(q2, q3), target, atol=1e-9)
    return [math.degrees(q1), math.degrees(q2), math.degrees(q3)]


@reference("puma_ik", 18)
def _():
    # the tool of the Stanford-type arm by its hand-multiplied DH links, solved by
    # bisection: q1 turns the offset plane onto the target, q2 tips the boom
    def tool(q1, q2, q3):
        T = np.eye(4)
        for row in (
            (q1, 0.4, 0, -math.pi / 2),
            (q2, 0.15, 0, math.pi / 2),
            (0, q3, 0, 0),
        ):
            T = T @ dh_standard(*row)
        return T[:3, 3]

    target = np.array([0.3, 0.4, 0.6])
    q3 = np.linalg.norm(target - [0, 0, 0.4]) ** 2 - 0.15**2
    q3 = math.sqrt(q3)
    q2 = math.acos((target[2] - 0.4) / q3)
    q1 = _bisect(lambda q1: tool(q1, q2, q3)[1] - target[1], 0.0, math.pi / 2)
    np.testing.assert_allclose(tool(q1, q2, q3), target, atol=1e-9)
    return [math.degrees(q1), math.degrees(q2)]


@reference("puma_ik", 21)
def _():
    # turn p about the vertical line through (1, 0, 0) until it reaches q, by bisection
    c = np.array([1.0, 0, 0])
    turned = lambda t: (c + rot("z", t) @ (np.array([2.0, 0, 0.5]) - c))[0]  # noqa: E731
    return math.degrees(_bisect(lambda t: turned(t) - 1.0, 0.1, math.pi - 0.1))


@reference("puma_ik", 22)
def _():
    def gap(t):
        return np.linalg.norm(rot("z", t) @ [1.0, 0, 0] - [2.0, 0, 0]) - 1.5

    return math.degrees(_bisect(gap, 0.0, math.pi))
