"""screwkit.ik.spherical_wrist: the geometry of a 6R arm with a spherical wrist, its
labels and its closed form, step by step; the wrist singularity decided by one
measure."""

import numpy as np
import pytest

from screwkit import ik
from screwkit.ik.spherical_wrist import CONFIGURATIONS, SphericalWristArm


@pytest.fixture(scope="module")
def arm(puma):
    return SphericalWristArm.from_chain(puma)


def test_wrist_centre_is_the_origin_of_frame_4(puma, arm):
    """From the screws (least squares on axes 4, 5, 6) and from the DH frames (generated
    code): two routes to the same point."""
    assert np.allclose(arm.c, puma.frames(np.zeros(6))[4][:3, 3], atol=1e-12)


@pytest.mark.parametrize("q5", [0.0, 1e-12, -1e-12, 1e-9, -0.3, 2.0])
def test_wrist_sine_of_the_puma_is_sin_q5(arm, q5):
    """The PUMA's axes 4, 5, 6 are mutually perpendicular with 4 along 6 at q5 = 0, so
    the sine between axes 4 and 6 is |sin q5| (by hand)."""
    assert np.isclose(
        arm.wrist_sine(np.array(q5)), abs(np.sin(q5)), rtol=1e-9, atol=1e-15
    )


def test_joint1_step_holds_the_true_angle(puma, arm):
    """The shoulder step alone: one of its two angles is -q1 of the configuration."""
    rng = np.random.default_rng(11)
    Q = rng.uniform(-3, 3, (200, 6))
    T = puma.fk(Q)
    G = T @ np.linalg.inv(arm.home)
    d = (G[:, :3, :3] @ arm.c + G[:, :3, 3] - arm.p[0]).T
    theta = arm._joint1(d).theta
    gap = np.abs(np.angle(np.exp(1j * (theta + Q[:, :1])))).min(axis=1)
    assert gap.max() < 1e-9


@pytest.mark.parametrize("q5", [0.0, 1e-12, -1e-12])
def test_wrist_singular_labels_round_trip(puma, q5):
    """At (and within round-off of) the wrist singularity, the solution of a pose
    computed by fk carries the label of the configuration it came from, and reaches the
    pose: 10,000 random joint vectors for each q5."""
    rng = np.random.default_rng(2024)
    Q = rng.uniform(-np.pi, np.pi, (10_000, 6))
    Q[:, 4] = q5
    labels = ik.configuration(puma, Q)
    solutions = ik.analytic_ik_all(puma, puma.fk(Q))
    chosen = solutions[np.arange(len(Q)), [CONFIGURATIONS.index(s) for s in labels]]
    assert not np.isnan(chosen).any()
    assert ik.configuration(puma, chosen) == labels
    assert np.abs(puma.fk(chosen) - puma.fk(Q)).max() < 1e-8


def test_wrist_singular_one_pose_by_config(puma):
    """The scalar API: puma560_ik(fk(q)).by_config(label(q)) has the same label."""
    q = np.array([0.4, -0.7, 0.9, 2.5, 0.0, -1.0])
    label = ik.puma560_config(q, puma)
    solution = ik.puma560_ik(puma.fk(q), puma).by_config(label)
    assert solution.config == label == ik.puma560_config(solution.q, puma)
    assert "wrist" in solution.singular
    assert np.allclose(puma.fk(solution.q), puma.fk(q), atol=1e-10)
