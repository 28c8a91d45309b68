"""Closed-form IK of UR-type arms (joints 2, 3, 4 parallel): all eight solutions, the
generating configuration among them, Hawkins's own formulas for q1 and q5, singular and
unreachable poses, and arms this closed form refuses."""

import numpy as np
import pytest
from builders import ur5e

import screwkit as sk
from screwkit import ik
from screwkit.ik.ur import STRUCTURE, URArm

RNG = np.random.default_rng(2013)
# a region of generic poses where all eight solutions exist (elbow bent, wrist forward)
LOW = np.array([-np.pi, -1.9, 1.4, -0.5, 0.4, -np.pi])
HIGH = np.array([np.pi, -1.1, 2.0, 2.5, 2.7, np.pi])


def residual(chain, q, T):
    return np.abs(chain.fk(q) - T).max()


def test_generating_configuration_is_among_eight_solutions():
    Q = RNG.uniform(LOW, HIGH, (200, 6))
    for q in Q:
        T = ur5e().fk(q)
        solutions = ik.analytic_ik(ur5e(), T)
        assert solutions.structure == STRUCTURE
        assert len(solutions) == 8
        assert [s.config for s in solutions] == list(ik.CONFIGURATIONS)
        for s in solutions:
            assert residual(ur5e(), s.q, T) <= 1e-9
            assert ik.configuration(ur5e(), s.q) == s.config  # labels round-trip
        distance = [np.abs(sk.wrap_angle(s.q - q)).max() for s in solutions]
        assert min(distance) < 1e-9


def test_any_configuration_is_found_where_it_is_not_singular():
    Q = RNG.uniform(-np.pi, np.pi, (2000, 6))
    S = ik.analytic_ik_all(ur5e(), ur5e().fk(Q))
    assert S.shape == (2000, 8, 6)
    difference = np.nan_to_num(S - Q[:, None], nan=np.pi)
    distance = np.abs(sk.wrap_angle(difference)).max(-1)
    assert np.all(distance.min(axis=1) < 1e-8)
    found = ~np.isnan(S[..., 0])
    poses = np.repeat(ur5e().fk(Q), 8, axis=0)[found.ravel()]
    errors = np.abs(ur5e().fk(S[found]) - poses).max(axis=(1, 2))
    assert errors.max() <= 1e-9


def test_hawkins_formulas_for_q1_and_q5():
    # Hawkins 2013, the equations of theta1 and theta5, with the UR5e's published d4, d6
    d4, d6 = 0.1333, 0.0996
    q = np.array([0.4, -1.3, 1.7, 0.2, 1.1, -0.6])
    T = ur5e().fk(q)
    p05 = T @ np.array([0, 0, -d6, 1])
    psi = np.arctan2(p05[1], p05[0])
    phi = np.arccos(d4 / np.hypot(p05[0], p05[1]))
    q1_expected = sk.wrap_angle(np.array([psi + phi, psi - phi]) + np.pi / 2)
    solutions = ik.analytic_ik(ur5e(), T)
    q1 = {round(float(s.q[0]), 9) for s in solutions}
    assert q1 == {round(float(v), 9) for v in q1_expected}
    for s in solutions:
        c1, s1 = np.cos(s.q[0]), np.sin(s.q[0])
        cos5 = (T[0, 3] * s1 - T[1, 3] * c1 - d4) / d6
        assert np.isclose(np.cos(s.q[4]), cos5, atol=1e-12)


def test_a_chain_from_screws_is_solved_the_same():
    urdf = sk.Chain.from_urdf(sk.urdf.data_file("ur5e.urdf"))
    tool = sk.transl(0.01, 0.02, 0.15) @ sk.homogeneous(sk.rotx(0.3))
    for chain in (urdf.with_tool(tool), ur5e().with_base(sk.transl(0.5, -0.2, 0.8))):
        q = np.array([-0.7, -1.5, 1.6, 0.8, 2.0, 0.3])
        T = chain.fk(q)
        solutions = ik.analytic_ik(chain, T)
        assert len(solutions) == 8 and ik.structure(chain) == STRUCTURE
        assert min(np.abs(sk.wrap_angle(s.q - q)).max() for s in solutions) < 1e-9
        assert max(residual(chain, s.q, T) for s in solutions) <= 1e-9


