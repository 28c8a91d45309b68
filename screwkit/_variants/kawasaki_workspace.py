"""The parametrised exercises of the chapter kawasaki_workspace."""

import math

import numpy as np

from ..ik.subproblems import subproblem3
from ..robots import planar
from . import pick, register


def _reach(arm, q):
    """The tip's distance from the base at q (m)."""
    return float(np.linalg.norm(arm.fk(np.radians(q))[:2, 3]))


@register("kawasaki_workspace", 10)
def area_of_the_two_link_workspace(rng):
    l1 = pick(rng, [0.4, 0.5, 0.6, 0.7], 0.5)
    l2 = pick(rng, [0.1, 0.2, 0.3], 0.3)
    arm = planar([l1, l2])
    outer, inner = _reach(arm, [0, 0]), _reach(arm, [0, 180])  # stretched, folded
    numbers = {"l1": (l1, "m"), "l2": (l2, "m")}
    statement = (
        f"A two-link arm (l1 = {l1} m, l2 = {l2} m) has no joint limits. Sketch its "
        f"workspace and give its inner and outer radii; type its area (m²) in the box."
    )
    return numbers, statement, math.pi * (outer**2 - inner**2)


@register("kawasaki_workspace", 12)
def closest_reach_with_an_elbow_limit(rng):
    l1 = pick(rng, [0.4, 0.5, 0.6], 0.5)
    l2 = pick(rng, [0.2, 0.3, 0.4], 0.3)
    limit = pick(rng, [90, 100, 120, 135, 150], 120)
    arm = planar([l1, l2])
    # every q2 in its range, to the limit itself (q1 does not change the distance)
    closest = min(_reach(arm, [0, q2]) for q2 in np.linspace(0, limit, 121))
    numbers = {"l1": (l1, "m"), "l2": (l2, "m"), "limit": (limit, "deg")}
    statement = (
        f"A two-link arm like that of exercise 11, l1 = {l1} m and l2 = {l2} m, has "
        f"the limits 0 <= q1 <= 180 deg and 0 <= q2 <= {limit} deg. How close to the "
        f"base can the tip come (m)?"
    )
    return numbers, statement, closest


@register("kawasaki_workspace", 13)
def area_of_the_dexterous_workspace(rng):
    l1 = pick(rng, [0.5, 0.6, 0.7], 0.5)
    l2 = pick(rng, [0.2, 0.3], 0.3)
    l3 = pick(rng, [0.05, 0.1, 0.15], 0.1)
    arm = planar([l1, l2, l3])
    # the tip with link 3 turned back: from the stretched arm, and from the folded one
    outer, inner = _reach(arm, [0, 0, 180]), _reach(arm, [0, 180, 180])
    numbers = {"l1": (l1, "m"), "l2": (l2, "m"), "l3": (l3, "m")}
    statement = (
        f"A planar three-link arm, l = ({l1}, {l2}, {l3}) m, has no joint limits. Its "
        f"dexterous workspace is the set of tip positions it reaches with every "
        f"orientation phi. Find it and give its area (m²)."
    )
    return numbers, statement, math.pi * (outer**2 - inner**2)


@register("kawasaki_workspace", 15)
def elbow_angle_for_a_target(rng):
    l1 = pick(rng, [0.5, 0.6], 0.5)
    l2 = pick(rng, [0.3, 0.4], 0.3)
    x = pick(rng, [0.4, 0.5, 0.6], 0.6)
    y = pick(rng, [0.1, 0.2, 0.3], 0.2)
    arm = planar([l1, l2])
    # turn the tip about joint 2 (at home) until it is |target| from the base
    angles = subproblem3(
        arm.screw_axes()[1], arm.fk([0.0, 0.0])[:3, 3], [0, 0, 0], math.hypot(x, y)
    )
    elbow = next(a for a in angles if 0 < a < math.pi)
    numbers = {"l1": (l1, "m"), "l2": (l2, "m"), "x": (x, "m"), "y": (y, "m")}
    statement = (
        f"The two-link arm (l1 = {l1} m, l2 = {l2} m) must put its tip on the point "
        f"({x}, {y}) m. Find q2 from the law of cosines; give the positive root."
    )
    return numbers, statement, float(elbow)
