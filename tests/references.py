"""Hand-written references: textbook formulas written out with NumPy alone, each once.

Nothing here calls screwkit: a test compares screwkit's answer with one of these, so a
reference must not be screwkit's own output. Angles in radians, lengths in metres.
"""

import math

import numpy as np


def Rx(t):
    """The elementary rotation about x by t, written out. Returns shape (3, 3)."""
    c, s = math.cos(t), math.sin(t)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def Ry(t):
    """The elementary rotation about y by t, written out. Returns shape (3, 3)."""
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def Rz(t):
    """The elementary rotation about z by t, written out. Returns shape (3, 3)."""
    c, s = math.cos(t), math.sin(t)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def rot(axis, angle):
    """The elementary rotation about ``axis`` ('x', 'y' or 'z') by ``angle``."""
    return {"x": Rx, "y": Ry, "z": Rz}[axis](angle)


def dh_standard(theta, d, a, alpha):
    """One standard DH link, Rz(theta) Tz(d) Tx(a) Rx(alpha), multiplied out by hand.

    Parameters
    ----------
    theta, d, a, alpha : float
        The link's DH parameters (rad, m, m, rad).

    Returns
    -------
    ndarray, shape (4, 4)
    """
    ct, st, ca, sa = np.cos(theta), np.sin(theta), np.cos(alpha), np.sin(alpha)
    return np.array(
        [
            [ct, -st * ca, st * sa, a * ct],
            [st, ct * ca, -ct * sa, a * st],
            [0, sa, ca, d],
            [0, 0, 0, 1],
        ],
        dtype=float,
    )


def dh_modified(theta, d, a, alpha):
    """One modified (Craig) DH link, Rx(alpha) Tx(a) Rz(theta) Tz(d), multiplied out by
    hand. The same argument order as :func:`dh_standard`.

    Parameters
    ----------
    theta, d, a, alpha : float
        The link's DH parameters (rad, m, m, rad); ``a`` and ``alpha`` are Craig's
        a_{i-1} and alpha_{i-1}.

    Returns
    -------
    ndarray, shape (4, 4)
    """
    ct, st, ca, sa = np.cos(theta), np.sin(theta), np.cos(alpha), np.sin(alpha)
    return np.array(
        [
            [ct, -st, 0, a],
            [st * ca, ct * ca, -sa, -sa * d],
            [st * sa, ct * sa, ca, ca * d],
            [0, 0, 0, 1],
        ],
        dtype=float,
    )


def dh_fk(table, q):
    """The pose of a revolute standard-DH arm: the product of its link matrices.

    Parameters
    ----------
    table : sequence of (d, a, alpha)
        One row per joint (m, m, rad).
    q : sequence of float
        The joint angles (rad), one per row.

    Returns
    -------
    ndarray, shape (4, 4)
    """
    T = np.eye(4)
    for qi, (d, a, alpha) in zip(q, table):
        T = T @ dh_standard(qi, d, a, alpha)
    return T


#: The PUMA 560's lengths in Corke's standard DH table (m).
A2, A3, D3, D4 = 0.4318, 0.0203, 0.15005, 0.4318

#: The PUMA 560 of Corke's table, written here: (d, a, alpha) per link.
PUMA_TABLE = [
    (0, 0, math.pi / 2),
    (0, A2, 0),
    (D3, A3, -math.pi / 2),
    (D4, 0, math.pi / 2),
    (0, 0, -math.pi / 2),
    (0, 0, 0),
]


def rpr_mode_count(a, b, rho, samples=400_001):
    """The real assembly modes of a 3-RPR, counted by sign changes over a dense grid of
    the platform angle phi: for each phi, legs 1 and 2 fix the platform point 0 (two
    linear equations after subtracting leg 0's circle), and leg 0's residual changes
    sign at each mode. ``a``, ``b`` (3, 2): base and platform points (b_0 = 0, the
    platform frame's origin); ``rho`` (3,): leg lengths (m). Returns an int."""
    phi = np.linspace(-np.pi, np.pi, samples)
    c, s = np.cos(phi), np.sin(phi)
    rows, rhs = [], []
    for k in (1, 2):
        w = np.c_[c * b[k, 0] - s * b[k, 1], s * b[k, 0] + c * b[k, 1]] - a[k]
        rows.append(2 * (w + a[0]))
        rhs.append(rho[k] ** 2 - rho[0] ** 2 - np.sum(w * w, 1) + a[0] @ a[0])
    q = np.linalg.solve(np.stack(rows, 1), np.stack(rhs, 1)[..., None])[..., 0]
    f = np.sum((q - a[0]) ** 2, 1) - rho[0] ** 2
    return int(np.sum(np.sign(f[1:]) != np.sign(f[:-1])))
