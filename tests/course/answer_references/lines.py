"""The answer keys of the lines chapter, each recomputed another way: a formula written
out here with NumPy (never screwkit.lines, whose results the chapter compares), or the
problem as stated solved by least squares or a null space."""

import math

import numpy as np
import sympy as sp

import screwkit as sk

from .registry import reference


@reference("lines", 1)
def _():
    # the moment of the point (1, 2, 2), not (1, 0, 0), with the unit direction
    p, q = np.array([1.0, 0, 0]), np.array([1.0, 2, 2])
    u = (q - p) / np.linalg.norm(q - p)
    return np.cross(q, u)


@reference("lines", 2)
def _():
    # the point of the line closest to the origin: minimise |x|^2 over x = p + t w,
    # with one point p solving p x w = m (least squares on the cross-product matrix)
    w, m = np.array([0.0, 0, 1]), np.array([2.0, 0, 0])
    Wx = np.array([[0, w[2], -w[1]], [-w[2], 0, w[0]], [w[1], -w[0], 0]])
    p = np.linalg.lstsq(Wx, m, rcond=None)[0]
    return p - (p @ w) / (w @ w) * w


@reference("lines", 3)
def _():
    # least squares on |p1 + s d1 - p2 - t d2|
    p1, d1 = np.zeros(3), np.array([1.0, 0, 0])
    p2, d2 = np.array([0.0, 0, 3]), np.array([0.0, 1, 1])
    s, t = np.linalg.lstsq(np.stack([d1, -d2], 1), p2 - p1, rcond=None)[0]
    return np.linalg.norm(p1 + s * d1 - p2 - t * d2)


@reference("lines", 4)
def _():
    # -d sin(alpha): d = 3/sqrt(2) along the normal from a to b, n = (0, -1, 1)/sqrt(2);
    # the angle from (1, 0, 0) to (0, 1, 1)/sqrt(2) about n is +90 degrees
    n = np.array([0.0, -1, 1]) / math.sqrt(2)
    wa, wb = np.array([1.0, 0, 0]), np.array([0.0, 1, 1]) / math.sqrt(2)
    alpha = math.atan2(np.cross(wa, wb) @ n, wa @ wb)
    return -3 / math.sqrt(2) * math.sin(alpha)


@reference("lines", 5)
def _():
    # the point of x + y = 2, z = 1 nearest the origin: minimum norm solution
    A, b = np.array([[1.0, 1, 0], [0, 0, 1]]), np.array([2.0, 1])
    return np.linalg.lstsq(A, b, rcond=None)[0]


@reference("lines", 7)
def _():
    f = np.array([0.0, 0, 10])
    m = np.cross([1.0, 0, 0], f) + [0, 0, 2]
    return f @ m / (f @ f)


@reference("lines", 8)
def _():
    # the point of the x axis about which the moments of the two forces cancel
    return np.array([(2 * 0 + 6 * 4) / (2 + 6), 0.0, 0.0])


def _cylindroid_member(theta):
    """The member cos(t) S1 + sin(t) S2 of the cylindroid with S1 along x (pitch 0.1)
    and S2 along y (pitch 0.4), as a 6-vector."""
    S1 = np.array([1.0, 0, 0, 0.1, 0, 0])
    S2 = np.array([0.0, 1, 0, 0, 0.4, 0])
    return math.cos(theta) * S1 + math.sin(theta) * S2


@reference("lines", 9)
def _():
    x = _cylindroid_member(math.radians(60))
    return x[:3] @ x[3:] / (x[:3] @ x[:3])


@reference("lines", 10)
def _():
    x = _cylindroid_member(math.radians(60))
    h = x[:3] @ x[3:] / (x[:3] @ x[:3])
    point = np.cross(x[:3], x[3:] - h * x[:3]) / (x[:3] @ x[:3])
    return point[2]


@reference("lines", 12)
def _():
    rng = np.random.default_rng(0)
    p = rng.normal(size=3)
    lines = [np.r_[w, np.cross(p, w)] for w in rng.normal(size=(8, 3))]
    return np.linalg.matrix_rank(np.array(lines))


@reference("lines", 14)
def _():
    # six random lines meeting the z axis: the rank of their coordinates
    rng = np.random.default_rng(1)
    lines = []
    for _ in range(6):
        p, q = np.r_[0, 0, rng.normal()], rng.normal(size=3)
        lines.append(np.r_[q - p, np.cross(p, q)])
    return np.linalg.matrix_rank(np.array(lines))


@reference("lines", 21)
def _():
    # the screw reciprocal to the six leg lines: the null space of L Delta, L the
    # leg lines (unit directions, moments about the origin) at Fichter's turn
    T = np.array(sk.homogeneous(sk.rotz(math.pi / 2), [0, 0, 0.8]), dtype=float)
    base = np.array(sp.Matrix(sk.parallel.catalogue.STEWART_BASE), dtype=float)
    top = np.array(sp.Matrix(sk.parallel.catalogue.STEWART_PLATFORM), dtype=float)
    tops = top @ T[:3, :3].T + T[:3, 3]
    L = np.array([np.r_[q - p, np.cross(p, q)] for p, q in zip(base, tops)])
    Delta = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])
    rho = np.linalg.svd(L @ Delta)[2][-1]
    return rho[:3] @ rho[3:] / (rho[:3] @ rho[:3])
