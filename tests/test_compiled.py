"""screwkit._compiled: the straight-line code generated from a chain's numbers, checked
against independent routes (exp_twist products, hand-derived poses)."""

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit import _compiled
from screwkit._compiled import Program, Term, exponential_coefficients


def test_term_algebra_and_text():
    a, b = Term(2.0, ("c1",)), Term(-0.5, ("s2", "e3"))
    product = a.times(b)
    assert product == Term(-1.0, ("c1", "s2", "e3"))
    assert product.text() == "-1.0*c1*s2*e3"
    assert product.magnitude_text() == "c1*s2*e3"
    assert Term(1.0, ("e4",)).text() == "e4" and a.negated() == Term(-2.0, ("c1",))


@pytest.mark.parametrize(
    "twist",
    [[0, 0, 1, 0, 0, 0], [0, 0, 0, 0.6, 0, 0.8], [0.6, 0.8, 0, 1.0, -0.75, 2.0]],
)
def test_exponential_coefficients_give_exp_twist(twist):
    """exp([X] theta) = K1 + Kc cos + Ks sin + Kt theta, against
    transforms.exp_twist."""
    K1, Kc, Ks, Kt = exponential_coefficients(np.array(twist, dtype=float))
    for theta in (-2.0, 0.3, 1.7):
        expected = sk.exp_twist(twist, theta)
        got = K1 + Kc * np.cos(theta) + Ks * np.sin(theta) + Kt * theta
        assert np.allclose(got, expected, atol=1e-14)


def test_program_pose_is_the_product_of_exponentials(rng):
    """A made-up program C0 exp(X1 t1) C1 exp(X2 t2) C2 run as generated code, against
    the product written with exp_twist."""
    C = [
        sk.transl(*rng.normal(size=3))
        @ sk.homogeneous(sk.rot_axis(rng.normal(size=3), 0.7))
        for _ in range(3)
    ]
    w = rng.normal(size=3)
    w /= np.linalg.norm(w)
    X = [np.r_[w, np.cross(rng.normal(size=3), w)], np.r_[0, 0, 0, 0, 0.6, 0.8]]
    program = Program(C[0], [(X[0], C[1], np.zeros(3)), (X[1], C[2], np.zeros(3))])
    pose = program.compile("pose")
    for t in rng.uniform(-3, 3, (5, 2)):
        expected = (
            C[0] @ sk.exp_twist(X[0], t[0]) @ C[1] @ sk.exp_twist(X[1], t[1]) @ C[2]
        )
        got = np.reshape(_compiled.evaluate(pose, t), (3, 4))
        assert np.allclose(got, expected[:3], atol=1e-12)


def test_source_of_a_planar_arm_by_hand():
    """Rz(q1) Tx(l1) Rz(q2) Tx(l2): x = l1 c1 + l2 c12, y = l1 s1 + l2 s12."""
    arm = sk.robots.planar([1.5, 0.5])
    namespace = {}
    exec(arm.source("pose"), namespace)
    q = np.array([0.4, -1.1])
    entries = namespace["kinematics"](list(q), list(np.cos(q)), list(np.sin(q)))
    assert np.isclose(entries[3], 1.5 * np.cos(0.4) + 0.5 * np.cos(-0.7))
    assert np.isclose(entries[7], 1.5 * np.sin(0.4) + 0.5 * np.sin(-0.7))


@pytest.mark.parametrize("outputs", ["pose", "frames", "space", "geometric", "axes"])
def test_chain_source_is_what_the_chain_runs(puma, outputs):
    source = puma.source(outputs)
    assert source.startswith("def kinematics(t, c, s):\n")
    namespace = {}
    exec(source, namespace)
    q = np.array([0.3, -0.5, 0.9, 1.2, -0.4, 2.0])
    offsets = puma._program[1]
    t = q + offsets
    values = np.array(
        namespace["kinematics"](list(t), list(np.cos(t)), list(np.sin(t)))
    )
    if outputs == "pose":
        assert np.allclose(values.reshape(3, 4), puma.fk(q)[:3], atol=1e-14)
    elif outputs == "space":
        assert np.allclose(values.reshape(6, 6), puma.space_jacobian(q), atol=1e-14)
    elif outputs == "geometric":
        assert np.allclose(
            values.reshape(6, 6), sk.jacobians.numerical_jacobian(puma, q), atol=1e-7
        )
    assert (
        len(values)
        == {
            "pose": 12,
            "frames": 12 * 7,
            "space": 36,
            "geometric": 36,
            "axes": 9 * 6 + 12,
        }[outputs]
    )


def test_chain_source_refuses_an_unknown_output(puma):
    with pytest.raises(ValueError, match="outputs must be one of 'pose'"):
        puma.source("jacobian")
    with pytest.raises(TypeError, match="outputs must be one of"):
        puma.source(3)


def test_in_chunks_concatenates_and_fills(monkeypatch):
    monkeypatch.setattr(_compiled, "CHUNK", 3)
    batch = np.arange(10.0)[:, None]
    assert np.array_equal(_compiled.in_chunks(batch, lambda part: 2 * part), 2 * batch)
    out = np.empty((10, 1))
    assert _compiled.in_chunks(batch, lambda part: part + 1, out) is out
    assert np.array_equal(out, batch + 1)


def test_exact_model_numbers_are_snapped():
    """alpha = pi/2 given exactly generates no 6e-17 terms: the source has no tiny
    numbers."""
    arm = sk.Chain([sk.Link.revolute(alpha=sp.pi / 2, a=1.0), sk.Link.revolute(a=1.0)])
    assert "e-1" not in arm.source("pose")
