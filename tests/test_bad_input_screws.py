"""Bad input to screws, screw systems, mobility and joints: each case raises the
documented error, and its message names the argument at fault."""

import functools

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit import limbs
from screwkit.screws import Twist, Wrench
from screwkit.systems import ScrewSystem

X, Y, Z, O = [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]
theta = sp.Symbol("theta_11")


@functools.cache
def planar_limbs():
    return sk.robots.planar_3rrr()


REVOLUTE = (Z, O, 0)

SCREW_CASES = [  # (call, error, a phrase the message must contain)
    (lambda: Twist.from_axis(O, O, 0), ValueError, "s must be a non-zero direction"),
    (lambda: Twist.from_axis([0, 0], O, 0), ValueError, r"s must have shape"),
    (lambda: Twist.from_axis(Z, [0, 0], 0), ValueError, r"r must have shape"),
    (lambda: Twist.from_axis(Z, O, "x"), TypeError, "h must be a pitch"),
    (lambda: Twist.from_axis(Z, O, None), TypeError, "h must be a pitch"),
    (lambda: Twist.from_axis(Z, O, sp.nan), ValueError, "h must be finite"),
    (lambda: Twist.from_axis(["s", 0, 1], O, 0), TypeError, "s must hold numbers"),
    (lambda: Twist.from_axis([0, 0, sp.nan], O, 0), ValueError, "s must be finite"),
    (lambda: Twist.from_axis(Z, [np.inf, 0, 0], 0), ValueError, "r must be finite"),
    (lambda: Twist([1, 2, 3]), ValueError, "vector must have shape"),
    (lambda: Wrench([0, 0, 0, 0, 0, "m"]), TypeError, "vector must hold numbers"),
    (
        lambda: Twist.from_axis(Z, O, 0) + Wrench.from_axis(Z, O, 0),
        TypeError,
        "cannot add a twist and a wrench",
    ),
    (
        lambda: Wrench.from_axis(Z, O, 0) - Twist.from_axis(Z, O, 0),
        TypeError,
        "cannot subtract a wrench",
    ),
]

SYSTEM_CASES = [
    (lambda: ScrewSystem("twists"), TypeError, "screws must be a list"),
    (lambda: ScrewSystem(Twist.from_axis(Z, O, 0)), TypeError, "screws must be a list"),
    (
        lambda: ScrewSystem([Twist.from_axis(Z, O, 0), Wrench.from_axis(Z, O, 0)]),
        TypeError,
        "one kind of screw",
    ),
    (
        lambda: ScrewSystem([(O, O, 0)]),
        ValueError,
        "screw 0: s must be a non-zero direction",
    ),
    (
        lambda: ScrewSystem([REVOLUTE, (Z, O, "p")]),
        TypeError,
        "screw 1: h must be a pitch",
    ),
    (
        lambda: ScrewSystem([[1, 2, 3, 4]]),
        ValueError,
        "screw 0: vector must have shape",
    ),
    (
        lambda: ScrewSystem([REVOLUTE], kind=str),
        TypeError,
        "kind must be Twist, Wrench or Screw",
    ),
    (
        lambda: ScrewSystem([REVOLUTE], tol=0),
        ValueError,
        "tol must be a positive number below 1",
    ),
    (
        lambda: ScrewSystem([REVOLUTE], tol=2.0),
        ValueError,
        "tol must be a positive number below 1",
    ),
    (
        lambda: ScrewSystem([REVOLUTE], tol="small"),
        TypeError,
        "tol must be a positive number",
    ),
    (
        lambda: ScrewSystem([(Z, [0.5, sp.Symbol("a"), 0], 0)]),
        ValueError,
        r"screws mix floats with the symbols \['a'\]",
    ),
    (
        lambda: ScrewSystem([REVOLUTE]).union([REVOLUTE]),
        TypeError,
        r"other must be a ScrewSystem \(the union is of two systems\)",
    ),
    (
        lambda: ScrewSystem([REVOLUTE]).union(ScrewSystem([REVOLUTE], kind=Wrench)),
        TypeError,
        "cannot take the union of a twist system and a wrench system",
    ),
    (
        lambda: ScrewSystem([REVOLUTE]).intersection(None),
        TypeError,
        r"other must be a ScrewSystem \(the intersection is of two systems\)",
    ),
]

