"""The parametrised exercises of the chapter poe."""

import math

from ..chains import Chain
from ..lie import log_transform
from ..screws import Twist
from ..transforms import transl
from . import pick, register

#: translations of a whole length, so that theta is a whole number of metres
WHOLE_LENGTHS = [
    (1, 2, 2),
    (2, -1, 2),
    (2, 3, 6),
    (-3, 0, 4),
    (0, 3, -4),
    (1, 4, 8),
    (4, -4, 2),
    (-2, 6, 9),
    (6, 2, 3),
]


def pi_text(fraction):
    """``(2, 3)`` -> '2pi/3', ``(-1, 2)`` -> '-pi/2', ``(0, 1)`` -> '0'."""
    top, bottom = fraction
    if top == 0:
        return "0"
    sign = "-" if top < 0 else ""
    count = "" if abs(top) == 1 else str(abs(top))
    below = "" if bottom == 1 else f"/{bottom}"
    return f"{sign}{count}pi{below}"


def pi_value(fraction):
    return math.pi * fraction[0] / fraction[1]


@register("poe", 3)
def log_of_a_translation(rng):
    p = pick(rng, WHOLE_LENGTHS, (1, 2, 2))
    log = log_transform(transl(*p))
    numbers = {"px": (p[0], "m"), "py": (p[1], "m"), "pz": (p[2], "m")}
    statement = (
        f"What is the logarithm S theta of a pure translation by ({p[0]}, {p[1]}, "
        f"{p[2]}) m? Give its six numbers, then name omega, v and theta of the unit "
        f"screw."
    )
    return numbers, statement, [float(v) for v in log]


@register("poe", 8)
def nut_after_a_turn(rng):
    q = pick(
        rng,
        [(1, 3), (1, 2), (2, 3), (3, 4), (1, 1), (4, 3), (3, 2), (5, 3), (5, 4)],
        (2, 3),
    )
    lead_screw = Twist.from_axis([0, 0, 1], [1, 0, 0], 0.05)
    nut = Chain.from_screws([lead_screw], transl(2, 0, 0))
    tool = nut.fk([pi_value(q)])[:3, 3]
    numbers = {"q": (pi_value(q), "rad")}
    statement = (
        f"Where is the nut's tool (of the section A helical joint) at "
        f"q = {pi_text(q)}? Give (x, y, z) in metres."
    )
    return numbers, statement, [float(v) for v in tool]


@register("poe", 14)
def elbow_arm_position(rng):
    q1 = pick(rng, [(0, 1), (1, 2), (-1, 2), (1, 1)], (0, 1))
    q2 = pick(rng, [(-1, 2), (0, 1), (-1, 4), (1, 4)], (-1, 2))
    q3 = pick(rng, [(1, 2), (-1, 2), (1, 4), (0, 1)], (1, 2))
    screws = [[0, 0, 1, 0, 0, 0], [0, 1, 0, -0.3, 0, 0], [0, 1, 0, -0.3, 0, 0.35]]
    elbow = Chain.from_screws(screws, transl(0.65, 0, 0.3))
    q = [pi_value(q1), pi_value(q2), pi_value(q3)]
    tool = elbow.fk(q)[:3, 3]
    numbers = {"q1": (q[0], "rad"), "q2": (q[1], "rad"), "q3": (q[2], "rad")}
    statement = (
        f"The elbow arm of exercise 13 is at q = ({pi_text(q1)}, {pi_text(q2)}, "
        f"{pi_text(q3)}). Where is the tool (metres)?"
    )
    return numbers, statement, [float(v) for v in tool]


@register("poe", 16)
def rpr_arm_position(rng):
    q1 = pick(rng, [(1, 2), (-1, 2), (1, 1), (1, 4), (1, 3), (2, 3)], (1, 2))
    slide = pick(rng, [0.1, 0.2, 0.3, -0.1, -0.2], 0.2)
    roll = pick(rng, [0.7, 0.5, 1.2, -0.4], 0.7)
    screws = [[0, 0, 1, 0, 0, 0], [0, 0, 0, 1, 0, 0], [1, 0, 0, 0, 0.4, 0]]
    rpr = Chain.from_screws(screws, transl(0.6, 0, 0.4))
    tool = rpr.fk([pi_value(q1), slide, roll])[:3, 3]
    numbers = {"q1": (pi_value(q1), "rad"), "q2": (slide, "m"), "q3": (roll, "rad")}
    statement = (
        "An RPR arm: a waist about z_s, a telescopic arm that slides along x_s at "
        "height 0.4 m, and a roll joint about the arm's own axis; at home the tool is "
        "at (0.6, 0, 0.4) m, its frame parallel to {s}. Where is the tool at "
        f"q = ({pi_text(q1)}, {slide:g}, {roll:g}) (metres)?"
    )
    return numbers, statement, [float(v) for v in tool]
