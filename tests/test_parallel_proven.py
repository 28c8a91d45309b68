"""Forward kinematics with a proof of completeness (screwkit.parallel.proven).

References, none from the code under test: Dietmaier's 6-6 platform with 40 real
assembly modes (the most a Stewart-Gough platform can have: its forward kinematics has
40 complex solutions in general, Raghavan 1993, so 40 distinct real poses are all of
them; its geometry, as printed, is screwkit.parallel's DIETMAIER_* data); the search
``fk_all`` (every pose it finds must be in the proven list); an independent exact count
in other unknowns (rotation matrix and translation, with R^T R = I and det R = 1, solved
by msolve, written here with SymPy); the 3-RPR's modes of ``rpr_sextic`` (numeric roots
of the same sextic) and a pose built at phi = pi.

The Stewart tests need msolve (``pip install screwkit[proof]``) and skip without it;
the slow ones (random platforms against the independent count, the platform in full
float precision) run with SCREWKIT_SLOW_TESTS=1.
"""

import functools
import os
from decimal import Decimal

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
import screwkit.parallel.proven as proven
from screwkit.parallel import DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO
from screwkit.parallel.proven import rpr_fk_proven, stewart_fk_proven
from screwkit.tolerances import (
    PARALLEL_FK_ACCEPT_TOL,
    PARALLEL_SAME_POSE_TOL,
    length_scale,
)

SLOW = os.environ.get("SCREWKIT_SLOW_TESTS") == "1"
slow = pytest.mark.skipif(not SLOW, reason="slow: set SCREWKIT_SLOW_TESTS=1")


def _has_msolve():
    try:
        proven._msolve()
    except ModuleNotFoundError:
        return False
    return True


if os.environ.get("SCREWKIT_PROOF") == "required" and not _has_msolve():
    raise RuntimeError(
        "SCREWKIT_PROOF=required but msolve is missing (.ci/nodeps-requirements.txt)"
    )

needs_msolve = pytest.mark.skipif(
    not _has_msolve(), reason="msolve missing: pip install screwkit[proof]"
)


@functools.cache
def dietmaier_modes():
    """stewart_fk_proven on Dietmaier's platform, once for the tests that use it: the
    decimals printed in the paper, exactly (rationals="decimal")."""
    return stewart_fk_proven(
        DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO, rationals="decimal"
    )


def leg_error(T, base, platform, lengths):
    """The largest leg-length error of pose T (m)."""
    base, platform = np.asarray(base, float), np.asarray(platform, float)
    ends = platform @ T[:3, :3].T + T[:3, 3]
    return np.max(np.abs(np.linalg.norm(ends - base, axis=1) - lengths))


def same_pose(T1, T2, scale):
    rotation = np.max(np.abs(T1[:3, :3] - T2[:3, :3]))
    translation = np.max(np.abs(T1[:3, 3] - T2[:3, 3])) / scale
    return max(rotation, translation) < PARALLEL_SAME_POSE_TOL


def check_modes(poses, base, platform, lengths):
    """Every pose a rigid motion satisfying the legs, no two the same."""
    scale = length_scale(base, platform, lengths)
    for T in poses:
        R = T[:3, :3]
        assert np.allclose(R.T @ R, np.eye(3)) and np.isclose(np.linalg.det(R), 1)
        assert leg_error(T, base, platform, lengths) < PARALLEL_FK_ACCEPT_TOL * scale
    for i, T in enumerate(poses):
        assert not any(same_pose(T, U, scale) for U in poses[:i])


def in_decimal_units(values, factor):
    """The numbers a user would type in other units: the printed decimals times
    ``factor`` (a power of ten), exactly, then as floats."""
    return [
        [float(Decimal(repr(float(v))) * Decimal(factor)) for v in row]
        for row in np.atleast_2d(values)
    ]


def stewart_of(base, platform):
    pm = sk.parallel.stewart_gough(
        base=np.asarray(base, float), platform=np.asarray(platform, float)
    )
    return pm


@needs_msolve
def test_dietmaier_forty_real_modes_complete():
    poses, complete, reason = dietmaier_modes()
    assert (len(poses), complete, reason) == (40, True, None)
    check_modes(poses, DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO)


