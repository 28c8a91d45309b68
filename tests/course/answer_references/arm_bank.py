"""The answer keys of the problem bank's arms (issue 42) in the PoE, PUMA FK and PUMA
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
    shoulder, elbow, tool = (np.array(p) for p in ([0, 0, 0.3], [0.35, 0, 0.3],
                                                    [0.65, 0, 0.3]))
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
    for row in ((math.pi / 2, 0.4, 0, -math.pi / 2), (math.pi / 2, 0.15, 0, math.pi / 2),
                (0, 0.5, 0, 0)):
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
