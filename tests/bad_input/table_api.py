"""Bad input across the public API: lie, transforms, screws, chains,
jacobians, the catalogue, notation and display, ik and more. Rows in the format of
rows.py; robots are built on first use, not at import."""

import functools

import numpy as np
import sympy as sp
from builders import planar, puma
from rows import row

import screwkit as sk
from screwkit import _notation, limbs, robots
from screwkit import jacobians as jac

Z, O = [0, 0, 1], [0, 0, 0]


def arm():
    return planar(1.0, 1.0)


@functools.cache
def poe():
    return sk.Chain.from_screws([[0, 0, 1, 0, 0, 0], [0, 0, 0, 0, 0, 1]], np.eye(4))


def twist():
    return sk.Twist.from_axis(Z, O, 0)


LIE_AND_TRANSFORMS = [
    row("adjoint-None", lambda: sk.adjoint(None), TypeError, "T"),
    row("adjoint-scaled", lambda: sk.adjoint(np.diag([2.0, 1, 1, 1])), ValueError, "T"),
    row("ad-str", lambda: sk.ad("x"), TypeError, "twist"),
    row("ad-short", lambda: sk.ad([1, 2, 3]), ValueError, "twist"),
    row("vee-None", lambda: sk.vee(None), TypeError, "W"),
    row("vee-shape", lambda: sk.vee(np.zeros((2, 2))), ValueError, "W"),
    row("log_rotation-str", lambda: sk.log_rotation("R"), TypeError, "R"),
    row(
        "log_rotation-reflection",
        lambda: sk.log_rotation(np.diag([1.0, 1, -1])),
        ValueError,
        "R",
    ),
    row("log_transform-None", lambda: sk.log_transform(None), TypeError, "T"),
    row("wrap_angle-str", lambda: sk.wrap_angle("pi"), TypeError, "angle"),
    row("wrap_angle-nan", lambda: sk.wrap_angle(float("nan")), ValueError, "angle"),
    row(
        "axis_coordinates-via-twist_from_axis",
        lambda: sk.twist_from_axis(O, O, 0),
        ValueError,
        "s",
    ),
    row(
        "subproblem3_prismatic-delta",
        lambda: sk.ik.subproblem3_prismatic(Z, O, O, "d"),
        TypeError,
        "delta",
    ),
]

SCREWS = [
    row("pitch-zero", lambda: sk.Twist([0] * 6).pitch, ValueError, "pitch"),
    row(
        "direction-zero", lambda: sk.Wrench([0] * 6).direction, ValueError, "direction"
    ),
    row("point-zero", lambda: sk.Twist([0] * 6).point, ValueError, "point"),
    row("add-None", lambda: twist() + None, TypeError, "add"),
    row("add-array", lambda: twist() + np.zeros(6), TypeError, "add"),
    row("radd-array", lambda: np.zeros(6) + twist(), TypeError, "add"),
    row("sub-None", lambda: twist() - None, TypeError, "subtract"),
    row("rsub-list", lambda: [0] * 6 - twist(), TypeError, "subtract"),
    row("mul-None", lambda: twist() * None, TypeError, "scalar"),
    row("mul-array", lambda: twist() * np.ones(6), TypeError, "scaled"),
    row("rmul-array", lambda: np.ones(6) * twist(), TypeError, "scaled"),
    row("mul-str", lambda: twist() * "2", TypeError, "scalar"),
    row("mul-nan", lambda: twist() * float("nan"), ValueError, "scalar"),
    row("mul-twist", lambda: twist() * twist(), TypeError, "multiply"),
    row("matmul-None", lambda: twist() @ None, TypeError, "reciprocal"),
    row("matmul-array", lambda: twist() @ np.zeros(6), TypeError, "reciprocal"),
    row("transform-None", lambda: twist().transform(None), TypeError, "T"),
    row("transform-str", lambda: twist().transform("T"), TypeError, "T"),
    row(
        "transform-batch",
        lambda: twist().transform(np.stack([np.eye(4)] * 2)),
        ValueError,
        "T",
    ),
    row("transform-3x3", lambda: twist().transform(np.eye(3)), ValueError, "T"),
    row("exp-str", lambda: twist().exp("a"), TypeError, "theta"),
    row(
        "from_vector-short", lambda: sk.Twist.from_vector([1, 2]), ValueError, "vector"
    ),
    row("from_axis-s-None", lambda: sk.Screw.from_axis(None, O, 0), TypeError, "s"),
]

