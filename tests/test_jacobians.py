"""Jacobians: finite differences of FK, the change of reference point, the factorised
determinant, manipulability and its ellipsoid against closed forms, singular
configurations, bad input."""

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit import jacobians


def mixed(convention):
    """A chain with a prismatic joint, a base and a tool, in either DH convention."""
    links = [
        sk.Link.revolute(d=0.3, a=0.2, alpha=0.4),
        sk.Link.prismatic(a=0.1, alpha=-1.2),
        sk.Link.revolute(a=0.3, alpha=1.0),
    ]
    if convention == "standard":
        return sk.Chain(
            links,
            base=sk.transl(0.1, 0.2, 0.3) @ sk.homogeneous(sk.rotx(0.5)),
            tool=sk.transl(0.1, 0, 0.2),
        )
    return sk.Chain(
        links,
        convention=sk.Convention.MODIFIED,
        tool=sk.transl(0.1, 0, 0.2) @ sk.homogeneous(sk.roty(0.3)),
    )


ARMS = ["puma", "kawasaki", "mixed standard", "mixed modified"]


@pytest.fixture
def chain(request, puma, kawasaki):
    """The arm named by the test's parameter, built on first use."""
    name = request.param
    return {"puma": puma, "kawasaki": kawasaki}.get(name) or mixed(name.split()[1])


@pytest.mark.parametrize("chain", ARMS, indirect=True)
def test_geometric_jacobian_equals_finite_differences(chain):
    # numerical_jacobian differences FK: independent of the joint axes the geometric
    # Jacobian uses
    Q = np.random.default_rng(1).uniform(-2, 2, (10, chain.n))
    for q in Q:
        # central differences with h = 1e-6 are exact to O(h^2) ~ 1e-12 times the third
        # derivative
        assert np.allclose(
            chain.geometric_jacobian(q),
            jacobians.numerical_jacobian(chain, q),
            atol=1e-9,
        )
    # the batch gives the same as one configuration at a time
    assert np.allclose(
        chain.geometric_jacobian(Q),
        [chain.geometric_jacobian(q) for q in Q],
        atol=1e-14,
    )


@pytest.mark.parametrize("chain", ARMS, indirect=True)
def test_space_jacobian_is_the_geometric_one_moved_to_the_base_origin(chain):
    Q = np.random.default_rng(2).uniform(-3, 3, (50, chain.n))
    Jg, Js = chain.geometric_jacobian(Q), chain.space_jacobian(Q)
    p = chain.fk(Q)[:, :3, 3]
    omega, v_origin = Js[:, :3], Js[:, 3:]
    # the end-effector point's velocity: v_p = v_origin + omega x p
    v_point = v_origin + np.cross(np.swapaxes(omega, 1, 2), p[:, None, :]).swapaxes(
        1, 2
    )
    assert np.allclose(Jg[:, :3], v_point, atol=1e-9)
    assert np.allclose(Jg[:, 3:], omega, atol=1e-12)
    # at q = 0 the space Jacobian's columns are the screw axes of the product of
    # exponentials
    assert np.allclose(
        chain.space_jacobian(np.zeros(chain.n)).T, chain.screw_axes(), atol=1e-12
    )


def test_puma_determinant_factorises_into_shoulder_elbow_and_wrist(puma):
    q2, q3, q5 = puma.q_symbols[1], puma.q_symbols[2], puma.q_symbols[4]
    a2, a3, d4 = sp.symbols("a2 a3 d4", positive=True)
    det = jacobians.determinant_symbolic(puma, point=4, symbolic_lengths=True)
    # the textbook result (e.g. Siciliano et al. 2009, sec. 3.3): elbow, shoulder and
    # wrist factors
    expected = (
        a2
        * (a3 * sp.sin(q3) + d4 * sp.cos(q3))
        * (a2 * sp.cos(q2) + a3 * sp.cos(q2 + q3) - d4 * sp.sin(q2 + q3))
        * sp.sin(q5)
    )
    assert sp.simplify(det - expected) == 0
    numeric = sp.lambdify(puma.q_symbols, det.subs(puma.length_symbols()))
    for q in np.random.default_rng(3).uniform(-3, 3, (20, 6)):
        assert np.isclose(
            numeric(*q), np.linalg.det(puma.geometric_jacobian(q)), atol=1e-12
        )


