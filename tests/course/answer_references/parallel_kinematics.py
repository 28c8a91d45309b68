"""The answer keys of the parallel-kinematics chapter, recomputed from the geometry
written out here (the default Stewart-Gough attachment angles of its docstring), not
from the key's formula nor from screwkit's legs.
"""

import numpy as np

from .registry import reference


def leg_1_at_home():
    """The vector from base point 1 (unit circle, -15 deg) to platform point 1 (radius
    0.5, -45 deg) with the platform 1 m up."""
    base = np.array([np.cos(np.radians(-15)), np.sin(np.radians(-15)), 0.0])
    platform = 0.5 * np.array([np.cos(np.radians(-45)), np.sin(np.radians(-45)), 0.0])
    return platform + [0, 0, 1] - base


@reference("parallel_kinematics", 10)
def _():
    return np.sqrt(np.sum(leg_1_at_home() ** 2))


@reference("parallel_kinematics", 11)
def _():
    leg = leg_1_at_home()
    return leg[2] / np.sqrt(np.sum(leg**2))