CHAINS = [
    row(
        "geometric_jacobian-short",
        lambda: puma().geometric_jacobian([0] * 5),
        ValueError,
        "q",
    ),
    row(
        "geometric_jacobian-nan",
        lambda: puma().geometric_jacobian([0, 0, np.nan, 0, 0, 0]),
        ValueError,
        "q",
    ),
    row("space_jacobian-str", lambda: puma().space_jacobian("q"), TypeError, "q"),
    row("body_jacobian-long", lambda: puma().body_jacobian([0] * 7), ValueError, "q"),
    row(
        "Chain.manipulability-short",
        lambda: puma().manipulability([0, 0, 0]),
        ValueError,
        "q",
    ),
    row(
        "Chain.manipulability-rows",
        lambda: puma().manipulability([0] * 6, rows="x"),
        ValueError,
        "rows",
    ),
    row(
        "link_transforms-short",
        lambda: puma().link_transforms([0, 0, 0]),
        ValueError,
        "q",
    ),
    row(
        "link_transforms-long", lambda: puma().link_transforms([0] * 7), ValueError, "q"
    ),
    row(
        "link_transforms-str", lambda: puma().link_transforms("abcdef"), TypeError, "q"
    ),
    row(
        "link_transforms-entry",
        lambda: puma().link_transforms([0, 0, "x", 0, 0, 0]),
        TypeError,
        "q[2]",
    ),
    row(
        "twists_symbolic-str", lambda: puma().twists_symbolic("abcdef"), TypeError, "q"
    ),
    row(
        "twists_symbolic-short",
        lambda: puma().twists_symbolic([0] * 5),
        ValueError,
        "q",
    ),
    row(
        "twists_symbolic-flag",
        lambda: arm().twists_symbolic(rational="yes"),
        TypeError,
        "rational",
    ),
    row(
        "joint_twists-short",
        lambda: puma().joint_twists([sp.Integer(0)] * 5),
        ValueError,
        "q",
    ),
    row("joint_twists-str", lambda: puma().joint_twists("q"), TypeError, "q"),
    row(
        "fk_symbolic-upto-float",
        lambda: puma().fk_symbolic(upto=2.5),
        TypeError,
        "upto",
    ),
    row(
        "fk_symbolic-upto-str", lambda: puma().fk_symbolic(upto="2"), TypeError, "upto"
    ),
    row(
        "fk_symbolic-upto-bool",
        lambda: puma().fk_symbolic(upto=True),
        TypeError,
        "upto",
    ),
    row("fk_symbolic-upto-big", lambda: puma().fk_symbolic(upto=7), ValueError, "upto"),
    row(
        "fk_symbolic-upto-negative",
        lambda: puma().fk_symbolic(upto=-1),
        ValueError,
        "upto",
    ),
    row(
        "fk_symbolic-simplify",
        lambda: arm().fk_symbolic(simplify="no"),
        TypeError,
        "simplify",
    ),
    row(
        "frames_symbolic-flag",
        lambda: arm().frames_symbolic(symbolic_lengths=1),
        TypeError,
        "symbolic_lengths",
    ),
    row("source-unknown", lambda: arm().source("jacobian"), ValueError, "outputs"),
    row("check_one-batch", lambda: arm().check_one(np.zeros((2, 2))), ValueError, "q"),
    row(
        "jacobian_rows-rows",
        lambda: arm().jacobian_rows([0, 0], rows="xy"),
        ValueError,
        "rows",
    ),
    row(
        "Chain.singular_values-rows-int",
        lambda: arm().singular_values([0, 0], rows=2),
        TypeError,
        "rows",
    ),
    row(
        "lost_rank-rows",
        lambda: arm().lost_rank(np.ones(2), rows=None),
        ValueError,
        "rows",
    ),
    row("check_q-3d", lambda: arm().check_q(np.zeros((2, 2, 2))), ValueError, "q"),
    row(
        "with_tool-scaled",
        lambda: arm().with_tool(np.diag([2.0, 1, 1, 1])),
        ValueError,
        "tool",
    ),
    row("joint_frames-str", lambda: arm().joint_frames("frames"), TypeError, "frames"),
    row(
        "configurations-float",
        lambda: sk.workspace.sweep(arm(), {1: (0, 1)}, num=3).configurations(0.5),
        TypeError,
        "start",
    ),
    row(
        "configurations-stop",
        lambda: sk.workspace.sweep(arm(), {1: (0, 1)}, num=3).configurations(0, 4),
        ValueError,
        "stop",
    ),
    row(
        "numeric_ik-tol",
        lambda: arm().numeric_ik(np.eye(4), [0, 0], tol="small"),
        TypeError,
        "tol",
    ),
    row("fk_poe-batch", lambda: arm().fk_poe(np.zeros((3, 2))), ValueError, "q"),
    row("joint_axes-str", lambda: arm().joint_axes("q"), TypeError, "q"),
    row("frames-short", lambda: arm().frames([0.0]), ValueError, "q"),
    row("within_limits-str", lambda: arm().within_limits("a"), TypeError, "q"),
    row("with_base-str", lambda: arm().with_base("x"), TypeError, "base"),
    row(
        "link_transforms-poe",
        lambda: poe().link_transforms(),
        ValueError,
        "link_transforms",
    ),
    row(
        "from_table-shape",
        lambda: sk.Chain.from_table(np.zeros((2, 3))),
        ValueError,
        "table",
    ),
    row(
        "from_screws-frame",
        lambda: sk.Chain.from_screws([[0, 0, 1, 0, 0, 0]], np.eye(4), frame="world"),
        ValueError,
        "frame",
    ),
    row(
        "Link-transform-convention",
        lambda: sk.Link.revolute().transform(0, "standard"),
        TypeError,
        "convention",
    ),
    row("Link-prismatic-str", lambda: sk.Link.prismatic(a="0.5"), TypeError, "a"),
]

