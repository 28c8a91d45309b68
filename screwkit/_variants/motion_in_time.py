"""The parametrised exercises of the chapter motion_in_time."""

from ..motion import trajectory
from . import pick, register


@register("motion_in_time", 3)
def peak_speed_of_a_quintic(rng):
    duration = pick(rng, [1.0, 1.5, 2.5, 3.0, 4.0, 5.0], 2.0)
    numbers = {"T": (duration, "s")}
    statement = (
        f"The quintic time scaling of duration T = {duration:g} s: what is its "
        f"largest ds/dt (1/s)?"
    )
    return numbers, statement, float(trajectory.quintic(duration).peak_velocity)
