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

#: 10^8 configurations of the PUMA, a broadcast view (no memory): every second-order
#: function refuses it before any work (minutes or exhausted memory before)
HUGE = np.broadcast_to(Q, (10**8, 6))
#: 2 x 10^8 samples of a path or times, a broadcast view
MANY = np.broadcast_to(0.5, (2 * 10**8,))
LINE = ([0.0, 1.0], [0.0, 1.0])

SECOND_ORDER = [
    # every second-order function refuses 10^8 configurations (as many q, dq, ddq)
    *(
        row(
            f"{prefix}{name}-huge",
            lambda name=name, n=n: getattr(acc, name)(puma(), *[HUGE] * n),
            ValueError,
            "q",
            match=match,
        )
        for prefix, name, n, match in [
            ("acc.", "space_jacobian_dot", 2, "at most"),
            ("acc.", "body_jacobian_dot", 2, "at most"),
            ("acc.", "space_hessian", 1, "Hessians.*at most"),
            ("acc.", "body_hessian", 1, "at most"),
            ("acc.", "geometric_hessian", 1, "at most"),
            ("", "space_acceleration", 3, "accelerations.*at most"),
            ("", "body_acceleration", 3, "at most"),
            ("", "geometric_acceleration", 3, "at most"),
        ]
    ),
    row(
        "acc.space_jacobian_dot-q",
        lambda: acc.space_jacobian_dot(puma(), BAD, Q),
        ValueError,
        "q",
    ),
    row(
        "acc.space_jacobian_dot-dq",
        lambda: acc.space_jacobian_dot(puma(), Q, "x"),
        TypeError,
        "dq",
    ),
    row(
        "acc.body_jacobian_dot-chain",
        lambda: acc.body_jacobian_dot(None, Q, Q),
        TypeError,
        "chain",
    ),
    row(
        "acc.body_jacobian_dot-q",
        lambda: acc.body_jacobian_dot(puma(), [np.inf] * 6, Q),
        ValueError,
        "q",
    ),
    row(
        "acc.geometric_jacobian_dot-chain",
        lambda: acc.geometric_jacobian_dot(np.eye(4), Q, Q),
        TypeError,
        "chain",
    ),
    row(
        "acc.geometric_jacobian_dot-dq",
        lambda: acc.geometric_jacobian_dot(puma(), Q, np.zeros((3, 6))),
        ValueError,
        "dq",
    ),
    row(
        "acc.space_hessian-chain",
        lambda: acc.space_hessian("puma", Q),
        TypeError,
        "chain",
    ),
    row(
        "acc.space_hessian-q",
        lambda: acc.space_hessian(puma(), np.zeros((2, 3, 6))),
        ValueError,
        "q",
    ),
    row("acc.body_hessian-chain", lambda: acc.body_hessian(1, Q), TypeError, "chain"),
    row(
        "acc.geometric_hessian-q",
        lambda: acc.geometric_hessian(puma(), [None] * 6),
        TypeError,
        "q",
    ),
    row(
        "space_acceleration-chain",
        lambda: acc.space_acceleration([], Q, Q, Q),
        TypeError,
        "chain",
    ),
    row(
        "space_acceleration-q",
        lambda: acc.space_acceleration(puma(), BAD, Q, Q),
        ValueError,
        "q",
    ),
    row(
        "space_acceleration-dq",
        lambda: acc.space_acceleration(puma(), Q, "x", Q),
        TypeError,
        "dq",
    ),
    row(
        "body_acceleration-chain",
        lambda: acc.body_acceleration("x", Q, Q, Q),
        TypeError,
        "chain",
    ),
    row(
        "body_acceleration-q",
        lambda: acc.body_acceleration(puma(), [np.nan] * 6, Q, Q),
        ValueError,
        "q",
    ),
    row(
        "body_acceleration-dq",
        lambda: acc.body_acceleration(puma(), Q, BAD, Q),
        ValueError,
        "dq",
    ),
    row(
        "geometric_acceleration-chain",
        lambda: acc.geometric_acceleration(None, Q, Q, Q),
        TypeError,
        "chain",
    ),
    row(
        "geometric_acceleration-q",
        lambda: acc.geometric_acceleration(puma(), "q", Q, Q),
        TypeError,
        "q",
    ),
    row(
        "geometric_acceleration-ddq",
        lambda: acc.geometric_acceleration(puma(), Q, Q, np.zeros((2, 6))),
        ValueError,
        "ddq",
    ),
    row(
        "space_jacobian_dot-q",
        lambda: puma().space_jacobian_dot(BAD, BAD),
        ValueError,
        "q",
    ),
    row(
        "body_jacobian_dot-q", lambda: puma().body_jacobian_dot(None, Q), TypeError, "q"
    ),
    row(
        "geometric_jacobian_dot-q",
        lambda: puma().geometric_jacobian_dot([np.inf] * 6, Q),
        ValueError,
        "q",
    ),
]

