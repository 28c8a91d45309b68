"""The answer keys of the parallel-kinematics chapter, recomputed from the geometry
written out here (the default Stewart-Gough attachment angles of its docstring), not
from the key's formula nor from screwkit's legs; registered with the engine's tests.
"""

import numpy as np

import screwkit as sk

try:  # the engine's registry of references, when its tests are collected with these
    from test_exercises import REFERENCES as ENGINE_REFERENCES
except ImportError:  # pragma: no cover - run alone from elsewhere
    ENGINE_REFERENCES = {}


def reference(chapter, number):
    def register(function):
        ENGINE_REFERENCES[chapter, number] = function
        return function

    return register


def leg_1_at_home():
    """The vector from base point 1 (unit circle, -15 deg) to platform point 1 (radius
    0.5, -45 deg) with the platform 1 m up."""
    base = np.array([np.cos(np.radians(-15)), np.sin(np.radians(-15)), 0.0])
    platform = 0.5 * np.array([np.cos(np.radians(-45)), np.sin(np.radians(-45)), 0.0])
    return platform + [0, 0, 1] - base


@reference("parallel_kinematics", 10)
def _():
    return np.sqrt(np.sum(leg_1_at_home() ** 2))


@reference("parallel_kinematics", 11)
def _():
    leg = leg_1_at_home()
    return leg[2] / np.sqrt(np.sum(leg**2))


def test_the_keys_match_the_chapter_geometry():
    stewart = sk.robots.stewart_gough()
    leg = leg_1_at_home()
    assert np.allclose(stewart.ik(stewart.home()), np.linalg.norm(leg), atol=1e-12)
    assert np.isclose(
        stewart.jacobian(stewart.home())[0, 5], leg[2] / np.linalg.norm(leg)
    )
