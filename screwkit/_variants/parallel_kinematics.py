"""The parametrised exercises of the chapter parallel_kinematics."""

import math

import numpy as np

from ..parallel.catalogue import STEWART_PLATFORM, stewart_gough
from ..transforms import homogeneous, rotz
from . import pick, register


def _stewart(platform_radius, height):
    """The default Stewart-Gough platform with its platform points on a circle of
    ``platform_radius`` (m) and its home ``height`` (m) up, without leg limits."""
    platform = np.array(STEWART_PLATFORM, dtype=float) * (platform_radius / 0.5)
    return stewart_gough(platform=platform, height=height, leg_limits=None)


@register("parallel_kinematics", 10)
def leg_length_at_home(rng):
    height = pick(rng, [0.8, 0.9, 1.0, 1.1, 1.2, 1.4], 1.0)
    radius = pick(rng, [0.4, 0.5, 0.6], 0.5)
    pm = _stewart(radius, height)
    numbers = {"h": (height, "m"), "r": (radius, "m")}
    statement = (
        f"At its home pose a Stewart-Gough platform stands {height:g} m above the "
        f"base, unrotated; leg 1 joins the base point at -15 deg on the unit circle "
        f"to the platform point at -45 deg on the circle of radius {radius:g} m. How "
        f"long is the leg, in metres?"
    )
    return numbers, statement, float(pm.ik(pm.home())[0])


@register("parallel_kinematics", 14)
def largest_turn_within_the_leg_limits(rng):
    # every height and upper limit: the home pose within the limits, the lower limit
    # 0.9 m never reached (rho^2 >= h^2 + 1/4 > 0.81) and the turn below 150 deg
    height = pick(rng, [0.8, 0.9, 1.0, 1.1, 1.2], 1.0)
    longest = pick(rng, [1.4, 1.5, 1.6], 1.6)
    pm = _stewart(0.5, height)

    def longest_leg(turn):
        return float(np.max(pm.ik(homogeneous(rotz(turn), [0, 0, height]))))

    # the longest leg lengthens as the platform turns from 0 to 150 deg: bisect
    low, high = 0.0, math.radians(150)
    for _ in range(45):
        middle = (low + high) / 2
        low, high = (middle, high) if longest_leg(middle) < longest else (low, middle)
    numbers = {"h": (height, "m"), "rho_max": (longest, "m")}
    statement = (
        f"At its home position, {height:g} m up, a Stewart-Gough platform of the "
        f"default geometry turns about the vertical axis by phi. Write leg 1's and "
        f"leg 2's lengths as functions of phi (law of cosines, as in exercise 10), "
        f"and find the largest turn phi > 0 (in deg) that the leg limits of 0.9 to "
        f"{longest:g} m allow: a point of the orientation workspace's edge."
    )
    return numbers, statement, math.degrees((low + high) / 2)
