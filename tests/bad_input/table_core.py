"""Bad input to the core modules (transforms, the shared checks, workspace, redundancy,
plotting): rows in the format of rows.py. The valid edge cases and the check that no
function changes its input are in test_valid_input.py, which uses the builders here."""

import functools

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import sympy as sp  # noqa: E402
from builders import planar, puma  # noqa: E402
from rows import keyword_rows, row, value_rows  # noqa: E402

import screwkit as sk  # noqa: E402
from screwkit import plotting as pl  # noqa: E402
from screwkit import redundancy as rd  # noqa: E402
from screwkit import workspace as ws  # noqa: E402

theta = sp.Symbol("theta", real=True)


def arm():
    return planar(0.4, 0.3, 0.2)


def arm2():
    return planar(1.0, 0.5)


@functools.cache
def limited():
    return sk.robots.planar(
        [0.4, 0.3, 0.2], qlim=np.radians([[-180, 180], [-60, 60], [-60, 60]])
    )


@functools.cache
def path():
    return rd.circle((0.5, 0.1), 0.1, duration=1.0, dt=0.01)


@functools.cache
def q0():
    return rd.start_configuration(arm(), path().position[0], [0.3, 0.6, 0.6])


T_STEPS = np.arange(5) * 0.1
POS = np.zeros((5, 2))


@functools.cache
def sweep():
    return ws.sweep(arm2(), {1: (0.0, 1.0), 2: (0.0, 1.0)}, num=5)


def ax3():
    return pl.axes3d()


def ax2():
    return plt.figure().add_subplot()


EYE = np.eye(4)


@functools.cache
def mechanism():
    """The 3-PRRR's limbs (symbolic), for the mechanism drawing."""
    return sk.robots.pm_3prrr()


def mechanism_symbols():
    """The symbols of mechanism()'s limbs, sorted by name."""
    entries = [x for limb in mechanism() for joint in limb for x in joint]
    found = set().union(*(sp.sympify(x).free_symbols for x in entries))
    return sorted(found, key=str)


def mechanism_values():
    """A value for every symbol of mechanism()."""
    return dict.fromkeys(mechanism_symbols(), 0.1)


def limits_q0():
    """A q0 outside LIMITED's limits (joint 2 at 90 deg) that still starts on the
    path."""
    return rd.start_configuration(limited(), path().position[0], [-1.0, 1.6, 0.2])


