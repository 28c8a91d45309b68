"""The parametrised exercises of the chapter rigid_motions: the keys' computations.

The statements and their draws are in screwkit/answers/rigid_motions.toml.
"""

import math

from ..lie import adjoint
from ..orientation import quaternion_from_rotation
from ..transforms import homogeneous, inv, rot_axis, rotz, screw_motion, transl
from . import register


@register("rigid_motions", 2)
def turn_about_a_vertical_line(a, b, angle):
    """Where a turn by ``angle`` (deg) about the vertical through (a, b, 0) m carries
    the origin (m)."""
    return screw_motion([0, 0, 1], [a, b, 0], 0, math.radians(angle))[:3, 3]


@register("rigid_motions", 7)
def quaternion_of_a_turn(angle, about):
    """The unit quaternion (w, x, y, z) of a turn by ``angle`` (deg) about the axis
    ``about`` ("x", "y" or "z"), and that axis's index."""
    direction = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}[about]
    q = quaternion_from_rotation(rot_axis(direction, math.radians(angle)))
    return q, {"axis": "xyz".index(about)}


@register("rigid_motions", 11)
def point_of_a_body_frame_in_the_fixed_frame(x_b, y_b, z_b):
    """The point (x_b, y_b, z_b) of {b} in {s} (m), {b} at (1, 2, 0) m turned a
    quarter turn about the vertical."""
    T_sb = transl(1.0, 2.0, 0.0) @ homogeneous(rotz(math.pi / 2))
    return (T_sb @ [x_b, y_b, z_b, 1.0])[:3]


@register("rigid_motions", 16)
def body_twist_of_a_cart_on_a_circle(speed, radius):
    """The body twist (rad/s, m/s) of a cart at ``speed`` on a circle of ``radius``
    about the origin, as it passes (radius, 0, 0)."""
    # the cart turns about the vertical through the centre: a spatial twist with no v
    V_s = [0.0, 0.0, speed / radius, 0.0, 0.0, 0.0]
    # at (radius, 0, 0), x_b forward (along y of {s}) and y_b towards the centre
    T_sb = transl(radius, 0.0, 0.0) @ homogeneous(rotz(math.pi / 2))
    return adjoint(inv(T_sb)) @ V_s
