"""The parametrised exercises of the chapter statics."""

import numpy as np

from ..robots import planar
from ..statics import compliance_at_tool, gravity_torques, joint_torques
from . import pick, register, units


@register("statics", 1)
def shoulder_torque_of_a_push_on_a_wall(rng):
    l1 = pick(rng, [0.3, 0.4, 0.5], 0.4)
    l2 = pick(rng, [0.2, 0.3, 0.4], 0.3)
    q1 = pick(rng, [15, 30, 45, 60], 30)
    q2 = pick(rng, [30, 60, 90], 60)
    push = pick(rng, [5, 10, 20, 25], 10)
    q = np.radians([q1, q2])
    tau = joint_torques(planar([l1, l2]), q, force=[push, 0.0, 0.0])
    numbers = units("m", l1=l1, l2=l2) | units("deg", q1=q1, q2=q2) | units("N", f=push)
    statement = (
        f"A planar two-link arm, l1 = {l1} m and l2 = {l2} m, at q = ({q1} deg, "
        f"{q2} deg) pushes with its tip on a wall with the force f = ({push}, 0) N. "
        f"Find the torque tau1 (N m, with its sign) of joint 1 from "
        f"tau = J_s^T Pi F."
    )
    return numbers, statement, float(tau[0])


@register("statics", 4)
def shoulder_torque_holding_a_load(rng):
    l1 = pick(rng, [0.3, 0.4, 0.5, 0.6], 0.5)
    l2 = pick(rng, [0.2, 0.3, 0.4, 0.5], 0.4)
    mass = pick(rng, [1, 2, 3, 4, 5], 3)
    gravity = [0.0, -9.81, 0.0]  # the arm's plane is x-y: gravity along -y
    tau = gravity_torques(planar([l1, l2]), [0.0, 0.0], [(2, mass, [0, 0, 0])], gravity)
    numbers = units("m", l1=l1, l2=l2) | units("kg", M=mass)
    statement = (
        f"A planar two-link arm in a vertical plane, l1 = {l1} m and l2 = {l2} m, "
        f"stretched horizontally (q = (0, 0)), holds a {mass} kg load at its tip "
        f"(g = 9.81 m/s^2 down). Which torque tau1 (N m) holds it?"
    )
    return numbers, statement, float(tau[0])


@register("statics", 18)
def rotational_stiffness_of_two_joint_springs(rng):
    k1 = pick(rng, [100, 200, 300, 400, 500], 300)
    k2 = pick(rng, [150, 250, 600, 800], 600)
    # any two-link arm away from its singularity: a couple turns the tool alike
    C = compliance_at_tool(planar([0.5, 0.3]), [0.4, 1.1], [k1, k2])
    numbers = units("N m/rad", k1=k1, k2=k2)
    statement = (
        f"A planar two-link arm has joint springs k1 = {k1} and k2 = {k2} N m/rad. "
        f"A pure couple acts on its tool and the tip may move freely. What is the "
        f"tool's rotational stiffness (N m/rad)?"
    )
    # C maps the wrench (f; m) to (d theta; dx): a couple m_z turns the tool by C[2, 5]
    return numbers, statement, float(1 / C[2, 5])
