"""Independent references for the parametrised exercises of redundancy: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def least_norm_rates_of_the_last_link(n):
    # minimise sum qdot_i^2 subject to sum qdot_i = phidot: by Lagrange every
    # qdot_i equals the multiplier, so each joint takes phidot / n
    return n["phidot"][0] / n["n"][0]


def tip_of_a_three_link_arm(n):
    # add the links' vectors, link i pointing at the angle q1 + ... + qi
    x = y = heading = 0.0
    for i in (1, 2, 3):
        heading += math.radians(n[f"q{i}"][0])
        x += n[f"l{i}"][0] * math.cos(heading)
        y += n[f"l{i}"][0] * math.sin(heading)
    return [x, y]


def least_norm_rates_along_a_path(n):
    # at q = (0, 90, -90) deg the joints are at (0, 0), (l1, 0), (l1, l2) and the
    # tip at (l1 + l3, l2); column i is (-(y - y_i), x - x_i):
    # J = [[-l2, -l2, 0], [l1 + l3, l3, l3]]; J J^T = [[a, b], [b, c]] inverted by
    # hand (Cramer), then qdot = J^T (J J^T)^-1 (v, 0)
    l1, l2, l3, v = (n[k][0] for k in ("l1", "l2", "l3", "v"))
    rows = [[-l2, -l2, 0.0], [l1 + l3, l3, l3]]
    a = sum(r * r for r in rows[0])
    b = sum(r * s for r, s in zip(rows[0], rows[1], strict=True))
    c = sum(s * s for s in rows[1])
    det = a * c - b * b
    y1, y2 = c * v / det, -b * v / det
    return [rows[0][i] * y1 + rows[1][i] * y2 for i in range(3)]


INDEPENDENT[4] = least_norm_rates_of_the_last_link
INDEPENDENT[13] = tip_of_a_three_link_arm
INDEPENDENT[14] = least_norm_rates_along_a_path
