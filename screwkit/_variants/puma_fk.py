"""The parametrised exercises of the chapter puma_fk: the keys' computations.

The statements and their draws are in screwkit/answers/puma_fk.toml.
"""

import math

from ..chains import Chain
from ..lines import Line, common_normal
from . import register
from .poe import turns


@register("puma_fk", 15)
def spherical_arm_position(q1_over_pi, q2_over_pi, q3):
    """The tool (m) of the spherical (Stanford-type) arm at q = (pi ``q1_over_pi``,
    pi ``q2_over_pi``, q3 (m))."""
    shown = turns(q1=q1_over_pi, q2=q2_over_pi)
    stanford = Chain.from_table(
        [[0, 0.4, 0, -math.pi / 2], [0, 0.15, 0, math.pi / 2], [0, 0, 0, 0]],
        joints="RRP",
    )
    return stanford.fk([shown["q1"], shown["q2"], q3])[:3, 3], shown


@register("puma_fk", 18)
def common_normal_of_two_axes(x, y, z):
    """a_1 and d_1 (m) of z_0 and the line along x through (x, y, z) m."""
    normal = common_normal(
        Line.through([0, 0, 0], [0, 0, 1]), Line.through([x, y, z], [x + 1, y, z])
    )
    # a_1 is the normal's length, d_1 the height of its foot on z_0
    return [float(normal.distance), float(normal.foot_a[2])]


@register("puma_fk", 22)
def cylindrical_arm_position(q1_over_pi, q2, q3):
    """The tool (m) of the cylindrical arm of exercise 14 at q = (pi ``q1_over_pi``,
    q2 (m), q3 (m))."""
    shown = turns(q1=q1_over_pi)
    cylindrical = Chain.from_table(
        [[0, 0.3, 0, 0], [0, 0, 0, -math.pi / 2], [0, 0, 0, 0]], joints="RPP"
    )
    return cylindrical.fk([shown["q1"], q2, q3])[:3, 3], shown
