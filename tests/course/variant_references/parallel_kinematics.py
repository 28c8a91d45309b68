"""Independent references for the parametrised exercises of parallel_kinematics:
exercise number -> a function of the statement's numbers ({name: (value, unit)})
giving the key, written here from the statement, not with the generator's code."""

import math

INDEPENDENT = {}


def leg_length_at_home(n):
    # the base point (radius 1) and the platform point (radius r) are 30 deg apart
    # seen from the axis: law of cosines for the horizontal part, plus the height
    h, r = n["h"][0], n["r"][0]
    return math.sqrt(1 + r * r - 2 * r * math.cos(math.radians(30)) + h * h)


def largest_turn_within_the_leg_limits(n):
    # leg 2 joins the points at 15 deg (radius 1) and 45 deg + phi (radius 0.5):
    # rho^2 = h^2 + 1 + 0.25 - cos(phi + 30 deg) reaches rho_max^2 at
    # phi = acos(h^2 + 1.25 - rho_max^2) - 30 deg; leg 1 (phi - 30 deg) is shorter
    h, rho_max = n["h"][0], n["rho_max"][0]
    return math.degrees(math.acos(h * h + 1.25 - rho_max**2)) - 30


INDEPENDENT[10] = leg_length_at_home
INDEPENDENT[14] = largest_turn_within_the_leg_limits
