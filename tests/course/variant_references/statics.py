"""Independent references for the parametrised exercises of statics: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def shoulder_torque_of_the_push(n):
    # joint 1's torque is the z moment about the origin of the tip force (f, 0):
    # x f_y - y f_x = -y f, with y = l1 sin q1 + l2 sin(q1 + q2)
    l1, l2, f = n["l1"][0], n["l2"][0], n["f"][0]
    q1, q12 = math.radians(n["q1"][0]), math.radians(n["q1"][0] + n["q2"][0])
    return -(l1 * math.sin(q1) + l2 * math.sin(q12)) * f


def shoulder_torque_holding_the_load(n):
    # the tip pushes the load up with M g at x = l1 + l2
    return n["M"][0] * 9.81 * (n["l1"][0] + n["l2"][0])


def springs_in_series(n):
    # a couple loads both joints alike; the tool turns by the sum of their turns
    k1, k2 = n["k1"][0], n["k2"][0]
    return 1 / (1 / k1 + 1 / k2)


INDEPENDENT[1] = shoulder_torque_of_the_push
INDEPENDENT[4] = shoulder_torque_holding_the_load
INDEPENDENT[18] = springs_in_series