@needs_msolve
@pytest.mark.parametrize("factor", ["1000", "0.01"])
def test_dietmaier_in_mm_and_cm_same_modes_scaled(factor):
    base = in_decimal_units(DIETMAIER_BASE, factor)
    platform = in_decimal_units(DIETMAIER_PLATFORM, factor)
    lengths = in_decimal_units(DIETMAIER_RHO, factor)[0]
    poses, complete, _ = stewart_fk_proven(base, platform, lengths, rationals="decimal")
    assert (len(poses), complete) == (40, True)
    check_modes(poses, base, platform, lengths)
    metres, _, _ = dietmaier_modes()
    k = float(factor)
    for T in poses:
        U = T.copy()
        U[:3, 3] /= k
        assert any(same_pose(U, V, 1.0) for V in metres)


@needs_msolve
def test_every_mode_the_search_finds_is_in_the_proven_list():
    pm = stewart_of(DIETMAIER_BASE, DIETMAIER_PLATFORM)
    found = pm.fk_all(np.array(DIETMAIER_RHO, float), starts=400, seed=3)
    poses, _, _ = dietmaier_modes()
    assert found and len(found) <= len(poses)
    for T in found:
        assert any(same_pose(T, U, 1.0) for U in poses)


def short_decimal_platform(seed):
    """A random 6-6 platform in 3 decimals and the legs of a random pose (4
    decimals): the platform has at least one real mode near that pose."""
    rng = np.random.default_rng(seed)
    base = np.round(rng.uniform(-1, 1, (6, 3)), 3)
    platform = np.round(rng.uniform(-0.6, 0.6, (6, 3)), 3)
    q = rng.normal(size=4)
    T = np.eye(4)
    T[:3, :3] = sk.orientation.rotation_from_quaternion(q / np.linalg.norm(q))
    T[:3, 3] = rng.uniform(-0.3, 0.3, 3) + [0, 0, 1.2]
    lengths = np.round(
        np.linalg.norm(platform @ T[:3, :3].T + T[:3, 3] - base, axis=1), 4
    )
    return base, platform, lengths, T


@needs_msolve
@pytest.mark.parametrize(
    "seed", [0, pytest.param(1, marks=slow), pytest.param(2, marks=slow)]
)
def test_random_platforms_contain_the_search_and_the_pose(seed):
    base, platform, lengths, T0 = short_decimal_platform(seed)
    poses, complete, _ = stewart_fk_proven(base, platform, lengths, rationals="decimal")
    assert complete and 1 <= len(poses) <= 40
    check_modes(poses, base, platform, lengths)
    # the legs were rounded to 1e-4 m: a mode within a few times that of T0
    assert min(np.max(np.abs(T[:3, 3] - T0[:3, 3])) for T in poses) < 0.05
    for T in stewart_of(base, platform).fk_all(lengths, starts=400, seed=seed):
        assert any(same_pose(T, U, 1.0) for U in poses)


def rotation_matrix_count(base, platform, lengths):
    """The real assembly modes counted in other unknowns: R (9 entries) and t,
    R^T R = I, det R = 1, the six |R p + t - b|^2 = l^2; msolve's count."""
    r, t = sp.symbols("r0:9"), sp.symbols("t0:3")
    R, tv = sp.Matrix(3, 3, r), sp.Matrix(t)

    def rat(v):
        return sp.Rational(repr(float(v)))

    equations = []
    for b, p, length in zip(base, platform, lengths):
        v = R * sp.Matrix([rat(c) for c in p]) + tv - sp.Matrix([rat(c) for c in b])
        equations.append((v.T * v)[0] - rat(length) ** 2)
    gram = R.T * R - sp.eye(3)
    equations += [gram[i, j] for i in range(3) for j in range(i, 3)]
    equations.append(R.det() - 1)
    texts = []
    for e in equations:
        poly = sp.Poly(sp.expand(e), *r, *t)
        poly = poly * sp.ilcm(*[c.q for c in poly.coeffs()])
        texts.append(str(poly.as_expr()).replace("**", "^").replace(" ", ""))
    names = [str(s) for s in r + t]
    text = proven._run_msolve(proven._msolve(), names, texts, 600)
    boxes = proven._parse_real_solutions(text)
    assert boxes is not None, "positive-dimensional in the rotation-matrix unknowns"
    return len(boxes)


