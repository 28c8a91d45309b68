"""Bad input to the inverse kinematics: one row per case, the error type and the
argument the message names."""

import functools

import numpy as np
from builders import planar, puma, puma_offset_wrist
from rows import keyword_rows, row, value_rows

import screwkit as sk
from screwkit import ik


@functools.cache
def t0():
    return puma().fk(np.zeros(6))


SCALED = np.diag([1.0, 2.0, 1.0, 1.0])
Z_AXIS = [0, 0, 1, 0, 0, 0]


def planar_3r():
    return planar(1.0, 1.0, 1.0)


# a 6R chain whose joints 2 and 3 are not parallel
@functools.cache
def twisted():
    return sk.Chain(
        [puma().links[0], sk.Link.revolute(a=0.4318, alpha=0.3)]
        + list(puma().links[2:])
    )


@functools.cache
def prismatic():
    return sk.Chain([sk.Link.prismatic()] + list(puma().links[1:]))


ROWS = [
    row(
        "T not rigid",
        lambda: ik.puma560_ik(SCALED),
        ValueError,
        "T",
        match=r"T must .*rotation",
    ),
    row(
        "T with NaN",
        lambda: ik.puma560_ik(np.full((4, 4), np.nan)),
        ValueError,
        "T",
        match="T must be finite",
    ),
    row("T a string", lambda: ik.puma560_ik("pose"), TypeError, "T", match="T must be"),
    row(
        "T a batch",
        lambda: ik.puma560_ik(np.stack([t0(), t0()])),
        ValueError,
        "T",
        match=r"T must be one pose of shape \(4, 4\)",
    ),
    row(
        "T wrong shape",
        lambda: ik.analytic_ik_all(puma(), np.eye(3)),
        ValueError,
        "T",
        match=r"T must have shape \(4, 4\)",
    ),
    row(
        "T wrong batch shape",
        lambda: ik.analytic_ik_all(puma(), np.zeros((2, 3, 4, 4))),
        ValueError,
        "T",
        match=r"T must have shape \(4, 4\) or \(N, 4, 4\)",
    ),
    row(
        "last row",
        lambda: ik.analytic_ik(puma(), np.vstack([t0()[:3], [0, 0, 1, 1]])),
        ValueError,
        "T",
        match=r"T must have last row",
    ),
    row(
        "label unknown",
        lambda: ik.puma560_ik(t0()).by_config("xyz"),
        ValueError,
        "config",
        match="config must be one of lun",
    ),
    # puma560_ik's options
    *keyword_rows(
        "{}",
        lambda **kw: ik.puma560_ik(t0(), **kw),
        [
            (
                "near wrong length",
                "near",
                [0, 0],
                ValueError,
                "near must be a joint vector of 6 entries",
            ),
            (
                "within_limits not bool",
                "within_limits",
                "yes",
                TypeError,
                "within_limits must be True or False",
            ),
            (
                "robot not a chain",
                "robot",
                "puma",
                TypeError,
                r"robot must be a screwkit Chain .*got 'puma'",
            ),
        ],
    ),
    # a chain the closed form cannot take, built when the row runs
    *value_rows(
        "{}",
        lambda chain: ik.analytic_ik(chain(), t0()),
        "chain",
        [
            (
                "chain of 3 joints",
                planar_3r,
                ValueError,
                "chain must have 6 joints for the closed form, got 3",
            ),
            (
                "prismatic joint",
                prismatic,
                ValueError,
                "chain must have revolute joints only",
            ),
        ],
    ),
    *value_rows(
        "{}",
        lambda chain: ik.spherical_wrist.SphericalWristArm.from_chain(chain()),
        "chain",
        [
            (
                "wrist axes miss",
                puma_offset_wrist,
                ValueError,
                "chain must have a spherical wrist: "
                "the axes of joints 4, 5 and 6 must meet",
            ),
            (
                "joints 2, 3 not parallel",
                twisted,
                ValueError,
                "chain must have parallel axes for joints 2 and 3",
            ),
        ],
    ),
    row(
        "config q short",
        lambda: ik.puma560_config(np.zeros(5)),
        ValueError,
        "q",
        match="q must have 6 entries",
    ),
    row(
        "config q batch",
        lambda: ik.puma560_config(np.zeros((2, 6))),
        ValueError,
        "q",
        match=r"q must be one configuration of shape \(6,\)",
    ),
    row(
        "numeric q0 short",
        lambda: ik.numeric_ik(puma(), t0(), np.zeros(4)),
        ValueError,
        "q0",
        match="q0 must have 6 entries",
    ),
    row(
        "numeric chain",
        lambda: ik.numeric_ik("puma", t0(), np.zeros(6)),
        TypeError,
        "chain",
        match="chain must be a screwkit Chain",
    ),
    row(
        "numeric T batch",
        lambda: ik.numeric_ik(puma(), np.stack([t0(), t0()]), np.zeros(6)),
        ValueError,
        "T",
        match="T must be one pose",
    ),
    # numeric_ik's options, each refused with what it must be
    *keyword_rows(
        "numeric {}",
        lambda **kw: ik.numeric_ik(puma(), t0(), np.zeros(6), **kw),
        [
            ("frame", "frame", "world", ValueError, "frame must be 'body' or 'space'"),
            ("tol", "tol", -1, ValueError, "tol must be a positive number"),
            (
                "iterations",
                "max_iterations",
                0,
                ValueError,
                "max_iterations must be a positive integer",
            ),
            (
                "damping",
                "damping",
                -0.1,
                ValueError,
                "damping must be None or a number >= 0",
            ),
        ],
    ),
    # the subproblems, one bad argument each
    *value_rows(
        "subproblem {}",
        lambda twist: ik.subproblem1(twist, [1, 0, 0], [0, 1, 0]),
        "twist",
        [
            (
                "twist shape",
                [0, 0, 1],
                ValueError,
                r"twist must be a twist of shape \(6,\)",
            ),
            (
                "twist not unit",
                [0, 0, 2, 0, 0, 0],
                ValueError,
                "twist must have a unit angular part",
            ),
            ("helical", [0, 0, 1, 0, 0, 0.1], ValueError, "twist must have pitch 0"),
        ],
    ),
    *value_rows(
        "subproblem {}",
        lambda p: ik.subproblem1(Z_AXIS, p, [0, 1, 0]),
        "p",
        [
            ("point", [1, 0], ValueError, r"p must be a point of shape \(3,\)"),
            ("point text", "p", TypeError, "p must be a number or an array"),
        ],
    ),
    *value_rows(
        "subproblem3 {}",
        lambda delta: ik.subproblem3(Z_AXIS, [1, 0, 0], [2, 0, 0], delta),
        "delta",
        [
            ("delta < 0", -1.0, ValueError, "delta must be a distance >= 0"),
            ("delta array", [1, 2], TypeError, "delta must be one distance"),
        ],
    ),
    row(
        "subproblem2 parallel",
        lambda: ik.subproblem2(Z_AXIS, Z_AXIS, [1, 0, 0], [0, 1, 0]),
        ValueError,
        "twist1",
        match="twist1 and twist2 must have axes that meet",
    ),
    row(
        "subproblem4 normal",
        lambda: ik.subproblem4(Z_AXIS, [1, 0, 0], [0, 2, 0], 0.5),
        ValueError,
        "normal",
        match="normal must be a unit direction",
    ),
    row(
        "prismatic direction",
        lambda: ik.subproblem1_prismatic([1, 1, 0], [0, 0, 0], [1, 1, 0]),
        ValueError,
        "s",
        match="s must be a unit direction",
    ),
]
