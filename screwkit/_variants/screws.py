"""The parametrised exercises of the chapter screws."""

from ..screws import Screw, Twist, Wrench
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