JACOBIANS = [
    row(
        "jacobians.manipulability-q-str",
        lambda: jac.manipulability(arm(), "q"),
        TypeError,
        "q",
    ),
    row(
        "jacobians.manipulability-chain-str",
        lambda: jac.manipulability("arm", [0, 0]),
        TypeError,
        "chain",
    ),
    row(
        "point-float",
        lambda: jac.geometric_jacobian_symbolic(arm(), point=2.5),
        TypeError,
        "point",
    ),
    row(
        "point-integral-float",
        lambda: jac.geometric_jacobian_symbolic(arm(), point=2.0),
        TypeError,
        "point",
    ),
    row(
        "point-bool",
        lambda: jac.geometric_jacobian_symbolic(arm(), point=True),
        TypeError,
        "point",
    ),
    row(
        "point-str",
        lambda: jac.geometric_jacobian_symbolic(arm(), point="p"),
        TypeError,
        "point",
    ),
    row(
        "point-None-entry",
        lambda: jac.geometric_jacobian_symbolic(arm(), point=[1, None, 2]),
        TypeError,
        "point",
    ),
    row(
        "point-short",
        lambda: jac.geometric_jacobian_symbolic(arm(), point=[1, 2]),
        ValueError,
        "point",
    ),
    row(
        "point-frame-out",
        lambda: jac.geometric_jacobian_symbolic(arm(), point=np.int64(5)),
        ValueError,
        "point",
    ),
    row(
        "symbolic-lengths-flag",
        lambda: jac.geometric_jacobian_symbolic(arm(), symbolic_lengths="yes"),
        TypeError,
        "symbolic_lengths",
    ),
    row(
        "determinant-chain", lambda: jac.determinant_symbolic("arm"), TypeError, "chain"
    ),
    row(
        "determinant-3-joints",
        lambda: jac.determinant_symbolic(arm()),
        ValueError,
        "chain",
    ),
    row("joint_axes-chain", lambda: jac.joint_axes(None, [0, 0]), TypeError, "chain"),
    row("space-chain", lambda: jac.space_jacobian("arm", [0, 0]), TypeError, "chain"),
    row(
        "geometric-q", lambda: jac.geometric_jacobian(arm(), [0, 0, 0]), ValueError, "q"
    ),
    row("body-q", lambda: jac.body_jacobian(arm(), "q"), TypeError, "q"),
    row(
        "numerical-h",
        lambda: jac.numerical_jacobian(arm(), [0, 0], h=-1),
        ValueError,
        "h",
    ),
    row(
        "jacobians.singular_values-rows-str",
        lambda: jac.singular_values(arm(), [0, 0], rows="x"),
        ValueError,
        "rows",
    ),
    row(
        "condition_number-q",
        lambda: jac.condition_number(arm(), [[0]]),
        ValueError,
        "q",
    ),
    row("rank-rows", lambda: jac.rank(arm(), [0, 0], rows=1), TypeError, "rows"),
    row(
        "ellipsoid-rows",
        lambda: jac.ellipsoid(arm(), [0, 0], rows="all"),
        ValueError,
        "rows",
    ),
]

