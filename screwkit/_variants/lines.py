"""The parametrised exercises of the chapter lines: the keys' computations.

The statements and their draws are in screwkit/answers/lines.toml.
"""

import math

import numpy as np

from ..lines import Line, central_axis, dependency
from ..parallel import stewart_gough
from ..screws import Screw, Wrench
from ..transforms import homogeneous, rotz
from . import register

_AXES = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}


def _shown(values):
    return ", ".join(f"{v + 0:g}" for v in values)  # + 0: no "-0"


@register("lines", 2)
def point_of_a_line_nearest_the_origin(w, p):
    """The point (m) nearest the origin of the line along w through p, and the
    line's Plücker coordinates (w; m) the statement gives."""
    m = np.cross(p, w)  # a point p of the line: m = p x w, so w . m = 0
    shown = {f"w{i}": v for i, v in enumerate(w, 1)}
    shown |= {f"m{i}": int(v) for i, v in enumerate(m, 1)}
    shown |= {"w_shown": _shown(w), "m_shown": _shown(m)}
    return Line([*w, *m]).point, shown


@register("lines", 8)
def resultant_of_two_parallel_forces(F1, F2, d):
    """The point (m) of the x axis the resultant of F1 (N) along z through the origin
    and F2 (N) along z through (d, 0, 0) m passes through."""
    up = Screw.from_axis(_AXES["z"], [0, 0, 0], 0).vector
    up_there = Screw.from_axis(_AXES["z"], [d, 0, 0], 0).vector
    total = Wrench.from_vector(F1 * up + F2 * up_there)
    return central_axis(total).line.point


@register("lines", 9)
def pitch_of_a_member_of_the_cylindroid(h1, h2, theta):
    """The pitch (m/rad) of the cylindroid's member at ``theta`` (deg) from the first
    principal screw, of pitches h1 and h2 (m/rad)."""
    # the principal screws: along x and y through their common point, the origin
    first = Screw.from_axis(_AXES["x"], [0, 0, 0], h1).vector
    second = Screw.from_axis(_AXES["y"], [0, 0, 0], h2).vector
    angle = math.radians(theta)
    return Screw.from_vector(math.cos(angle) * first + math.sin(angle) * second).pitch


@register("lines", 21)
def pitch_of_the_complex_at_fichters_turn(z):
    """The pitch (m) of the linear complex of the chapter's Stewart platform's legs,
    turned by 90 deg about the vertical at height z (m)."""
    turned = homogeneous(rotz(math.pi / 2), [0.0, 0.0, z])
    return dependency(stewart_gough().wrenches(turned)[0]).data["pitch"]
