"""Bad input to screws, screw systems, mobility and the limb builders: rows in the
format of rows.py (the phrase each message must contain is kept as ``match``)."""

import functools

import numpy as np
import sympy as sp
from rows import row

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

SCREW = [
    row(
        "from_axis-1",
        lambda: Twist.from_axis(O, O, 0),
        ValueError,
        "s",
        match="s must be a non-zero direction",
    ),
    row(
        "from_axis-2",
        lambda: Twist.from_axis([0, 0], O, 0),
        ValueError,
        "s",
        match=r"s must have shape",
    ),
    row(
        "from_axis-3",
        lambda: Twist.from_axis(Z, [0, 0], 0),
        ValueError,
        "r",
        match=r"r must have shape",
    ),
    row(
        "from_axis-4",
        lambda: Twist.from_axis(Z, O, "x"),
        TypeError,
        "h",
        match="h must be a pitch",
    ),
    row(
        "from_axis-5",
        lambda: Twist.from_axis(Z, O, None),
        TypeError,
        "h",
        match="h must be a pitch",
    ),
    row(
        "from_axis-6",
        lambda: Twist.from_axis(Z, O, sp.nan),
        ValueError,
        "h",
        match="h must be finite",
    ),
    row(
        "from_axis-7",
        lambda: Twist.from_axis(["s", 0, 1], O, 0),
        TypeError,
        "s",
        match="s must hold numbers",
    ),
    row(
        "from_axis-8",
        lambda: Twist.from_axis([0, 0, sp.nan], O, 0),
        ValueError,
        "s",
        match="s must be finite",
    ),
    row(
        "from_axis-9",
        lambda: Twist.from_axis(Z, [np.inf, 0, 0], 0),
        ValueError,
        "r",
        match="r must be finite",
    ),
    row(
        "Twist-1",
        lambda: Twist([1, 2, 3]),
        ValueError,
        "vector",
        match="vector must have shape",
    ),
    row(
        "Wrench-1",
        lambda: Wrench([0, 0, 0, 0, 0, "m"]),
        TypeError,
        "vector",
        match="vector must hold numbers",
    ),
    row(
        "add-1",
        lambda: Twist.from_axis(Z, O, 0) + Wrench.from_axis(Z, O, 0),
        TypeError,
        "add",
        match="cannot add a twist and a wrench",
    ),
    row(
        "sub-1",
        lambda: Wrench.from_axis(Z, O, 0) - Twist.from_axis(Z, O, 0),
        TypeError,
        "subtract",
        match="cannot subtract a wrench",
    ),
]

SYSTEM = [
    row(
        "certificate-timeout-str",
        lambda: ScrewSystem([[1, 0, 0, 0, 0, 0]]).certificate(timeout="1"),
        TypeError,
        "timeout",
    ),
    row(
        "certificate-timeout-negative",
        lambda: ScrewSystem([[1, 0, 0, 0, 0, 0]]).certificate(timeout=-1),
        ValueError,
        "timeout",
    ),
    row(
        "ScrewSystem-1",
        lambda: ScrewSystem("twists"),
        TypeError,
        "screws",
        match="screws must be a list",
    ),
    row(
        "ScrewSystem-2",
        lambda: ScrewSystem(Twist.from_axis(Z, O, 0)),
        TypeError,
        "screws",
        match="screws must be a list",
    ),
    row(
        "ScrewSystem-3",
        lambda: ScrewSystem([Twist.from_axis(Z, O, 0), Wrench.from_axis(Z, O, 0)]),
        TypeError,
        "one",
        match="one kind of screw",
    ),
    row(
        "ScrewSystem-4",
        lambda: ScrewSystem([(O, O, 0)]),
        ValueError,
        "s",
        match="screw 0: s must be a non-zero direction",
    ),
    row(
        "ScrewSystem-5",
        lambda: ScrewSystem([REVOLUTE, (Z, O, "p")]),
        TypeError,
        "h",
        match="screw 1: h must be a pitch",
    ),
    row(
        "ScrewSystem-6",
        lambda: ScrewSystem([[1, 2, 3, 4]]),
        ValueError,
        "vector",
        match="screw 0: vector must have shape",
    ),
    row(
        "ScrewSystem-7",
        lambda: ScrewSystem([REVOLUTE], kind=str),
        TypeError,
        "kind",
        match="kind must be Twist, Wrench or Screw",
    ),
    *(
        row(
            f"ScrewSystem-{n}",
            lambda tol=tol: ScrewSystem([REVOLUTE], tol=tol),
            error,
            "tol",
            match=match,
        )
        for n, tol, error, match in [
            (8, 0, ValueError, "tol must be a positive number below 1"),
            (9, 2.0, ValueError, "tol must be a positive number below 1"),
            (10, "small", TypeError, "tol must be a positive number"),
        ]
    ),
    row(
        "ScrewSystem-11",
        lambda: ScrewSystem([(Z, [0.5, sp.Symbol("a"), 0], 0)]),
        ValueError,
        "screws",
        match=r"screws mix floats with the symbols \['a'\]",
    ),
    row(
        "union-1",
        lambda: ScrewSystem([REVOLUTE]).union([REVOLUTE]),
        TypeError,
        "other",
        match=r"other must be a ScrewSystem \(the union is of two systems\)",
    ),
    row(
        "union-2",
        lambda: ScrewSystem([REVOLUTE]).union(ScrewSystem([REVOLUTE], kind=Wrench)),
        TypeError,
        "union",
        match="cannot take the union of a twist system and a wrench system",
    ),
    row(
        "intersection-1",
        lambda: ScrewSystem([REVOLUTE]).intersection(None),
        TypeError,
        "other",
        match=r"other must be a ScrewSystem \(the intersection is of two systems\)",
    ),
]

