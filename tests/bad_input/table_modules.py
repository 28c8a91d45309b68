"""Bad input to the modules added after the first tables (parallel, orientation, urdf,
exercises, the closed-form IK engines, screw systems' methods, the viewers): rows in the
format of rows.py. Robots are built on first use, not at import."""

import functools

import numpy as np
import sympy as sp
from builders import puma, rpr, stanford, stewart, ur5e
from rows import row

import screwkit as sk
from screwkit import exercises, parallel, urdf, viewer
from screwkit import orientation as ori
from screwkit.ik.spherical_wrist import SphericalWristArm
from screwkit.ik.stanford import StanfordArm
from screwkit.ik.ur import URArm

Z, O = [0, 0, 1], [0, 0, 0]


@functools.cache
def wrist_arm():
    return SphericalWristArm.from_chain(puma())


@functools.cache
def ur_arm():
    return URArm.from_chain(ur5e())


@functools.cache
def stanford_arm():
    return StanfordArm.from_chain(stanford())


def system():
    return sk.ScrewSystem([sk.Twist.from_axis(Z, O, 0)])


PARALLEL = [
    row("fk-rho-str", lambda: stewart().fk("x"), TypeError, "rho"),
    row("fk-rho-short", lambda: stewart().fk([1.0] * 5), ValueError, "rho"),
    row(
        "fk-guess-3x3",
        lambda: stewart().fk([1.2] * 6, guess=np.eye(3)),
        ValueError,
        "guess",
    ),
    row("attachments-str", lambda: stewart().attachments("x"), TypeError, "T"),
    row("ik_all-3x3", lambda: stewart().ik_all(np.eye(3)), ValueError, "T"),
    row(
        "jacobian-mode",
        lambda: stewart().jacobian(stewart().home(), mode="zz"),
        ValueError,
        "mode",
    ),
    row("jacobian-3x3", lambda: stewart().jacobian(np.eye(3)), ValueError, "T"),
    row("limbs-str", lambda: stewart().limbs("x"), TypeError, "T"),
    row("wrenches-3x3", lambda: stewart().wrenches(np.eye(3)), ValueError, "T"),
    row("singularities-str", lambda: stewart().singularities("x"), TypeError, "T"),
    row("fk_all-str", lambda: rpr().fk_all("x"), TypeError, "rho"),
    row(
        "fk_all-seed", lambda: stewart().fk_all([1.2] * 6, seed="a"), TypeError, "seed"
    ),
    row(
        "ik-mode", lambda: stewart().ik(stewart().home(), mode="up"), ValueError, "mode"
    ),
    row(
        "workspace-x",
        lambda: stewart().workspace("x", [0.0]),
        TypeError,
        "x",
    ),
    row(
        "stewart_gough-height",
        lambda: parallel.stewart_gough(height="h"),
        TypeError,
        "height",
    ),
    row(
        "stewart_gough-limits",
        lambda: parallel.stewart_gough(leg_limits=((1, 0.5),) * 6),
        ValueError,
        "leg_limits",
    ),
    row(
        "planar_3rpr-base",
        lambda: parallel.planar_3rpr(base=[[0, 0]]),
        ValueError,
        "base",
    ),
    row(
        "stewart_fk_proven-base-shape",
        lambda: parallel.stewart_fk_proven([[0, 0, 0]], np.zeros((6, 3)), [1] * 6),
        ValueError,
        "base",
    ),
    row(
        "stewart_fk_proven-lengths-negative",
        lambda: parallel.stewart_fk_proven(
            np.eye(6, 3), np.eye(6, 3), [1, 1, 1, 1, 1, -1]
        ),
        ValueError,
        "lengths",
    ),
    row(
        "stewart_fk_proven-timeout-str",
        lambda: parallel.stewart_fk_proven(
            np.eye(6, 3), np.eye(6, 3), [1] * 6, timeout="1"
        ),
        TypeError,
        "timeout",
    ),
    row(
        "stewart_fk_proven-rationals",
        lambda: parallel.stewart_fk_proven(
            np.eye(6, 3), np.eye(6, 3), [1] * 6, rationals="float"
        ),
        ValueError,
        "rationals",
    ),
    row(
        "rpr_fk_proven-platform-str",
        lambda: parallel.rpr_fk_proven(np.eye(3, 2), "x", [1, 1, 1]),
        TypeError,
        "platform",
    ),
    row(
        "rpr_fk_proven-lengths-shape",
        lambda: parallel.rpr_fk_proven(np.eye(3, 2), np.eye(3, 2), [1, 1]),
        ValueError,
        "lengths",
    ),
    row(
        "stewart_fk_proven-platform-nan",
        lambda: parallel.stewart_fk_proven(
            np.eye(6, 3), np.full((6, 3), np.nan), [1] * 6
        ),
        ValueError,
        "platform",
    ),
    row(
        "stewart_fk_proven-lengths-shape",
        lambda: parallel.stewart_fk_proven(np.eye(6, 3), np.eye(6, 3), [1] * 5),
        ValueError,
        "lengths",
    ),
    row(
        "stewart_fk_proven-timeout-negative",
        lambda: parallel.stewart_fk_proven(
            np.eye(6, 3), np.eye(6, 3), [1] * 6, timeout=-1.0
        ),
        ValueError,
        "timeout",
    ),
    row(
        "stewart_fk_proven-rationals-not-str",
        lambda: parallel.stewart_fk_proven(
            np.eye(6, 3), np.eye(6, 3), [1] * 6, rationals=2
        ),
        TypeError,
        "rationals",
    ),
    row(
        "rpr_fk_proven-base-shape",
        lambda: parallel.rpr_fk_proven(np.eye(3), np.eye(3, 2), [1, 1, 1]),
        ValueError,
        "base",
    ),
    row(
        "rpr_fk_proven-lengths-zero",
        lambda: parallel.rpr_fk_proven(np.eye(3, 2), np.eye(3, 2), [1, 0, 1]),
        ValueError,
        "lengths",
    ),
    row(
        "rpr_fk_proven-rationals",
        lambda: parallel.rpr_fk_proven(
            np.eye(3, 2), np.eye(3, 2), [1, 1, 1], rationals="exact"
        ),
        ValueError,
        "rationals",
    ),
    row(  # a thousand digits, quoted in 80 characters
        "fk_all-starts-thousand-digits",
        lambda: stewart().fk_all([1.2] * 6, starts=-(10**1000)),
        ValueError,
        "starts",
    ),
    row(
        "fk_all-proof-str",
        lambda: stewart().fk_all([1.2] * 6, proof="yes"),
        TypeError,
        "proof",
    ),
    row(
        "fk_all-proof-rho-shape",
        lambda: stewart().fk_all(np.ones((2, 6)), proof=True),
        ValueError,
        "rho",
    ),
    row("planar_3rrr-l1", lambda: parallel.planar_3rrr(l1=-1), ValueError, "l1"),
    row("tripteron-L", lambda: parallel.tripteron(L="x"), TypeError, "L"),
    row(
        "delta-radius",
        lambda: parallel.delta(base_radius=-1),
        ValueError,
        "base_radius",
    ),
    # arguments that once slipped through unchecked
    row("fk-tol-str", lambda: stewart().fk([1.2] * 6, tol="1e-9"), TypeError, "tol"),
    row("fk-tol-nan", lambda: stewart().fk([1.2] * 6, tol=np.nan), ValueError, "tol"),
    row("fk-tol-negative", lambda: stewart().fk([1.2] * 6, tol=-1), ValueError, "tol"),
    row(
        "fk-max_iterations-float",
        lambda: stewart().fk([1.2] * 6, max_iterations=2.5),
        TypeError,
        "max_iterations",
    ),
    row(
        "fk-max_iterations-negative",
        lambda: stewart().fk([1.2] * 6, max_iterations=-3),
        ValueError,
        "max_iterations",
    ),
    # a pose with a free symbol is refused by the 3-RPR's ik and jacobian alike
    *(
        row(
            f"{method}-free-symbol",
            lambda method=method: getattr(rpr(), method)(
                sk.homogeneous(sk.rotz(sp.Symbol("t")))
            ),
            TypeError,
            "T",
            match="free symbol",
        )
        for method in ("ik", "jacobian")
    ),
    row(
        "ik-passive-str",
        lambda: stewart().ik(stewart().home(), passive="yes"),
        TypeError,
        "passive",
    ),
    row(
        "planar_3rpr-home-3x3",
        lambda: parallel.planar_3rpr(home=np.eye(3)),
        ValueError,
        "home",
    ),
    row(
        "planar_3rpr-home-tilted",
        lambda: parallel.planar_3rpr(home=sk.homogeneous(sk.rotx(0.3))),
        ValueError,
        "home",
    ),
    row(
        "fk_all-starts-huge",
        lambda: stewart().fk_all([1.2] * 6, starts=10**8),
        ValueError,
        "starts",
    ),
    row(
        "fk_all-starts-float",
        lambda: stewart().fk_all([1.2] * 6, starts=2.5),
        TypeError,
        "starts",
    ),
    row(
        "rpr_sextic-with_polynomial",
        lambda: parallel.rpr_sextic(rpr(), [1, 1, 1], with_polynomial="yes"),
        TypeError,
        "with_polynomial",
    ),
    row("tripteron-offset", lambda: parallel.tripteron(offset=0), ValueError, "offset"),
    row(
        "homogeneous-undefined-function",
        lambda: sk.homogeneous(
            sp.Matrix([[sp.Function("f")(sp.Symbol("t")), 0, 0], [0, 1, 0], [0, 0, 1]])
        ),
        TypeError,
        "R",
        match="undefined function",
    ),
]

