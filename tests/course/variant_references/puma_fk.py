"""Independent references for the parametrised exercises of puma_fk: exercise number
-> a function of the statement's numbers ({name: (value, unit)}) giving the key,
written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def spherical_arm_position(n):
    # at home the tool is q3 above the shoulder point (0, 0.15, 0.4); q2 about +y tips
    # the boom from +z to (sin q2, 0, cos q2); then q1 turns (x, y) about z
    q1, q2, q3 = n["q1"][0], n["q2"][0], n["q3"][0]
    x, y, z = q3 * math.sin(q2), 0.15, 0.4 + q3 * math.cos(q2)
    return [
        math.cos(q1) * x - math.sin(q1) * y,
        math.sin(q1) * x + math.cos(q1) * y,
        z,
    ]


def common_normal_of_two_axes(n):
    # both axes are perpendicular to y: the normal runs along y, at the height of the
    # second axis, from (0, 0, z) to (0, y, z); its length is |y|
    return [abs(n["y"][0]), n["z"][0]]


def cylindrical_arm_position(n):
    # the carriage at 0.3 + q2, the arm reaching q3 along +y_0, turned by q1 about z_0
    q1, lift, reach = n["q1"][0], n["q2"][0], n["q3"][0]
    return [-reach * math.sin(q1), reach * math.cos(q1), 0.3 + lift]


INDEPENDENT[15] = spherical_arm_position
INDEPENDENT[18] = common_normal_of_two_axes
INDEPENDENT[22] = cylindrical_arm_position