TRANSFORMS = [
    row("rotz-str", lambda: sk.rotz("a"), TypeError, "theta"),
    row("rotz-numeric-str", lambda: sk.rotz("0.5"), TypeError, "theta"),
    row("rotz-list-of-numeric-str", lambda: sk.rotz(["0.5"]), TypeError, "theta"),
    row("rotz-bool", lambda: sk.rotz(True), TypeError, "theta"),
    row("rotz-list-of-bool", lambda: sk.rotz([True, 0.1]), TypeError, "theta"),
    row(
        "rotz-bool-array", lambda: sk.rotz(np.array([True, False])), TypeError, "theta"
    ),
    row("rotz-complex", lambda: sk.rotz(1 + 2j), TypeError, "theta"),
    row("rotz-complex-array", lambda: sk.rotz(np.array([1j, 0])), TypeError, "theta"),
    row("rotz-none", lambda: sk.rotz(None), TypeError, "theta"),
    row("rotz-list-of-none", lambda: sk.rotz([None]), TypeError, "theta"),
    row("rotz-nan", lambda: sk.rotz(np.nan), ValueError, "theta"),
    row("rotz-inf-in-batch", lambda: sk.rotz([0.1, np.inf]), ValueError, "theta"),
    row("rotz-sympy-nan", lambda: sk.rotz(sp.nan), ValueError, "theta"),
    row("rotz-sympy-oo", lambda: sk.rotz(sp.oo), ValueError, "theta"),
    row("rotz-sympy-I", lambda: sk.rotz(sp.I), TypeError, "theta"),
    row("rotz-sympy-complex-expr", lambda: sk.rotz(1 + 2 * sp.I), TypeError, "theta"),
    row("rotz-sympy-true", lambda: sk.rotz(sp.true), TypeError, "theta"),
    row("rotz-ragged", lambda: sk.rotz([[0.1], [0.2, 0.3]]), ValueError, "theta"),
    row("rotz-dict", lambda: sk.rotz({"a": 1}), TypeError, "theta"),
    row("rotz-object", lambda: sk.rotz(object()), TypeError, "theta"),
    row("rotz-str-array", lambda: sk.rotz(np.array(["1"])), TypeError, "theta"),
    row("rotz-bytes", lambda: sk.rotz(b"1"), TypeError, "theta"),
    row(
        "rotz-sympy-matrix", lambda: sk.rotz(sp.Matrix([theta, 1])), TypeError, "theta"
    ),
    row("rotz-symbols-list", lambda: sk.rotz([theta, 1]), TypeError, "theta"),
    row("rotx-str", lambda: sk.rotx("x"), TypeError, "theta"),
    row("rotx-nan", lambda: sk.rotx([np.nan]), ValueError, "theta"),
    row("rotx-complex", lambda: sk.rotx(np.complex128(1)), TypeError, "theta"),
    row("roty-none", lambda: sk.roty(None), TypeError, "theta"),
    row("roty-bool-numpy", lambda: sk.roty(np.bool_(True)), TypeError, "theta"),
    row("roty-inf", lambda: sk.roty(-np.inf), ValueError, "theta"),
    row("skew-short", lambda: sk.skew([1, 2]), ValueError, "v"),
    row("skew-str", lambda: sk.skew("abc"), TypeError, "v"),
    row("skew-none", lambda: sk.skew(None), TypeError, "v"),
    row("skew-str-entry", lambda: sk.skew([1, 2, "3"]), TypeError, "v"),
    row("skew-nan", lambda: sk.skew([1, 2, np.nan]), ValueError, "v"),
    row("skew-matrix", lambda: sk.skew(np.zeros((2, 2))), ValueError, "v"),
    row("skew-bools", lambda: sk.skew([True, False, True]), TypeError, "v"),
    row("skew-sympy-short", lambda: sk.skew(sp.Matrix([1, 2])), ValueError, "v"),
    row("skew-sympy-I", lambda: sk.skew([1, 2, sp.I]), TypeError, "v"),
    row("skew-sympy-zoo", lambda: sk.skew([1, 2, sp.zoo]), ValueError, "v"),
    *(
        row(f"rot_axis-{case}", lambda a=a, b=b: sk.rot_axis(a, b), error, name)
        for case, a, b, error, name in [
            ("zero", [0, 0, 0], 1.0, ValueError, "axis"),
            ("tiny", [1e-13, 0, 0], 1.0, ValueError, "axis"),
            ("sympy-zero", sp.Matrix([0, 0, 0]), theta, ValueError, "axis"),
            ("str", "z", 1.0, TypeError, "axis"),
            ("none", None, 1.0, TypeError, "axis"),
            ("short", [1, 0], 1.0, ValueError, "axis"),
            ("batch", np.ones((2, 3)), 1.0, ValueError, "axis"),
            ("nan", [np.nan, 0, 1], 1.0, ValueError, "axis"),
            ("complex", [0, 0, 1j], 1.0, TypeError, "axis"),
            ("theta-str", [0, 0, 1], "x", TypeError, "theta"),
            ("theta-none", [0, 0, 1], None, TypeError, "theta"),
            ("theta-bool", [0, 0, 1], True, TypeError, "theta"),
            ("theta-complex", [0, 0, 1], 1j, TypeError, "theta"),
            ("theta-nan", [0, 0, 1], [0.0, np.nan], ValueError, "theta"),
            (
                "sympy-axis-batch-theta",
                sp.Matrix([0, 0, 1]),
                [0.1, 0.2],
                TypeError,
                "theta",
            ),
            ("sympy-axis-str-theta", sp.Matrix([0, 0, 1]), "t", TypeError, "theta"),
            ("sympy-theta-nan", [0, 0, 1], sp.nan, ValueError, "theta"),
        ]
    ),
    row("transl-none", lambda: sk.transl(None), TypeError, "p"),
    row("transl-two-args", lambda: sk.transl(1, 2), TypeError, "transl"),
    row("transl-four-args", lambda: sk.transl(1, 2, 3, 4), TypeError, "transl"),
    row("transl-no-args", lambda: sk.transl(), TypeError, "transl"),
    row("transl-long", lambda: sk.transl([1, 2, 3, 4]), ValueError, "p"),
    row("transl-str", lambda: sk.transl("abc"), TypeError, "p"),
    row("transl-str-y", lambda: sk.transl(1, "a", 3), TypeError, "y"),
    row("transl-none-z", lambda: sk.transl(1, 2, None), TypeError, "z"),
    row(
        "transl-mismatched-batches",
        lambda: sk.transl([1, 2], [1, 2, 3], 0),
        ValueError,
        "x, y and z",
    ),
    row("transl-inf", lambda: sk.transl([np.inf, 0, 0]), ValueError, "p"),
    row("transl-bool", lambda: sk.transl([True, 0, 0]), TypeError, "p"),
    row("transl-nan-x", lambda: sk.transl(np.nan, 0, 0), ValueError, "x"),
    *value_rows(
        "homogeneous-{}",
        lambda R: sk.homogeneous(R),
        "R",
        [
            ("not-rotation", np.ones((3, 3)), ValueError, None),
            ("reflection", np.diag([1, 1, -1]), ValueError, None),
            ("2x2", np.eye(2), ValueError, None),
            (
                "sympy-not-rotation",
                sp.Matrix([[theta, 0, 0], [0, 1, 0], [0, 0, 1]]),
                ValueError,
                None,
            ),
            ("R-str", "eye", TypeError, None),
            ("R-nan", np.full((3, 3), np.nan), ValueError, None),
            ("R-scaled", 2 * np.eye(3), ValueError, None),
            ("R-complex", np.eye(3) * (1 + 0j), TypeError, None),
        ],
    ),
    row("homogeneous-p-short", lambda: sk.homogeneous(None, [1, 2]), ValueError, "p"),
    row("homogeneous-p-str", lambda: sk.homogeneous(None, "a"), TypeError, "p"),
    row(
        "homogeneous-batch-mismatch",
        lambda: sk.homogeneous(np.stack([np.eye(3)] * 2), np.zeros((3, 3))),
        ValueError,
        "R and p",
    ),
    row("inv-3x3", lambda: sk.inv(np.eye(3)), ValueError, "T"),
    row("inv-nan", lambda: sk.inv(np.full((4, 4), np.nan)), ValueError, "T"),
    row("inv-last-row", lambda: sk.inv(np.diag([1.0, 1, 1, 2])), ValueError, "T"),
    row("inv-not-rigid", lambda: sk.inv(np.diag([2.0, 1, 1, 1])), ValueError, "T"),
    row(
        "inv-batch-zero-rotation",
        lambda: sk.inv(np.zeros((2, 4, 4)) + EYE * [0, 0, 0, 1]),
        ValueError,
        "T",
    ),
    row("inv-none", lambda: sk.inv(None), TypeError, "T"),
    row("inv-str", lambda: sk.inv("T"), TypeError, "T"),
    row("inv-complex", lambda: sk.inv(EYE * (1 + 0j)), TypeError, "T"),
    row("inv-sympy-last-row", lambda: sk.inv(sp.diag(1, 1, 1, theta)), ValueError, "T"),
    row(
        "inv-one-bad-in-batch",
        lambda: sk.inv(np.stack([EYE, np.diag([1.0, 1, 1, 2])])),
        ValueError,
        "T",
    ),
    row(
        "twist_from_axis-h-str",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], "x"),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-h-numeric-str",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], "1.5"),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-h-nan",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], np.nan),
        ValueError,
        "h",
    ),
    row(
        "twist_from_axis-h-bool",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], True),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-h-minus-inf",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], -np.inf),
        ValueError,
        "h",
    ),
    row(
        "twist_from_axis-h-complex",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], 1j),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-h-batch",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], [0.1, 0.2]),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-h-none",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], None),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-h-zoo",
        lambda: sk.twist_from_axis([0, 0, 1], [theta, 0, 0], sp.zoo),
        ValueError,
        "h",
    ),
    row(
        "twist_from_axis-h-sympy-I",
        lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], sp.I),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-h-symbol-str",
        lambda: sk.twist_from_axis([0, 0, 1], [theta, 0, 0], "h"),
        TypeError,
        "h",
    ),
    row(
        "twist_from_axis-s-zero",
        lambda: sk.twist_from_axis([0, 0, 0], [0, 0, 0], 0),
        ValueError,
        "s",
    ),
    row(
        "twist_from_axis-s-none",
        lambda: sk.twist_from_axis(None, [0, 0, 0], 0),
        TypeError,
        "s",
    ),
    row(
        "twist_from_axis-s-batch",
        lambda: sk.twist_from_axis(np.ones((2, 3)), [0, 0, 0], 0),
        ValueError,
        "s",
    ),
    row(
        "twist_from_axis-r-short",
        lambda: sk.twist_from_axis([0, 0, 1], [1, 2], 0),
        ValueError,
        "r",
    ),
    row(
        "twist_from_axis-r-batch",
        lambda: sk.twist_from_axis([0, 0, 1], np.zeros((2, 3)), 0),
        ValueError,
        "r",
    ),
    row(
        "twist_from_axis-r-str-entry",
        lambda: sk.twist_from_axis([0, 0, 1], [theta, "x", 0], 0),
        TypeError,
        "r",
    ),
    row(
        "twist_from_axis-r-nan",
        lambda: sk.twist_from_axis([0, 0, 1], [np.nan, 0, 0], 0),
        ValueError,
        "r",
    ),
    *(
        row(f"exp_twist-{case}", lambda a=a, b=b: sk.exp_twist(a, b), error, name)
        for case, a, b, error, name in [
            ("short", [0, 0, 1], 1.0, ValueError, "twist"),
            ("sympy-short", sp.Matrix([0, 0, 1]), theta, ValueError, "twist"),
            ("str", "abc", 1.0, TypeError, "twist"),
            ("none", None, 1.0, TypeError, "twist"),
            ("nan", [0, 0, 1, np.nan, 0, 0], 1.0, ValueError, "twist"),
            ("complex", np.array([0, 0, 1, 0, 0, 1j]), 1.0, TypeError, "twist"),
            ("batch-twist", np.zeros((2, 6)), 1.0, ValueError, "twist"),
            ("theta-str", [0, 0, 1, 0, 0, 0], "a", TypeError, "theta"),
            ("theta-none", [0, 0, 1, 0, 0, 0], None, TypeError, "theta"),
            ("theta-bool", [0, 0, 1, 0, 0, 0], False, TypeError, "theta"),
            ("theta-inf", [0, 0, 1, 0, 0, 0], np.inf, ValueError, "theta"),
            (
                "sympy-twist-batch-theta",
                sp.Matrix([0, 0, 1, 0, 0, 0]),
                [0.1, 0.2],
                TypeError,
                "theta",
            ),
            ("overflow", [0, 0, 1e300, 0, 0, 1e300], 1e10, ValueError, "theta"),
            ("translation-overflow", [0, 0, 0, 1e300, 0, 0], 1e10, ValueError, "theta"),
        ]
    ),
    row(
        "screw_motion-s-zero",
        lambda: sk.screw_motion([0, 0, 0], [0, 0, 0], 0, 1.0),
        ValueError,
        "s",
    ),
    row(
        "screw_motion-theta-str",
        lambda: sk.screw_motion([0, 0, 1], [0, 0, 0], 0, "a"),
        TypeError,
        "theta",
    ),
    row(
        "screw_motion-h-str",
        lambda: sk.screw_motion([0, 0, 1], [0, 0, 0], "x", 1.0),
        TypeError,
        "h",
    ),
    row(
        "screw_motion-r-short",
        lambda: sk.screw_motion([0, 0, 1], [1, 2], 0, 1.0),
        ValueError,
        "r",
    ),
]

