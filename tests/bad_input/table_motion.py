"""Bad input of motion in time: screwkit.motion.acceleration, the Chain's *_jacobian_dot
and *_hessian, screwkit.motion.trajectory and screwkit.motion.differential_ik. One
row per case (tests/bad_input/rows.py): the error type and the argument its sentence
names."""

import functools

import numpy as np
import sympy as sp
from builders import puma
from rows import row

import screwkit as sk
from screwkit.motion import acceleration as acc
from screwkit.motion import differential_ik as dik
from screwkit.motion import trajectory as tr


@functools.cache
def arm():
    return sk.robots.planar([1.0, 1.0], qlim=[(-2.0, 2.0)] * 2)


Q, BAD = np.zeros(6), np.zeros(5)
NOT_RIGID = np.diag([2.0, 1.0, 1.0, 1.0])

CASES = [
    row(
        "space_jacobian_dot-dq",
        lambda: puma().space_jacobian_dot(Q, BAD),
        ValueError,
        "dq",
    ),
    row(
        "body_jacobian_dot-str",
        lambda: puma().body_jacobian_dot(Q, "x"),
        TypeError,
        "dq",
    ),
    row(
        "geometric_jacobian_dot-batch",
        lambda: puma().geometric_jacobian_dot(Q, np.zeros((2, 6))),
        ValueError,
        "dq",
    ),
    row("space_hessian-q", lambda: puma().space_hessian(BAD), ValueError, "q"),
    row("body_hessian-None", lambda: puma().body_hessian(None), TypeError, "q"),
    row(
        "geometric_hessian-nan",
        lambda: puma().geometric_hessian([np.nan] * 6),
        ValueError,
        "q",
    ),
    row(
        "acc.space_jacobian_dot-chain",
        lambda: acc.space_jacobian_dot("x", Q, Q),
        TypeError,
        "chain",
    ),
    row(
        "acc.body_jacobian_dot-exact",
        lambda: acc.body_jacobian_dot(puma(), [sp.S(0)] * 6, [1, 2]),
        ValueError,
        "dq",
    ),
    row(
        "acc.geometric_jacobian_dot-q",
        lambda: acc.geometric_jacobian_dot(puma(), BAD, BAD),
        ValueError,
        "q",
    ),
    row(
        "acc.space_hessian-exact-str",
        lambda: acc.space_hessian(puma(), [sp.S(0)] * 5 + ["a"]),
        TypeError,
        "q[5]",
    ),
    row("acc.body_hessian-q", lambda: acc.body_hessian(puma(), "q"), TypeError, "q"),
    row(
        "acc.geometric_hessian-chain",
        lambda: acc.geometric_hessian(None, Q),
        TypeError,
        "chain",
    ),
    row(
        "space_acceleration-ddq",
        lambda: acc.space_acceleration(puma(), Q, Q, BAD),
        ValueError,
        "ddq",
    ),
    row(
        "body_acceleration-ddq-exact",
        lambda: acc.body_acceleration(puma(), [sp.S(0)] * 6, Q.tolist(), "x"),
        TypeError,
        "ddq",
    ),
    row(
        "geometric_acceleration-dq",
        lambda: acc.geometric_acceleration(puma(), Q, BAD, Q),
        ValueError,
        "dq",
    ),
    row("cubic-negative", lambda: tr.cubic(-1.0), ValueError, "duration"),
    row("quintic-a_max", lambda: tr.quintic(a_max=0.0), ValueError, "a_max"),
    row(
        "trapezoidal-v_max",
        lambda: tr.trapezoidal(v_max=-1.0, a_max=1.0),
        ValueError,
        "v_max",
    ),
    row(
        "fastest_joint_scaling-v_max",
        lambda: tr.fastest_joint_scaling(tr.cubic, [0.0], [1.0], [1.0, 2.0], 1.0),
        ValueError,
        "v_max",
    ),
    row("evaluate-late", lambda: tr.cubic(1.0).evaluate(2.0), ValueError, "t"),
    row("times-count", lambda: tr.cubic(1.0).times(1), ValueError, "count"),
    row(
        "joint_path-shapes",
        lambda: tr.joint_path([0.0], [1.0, 2.0], tr.cubic(1.0), 0.5),
        ValueError,
        "q_start",
    ),
    row(
        "screw_path-not-rigid",
        lambda: tr.screw_path(np.eye(4), NOT_RIGID, 0.5),
        ValueError,
        "T_end",
    ),
    row(
        "cartesian_path-s",
        lambda: tr.cartesian_path(np.eye(4), np.eye(4), np.zeros((2, 2))),
        ValueError,
        "s",
    ),
    row(
        "slerp-shape",
        lambda: tr.slerp([1.0, 0, 0], [1.0, 0, 0, 0], 0.5),
        ValueError,
        "q_start",
    ),
    row(
        "via_points-order",
        lambda: tr.via_points([0.0, 0.0], [0.0, 1.0]),
        ValueError,
        "times",
    ),
    row(
        "ViaPoints.evaluate-late",
        lambda: tr.via_points([0.0, 1.0], [0.0, 1.0]).evaluate(3.0),
        ValueError,
        "t",
    ),
    row(
        "follow_path-method",
        lambda: tr.follow_path(puma(), np.eye(4)[None], method="fast"),
        ValueError,
        "method",
    ),
    row(
        "follow_path-poses",
        lambda: tr.follow_path(puma(), NOT_RIGID[None]),
        ValueError,
        "poses",
    ),
    row(
        "pseudo_inverse_step-twist",
        lambda: dik.pseudo_inverse_step(arm(), [0.0, 0.0], [1.0], 0.1, rows="planar"),
        ValueError,
        "twist",
    ),
    row(
        "qp_step-v_max",
        lambda: dik.qp_step(
            arm(), [0.0, 0.0], [1.0, 0.0], 0.1, rows="planar", v_max=[-1.0, 1.0]
        ),
        ValueError,
        "v_max",
    ),
    row(
        "qp_step-dt",
        lambda: dik.qp_step(arm(), [0.0, 0.0], [1.0, 0.0], 0.0, rows="planar"),
        ValueError,
        "dt",
    ),
]

ROWS = CASES