CATALOGUE = [
    row(
        "planar-numeric-strings",
        lambda: robots.planar(["1", "2"]),
        TypeError,
        "lengths",
    ),
    row("planar-None", lambda: robots.planar(None), TypeError, "lengths"),
    row("planar-big-int", lambda: robots.planar([10**400, 1]), ValueError, "lengths"),
    row("planar-complex", lambda: robots.planar([1j, 1]), TypeError, "lengths"),
    row("planar-ragged", lambda: robots.planar([[1, 2], [3]]), ValueError, "lengths"),
    row("planar-one", lambda: robots.planar([1.0]), ValueError, "lengths"),
    row("planar-qlim-str", lambda: robots.planar([1, 1], qlim="x"), TypeError, "qlim"),
    row(
        "planar-qlim-None-entry",
        lambda: robots.planar([1, 1], qlim=[[0, 1], [None, 2]]),
        TypeError,
        "qlim",
    ),
    row(
        "planar-qlim-shape",
        lambda: robots.planar([1, 1], qlim=[[0, 1]]),
        ValueError,
        "qlim",
    ),
    row(
        "two_arm-separation-str",
        lambda: robots.two_arm_planar(separation="a"),
        TypeError,
        "separation",
    ),
    row(
        "two_arm-separation-None",
        lambda: robots.two_arm_planar(separation=None),
        TypeError,
        "separation",
    ),
    row(
        "two_arm-separation-big",
        lambda: robots.two_arm_planar(separation=10**400),
        ValueError,
        "separation",
    ),
    row(
        "rotate_limb-str",
        lambda: limbs.rotate_limb("limb", sp.eye(3)),
        TypeError,
        "limb",
    ),
    row(
        "rotate_limb-None",
        lambda: limbs.rotate_limb(None, sp.eye(3)),
        TypeError,
        "limb",
    ),
    row(
        "rotate_limb-pairs",
        lambda: limbs.rotate_limb([(Z, O)], sp.eye(3)),
        TypeError,
        "limb",
    ),
    row(
        "rotate_limb-R",
        lambda: limbs.rotate_limb(limbs.revolute(Z, O), "R"),
        TypeError,
        "R",
    ),
    row(
        "translate_limb-str", lambda: limbs.translate_limb("limb", O), TypeError, "limb"
    ),
    row("translate_limb-int", lambda: limbs.translate_limb(5, O), TypeError, "limb"),
    row(
        "translate_limb-p",
        lambda: limbs.translate_limb(limbs.revolute(Z, O), None),
        TypeError,
        "p",
    ),
    row("limbs-revolute-None", lambda: limbs.revolute(None, O), TypeError, "s"),
    row("limbs-prismatic-zero", lambda: limbs.prismatic(O), ValueError, "s"),
    row("limbs-helical-oo", lambda: limbs.helical(Z, O, sp.oo), TypeError, "h"),
    row("limbs-cylindrical-r", lambda: limbs.cylindrical(Z, "r"), TypeError, "r"),
    row("limbs-universal-None", lambda: limbs.universal(None, Z, O), TypeError, "s1"),
    row("limbs-spherical-None", lambda: limbs.spherical(None), TypeError, "r"),
    row(
        "limbs-parallelogram-None",
        lambda: limbs.parallelogram(Z, None, O, O, O),
        TypeError,
        "a1",
    ),
]

