"""Independent references for the parametrised exercises of poe: exercise number -> a
function of the statement's numbers ({name: (value, unit)}) giving the key, written
here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def log_of_a_translation(n):
    # omega = 0, theta = |p| and v = p / |p|: S theta = (0, 0, 0, p)
    return [0.0, 0.0, 0.0, n["px"][0], n["py"][0], n["pz"][0]]


def nut_after_a_turn(n):
    # the tool circles the axis x = 1, y = 0 at radius 1 and rises h q, h = 0.05 m/rad
    q = n["q"][0]
    return [1 + math.cos(q), math.sin(q), 0.05 * q]


def elbow_arm_position(n):
    # in the arm's plane: shoulder at height 0.3, upper arm 0.35, forearm 0.3; a turn
    # by a about +y carries +x to (cos a, 0, -sin a); then the waist turns it about z
    q1, q2, q3 = n["q1"][0], n["q2"][0], n["q3"][0]
    reach = 0.35 * math.cos(q2) + 0.3 * math.cos(q2 + q3)
    height = 0.3 - 0.35 * math.sin(q2) - 0.3 * math.sin(q2 + q3)
    return [reach * math.cos(q1), reach * math.sin(q1), height]


def rpr_arm_position(n):
    # the roll leaves the tool on its axis; the slide moves it to 0.6 + q2 along x;
    # the waist turns (0.6 + q2, 0, 0.4) about z by q1
    q1, reach = n["q1"][0], 0.6 + n["q2"][0]
    return [reach * math.cos(q1), reach * math.sin(q1), 0.4]


INDEPENDENT[3] = log_of_a_translation
INDEPENDENT[8] = nut_after_a_turn
INDEPENDENT[14] = elbow_arm_position
INDEPENDENT[16] = rpr_arm_position
