"""The closed-form quartic (Ferrari) behind subproblems 5 and 6, against known roots."""

import numpy as np
import pytest

from screwkit.ik import _quartic
from screwkit.ik._quartic import quartic_roots


def _distance(found, expected):
    """The largest distance from a root of one set to the nearest of the other."""
    gap = np.abs(found[..., :, None] - expected[..., None, :])
    return max(gap.min(-1).max(), gap.min(-2).max())


def _from_roots(roots, lead=1.0):
    return np.array([lead * np.poly(r) for r in roots])


def test_random_quartics_give_back_their_roots():
    rng = np.random.default_rng(1)
    roots = rng.normal(size=(2000, 4)) + 1j * rng.normal(size=(2000, 4))
    found = quartic_roots(_from_roots(roots, lead=2.5 - 1j))
    assert found.shape == (2000, 4)
    assert _distance(found, roots) < 1e-10


def test_roots_on_the_unit_circle_as_subproblems_have_them():
    rng = np.random.default_rng(2)
    roots = np.exp(1j * rng.uniform(-np.pi, np.pi, (2000, 4)))
    roots[:, 2:] *= rng.uniform(0.2, 3.0, (2000, 2))  # two off the circle
    assert _distance(quartic_roots(_from_roots(roots)), roots) < 1e-10


@pytest.mark.parametrize(
    "roots, accuracy",
    [
        ([1, 1, 2j, -3], 1e-6),  # a double root splits by about sqrt(eps)
        ([2, -2, 1, -1], 1e-12),  # biquadratic: no odd power
        ([1j, 1j, -1j, -1j], 1e-6),  # (z^2 + 1)^2
        ([0, 0, 0, 0], 1e-12),
        ([1, 1, 1, 1], 1e-3),  # a fourfold root: eps^(1/4)
        ([0, 0, 5, 5], 1e-6),
    ],
)
def test_multiple_roots(roots, accuracy):
    expected = np.array([roots], complex)
    assert _distance(quartic_roots(_from_roots(expected)), expected) < accuracy


def test_the_fallback_gives_the_companion_matrix_roots(monkeypatch):
    rng = np.random.default_rng(3)
    roots = rng.normal(size=(50, 4)) + 1j * rng.normal(size=(50, 4))
    monkeypatch.setattr(_quartic, "IK_QUARTIC_TOL", -1.0)  # no closed form trusted
    assert _distance(quartic_roots(_from_roots(roots)), roots) < 1e-10


def test_ferrari_alone_finds_the_roots_of_random_quartics(monkeypatch):
    # the fallback would hide a wrong formula: here it must not be called
    def no_eigvals(a):
        raise AssertionError("the companion matrix was needed")

    monkeypatch.setattr(_quartic.np.linalg, "eigvals", no_eigvals)
    rng = np.random.default_rng(4)
    roots = rng.normal(size=(2000, 4)) + 1j * rng.normal(size=(2000, 4))
    coeffs = _from_roots(roots)
    raw = _quartic._ferrari(*(coeffs[:, k] for k in range(1, 5)))
    assert _distance(raw, roots) < 1e-8
    assert _distance(quartic_roots(coeffs), roots) < 1e-10
