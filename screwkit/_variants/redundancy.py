"""The parametrised exercises of the chapter redundancy."""

import numpy as np

from ..redundancy import pseudo_inverse
from ..robots import planar
from . import pick, register

WORDS = {3: "three", 4: "four", 5: "five"}


@register("redundancy", 4)
def least_norm_rates_of_the_last_link(rng):
    links = pick(rng, [3, 4, 5], 3)
    rate = pick(rng, [0.2, 0.3, 0.4, 0.5, 0.6, 0.9, 1.2], 0.3)
    arm = planar([1.0] * links)
    # the row omega_z of the geometric Jacobian: phi = q1 + ... + qn
    row = arm.geometric_jacobian(np.zeros(links))[5:6]
    qdot = np.linalg.pinv(row) @ [rate]
    numbers = {"n": (links, ""), "phidot": (rate, "rad/s")}
    ones = " ".join(["1"] * links)
    angle = " + ".join(f"q{i}" for i in range(1, links + 1))
    statement = (
        f"The last link of a planar arm of {WORDS[links]} links must turn at "
        f"phi' = {rate:g} rad/s, where phi = {angle}: the Jacobian of "
        f"this one task coordinate is J = [{ones}]. Find the least-norm joint "
        f"rates J+ phi'. What is q1' (rad/s)?"
    )
    return numbers, statement, float(qdot[0])


@register("redundancy", 13)
def tip_of_a_three_link_arm(rng):
    lengths = (
        pick(rng, [0.4, 0.5, 0.6], 0.5),
        pick(rng, [0.3, 0.4, 0.5], 0.4),
        pick(rng, [0.2, 0.3], 0.3),
    )
    angles = (
        pick(rng, [0, 30, 45, 60], 30),
        pick(rng, [30, 60, 90, 120], 60),
        pick(rng, [-90, -60, -45, 45], -90),
    )
    tip = planar(list(lengths)).fk(np.radians(angles))[:2, 3]
    numbers = {f"l{i}": (v, "m") for i, v in enumerate(lengths, start=1)}
    numbers |= {f"q{i}": (v, "deg") for i, v in enumerate(angles, start=1)}
    statement = (
        f"A planar three-link arm has l = ({lengths[0]:g}, {lengths[1]:g}, "
        f"{lengths[2]:g}) m and is at q = ({angles[0]}, {angles[1]}, {angles[2]}) "
        f"deg. Find its tip position (x, y) (m) link by link."
    )
    return numbers, statement, [float(v) for v in tip]


@register("redundancy", 14)
def least_norm_rates_along_a_path(rng):
    lengths = (
        pick(rng, [0.4, 0.5, 0.6], 0.5),
        pick(rng, [0.3, 0.4, 0.5], 0.4),
        pick(rng, [0.2, 0.3, 0.4], 0.3),
    )
    speed = pick(rng, [0.05, 0.1, 0.2, 0.25], 0.1)
    arm = planar(list(lengths))
    jacobian = arm.geometric_jacobian(np.radians([0, 90, -90]))[:2]
    qdot = pseudo_inverse(jacobian) @ [speed, 0.0]
    numbers = {f"l{i}": (v, "m") for i, v in enumerate(lengths, start=1)}
    numbers |= {"v": (speed, "m/s")}
    statement = (
        f"The planar arm l = ({lengths[0]:g}, {lengths[1]:g}, {lengths[2]:g}) m at "
        f"q = (0, 90, -90) deg must move its tip along a path to the right at "
        f"xd' = ({speed:g}, 0) m/s. Write J and J J^T, and find the least-norm "
        f"joint rates (rad/s)."
    )
    return numbers, statement, [float(v) for v in qdot]
