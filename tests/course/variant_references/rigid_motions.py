"""Independent references for the parametrised exercises of rigid_motions: exercise
number -> a function of the statement's numbers ({name: (value, unit)}) giving the
key, written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def turn_about_a_vertical_line(n):
    # the origin is at (-a, -b) from the axis's foot (a, b): turn that arrow by the
    # angle about z and add it to the foot
    a, b, angle = n["a"][0], n["b"][0], n["angle"][0]
    c, s = math.cos(math.radians(angle)), math.sin(math.radians(angle))
    return [a + (-a * c + b * s), b + (-a * s - b * c), 0.0]


INDEPENDENT[2] = turn_about_a_vertical_line
