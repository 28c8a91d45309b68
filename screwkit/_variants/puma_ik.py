"""The parametrised exercises of the chapter puma_ik."""

import math

import numpy as np

from ..chains import Chain
from ..ik.dispatch import analytic_ik
from ..ik.subproblems import subproblem1, subproblem3
from ..tolerances import IK_DUPLICATE_TOL
from ..transforms import transl, twist_from_axis
from . import pick, register

#: directions across a vertical axis whose coordinates print exactly
ACROSS = [(1, 0), (0, 1), (-1, 0), (0, -1), (0.6, 0.8), (0.8, 0.6), (-0.6, 0.8)]

#: the arm of exercise 16: a spherical wrist, a shoulder ahead of the waist axis and
#: an elbow offset
OFFSET_ARM = [
    [0, 0.45, 0.15, -math.pi / 2],
    [0, 0, 0.6, 0],
    [0, 0, 0.12, math.pi / 2],
    [0, 0.72, 0, -math.pi / 2],
    [0, 0, 0, math.pi / 2],
    [0, 0.1, 0, 0],
]


def _point(values):
    return "(" + ", ".join(f"{v:g}" for v in values) + ")"


@register("puma_ik", 16)
def offset_arm_wrist_centre(rng):
    x = pick(rng, [0.7, 0.5, 0.9, 0.6], 0.7)
    y = pick(rng, [0.3, -0.2, 0.4, 0.1], 0.3)
    z = pick(rng, [1.0, 0.8, 1.2, 0.6], 1.0)
    arm = Chain.from_table(OFFSET_ARM)
    # the tool 0.1 m above the wrist centre, along its own z = z_0
    solutions = analytic_ik(arm, transl(x, y, z + 0.1))
    facing = math.atan2(y, x)
    found = [
        s.q[:3]
        for s in solutions
        if abs(math.remainder(s.q[0] - facing, 2 * math.pi)) < IK_DUPLICATE_TOL
        and abs(s.q[2]) < math.pi / 2
    ]
    # the wrist's two ways share (q1, q2, q3): one arm solution
    if not found or not all(
        np.allclose(f, found[0], atol=IK_DUPLICATE_TOL) for f in found
    ):
        raise RuntimeError(f"no single arm solution for the wrist centre {x, y, z}")
    q = found[0]
    numbers = {"x": (x, "m"), "y": (y, "m"), "z": (z, "m")}
    statement = (
        "An industrial arm with a spherical wrist and two offsets (no shoulder offset "
        "sideways, as the PUMA has): the waist about z_0; the shoulder 0.45 m up and "
        "0.15 m ahead of the waist axis (a_1); an upper arm a_2 = 0.6 m; an elbow "
        "offset a_3 = 0.12 m and a forearm d_4 = 0.72 m to the wrist centre "
        "(straight up at home). Its table is [[0, 0.45, 0.15, -pi/2], [0, 0, 0.6, "
        "0], [0, 0, 0.12, pi/2], [0, 0.72, 0, -pi/2], [0, 0, 0, pi/2], [0, 0.1, 0, "
        "0]]; positive q_2 and q_3 turn the links downward. Find (q_1, q_2, q_3) "
        f"that put the wrist centre at ({x:.1f}, {y:.1f}, {z:.1f}) m with the "
        "shoulder facing it and abs(q_3) < 90 deg, in degrees."
    )
    return numbers, statement, [math.degrees(v) for v in q]


