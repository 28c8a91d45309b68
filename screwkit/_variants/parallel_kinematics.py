"""The parametrised exercises of the chapter parallel_kinematics: the keys'
computations.

The statements and their draws are in screwkit/answers/parallel_kinematics.toml.
"""

import math

import numpy as np

from ..parallel.catalogue import STEWART_PLATFORM, stewart_gough
from ..transforms import homogeneous, rotz
from . import register


def _stewart(platform_radius, height):
    """The default Stewart-Gough platform with its platform points on a circle of
    ``platform_radius`` (m) and its home ``height`` (m) up, without leg limits."""
    platform = np.array(STEWART_PLATFORM, dtype=float) * (platform_radius / 0.5)
    return stewart_gough(platform=platform, height=height, leg_limits=None)


@register("parallel_kinematics", 10)
def leg_length_at_home(h, r):
    """Leg 1's length (m) at the home pose, h (m) up, of the platform of radius r."""
    pm = _stewart(r, h)
    return pm.ik(pm.home())[0]


@register("parallel_kinematics", 14)
def largest_turn_within_the_leg_limits(h, rho_max):
    """The largest turn (deg) about the vertical, at the home height h (m), that keeps
    every leg of the default platform shorter than ``rho_max`` (m)."""
    pm = _stewart(0.5, h)

    def longest_leg(turn):
        return float(np.max(pm.ik(homogeneous(rotz(turn), [0, 0, h]))))

    # the longest leg lengthens as the platform turns from 0 to 150 deg: bisect
    low, high = 0.0, math.radians(150)
    for _ in range(45):
        middle = (low + high) / 2
        low, high = (middle, high) if longest_leg(middle) < rho_max else (low, middle)
    return math.degrees((low + high) / 2)