ORIENTATION = [
    row(
        "rotation_from_euler-convention",
        lambda: ori.rotation_from_euler([0, 0, 0], convention="XXX"),
        ValueError,
        "convention",
    ),
    row(
        "rotation_from_euler-2",
        lambda: ori.rotation_from_euler([0, 0]),
        ValueError,
        "angles",
    ),
    row(
        "euler_from_rotation-4x4",
        lambda: ori.euler_from_rotation(np.eye(4)),
        ValueError,
        "R",
    ),
    row(
        "rotation_from_rpy-2", lambda: ori.rotation_from_rpy([1, 2]), ValueError, "rpy"
    ),
    row("rpy_from_rotation-str", lambda: ori.rpy_from_rotation("R"), TypeError, "R"),
    row(
        "rotation_from_quaternion-3",
        lambda: ori.rotation_from_quaternion([1, 0, 0]),
        ValueError,
        "q",
    ),
    row(
        "rotation_from_quaternion-zero",
        lambda: ori.rotation_from_quaternion([0, 0, 0, 0]),
        ValueError,
        "q",
    ),
    row(
        "quaternion_from_rotation-scaled",
        lambda: ori.quaternion_from_rotation(np.diag([2.0, 1, 1])),
        ValueError,
        "R",
    ),
    row(
        "quaternion_multiply-2",
        lambda: ori.quaternion_multiply([1, 0, 0, 0], [1, 0]),
        ValueError,
        "q",
    ),
    row("gimbal_lock-2x2", lambda: ori.gimbal_lock(np.eye(2)), ValueError, "R"),
    row(
        "gimbal_lock-convention",
        lambda: ori.gimbal_lock(np.eye(3), convention="ABC"),
        ValueError,
        "convention",
    ),
    row(
        "euler_rate_matrix-frame",
        lambda: ori.euler_rate_matrix([0, 0, 0], frame="world"),
        ValueError,
        "frame",
    ),
    row(
        "euler_rate_matrix-str",
        lambda: ori.euler_rate_matrix("abc"),
        TypeError,
        "angles",
    ),
]