WORKSPACE = [
    row("sweep-chain-str", lambda: ws.sweep("puma", {1: (0, 1)}), TypeError, "chain"),
    row("sweep-chain-none", lambda: ws.sweep(None, {1: (0, 1)}), TypeError, "chain"),
    row("sweep-ranges-list", lambda: ws.sweep(arm2(), [(0, 1)]), TypeError, "ranges"),
    row("sweep-ranges-empty", lambda: ws.sweep(arm2(), {}), TypeError, "ranges"),
    row("sweep-joint-0", lambda: ws.sweep(arm2(), {0: (0, 1)}), ValueError, "ranges"),
    row(
        "sweep-joint-too-big",
        lambda: ws.sweep(puma(), {7: (0, 1)}),
        ValueError,
        "ranges",
    ),
    row(
        "sweep-joint-bool",
        lambda: ws.sweep(arm2(), {True: (0, 1)}),
        TypeError,
        "ranges",
    ),
    row(
        "sweep-joint-float",
        lambda: ws.sweep(arm2(), {1.0: (0, 1)}),
        TypeError,
        "ranges",
    ),
    row(
        "sweep-joint-str", lambda: ws.sweep(arm2(), {"1": (0, 1)}), TypeError, "ranges"
    ),
    row(
        "sweep-range-three",
        lambda: ws.sweep(arm2(), {1: (0, 1, 2)}),
        ValueError,
        "ranges[1]",
    ),
    row(
        "sweep-range-nan",
        lambda: ws.sweep(arm2(), {1: (0, np.nan)}),
        ValueError,
        "ranges[1]",
    ),
    row(
        "sweep-range-str",
        lambda: ws.sweep(arm2(), {1: ("a", "b")}),
        TypeError,
        "ranges[1]",
    ),
    row(
        "sweep-range-equal",
        lambda: ws.sweep(arm2(), {1: (1, 1)}),
        ValueError,
        "ranges[1]",
    ),
    row(
        "sweep-range-none",
        lambda: ws.sweep(arm2(), {1: None}),
        TypeError,
        "ranges[1]",
    ),
    row("sweep-num-1", lambda: ws.sweep(arm2(), {1: (0, 1)}, num=1), ValueError, "num"),
    row(
        "sweep-num-float",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, num=2.5),
        TypeError,
        "num",
    ),
    row(
        "sweep-num-bool",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, num=True),
        TypeError,
        "num",
    ),
    row(
        "sweep-num-str",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, num="10"),
        TypeError,
        "num",
    ),
    row(
        "sweep-num-none",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, num=None),
        TypeError,
        "num",
    ),
    row(
        "sweep-num-count",
        lambda: ws.sweep(arm2(), {1: (0, 1), 2: (0, 1)}, num=(10,)),
        ValueError,
        "num",
    ),
    row(
        "sweep-num-entry",
        lambda: ws.sweep(arm2(), {1: (0, 1), 2: (0, 1)}, num=(10, "a")),
        TypeError,
        "num",
    ),
    row(
        "sweep-q-short", lambda: ws.sweep(arm2(), {1: (0, 1)}, q=[0.0]), ValueError, "q"
    ),
    row(
        "sweep-q-batch",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, q=np.zeros((2, 2))),
        ValueError,
        "q",
    ),
    row(
        "sweep-q-nan",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, q=[0.0, np.nan]),
        ValueError,
        "q",
    ),
    row("sweep-q-str", lambda: ws.sweep(arm2(), {1: (0, 1)}, q="zero"), TypeError, "q"),
    row(
        "sweep-too-large-3-joints",
        lambda: ws.sweep(puma(), {1: (0, 1), 2: (0, 1), 3: (0, 1)}),
        ValueError,
        "max_configurations",
    ),
    row(
        "sweep-too-large-4-joints",
        lambda: ws.sweep(puma(), {1: (0, 1), 2: (0, 1), 3: (0, 1), 4: (0, 1)}),
        ValueError,
        "max_configurations",
    ),
    row(
        "sweep-limit-0",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, max_configurations=0),
        ValueError,
        "max_configurations",
    ),
    row(
        "sweep-limit-str",
        lambda: ws.sweep(arm2(), {1: (0, 1)}, max_configurations="big"),
        TypeError,
        "max_configurations",
    ),
    row("reach-str", lambda: sweep().reach("origin"), TypeError, "centre"),
    row("reach-short", lambda: sweep().reach([0, 0]), ValueError, "centre"),
    row("reach-nan", lambda: sweep().reach([0, 0, np.nan]), ValueError, "centre"),
    row("section-axis", lambda: sweep().section("w"), ValueError, "axis"),
    row("section-axis-int", lambda: sweep().section(1), TypeError, "axis"),
    row("section-value-str", lambda: sweep().section("y", "a"), TypeError, "value"),
    row(
        "section-value-batch", lambda: sweep().section("y", [0, 1]), TypeError, "value"
    ),
    row(
        "section-tolerance-negative",
        lambda: sweep().section("y", 0.0, -1.0),
        ValueError,
        "tolerance",
    ),
    row(
        "section-tolerance-nan",
        lambda: sweep().section("y", 0.0, np.nan),
        ValueError,
        "tolerance",
    ),
    row("determinant-not-square", lambda: sweep().determinant(), ValueError, "rows"),
    row(
        "determinant-rows-bad",
        lambda: sweep().determinant(rows="bad"),
        ValueError,
        "rows",
    ),
    row("singular-rows-bad", lambda: sweep().singular(rows="xyz"), ValueError, "rows"),
    row(
        "manipulability-rows-int",
        lambda: sweep().manipulability(rows=3),
        TypeError,
        "rows",
    ),
    row(
        "jacobians-rows-none", lambda: sweep().jacobians(rows=None), ValueError, "rows"
    ),
]

