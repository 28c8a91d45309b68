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


def quaternion_of_a_turn(n):
    # q = (cos(theta/2), sin(theta/2) u), with u the axis (0 x, 1 y, 2 z); theta is
    # below 180 deg, so w > 0 (the representative screwkit gives)
    half = math.radians(n["angle"][0]) / 2
    q = [math.cos(half), 0.0, 0.0, 0.0]
    q[1 + int(n["axis"][0])] = math.sin(half)
    return q


def point_in_the_fixed_frame(n):
    # x_b = y_s and y_b = -x_s: the point (x, y, z) of {b} is 1 - y, 2 + x, z in {s}
    x, y, z = n["x_b"][0], n["y_b"][0], n["z_b"][0]
    return [1.0 - y, 2.0 + x, z]


def body_twist_of_the_cart(n):
    # it turns once per lap, omega = v / rho about z_b (= z_s); its own origin moves
    # forward, along x_b, at v
    v, rho = n["speed"][0], n["radius"][0]
    return [0.0, 0.0, v / rho, v, 0.0, 0.0]


INDEPENDENT[7] = quaternion_of_a_turn
INDEPENDENT[11] = point_in_the_fixed_frame
INDEPENDENT[16] = body_twist_of_the_cart
