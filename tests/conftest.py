"""Test configuration: the hypothesis profiles, and the fixtures the test files share.

Robots and figures are fixtures, built on first use (once per session for the immutable
chains, by tests/builders.py, which test files may also call), never at the import of a
test file. Hand-written references are in tests/references.py; the bad-input contract
(its tables and their one driver) in tests/bad_input/; the course's own tests
(chapters, book, answer keys) in tests/course/.

``ci`` (the default, so CI and ``make test`` use it whether or not ``CI`` is set) is
derandomized: every run draws the same examples, so a failure in CI reproduces on any
machine. ``explore`` draws fresh random examples, more of them, for hunting new bugs
locally: ``HYPOTHESIS_PROFILE=explore pytest tests``.
"""

import os
import sys

import builders
import numpy as np
import pytest
from hypothesis import HealthCheck, settings

settings.register_profile(
    "ci",
    derandomize=True,  # a fixed seed per test: the same examples on every run
    database=None,  # nothing remembered between runs, nothing written to disk
    deadline=None,  # timing on a shared 2-core machine is not a failure
    print_blob=True,  # a failure prints the @reproduce_failure line
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("explore", max_examples=1000, deadline=None, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


# ---- robots: chains are immutable, so one of each serves the whole session -----------


@pytest.fixture(scope="session")
def puma():
    """The PUMA 560 of the catalogue (Corke's standard DH model, SI units)."""
    return builders.puma()


@pytest.fixture(scope="session")
def kawasaki():
    """The Kawasaki CX210L of the catalogue."""
    return builders.kawasaki()


@pytest.fixture
def rng():
    """A seeded generator: the same draws on every run."""
    return np.random.default_rng(20241201)


# ---- figures -------------------------------------------------------------------------


@pytest.fixture
def figure():
    """A new matplotlib figure, closed after the test (so no test sees another's
    figures)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure()
    yield fig
    plt.close(fig)


@pytest.fixture(autouse=True)
def _close_figures():
    """Close every matplotlib figure a test leaves open (figures made inside a table's
    calls, too), so that no test sees another's."""
    yield
    plt = sys.modules.get("matplotlib.pyplot")
    if plt is not None:
        plt.close("all")