#: Bad values of mobility's ``at`` for planar_limbs(): (row number, at, error, match).
BAD_AT = [
    (13, [(theta, 0)], TypeError, "at must be a dict"),
    (14, {"theta_11": 0}, TypeError, "at must be a dict"),
    (15, {sp.Symbol("phi"): 0}, ValueError, r"at gives values for \['phi'\]"),
    (16, {sp.Symbol("theta_11", real=True): 0}, ValueError, "at gives values for"),
    *(
        (n, {theta: v}, ValueError, r"at\[theta_11\] must be finite")
        for n, v in [(17, float("nan")), (18, np.inf), (19, sp.nan), (20, sp.oo)]
    ),
    *(
        (n, {theta: v}, TypeError, r"at\[theta_11\] must be a number")
        for n, v in [(21, "0.3"), (22, None), (23, True), (24, [0.1, 0.2])]
    ),
]

MOBILITY = [
    row(
        "mobility-1",
        lambda: sk.mobility([]),
        ValueError,
        "limbs",
        match="limbs must be a non-empty list",
    ),
    row(
        "mobility-2",
        lambda: sk.mobility("limbs"),
        ValueError,
        "limbs",
        match="limbs must be a non-empty list",
    ),
    row(
        "mobility-3",
        lambda: sk.mobility([[]]),
        ValueError,
        "limb",
        match="limb 0 must be a non-empty list",
    ),
    row(
        "mobility-4",
        lambda: sk.mobility([[REVOLUTE], 5]),
        ValueError,
        "limb",
        match="limb 1 must be a non-empty list",
    ),
    row(
        "mobility-5",
        lambda: sk.mobility([[(Z, O)]]),
        TypeError,
        "limb",
        match=r"limb 0, joint 0 must be an \(s, r, h\) triple",
    ),
    row(
        "mobility-6",
        lambda: sk.mobility([[REVOLUTE, "R"]]),
        TypeError,
        "limb",
        match=r"limb 0, joint 1 must be an \(s, r, h\) triple",
    ),
    row(
        "mobility-7",
        lambda: sk.mobility([[(O, O, 0)]]),
        ValueError,
        "s",
        match="limb 0, joint 0: s must be a non-zero direction",
    ),
    row(
        "mobility-8",
        lambda: sk.mobility([[(Z, O, "p")]]),
        TypeError,
        "h",
        match="limb 0, joint 0: h must be a pitch",
    ),
    row(
        "mobility-9",
        lambda: sk.mobility([[(Z, [0, 0, sp.nan], 0)]]),
        ValueError,
        "r",
        match="limb 0, joint 0: r must be finite",
    ),
    row(
        "mobility-10",
        lambda: sk.mobility([[Wrench.from_axis(Z, O, 0)]]),
        TypeError,
        "limb",
        match="limb 0, joint 0 is a wrench",
    ),
    row(
        "mobility-11",
        lambda: sk.mobility([[(Z, [0.5, sp.Symbol("a"), 0], 0)]]),
        ValueError,
        "limbs",
        match=r"limbs mix floats with the symbols \['a'\]",
    ),
    row(
        "mobility-12",
        lambda: sk.mobility([[REVOLUTE]], tol=-1e-9),
        ValueError,
        "tol",
        match="tol must be a positive number below 1",
    ),
    *(
        row(
            f"mobility-{n}",
            lambda at=at: sk.mobility(planar_limbs(), at=at),
            error,
            "at",
            match=match,
        )
        for n, at, error, match in BAD_AT
    ),
    row(
        "grubler_kutzbach-1",
        lambda: sk.grubler_kutzbach(3.5, 2, 2),
        TypeError,
        "links",
        match="links must be a non-negative integer",
    ),
    row(
        "grubler_kutzbach-2",
        lambda: sk.grubler_kutzbach(3, -1, 2),
        TypeError,
        "joints",
        match="joints must be a non-negative integer",
    ),
]

