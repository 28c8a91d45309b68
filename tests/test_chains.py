"""DH chains: FK against independent closed forms, the paper's named poses, PoE,
conventions."""

import numpy as np
import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from references import A2, A3, D3, D4, Rx, Ry, Rz, dh_standard

import screwkit as sk
from screwkit.transforms import rotx, transl

joint_vectors = arrays(float, 6, elements=st.floats(-np.pi, np.pi, allow_nan=False))


def puma_by_hand(q):
    """The PUMA 560 pose derived by hand: the wrist centre from the arm's plane, and R =
    Rz(q1) Rx(90) Rz(q2 + q3) Rx(-90) . Rz(q4) Ry(-q5) Rz(q6) (the wrist's Z-Y-Z
    angles)."""
    q1, q2, q3, q4, q5, q6 = q
    reach = A2 * np.cos(q2) + A3 * np.cos(q2 + q3) - D4 * np.sin(q2 + q3)
    height = A2 * np.sin(q2) + A3 * np.sin(q2 + q3) + D4 * np.cos(q2 + q3)
    p = [
        np.cos(q1) * reach + np.sin(q1) * D3,
        np.sin(q1) * reach - np.cos(q1) * D3,
        height,
    ]
    R = (
        Rz(q1)
        @ Rx(np.pi / 2)
        @ Rz(q2 + q3)
        @ Rx(-np.pi / 2)
        @ Rz(q4)
        @ Ry(-q5)
        @ Rz(q6)
    )
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    return T


@settings(max_examples=300, deadline=None)
@given(joint_vectors)
def test_puma_fk_equals_hand_derivation(puma, q):
    assert np.allclose(puma.fk(q), puma_by_hand(q), atol=1e-12, rtol=0)


def test_batch_fk_equals_single_fk(puma):
    Q = np.random.default_rng(3).uniform(-np.pi, np.pi, (200, 6))
    batch = puma.fk(Q)
    assert batch.shape == (200, 4, 4)
    assert np.allclose(
        batch, np.stack([puma_by_hand(q) for q in Q]), atol=1e-12, rtol=0
    )


def test_named_poses(puma):
    # zero: upper arm along x, forearm up: (a2 + a3, -d3, d4); the paper prints z =
    # 0.4381 (digits swapped)
    assert np.allclose(
        puma.fk(puma.configurations["zero"]), transl(A2 + A3, -D3, D4), atol=1e-12
    )
    # ready: arm vertical: (a3, -d3, a2 + d4)
    assert np.allclose(
        puma.fk(puma.configurations["ready"]), transl(A3, -D3, A2 + D4), atol=1e-12
    )
    # stretch (q3 = -90) and nominal (q2 = 45, q3 = -180, q5 = 45): the tool's z is
    # along x0 and its x along -z0 (the paper prints a stray 1 at r11). By hand, the
    # reach along x is a2 c2 + a3 c23 - d4 s23 and the height a2 s2 + a3 s23 + d4 c23.
    R = np.array([[0, 0, 1], [0, 1, 0], [-1, 0, 0]])
    h = np.sqrt(0.5)
    expected = {
        "stretch": [A2 + D4, -D3, -A3],
        "nominal": [h * (A2 - A3 + D4), -D3, h * (A2 - A3 - D4)],
    }
    for name, p in expected.items():
        T = puma.fk(puma.configurations[name])
        assert np.allclose(T[:3, :3], R, atol=1e-12)
        assert np.allclose(T[:3, 3], p, atol=1e-12)
    # the paper's eq. 35 rounds the nominal position to (0.5963, -0.1501, -0.01435)
    assert np.allclose(expected["nominal"], [0.5963, -0.1501, -0.01435], atol=6e-5)


def test_symbolic_fk_lambdified_equals_numeric(puma):
    T = puma.fk_symbolic()
    f = sp.lambdify([puma.q_symbols], T, "numpy")
    for q in np.random.default_rng(4).uniform(-3, 3, (20, 6)):
        assert np.allclose(f(q), puma.fk(q), atol=1e-12)


def test_symbolic_fk_in_textbook_notation(puma):
    T = puma.fk_symbolic(symbolic_lengths=True)
    c1, s1, c2 = sp.symbols("c1 s1 c2")
    c23, s23 = sp.Symbol("c_{23}"), sp.Symbol("s_{23}")
    a2, a3, d3, d4 = sp.symbols("a2 a3 d3 d4", positive=True)
    assert (
        sp.expand(sk.textbook(T[2, 3]) - (a2 * sp.Symbol("s2") + a3 * s23 + d4 * c23))
        == 0
    )
    assert (
        sp.expand(
            sk.textbook(T[0, 3]) - (c1 * (a2 * c2 + a3 * c23 - d4 * s23) + d3 * s1)
        )
        == 0
    )


def test_product_of_exponentials_equals_dh(puma):
    for q in np.random.default_rng(5).uniform(-3, 3, (20, 6)):
        assert np.allclose(puma.fk_poe(q), puma.fk(q), atol=1e-12)
    # screw axes at home: joint 1 is the z axis through the origin
    assert np.allclose(puma.screw_axes()[0], [0, 0, 1, 0, 0, 0])