URDF_AND_EXERCISES = [
    row("read_urdf-None", lambda: urdf.read_urdf(None), TypeError, "source"),
    row("read_urdf-broken", lambda: urdf.read_urdf("<robot"), ValueError, "source"),
    row(
        "data_file-unknown", lambda: urdf.data_file("nothing.urdf"), ValueError, "name"
    ),
    row("data_file-int", lambda: urdf.data_file(3), TypeError, "name"),
    row(
        "check-chapter", lambda: exercises.check("nope", 1, "1"), ValueError, "chapter"
    ),
    row(
        "check-number",
        lambda: exercises.check("parallel_kinematics", 99, "1"),
        ValueError,
        "number",
    ),
    row(
        "answer_box-chapter",
        lambda: exercises.answer_box("nope", 1),
        ValueError,
        "chapter",
    ),
    row(
        "answer_key-number",
        lambda: exercises.answer_key("parallel_kinematics", "x"),
        TypeError,
        "number",
    ),
    row("parse_answer-int", lambda: exercises.parse_answer(3), TypeError, "text"),
    row("variant-seed", lambda: exercises.variant("screws", 6, -1), ValueError, "seed"),
    row(
        "variant-number",
        lambda: exercises.variant("screws", 4, 1),
        ValueError,
        "number",
    ),
]

