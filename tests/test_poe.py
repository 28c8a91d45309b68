"""Chains from screws (product of exponentials): Modern Robotics' worked examples, DH =
PoE for every catalogue robot, helical joints by hand, exact = numeric, body Jacobians,
immutability."""

import numpy as np
import pytest
import sympy as sp
from builders import refusals

import screwkit as sk
from screwkit.transforms import rotx, rotz, transl

# Modern Robotics library examples (FKinSpace / FKinBody): a helical third joint of
# pitch 0.1.
M = np.array([[-1, 0, 0, 0], [0, 1, 0, 6], [0, 0, -1, 2], [0, 0, 0, 1.0]])
S_LIST = [[0, 0, 1, 4, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, -1, -6, 0, -0.1]]
B_LIST = [[0, 0, -1, 2, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 1, 0, 0, 0.1]]
THETA = [np.pi / 2, 3, np.pi]
T_EXPECTED = np.array(
    [[0, 1, 0, -5], [1, 0, 0, 4], [0, 0, -1, 1.68584073], [0, 0, 0, 1]]
)

# JacobianSpace / JacobianBody examples (the same four screws, read in either frame).
J_SCREWS = [
    [0, 0, 1, 0, 0.2, 0.2],
    [1, 0, 0, 2, 0, 3],
    [0, 1, 0, 0, 2, 1],
    [1, 0, 0, 0.2, 0.3, 0.4],
]
J_THETA = [0.2, 1.1, 0.1, 1.2]
JS_EXPECTED = np.array(
    [
        [0, 0.98006658, -0.09011564, 0.95749426],
        [0, 0.19866933, 0.4445544, 0.28487557],
        [1, 0, 0.89120736, -0.04528405],
        [0, 1.95218638, -2.21635216, -0.51161537],
        [0.2, 0.43654132, -2.43712573, 2.77535713],
        [0.2, 2.96026613, 3.23573065, 2.22512443],
    ]
)
JB_EXPECTED = np.array(
    [
        [-0.04528405, 0.99500417, 0, 1],
        [0.74359313, 0.09304865, 0.36235775, 0],
        [-0.66709716, 0.03617541, -0.93203909, 0],
        [2.32586047, 1.66809, 0.56410831, 0.2],
        [-1.44321167, 2.94561275, 1.43306521, 0.3],
        [-2.06639565, 1.82881722, -1.58868628, 0.4],
    ]
)


def test_modern_robotics_forward_kinematics_space_and_body():
    space = sk.Chain.from_screws(S_LIST, M)
    body = sk.Chain.from_screws(B_LIST, M, frame="body")
    assert space.joints == (sk.Joint.REVOLUTE, sk.Joint.PRISMATIC, sk.Joint.HELICAL)
    assert np.allclose(space.fk(THETA), T_EXPECTED, atol=1e-8)
    assert np.allclose(body.fk(THETA), T_EXPECTED, atol=1e-8)
    # z = 2 - 0.1 pi exactly: the helical joint advances 0.1 m/rad over pi, downwards
    assert abs(space.fk(THETA)[2, 3] - (2 - 0.1 * np.pi)) < 1e-14
    # the two descriptions are one robot: the body screws are the space screws moved by
    # M^-1
    assert np.allclose(space.body_screw_axes(), B_LIST, atol=1e-14)
    assert np.allclose(body.screw_axes(), S_LIST, atol=1e-14)


def test_modern_robotics_jacobians():
    space = sk.Chain.from_screws(J_SCREWS, np.eye(4))
    body = sk.Chain.from_screws(J_SCREWS, np.eye(4), frame="body")
    assert np.allclose(space.space_jacobian(J_THETA), JS_EXPECTED, atol=1e-8)
    assert np.allclose(body.body_jacobian(J_THETA), JB_EXPECTED, atol=1e-8)


def test_body_jacobian_is_the_adjoint_of_the_space_one_and_a_derivative():
    rng = np.random.default_rng(2)
    for chain in (
        sk.robots.puma560(),
        sk.Chain.from_screws(S_LIST, M, tool=transl(0.1, 0, 0.2)),
    ):
        for q in rng.uniform(-2, 2, (5, chain.n)):
            T = chain.fk(q)
            Js, Jb = chain.space_jacobian(q), chain.body_jacobian(q)
            assert np.allclose(Jb, sk.adjoint(sk.inv(T)) @ Js, atol=1e-12)
            # body twist of joint i: T^-1 dT/dq_i, by central differences
            h = 1e-6
            for i in range(chain.n):
                step = h * np.eye(chain.n)[i]
                dT = (chain.fk(q + step) - chain.fk(q - step)) / (2 * h)
                twist = sk.inv(T) @ dT
                assert np.allclose(
                    [twist[2, 1], twist[0, 2], twist[1, 0], *twist[:3, 3]],
                    Jb[:, i],
                    atol=1e-7,
                )