def test_kawasaki_determinant_and_its_elbow_singularity(kawasaki):
    det = jacobians.determinant_symbolic(kawasaki, point=4)
    numeric = sp.lambdify(kawasaki.q_symbols, det)
    for q in np.random.default_rng(4).uniform(-3, 3, (20, 6)):
        assert np.isclose(
            numeric(*q), np.linalg.det(kawasaki.geometric_jacobian(q)), atol=1e-9
        )
    # the wrist centre lies on the line of the upper arm when a3 sin q3 + d4 cos q3 = 0
    elbow = np.arctan2(-1.19, 0.3)  # -75.85 deg
    assert np.isclose(np.degrees(elbow), -75.85, atol=0.005)
    q = np.radians([0, 60, 0, 10, 90, 0])
    q[2] = elbow
    assert jacobians.rank(kawasaki, q) == 5 and kawasaki.manipulability(q) == 0.0
    q[2] = np.radians(
        -78.15
    )  # the paper's planar answer is not singular for the 6R arm
    assert jacobians.rank(kawasaki, q) == 6 and kawasaki.manipulability(q) > 0.01


def test_kawasaki_reproduces_the_papers_matlab_poses(kawasaki):
    # Table 2, MATLAB column (mm), printed to 0.1 mm
    table2 = {
        "table2_1": (-2114.7, 0, 1597.7),
        "table2_2": (-2015.0, 0, 1831.2),
        "table2_3": (-1876.4, 0, 2043.8),
    }
    for name, expected in table2.items():
        position = kawasaki.fk(kawasaki.configurations[name])[:3, 3] * 1000
        assert np.allclose(position, expected, atol=0.05), name


def test_symbolic_jacobian_equals_the_numeric_one(puma):
    for chain in (puma, mixed("modified")):
        J = sp.lambdify(chain.q_symbols, jacobians.geometric_jacobian_symbolic(chain))
        for q in np.random.default_rng(5).uniform(-2, 2, (5, chain.n)):
            assert np.allclose(J(*q), chain.geometric_jacobian(q), atol=1e-12)


def test_manipulability_and_ellipsoid_of_a_two_link_arm_match_closed_forms():
    l1, l2 = 0.7, 0.4
    arm = sk.robots.planar([l1, l2])
    Q = np.random.default_rng(6).uniform(-3, 3, (100, 2))
    # w = |det J| = l1 l2 |sin q2| for the 2 x 2 planar Jacobian
    assert np.allclose(
        arm.manipulability(Q, rows="planar"),
        l1 * l2 * np.abs(np.sin(Q[:, 1])),
        atol=1e-12,
    )
    assert np.allclose(
        arm.manipulability(Q, rows="position"),
        l1 * l2 * np.abs(np.sin(Q[:, 1])),
        atol=1e-12,
    )
    # unit links at q2 = 90 deg: J J^T = [[2, 1], [1, 1]] up to a rotation, radii the
    # golden ratio and its inverse
    unit = sk.robots.planar([1.0, 1.0])
    centre, radii, axes = jacobians.ellipsoid(unit, [0.3, np.pi / 2])
    golden = (1 + np.sqrt(5)) / 2
    assert np.allclose(radii, [golden, 1 / golden, 0.0], atol=1e-12)
    assert np.allclose(
        centre, [np.cos(0.3) - np.sin(0.3), np.sin(0.3) + np.cos(0.3), 0], atol=1e-12
    )
    assert np.allclose(axes.T @ axes, np.eye(3), atol=1e-12)
    # the condition number is the ratio of the radii
    assert np.isclose(
        jacobians.condition_number(unit, [0.3, np.pi / 2], rows="planar"), golden**2
    )


def test_singular_configurations_are_answers(puma):
    wrist_singular = np.array(
        [0.1, 0.5, -0.4, 0.3, 0.0, 0.2]
    )  # q5 = 0: axes 4 and 6 aligned
    assert puma.manipulability(wrist_singular) == 0.0
    assert jacobians.rank(puma, wrist_singular) == 5
    assert jacobians.condition_number(puma, wrist_singular) == np.inf
    stretched = sk.robots.planar([1.0, 1.0, 1.0])
    assert stretched.manipulability(np.zeros(3), rows="planar") == 0.0
    assert np.all(stretched.manipulability(np.zeros((4, 3)), rows="planar") == 0.0)


def test_bad_input_is_a_clear_error(puma):
    with pytest.raises(ValueError, match="q must have 6 entries"):
        puma.geometric_jacobian(np.zeros(5))
    with pytest.raises(ValueError, match="finite"):
        puma.geometric_jacobian([0, np.nan, 0, 0, 0, 0])
    with pytest.raises(TypeError, match="number or an array of numbers"):
        puma.manipulability("home")
    with pytest.raises(ValueError, match="rows must be one of"):
        puma.manipulability(np.zeros(6), rows="linear")
    with pytest.raises(ValueError, match="one configuration"):
        jacobians.ellipsoid(puma, np.zeros((2, 6)))
    with pytest.raises(ValueError, match="one configuration"):
        jacobians.numerical_jacobian(puma, np.zeros((2, 6)))
    with pytest.raises(ValueError, match="6 joints"):
        jacobians.determinant_symbolic(sk.robots.planar([1, 1]))
    with pytest.raises(ValueError, match="lengths must be two or more positive"):
        sk.robots.planar([1.0, -1.0])