IK_ENGINES = [
    row("URArm.from_chain-puma", lambda: URArm.from_chain(puma()), ValueError, "chain"),
    row("URArm.from_chain-str", lambda: URArm.from_chain("ur5"), TypeError, "chain"),
    row("URArm.solve-3x3", lambda: ur_arm().solve(np.eye(3)), ValueError, "T"),
    row("URArm.measures-5", lambda: ur_arm().measures([0] * 5), ValueError, "q"),
    row("URArm.labels-str", lambda: ur_arm().labels("q"), TypeError, "q"),
    row(
        "URArm.reason-code", lambda: ur_arm().reason(np.eye(4), 99), ValueError, "code"
    ),
    row(
        "StanfordArm.from_chain-puma",
        lambda: StanfordArm.from_chain(puma()),
        ValueError,
        "chain",
    ),
    row("StanfordArm.solve-str", lambda: stanford_arm().solve("T"), TypeError, "T"),
    row(
        "StanfordArm.measures-7",
        lambda: stanford_arm().measures([0] * 7),
        ValueError,
        "q",
    ),
    row(
        "StanfordArm.labels-5", lambda: stanford_arm().labels([0] * 5), ValueError, "q"
    ),
    row(
        "StanfordArm.reason-str", lambda: stanford_arm().reason("T", 1), TypeError, "T"
    ),
    row(
        "SphericalWristArm.from_chain-planar",
        lambda: SphericalWristArm.from_chain(sk.robots.planar([1, 1])),
        ValueError,
        "chain",
    ),
    row(
        "SphericalWristArm.solve-3x3",
        lambda: wrist_arm().solve(np.eye(3)),
        ValueError,
        "T",
    ),
    row(
        "SphericalWristArm.measures-5",
        lambda: wrist_arm().measures([0] * 5),
        ValueError,
        "q",
    ),
    row(
        "SphericalWristArm.labels-str", lambda: wrist_arm().labels("q"), TypeError, "q"
    ),
    row(
        "SphericalWristArm.wrist_sine-str",
        lambda: wrist_arm().wrist_sine("a"),
        TypeError,
        "q5",
    ),
    row(
        "SphericalWristArm.reason-code",
        lambda: wrist_arm().reason(np.eye(4), 99),
        ValueError,
        "code",
    ),
]

SYSTEMS = [
    row("contains-short", lambda: system().contains([1, 2]), ValueError, "screw"),
    row(
        "contains-wrench",
        lambda: system().contains(sk.Wrench.from_axis(Z, O, 0)),
        TypeError,
        "screw",
    ),
    row("union-str", lambda: system().union("x"), TypeError, "other"),
    row("intersection-int", lambda: system().intersection(3), TypeError, "other"),
]

