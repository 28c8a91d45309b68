"""The parametrised exercises of the chapter poe: the keys' computations.

The statements and their draws are in screwkit/answers/poe.toml; an angle drawn as
a fraction of pi, ``[top, bottom]``, is shown as ``2pi/3`` (:func:`turns`).
"""

import math

from ..chains import Chain
from ..lie import log_transform
from ..screws import Twist
from ..transforms import transl
from . import register


def pi_text(fraction):
    """``(2, 3)`` -> '2pi/3', ``(-1, 2)`` -> '-pi/2', ``(0, 1)`` -> '0'."""
    top, bottom = fraction
    if top == 0:
        return "0"
    sign = "-" if top < 0 else ""
    count = "" if abs(top) == 1 else str(abs(top))
    below = "" if bottom == 1 else f"/{bottom}"
    return f"{sign}{count}pi{below}"


def turns(**fractions):
    """Angles drawn as fractions of pi, ``q1=(1, 2)``: ``{"q1": pi / 2, "q1_text":
    "pi/2"}``, the value (rad) and its text in the statement."""
    shown = {}
    for name, (top, bottom) in fractions.items():
        shown[name] = math.pi * top / bottom
        shown[f"{name}_text"] = pi_text((top, bottom))
    return shown


@register("poe", 3)
def log_of_a_translation(p):
    """The logarithm S theta of a pure translation by p (m), and p's coordinates."""
    return log_transform(transl(*p)), dict(zip(("px", "py", "pz"), p))


@register("poe", 8)
def nut_after_a_turn(q_over_pi):
    """The tool (m) of the nut on the lead screw (pitch 0.05 m/rad, along z through
    (1, 0, 0)) after the turn q = pi ``q_over_pi``."""
    shown = turns(q=q_over_pi)
    lead_screw = Twist.from_axis([0, 0, 1], [1, 0, 0], 0.05)
    nut = Chain.from_screws([lead_screw], transl(2, 0, 0))
    return nut.fk([shown["q"]])[:3, 3], shown


@register("poe", 14)
def elbow_arm_position(q1_over_pi, q2_over_pi, q3_over_pi):
    """The tool (m) of the elbow arm of exercise 13 at q = pi (q1, q2, q3 over pi)."""
    shown = turns(q1=q1_over_pi, q2=q2_over_pi, q3=q3_over_pi)
    screws = [[0, 0, 1, 0, 0, 0], [0, 1, 0, -0.3, 0, 0], [0, 1, 0, -0.3, 0, 0.35]]
    elbow = Chain.from_screws(screws, transl(0.65, 0, 0.3))
    return elbow.fk([shown["q1"], shown["q2"], shown["q3"]])[:3, 3], shown


@register("poe", 16)
def rpr_arm_position(q1_over_pi, q2, q3):
    """The tool (m) of the RPR arm at q = (pi ``q1_over_pi``, q2 (m), q3 (rad))."""
    shown = turns(q1=q1_over_pi)
    screws = [[0, 0, 1, 0, 0, 0], [0, 0, 0, 1, 0, 0], [1, 0, 0, 0, 0.4, 0]]
    rpr = Chain.from_screws(screws, transl(0.6, 0, 0.4))
    return rpr.fk([shown["q1"], q2, q3])[:3, 3], shown
