"""The parametrised exercises of the chapter screws: the keys' computations.

The statements and their draws are in screwkit/answers/screws.toml.
"""

import math

from ..lie import log_transform
from ..screws import Screw, Twist, Wrench
from ..transforms import homogeneous, rotz, transl
from . import register


@register("screws", 5)
def point_of_a_screw_axis_nearest_the_origin(s, s0x, s0y, s0z):
    """The point (m) of the axis of the screw S = (s; s0) nearest the origin, and
    S's six numbers."""
    vector = [*s, s0x, s0y, s0z]
    shown = ", ".join(f"{v:g}" for v in s) + "; " + f"{s0x:g}, {s0y:g}, {s0z:g}"
    numbers = {f"S{i + 1}": v for i, v in enumerate(vector)}
    return Screw.from_vector(vector).point, numbers | {"shown": shown}


@register("screws", 6)
def power_of_a_force_on_a_spinning_body(F, x, omega):
    """The power (W) of a force F (N) along y through (x, 0, 0) m on a body that
    spins at omega (rad/s) about z."""
    line = Screw.from_axis([0, 1, 0], [x, 0, 0], 0).vector
    return Twist.from_vector([0, 0, omega, 0, 0, 0]) @ Wrench.from_vector(F * line)


@register("screws", 12)
def wrench_of_a_weight_on_a_plate(F, x, y):
    """The wrench (f; m) (N, N m) about the origin of a weight F (N) pressing down at
    (x, y, 0) m."""
    # a pure force (pitch 0) along the downward line through (x, y, 0)
    line = Screw.from_axis([0, 0, -1], [x, y, 0], 0).vector
    return Wrench.from_vector(F * line).vector


@register("screws", 13)
def pitch_of_a_thread(lead, hand):
    """The pitch (m/rad) of a nut's helical joint on a thread of ``lead`` (mm) and
    ``hand`` ("right" or "left")."""
    # a quarter turn about the rod (+z) moves the nut a quarter of the lead: up for a
    # right-hand thread, down for a left-hand one; the screw of that motion
    advance = (lead / 1000) / 4 * (1 if hand == "right" else -1)
    motion = transl(0.0, 0.0, advance) @ homogeneous(rotz(math.pi / 2))
    pitch = Twist.from_vector(log_transform(motion)).pitch
    return pitch, {"right_hand": int(hand == "right")}
