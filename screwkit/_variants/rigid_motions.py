"""The parametrised exercises of the chapter rigid_motions."""

import math

from ..lie import adjoint
from ..orientation import quaternion_from_rotation
from ..transforms import homogeneous, inv, rot_axis, rotz, screw_motion, transl
from . import pick, register


@register("rigid_motions", 2)
def turn_about_a_vertical_line(rng):
    a = pick(rng, [-2, -1, 1, 2, 3], 1)
    b = pick(rng, [-2, -1, 0, 1, 2], 0)
    angle = pick(rng, [90, 180, 270], 180)
    origin = screw_motion([0, 0, 1], [a, b, 0], 0, math.radians(angle))[:3, 3]
    numbers = {"a": (a, "m"), "b": (b, "m"), "angle": (angle, "deg")}
    statement = (
        f"A revolute joint turns about the vertical line through ({a}, {b}, 0) m. "
        f"Where does the origin go when the joint turns by {angle} deg?"
    )
    return numbers, statement, [float(v) for v in origin]


@register("rigid_motions", 7)
def quaternion_of_a_turn(rng):
    angle = pick(rng, [30, 45, 60, 90, 120, 135, 150], 90)
    axis = pick(rng, ["x", "y", "z"], "z")
    direction = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}[axis]
    # w >= 0: the angles drawn are below 180 deg, where -q is the other answer
    q = quaternion_from_rotation(rot_axis(direction, math.radians(angle)))
    numbers = {"angle": (angle, "deg"), "axis": ("xyz".index(axis), "")}
    statement = (
        f"Write the unit quaternion (w, x, y, z) of a turn by {angle} deg about the "
        f"{axis} axis."
    )
    return numbers, statement, [float(v) for v in q]


@register("rigid_motions", 11)
def point_of_a_body_frame_in_the_fixed_frame(rng):
    x = pick(rng, [-0.5, 0.2, 0.4, 0.5, 0.8, 1.0], 0.5)
    y = pick(rng, [-0.4, 0.0, 0.3, 0.6], 0.0)
    z = pick(rng, [0.0, 0.2, 0.3, 0.5], 0.3)
    # {b} at (1, 2, 0) m, turned a quarter turn about the vertical
    T_sb = transl(1.0, 2.0, 0.0) @ homogeneous(rotz(math.pi / 2))
    p_s = (T_sb @ [x, y, z, 1.0])[:3]
    numbers = {"x_b": (x, "m"), "y_b": (y, "m"), "z_b": (z, "m")}
    statement = (
        f"A body frame {{b}} has its origin at (1, 2, 0) m in the fixed frame {{s}}; "
        f"its x axis points along the y of {{s}}, its y axis along minus x of {{s}} "
        f"and its z axis along the z of {{s}}. Find the coordinates in {{s}} (m) of "
        f"the point whose coordinates in {{b}} are ({x:g}, {y:g}, {z:g}) m."
    )
    return numbers, statement, [float(v) for v in p_s]


@register("rigid_motions", 16)
def body_twist_of_a_cart_on_a_circle(rng):
    speed = pick(rng, [0.5, 1, 1.5, 2, 3], 1)
    radius = pick(rng, [0.5, 1, 2, 2.5, 4], 2)
    # the cart turns about the vertical through the centre: a spatial twist with no v
    turn_rate = speed / radius
    V_s = [0.0, 0.0, turn_rate, 0.0, 0.0, 0.0]
    # at (radius, 0, 0), x_b forward (along y of {s}) and y_b towards the centre
    T_sb = transl(radius, 0.0, 0.0) @ homogeneous(rotz(math.pi / 2))
    V_b = adjoint(inv(T_sb)) @ V_s
    numbers = {"speed": (speed, "m/s"), "radius": (radius, "m")}
    statement = (
        f"A cart drives counter-clockwise at {speed:g} m/s around a circle of radius "
        f"{radius:g} m centred on the origin of {{s}}. Its body frame {{b}} has x_b "
        f"forward, y_b towards the centre and z_b up. Write its body twist "
        f"V_b = (omega_b; v_b) (rad/s, then m/s) at the moment it passes "
        f"({radius:g}, 0, 0) m."
    )
    return numbers, statement, [float(v) for v in V_b]
