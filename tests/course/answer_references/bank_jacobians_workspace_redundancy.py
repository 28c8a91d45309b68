"""The answer keys of the problem bank's new exercises (issue 42) of the Jacobian,
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
    return np.column_stack(
        [_tip_velocity(lengths, q, e) for e in np.eye(len(lengths))]
    )


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
