"""The answer keys of the parallel-kinematics chapter, recomputed from the geometry
written out here (the default attachment angles and lengths of the catalogue's
docstrings), not from the key's formula nor from screwkit's legs.
"""

import numpy as np

from .registry import reference
from .roots import bisect


def circle(radius, degrees):
    """Points on a circle in the xy-plane, (k, 3) (m)."""
    angles = np.radians(degrees)
    return radius * np.c_[np.cos(angles), np.sin(angles), np.zeros(len(angles))]


# the default Stewart-Gough platform: base on 1 m at 120 k -/+ 15 deg, platform on
# 0.5 m at 120 k -/+ 45 deg, leg i from base point i to platform point i
STEWART_BASE = circle(1.0, [-15, 15, 105, 135, 225, 255])
STEWART_PLATFORM = circle(0.5, [-45, 45, 75, 165, 195, 285])


def leg_1_at_home():
    """The vector from base point 1 (unit circle, -15 deg) to platform point 1 (radius
    0.5, -45 deg) with the platform 1 m up."""
    base = np.array([np.cos(np.radians(-15)), np.sin(np.radians(-15)), 0.0])
    platform = 0.5 * np.array([np.cos(np.radians(-45)), np.sin(np.radians(-45)), 0.0])
    return platform + [0, 0, 1] - base


def plucker_det(yaw):
    """det of the six leg lines (a_i x n_i; n_i), the platform 1 m up turned by yaw
    (rad) about z: zero where the lines are dependent."""
    c, s = np.cos(yaw), np.sin(yaw)
    R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
    legs = STEWART_PLATFORM @ R.T + [0, 0, 1] - STEWART_BASE
    return np.linalg.det(np.c_[np.cross(STEWART_BASE, legs), legs])


@reference("parallel_kinematics", 6)
def _():
    # the leg lines' determinant changes sign between 60 and 120 deg (unnormalised
    # lines: the same zeros as the Jacobian's)
    return np.degrees(bisect(plucker_det, np.radians(60), np.radians(120)))


@reference("parallel_kinematics", 8)
def _():
    # the 3-RRR at home: crank 1 (0.6 m) about a1 = (1, 0), link (0.5 m) to c1 = (0.25,
    # 0); the elbow is a point where the two circles cross (the radical line), mode '+'
    # the one to the left of the ray from a1 to c1; the crank angle is its direction
    a1, c1, l1, l2 = np.array([1.0, 0.0]), np.array([0.25, 0.0]), 0.6, 0.5
    d = np.linalg.norm(c1 - a1)
    along = (d**2 + l1**2 - l2**2) / (2 * d)  # from a1 to the radical line
    half_chord = np.sqrt(l1**2 - along**2)
    unit = (c1 - a1) / d
    left = np.array([-unit[1], unit[0]])
    elbow = a1 + along * unit + half_chord * left
    return np.arctan2(elbow[1] - a1[1], elbow[0] - a1[0])


@reference("parallel_kinematics", 10)
def _():
    return np.sqrt(np.sum(leg_1_at_home() ** 2))


@reference("parallel_kinematics", 11)
def _():
    leg = leg_1_at_home()
    return leg[2] / np.sqrt(np.sum(leg**2))


@reference("parallel_kinematics", 12)
def _():
    # the delta with its cranks horizontal: leg 1's elbow at (0.4, 0, 0), its
    # platform point (0.05, 0, 0) off the platform's origin; by symmetry the origin is
    # on the z axis, 0.45 m from the elbow: bisection below the base
    elbow, b1, l2 = np.array([0.4, 0.0, 0.0]), np.array([0.05, 0.0, 0.0]), 0.45

    def reach(z):
        return np.linalg.norm(np.array([0.0, 0.0, z]) + b1 - elbow) - l2

    return bisect(reach, -0.45, 0.0)


@reference("parallel_kinematics", 14)
def _():
    # the longest leg of the platform 1 m up turned by yaw reaches 1.6 m: bisection
    # on the legs written out from the table's circles
    def longest(yaw):
        c, s = np.cos(yaw), np.sin(yaw)
        R = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
        legs = STEWART_PLATFORM @ R.T + [0, 0, 1] - STEWART_BASE
        return np.linalg.norm(legs, axis=1).max() - 1.6

    return np.degrees(bisect(longest, 0.0, np.radians(100)))
