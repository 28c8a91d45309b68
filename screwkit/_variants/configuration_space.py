"""The parametrised exercises of the chapter configuration_space: the keys'
computations.

The statements and their draws are in screwkit/answers/configuration_space.toml.
"""

import math

import numpy as np

from ..mobility_analysis import grubler_kutzbach
from ..robots import planar
from . import register


def _distance_constraints(points, dimension, freedoms_order):
    """The coordinates of ``points`` points less the freedoms of a rigid body (a body
    joined to the ground by no joint: 2 links, no joint), and the coordinates."""
    coordinates = dimension * points
    body = grubler_kutzbach(links=2, joints=0, freedoms=0, order=freedoms_order)
    return coordinates - body, {"coordinates": coordinates}


@register("configuration_space", 1)
def distance_constraints_in_the_plane(n):
    """The distance constraints that tie n points of a body in the plane: their 2 n
    coordinates less the body's 3 freedoms."""
    return _distance_constraints(n, 2, freedoms_order=3)


@register("configuration_space", 2)
def distance_constraints_in_space(n):
    """The distance constraints that tie n points of a body in space: their 3 n
    coordinates less the body's 6 freedoms."""
    return _distance_constraints(n, 3, freedoms_order=6)


@register("configuration_space", 5)
def platform_on_sps_legs(legs):
    """Grübler's count of a platform on ``legs`` SPS legs."""
    # ground, platform, and a cylinder and a rod per leg; S, P and S joints
    return grubler_kutzbach(2 + 2 * legs, 3 * legs, (3 + 1 + 3) * legs)


@register("configuration_space", 14)
def area_of_the_2r_workspace(l1, l2):
    """The area (m²) of the annulus a planar 2R arm without joint limits reaches."""
    arm = planar([l1, l2])
    # the boundaries: the tip stretched out and folded back, about the base
    outer = np.linalg.norm(arm.fk([0.0, 0.0])[:2, 3])
    inner = np.linalg.norm(arm.fk([0.0, math.pi])[:2, 3])
    return math.pi * (outer**2 - inner**2)