CATALOGUE = {  # built when a test asks for one, not at import
    "puma560": sk.robots.puma560,
    "kawasaki_cx210l": sk.robots.kawasaki_cx210l,
    "planar_3r": lambda: sk.robots.planar([0.4, 0.3, 0.2]),
    "two_arm_planar_0": lambda: sk.robots.two_arm_planar()[0],
    "two_arm_planar_1": lambda: sk.robots.two_arm_planar()[1],
    "modified_rpr": lambda: sk.Chain.from_table(
        [[0.3, 0.1, 0.4, 1.0], [0.5, 0.2, 0.5, -0.7], [0, -0.3, 0.2, 0.4]],
        joints="RPR",
        convention=sk.Convention.MODIFIED,
        base=transl(0.1, 0.2, 0.3) @ sk.homogeneous(rotx(0.5)),
        tool=transl(0, 0, 0.1),
    ),
}


@pytest.mark.parametrize("name", sorted(CATALOGUE))
def test_dh_and_product_of_exponentials_are_the_same_robot(name):
    chain = CATALOGUE[name]()
    space = sk.Chain.from_screws(chain.screw_axes(), chain.home())
    body = sk.Chain.from_screws(chain.body_screw_axes(), chain.home(), frame="body")
    Q = np.random.default_rng(11).uniform(-2, 2, (50, chain.n))
    for other in (space, body):
        assert np.allclose(other.fk(Q), chain.fk(Q), atol=1e-12)
        assert np.allclose(
            other.geometric_jacobian(Q), chain.geometric_jacobian(Q), atol=1e-12
        )
    assert np.allclose(chain.fk_poe(Q[0]), chain.fk(Q[0]), atol=1e-12)


def test_a_helical_joint_by_hand():
    # A screw along z through (1, 0, 0), pitch 0.05 m/rad; the tool sits at (2, 0, 0.3)
    # at home.
    h = 0.05
    chain = sk.Chain.from_screws(
        [sk.Twist.from_axis([0, 0, 1], [1, 0, 0], h)], transl(2, 0, 0.3)
    )
    for q in (-2.0, 0.4, 3.0):
        # the tool turns about the axis by q (radius 1 about (1, 0)) and rises h q
        expected = transl(1 + np.cos(q), np.sin(q), 0.3 + h * q) @ sk.homogeneous(
            rotz(q)
        )
        assert np.allclose(chain.fk([q]), expected, atol=1e-14)
    # its Jacobian column: angular z, linear velocity of the tool point = z x (p - r) +
    # h z
    J = chain.geometric_jacobian([0.4])
    assert np.allclose(J[:, 0], [-np.sin(0.4), np.cos(0.4), h, 0, 0, 1], atol=1e-14)


def test_exact_and_numeric_paths_agree():
    chain = sk.Chain.from_screws(S_LIST, M)
    T = chain.fk_symbolic()
    f = sp.lambdify([chain.q_symbols], T, "numpy")
    J = sk.jacobians.geometric_jacobian_symbolic(chain)
    g = sp.lambdify([chain.q_symbols], J, "numpy")
    for q in np.random.default_rng(4).uniform(-3, 3, (10, 3)):
        assert np.allclose(f(q), chain.fk(q), atol=1e-12)
        assert np.allclose(g(q), chain.geometric_jacobian(q), atol=1e-12)


def test_joint_twists_of_a_singular_puma_are_an_exact_screw_system():
    puma = sk.robots.puma560()
    q = [
        0,
        sp.pi / 4,
        -sp.pi / 2,
        sp.pi / 3,
        0,
        0,
    ]  # q5 = 0: joints 4 and 6 are aligned
    twists = puma.joint_twists(q)
    assert twists.rank == 5
    lost = twists.reciprocal()
    assert lost.rank == 1
    assert all(sp.simplify(t @ w) == 0 for t in twists.screws for w in lost.screws)
    # numerically: the space Jacobian's columns, rank 5 there, 6 elsewhere
    # float q: a ScrewSystem too (SVD rank), rank 5 there as NumPy's rank of the
    # Jacobian says
    q_float = np.array([0, 0.7, -1.5, 1.0, 0.0, 0])
    floats = puma.joint_twists(q_float)
    assert isinstance(floats, sk.ScrewSystem) and floats.rank == 5
    assert floats.reciprocal().rank == 1
    assert np.linalg.matrix_rank(puma.space_jacobian(q_float)) == 5
    assert np.allclose(
        np.array([list(t.vector) for t in floats.screws], dtype=float),
        puma.space_jacobian(q_float).T,
    )
    assert puma.joint_twists(np.array([0, 0.7, -1.5, 1.0, 0.5, 0])).rank == 6
    assert puma.joint_twists(np.zeros((3, 6))).shape == (3, 6, 6)


