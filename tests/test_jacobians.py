"""Geometric and space Jacobians: finite differences of FK, and the change of reference point."""
import numpy as np

import screwkit as sk

PUMA = sk.robots.puma560()


def finite_difference_jacobian(chain, q, h=1e-6):
    """Rows [v; omega] from central differences of FK (omega from the skew part of dR R^T)."""
    columns = []
    for i in range(chain.n):
        dq = np.zeros(chain.n)
        dq[i] = h
        plus, minus = chain.fk(q + dq), chain.fk(q - dq)
        v = (plus[:3, 3] - minus[:3, 3]) / (2 * h)
        W = (plus[:3, :3] - minus[:3, :3]) / (2 * h) @ chain.fk(q)[:3, :3].T
        columns.append(np.concatenate([v, [W[2, 1], W[0, 2], W[1, 0]]]))
    return np.array(columns).T


def test_geometric_jacobian_equals_finite_differences():
    chains = [PUMA, sk.Chain([sk.Link.revolute(d=0.3, a=0.2, alpha=0.4), sk.Link.prismatic(a=0.1, alpha=-1.2),
                              sk.Link.revolute(a=0.3, alpha=1.0)], tool=sk.transl(0.1, 0, 0.2))]
    for chain in chains:
        for q in np.random.default_rng(1).uniform(-2, 2, (10, chain.n)):
            assert np.allclose(chain.geometric_jacobian(q), finite_difference_jacobian(chain, q), atol=1e-8)


def test_space_jacobian_is_the_geometric_one_moved_to_the_base_origin():
    Q = np.random.default_rng(2).uniform(-3, 3, (50, 6))
    Jg, Js = PUMA.geometric_jacobian(Q), PUMA.space_jacobian(Q)
    p = PUMA.fk(Q)[:, :3, 3]
    omega, v_origin = Js[:, :3], Js[:, 3:]
    # the end-effector point's velocity: v_p = v_origin + omega x p
    v_point = v_origin + np.cross(np.swapaxes(omega, 1, 2), p[:, None, :]).swapaxes(1, 2)
    assert np.allclose(Jg[:, :3], v_point, atol=1e-12)
    assert np.allclose(Jg[:, 3:], omega, atol=1e-12)
    # at q = 0 the space Jacobian's columns are the screw axes of the product of exponentials
    assert np.allclose(PUMA.space_jacobian(np.zeros(6)).T, PUMA.screw_axes(), atol=1e-12)
