"""The parametrised exercises of the chapter puma_fk."""

import math

from ..chains import Chain
from ..lines import Line, common_normal
from . import pick, register
from .poe import pi_text, pi_value


@register("puma_fk", 15)
def spherical_arm_position(rng):
    q1 = pick(rng, [(1, 2), (-1, 2), (1, 4), (1, 3), (1, 1), (0, 1)], (1, 2))
    q2 = pick(rng, [(1, 2), (1, 4), (1, 3), (-1, 4), (2, 3)], (1, 2))
    boom = pick(rng, [0.3, 0.4, 0.5, 0.6, 0.8], 0.5)
    stanford = Chain.from_table(
        [[0, 0.4, 0, -math.pi / 2], [0, 0.15, 0, math.pi / 2], [0, 0, 0, 0]],
        joints="RRP",
    )
    q = [pi_value(q1), pi_value(q2), boom]
    tool = stanford.fk(q)[:3, 3]
    numbers = {"q1": (q[0], "rad"), "q2": (q[1], "rad"), "q3": (boom, "m")}
    statement = (
        "A spherical (Stanford-type) arm: a waist about z_0; a shoulder 0.4 m up, its "
        "axis along y_0; a boom that slides along a line 0.15 m to the side (along "
        "+y_0) of the waist axis, and points straight up at home, q_3 being its "
        "length from the shoulder's axis. The DH table (link: theta, d, a, alpha) is "
        "1: q_1, 0.4, 0, -90 deg; 2: q_2, 0.15, 0, 90 deg; 3: 0, q_3, 0, 0. Where is "
        f"the tool at q = ({pi_text(q1)}, {pi_text(q2)}, {boom:g}) (metres)?"
    )
    return numbers, statement, [float(v) for v in tool]


@register("puma_fk", 18)
def common_normal_of_two_axes(rng):
    x = pick(rng, [0.3, 0.1, -0.2, 0.5], 0.3)
    y = pick(rng, [0.2, 0.1, 0.25, 0.3, 0.4], 0.2)
    z = pick(rng, [0.5, 0.3, 0.4, 0.6, 0.8], 0.5)
    normal = common_normal(
        Line.through([0, 0, 0], [0, 0, 1]), Line.through([x, y, z], [x + 1, y, z])
    )
    numbers = {"x": (x, "m"), "y": (y, "m"), "z": (z, "m")}
    statement = (
        "Joint 1's axis is z_0 (through the origin, along z); joint 2's passes "
        f"through ({x:g}, {y:g}, {z:g}) m along x. Find their common normal, and from "
        "it a_1 and d_1 (metres, in that order); what are alpha_1 and theta_1 at home "
        "if x_0 is the x axis?"
    )
    # a_1 is the normal's length, d_1 the height of its foot on z_0
    return numbers, statement, [float(normal.distance), float(normal.foot_a[2])]


@register("puma_fk", 22)
def cylindrical_arm_position(rng):
    q1 = pick(rng, [(1, 2), (-1, 2), (1, 1), (1, 4), (1, 3), (0, 1)], (1, 2))
    lift = pick(rng, [0.2, 0.1, 0.4, 0.5], 0.2)
    reach = pick(rng, [0.3, 0.2, 0.4, 0.6], 0.3)
    cylindrical = Chain.from_table(
        [[0, 0.3, 0, 0], [0, 0, 0, -math.pi / 2], [0, 0, 0, 0]], joints="RPP"
    )
    q = [pi_value(q1), lift, reach]
    tool = cylindrical.fk(q)[:3, 3]
    numbers = {"q1": (q[0], "rad"), "q2": (lift, "m"), "q3": (reach, "m")}
    statement = (
        f"The cylindrical arm of exercise 14 is at q = ({pi_text(q1)}, {lift:g}, "
        f"{reach:g}). Where is the tool (metres)?"
    )
    return numbers, statement, [float(v) for v in tool]