VIEWERS = [
    row("robot_viewer-str", lambda: viewer.robot_viewer("puma"), TypeError, "chain"),
    row(
        "robot_viewer-q5", lambda: viewer.robot_viewer(puma(), [0] * 5), ValueError, "q"
    ),
    row(
        "robot_viewer-size",
        lambda: viewer.robot_viewer(puma(), size=(0, 1)),
        ValueError,
        "size",
    ),
    row(
        "screw_motion_viewer-s",
        lambda: viewer.screw_motion_viewer([0, 0], O, 0),
        ValueError,
        "s",
    ),
    row(
        "trajectory_viewer-str",
        lambda: viewer.trajectory_viewer(puma(), "q"),
        TypeError,
        "paths",
    ),
    row(
        "trajectory_viewer-times",
        lambda: viewer.trajectory_viewer(puma(), np.zeros((3, 6)), times=[0, 2, 1]),
        ValueError,
        "times",
    ),
    row(
        "trajectory_viewer-chain",
        lambda: viewer.trajectory_viewer("puma", np.zeros((3, 6))),
        TypeError,
        "chain",
    ),
    row("show_platform-str", lambda: viewer.show_platform("pm"), TypeError, "pm"),
    row(
        "show_platform-yaw",
        lambda: viewer.show_platform(stewart(), yaw=-1),
        ValueError,
        "yaw",
    ),
    row(
        "show_platform-pose",
        lambda: viewer.show_platform(stewart(), pose=np.eye(3)),
        ValueError,
        "pose",
    ),
    row(
        "show_mechanism-str",
        lambda: viewer.show_mechanism("limbs"),
        ValueError,
        "limbs",
    ),
    row(
        "stepped_figure-draw",
        lambda: viewer.stepped_figure("draw", "x", values=[0, 1]),
        TypeError,
        "draw",
    ),
    row("grid-reversed", lambda: viewer.grid(1, 0, 0.1), ValueError, "low"),
    row("grid-step-zero", lambda: viewer.grid(0, 1, 0), ValueError, "step"),
    row(
        "html-library",
        lambda: viewer.robot_viewer(puma()).html(library=3),
        TypeError,
        "library",
    ),
    row(
        "page-title",
        lambda: viewer.robot_viewer(puma()).page(title=3),
        TypeError,
        "title",
    ),
]

PARALLEL_PACKAGE = [
    row(
        "rpr_sextic-not-rpr",
        lambda: parallel.rpr_sextic(stewart(), [1, 1, 1]),
        ValueError,
        "pm",
    ),
    row(
        "rpr_sextic-rho", lambda: parallel.rpr_sextic(rpr(), [1, 1]), ValueError, "rho"
    ),
    row(
        "draw_planar_platform-pm",
        lambda: parallel_plotting().draw_planar_platform("x"),
        TypeError,
        "pm",
    ),
    row(
        "draw_planar_platform-T",
        lambda: parallel_plotting().draw_planar_platform(rpr(), T="a"),
        TypeError,
        "T",
    ),
    row(
        "draw_spatial-pm", lambda: parallel_plotting().draw_spatial(3), TypeError, "pm"
    ),
    row(
        "draw_spatial-T",
        lambda: parallel_plotting().draw_spatial(stewart(), T=np.eye(3)),
        ValueError,
        "T",
    ),
    row(
        "draw_workspace-str",
        lambda: parallel_plotting().draw_workspace("w"),
        TypeError,
        "workspace",
    ),
]


def parallel_plotting():
    """screwkit.parallel.plotting, imported on first use (it loads matplotlib)."""
    from screwkit.parallel import plotting

    return plotting


ROWS = (
    PARALLEL_PACKAGE
    + PARALLEL
    + ORIENTATION
    + URDF_AND_EXERCISES
    + IK_ENGINES
    + SYSTEMS
    + VIEWERS
)
