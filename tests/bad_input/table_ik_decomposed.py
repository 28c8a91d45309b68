"""Bad input to the decomposed closed form and subproblems 5 and 6: one row per case,
the error type and the argument the message names."""

import functools

import numpy as np
from builders import planar, puma, puma_offset_wrist
from rows import keyword_rows, row, value_rows

import screwkit as sk
from screwkit import ik
from screwkit.ik import decomposed

Z = [0.0, 0.0, 1.0]


@functools.cache
def iiwa():
    return sk.robots.iiwa14()


@functools.cache
def shoulder_arm():
    return decomposed.DecomposedArm.from_chain(
        sk.Chain.from_screws(sk.robots.iiwa14().screw_axes()[1:], np.eye(4))
    )


@functools.cache
def shoulder_chain():
    """The iiwa's joints 2 ... 7: a decomposable 6R (a spherical shoulder)."""
    return sk.Chain.from_screws(sk.robots.iiwa14().screw_axes()[1:], np.eye(4))


@functools.cache
def t7():
    return iiwa().fk(np.zeros(7))


ROWS = [
    row(
        "subproblem5 k not unit",
        lambda: ik.subproblem5(Z, [0, 0, 2.0], Z, Z, Z, Z, Z),
        ValueError,
        "k2",
        match="k2 must be a unit direction",
    ),
    row(
        "subproblem5 p shape",
        lambda: ik.subproblem5(Z, Z, Z, [1.0, 0], Z, Z, Z),
        ValueError,
        "p0",
        match=r"p0 must be a point of shape \(3,\)",
    ),
    row(
        "subproblem5 p text",
        lambda: ik.subproblem5(Z, Z, Z, Z, "p", Z, Z),
        TypeError,
        "p1",
        match="p1 must be a number or an array",
    ),
    row(
        "subproblem6 h shape",
        lambda: ik.subproblem6(
            np.zeros((3, 3)), np.eye(3)[[2, 2, 2, 2]], np.ones((4, 3)), [0, 0]
        ),
        ValueError,
        "h",
        match=r"h must have shape \(4, 3\)",
    ),
    row(
        "subproblem6 k not unit",
        lambda: ik.subproblem6(
            np.ones((4, 3)), np.ones((4, 3)), np.ones((4, 3)), [0, 0]
        ),
        ValueError,
        "k",
        match="k must hold unit axes",
    ),
    row(
        "subproblem6 d shape",
        lambda: ik.subproblem6(
            np.ones((4, 3)), np.eye(3)[[2, 2, 2, 2]], np.ones((4, 3)), 0.0
        ),
        ValueError,
        "d",
        match=r"d must have shape \(2,\)",
    ),
    # analytic_ik of the 7R iiwa: the joint to fix, then the other options
    *value_rows(
        "{}",
        lambda fixed: ik.analytic_ik(iiwa(), t7(), fixed=fixed),
        "fixed",
        [
            (
                "7R without fixed",
                None,
                ValueError,
                "fixed must name one joint of a 7-joint chain",
            ),
            (
                "fixed not a dict",
                [2, 0.0],
                TypeError,
                "fixed must be a dict of one entry",
            ),
            (
                "fixed joint out of range",
                {9: 0.0},
                ValueError,
                "fixed must name a joint index 0 ... 6, got 9",
            ),
            ("fixed value text", {2: "zero"}, TypeError, None),
            (
                "fixed value an array",
                {0: [1, 2]},
                ValueError,
                r"fixed must map the joint index to one angle .* shape \(2,\)",
            ),
        ],
    ),
    *keyword_rows(
        "7R {}",
        lambda **kw: ik.analytic_ik(iiwa(), t7(), fixed={2: 0.0}, **kw),
        [
            (
                "near wrong length",
                "near",
                np.zeros(6),
                ValueError,
                "near must be a joint vector of 7 entries",
            ),
            ("within_limits not bool", "within_limits", "no", TypeError, None),
        ],
    ),
    row(
        "fixed on a 6R",
        lambda: ik.analytic_ik(puma(), puma().fk(np.zeros(6)), fixed={2: 0.0}),
        ValueError,
        "fixed",
        match="fixed is for a chain of 7 joints, got 6",
    ),
    row(
        "classify 3 joints",
        lambda: decomposed.classify(planar(1.0, 1.0, 1.0)),
        ValueError,
        "chain",
        match="chain must have 6 joints for the closed form, got 3",
    ),
    row(
        "classify not a chain",
        lambda: decomposed.classify("puma"),
        TypeError,
        "chain",
        match="chain must be a screwkit Chain",
    ),
    row(
        "DecomposedArm of a general 6R",
        lambda: decomposed.DecomposedArm.from_chain(puma_offset_wrist()),
        ValueError,
        "chain",
        match="chain must have three consecutive axes meeting",
    ),
    row(
        "DecomposedArm.solve T not rigid",
        lambda: shoulder_arm().solve(np.diag([1.0, 2.0, 1.0, 1.0])),
        ValueError,
        "T",
        match=r"T must .*rotation",
    ),
    row(
        "DecomposedArm.solve T shape",
        lambda: shoulder_arm().solve(np.eye(3)),
        ValueError,
        "T",
    ),
    row(
        "configuration of a decomposed arm",
        lambda: ik.configuration(
            sk.Chain.from_screws(sk.robots.iiwa14().screw_axes()[1:], np.eye(4)),
            np.zeros(6),
        ),
        ValueError,
        "chain",
        match="chain must be an arm of the STRUCTURES",
    ),
    row(
        "7R T not rigid",
        lambda: ik.analytic_ik(iiwa(), np.diag([1.0, 2.0, 1.0, 1.0]), fixed={2: 0.0}),
        ValueError,
        "T",
    ),
    row(
        "analytic_ik T 10^7 poses broadcast",
        lambda: ik.analytic_ik(shoulder_chain(), np.broadcast_to(t7(), (10**7, 4, 4))),
        ValueError,
        "T",
        match=r"T must be a batch of at most 100,000 poses .* got 10,000,000",
    ),
    row(
        "analytic_ik_all T 10^8 poses broadcast",
        lambda: ik.analytic_ik_all(
            shoulder_chain(), np.broadcast_to(t7(), (10**8, 4, 4))
        ),
        ValueError,
        "T",
        match=r"T must be a batch of at most 1,000,000 poses .* got 100,000,000",
    ),
]