REDUNDANCY = [
    row(
        "Path-one-sample",
        lambda: rd.Path([0.0], np.zeros((1, 2)), np.zeros((1, 2))),
        ValueError,
        "t",
    ),
    row("Path-dt-zero", lambda: rd.Path(np.zeros(5), POS, POS), ValueError, "dt"),
    row("Path-dt-negative", lambda: rd.Path(-T_STEPS, POS, POS), ValueError, "dt"),
    row(
        "Path-non-uniform",
        lambda: rd.Path([0, 0.1, 0.3, 0.4, 0.5], POS, POS),
        ValueError,
        "t",
    ),
    row(
        "Path-t-nan",
        lambda: rd.Path([0, 0.1, np.nan, 0.3, 0.4], POS, POS),
        ValueError,
        "t",
    ),
    row("Path-t-2d", lambda: rd.Path(np.zeros((5, 1)), POS, POS), ValueError, "t"),
    row(
        "Path-position-shape",
        lambda: rd.Path(T_STEPS, np.zeros((4, 2)), POS),
        ValueError,
        "position",
    ),
    row(
        "Path-velocity-3d",
        lambda: rd.Path(T_STEPS, POS, np.zeros((5, 3))),
        ValueError,
        "velocity",
    ),
    row(
        "Path-velocity-str",
        lambda: rd.Path(T_STEPS, POS, "still"),
        TypeError,
        "velocity",
    ),
    row("Path-name", lambda: rd.Path(T_STEPS, POS, POS, 5), TypeError, "name"),
    row("timing-zero-duration", lambda: rd.timing(T_STEPS, 0), ValueError, "duration"),
    row(
        "timing-negative-duration",
        lambda: rd.timing(T_STEPS, -1.0),
        ValueError,
        "duration",
    ),
    row(
        "timing-nan-duration",
        lambda: rd.timing(T_STEPS, np.nan),
        ValueError,
        "duration",
    ),
    row("timing-str-duration", lambda: rd.timing(T_STEPS, "1"), TypeError, "duration"),
    row("timing-kind", lambda: rd.timing(T_STEPS, 1.0, "fast"), ValueError, "kind"),
    row("timing-t-str", lambda: rd.timing("a", 1.0), TypeError, "t"),
    row("timing-t-outside", lambda: rd.timing([0.0, 2.0], 1.0), ValueError, "t"),
    row("timing-t-negative", lambda: rd.timing([-0.5, 0.5], 1.0), ValueError, "t"),
    row(
        "circle-radius-nan",
        lambda: rd.circle((0, 0), np.nan, 1.0, 0.01),
        ValueError,
        "radius",
    ),
    row(
        "circle-radius-negative",
        lambda: rd.circle((0, 0), -0.1, 1.0, 0.01),
        ValueError,
        "radius",
    ),
    row(
        "circle-radius-str",
        lambda: rd.circle((0, 0), "a", 1.0, 0.01),
        TypeError,
        "radius",
    ),
    row(
        "circle-center-3d",
        lambda: rd.circle((0, 0, 0), 0.1, 1.0, 0.01),
        ValueError,
        "center",
    ),
    row(
        "circle-center-str",
        lambda: rd.circle("ab", 0.1, 1.0, 0.01),
        TypeError,
        "center",
    ),
    row("circle-dt-zero", lambda: rd.circle((0, 0), 0.1, 1.0, 0.0), ValueError, "dt"),
    row(
        "circle-dt-negative",
        lambda: rd.circle((0, 0), 0.1, 1.0, -0.01),
        ValueError,
        "dt",
    ),
    row("circle-dt-bool", lambda: rd.circle((0, 0), 0.1, 1.0, True), TypeError, "dt"),
    row(
        "circle-duration-zero",
        lambda: rd.circle((0, 0), 0.1, 0.0, 0.01),
        ValueError,
        "duration",
    ),
    row(
        "circle-not-whole-steps",
        lambda: rd.circle((0, 0), 0.1, 1.0, 0.3),
        ValueError,
        "duration",
    ),
    row(
        "circle-too-many-steps",
        lambda: rd.circle((0, 0), 0.1, 1e6, 1e-6),
        ValueError,
        "dt",
    ),
    row(
        "circle-timing-kind",
        lambda: rd.circle((0, 0), 0.1, 1.0, 0.01, "x"),
        ValueError,
        "timing_kind",
    ),
    row(
        "line-same-points",
        lambda: rd.line((0, 0), (0, 0), 1.0, 0.01),
        ValueError,
        "start and end",
    ),
    row("line-end-none", lambda: rd.line((0, 0), None, 1.0, 0.01), TypeError, "end"),
    row(
        "line-start-nan",
        lambda: rd.line((np.nan, 0), (1, 0), 1.0, 0.01),
        ValueError,
        "start",
    ),
    row(
        "line-timing-kind-int",
        lambda: rd.line((0, 0), (1, 0), 1.0, 0.01, 1),
        TypeError,
        "timing_kind",
    ),
    row("resolve-arm-str", lambda: rd.resolve("arm", path(), q0()), TypeError, "arm"),
    row(
        "resolve-arm-puma",
        lambda: rd.resolve(puma(), path(), np.zeros(6)),
        ValueError,
        "arm",
    ),
    row(
        "resolve-path-array",
        lambda: rd.resolve(arm(), path().position, q0()),
        TypeError,
        "path",
    ),
    row(
        "resolve-q0-short",
        lambda: rd.resolve(arm(), path(), q0()[:2]),
        ValueError,
        "q0",
    ),
    row(
        "resolve-q0-nan",
        lambda: rd.resolve(arm(), path(), [np.nan, 0, 0]),
        ValueError,
        "q0",
    ),
    row(
        "resolve-q0-batch",
        lambda: rd.resolve(arm(), path(), np.stack([q0(), q0()])),
        ValueError,
        "q0",
    ),
    row(
        "resolve-q0-off-path",
        lambda: rd.resolve(arm(), path(), q0() + 0.1),
        ValueError,
        "q0",
    ),
    *keyword_rows(
        "resolve-{}",
        lambda **kw: rd.resolve(arm(), path(), q0(), **kw),
        [
            ("null-space-nan", "null_space_gain", np.nan, ValueError, None),
            ("null-space-str", "null_space_gain", "1", TypeError, None),
            ("null-space-bool", "null_space_gain", True, TypeError, None),
            ("null-space-array", "null_space_gain", [1.0, 2.0], TypeError, None),
            ("damping-nan", "damping", np.nan, ValueError, None),
            ("damping-negative", "damping", -0.1, ValueError, None),
            ("max-rate-negative", "max_rate", -1.0, ValueError, None),
            ("max-rate-zero", "max_rate", 0.0, ValueError, None),
            ("feedback-negative", "feedback_gain", -1.0, ValueError, None),
            ("feedback-nan", "feedback_gain", np.nan, ValueError, None),
            ("feedback-unstable", "feedback_gain", 500.0, ValueError, None),
            ("limit-gain-nan", "limit_gain", np.nan, ValueError, None),
            ("start-tolerance-zero", "start_tolerance", 0.0, ValueError, None),
            ("joint-limits-str", "joint_limits", "soft", ValueError, None),
            ("joint-limits-bool", "joint_limits", True, TypeError, None),
        ],
    ),
    row(
        "resolve-q0-outside-limits",
        lambda: rd.resolve(limited(), path(), limits_q0(), joint_limits="clamp"),
        ValueError,
        "q0",
    ),
    row(
        "resolve-path-outside-annulus",
        lambda: rd.resolve(arm(), rd.circle((0.8, 0.0), 0.3, 1.0, 0.01), q0()),
        ValueError,
        "path",
    ),
    row(
        "start-max-iterations-0",
        lambda: rd.start_configuration(
            arm(), (0.5, 0.1), [0.3, 0.6, 0.6], max_iterations=0
        ),
        ValueError,
        "max_iterations",
    ),
    row(
        "start-max-iterations-float",
        lambda: rd.start_configuration(
            arm(), (0.5, 0.1), [0.3, 0.6, 0.6], max_iterations=2.5
        ),
        TypeError,
        "max_iterations",
    ),
    row(
        "start-max-iterations-bool",
        lambda: rd.start_configuration(
            arm(), (0.5, 0.1), [0.3, 0.6, 0.6], max_iterations=True
        ),
        TypeError,
        "max_iterations",
    ),
    row(
        "start-tol-zero",
        lambda: rd.start_configuration(arm(), (0.5, 0.1), [0.3, 0.6, 0.6], tol=0.0),
        ValueError,
        "tol",
    ),
    row(
        "start-tol-nan",
        lambda: rd.start_configuration(arm(), (0.5, 0.1), [0.3, 0.6, 0.6], tol=np.nan),
        ValueError,
        "tol",
    ),
    row(
        "start-q-guess-short",
        lambda: rd.start_configuration(arm(), (0.5, 0.1), [0.3, 0.6]),
        ValueError,
        "q_guess",
    ),
    row(
        "start-q-guess-batch",
        lambda: rd.start_configuration(arm(), (0.5, 0.1), np.zeros((2, 3))),
        ValueError,
        "q_guess",
    ),
    row(
        "start-point-3d",
        lambda: rd.start_configuration(arm(), (0.5, 0.1, 0.0), [0.3, 0.6, 0.6]),
        ValueError,
        "point",
    ),
    row(
        "start-point-str",
        lambda: rd.start_configuration(arm(), "ab", [0.3, 0.6, 0.6]),
        TypeError,
        "point",
    ),
    row(
        "start-unreachable",
        lambda: rd.start_configuration(arm(), (2.0, 0.0), [0.3, 0.6, 0.6]),
        ValueError,
        "point",
    ),
    row(
        "start-arm-none",
        lambda: rd.start_configuration(None, (0.5, 0.1), [0.3, 0.6, 0.6]),
        TypeError,
        "arm",
    ),
    *value_rows(
        "pinv-J-{}",
        lambda J: rd.pseudo_inverse(J),
        "J",
        [
            ("3x3", np.eye(3), ValueError, None),
            ("str", "J", TypeError, None),
            ("nan", np.full((2, 3), np.nan), ValueError, None),
        ],
    ),
    row(
        "pinv-damping-nan",
        lambda: rd.pseudo_inverse(np.ones((2, 3)), damping=np.nan),
        ValueError,
        "damping",
    ),
    row(
        "pinv-region-zero",
        lambda: rd.pseudo_inverse(np.ones((2, 3)), singular_region=0.0),
        ValueError,
        "singular_region",
    ),
    row(
        "kinematics-lengths-str",
        lambda: rd.planar_kinematics("a", [0.0]),
        TypeError,
        "lengths",
    ),
    row(
        "kinematics-lengths-negative",
        lambda: rd.planar_kinematics([-1.0, 1.0], [0.0, 0.0]),
        ValueError,
        "lengths",
    ),
    row(
        "kinematics-q-mismatch",
        lambda: rd.planar_kinematics([1.0, 1.0], [0.0, 0.0, 0.0]),
        ValueError,
        "q",
    ),
    row(
        "gradient-q-nan",
        lambda: rd.manipulability_gradient([1.0, 1.0], [0.0, np.nan]),
        ValueError,
        "q",
    ),
]

