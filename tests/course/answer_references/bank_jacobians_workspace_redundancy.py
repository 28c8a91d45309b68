"""The answer keys of the problem bank's new exercises of the Jacobian,
Kawasaki and redundancy chapters, each recomputed another way than its key: a central
difference of the forward kinematics, a search over directions, a linear solve with
screwkit's Jacobian, or a formula written here.

Each computation is registered in .registry; tests/course/test_answer_keys.py checks
every key against it.
"""

import numpy as np

import screwkit as sk

from .registry import reference


def _tip(lengths, q):
    return sk.robots.planar(lengths).fk(np.asarray(q, dtype=float))[:2, 3]


def _tip_velocity(lengths, q, rates, h=1e-6):
    """The tip's velocity by a central difference of the forward kinematics."""
    q, rates = np.asarray(q, dtype=float), np.asarray(rates, dtype=float)
    return (_tip(lengths, q + h * rates) - _tip(lengths, q - h * rates)) / (2 * h)


def _numeric_jacobian(lengths, q):
    return np.column_stack([_tip_velocity(lengths, q, e) for e in np.eye(len(lengths))])


# --- jacobians ---


@reference("jacobians", 10)
def _():
    return _tip_velocity([0.5, 0.3], np.radians([30, 60]), [1, 1])


@reference("jacobians", 14)
def _():
    # virtual work: tau . dq = F . dx for every dq
    return _numeric_jacobian([0.4, 0.3], np.radians([90, -90])).T @ [0, -20]


@reference("jacobians", 16)
def _():
    J = _numeric_jacobian([0.5, 0.5], np.radians([0, 90]))
    angles = np.linspace(0, np.pi, 200_001)
    stretch = np.linalg.norm(J @ np.stack([np.cos(angles), np.sin(angles)]), axis=0)
    return stretch.max() / stretch.min()


@reference("jacobians", 22)
def _():
    q = np.radians([0, 10])
    tip = _tip([0.5, 0.3], q)
    inward = -0.1 * tip / np.linalg.norm(tip)
    rates = np.linalg.solve(_numeric_jacobian([0.5, 0.3], q), inward)
    return rates[1]


# --- kawasaki_workspace ---


def _annulus_area(inner, outer, n=2001):
    """The area between two circles by the midpoint rule on rings of width dr."""
    edges = np.linspace(inner, outer, n)
    middles = (edges[1:] + edges[:-1]) / 2
    return float(np.sum(2 * np.pi * middles * np.diff(edges)))


def _distances(lengths, q2):
    """The tip's distance from the base of a planar arm for the elbow angles q2."""
    Q = np.column_stack([np.zeros_like(q2), q2])
    return np.linalg.norm(sk.robots.planar(lengths).fk(Q)[:, :2, 3], axis=1)


@reference("kawasaki_workspace", 10)
def _():
    r = _distances([0.5, 0.3], np.linspace(0, np.pi, 100_001))
    return _annulus_area(r.min(), r.max())


@reference("kawasaki_workspace", 12)
def _():
    return _distances([0.5, 0.3], np.linspace(0, 2 * np.pi / 3, 100_001)).min()


@reference("kawasaki_workspace", 13)
def _():
    # a tip distance r is dexterous when joint 3 lies in the two-link annulus for
    # every orientation phi: bisect on r for where that starts and stops holding
    r2 = _distances([0.5, 0.3], np.linspace(0, np.pi, 20_001))
    phi = np.linspace(-np.pi, np.pi, 721)

    def every_phi(r):
        wrist = np.hypot(r - 0.1 * np.cos(phi), 0.1 * np.sin(phi))
        return bool(np.all((wrist >= r2.min() - 1e-12) & (wrist <= r2.max() + 1e-12)))

    def edge(outside, inside):
        for _ in range(60):
            mid = (outside + inside) / 2
            outside, inside = (outside, mid) if every_phi(mid) else (mid, inside)
        return inside

    return _annulus_area(edge(0.0, 0.5), edge(1.0, 0.5))


@reference("kawasaki_workspace", 15)
def _():
    # the elbow angle that puts the tip at the target's distance, by bisection
    target = np.hypot(0.6, 0.2)
    lo, hi = 0.0, np.pi
    for _ in range(80):
        mid = (lo + hi) / 2
        farther = _distances([0.5, 0.3], np.array([mid]))[0] > target
        lo, hi = (mid, hi) if farther else (lo, mid)
    return (lo + hi) / 2


@reference("kawasaki_workspace", 17)
def _():
    tool = sk.robots.kawasaki_cx210l().fk(np.radians([0, 90, 0, 0, 0, 0]))[:3, 3]
    return tool[[0, 2]]


# --- redundancy ---


def _least_norm(J, xdot):
    """The least-norm solution by minimising |qdot|^2 on J qdot = xdot through the
    KKT system (no pseudo-inverse)."""
    m, n = J.shape
    kkt = np.block([[np.eye(n), J.T], [J, np.zeros((m, m))]])
    return np.linalg.solve(kkt, np.r_[np.zeros(n), xdot])[:n]


@reference("redundancy", 11)
def _():
    return _least_norm(_numeric_jacobian([1, 1, 1], np.radians([0, 90, -90])), [0.1, 0])


@reference("redundancy", 13)
def _():
    angles = np.cumsum(np.radians([30, 60, -90]))
    return np.array([0.5, 0.4, 0.3]) @ np.column_stack([np.cos(angles), np.sin(angles)])


@reference("redundancy", 14)
def _():
    J = _numeric_jacobian([0.5, 0.4, 0.3], np.radians([0, 90, -90]))
    return _least_norm(J, [0.1, 0])


@reference("redundancy", 15)
def _():
    # q1 by bisection on the tip's miss, with q = (q1, 90 deg, 0)
    def miss_angle(q1):
        tip = _tip([1, 1, 1], [q1, np.pi / 2, 0])
        return np.arctan2(tip[1], tip[0]) - np.arctan2(1, 2)

    lo, hi = -np.pi / 2, 0.0
    assert miss_angle(lo) < 0 < miss_angle(hi)
    for _ in range(80):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if miss_angle(mid) < 0 else (lo, mid)
    q1 = (lo + hi) / 2
    assert np.allclose(_tip([1, 1, 1], [q1, np.pi / 2, 0]), [2, 1])
    return q1


@reference("redundancy", 22)
def _():
    # the largest reach over a grid of configurations, then where y = 0.6 m meets it
    grid = np.radians(np.linspace(-20, 20, 41))
    Q = np.array([[0.0, a, b] for a in grid for b in grid])
    reach = np.linalg.norm(sk.robots.planar([0.4, 0.3, 0.2]).fk(Q)[:, :2, 3], axis=1)
    return np.sqrt(reach.max() ** 2 - 0.6**2)
