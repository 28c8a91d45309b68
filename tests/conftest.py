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
from pathlib import Path

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


@pytest.fixture
def chromium(request):
    """The system Chromium, fenced (conftest.py at the top): pytest-playwright's
    ``browser`` fixture, or a skip that says what is missing."""
    import importlib.util

    import browser

    if importlib.util.find_spec("pytest_playwright") is None:
        pytest.skip("needs pytest-playwright (.ci/requirements.txt, make test-all)")
    if browser.CHROMIUM is None:
        pytest.skip("needs Chromium (apt-get install chromium)")
    return request.getfixturevalue("browser")


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


# ---- the test tiers: `make test` runs the fast one, `make test-all` every one --------
#
# The slow tiers, in this one place: each is a marker (registered in pyproject.toml),
# why the tier is slow or needs something, and the node ids of its tests (fnmatch
# patterns). `pytest --tier fast` (make test) leaves them out and says how many it left
# out and why; `--tier slow` runs only them; `--tier all` (the default, and make
# test-all) runs every test. A pattern that matches nothing in a file that was
# collected is an error (a renamed test would otherwise move to the fast tier unseen).
SLOW_TIERS = {
    "certificates": (
        "rank certificates checked with 60-digit evaluation",
        ["tests/test_certificates.py::*"],
    ),
    "ranks60": (
        "exact ranks against a 60-digit mpmath rank or SymPy's",
        [
            "tests/test_exact.py::test_*_60_digit_rank",
            "tests/test_exact.py::test_symbolic_systems_agree_with_the_rank_at_random_*",
            "tests/test_exact.py::test_rank_and_null_space_agree_with_sympy[[]True]",
            "tests/test_systems.py::test_puma_joint_twists_agree_with_a_60_digit_rank",
            "tests/test_systems.py::test_puma_at_textbook_angles_is_no_longer_refused",
        ],
    ),
    "network": (
        "Binder's pip resolve, which needs PyPI",
        ["tests/course/test_binder.py::test_binder_requirements_resolve_*"],
    ),
    "references": (
        "reference packages (Pinocchio, Modern Robotics, SciPy, EAIK, msolve)",
        [
            "tests/test_urdf_pinocchio.py::*",
            "tests/test_motion_references.py::*",
            "tests/test_zoo.py::test_panda_matches_frankas_urdf",
            "tests/test_zoo.py::test_ur_dh_frames_match_the_ur5_urdf",
            "tests/test_zoo.py::test_panda_link_frames_are_frankas",
            "tests/test_zoo.py::test_panda_limits_match_frankas_urdf",
            "tests/test_ik_decomposed.py::test_every_exact_eaik_solution_is_returned",
            "tests/test_parallel_proven.py::test_dietmaier_*",
            "tests/test_parallel_proven.py::test_every_mode_the_search_finds_is_in_*",
            "tests/test_parallel_proven.py::test_random_platforms_*",
            "tests/test_parallel_proven.py::test_default_platform_home_pose_among_*",
            "tests/test_parallel_proven.py::test_a_continuum_is_reported_not_listed",
            "tests/test_parallel_proven.py::test_legs_too_short_have_no_mode_and_*",
            "tests/test_parallel_proven.py::test_timeout_gives_no_proof",
            "tests/test_parallel_proven.py::test_fk_all_with_proof_is_the_proven_list_*",
        ],
    ),
    "browser": (
        "headless Chromium",
        [
            "tests/test_exercises.py::test_answer_boxes_answer_in_the_browser",
            "tests/course/test_answer_keys.py::test_stored_chapter_boxes_answer_in_*",
            "tests/course/test_teacher_answers.py::test_answers_html_typesets_*",
        ],
    ),
    "slow": (
        "slow sweeps and exact-against-float checks (a few seconds to a minute each)",
        [
            "tests/test_subproblems.py::test_subproblem5_random_instances",
            "tests/test_subproblems.py::test_subproblem6_random_instances",
            "tests/test_acceleration.py::test_exact_and_float_forms_agree",
            "tests/test_acceleration.py::test_bad_input_is_a_clear_error",
            "tests/test_transforms.py::test_symbolic_rotation_about_any_unit_axis_*",
            "tests/test_jacobians.py::test_symbolic_jacobian_equals_the_numeric_one",
            "tests/test_jacobians.py::test_puma_determinant_factorises_into_*",
            "tests/test_jacobians.py::test_kawasaki_determinant_and_its_elbow_*",
            "tests/test_ik_decomposed.py::test_random_decomposable_arms",
            "tests/test_ik_general.py::test_the_generating_configuration_is_found_on_*",
            "tests/test_parallel.py::test_constraint_singularity_of_the_delta_with_*",
            "tests/test_parallel.py::test_3rpr_fk_all_returns_the_generating_pose_*",
            "tests/test_parallel_proven.py::test_3rrr_modes_are_the_elbows_3rpr_*",
            "tests/course/test_answer_keys.py::test_key_agrees_with_its_reference"
            "[[]kawasaki_workspace-6]",
            "tests/test_tiers.py::*",
        ],
    ),
}
TIERS = ("fast", "slow", "all")


def pytest_addoption(parser):
    parser.addoption(
        "--tier",
        choices=TIERS,
        default="all",
        help="fast: leave out the slow tiers (conftest.py SLOW_TIERS; make test); "
        "slow: only them; all: every test (the default; make test-all)",
    )


def _tier_of(nodeid):
    from fnmatch import fnmatchcase

    for marker, (_, patterns) in SLOW_TIERS.items():
        for pattern in patterns:
            if fnmatchcase(nodeid, pattern) or fnmatchcase(nodeid, pattern + "[[]*"):
                return marker, pattern
    return None, None


def pytest_collection_modifyitems(config, items):
    import pytest

    used, files = set(), {item.nodeid.split("::")[0] for item in items}
    kept, left_out = [], []
    for item in items:
        marker, pattern = _tier_of(item.nodeid)
        if marker:
            used.add(pattern)
            item.add_marker(getattr(pytest.mark, marker))
        slow = marker is not None
        tier = config.getoption("tier")
        (
            left_out
            if (tier == "fast" and slow) or (tier == "slow" and not slow)
            else kept
        ).append(item)
    # files named with a test (path::name) were not collected whole: not checked
    for arg in config.args:
        if "::" in arg:
            path = Path(arg.split("::")[0]).resolve()
            if path.is_relative_to(config.rootpath):
                files.discard(path.relative_to(config.rootpath).as_posix())
    stale = [
        pattern
        for _, patterns in SLOW_TIERS.values()
        for pattern in patterns
        if pattern.split("::")[0] in files and pattern not in used
    ]
    if stale:
        raise pytest.UsageError(
            "conftest.py SLOW_TIERS: no collected test matches " + ", ".join(stale)
        )
    if left_out:
        config.hook.pytest_deselected(items=left_out)
        items[:] = kept
    config._screwkit_left_out = left_out


def pytest_terminal_summary(terminalreporter, config):
    left_out = getattr(config, "_screwkit_left_out", [])
    if not left_out or config.getoption("tier") != "fast":
        return
    counts = {}
    for item in left_out:
        marker, _ = _tier_of(item.nodeid)
        counts[marker] = counts.get(marker, 0) + 1
    terminalreporter.section(
        "left out by --tier fast (make test); make test-all runs them"
    )
    for marker in SLOW_TIERS:
        if marker not in counts:
            continue
        count = counts[marker]
        terminalreporter.write_line(f"{count:5d} {marker}: {SLOW_TIERS[marker][0]}")
