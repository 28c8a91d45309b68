"""The parametrised exercises of the chapter configuration_space."""

import math

import numpy as np

from ..mobility_analysis import grubler_kutzbach
from ..robots import planar
from . import pick, register


def _freedoms_of_a_free_body(order):
    # a body joined to the ground by no joint at all: 2 links, no joint
    return grubler_kutzbach(links=2, joints=0, freedoms=0, order=order)


@register("configuration_space", 1)
def distance_constraints_in_the_plane(rng):
    points = pick(rng, [3, 4, 5, 6, 7, 8, 9], 3)
    coordinates = 2 * points
    numbers = {"n": (points, "")}
    statement = (
        f"A rigid body in the plane is placed by {points} of its points, not all on "
        f"one line. How many independent distance constraints tie their "
        f"{coordinates} coordinates?"
    )
    # the coordinates less the freedoms of a rigid body in the plane
    return numbers, statement, float(coordinates - _freedoms_of_a_free_body(3))


@register("configuration_space", 2)
def distance_constraints_in_space(rng):
    points = pick(rng, [4, 5, 6, 7, 8, 9, 10], 4)
    coordinates = 3 * points
    numbers = {"n": (points, "")}
    statement = (
        f"Take {points} points of a rigid body in space, not all in one plane: how "
        f"many independent distance constraints tie their {coordinates} coordinates?"
    )
    # the coordinates less the freedoms of a rigid body in space
    return numbers, statement, float(coordinates - _freedoms_of_a_free_body(6))


@register("configuration_space", 5)
def platform_on_sps_legs(rng):
    legs = pick(rng, [2, 3, 4, 5, 6, 7, 8], 6)
    # ground, platform, and a cylinder and a rod per leg; S, P and S joints
    links, joints, freedoms = 2 + 2 * legs, 3 * legs, (3 + 1 + 3) * legs
    numbers = {"legs": (legs, "")}
    statement = (
        f"A platform joined to the ground by {legs} SPS legs (a spherical joint at "
        f"each end of every prismatic leg). What does the spatial Grübler formula "
        f"give?"
    )
    return numbers, statement, float(grubler_kutzbach(links, joints, freedoms))


@register("configuration_space", 14)
def area_of_the_2r_workspace(rng):
    l1 = pick(rng, [0.3, 0.4, 0.5, 0.6, 0.8, 1.0], 0.5)
    l2 = pick(rng, [0.1, 0.2, 0.3, 0.4, 0.5], 0.3)
    arm = planar([l1, l2])
    # the boundaries: the tip stretched out and folded back, about the base
    outer = np.linalg.norm(arm.fk([0.0, 0.0])[:2, 3])
    inner = np.linalg.norm(arm.fk([0.0, math.pi])[:2, 3])
    numbers = {"l1": (l1, "m"), "l2": (l2, "m")}
    statement = (
        f"The area (m²) of the workspace of a planar 2R arm, l1 = {l1} m and "
        f"l2 = {l2} m, with joints that turn without limits."
    )
    return numbers, statement, float(math.pi * (outer**2 - inner**2))