NOTATION_AND_DISPLAY = [
    row("textbook-str", lambda: sk.textbook("cos(q1)"), TypeError, "expr"),
    row("textbook-None", lambda: sk.textbook(None), TypeError, "expr"),
    row("textbook-list", lambda: sk.textbook([1, 2]), TypeError, "expr"),
    row("textbook-object", lambda: _notation.textbook(object()), TypeError, "expr"),
    row(
        "textbook-q_symbols-str",
        lambda: sk.textbook(sp.cos(sp.Symbol("q1")), q_symbols="q1"),
        TypeError,
        "q_symbols",
    ),
    row(
        "textbook-q_symbols-int",
        lambda: sk.textbook(sp.Symbol("q1"), q_symbols=3),
        TypeError,
        "q_symbols",
    ),
    row(
        "widgets-joint_sliders-str",
        lambda: sk.widgets.joint_sliders("puma"),
        TypeError,
        "chain",
    ),
    row(
        "widgets-joint_sliders-None",
        lambda: sk.widgets.joint_sliders(None),
        TypeError,
        "chain",
    ),
    row(
        "widgets-screw_motion_slider-s",
        lambda: sk.widgets.screw_motion_slider("s", O, 0),
        TypeError,
        "s",
    ),
    row(
        "widgets-figure_slider-draw",
        lambda: sk.widgets.figure_slider(None, "x", values=[1.0, 2.0]),
        TypeError,
        "draw",
    ),
    row(
        "widgets-screw_motion_slider-start",
        lambda: sk.widgets.screw_motion_slider(Z, O, 0, start=np.eye(3)),
        ValueError,
        "start",
    ),
]

IK_AND_MORE = [
    row(
        "puma560_config-robot",
        lambda: sk.ik.puma560_config(np.zeros(6), robot="puma"),
        TypeError,
        "robot",
    ),
    row("puma560_ik_all-T", lambda: sk.ik.puma560_ik_all("T"), TypeError, "T"),
    row(
        "configuration-chain",
        lambda: sk.ik.configuration("puma", np.zeros(6)),
        TypeError,
        "chain",
    ),
    row(
        "nearest-str",
        lambda: sk.ik.puma560_ik(puma().fk(np.zeros(6))).nearest("q"),
        TypeError,
        "q",
    ),
    row("pose_error-T", lambda: sk.ik.pose_error("a", np.eye(4)), TypeError, "T"),
    row(
        "pose_error-target",
        lambda: sk.ik.pose_error(np.eye(4), None),
        TypeError,
        "T_target",
    ),
    row(
        "numeric_ik-damping",
        lambda: sk.ik.numeric_ik(arm(), np.eye(4), [0, 0], damping="x"),
        TypeError,
        "damping",
    ),
    row(
        "numeric_ik-within_limits",
        lambda: sk.ik.numeric_ik(arm(), np.eye(4), [0, 0], within_limits=1),
        TypeError,
        "within_limits",
    ),
    row("mobility-str", lambda: sk.mobility("limbs"), ValueError, "limbs"),
    row(
        "grubler_kutzbach-str",
        lambda: sk.grubler_kutzbach("a", 1, []),
        TypeError,
        "links",
    ),
    row("from_urdf-None", lambda: sk.Chain.from_urdf(None), TypeError, "source"),
    row(
        "from_urdf-tip-unknown",
        lambda: sk.Chain.from_urdf(
            '<robot name="r"><link name="a"/></robot>', None, "b"
        ),
        ValueError,
        "tip_link",
    ),
    row("structure-str", lambda: sk.ik.structure("puma"), TypeError, "chain"),
    row("structure-planar", lambda: sk.ik.structure(arm()), ValueError, "chain"),
]

ROWS = (
    LIE_AND_TRANSFORMS
    + SCREWS
    + CHAINS
    + JACOBIANS
    + CATALOGUE
    + NOTATION_AND_DISPLAY
    + IK_AND_MORE
)