def test_chains_are_immutable_and_change_by_copy():
    puma = sk.robots.puma560()
    with pytest.raises(AttributeError, match="immutable"):
        puma.tool = transl(0, 0, 0.2)
    with pytest.raises(ValueError):
        puma.base[0, 3] = 1.0  # read-only arrays
    tool = transl(0, 0, 0.2)
    longer = puma.with_tool(tool)
    q = np.array([0.1, 0.5, -1.0, 0.3, 0.6, -0.2])
    assert np.allclose(longer.fk(q), puma.fk(q) @ tool)
    assert np.allclose(
        puma.fk(q), sk.robots.puma560().fk(q)
    )  # the original is unchanged
    moved = puma.with_base(transl(1, 0, 0))
    assert np.allclose(moved.fk(q)[:3, 3], puma.fk(q)[:3, 3] + [1, 0, 0])
    assert moved.configurations.keys() == puma.configurations.keys()
    # a caller's array is copied, never kept
    base = np.eye(4)
    chain = sk.Chain([sk.Link.revolute(a=1.0)], base=base)
    base[0, 3] = 5.0
    assert chain.fk([0.0])[0, 3] == 1.0
    assert float(chain.fk_symbolic()[0, 3].subs(chain.q_symbols[0], 0)) == 1.0


def test_from_table_accepts_its_own_limits_back():
    chain = sk.Chain.from_table(
        [[0, 0, 1, 0], [0, 0, 1, 0]], qlim=[[-1, 1], [-np.inf, np.inf]]
    )
    again = sk.Chain.from_table([[0, 0, 1, 0], [0, 0, 1, 0]], qlim=chain.qlim)
    assert np.array_equal(again.qlim, chain.qlim)
    assert again.links[1].qlim is None


def test_planar_rows_use_the_plane_of_the_chain():
    # a two-link arm whose base turns its plane to the world's x-z plane
    arm = sk.Chain(
        [sk.Link.revolute(a=1.0), sk.Link.revolute(a=1.0)],
        base=sk.homogeneous(rotx(np.pi / 2)),
    )
    q = [0.3, 1.1]
    assert (
        abs(arm.manipulability(q, rows="planar") - abs(np.sin(1.1))) < 1e-12
    )  # l1 l2 |sin q2|


test_bad_input_names_the_argument = refusals(
    [
        (
            lambda: sk.Chain.from_screws([[0, 0, 0, 0, 0, 0]], np.eye(4)),
            ValueError,
            r"axes\[0\].*zero twist",
        ),
        (
            lambda: sk.Chain.from_screws([[0, 0, 2, 0, 0, 0]], np.eye(4)),
            ValueError,
            r"axes\[0\].*\|omega\| = 1",
        ),
        (
            lambda: sk.Chain.from_screws([[0, 0, 0, 0, 0, 3]], np.eye(4)),
            ValueError,
            r"axes\[0\].*\|v\| = 1",
        ),
        (
            lambda: sk.Chain.from_screws([[0, 0, 1, 0, 0]], np.eye(4)),
            ValueError,
            r"axes\[0\] must be a 6-vector",
        ),
        (
            lambda: sk.Chain.from_screws([], np.eye(4)),
            ValueError,
            "axes must hold at least one",
        ),
        (
            lambda: sk.Chain.from_screws("z", np.eye(4)),
            TypeError,
            "axes must be a list",
        ),
        (
            lambda: sk.Chain.from_screws([[0, 0, 1, 0, 0, 0]], np.diag([1.0, 1, 2, 1])),
            ValueError,
            "home",
        ),
        (
            lambda: sk.Chain.from_screws([[0, 0, 1, 0, 0, 0]], np.eye(3)),
            ValueError,
            r"home must be one pose of shape \(4, 4\), got shape \(3, 3\)",
        ),
        (
            lambda: sk.Chain.from_screws([[0, 0, 1, 0, 0, 0]], np.eye(4), frame="bdy"),
            ValueError,
            "frame must be",
        ),
        (
            lambda: sk.Chain.from_screws(
                [[0, 0, 1, 0, 0, 0]], np.eye(4), qlim=[[0, 1], [0, 1]]
            ),
            ValueError,
            r"qlim must have shape \(1, 2\)",
        ),
        (
            lambda: sk.Chain.from_screws(
                [sk.Wrench.from_axis([0, 0, 1], [0, 0, 0], 0)], np.eye(4)
            ),
            TypeError,
            "Wrench",
        ),
        (
            lambda: sk.Chain.from_table([[0, 0, 1, 0]], qlim=[[1, 0]]),
            ValueError,
            r"qlim\[0\] must be a pair",
        ),
        (lambda: sk.Link.revolute(d=np.nan), ValueError, "d must be finite"),
        (lambda: sk.Link.revolute(a=np.inf), ValueError, "a must be finite"),
        (lambda: sk.Link.revolute(a="0.3"), TypeError, "a must be a real number"),
        (lambda: sk.Link("R", a=1), TypeError, "joint must be Joint"),
        (
            lambda: sk.Link.revolute().transform(0, convention="standard"),
            TypeError,
            "convention must be",
        ),
        (
            lambda: sk.Chain([sk.Link.revolute(a=sp.Symbol("a"))]).fk([0.0]),
            ValueError,
            "link 1's a",
        ),
        (
            lambda: sk.jacobians.manipulability("puma", [0, 0]),
            TypeError,
            "chain must be a screwkit Chain",
        ),
        (
            lambda: sk.jacobians.numerical_jacobian(
                sk.robots.planar([1, 1]), [0, 0], h=0
            ),
            ValueError,
            "h must be",
        ),
        (
            lambda: sk.robots.puma560().manipulability(np.zeros(6), rows="xy"),
            ValueError,
            "rows must be one of",
        ),
    ]
)


