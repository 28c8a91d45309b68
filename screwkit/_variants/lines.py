"""The parametrised exercises of the chapter lines."""

import math

import numpy as np

from ..lines import Line, central_axis, dependency
from ..parallel import stewart_gough
from ..screws import Screw, Wrench
from ..transforms import homogeneous, rotz
from . import pick, register

_AXES = {"x": [1, 0, 0], "y": [0, 1, 0], "z": [0, 0, 1]}


def _shown(values):
    return ", ".join(f"{v + 0:g}" for v in values)  # + 0: no "-0"


@register("lines", 2)
def point_of_a_line_nearest_the_origin(rng):
    w = pick(rng, [(0, 0, 1), (1, 0, 0), (0, 1, 0), (1, 1, 0), (0, 1, 1)], (0, 0, 1))
    p = pick(rng, [(0, 2, 0), (1, 0, 0), (2, 1, 0), (1, 2, 3), (0, 1, -1)], (0, 2, 0))
    m = np.cross(p, w)  # a point p of the line: m = p x w, so w . m = 0
    line = Line([*w, *m])
    numbers = {f"w{i}": (v, "") for i, v in enumerate(w, 1)}
    numbers |= {f"m{i}": (int(v), "m") for i, v in enumerate(m, 1)}
    statement = (
        f"The line (w; m) = ({_shown(w)}; {_shown(m)}): check that it is a line, and "
        f"give its point nearest the origin (m)."
    )
    return numbers, statement, [float(v) for v in line.point]


@register("lines", 8)
def resultant_of_two_parallel_forces(rng):
    first = pick(rng, [1, 2, 3, 4, 5], 2)
    second = pick(rng, [2, 4, 5, 6, 8], 6)
    distance = pick(rng, [1, 2, 3, 4, 5], 4)
    up = Screw.from_axis(_AXES["z"], [0, 0, 0], 0).vector
    up_there = Screw.from_axis(_AXES["z"], [distance, 0, 0], 0).vector
    total = Wrench.from_vector(first * up + second * up_there)
    numbers = {"F1": (first, "N"), "F2": (second, "N"), "d": (distance, "m")}
    statement = (
        f"Two parallel forces along z, {first} N through the origin and {second} N "
        f"through ({distance}, 0, 0) m. Through which point of the x axis does their "
        f"resultant pass? Give (x, y, z) in m."
    )
    return numbers, statement, [float(v) for v in central_axis(total).line.point]


@register("lines", 9)
def pitch_of_a_member_of_the_cylindroid(rng):
    h1 = pick(rng, [-0.2, 0.0, 0.1, 0.2], 0.1)
    h2 = pick(rng, [0.3, 0.4, 0.5, 0.8], 0.4)
    angle = pick(rng, [30, 45, 60, 120, 135], 60)
    # the principal screws: along x and y through their common point, the origin
    first = Screw.from_axis(_AXES["x"], [0, 0, 0], h1).vector
    second = Screw.from_axis(_AXES["y"], [0, 0, 0], h2).vector
    theta = math.radians(angle)
    member = Screw.from_vector(math.cos(theta) * first + math.sin(theta) * second)
    numbers = {"h1": (h1, "m/rad"), "h2": (h2, "m/rad"), "theta": (angle, "deg")}
    statement = (
        f"A cylindroid has principal pitches h1 = {h1:g} and h2 = {h2:g} m/rad. What "
        f"is the pitch of the member at theta = {angle} deg from the first principal "
        f"screw (m/rad)?"
    )
    return numbers, statement, float(member.pitch)


@register("lines", 21)
def pitch_of_the_complex_at_fichters_turn(rng):
    height = pick(rng, [0.5, 0.6, 0.7, 0.8, 0.9, 1.0, 1.2], 0.8)
    turned = homogeneous(rotz(math.pi / 2), [0.0, 0.0, height])
    found = dependency(stewart_gough().wrenches(turned)[0])
    numbers = {"z": (height, "m")}
    statement = (
        f"The Stewart platform of the chapter (sk.parallel.stewart_gough()), turned "
        f"by 90 deg about the vertical at height {height:g} m: its leg lines form a "
        f"general linear complex. What is the pitch of the complex's screw (m)? Use "
        f"sk.lines.dependency on stewart.wrenches(T)[0], or NumPy's null space of the "
        f"6 x 6 matrix of leg lines."
    )
    return numbers, statement, float(found.data["pitch"])