def test_wrist_singularity_is_an_answer():
    # q5 = 0: axis 6 parallel to axes 2-4, four parallel joints for three planar
    # freedoms: a one-parameter family of solutions; the solver takes q6 = 0
    q = np.array([0.3, -1.2, 1.5, 0.4, 0.0, 0.5])
    T = ur5e().fk(q)
    solutions = ik.analytic_ik(ur5e(), T)
    assert solutions and all(residual(ur5e(), s.q, T) <= 1e-9 for s in solutions)
    singular = [s for s in solutions if "wrist" in s.singular]
    assert singular and all(s.q[5] == 0 for s in singular)
    # the generating shoulder branch is singular, the other one is not
    assert len(singular) == 4 and all(abs(s.q[0] - q[0]) < 1e-9 for s in singular)
    # the answer's reason says so too, not only the solutions' flags
    assert "4 of the" in solutions.reason and "continuum" in solutions.reason


def test_elbow_singularity_is_an_answer():
    q = np.array([0.3, -1.0, 0.0, 0.4, 1.2, 0.5])  # stretched: q3 = 0
    T = ur5e().fk(q)
    solutions = ik.analytic_ik(ur5e(), T)
    stretched = [s for s in solutions if "elbow" in s.singular]
    assert stretched and all(residual(ur5e(), s.q, T) <= 1e-9 for s in solutions)
    assert min(np.abs(sk.wrap_angle(s.q - q)).max() for s in solutions) < 1e-6


def test_out_of_reach_is_an_empty_answer_with_a_reason():
    far = sk.transl(2.0, 0.0, 0.3)
    solutions = ik.analytic_ik(ur5e(), far)
    assert solutions == [] and "reach" in solutions.reason
    near_axis = sk.transl(0.0, 0.05, 0.3)  # closer to axis 1 than the shoulder offset
    answer = ik.analytic_ik(ur5e(), near_axis)
    assert answer == [] and "shoulder offset" in answer.reason
    assert np.isnan(ik.analytic_ik_all(ur5e(), far)).all()


@pytest.mark.parametrize(
    "build",
    [sk.robots.panda, sk.robots.iiwa14, lambda: sk.robots.planar([1.0, 1.0, 1.0])],
    ids=["panda", "iiwa14", "planar_3r"],
)
def test_other_arms_are_refused_naming_the_structures(build):
    chain = build()
    with pytest.raises(ValueError, match="none of the structures") as error:
        ik.analytic_ik(chain, np.eye(4))
    assert "UR-type" in str(error.value) and "spherical wrist" in str(error.value)
    assert "must have 6 joints" in str(error.value)


def test_a_ur_with_joint_4_not_parallel_is_refused_by_the_ur_engine():
    """The UR engine refuses it; analytic_ik solves it as another class of 6R."""
    links = list(ur5e().links)
    links[2] = sk.Link.revolute(a=-0.3922, alpha=0.2)
    chain = sk.Chain(links)
    with pytest.raises(ValueError, match="parallel axes for joints 2, 3 and 4"):
        URArm.from_chain(chain)
    q = np.array([0.4, -1.3, 1.7, 0.2, 1.1, -0.6])
    solutions = ik.analytic_ik(chain, chain.fk(q))
    assert solutions.structure != STRUCTURE
    assert any(np.allclose(sk.wrap_angle(s.q - q), 0, atol=1e-8) for s in solutions)


def test_puma_is_still_the_spherical_wrist_structure():
    assert ik.structure(sk.robots.puma560()).startswith("spherical wrist")
