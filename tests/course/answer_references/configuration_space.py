"""The answer keys of the configuration-space chapter, each recomputed independently: a
rank of constraint Jacobians computed here with NumPy, a linkage counted from its list
of joints (which links each joins), a curl by SymPy, a reach found by sampling.

Each computation is registered in .registry; tests/course/test_answer_keys.py checks
every key against it.
"""

import math

import numpy as np
import sympy as sp

import screwkit as sk

from .registry import reference


def _distance_rank(points):
    """Rank of the Jacobian of all pairwise squared distances of `points` (k, dim)."""
    k, dim = points.shape
    rows = []
    for i in range(k):
        for j in range(i + 1, k):
            row = np.zeros(k * dim)
            row[dim * i : dim * i + dim] = 2 * (points[i] - points[j])
            row[dim * j : dim * j + dim] = -2 * (points[i] - points[j])
            rows.append(row)
    return np.linalg.matrix_rank(np.array(rows))


def _count(joints, order):
    """Grübler's count of a linkage given as (link, link, freedoms) per joint."""
    links = {name for a, b, _ in joints for name in (a, b)}
    return sk.grubler_kutzbach(
        links=len(links),
        joints=len(joints),
        freedoms=sum(f for *_, f in joints),
        order=order,
    )


@reference("configuration_space", 1)
def _():
    return _distance_rank(np.array([[0.0, 0.0], [1.0, 0.2], [0.3, 0.9]]))


@reference("configuration_space", 2)
def _():
    return _distance_rank(
        np.array([[0.0, 0, 0], [1, 0.1, 0], [0.2, 1, 0], [0.3, 0.2, 1]])
    )


@reference("configuration_space", 3)
def _():
    # Watt's six-bar as drawn: ground G and triangle PQS ternary, four bars
    joints = [
        ("G", "b1", 1),
        ("b1", "PQS", 1),
        ("G", "b2", 1),
        ("b2", "PQS", 1),
        ("PQS", "b3", 1),
        ("b3", "b4", 1),
        ("b4", "G", 1),
    ]
    return _count(joints, order=3)


def _legs(n, base, inner, outer, freedoms):
    """The joints of ``n`` legs, each ``base -J1- inner_i -J2- outer_i -J3- platform``
    with the joints' ``freedoms`` (three numbers)."""
    f1, f2, f3 = freedoms
    joints = []
    for i in range(n):
        joints += [
            (base, f"{inner}{i}", f1),
            (f"{inner}{i}", f"{outer}{i}", f2),
            (f"{outer}{i}", "platform", f3),
        ]
    return joints


@reference("configuration_space", 4)
def _():
    # three legs ground -R- tube -P- rod -R- platform
    return _count(_legs(3, "ground", "tube", "rod", (1, 1, 1)), order=3)


@reference("configuration_space", 5)
def _():
    # six legs base -S- cylinder -P- piston -S- platform
    return _count(_legs(6, "base", "cyl", "pis", (3, 1, 3)), order=6)


@reference("configuration_space", 6)
def _():
    n = 1
    while _count([(f"l{i}", f"l{(i + 1) % n}", 1) for i in range(n)], 6) < 1:
        n += 1
    return n


@reference("configuration_space", 9)
def _():
    def rpy(t):
        return sk.rotz(t[2]) @ sk.roty(t[1]) @ sk.rotx(t[0])

    angles, h = np.array([0.3, math.pi / 2, -0.2]), 1e-6
    D = np.column_stack(
        [((rpy(angles + e) - rpy(angles - e)) / (2 * h)).ravel() for e in h * np.eye(3)]
    )
    return np.linalg.matrix_rank(D, tol=1e-6)


@reference("configuration_space", 11)
def _():
    x, y, phi = sp.symbols("x y phi", real=True)
    a = sp.Matrix([sp.sin(phi), -sp.cos(phi), 0])
    curl = sp.Matrix(
        [
            sp.diff(a[2], y) - sp.diff(a[1], phi),
            sp.diff(a[0], phi) - sp.diff(a[2], x),
            sp.diff(a[1], x) - sp.diff(a[0], y),
        ]
    )
    return float(sp.simplify(a.dot(curl)))


@reference("configuration_space", 14)
def _():
    # the reach over a fine grid of q2 (q1 only turns it): the workspace is the ring
    q2 = np.linspace(-math.pi, math.pi, 200_001)
    r = np.hypot(0.5 + 0.3 * np.cos(q2), 0.3 * np.sin(q2))
    return math.pi * (r.max() ** 2 - r.min() ** 2)


@reference("configuration_space", 19)
def _():
    joints = []
    for i in range(3):  # crank on R; two rods, S at the crank, U at the platform
        joints.append(("base", f"crank{i}", 1))
        for rod in (f"rod{i}a", f"rod{i}b"):
            joints += [(f"crank{i}", rod, 3), (rod, "platform", 2)]
    return _count(joints, order=6)


@reference("configuration_space", 22)
def _():
    # the excavator arm as drawn: cab -R- boom -R- stick -R- bucket, and three
    # cylinders, each body -R- barrel -P- rod -R- body
    joints = [("cab", "boom", 1), ("boom", "stick", 1), ("stick", "bucket", 1)]
    for k, (p, q) in enumerate(
        (("cab", "boom"), ("boom", "stick"), ("stick", "bucket"))
    ):
        joints += [
            (p, f"barrel{k}", 1),
            (f"barrel{k}", f"rod{k}", 1),
            (f"rod{k}", q, 1),
        ]
    return _count(joints, order=3)
