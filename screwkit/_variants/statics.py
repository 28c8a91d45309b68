"""The parametrised exercises of the chapter statics: the keys' computations.

The statements and their draws are in screwkit/answers/statics.toml.
"""

import numpy as np

from ..robots import planar
from ..statics import compliance_at_tool, gravity_torques, joint_torques
from . import register


@register("statics", 1)
def shoulder_torque_of_a_push_on_a_wall(l1, l2, q1, q2, f):
    """The torque tau1 (N m) of joint 1 of a two-link arm at (q1, q2) (deg) whose
    tip pushes with the force (f, 0) N."""
    q = np.radians([q1, q2])
    return joint_torques(planar([l1, l2]), q, force=[f, 0.0, 0.0])[0]


@register("statics", 4)
def shoulder_torque_holding_a_load(l1, l2, M):
    """The torque tau1 (N m) that holds a load M (kg) at the tip of a two-link arm
    stretched horizontally in a vertical plane."""
    gravity = [0.0, -9.81, 0.0]  # the arm's plane is x-y: gravity along -y
    load = [(2, M, [0, 0, 0])]
    return gravity_torques(planar([l1, l2]), [0.0, 0.0], load, gravity)[0]


@register("statics", 18)
def rotational_stiffness_of_two_joint_springs(k1, k2):
    """The tool's rotational stiffness (N m/rad) of a two-link arm with joint springs
    k1 and k2 (N m/rad)."""
    # any two-link arm away from its singularity: a couple turns the tool alike
    C = compliance_at_tool(planar([0.5, 0.3]), [0.4, 1.1], [k1, k2])
    # C maps the wrench (f; m) to (d theta; dx): a couple m_z turns the tool by C[2, 5]
    return 1 / C[2, 5]
