"""Independent references for the parametrised exercises of screws: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

import numpy as np

INDEPENDENT = {}


def power_of_the_force(n):
    # the force's moment about the origin is x F along z; the body turns at omega
    # about z through the origin, so every point of the z axis is at rest: P = x F omega
    return n["x"][0] * n["F"][0] * n["omega"][0]


INDEPENDENT[6] = power_of_the_force


def nearest_point_by_least_squares(n):
    # s0 = r x s + h s = -[s] r + h s: solve for (r, h) by least squares (a line of
    # solutions r, the points of the axis); take away the part of r along s
    S = [n[f"S{i}"][0] for i in range(1, 7)]
    s, s0 = np.array(S[:3], float), np.array(S[3:], float)
    skew = np.array([[0, -s[2], s[1]], [s[2], 0, -s[0]], [-s[1], s[0], 0]])
    A = np.column_stack([-skew, s])
    solution, *_ = np.linalg.lstsq(A, s0, rcond=None)
    r = solution[:3]
    return r - (r @ s) / (s @ s) * s


def wrench_of_the_weight(n):
    # f = (0, 0, -F), m = (x, y, 0) x (0, 0, -F) = (-y F, x F, 0), written out
    F, x, y = n["F"][0], n["x"][0], n["y"][0]
    return [0.0, 0.0, -F, -y * F, x * F, 0.0]


def pitch_of_the_thread(n):
    # one turn (2 pi rad) moves the nut one lead (mm -> m); a left-hand thread
    # advances against the right-hand rule: a negative pitch
    sign = 1.0 if n["right_hand"][0] else -1.0
    return sign * n["lead"][0] / 1000 / (2 * math.pi)


INDEPENDENT[5] = nearest_point_by_least_squares
INDEPENDENT[12] = wrench_of_the_weight
INDEPENDENT[13] = pitch_of_the_thread
