"""Independent references for the parametrised exercises of motion_in_time: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def peak_of_the_quintic(n):
    # ds/dt = 30 tau^2 (1 - tau)^2 / T is largest at tau = 1/2: 30/16/T
    return 15 / (8 * n["T"][0])


def shortest_trapezoid(n):
    # each ramp lasts v / a and covers v^2 / (2 a); the cruise at v covers the rest of
    # s = 1 (the statements' v^2 < a, so the ramps leave some)
    v, a = n["v"][0], n["a"][0]
    ramp_time, ramp_length = v / a, v * v / (2 * a)
    assert 2 * ramp_length < 1
    return 2 * ramp_time + (1 - 2 * ramp_length) / v


def bang_bang_duration(n):
    # the phase plane of s: U = a / Delta, L = -a / Delta; s'^2 = 2 U s from (0, 0)
    # and s'^2 = 2 U (1 - s) from (1, 0) cross at s = 1/2, s' = sqrt(U); each half
    # takes s' / U
    u = n["a"][0] / n["Delta"][0]
    return 2 * math.sqrt(u) / u


INDEPENDENT[3] = peak_of_the_quintic
INDEPENDENT[4] = shortest_trapezoid
INDEPENDENT[15] = bang_bang_duration
