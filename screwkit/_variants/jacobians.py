"""The parametrised exercises of the chapter jacobians: the keys' computations.

The statements and their draws are in screwkit/answers/jacobians.toml.
"""

import numpy as np

from ..robots import planar
from ..statics import joint_torques
from . import register


@register("jacobians", 10)
def tip_velocity_of_a_two_link_arm(l1, l2, q1, q2, qdot):
    """The tip velocity (m/s) of a two-link arm at (q1, q2) (deg) for the joint
    rates ``qdot`` (rad/s)."""
    J = planar([l1, l2]).jacobian_rows(np.radians([q1, q2]), "position")[:2]
    return J @ np.array(qdot, dtype=float), {"qdot1": qdot[0], "qdot2": qdot[1]}


@register("jacobians", 14)
def torques_of_a_push_on_a_table(l1, l2, q1, F):
    """The joint torques (N m) of a two-link arm at (q1, -q1) (deg) whose tip
    presses down with F (N)."""
    q = np.radians([q1, -q1])
    return joint_torques(planar([l1, l2]), q, force=[0.0, -F, 0.0])


@register("jacobians", 22)
def elbow_rate_near_the_stretched_arm(l1, l2, q2, speed):
    """The rate of joint 2 (rad/s) that moves the tip of a two-link arm at (0, q2)
    (deg) straight toward the base at ``speed`` (m/s)."""
    arm, q = planar([l1, l2]), np.radians([0, q2])
    tip = arm.fk(q)[:2, 3]
    J = arm.jacobian_rows(q, "position")[:2]
    return np.linalg.solve(J, -speed * tip / np.linalg.norm(tip))[1]
