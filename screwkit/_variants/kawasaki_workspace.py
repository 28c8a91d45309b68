"""The parametrised exercises of the chapter kawasaki_workspace: the keys'
computations.

The statements and their draws are in screwkit/answers/kawasaki_workspace.toml.
"""

import math

import numpy as np

from ..ik.subproblems import subproblem3
from ..robots import planar
from . import register


def _reach(arm, q):
    """The tip's distance from the base at q (deg), in m."""
    return float(np.linalg.norm(arm.fk(np.radians(q))[:2, 3]))


@register("kawasaki_workspace", 10)
def area_of_the_two_link_workspace(l1, l2):
    """The area (m²) of the annulus a two-link arm without joint limits reaches."""
    arm = planar([l1, l2])
    outer, inner = _reach(arm, [0, 0]), _reach(arm, [0, 180])  # stretched, folded
    return math.pi * (outer**2 - inner**2)


@register("kawasaki_workspace", 12)
def closest_reach_with_an_elbow_limit(l1, l2, limit):
    """How close to the base (m) the tip comes with 0 <= q2 <= ``limit`` (deg)."""
    arm = planar([l1, l2])
    # every q2 in its range, to the limit itself (q1 does not change the distance)
    return min(_reach(arm, [0, q2]) for q2 in np.linspace(0, limit, 121))


@register("kawasaki_workspace", 13)
def area_of_the_dexterous_workspace(l1, l2, l3):
    """The area (m²) of the dexterous workspace of a planar three-link arm."""
    arm = planar([l1, l2, l3])
    # the tip with link 3 turned back: from the stretched arm, and from the folded one
    outer, inner = _reach(arm, [0, 0, 180]), _reach(arm, [0, 180, 180])
    return math.pi * (outer**2 - inner**2)


@register("kawasaki_workspace", 15)
def elbow_angle_for_a_target(l1, l2, x, y):
    """The positive elbow angle q2 (rad) that puts the tip at (x, y) m."""
    arm = planar([l1, l2])
    # turn the tip about joint 2 (at home) until it is |target| from the base
    angles = subproblem3(
        arm.screw_axes()[1], arm.fk([0.0, 0.0])[:3, 3], [0, 0, 0], math.hypot(x, y)
    )
    return next(a for a in angles if 0 < a < math.pi)