@needs_msolve
@slow
@pytest.mark.parametrize("seed", range(10))
def test_random_platforms_count_equals_independent_exact_count(seed):
    base, platform, lengths, _ = short_decimal_platform(100 + seed)
    # the decimals, as rotation_matrix_count reads them
    poses, complete, _ = stewart_fk_proven(base, platform, lengths, rationals="decimal")
    assert complete
    assert len(poses) == rotation_matrix_count(base, platform, lengths)
    for T in stewart_of(base, platform).fk_all(lengths, starts=2000, seed=seed):
        assert any(same_pose(T, U, 1.0) for U in poses)


@needs_msolve
@slow
def test_dietmaier_independent_count_and_binary_floats_times_1000():
    assert (
        rotation_matrix_count(DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO) == 40
    )
    k = 1000.0
    base = np.array(DIETMAIER_BASE) * k
    platform = np.array(DIETMAIER_PLATFORM) * k
    lengths = np.array(DIETMAIER_RHO) * k
    for rationals in ("decimal", "binary"):
        poses, complete, _ = stewart_fk_proven(
            base, platform, lengths, rationals=rationals
        )
        assert (len(poses), complete) == (40, True)
        check_modes(poses, base, platform, lengths)


@needs_msolve
@slow
def test_default_platform_home_pose_among_the_modes():
    pm = sk.parallel.stewart_gough()
    rho = pm.ik(pm.home())
    poses, complete, _ = stewart_fk_proven(pm.base_points, pm.platform_points, rho)
    assert complete
    check_modes(poses, pm.base_points, pm.platform_points, rho)
    assert any(same_pose(pm.home(), T, pm.scale) for T in poses)
    for T in pm.fk_all(rho):
        assert any(same_pose(T, U, pm.scale) for U in poses)


@needs_msolve
def test_a_continuum_is_reported_not_listed():
    # every platform point at one place: any rotation about it keeps the legs
    poses, complete, reason = stewart_fk_proven(
        sk.parallel.STEWART_BASE, np.zeros((6, 3)), np.full(6, 1.2)
    )
    assert (poses, complete) == ([], False)
    assert "positive-dimensional" in reason


def similar_hexagons():
    """A platform 0.5 times its base (similar hexagons, the floats of STEWART_BASE
    halved, exactly), legs of 1.2 m: architecture-singular. The platform parallel to
    the base above its centre, R = I, at z = sqrt(1.2^2 - 0.5^2) has every leg of
    1.2 m (each platform point is 0.5 m horizontally from its base point, as
    |b_i - b_i / 2| = |b_i| / 2 with |b_i| = 1), and it moves with one degree of
    freedom (a self-motion) from there."""
    base = np.array(sk.parallel.STEWART_BASE, dtype=float)
    return base, 0.5 * base, np.full(6, 1.2)


@needs_msolve
def test_similar_hexagons_are_a_continuum_not_a_proof_of_isolated_modes():
    # the decimals of the floats are not similar hexagons, and the proof of
    # that other problem said complete=True with 4 modes at z = 0
    base, platform, lengths = similar_hexagons()
    T = np.eye(4)
    T[2, 3] = np.sqrt(1.2**2 - 0.5**2)
    assert leg_error(T, base, platform, lengths) < 1e-15  # on the continuum
    poses, complete, reason = stewart_fk_proven(base, platform, lengths)
    assert (poses, complete) == ([], False)
    assert reason.startswith(proven.POSITIVE_DIMENSIONAL)
    pm = stewart_of(base, platform)
    modes = pm.fk_all(lengths, proof=True)
    assert not modes.complete and modes.continuum
    assert proven.POSITIVE_DIMENSIONAL in modes.reason and "msolve" in modes.method
    assert modes, "a pose of the continuum is listed"
    check_modes(modes, base, platform, lengths)


def scaled_home_legs():
    """The default platform's points and the legs of a pose near home (8 real
    modes)."""
    pm = sk.parallel.stewart_gough()
    T = pm.home()
    T[:3, 3] += [0.05, -0.03, 0.1]
    return pm.base_points, pm.platform_points, pm.ik(T)


@functools.cache
def home_legs_modes():
    """stewart_fk_proven of :func:`scaled_home_legs` in m, once."""
    return stewart_fk_proven(*scaled_home_legs())


