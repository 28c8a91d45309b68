"""Independent recomputations of the statics chapter's answer keys: screwkit on the
problem as stated, a linear program, a bisection, finite differences of FK."""

import numpy as np
from scipy.optimize import linprog

import screwkit as sk

from .registry import reference
from .roots import bisect


@reference("statics", 1)
def _():
    arm = sk.robots.planar([0.4, 0.3])
    return sk.statics.joint_torques(arm, np.radians([30, 60]), force=[10, 0, 0])[0]


@reference("statics", 4)
def _():
    arm = sk.robots.planar([0.5, 0.4])  # the x-y plane: gravity along -y
    load = [(2, 3.0, [0.0, 0.0, 0.0])]
    return sk.statics.gravity_torques(arm, [0.0, 0.0], load, g=[0, -9.81, 0])[0]


@reference("statics", 7)
def _():
    # the two unit leg directions as columns: A t = (0, 100)
    legs = np.array([[np.sin(np.pi / 6), -np.sin(np.pi / 6)], [np.cos(np.pi / 6)] * 2])
    return np.linalg.solve(legs, [0.0, 100.0])[0]


@reference("statics", 11)
def _():
    # variables (N, t1, t2): min N with t1 + t2 = m g, |t_i| <= mu N
    mu, weight = 0.5, 9.81
    A_ub = [[-mu, 1, 0], [-mu, -1, 0], [-mu, 0, 1], [-mu, 0, -1]]
    lp = linprog(
        [1, 0, 0],
        A_ub=A_ub,
        b_ub=np.zeros(4),
        A_eq=[[0, 1, 1]],
        b_eq=[weight],
        bounds=[(0, None), (None, None), (None, None)],
    )
    return lp.x[0]


@reference("statics", 12)
def _():
    beta = np.radians(40)
    p2 = np.array([np.cos(beta), np.sin(beta)])

    def closed(mu):
        pinch = [
            sk.contact.Contact([-1, 0], [1, 0], "friction", mu=mu),
            sk.contact.Contact(p2, -p2, "friction", mu=mu),
        ]
        return 1.0 if sk.contact.force_closure(pinch).closed else -1.0

    return bisect(closed, 0.2, 0.6, steps=30)


def _tip_jacobian(arm, q, h=1e-6):
    """The tip point's 2 x 2 Jacobian by central differences of FK."""
    columns = []
    for e in np.eye(2):
        columns.append((arm.fk(q + h * e)[:2, 3] - arm.fk(q - h * e)[:2, 3]) / (2 * h))
    return np.array(columns).T


@reference("statics", 17)
def _():
    arm = sk.robots.planar([0.5, 0.3])
    J = _tip_jacobian(arm, np.radians([0.0, 90.0]))
    C = J @ np.diag([1 / 100, 1 / 50]) @ J.T
    return np.linalg.inv(C)[1, 1]


@reference("statics", 18)
def _():
    arm = sk.robots.planar([0.5, 0.3])
    C = sk.statics.compliance_at_tool(arm, [0.4, 0.7], [300.0, 600.0], frame="body")
    return 1 / C[2, 5]  # the turn about z per unit couple about z
