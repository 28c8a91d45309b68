"""The parametrised exercises of the chapter screws."""

import math

from ..lie import log_transform
from ..screws import Screw, Twist, Wrench
from ..transforms import homogeneous, rotz, transl
from . import pick, register


@register("screws", 6)
def power_of_a_force_on_a_spinning_body(rng):
    force = pick(rng, [5, 10, 20, 40], 10)
    arm = pick(rng, [0.25, 0.5, 0.75, 1.5], 0.5)
    spin = pick(rng, [1, 2, 3, 4], 2)
    line = Screw.from_axis([0, 1, 0], [arm, 0, 0], 0).vector
    power = Twist.from_vector([0, 0, spin, 0, 0, 0]) @ Wrench.from_vector(force * line)
    numbers = {"F": (force, "N"), "x": (arm, "m"), "omega": (spin, "rad/s")}
    statement = (
        f"A force of {force} N along y acts through the point ({arm}, 0, 0) m on a "
        f"body that spins at {spin} rad/s about the z axis through the origin. What "
        f"power (W) does the force deliver?"
    )
    return numbers, statement, float(power)


@register("screws", 5)
def point_of_a_screw_axis_nearest_the_origin(rng):
    directions = [(0, 0, 1), (1, 0, 0), (0, 1, 0), (0, 0, 2), (1, 1, 0), (0, 3, 4)]
    s = pick(rng, directions, (0, 0, 1))
    s0 = [pick(rng, [-2, -1, 0, 0.5, 1, 2, 3], v) for v in (1, 2, 0.5)]
    vector = [*s, *s0]
    numbers = {f"S{i + 1}": (v, "") for i, v in enumerate(vector)}
    shown = ", ".join(f"{v:g}" for v in s) + "; " + ", ".join(f"{v:g}" for v in s0)
    statement = (
        f"Where does the axis of the screw S = ({shown}) pass closest to the origin? "
        f"Give the point (x, y, z) in metres."
    )
    return numbers, statement, [float(v) for v in Screw.from_vector(vector).point]


@register("screws", 12)
def wrench_of_a_weight_on_a_plate(rng):
    weight = pick(rng, [5, 10, 20, 30, 50], 20)
    x = pick(rng, [0.1, 0.2, 0.4, 0.5], 0.4)
    y = pick(rng, [0.1, 0.2, 0.3, 0.5], 0.3)
    # a pure force (pitch 0) along the downward line through (x, y, 0)
    line = Screw.from_axis([0, 0, -1], [x, y, 0], 0).vector
    wrench = Wrench.from_vector(weight * line)
    numbers = {"F": (weight, "N"), "x": (x, "m"), "y": (y, "m")}
    statement = (
        f"A weight presses down on a horizontal plate (z points up) with a "
        f"force of {weight} N at the point ({x}, {y}, 0) m. Write the wrench (f; m) "
        f"it applies about the origin: N, then N m."
    )
    return numbers, statement, [float(v) for v in wrench.vector]


@register("screws", 13)
def pitch_of_a_thread(rng):
    lead = pick(rng, [0.5, 0.8, 1, 1.25, 1.5, 2, 3, 4], 2)
    hand = pick(rng, ["right", "left"], "right")
    # a quarter turn about the rod (+z) moves the nut a quarter of the lead: up for a
    # right-hand thread, down for a left-hand one; the screw of that motion
    advance = (lead / 1000) / 4 * (1 if hand == "right" else -1)
    motion = transl(0.0, 0.0, advance) @ homogeneous(rotz(math.pi / 2))
    pitch = Twist.from_vector(log_transform(motion)).pitch
    numbers = {"lead": (lead, "mm"), "right_hand": (int(hand == "right"), "")}
    statement = (
        f"A nut runs on a threaded rod with a {hand}-hand thread of lead {lead:g} mm: "
        f"one turn moves it {lead:g} mm along the rod. What is the pitch of its "
        f"helical joint, in m/rad?"
    )
    return numbers, statement, float(pitch)
