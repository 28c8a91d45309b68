"""Test configuration: the hypothesis profiles.

``ci`` (the default, so CI and ``make test`` use it whether or not ``CI`` is set) is
derandomized: every run draws the same examples, so a failure in CI reproduces on any
machine. ``explore`` draws fresh random examples, more of them, for hunting new bugs
locally: ``HYPOTHESIS_PROFILE=explore pytest tests``.
"""
import os

from hypothesis import HealthCheck, settings

settings.register_profile(
    "ci",
    derandomize=True,          # a fixed seed per test: the same examples on every run
    database=None,             # nothing remembered between runs, nothing written to disk
    deadline=None,             # timing on a shared 2-core machine is not a failure
    print_blob=True,           # a failure prints the @reproduce_failure line
    suppress_health_check=[HealthCheck.too_slow],
)
settings.register_profile("explore", max_examples=1000, deadline=None, print_blob=True)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))
