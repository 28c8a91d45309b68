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


@register("motion_in_time", 4)
def shortest_trapezoid(rng):
    # every v^2 < a: the cruise velocity is reached, the profile is a trapezoid
    v_max = pick(rng, [0.25, 0.4, 0.5, 0.6, 0.8], 0.5)
    a_max = pick(rng, [1.0, 1.5, 2.0, 3.0, 4.0], 2.0)
    numbers = {"v": (v_max, "1/s"), "a": (a_max, "1/s²")}
    statement = (
        f"A trapezoidal scaling with ds/dt <= {v_max:g} 1/s and |d²s/dt²| <= "
        f"{a_max:g} 1/s²: what is its shortest duration (s)?"
    )
    duration = trajectory.trapezoidal(v_max=v_max, a_max=a_max).duration
    return numbers, statement, float(duration)


@register("motion_in_time", 15)
def bang_bang_duration(rng):
    distance = pick(rng, [0.5, 0.75, 1.0, 1.5, 2.0, 2.5], 1.0)
    a_max = pick(rng, [1.0, 2.0, 3.0, 5.0], 2.0)
    numbers = {"Delta": (distance, "rad"), "a": (a_max, "rad/s²")}
    statement = (
        f"One joint moves Delta = {distance:g} rad along the path q(s) = s Delta, "
        f"with |d²q/dt²| <= {a_max:g} rad/s² and no rate limit; along the path "
        f"d²q/ds² = 0. What are L and U, where do the two curves of the phase "
        f"plane cross, and what is the time-optimal duration (s)?"
    )
    # no rate limit: one far above any rate this motion reaches (the profile is a
    # triangle, whose duration the rate limit does not enter)
    scaling = trajectory.fastest_joint_scaling(
        trajectory.trapezoidal, [0.0], [distance], 1e6, a_max
    )
    return numbers, statement, float(scaling.duration)
