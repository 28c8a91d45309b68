"""The parametrised exercises of the chapter puma_ik: the keys' computations.

The statements and their draws are in screwkit/answers/puma_ik.toml; exercise 21's
two directions are drawn here (:func:`two_directions`).
"""

import math

import numpy as np

from ..chains import Chain
from ..ik.dispatch import analytic_ik
from ..ik.subproblems import subproblem1, subproblem3
from ..tolerances import IK_DUPLICATE_TOL
from ..transforms import transl, twist_from_axis
from . import register

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
def offset_arm_wrist_centre(x, y, z):
    """(q_1, q_2, q_3) (deg) of the arm with offsets that put its wrist centre at
    (x, y, z) m, the shoulder facing it and the elbow within 90 deg."""
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
    return [math.degrees(v) for v in found[0]]


@register("puma_ik", 18)
def spherical_arm_inverse(x, y, z):
    """(q1, q2) (deg) of the Stanford-type arm with its tool at (x, y, z) m."""
    # the boom's horizontal part and its length, from the distances
    across = math.sqrt(x**2 + y**2 - 0.15**2)
    boom = math.hypot(across, z - 0.4)
    # q1 turns the tool's place at q1 = 0 onto the target, about z_0
    waist = twist_from_axis([0, 0, 1], [0, 0, 0], 0)
    (q1,) = subproblem1(waist, [across, 0.15, z], [x, y, z])
    # q2 tips the boom, straight up at home, about +y_0 through the shoulder
    shoulder = twist_from_axis([0, 1, 0], [0, 0, 0.4], 0)
    (q2,) = subproblem1(shoulder, [0, 0.15, 0.4 + boom], [across, 0.15, z])
    return [math.degrees(q1), math.degrees(q2)]


def two_directions(rng):
    """Exercise 21's directions u and v of p and q from the axis: two of ACROSS,
    neither equal nor opposite (no half-turn tie); (1, 0) and (0, 1) for seed 0."""
    if rng is None:
        return {"u": (1, 0), "v": (0, 1)}
    while True:
        i, j = (int(k) for k in rng.choice(len(ACROSS), 2, replace=False))
        if ACROSS[i] != tuple(-c for c in ACROSS[j]):
            return {"u": ACROSS[i], "v": ACROSS[j]}


@register("puma_ik", 21, draws=two_directions)
def subproblem_one(a, b, h, u, v):
    """The angle (deg) about the vertical through (a, b, 0) that turns p, at u from
    the axis and height h (m), onto q, at v from it."""
    p = [round(a + u[0], 6), round(b + u[1], 6), h]
    q = [round(a + v[0], 6), round(b + v[1], 6), h]
    (angle,) = subproblem1(twist_from_axis([0, 0, 1], [a, b, 0], 0), p, q)
    higher = q[:2] + [round(h + 0.1, 6)]
    shown = {"px": p[0], "py": p[1], "qx": q[0], "qy": q[1]}
    texts = {"p_shown": _point(p), "q_shown": _point(q), "higher_shown": _point(higher)}
    return math.degrees(angle), shown | texts


@register("puma_ik", 22)
def subproblem_three(sides):
    """The positive angle (deg) that turns p = (p, 0, 0) about z until it is delta
    from q = (q, 0, 0), for ``sides`` = (p, q, delta) (m)."""
    r_p, r_q, delta = sides
    turn = twist_from_axis([0, 0, 1], [0, 0, 0], 0)
    angles = subproblem3(turn, [r_p, 0, 0], [r_q, 0, 0], delta)
    return math.degrees(max(angles)), {"p": r_p, "q": r_q, "delta": delta}
