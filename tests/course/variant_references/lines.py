"""Independent references for the parametrised exercises of lines: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

import numpy as np
import sympy as sp

import screwkit as sk

INDEPENDENT = {}


def nearest_point_by_projection(n):
    # a point p of the line solves p x w = m (least squares: a line of solutions);
    # take away its part along w: what is left is the foot of the perpendicular
    w = np.array([n[f"w{i}"][0] for i in range(1, 4)], float)
    m = np.array([n[f"m{i}"][0] for i in range(1, 4)], float)
    minus_skew_w = np.array([[0, w[2], -w[1]], [-w[2], 0, w[0]], [w[1], -w[0], 0]])
    p, *_ = np.linalg.lstsq(minus_skew_w, m, rcond=None)  # p x w = -[w] p
    return p - (p @ w) / (w @ w) * w


def lever_rule(n):
    # the resultant F1 + F2 passes where the moments about it balance:
    # F1 x = F2 (d - x)
    F1, F2, d = n["F1"][0], n["F2"][0], n["d"][0]
    return [F2 * d / (F1 + F2), 0.0, 0.0]


def pitch_on_the_cylindroid(n):
    # h(theta) = h1 cos^2(theta) + h2 sin^2(theta)
    c, s = math.cos(math.radians(n["theta"][0])), math.sin(math.radians(n["theta"][0]))
    return n["h1"][0] * c**2 + n["h2"][0] * s**2


def null_space_of_the_leg_lines(n):
    # the screw reciprocal to the six leg lines at Fichter's turn: the null space of
    # L Delta, L the leg lines (direction; moment about the origin) from the
    # catalogue's attachment points (its pitch is -sqrt(3) / (4 z))
    z = n["z"][0]
    base = np.array(sp.Matrix(sk.parallel.catalogue.STEWART_BASE), dtype=float)
    top = np.array(sp.Matrix(sk.parallel.catalogue.STEWART_PLATFORM), dtype=float)
    turn = np.array([[0.0, -1, 0], [1, 0, 0], [0, 0, 1]])  # 90 deg about z
    tops = top @ turn.T + [0.0, 0.0, z]
    L = np.array([np.r_[q - p, np.cross(p, q)] for p, q in zip(base, tops)])
    Delta = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])
    rho = np.linalg.svd(L @ Delta)[2][-1]
    return rho[:3] @ rho[3:] / (rho[:3] @ rho[:3])


INDEPENDENT[2] = nearest_point_by_projection
INDEPENDENT[8] = lever_rule
INDEPENDENT[9] = pitch_on_the_cylindroid
INDEPENDENT[21] = null_space_of_the_leg_lines