@needs_msolve
def test_scaled_by_a_power_of_two_the_same_exact_problem_the_same_bits():
    # 2^k times a float is exact, so 2^k times the geometry is the same exact problem
    # in a unit 2^k times larger: the modes are the same to the last bit, scaled
    base, platform, lengths = scaled_home_legs()
    metres, complete, _ = home_legs_modes()
    assert complete and len(metres) >= 1
    f = 2.0**-20  # about 1e-6 m
    poses, complete, _ = stewart_fk_proven(f * base, f * platform, f * lengths)
    assert complete and len(poses) == len(metres)
    for T, U in zip(poses, metres):
        assert np.array_equal(T[:3, :3], U[:3, :3])
        assert np.array_equal(T[:3, 3], f * U[:3, 3])


@needs_msolve
@pytest.mark.parametrize("factor", [100.0, 1e-6])
def test_in_other_units_the_same_modes_scaled(factor):
    # 100 m and 1 micrometre: floats of another problem, each entry within round-off
    # of the scaled one, so the same modes to round-off (right, but slow)
    base, platform, lengths = scaled_home_legs()
    metres, _, _ = home_legs_modes()
    poses, complete, _ = stewart_fk_proven(
        factor * base, factor * platform, factor * lengths
    )
    assert complete and len(poses) == len(metres)
    check_modes(poses, factor * base, factor * platform, factor * lengths)
    for T in poses:
        U = T.copy()
        U[:3, 3] /= factor
        assert any(same_pose(U, V, 1.0) for V in metres)


@needs_msolve
@slow
def test_legs_too_short_have_no_mode_and_that_is_proven():
    # legs of 0.1 m cannot span base points 1.1 m apart to platform points 0.54 m
    # apart (triangle inequality: |A_0 - A_1| <= 0.2 + |B_0 - B_1| fails)
    poses, complete, reason = stewart_fk_proven(
        DIETMAIER_BASE, DIETMAIER_PLATFORM, np.full(6, 0.1)
    )
    assert (poses, complete, reason) == ([], True, None)


@needs_msolve
def test_timeout_gives_no_proof():
    _, complete, reason = stewart_fk_proven(
        DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO, timeout=1e-3
    )
    assert not complete and "timeout" in reason


def test_missing_msolve_says_how_to_install(monkeypatch):
    def missing(name):
        raise proven.importlib.metadata.PackageNotFoundError(name)

    monkeypatch.setattr(proven.importlib.metadata, "distribution", missing)
    monkeypatch.setattr(proven.shutil, "which", lambda name: None)
    with pytest.raises(ModuleNotFoundError, match=r"screwkit\[proof\]"):
        stewart_fk_proven(DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO)


# ---- the 3-RPR ----------------------------------------------------------------------


def rpr_points(pm):
    return pm.base_points[:, :2], pm.platform_points[:, :2]


def test_rpr_six_modes_as_rpr_sextic():
    pm = sk.parallel.planar_3rpr()
    rho = np.array(sk.parallel.RPR_SIX_MODES_RHO)
    poses, complete, reason = rpr_fk_proven(*rpr_points(pm), rho)
    assert (len(poses), complete, reason) == (6, True, None)
    reference = sk.parallel.rpr_sextic(pm, rho)
    assert len(reference) == 6
    for T in reference:
        assert any(same_pose(T, U, pm.scale) for U in poses)
    base, platform = rpr_points(pm)
    for T in poses:
        assert leg_error(
            T, np.c_[base, np.zeros(3)], np.c_[platform, np.zeros(3)], rho
        ) < (PARALLEL_FK_ACCEPT_TOL * pm.scale)


@pytest.mark.parametrize("seed", range(5))
def test_rpr_random_instances_as_rpr_sextic_and_in_mm(seed):
    rng = np.random.default_rng(seed)
    base = np.round(rng.uniform(-1, 1, (3, 2)), 3)
    platform = np.round(rng.uniform(-0.5, 0.5, (3, 2)), 3)
    rho = np.round(rng.uniform(0.4, 1.6, 3), 3)
    pm = sk.parallel.planar_3rpr(base=base, platform=platform, leg_limits=None)
    poses, complete, _ = rpr_fk_proven(base, platform, rho)
    assert complete
    reference = sk.parallel.rpr_sextic(pm, rho)
    assert len(reference) == len(poses)
    for T in reference:
        assert any(same_pose(T, U, pm.scale) for U in poses)
    mm = rpr_fk_proven(
        in_decimal_units(base, "1000"),
        in_decimal_units(platform, "1000"),
        in_decimal_units(rho, "1000")[0],
    )
    assert len(mm[0]) == len(poses) and mm[1]