PLOTTING = [
    row(
        "draw_mechanism-limbs-str",
        lambda: pl.draw_mechanism("limbs", {}),
        ValueError,
        "limbs",
    ),
    row(
        "draw_mechanism-values-str",
        lambda: pl.draw_mechanism(mechanism(), "values"),
        TypeError,
        "values",
    ),
    row(
        "draw_mechanism-values-missing",
        lambda: pl.draw_mechanism(mechanism(), {}),
        ValueError,
        "values",
        match="L_y",
    ),
    row(
        "draw_mechanism-values-nan",
        lambda: pl.draw_mechanism(
            mechanism(), dict.fromkeys(mechanism_symbols(), float("nan"))
        ),
        ValueError,
        "values['L_y']",
    ),
    row(
        "draw_mechanism-twists-str",
        lambda: pl.draw_mechanism(mechanism(), mechanism_values(), twists="x"),
        TypeError,
        "twists[0]",
    ),
    row(
        "draw_mechanism-ax-str",
        lambda: pl.draw_mechanism(mechanism(), mechanism_values(), ax="ax"),
        TypeError,
        "ax",
    ),
    row(
        "draw_mechanism-axis_length-str",
        lambda: pl.draw_mechanism(mechanism(), mechanism_values(), axis_length="a"),
        TypeError,
        "axis_length",
    ),
    row(
        "draw_mechanism-axis_length-negative",
        lambda: pl.draw_mechanism(mechanism(), mechanism_values(), axis_length=-1.0),
        ValueError,
        "axis_length",
    ),
    row(
        "axes3d-limits-shape", lambda: pl.axes3d(limits=(0, 1, 2)), ValueError, "limits"
    ),
    row(
        "axes3d-limits-order",
        lambda: pl.axes3d(limits=((1, 0), (0, 1), (0, 1))),
        ValueError,
        "limits",
    ),
    row(
        "axes3d-limits-nan",
        lambda: pl.axes3d(limits=((0, np.nan), (0, 1), (0, 1))),
        ValueError,
        "limits",
    ),
    row("axes3d-figsize", lambda: pl.axes3d(figsize=(0, 1)), ValueError, "figsize"),
    row("axes3d-ax-str", lambda: pl.axes3d(ax="ax"), TypeError, "ax"),
    row("axes3d-ax-2d", lambda: pl.axes3d(ax=ax2()), TypeError, "ax"),
    row("draw_frame-ax", lambda: pl.draw_frame("ax", EYE), TypeError, "ax"),
    row("draw_frame-T-3x3", lambda: pl.draw_frame(ax3(), np.eye(3)), ValueError, "T"),
    row("draw_frame-T-str", lambda: pl.draw_frame(ax3(), "T"), TypeError, "T"),
    row(
        "draw_frame-T-str-entries",
        lambda: pl.draw_frame(ax3(), np.eye(4).astype(str)),
        TypeError,
        "T",
    ),
    row(
        "draw_frame-T-nan",
        lambda: pl.draw_frame(ax3(), np.full((4, 4), np.nan)),
        ValueError,
        "T",
    ),
    row(
        "draw_frame-T-symbolic",
        lambda: pl.draw_frame(ax3(), sk.homogeneous(sk.rotz(theta))),
        TypeError,
        "T",
    ),
    row(
        "draw_frame-T-batch",
        lambda: pl.draw_frame(ax3(), np.stack([EYE, EYE])),
        ValueError,
        "T",
    ),
    row(
        "draw_frame-length",
        lambda: pl.draw_frame(ax3(), EYE, length=-1.0),
        ValueError,
        "length",
    ),
    row(
        "draw_frame-alpha",
        lambda: pl.draw_frame(ax3(), EYE, alpha=2.0),
        ValueError,
        "alpha",
    ),
    row(
        "draw_frame-alpha-nan",
        lambda: pl.draw_frame(ax3(), EYE, alpha=np.nan),
        ValueError,
        "alpha",
    ),
    row(
        "draw_screw_axis-s-zero",
        lambda: pl.draw_screw_axis(ax3(), [0, 0, 0], [0, 0, 0]),
        ValueError,
        "s",
    ),
    row(
        "draw_screw_axis-s-short",
        lambda: pl.draw_screw_axis(ax3(), [0, 1], [0, 0, 0]),
        ValueError,
        "s",
    ),
    row(
        "draw_screw_axis-r-str",
        lambda: pl.draw_screw_axis(ax3(), [0, 0, 1], "abc"),
        TypeError,
        "r",
    ),
    row(
        "draw_screw_axis-length",
        lambda: pl.draw_screw_axis(ax3(), [0, 0, 1], [0, 0, 0], length=0.0),
        ValueError,
        "length",
    ),
    row(
        "draw_screw_axis-s-symbol",
        lambda: pl.draw_screw_axis(ax3(), sp.Matrix([0, 0, theta]), [0, 0, 0]),
        TypeError,
        "s",
    ),
    row(
        "draw_screw_motion-single",
        lambda: pl.draw_screw_motion(ax3(), EYE),
        ValueError,
        "Ts",
    ),
    row(
        "draw_screw_motion-empty",
        lambda: pl.draw_screw_motion(ax3(), np.zeros((0, 4, 4))),
        ValueError,
        "Ts",
    ),
    row(
        "draw_screw_motion-every-0",
        lambda: pl.draw_screw_motion(ax3(), np.stack([EYE, EYE]), every=0),
        ValueError,
        "every",
    ),
    row(
        "draw_screw_motion-every-float",
        lambda: pl.draw_screw_motion(ax3(), np.stack([EYE, EYE]), every=1.5),
        TypeError,
        "every",
    ),
    row(
        "draw_chain-chain-str",
        lambda: pl.draw_chain(ax3(), "puma", np.zeros(6)),
        TypeError,
        "chain",
    ),
    row(
        "draw_chain-q-batch",
        lambda: pl.draw_chain(ax3(), puma(), np.zeros((2, 6))),
        ValueError,
        "q",
    ),
    row(
        "draw_chain-q-short",
        lambda: pl.draw_chain(ax3(), puma(), np.zeros(5)),
        ValueError,
        "q",
    ),
    row(
        "draw_chain-ax-2d",
        lambda: pl.draw_chain(ax2(), puma(), np.zeros(6)),
        TypeError,
        "ax",
    ),
    row(
        "draw_chain-frame-length",
        lambda: pl.draw_chain(ax3(), puma(), np.zeros(6), frame_length=0),
        ValueError,
        "frame_length",
    ),
    row(
        "draw_ellipsoid-radii-negative",
        lambda: pl.draw_ellipsoid(ax3(), [0, 0, 0], [1, -1, 1], np.eye(3)),
        ValueError,
        "radii",
    ),
    row(
        "draw_ellipsoid-axes-shape",
        lambda: pl.draw_ellipsoid(ax3(), [0, 0, 0], [1, 1, 1], np.eye(2)),
        ValueError,
        "axes",
    ),
    row(
        "draw_ellipsoid-centre-str",
        lambda: pl.draw_ellipsoid(ax3(), "o", [1, 1, 1], np.eye(3)),
        TypeError,
        "centre",
    ),
    row(
        "draw_ellipsoid-scale",
        lambda: pl.draw_ellipsoid(ax3(), [0, 0, 0], [1, 1, 1], np.eye(3), scale=0),
        ValueError,
        "scale",
    ),
    row(
        "draw_planar-chain-str",
        lambda: pl.draw_planar(ax2(), "arm", [0.0, 0.0]),
        TypeError,
        "chain",
    ),
    row(
        "draw_planar-base-3d",
        lambda: pl.draw_planar(ax2(), arm2(), [0.0, 0.0], base=(0, 0, 0)),
        ValueError,
        "base",
    ),
    row(
        "draw_planar-q-nan",
        lambda: pl.draw_planar(ax2(), arm2(), [0.0, np.nan]),
        ValueError,
        "q",
    ),
    row(
        "draw_planar-ax-none",
        lambda: pl.draw_planar(None, arm2(), [0.0, 0.0]),
        TypeError,
        "ax",
    ),
    row(
        "animation_html-str",
        lambda: pl.animation_html("<html>"),
        TypeError,
        "animation",
    ),
]

ROWS = TRANSFORMS + WORKSPACE + REDUNDANCY + PLOTTING