@register("puma_ik", 18)
def spherical_arm_inverse(rng):
    x = pick(rng, [0.3, 0.2, -0.3, 0.4, 0.5], 0.3)
    y = pick(rng, [0.4, 0.3, -0.2, 0.1], 0.4)
    z = pick(rng, [0.6, 0.3, 0.8, 0.5, 0.2], 0.6)
    # the boom's horizontal part and its length, from the distances
    across = math.sqrt(x**2 + y**2 - 0.15**2)
    boom = math.hypot(across, z - 0.4)
    # q1 turns the tool's place at q1 = 0 onto the target, about z_0
    waist = twist_from_axis([0, 0, 1], [0, 0, 0], 0)
    (q1,) = subproblem1(waist, [across, 0.15, z], [x, y, z])
    # q2 tips the boom, straight up at home, about +y_0 through the shoulder
    shoulder = twist_from_axis([0, 1, 0], [0, 0, 0.4], 0)
    (q2,) = subproblem1(shoulder, [0, 0.15, 0.4 + boom], [across, 0.15, z])
    numbers = {"x": (x, "m"), "y": (y, "m"), "z": (z, "m")}
    statement = (
        "The Stanford-type arm of the PUMA FK chapter's exercise 15 puts its tool at "
        "(c1 s2 q3 - 0.15 s1, s1 s2 q3 + 0.15 c1, 0.4 + c2 q3). Solve for the tool "
        f"at {_point((x, y, z))} m with q3 > 0 and q2 > 0: give (q1, q2) in degrees, "
        "and q3."
    )
    return numbers, statement, [math.degrees(q1), math.degrees(q2)]


@register("puma_ik", 21)
def subproblem_one(rng):
    a = pick(rng, [1, 0, -1, 0.5], 1)
    b = pick(rng, [0, 1, -0.5], 0)
    height = pick(rng, [0.5, 0.2, 0.3], 0.5)
    u, v = ((1, 0), (0, 1)) if rng is None else (ACROSS[i] for i in _two(rng))
    p = [round(a + u[0], 6), round(b + u[1], 6), height]
    q = [round(a + v[0], 6), round(b + v[1], 6), height]
    (angle,) = subproblem1(twist_from_axis([0, 0, 1], [a, b, 0], 0), p, q)
    numbers = {"a": (a, "m"), "b": (b, "m"), "h": (height, "m")}
    numbers |= {"px": (p[0], "m"), "py": (p[1], "m")}
    numbers |= {"qx": (q[0], "m"), "qy": (q[1], "m")}
    higher = q[:2] + [round(height + 0.1, 6)]
    statement = (
        f"Subproblem 1 with numbers: the axis is vertical (+z) through ({a:g}, {b:g}, "
        f"0); turn p = {_point(p)} onto q = {_point(q)}. Which angle, in degrees? Why "
        f"does q = {_point(higher)} have none?"
    )
    return numbers, statement, math.degrees(angle)


def _two(rng):
    """Two directions of ACROSS, neither equal nor opposite (no half-turn tie)."""
    while True:
        i, j = (int(k) for k in rng.choice(len(ACROSS), 2, replace=False))
        if ACROSS[i] != tuple(-c for c in ACROSS[j]):
            return i, j


@register("puma_ik", 22)
def subproblem_three(rng):
    # (distance of p from the axis, of q, delta): two solutions, well apart
    r_p, r_q, delta = pick(
        rng,
        [
            (1, 2, 1.5),
            (1, 2, 2),
            (1, 2, 2.5),
            (1.5, 2, 1),
            (1.5, 2, 2),
            (0.5, 1, 0.8),
            (2, 2.5, 1.5),
            (1, 3, 2.5),
            (2, 3, 2),
            (1.5, 2.5, 3),
            (0.5, 2, 1.8),
        ],
        (1, 2, 1.5),
    )
    turn = twist_from_axis([0, 0, 1], [0, 0, 0], 0)
    angles = subproblem3(turn, [r_p, 0, 0], [r_q, 0, 0], delta)
    numbers = {"p": (r_p, "m"), "q": (r_q, "m"), "delta": (delta, "m")}
    statement = (
        f"Subproblem 3 with numbers: turn p = ({r_p:g}, 0, 0) about z (through the "
        f"origin) until it is {delta:g} m from q = ({r_q:g}, 0, 0). Give the positive "
        f"angle, in degrees, and explain why there are two."
    )
    return numbers, statement, math.degrees(max(angles))
