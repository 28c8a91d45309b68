"""The answer keys of the Jacobian, Kawasaki, redundancy and mobility chapters, each
recomputed independently: a screwkit computation that does not read the key's formula
(a root found by bisection, a maximum found where a derivative changes sign, a mobility
analysis) or a formula written here.

Each computation is registered in .registry; tests/course/test_answer_keys.py checks
every key against it.
"""

import math

import numpy as np
import sympy as sp
from builders import kawasaki, planar, puma

import screwkit as sk

from .registry import reference
from .roots import argmax, bisect

# --- jacobians ---


@reference("jacobians", 1)
def _():
    arm = sk.robots.planar([0.7, 0.4])
    return argmax(
        lambda q2: arm.manipulability(np.array([0.3, q2]), rows="planar"), 0.3, 2.8
    )


def _puma_det(q3, q2=0.5):
    return np.linalg.det(
        puma().geometric_jacobian(np.array([0.3, q2, q3, 0.2, 0.9, 0]))
    )


@reference("jacobians", 4)
def _():
    return bisect(_puma_det, -1.6, -1.45)


def j_two_link():
    """The 2R arm's planar Jacobian at q = (0, 90 deg)."""
    return planar(0.5, 0.3).geometric_jacobian(np.array([0, np.pi / 2]))[:2]


@reference("jacobians", 5)
def _():
    # the force the tip applies to hold up a 10 N weight: 10 N up
    return (j_two_link().T @ np.array([0.0, 10.0]))[0]


@reference("jacobians", 6)
def _():
    angles = np.linspace(0, 2 * np.pi, 200_001)
    u = np.stack([np.cos(angles), np.sin(angles)], axis=1)
    # the force of unit torque norm in direction u is u / |J^T u|
    return (1 / np.linalg.norm(u @ j_two_link(), axis=1)).max()


# --- kawasaki_workspace ---


SHOULDER = np.array([0.3, 0, 0.55])  # the axis of joint 2 at theta1 = 0


@reference("kawasaki_workspace", 3)
def _():
    def wrist_x(theta2):  # the wrist centre's distance from z0, signed
        return kawasaki().frames(np.array([0, theta2, 0, 0, 0, 0]))[4, 0, 3]

    return bisect(wrist_x, np.radians(30), np.radians(60))


def _reach(theta3):
    q = np.array([0, np.radians(100), theta3, 0, 0, 0])
    return np.linalg.norm(kawasaki().fk(q)[:3, 3] - SHOULDER)


@reference("kawasaki_workspace", 4)
def _():
    return _reach(argmax(_reach, np.radians(-120), np.radians(-40)))


@reference("kawasaki_workspace", 8)
def _():
    # the two links line up where the tool point is farthest from the shoulder
    return argmax(_reach, np.radians(-120), np.radians(-40))


@reference("kawasaki_workspace", 5)
def _():
    def det(theta3):
        q = np.array([0, np.radians(60), theta3, 0, np.pi / 2, 0])
        return np.linalg.det(kawasaki().geometric_jacobian(q))

    return bisect(det, np.radians(-80), np.radians(-72))


@reference("kawasaki_workspace", 6)
def _():
    # theta3 over a fine grid, for theta2 near the vertical upper arm (90 deg)
    best = -np.inf
    theta3 = np.linspace(-np.pi, np.pi, 20_001)
    for theta2 in np.radians(np.linspace(80, 100, 201)):
        Q = np.zeros((theta3.size, 6))
        Q[:, 1], Q[:, 2] = theta2, theta3
        best = max(best, kawasaki().frames(Q)[:, 4, 2, 3].max())
    return best


# --- redundancy ---


@reference("redundancy", 4)
def _():
    rates = np.linalg.pinv(np.array([[1.0, 1.0, 1.0]])) @ np.array([0.3])
    assert np.allclose(rates, rates[0])
    return rates[0]


Q_THREE = np.radians([0, 90, -90])


@reference("redundancy", 5)
def _():
    return planar(1, 1, 1).manipulability(Q_THREE, rows="planar")


@reference("redundancy", 6)
def _():
    J = planar(1, 1, 1).geometric_jacobian(Q_THREE)[:2]
    null = np.linalg.svd(J)[2][
        -1
    ]  # the right singular vector of the zero singular value
    assert np.allclose(J @ null, 0, atol=1e-12)
    return (0.1 / null[0] * null)[2]


@reference("redundancy", 7)
def _():
    dt = 0.01

    def growth(K):  # log of the error after 100 feedback steps, e_0 = 1
        e = 1.0
        for _ in range(100):
            e = e - K * dt * e
        return math.log(abs(e))

    assert growth(150) < 0 < growth(250)
    return bisect(growth, 150, 250)


# --- mobility ---


@reference("mobility", 3)
def _():
    return sk.mobility(sk.robots.pm_4prru(), at={sp.Symbol("alpha"): 0}).number


@reference("mobility", 4)
def _():
    assert sk.grubler_kutzbach(links=8, joints=9, freedoms=15) == 3
    return sk.mobility(sk.robots.pm_3rps()).number


@reference("mobility", 5)
def _():
    # the planar 3-RRR's links and joints, counted here: base, platform, two per limb
    counted = sk.grubler_kutzbach(links=2 + 3 * 2, joints=3 * 3, freedoms=3 * 3)
    assert counted == sk.mobility(sk.robots.planar_3rrr()).grubler_kutzbach
    return counted


@reference("mobility", 6)
def _():
    m = sk.mobility(sk.robots.planar_3rrr())
    assert m.grubler_kutzbach + m.redundant_constraints - m.idle_mobility == m.number
    return m.redundant_constraints


@reference("mobility", 7)
def _():
    ranks = {s.rank for s in sk.mobility(sk.robots.pm_3prrr()).limb_wrench_systems}
    assert len(ranks) == 1
    return ranks.pop()