def test_the_lost_wrench_of_a_stretched_elbow_is_a_force_along_the_arm():
    puma = sk.robots.puma560()
    a3, d4 = sp.Rational("0.0203"), sp.Rational("0.4318")
    q = [
        0,
        0,
        sp.atan2(a3, d4) - sp.pi / 2,
        0,
        sp.pi / 2,
        0,
    ]  # a3 s3 + d4 c3 = 0 exactly
    twists = puma.joint_twists(q)
    lost = twists.reciprocal()
    assert (twists.rank, lost.rank) == (5, 1)
    wrench = lost.basis()[0]
    assert all(sp.simplify(t @ wrench) == 0 for t in twists.screws)
    # a pure force (zero moment about the shoulder at the origin) along the line to the
    # wrist centre
    f, m = np.array(wrench.vector, dtype=float).reshape(2, 3)
    wrist_centre = puma.fk(np.array([float(v) for v in q]))[:3, 3]
    assert np.allclose(m, 0) and np.allclose(np.cross(f, wrist_centre), 0, atol=1e-12)


def test_the_parameter_table_of_each_kind_of_chain():
    header, rows = sk.robots.puma560().table()
    assert header == ["joint", "θ (deg)", "d (m)", "a (m)", "α (deg)", "limits"]
    assert rows[2] == ["3 R", "q3", "0.15005", "0.0203", "-90", "[-225, 45]"]
    assert (
        sk.robots.kawasaki_cx210l().table()[1][1][1] == "q2 + 180"
    )  # the joint-2 offset
    header, rows = sk.Chain.from_screws(S_LIST, M).table()
    assert rows[2] == ["3 H", "(0, 0, -1)", "(-6, 0, -0.1)", "0.1", ""]
    assert (
        "<caption>PUMA 560: standard DH</caption>" in sk.robots.puma560()._repr_html_()
    )


def test_batch_cosines_and_sines_from_the_half_angle_tangent():
    import math

    from screwkit._compiled import cos_sin

    special = [
        0.0,
        np.pi / 2,
        -np.pi / 2,
        np.pi,
        -np.pi,
        1e-300,
        3 * np.pi,
        50.0,
        -1234.5,
    ]
    angles = np.concatenate([np.linspace(-4 * np.pi, 4 * np.pi, 100_001), special])
    c, s = cos_sin(angles)
    # against the C library's cos and sin, one angle at a time: within 3 units in the
    # last place
    assert max(abs(x - math.cos(t)) for x, t in zip(c, angles)) < 6e-16
    assert max(abs(x - math.sin(t)) for x, t in zip(s, angles)) < 6e-16
    puma = sk.robots.puma560()
    Q = np.random.default_rng(12).uniform(-np.pi, np.pi, (3000, 6))
    assert np.abs(puma.fk(Q) - np.array([puma.fk(q) for q in Q])).max() < 1e-14
