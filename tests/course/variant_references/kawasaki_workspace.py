"""Independent references for the parametrised exercises of kawasaki_workspace: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def annulus(n):
    # l1 - l2 <= r <= l1 + l2: pi ((l1 + l2)^2 - (l1 - l2)^2) = 4 pi l1 l2
    return 4 * math.pi * n["l1"][0] * n["l2"][0]


def closest_reach(n):
    # r^2 = l1^2 + l2^2 + 2 l1 l2 cos q2 falls as q2 grows to the limit (< 180 deg)
    l1, l2, limit = n["l1"][0], n["l2"][0], math.radians(n["limit"][0])
    return math.sqrt(l1**2 + l2**2 + 2 * l1 * l2 * math.cos(limit))


def dexterous_annulus(n):
    # joint 3's circle of radius l3 about the tip must lie in the two-link annulus
    # (here l3 < l1 - l2 and l3 < l2): l1 - l2 + l3 <= r <= l1 + l2 - l3
    l1, l2, l3 = n["l1"][0], n["l2"][0], n["l3"][0]
    return math.pi * ((l1 + l2 - l3) ** 2 - (l1 - l2 + l3) ** 2)


def elbow_angle(n):
    # the law of cosines: cos q2 = (x^2 + y^2 - l1^2 - l2^2) / (2 l1 l2)
    l1, l2, x, y = n["l1"][0], n["l2"][0], n["x"][0], n["y"][0]
    return math.acos((x**2 + y**2 - l1**2 - l2**2) / (2 * l1 * l2))


INDEPENDENT[10] = annulus
INDEPENDENT[12] = closest_reach
INDEPENDENT[13] = dexterous_annulus
INDEPENDENT[15] = elbow_angle
