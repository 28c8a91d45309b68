"""The parametrised exercises of the chapter jacobians."""

import numpy as np

from ..robots import planar
from ..statics import joint_torques
from . import pick, register, units


@register("jacobians", 10)
def tip_velocity_of_a_two_link_arm(rng):
    l1 = pick(rng, [0.4, 0.5, 0.6], 0.5)
    l2 = pick(rng, [0.2, 0.3, 0.4], 0.3)
    q1 = pick(rng, [0, 30, 45, 60], 30)
    q2 = pick(rng, [30, 45, 60, 90, 120], 60)
    rate1, rate2 = pick(rng, [(1, 1), (1, -1), (2, 1), (1, 2), (-1, 2)], (1, 1))
    J = planar([l1, l2]).jacobian_rows(np.radians([q1, q2]), "position")[:2]
    velocity = J @ np.array([rate1, rate2], dtype=float)
    numbers = (
        units("m", l1=l1, l2=l2)
        | units("deg", q1=q1, q2=q2)
        | units("rad/s", qdot1=rate1, qdot2=rate2)
    )
    statement = (
        f"A two-link arm, l1 = {l1} m and l2 = {l2} m, is at q = ({q1} deg, {q2} "
        f"deg). Write its 2 x 2 Jacobian from the joint positions (column i is "
        f"z x (p - o_(i-1)) = (-(y - y_(i-1)), x - x_(i-1))) and the tip velocity "
        f"(xdot, ydot) for qdot = ({rate1}, {rate2}) rad/s, in m/s."
    )
    return numbers, statement, [float(v) for v in velocity]


@register("jacobians", 14)
def torques_of_a_push_on_a_table(rng):
    l1 = pick(rng, [0.3, 0.4, 0.5], 0.4)
    l2 = pick(rng, [0.2, 0.3, 0.4, 0.5], 0.3)
    q1 = pick(rng, [60, 90, 120], 90)
    push = pick(rng, [10, 20, 30, 40], 20)
    q = np.radians([q1, -q1])
    tau = joint_torques(planar([l1, l2]), q, force=[0.0, -push, 0.0])
    numbers = units("m", l1=l1, l2=l2) | units("deg", q1=q1) | units("N", F=push)
    statement = (
        f"A two-link arm, l1 = {l1} m and l2 = {l2} m at q = ({q1} deg, -{q1} deg) "
        f"(its second link horizontal), presses its tip down on a table: the force "
        f"the tool applies is F = (0, -{push}) N. Find the joint torques "
        f"tau = J^T F (N m), and check each as the moment of F about its joint."
    )
    return numbers, statement, [float(t) for t in tau]


@register("jacobians", 22)
def elbow_rate_near_the_stretched_arm(rng):
    l1 = pick(rng, [0.4, 0.5, 0.6], 0.5)
    l2 = pick(rng, [0.2, 0.3, 0.4], 0.3)
    q2 = pick(rng, [10, 15, 20, 30], 10)
    speed = pick(rng, [0.05, 0.1, 0.15, 0.2], 0.1)
    arm, q = planar([l1, l2]), np.radians([0, q2])
    tip = arm.fk(q)[:2, 3]
    J = arm.jacobian_rows(q, "position")[:2]
    rates = np.linalg.solve(J, -speed * tip / np.linalg.norm(tip))
    numbers = units("m", l1=l1, l2=l2) | units("deg", q2=q2) | units("m/s", speed=speed)
    statement = (
        f"A two-link arm, l1 = {l1} m and l2 = {l2} m, is at q = (0, {q2} deg) and "
        f"its tip must move straight toward the base at {speed} m/s. The distance "
        f"r of the tip from the base, with r^2 = l1^2 + l2^2 + 2 l1 l2 cos q2, "
        f"depends on q2 alone: how fast must joint 2 turn (rad/s, with its sign)?"
    )
    return numbers, statement, float(rates[1])