MOBILITY_CASES = [
    (lambda: sk.mobility([]), ValueError, "limbs must be a non-empty list"),
    (lambda: sk.mobility("limbs"), ValueError, "limbs must be a non-empty list"),
    (lambda: sk.mobility([[]]), ValueError, "limb 0 must be a non-empty list"),
    (
        lambda: sk.mobility([[REVOLUTE], 5]),
        ValueError,
        "limb 1 must be a non-empty list",
    ),
    (
        lambda: sk.mobility([[(Z, O)]]),
        TypeError,
        r"limb 0, joint 0 must be an \(s, r, h\) triple",
    ),
    (
        lambda: sk.mobility([[REVOLUTE, "R"]]),
        TypeError,
        r"limb 0, joint 1 must be an \(s, r, h\) triple",
    ),
    (
        lambda: sk.mobility([[(O, O, 0)]]),
        ValueError,
        "limb 0, joint 0: s must be a non-zero direction",
    ),
    (
        lambda: sk.mobility([[(Z, O, "p")]]),
        TypeError,
        "limb 0, joint 0: h must be a pitch",
    ),
    (
        lambda: sk.mobility([[(Z, [0, 0, sp.nan], 0)]]),
        ValueError,
        "limb 0, joint 0: r must be finite",
    ),
    (
        lambda: sk.mobility([[Wrench.from_axis(Z, O, 0)]]),
        TypeError,
        "limb 0, joint 0 is a wrench",
    ),
    (
        lambda: sk.mobility([[(Z, [0.5, sp.Symbol("a"), 0], 0)]]),
        ValueError,
        r"limbs mix floats with the symbols \['a'\]",
    ),
    (
        lambda: sk.mobility([[REVOLUTE]], tol=-1e-9),
        ValueError,
        "tol must be a positive number below 1",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at=[(theta, 0)]),
        TypeError,
        "at must be a dict",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={"theta_11": 0}),
        TypeError,
        "at must be a dict",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={sp.Symbol("phi"): 0}),
        ValueError,
        r"at gives values for \['phi'\]",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={sp.Symbol("theta_11", real=True): 0}),
        ValueError,
        "at gives values for",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: float("nan")}),
        ValueError,
        r"at\[theta_11\] must be finite",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: np.inf}),
        ValueError,
        r"at\[theta_11\] must be finite",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: sp.nan}),
        ValueError,
        r"at\[theta_11\] must be finite",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: sp.oo}),
        ValueError,
        r"at\[theta_11\] must be finite",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: "0.3"}),
        TypeError,
        r"at\[theta_11\] must be a number",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: None}),
        TypeError,
        r"at\[theta_11\] must be a number",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: True}),
        TypeError,
        r"at\[theta_11\] must be a number",
    ),
    (
        lambda: sk.mobility(planar_limbs(), at={theta: [0.1, 0.2]}),
        TypeError,
        r"at\[theta_11\] must be a number",
    ),
    (
        lambda: sk.grubler_kutzbach(3.5, 2, 2),
        TypeError,
        "links must be a non-negative integer",
    ),
    (
        lambda: sk.grubler_kutzbach(3, -1, 2),
        TypeError,
        "joints must be a non-negative integer",
    ),
]