JOINT = [
    row(
        "revolute-1",
        lambda: limbs.revolute(O, O),
        ValueError,
        "s",
        match="s must be a non-zero direction",
    ),
    row(
        "revolute-2",
        lambda: limbs.revolute(Z, [0, 0]),
        ValueError,
        "r",
        match="r must have shape",
    ),
    row(
        "revolute-3",
        lambda: limbs.revolute("z", O),
        TypeError,
        "s",
        match="s must be a matrix of shape",
    ),
    row(
        "prismatic-1",
        lambda: limbs.prismatic(O),
        ValueError,
        "s",
        match="s must be a non-zero direction",
    ),
    row(
        "prismatic-2",
        lambda: limbs.prismatic([0, np.nan, 1]),
        ValueError,
        "s",
        match="s must be finite",
    ),
    row(
        "helical-1",
        lambda: limbs.helical(Z, O, "h"),
        TypeError,
        "h",
        match="h must be a finite pitch",
    ),
    row(
        "helical-2",
        lambda: limbs.helical(Z, O, sp.oo),
        TypeError,
        "h",
        match="h must be a finite pitch",
    ),
    row(
        "helical-3",
        lambda: limbs.helical(Z, O, sp.nan),
        ValueError,
        "h",
        match="h must be finite",
    ),
    row(
        "cylindrical-1",
        lambda: limbs.cylindrical(O, O),
        ValueError,
        "s",
        match="s must be a non-zero direction",
    ),
    row(
        "universal-1",
        lambda: limbs.universal(Z, Z, O),
        ValueError,
        "s1",
        match="s1 and s2 of a universal joint must not be parallel",
    ),
    row(
        "universal-2",
        lambda: limbs.universal(Z, [0, 0, -2], O),
        ValueError,
        "s1",
        match="s1 and s2 of a universal joint must not be parallel",
    ),
    row(
        "universal-3",
        lambda: limbs.universal(
            [sp.cos(theta), sp.sin(theta), 0],
            [2 * sp.cos(theta), 2 * sp.sin(theta), 0],
            O,
        ),
        ValueError,
        "must",
        match="must not be parallel",
    ),
    row(
        "spherical-1",
        lambda: limbs.spherical(O, axes=(X, Y)),
        ValueError,
        "axes",
        match="axes of a spherical joint must be three",
    ),
    row(
        "spherical-2",
        lambda: limbs.spherical(O, axes=(X, Y, Z, X)),
        ValueError,
        "axes",
        match="axes of a spherical joint must be three",
    ),
    row(
        "spherical-3",
        lambda: limbs.spherical(O, axes=(X, Y, [1, 1, 0])),
        ValueError,
        "axes",
        match="axes of a spherical joint must be independent",
    ),
    row(
        "spherical-4",
        lambda: limbs.spherical(O, axes=(X, Y, O)),
        ValueError,
        "axes",
        match=r"axes\[2\] must be a non-zero direction",
    ),
    row(
        "spherical-5",
        lambda: limbs.spherical(O, axes="xyz"),
        ValueError,
        "axes",
        match="axes of a spherical joint must be three",
    ),
    row(
        "parallelogram-1",
        lambda: limbs.parallelogram(Z, O, X, [0, 1, 0], [1, 2, 0]),
        ValueError,
        "corners",
        match="corners of a parallelogram",
    ),
    row(
        "parallelogram-2",
        lambda: limbs.parallelogram(Z, O, O, Y, Y),
        ValueError,
        "a1",
        match="a1 and a2 of a parallelogram must be different",
    ),
    row(
        "parallelogram-3",
        lambda: limbs.parallelogram(Z, O, X, O, X),
        ValueError,
        "a1",
        match="a1 and b1 of a parallelogram must be different",
    ),
    row(
        "parallelogram-4",
        lambda: limbs.parallelogram(Z, O, X, [0, 1], [1, 1, 0]),
        ValueError,
        "b1",
        match="b1 must have shape",
    ),
    row(
        "rotate_limb-1",
        lambda: limbs.rotate_limb(limbs.revolute(Z, X), 2 * sp.eye(3)),
        ValueError,
        "R",
        match="R must be a rotation matrix",
    ),
    row(
        "rotate_limb-2",
        lambda: limbs.rotate_limb(limbs.revolute(Z, X), np.diag([1.0, 1.0, -1.0])),
        ValueError,
        "R",
        match="R must be a rotation matrix with determinant",
    ),
    row(
        "rotate_limb-3",
        lambda: limbs.rotate_limb(
            limbs.revolute(Z, X), sp.diag(1, -1, -1) * sp.diag(1, 1, -1)
        ),
        ValueError,
        "R",
        match="R must be a rotation matrix with determinant",
    ),
    row(
        "rotate_limb-4",
        lambda: limbs.rotate_limb(limbs.revolute(Z, X), np.eye(2)),
        ValueError,
        "R",
        match="R must have shape",
    ),
    row(
        "translate_limb-1",
        lambda: limbs.translate_limb(limbs.revolute(Z, X), [1, 2]),
        ValueError,
        "p",
        match="p must have shape",
    ),
]


ROWS = SCREW + SYSTEM + MOBILITY + JOINT