TRAJECTORY = [
    row("cubic-v_max-str", lambda: tr.cubic(v_max="1"), TypeError, "v_max"),
    row("cubic-a_max-shape", lambda: tr.cubic(a_max=[1.0, 2.0]), ValueError, "a_max"),
    row("quintic-duration-nan", lambda: tr.quintic(np.nan), ValueError, "duration"),
    row("quintic-v_max-bool", lambda: tr.quintic(v_max=True), TypeError, "v_max"),
    row("quintic-too-fast", lambda: tr.quintic(0.5, v_max=1.0), ValueError, "duration"),
    row(
        "trapezoidal-duration",
        lambda: tr.trapezoidal(-1.0, v_max=1.5),
        ValueError,
        "duration",
    ),
    row(
        "trapezoidal-a_max",
        lambda: tr.trapezoidal(v_max=1.0, a_max=0.0),
        ValueError,
        "a_max",
    ),
    row(
        "trapezoidal-three-given",
        lambda: tr.trapezoidal(1.0, v_max=1.5, a_max=4.0),
        ValueError,
        "duration",
    ),
    row(
        "fastest_joint_scaling-profile",
        lambda: tr.fastest_joint_scaling(max, [0.0], [1.0], 1.0, 1.0),
        TypeError,
        "profile",
    ),
    row(
        "fastest_joint_scaling-q_start",
        lambda: tr.fastest_joint_scaling(tr.cubic, [[0.0]], [1.0], 1.0, 1.0),
        ValueError,
        "q_start",
    ),
    row(
        "fastest_joint_scaling-q_end",
        lambda: tr.fastest_joint_scaling(tr.cubic, [0.0], "x", 1.0, 1.0),
        TypeError,
        "q_end",
    ),
    row(
        "fastest_joint_scaling-a_max-many",
        lambda: tr.fastest_joint_scaling(
            tr.cubic, np.zeros(10**5), np.ones(10**5), 1.0, -np.ones(10**5)
        ),
        ValueError,
        "a_max",
    ),
    row(
        "fastest_joint_scaling-no-motion",
        lambda: tr.fastest_joint_scaling(tr.cubic, [1.0], [1.0], 1.0, 1.0),
        ValueError,
        "q_start",
    ),
    row("evaluate-str", lambda: tr.cubic(1.0).evaluate("0.5"), TypeError, "t"),
    row(
        "evaluate-many-late",
        lambda: tr.cubic(1.0).evaluate(np.linspace(0, 2, 10**6)),
        ValueError,
        "t",
    ),
    row("times-float", lambda: tr.cubic(1.0).times(10.0), TypeError, "count"),
    row(  # a thousand digits, quoted in 80 characters
        "times-negative-thousand-digits",
        lambda: tr.cubic(1.0).times(-(10**1000)),
        ValueError,
        "count",
    ),
    row(
        "times-huge",
        lambda: tr.quintic(2.0).times(10**10),
        ValueError,
        "count",
        match="GB",
    ),
    row(
        "joint_path-q_end",
        lambda: tr.joint_path([0.0], "x", tr.cubic(1.0), 0.5),
        TypeError,
        "q_end",
    ),
    row(
        "joint_path-scaling",
        lambda: tr.joint_path([0.0], [1.0], tr.cubic, 0.5),
        TypeError,
        "scaling",
    ),
    row(
        "joint_path-t",
        lambda: tr.joint_path([0.0], [1.0], tr.cubic(1.0), -1.0),
        ValueError,
        "t",
    ),
    row(
        "joint_path-t-huge",
        lambda: tr.joint_path([0.0] * 6, [1.0] * 6, tr.cubic(1.0), MANY),
        ValueError,
        "t",
        match="GB",
    ),
    # 2 x 10^8 path parameters are refused, their size in GB said
    *(
        row(
            f"{name}-s-huge",
            lambda name=name, ends=ends: getattr(tr, name)(*ends, MANY),
            ValueError,
            "s",
            match="GB",
        )
        for name, ends in [
            ("screw_path", (np.eye(4), np.eye(4))),
            ("cartesian_path", (np.eye(4), np.eye(4))),
            ("slerp", ([1.0, 0, 0, 0], [0.0, 1.0, 0, 0])),
        ]
    ),
    row(
        "screw_path-T_start",
        lambda: tr.screw_path("T", np.eye(4), 0.5),
        TypeError,
        "T_start",
    ),
    row(
        "screw_path-s", lambda: tr.screw_path(np.eye(4), np.eye(4), "s"), TypeError, "s"
    ),
    row(
        "cartesian_path-T_start",
        lambda: tr.cartesian_path(NOT_RIGID, np.eye(4), 0.5),
        ValueError,
        "T_start",
    ),
    row(
        "cartesian_path-T_end",
        lambda: tr.cartesian_path(np.eye(4), np.eye(3), 0.5),
        ValueError,
        "T_end",
    ),
    row(
        "slerp-q_end",
        lambda: tr.slerp([1.0, 0, 0, 0], [2.0, 0, 0, 0], 0.5),
        ValueError,
        "q_end",
    ),
    row(
        "slerp-s",
        lambda: tr.slerp([1.0, 0, 0, 0], [1.0, 0, 0, 0], [[0.5]]),
        ValueError,
        "s",
    ),
    row(
        "via_points-times-shape",
        lambda: tr.via_points([[0.0, 1.0]], [0.0, 1.0]),
        ValueError,
        "times",
    ),
    row(
        "via_points-points-rows",
        lambda: tr.via_points([0.0, 1.0, 2.0], [0.0, 1.0]),
        ValueError,
        "points",
    ),
    row(
        "via_points-points-str",
        lambda: tr.via_points([0.0, 1.0], ["a", "b"]),
        TypeError,
        "points",
    ),
    row(
        "via_points-velocities-size",
        lambda: tr.via_points([0.0, 1.0, 2.0], np.zeros((3, 2)), [1.0, 2.0, 3.0]),
        ValueError,
        "velocities",
        match=r"\(3, 2\)",
    ),
    row(
        "via_points-velocities-shape",
        lambda: tr.via_points([0.0, 1.0, 2.0], np.zeros((3, 2)), np.ones((2, 3))),
        ValueError,
        "velocities",
        match=r"got shape \(2, 3\)",
    ),
    row(
        "via_points-velocities-nan",
        lambda: tr.via_points(*LINE, velocities=[0.0, np.nan]),
        ValueError,
        "velocities",
    ),
    row(
        "ViaPoints.evaluate-many-late",
        lambda: tr.via_points(*LINE).evaluate(np.linspace(0.0, 2.0, 10**6)),
        ValueError,
        "t",
        match=r"t\[500000\]",
    ),
    row(
        "ViaPoints.evaluate-str",
        lambda: tr.via_points(*LINE).evaluate("1"),
        TypeError,
        "t",
    ),
    row(
        "ViaPoints.evaluate-huge",
        lambda: tr.via_points(*LINE).evaluate(MANY),
        ValueError,
        "t",
        match="GB",
    ),
    row(
        "follow_path-chain",
        lambda: tr.follow_path("puma", np.eye(4)[None]),
        TypeError,
        "chain",
    ),
    row(
        "follow_path-poses-one",
        lambda: tr.follow_path(puma(), np.eye(4)),
        ValueError,
        "poses",
    ),
    row(
        "follow_path-q_start",
        lambda: tr.follow_path(puma(), np.eye(4)[None], q_start=BAD),
        ValueError,
        "q_start",
    ),
]

ROWS = CASES + SECOND_ORDER + TRAJECTORY