def test_rpr_mode_at_a_half_turn_is_found():
    # the platform turned by exactly pi (R = -I) with its point 0 at q = (0.3, 0.4):
    # t = tan(phi / 2) is infinite there, outside the polynomial. Leg k runs from a_k
    # to q - b_k; a_k + b_k = 0, (-0.3, -0.4), (-0.5, 1) make the legs exact: 0.5, 1, 1
    base = np.array([[0.0, 0.0], [-1.0, 0.0], [0.0, 1.0]])
    platform = np.array([[0.0, 0.0], [0.7, -0.4], [-0.5, 0.0]])
    q = np.array([0.3, 0.4])
    rho = np.array([0.5, 1.0, 1.0])
    assert np.allclose(np.linalg.norm(q - platform - base, axis=1), rho)
    poses, complete, _ = rpr_fk_proven(base, platform, rho)
    assert complete
    half_turns = [T for T in poses if np.allclose(T[:2, :2], -np.eye(2))]
    assert len(half_turns) == 1 and np.allclose(half_turns[0][:2, 3], q)


def test_rpr_self_motion_is_a_continuum():
    # congruent base and platform, equal legs: the platform translates on a circle
    base = np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]])
    poses, complete, reason = rpr_fk_proven(base, base, [0.5, 0.5, 0.5])
    assert not complete and "self-motion" in reason


@needs_msolve
def test_fk_all_with_proof_is_the_proven_list_and_says_complete():
    pm = stewart_of(DIETMAIER_BASE, DIETMAIER_PLATFORM)
    modes = pm.fk_all(np.array(DIETMAIER_RHO, float), proof=True)
    assert (len(modes), modes.complete, modes.reason) == (40, True, None)
    assert "msolve" in modes.method
    check_modes(modes, DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO)
    fast = pm.fk_all(np.array(DIETMAIER_RHO, float))
    assert fast.complete is False and "may miss" in fast.reason


def test_fk_all_with_proof_on_the_3rpr():
    pm = sk.parallel.planar_3rpr()
    rho = np.array(sk.parallel.RPR_SIX_MODES_RHO)
    modes = pm.fk_all(rho, proof=True)
    assert (len(modes), modes.complete) == (6, True)
    for T in sk.parallel.rpr_sextic(pm, rho):
        assert any(same_pose(T, U, pm.scale) for U in modes)
    with pytest.raises(TypeError, match="proof"):
        pm.fk_all(rho, proof="yes")


def test_3rrr_modes_are_the_elbows_3rpr_and_contain_the_search():
    """A 3-RRR with its cranks held is a 3-RPR on its elbows: the sextic's modes, up to
    six, each reproducing the cranks, containing every mode a long search finds, the
    same with proof=True (exact roots) as in floating point."""
    rrr = sk.parallel.planar_3rrr(1, 0.6, 0.8, 0.9)  # a geometry with six at times
    rng = np.random.default_rng(0)
    counts = []
    for _ in range(20):
        T = np.eye(4)
        T[:2, :2] = sk.rotz(rng.uniform(-1, 1))[:2, :2]
        T[:2, 3] = rng.uniform(-0.3, 0.3, 2)
        theta = rrr.ik(T)
        if np.isnan(theta).any():  # out of reach
            continue
        modes = rrr.fk_all(theta)
        counts.append(len(modes))
        assert 1 <= len(modes) <= 6 and not modes.complete
        assert any(same_pose(T, U, rrr.scale) for U in modes)
        for U in modes:  # every mode holds the cranks at theta in one working mode
            assert any(
                np.allclose(sk.wrap_angle(q - theta), 0, atol=1e-7)
                for q in rrr.ik_all(U).values()
            )
        for U in sk.parallel.search.multistart(rrr, theta, 1000, 0):
            assert any(same_pose(U, V, rrr.scale) for V in modes)
        proven_modes = rrr.fk_all(theta, proof=True)
        assert proven_modes.complete and len(proven_modes) == len(modes)
    assert max(counts) == 6  # the most a 3-RRR can have, reached