JOINT_CASES = [
    (lambda: limbs.revolute(O, O), ValueError, "s must be a non-zero direction"),
    (lambda: limbs.revolute(Z, [0, 0]), ValueError, "r must have shape"),
    (lambda: limbs.revolute("z", O), TypeError, "s must be a matrix of shape"),
    (lambda: limbs.prismatic(O), ValueError, "s must be a non-zero direction"),
    (lambda: limbs.prismatic([0, np.nan, 1]), ValueError, "s must be finite"),
    (lambda: limbs.helical(Z, O, "h"), TypeError, "h must be a finite pitch"),
    (lambda: limbs.helical(Z, O, sp.oo), TypeError, "h must be a finite pitch"),
    (lambda: limbs.helical(Z, O, sp.nan), ValueError, "h must be finite"),
    (lambda: limbs.cylindrical(O, O), ValueError, "s must be a non-zero direction"),
    (
        lambda: limbs.universal(Z, Z, O),
        ValueError,
        "s1 and s2 of a universal joint must not be parallel",
    ),
    (
        lambda: limbs.universal(Z, [0, 0, -2], O),
        ValueError,
        "s1 and s2 of a universal joint must not be parallel",
    ),
    (
        lambda: limbs.universal(
            [sp.cos(theta), sp.sin(theta), 0], [-sp.sin(theta), sp.cos(theta), 0], O
        ),
        None,
        None,
    ),  # a valid U, perpendicular for every theta (a control row: no error)
    (
        lambda: limbs.universal(
            [sp.cos(theta), sp.sin(theta), 0],
            [2 * sp.cos(theta), 2 * sp.sin(theta), 0],
            O,
        ),
        ValueError,
        "must not be parallel",
    ),
    (
        lambda: limbs.spherical(O, axes=(X, Y)),
        ValueError,
        "axes of a spherical joint must be three",
    ),
    (
        lambda: limbs.spherical(O, axes=(X, Y, Z, X)),
        ValueError,
        "axes of a spherical joint must be three",
    ),
    (
        lambda: limbs.spherical(O, axes=(X, Y, [1, 1, 0])),
        ValueError,
        "axes of a spherical joint must be independent",
    ),
    (
        lambda: limbs.spherical(O, axes=(X, Y, O)),
        ValueError,
        r"axes\[2\] must be a non-zero direction",
    ),
    (
        lambda: limbs.spherical(O, axes="xyz"),
        ValueError,
        "axes of a spherical joint must be three",
    ),
    (
        lambda: limbs.parallelogram(Z, O, X, [0, 1, 0], [1, 2, 0]),
        ValueError,
        "corners of a parallelogram",
    ),
    (
        lambda: limbs.parallelogram(Z, O, O, Y, Y),
        ValueError,
        "a1 and a2 of a parallelogram must be different",
    ),
    (
        lambda: limbs.parallelogram(Z, O, X, O, X),
        ValueError,
        "a1 and b1 of a parallelogram must be different",
    ),
    (
        lambda: limbs.parallelogram(Z, O, X, [0, 1], [1, 1, 0]),
        ValueError,
        "b1 must have shape",
    ),
    (
        lambda: limbs.rotate_limb(limbs.revolute(Z, X), 2 * sp.eye(3)),
        ValueError,
        "R must be a rotation matrix",
    ),
    (
        lambda: limbs.rotate_limb(limbs.revolute(Z, X), np.diag([1.0, 1.0, -1.0])),
        ValueError,
        "R must be a rotation matrix with determinant",
    ),
    (
        lambda: limbs.rotate_limb(
            limbs.revolute(Z, X), sp.diag(1, -1, -1) * sp.diag(1, 1, -1)
        ),
        ValueError,
        "R must be a rotation matrix with determinant",
    ),
    (
        lambda: limbs.rotate_limb(limbs.revolute(Z, X), np.eye(2)),
        ValueError,
        "R must have shape",
    ),
    (
        lambda: limbs.translate_limb(limbs.revolute(Z, X), [1, 2]),
        ValueError,
        "p must have shape",
    ),
]


@pytest.mark.parametrize(
    "call, error, phrase", SCREW_CASES + SYSTEM_CASES + MOBILITY_CASES + JOINT_CASES
)
def test_bad_input_is_refused_with_a_message_naming_the_argument(call, error, phrase):
    if error is None:
        call()
        return
    with pytest.raises(error, match=phrase):
        call()
