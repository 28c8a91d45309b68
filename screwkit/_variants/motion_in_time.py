"""The parametrised exercises of the chapter motion_in_time: the keys' computations.

The statements and their draws are in screwkit/answers/motion_in_time.toml.
"""

from ..motion import trajectory
from . import register


@register("motion_in_time", 3)
def peak_speed_of_a_quintic(T):
    """The largest ds/dt (1/s) of the quintic time scaling of duration T (s)."""
    return trajectory.quintic(T).peak_velocity


@register("motion_in_time", 4)
def shortest_trapezoid(v, a):
    """The shortest duration (s) of a trapezoidal scaling with ds/dt <= v (1/s) and
    a bounded acceleration a (1/s²)."""
    return trajectory.trapezoidal(v_max=v, a_max=a).duration


@register("motion_in_time", 15)
def bang_bang_duration(Delta, a):
    """The time-optimal duration (s) of a joint's move by Delta (rad) with its
    acceleration bounded by a (rad/s²) and no rate limit."""
    # no rate limit: one far above any rate this motion reaches (the profile is a
    # triangle, whose duration the rate limit does not enter)
    scaling = trajectory.fastest_joint_scaling(
        trajectory.trapezoidal, [0.0], [Delta], 1e6, a
    )
    return scaling.duration