def random_chain(seed, convention=sk.Convention.STANDARD):
    rng = np.random.default_rng(seed)
    links = [
        sk.Link.revolute(
            d=rng.uniform(-1, 1),
            a=rng.uniform(-1, 1),
            alpha=rng.uniform(-3, 3),
            offset=rng.uniform(-1, 1),
        ),
        sk.Link.prismatic(
            theta=rng.uniform(-3, 3),
            a=rng.uniform(-1, 1),
            alpha=rng.uniform(-3, 3),
            offset=rng.uniform(-1, 1),
        ),
        sk.Link.revolute(
            d=rng.uniform(-1, 1), a=rng.uniform(-1, 1), alpha=rng.uniform(-3, 3)
        ),
    ]
    return links


def dh_by_hand(links, q, base=None, tool=None):
    base = np.eye(4) if base is None else base
    tool = np.eye(4) if tool is None else tool
    T = base
    for link, qi in zip(links, q):
        if link.joint is sk.Joint.REVOLUTE:
            theta, d = qi + link.offset, link.d
        else:
            theta, d = link.theta, qi + link.offset
        T = T @ dh_standard(float(theta), float(d), float(link.a), float(link.alpha))
    return T @ tool


def test_general_chain_fk_poe_and_batch():
    links = random_chain(6)
    base, tool = transl(0.1, -0.2, 0.3) @ sk.homogeneous(rotx(0.4)), transl(0, 0, 0.2)
    chain = sk.Chain(links, base=base, tool=tool)
    Q = np.random.default_rng(7).uniform(-2, 2, (30, 3))
    expected = np.stack([dh_by_hand(links, q, base, tool) for q in Q])
    assert np.allclose(chain.fk(Q), expected, atol=1e-12)
    assert np.allclose(chain.fk(Q[0]), expected[0], atol=1e-12)
    assert np.allclose(chain.frames(Q)[:, -1], expected, atol=1e-12)
    assert np.allclose(chain.fk_poe(Q[0]), expected[0], atol=1e-12)


def test_modified_dh_describes_the_same_arm():
    # Tx(a) and Rx(alpha) commute, so a standard chain is the modified chain whose link
    # i carries alpha_{i-1}, a_{i-1}, with Tx(a_n) Rx(alpha_n) as tool.
    links = random_chain(8)
    standard = sk.Chain(links)
    shifted = [
        sk.Link(
            k.joint,
            d=k.d,
            theta=k.theta,
            offset=k.offset,
            a=links[i - 1].a if i else 0,
            alpha=links[i - 1].alpha if i else 0,
        )
        for i, k in enumerate(links)
    ]
    tool = transl(links[-1].a, 0, 0) @ sk.homogeneous(rotx(links[-1].alpha))
    modified = sk.Chain(shifted, sk.Convention.MODIFIED, tool=tool)
    Q = np.random.default_rng(9).uniform(-2, 2, (20, 3))
    assert np.allclose(modified.fk(Q), standard.fk(Q), atol=1e-12)
    assert np.allclose(modified.fk_poe(Q[0]), standard.fk(Q[0]), atol=1e-12)


def test_from_table_and_limits(puma):
    chain = sk.Chain.from_table(
        [[0, 0.1, 0.3, 0], [0.5, 0.2, 0.5, np.pi / 2]],
        joints="RP",
        qlim=[[-1, 1], [0, 0.5]],
    )
    assert chain.joints == (sk.Joint.REVOLUTE, sk.Joint.PRISMATIC)
    assert chain.within_limits([0.5, 0.2]) and not chain.within_limits([0.5, 0.7])
    assert np.allclose(
        chain.fk([0.0, 0.1])[:3, 3],
        [0.3 + 0.5 * np.cos(0.5), 0.5 * np.sin(0.5), 0.1 + 0.3],
    )
    assert np.allclose(
        puma.within_limits(
            np.array([puma.configurations["ready"], [0, 4, 0, 0, 0, 0]])
        ),
        [True, False],
    )


@pytest.mark.parametrize(
    "q, message",
    [
        (np.zeros(5), r"q must have 6 entries for this chain.*got shape \(5,\)"),
        (np.zeros((3, 7)), r"q must have 6 entries"),
        ([0, 0, np.nan, 0, 0, 0], "q must be finite"),
    ],
)
def test_bad_joint_vectors(q, message, puma):
    with pytest.raises(ValueError, match=message):
        puma.fk(q)


def test_bad_tables_and_links():
    with pytest.raises(ValueError, match=r"table must have shape \(n, 4\)"):
        sk.Chain.from_table(np.zeros((6, 3)))
    with pytest.raises(ValueError, match="joints must name 2 joints"):
        sk.Chain.from_table(np.zeros((2, 4)), joints="RRR")
    with pytest.raises(TypeError, match="links must be a non-empty list of Link"):
        sk.Chain([])
    with pytest.raises(TypeError, match="convention must be a Convention"):
        sk.Chain([sk.Link.revolute()], convention="modified")
    with pytest.raises(ValueError, match="qlim must be a pair"):
        sk.Link.revolute(qlim=(1, -1))
    with pytest.raises(ValueError, match="must be a rotation matrix"):
        sk.Chain([sk.Link.revolute()], base=np.diag([2.0, 1, 1, 1]))
