"""Bad input to the inverse kinematics: one row per case, the error type and the
argument the message names."""

import functools

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit import ik


@functools.cache
def puma():
    return sk.robots.puma560()


@functools.cache
def t0():
    return puma().fk(np.zeros(6))


SCALED = np.diag([1.0, 2.0, 1.0, 1.0])
Z_AXIS = [0, 0, 1, 0, 0, 0]


@functools.cache
def planar_3r():
    return sk.robots.planar([1.0, 1.0, 1.0])


# a 6R chain whose wrist axes do not meet: the PUMA with a4 = 0.1
@functools.cache
def skew_wrist():
    return sk.Chain(
        list(puma().links[:3])
        + [sk.Link.revolute(d=0.4318, a=0.1, alpha=sp.pi / 2)]
        + list(puma().links[4:])
    )


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


CASES = [
    # (id, call, error type, pattern the message must contain)
    ("T not rigid", lambda: ik.puma560_ik(SCALED), ValueError, r"T must .*rotation"),
    (
        "T with NaN",
        lambda: ik.puma560_ik(np.full((4, 4), np.nan)),
        ValueError,
        "T must be finite",
    ),
    ("T a string", lambda: ik.puma560_ik("pose"), TypeError, "T must be"),
    (
        "T a batch",
        lambda: ik.puma560_ik(np.stack([t0(), t0()])),
        ValueError,
        r"T must be one pose of shape \(4, 4\)",
    ),
    (
        "T wrong shape",
        lambda: ik.analytic_ik_all(puma(), np.eye(3)),
        ValueError,
        r"T must have shape \(4 x 4\)",
    ),
    (
        "T wrong batch shape",
        lambda: ik.analytic_ik_all(puma(), np.zeros((2, 3, 4, 4))),
        ValueError,
        r"T must have shape \(4, 4\) or \(N, 4, 4\)",
    ),
    (
        "last row",
        lambda: ik.analytic_ik(puma(), np.vstack([t0()[:3], [0, 0, 1, 1]])),
        ValueError,
        r"T must have last row",
    ),
    (
        "label unknown",
        lambda: ik.puma560_ik(t0()).by_config("xyz"),
        ValueError,
        "config must be one of lun",
    ),
    (
        "near wrong length",
        lambda: ik.puma560_ik(t0(), near=[0, 0]),
        ValueError,
        "near must be a joint vector of 6 entries",
    ),
    (
        "within_limits not bool",
        lambda: ik.puma560_ik(t0(), within_limits="yes"),
        TypeError,
        "within_limits must be True or False",
    ),
    (
        "robot not a chain",
        lambda: ik.puma560_ik(t0(), robot="puma"),
        TypeError,
        r"robot must be a screwkit Chain .*got 'puma'",
    ),
    (
        "chain of 3 joints",
        lambda: ik.analytic_ik(planar_3r(), t0()),
        ValueError,
        "chain must have 6 joints for the closed form, got 3",
    ),
    (
        "prismatic joint",
        lambda: ik.analytic_ik(prismatic(), t0()),
        ValueError,
        "chain must have revolute joints only",
    ),
    (
        "wrist axes miss",
        lambda: ik.analytic_ik(skew_wrist(), t0()),
        ValueError,
        "chain must have a spherical wrist: the axes of joints 4, 5 and 6 must meet",
    ),
    (
        "joints 2, 3 not parallel",
        lambda: ik.analytic_ik(twisted(), t0()),
        ValueError,
        "chain must have parallel axes for joints 2 and 3",
    ),
    (
        "config q short",
        lambda: ik.puma560_config(np.zeros(5)),
        ValueError,
        "q must have 6 entries",
    ),
    (
        "config q batch",
        lambda: ik.puma560_config(np.zeros((2, 6))),
        ValueError,
        r"q must be one configuration of shape \(6,\)",
    ),
    (
        "numeric q0 short",
        lambda: ik.numeric_ik(puma(), t0(), np.zeros(4)),
        ValueError,
        "q0 must have 6 entries",
    ),
    (
        "numeric chain",
        lambda: ik.numeric_ik("puma", t0(), np.zeros(6)),
        TypeError,
        "chain must be a screwkit Chain",
    ),
    (
        "numeric T batch",
        lambda: ik.numeric_ik(puma(), np.stack([t0(), t0()]), np.zeros(6)),
        ValueError,
        "T must be one pose",
    ),
    (
        "numeric frame",
        lambda: ik.numeric_ik(puma(), t0(), np.zeros(6), frame="world"),
        ValueError,
        "frame must be 'body' or 'space'",
    ),
    (
        "numeric tol",
        lambda: ik.numeric_ik(puma(), t0(), np.zeros(6), tol=-1),
        ValueError,
        "tol must be a positive number",
    ),
    (
        "numeric iterations",
        lambda: ik.numeric_ik(puma(), t0(), np.zeros(6), max_iterations=0),
        ValueError,
        "max_iterations must be a positive integer",
    ),
    (
        "numeric damping",
        lambda: ik.numeric_ik(puma(), t0(), np.zeros(6), damping=-0.1),
        ValueError,
        "damping must be None or a number >= 0",
    ),
    (
        "subproblem twist shape",
        lambda: ik.subproblem1([0, 0, 1], [1, 0, 0], [0, 1, 0]),
        ValueError,
        r"twist must be a twist of shape \(6,\)",
    ),
    (
        "subproblem twist not unit",
        lambda: ik.subproblem1([0, 0, 2, 0, 0, 0], [1, 0, 0], [0, 1, 0]),
        ValueError,
        "twist must have a unit angular part",
    ),
    (
        "subproblem helical",
        lambda: ik.subproblem1([0, 0, 1, 0, 0, 0.1], [1, 0, 0], [0, 1, 0]),
        ValueError,
        "twist must have pitch 0",
    ),
    (
        "subproblem point",
        lambda: ik.subproblem1(Z_AXIS, [1, 0], [0, 1, 0]),
        ValueError,
        r"p must be a point of shape \(3,\)",
    ),
    (
        "subproblem point text",
        lambda: ik.subproblem1(Z_AXIS, "p", [0, 1, 0]),
        TypeError,
        "p must be a number or an array",
    ),
    (
        "subproblem3 delta < 0",
        lambda: ik.subproblem3(Z_AXIS, [1, 0, 0], [2, 0, 0], -1.0),
        ValueError,
        "delta must be a distance >= 0",
    ),
    (
        "subproblem3 delta array",
        lambda: ik.subproblem3(Z_AXIS, [1, 0, 0], [2, 0, 0], [1, 2]),
        TypeError,
        "delta must be one distance",
    ),
    (
        "subproblem2 parallel",
        lambda: ik.subproblem2(Z_AXIS, Z_AXIS, [1, 0, 0], [0, 1, 0]),
        ValueError,
        "twist1 and twist2 must have axes that meet",
    ),
    (
        "subproblem4 normal",
        lambda: ik.subproblem4(Z_AXIS, [1, 0, 0], [0, 2, 0], 0.5),
        ValueError,
        "normal must be a unit direction",
    ),
    (
        "prismatic direction",
        lambda: ik.subproblem1_prismatic([1, 1, 0], [0, 0, 0], [1, 1, 0]),
        ValueError,
        "s must be a unit direction",
    ),
]


@pytest.mark.parametrize(
    "call, error, pattern", [c[1:] for c in CASES], ids=[c[0] for c in CASES]
)
def test_bad_input(call, error, pattern):
    with pytest.raises(error, match=pattern):
        call()
