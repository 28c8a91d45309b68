"""The parametrised exercises of the chapter rigid_motions."""

import math

from ..transforms import screw_motion
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
