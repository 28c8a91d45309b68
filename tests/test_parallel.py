"""Parallel manipulators: legs' IK, Jacobians, FK, assembly modes, singularities.

Every reference is written here, independently of screwkit: leg lengths from
|p + R b - a| with rotations built from their own formula, Jacobians against central
differences of ik along twists exponentiated by a Taylor series, assembly modes counted
by a dense scan of the platform angle, singular poses from their geometry (concurrent
leg lines, Fichter's 90 degree turn, a stretched limb, vertical forearms).
"""

import numpy as np
import pytest
import sympy as sp
from builders import delta as delta_robot
from builders import refusals, rpr, rrr, stewart
from builders import tripteron as tripteron_robot
from references import rpr_mode_count

import screwkit as sk
from screwkit import parallel

RNG = np.random.default_rng(2026)


# ---- independent references --------------------------------------------------------


def rotation(axis, angle):
    """Rodrigues' formula written out: I + sin(a) K + (1 - cos(a)) K^2."""
    x, y, z = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -z, y], [z, 0, -x], [-y, x, 0]])
    return np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K


def pose(R, p):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    return T


def expm_twist(V, eps):
    """exp(eps [V]) for the space twist V = [w; v], by its Taylor series (30 terms)."""
    w, v = V[:3], V[3:]
    X = np.zeros((4, 4))
    X[:3, :3] = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
    X[:3, 3] = v
    X *= eps
    out, term = np.eye(4), np.eye(4)
    for k in range(1, 30):
        term = term @ X / k
        out = out + term
    return out


def leg_lengths(a, b, T):
    """|p + R b_i - a_i| for each leg, one leg at a time."""
    return np.array(
        [
            np.sqrt(
                sum(
                    (T[k, 3] + sum(T[k, j] * bi[j] for j in range(3)) - ai[k]) ** 2
                    for k in range(3)
                )
            )
            for ai, bi in zip(a, b)
        ]
    )


def random_stewart_pose():
    R = rotation(RNG.normal(size=3), RNG.uniform(0, 0.3))
    return pose(
        R, [RNG.uniform(-0.1, 0.1), RNG.uniform(-0.1, 0.1), RNG.uniform(0.9, 1.2)]
    )


def random_planar_pose(scale=0.1, centre=(0, 0), angle=0.0):
    return pose(
        rotation([0, 0, 1], angle + RNG.uniform(-0.3, 0.3)),
        [
            centre[0] + RNG.uniform(-scale, scale),
            centre[1] + RNG.uniform(-scale, scale),
            0,
        ],
    )


def test_default_stewart_geometry_is_the_documented_one():
    degrees = np.radians([-15, 15, 105, 135, 225, 255])
    assert np.allclose(
        stewart().base_points, np.c_[np.cos(degrees), np.sin(degrees), 0 * degrees]
    )
    degrees = np.radians([-45, 45, 75, 165, 195, 285])
    assert np.allclose(
        stewart().platform_points,
        0.5 * np.c_[np.cos(degrees), np.sin(degrees), 0 * degrees],
    )
    assert np.allclose(stewart().home(), pose(np.eye(3), [0, 0, 1]))


def test_viewer_attributes():
    for pm in (stewart(), rpr(), rrr(), delta_robot(), tripteron_robot()):
        assert pm.base_points.shape == (pm.m, 3) and pm.base_points.dtype == float
        assert pm.platform_points.shape == (pm.m, 3) and isinstance(pm.name, str)
        assert pm.home().shape == (4, 4) and isinstance(pm.planar, bool)
        if pm.planar:
            assert np.all(pm.platform_points[:, 2] == 0) and np.all(
                pm.base_points[:, 2] == 0
            )
    assert stewart().leg_limits.shape == (6, 2) and rrr().leg_limits is None


# ---- inverse kinematics ------------------------------------------------------------


def test_stewart_leg_lengths_match_the_written_out_formula():
    for _ in range(20):
        T = random_stewart_pose()
        expected = leg_lengths(stewart().base_points, stewart().platform_points, T)
        assert np.max(np.abs(stewart().ik(T) - expected)) < 1e-12


def test_stewart_ik_batch_equals_one_by_one():
    T = np.array([random_stewart_pose() for _ in range(50)])
    expected = np.array(
        [leg_lengths(stewart().base_points, stewart().platform_points, t) for t in T]
    )
    assert stewart().ik(T).shape == (50, 6)
    assert np.max(np.abs(stewart().ik(T) - expected)) < 1e-12


def test_3rpr_leg_lengths_match_the_written_out_formula():
    for _ in range(20):
        T = random_planar_pose(centre=(0.3, 0.85), angle=np.pi / 2)
        expected = leg_lengths(rpr().base_points, rpr().platform_points, T)
        assert np.max(np.abs(rpr().ik(T) - expected)) < 1e-12


def test_exact_ik_of_the_stewart_platform():
    T = sp.eye(4)
    T[2, 3] = 1
    rho = stewart().ik(T)
    # leg 1 at home: base (cos 15, -sin 15, 0), platform (cos 45, -sin 45, 0) / 2, 1
    # above
    c15, s15, c45 = sp.cos(sp.pi / 12), sp.sin(sp.pi / 12), sp.sqrt(2) / 2
    expected = sp.sqrt((c45 / 2 - c15) ** 2 + (-c45 / 2 + s15) ** 2 + 1)
    assert all(isinstance(r, sp.Expr) for r in rho)
    assert sp.simplify(rho[0] - expected) == 0
    assert abs(float(rho[0]) - stewart().ik(stewart().home())[0]) < 1e-15


def crank_closure(pm, T, theta, l1, l2):
    """|C_i - B_i(theta_i)| - l2 with B_i written out for the 3-RRR (cranks in the
    plane)."""
    C = (T[:3, :3] @ pm.platform_points.T).T + T[:3, 3]
    B = pm.base_points + l1 * np.c_[np.cos(theta), np.sin(theta), 0 * theta]
    return np.linalg.norm(C - B, axis=1) - l2


def test_3rrr_has_eight_labelled_working_modes_each_closing_the_loops():
    T = pose(rotation([0, 0, 1], 0.2), [0.05, -0.03, 0])
    modes = rrr().ik_all(T)
    assert sorted(modes) == sorted(a + b + c for a in "+-" for b in "+-" for c in "+-")
    solutions = np.array(list(modes.values()))
    assert len({tuple(np.round(s, 9)) for s in solutions}) == 8
    for theta in solutions:
        assert np.max(np.abs(crank_closure(rrr(), T, theta, 0.6, 0.5))) < 1e-12


def test_passive_joints_on_request():
    T = pose(rotation([0, 0, 1], 0.2), [0.05, -0.03, 0])
    result = rrr().ik(T, mode="+-+", passive=True)
    theta = result.rho
    B = rrr().base_points + 0.6 * np.c_[np.cos(theta), np.sin(theta), 0 * theta]
    assert np.allclose(result.passive["elbow"], B) and result.mode == "+-+"
    C = (T[:3, :3] @ rrr().platform_points.T).T + T[:3, 3]
    phi = np.arctan2(C[:, 1] - B[:, 1], C[:, 0] - B[:, 0])
    assert np.allclose(
        np.exp(1j * (theta + result.passive["theta2"])), np.exp(1j * phi)
    )
    leg = stewart().ik(stewart().home(), passive=True)
    n = (
        (stewart().home()[:3, :3] @ stewart().platform_points.T).T
        + [0, 0, 1]
        - stewart().base_points
    ) / leg.rho[:, None]
    assert np.allclose(np.sin(leg.passive["u2"]), n[:, 0])


def test_out_of_reach_gives_nan_rows_and_a_reason_in_a_batch():
    T = np.array([pose(np.eye(3), [0.02, 0, 0]), pose(np.eye(3), [3.0, 0, 0])])
    result = rrr().ik(T, passive=True)
    assert np.all(np.isfinite(result.rho[0])) and np.all(np.isnan(result.rho[1]))
    assert result.reachable.tolist() == [True, False]
    assert result.reason[0] == "" and "cannot reach" in result.reason[1]
    far = stewart().ik(pose(np.eye(3), [0, 0, 3.0]), passive=True)
    assert np.all(np.isnan(far.rho)) and "outside their limits" in far.reason


def test_delta_and_tripteron_ik_closes_their_loops():
    T = pose(np.eye(3), [0.03, -0.02, -0.33])
    theta = delta_robot().ik(T)
    radial = np.c_[
        np.cos(np.radians([0, 120, 240])), np.sin(np.radians([0, 120, 240])), [0] * 3
    ]
    B = 0.2 * radial + 0.2 * (
        np.cos(theta)[:, None] * radial - np.sin(theta)[:, None] * [0, 0, 1]
    )
    C = 0.05 * radial + T[:3, 3]
    assert np.max(np.abs(np.linalg.norm(C - B, axis=1) - 0.45)) < 1e-12
    p = np.array([0.3, 0.4, 0.36])
    d = tripteron_robot().ik(pose(np.eye(3), p))
    # carriage i moves along axis e_i from (0, 1, 0), (0, 0, 1), (0, 0, 0): its position
    # is e_i . (p + b_i - carriage_i), with b_i = (0, .1, 0), (0, 0, .1), (.1, 0, 0)
    # normal to e_i
    assert np.max(np.abs(d - [p[0], p[1], p[2]])) < 1e-15


# ---- Jacobians ---------------------------------------------------------------------


def finite_difference_jacobian(pm, T, freedoms, mode=None, eps=1e-5):
    J = np.zeros((pm.m, 6))
    for k in freedoms:
        V = np.zeros(6)
        V[k] = 1.0
        plus = pm.ik(expm_twist(V, eps) @ T, mode=mode)
        minus = pm.ik(expm_twist(V, -eps) @ T, mode=mode)
        J[:, k] = (plus - minus) / (2 * eps)
    return J


@pytest.mark.parametrize(
    "build, make, freedoms",
    [
        (stewart, random_stewart_pose, range(6)),
        (
            rpr,
            lambda: random_planar_pose(centre=(0.3, 0.85), angle=np.pi / 2),
            [2, 3, 4],
        ),
        (rrr, lambda: random_planar_pose(0.05), [2, 3, 4]),
        (delta_robot, lambda: pose(np.eye(3), [0.02, 0.01, -0.33]), [3, 4, 5]),
        (tripteron_robot, lambda: pose(np.eye(3), [0.3, 0.4, 0.36]), [3, 4, 5]),
    ],
)
def test_jacobian_matches_finite_differences_of_ik(build, make, freedoms):
    pm = build()
    for mode in pm.working_modes[:4]:
        T = make()
        J = pm.jacobian(T, mode=mode)
        assert J.shape == (pm.m, 6)
        reference = finite_difference_jacobian(pm, T, freedoms, mode)
        assert (
            np.max(np.abs(J[:, list(freedoms)] - reference[:, list(freedoms)])) < 1e-7
        )


def test_stewart_jacobian_rows_are_unit_line_screws_and_batch():
    T = np.array([random_stewart_pose() for _ in range(30)])
    J = stewart().jacobian(T)
    assert J.shape == (30, 6, 6)
    for t, j in zip(T, J):
        C = (t[:3, :3] @ stewart().platform_points.T).T + t[:3, 3]
        n = (C - stewart().base_points) / np.linalg.norm(
            C - stewart().base_points, axis=1
        )[:, None]
        assert np.allclose(j, np.c_[np.cross(stewart().base_points, n), n], atol=1e-14)


def test_exact_jacobian_equals_the_numeric_one():
    for pm in (stewart(), rpr(), rrr()):
        exact = pm.jacobian(pm.home_exact())
        assert isinstance(exact, sp.MatrixBase)
        assert (
            np.max(np.abs(np.array(exact.evalf(), float) - pm.jacobian(pm.home())))
            < 1e-14
        )


# ---- forward kinematics ------------------------------------------------------------


@pytest.mark.parametrize(
    "build, make",
    [
        (stewart, random_stewart_pose),
        (rpr, lambda: random_planar_pose(centre=(0.3, 0.85), angle=np.pi / 2)),
        (rrr, lambda: random_planar_pose(0.05)),
        (delta_robot, lambda: pose(np.eye(3), [0.02, 0.01, -0.33])),
        (tripteron_robot, lambda: pose(np.eye(3), [0.3, 0.4, 0.36])),
    ],
)
def test_fk_of_ik_returns_the_pose_from_a_nearby_guess(build, make):
    pm = build()
    T = make()
    guess = (
        expm_twist(
            np.array([0.02, -0.01, 0.03, 0.01, 0.02, -0.01])[[list(range(6))][0]]
            * np.isin(range(6), pm.freedoms),
            1.0,
        )
        @ T
    )
    result = pm.fk(pm.ik(T), guess=guess)
    assert result.success and np.max(np.abs(result.T - T)) < 1e-9


def test_batched_fk_with_batched_guesses():
    T = np.array([random_stewart_pose() for _ in range(100)])
    guess = np.array([expm_twist(RNG.normal(size=6), 0.02) @ t for t in T])
    result = stewart().fk(stewart().ik(T), guess=guess)
    assert result.T.shape == (100, 4, 4) and result.success.all()
    assert np.max(np.abs(result.T - T)) < 1e-9


def test_fk_that_cannot_converge_says_so():
    # a 3-RPR whose platform is its base halved: at R = I, p = 0 every leg points at the
    # origin, so no leg can turn the platform (the omega_z column of J is exactly zero)
    # and no Newton step exists from that guess
    halved = parallel.planar_3rpr(
        [[1, 0], [-1, 1], [0, -2]], [[0.5, 0], [-0.5, 0.5], [0, -1]]
    )
    rho = halved.ik(pose(rotation([0, 0, 1], 0.5), [0.1, 0.2, 0]))
    result = halved.fk(rho, guess=np.eye(4))
    assert not result.success and np.all(np.isnan(result.T))
    # too few steps from a far guess: not converged, and said so
    T = random_stewart_pose()
    far = pose(rotation([1, 1, 0], 0.8), [0.3, 0, 0.8])
    result = stewart().fk(stewart().ik(T), guess=far, max_iterations=2)
    assert not result.success and np.all(np.isnan(result.T)) and result.error > 1e-6
    # leg lengths that no pose has (legs 1 and 2: 1 cm each, platform points 0.58 m
    # apart)
    result = rpr().fk([0.01, 0.01, 1.5])
    assert not result.success and np.all(np.isnan(result.T)) and result.error > 1e-3


# ---- every assembly mode -----------------------------------------------------------


def test_3rpr_instance_with_six_real_modes_returns_exactly_six():
    rho = np.array(parallel.RPR_SIX_MODES_RHO)
    a, b = rpr().base_points[:, :2], rpr().platform_points[:, :2]
    assert rpr_mode_count(a, b, rho) == 6
    poses = rpr().fk_all(rho)
    assert len(poses) == 6
    for T in poses:
        assert (
            np.max(
                np.abs(leg_lengths(rpr().base_points, rpr().platform_points, T) - rho)
            )
            < 1e-9
        )


def test_3rpr_fk_all_returns_the_generating_pose_and_counts_agree_with_the_scan():
    for _ in range(10):
        T = random_planar_pose(0.3, centre=(0.3, 0.5), angle=RNG.uniform(-3, 3))
        rho = rpr().ik(T)
        poses = rpr().fk_all(rho)
        assert min(np.max(np.abs(P - T)) for P in poses) < 1e-9
        assert len(poses) == rpr_mode_count(
            rpr().base_points[:, :2], rpr().platform_points[:, :2], rho
        )
        for P in poses:
            assert (
                np.max(
                    np.abs(
                        leg_lengths(rpr().base_points, rpr().platform_points, P) - rho
                    )
                )
                < 1e-9
            )


def test_stewart_fk_all_returns_the_generating_pose_and_only_true_modes():
    T = random_stewart_pose()
    rho = stewart().ik(T)
    poses = stewart().fk_all(rho)
    assert min(np.max(np.abs(P - T)) for P in poses) < 1e-9
    mirror = np.diag([1.0, 1, -1, 1]) @ T @ np.diag([1.0, 1, -1, 1])
    assert min(np.max(np.abs(P - mirror)) for P in poses) < 1e-9
    for P in poses:
        assert np.allclose(P[:3, :3].T @ P[:3, :3], np.eye(3), atol=1e-12)
        assert (
            np.max(
                np.abs(
                    leg_lengths(stewart().base_points, stewart().platform_points, P)
                    - rho
                )
            )
            < 1e-9
        )


# ---- wrenches and singularities ----------------------------------------------------


def test_wrenches_joshi_tsai_form():
    actuation, constraint = stewart().wrenches(stewart().home())
    assert actuation.rank == 6 and constraint.rank == 0
    for pm in (rpr(), rrr(), delta_robot(), tripteron_robot()):
        actuation, constraint = pm.wrenches(pm.home_exact())
        assert not actuation.numeric and actuation.rank == 3 and constraint.rank == 3
        assert actuation.union(constraint).rank == 6
    # the 3-RPR's constraint wrenches: the couples about x and y and the force along z
    _, constraint = rpr().wrenches(rpr().home_exact())
    assert (
        sk.ScrewSystem(
            [[0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 1, 0, 0, 0]], kind=sk.Wrench
        )
        .union(constraint)
        .rank
        == 3
    )


def exact_pose(R, p):
    T = sp.eye(4)
    T[:3, :3], T[:3, 3] = R, sp.Matrix(p)
    return T


def test_3rpr_direct_singularity_when_the_leg_lines_meet_in_one_point():
    base = [[1, 0], [-1, 1], [0, -2]]
    platform = [
        [sp.Rational(1, 2), 0],
        [sp.Rational(-1, 2), sp.Rational(1, 2)],
        [0, -1],
    ]
    pm = parallel.planar_3rpr(sp.Matrix(base), sp.Matrix(platform))
    # the platform is the base halved about the origin: at R = I, p = 0 every leg line
    # runs through the origin, after a half turn too, and at R = I, p any, through 2 p
    # (similar triangles with one orientation); turned by a quarter, they meet in no
    # point
    assert pm.singularities(exact_pose(sp.eye(3), [0, 0, 0])) == {"direct"}
    assert pm.singularities(exact_pose(sk.rotz(sp.pi), [0, 0, 0])) == {"direct"}
    assert pm.singularities(exact_pose(sp.eye(3), [sp.Rational(1, 10), 0, 0])) == {
        "direct"
    }
    T = exact_pose(sk.rotz(sp.pi / 2), [sp.Rational(1, 10), 0, 0])
    assert pm.singularities(T) == set()
    # the lines' Pluecker coordinates (n, A x n) in the plane, written out: det != 0
    Tn = np.array(T.evalf(), float)
    A = np.array(base, float)
    C = (Tn[:2, :2] @ np.array(platform, float).T).T + Tn[:2, 3]
    n = C - A
    assert abs(np.linalg.det(np.c_[n, A[:, 0] * n[:, 1] - A[:, 1] * n[:, 0]])) > 0.1


def test_fichter_singularity_of_the_symmetric_stewart_platform():
    for height in (sp.Rational(7, 10), 1, sp.Rational(3, 2)):
        for angle in (sp.pi / 2, -sp.pi / 2):
            T = exact_pose(sk.rotz(angle), [0, 0, height])
            assert stewart().singularities(T) == {"direct"}
            # the same with six legs' lines written out here: their 6 x 6 is singular
            Tn = np.array(T.evalf(), float)
            C = (Tn[:3, :3] @ stewart().platform_points.T).T + Tn[:3, 3]
            n = C - stewart().base_points
            assert (
                abs(np.linalg.det(np.c_[n, np.cross(stewart().base_points, n)])) < 1e-12
            )
        assert (
            stewart().singularities(exact_pose(sk.rotz(sp.pi / 3), [0, 0, height]))
            == set()
        )


def test_inverse_singularity_of_a_stretched_3rrr_limb():
    # leg 1: A = (1, 0), platform point p + (1/4, 0); p = (-7/20, 0) puts it 11/10 = l1
    # + l2 away
    T = exact_pose(sp.eye(3), [sp.Rational(-7, 20), 0, 0])
    assert "inverse" in rrr().singularities(T)
    assert (
        rrr().singularities(exact_pose(sp.eye(3), [sp.Rational(-3, 10), 0, 0])) == set()
    )


def test_constraint_singularity_of_the_delta_with_vertical_forearms():
    # cos(theta) = (r_p - R_b) / l1 = -3/4 puts every elbow above its platform point:
    # the three constraint couples (along each forearm's part normal to its crank axis)
    # are all along z
    height = -sp.sqrt(7) / 20 - sp.Rational(9, 20)
    T = exact_pose(sp.eye(3), [0, 0, height])
    found = {mode: delta_robot().singularities(T, mode=mode) for mode in ("+++", "---")}
    assert any("constraint" in f for f in found.values())
    assert delta_robot().singularities(delta_robot().home_exact()) == set()


def test_float_and_exact_singularities_agree_on_fichter():
    T = pose(rotation([0, 0, 1], np.pi / 2), [0, 0, 1.1])
    assert stewart().singularities(T) == {"direct"}
    assert stewart().singularities(random_stewart_pose()) == set()


# ---- workspace ---------------------------------------------------------------------


def test_stewart_constant_orientation_workspace():
    x = np.linspace(-0.6, 0.6, 41)
    w = stewart().workspace(x, x, z=1.1)
    assert w.inside.shape == (41, 41) and w.rho.shape == (41, 41, 6)
    X, Y = np.meshgrid(x, x)
    for i, j in [(20, 20), (5, 30), (0, 0), (40, 12)]:
        rho = leg_lengths(
            stewart().base_points,
            stewart().platform_points,
            pose(np.eye(3), [X[i, j], Y[i, j], 1.1]),
        )
        assert w.inside[i, j] == bool(np.all((rho >= 0.9) & (rho <= 1.6)))
    assert w.inside[20, 20] and not w.inside[0, 0]
    chunked = stewart().workspace(x, x, z=1.1, chunk=100)
    assert np.array_equal(chunked.inside, w.inside)
    assert np.allclose(chunked.det, w.det, equal_nan=True)


# ---- bad input ---------------------------------------------------------------------


test_bad_input_is_refused_with_a_sentence = refusals(
    [
        (lambda: stewart().ik(np.eye(3)), ValueError, r"T must have shape \(4, 4\)"),
        (lambda: stewart().ik(np.full((4, 4), np.nan)), ValueError, "T must be finite"),
        (lambda: stewart().ik(np.diag([2.0, 1, 1, 1])), ValueError, "rotation matrix"),
        (lambda: stewart().ik("home"), TypeError, "T must be a number or an array"),
        (lambda: stewart().fk([1.0] * 5), ValueError, r"rho must have shape \(6,\)"),
        (
            lambda: stewart().fk([1.0, 1, 1, 1, 1, -1]),
            ValueError,
            "rho must be leg lengths > 0",
        ),
        (
            lambda: stewart().fk([1.0] * 6, guess=np.eye(3)),
            ValueError,
            "guess must have shape",
        ),
        (
            lambda: stewart().fk([1.0] * 6, guess=np.zeros((3, 4, 4)) + np.eye(4)),
            ValueError,
            "guess must be one pose or 1 poses",
        ),
        (lambda: stewart().fk([np.nan] * 6), ValueError, "rho must be finite"),
        (
            lambda: delta_robot().ik(pose(rotation([1, 0, 0], 0.1), [0, 0, -0.3])),
            ValueError,
            "only translates",
        ),
        (
            lambda: tripteron_robot().jacobian(
                pose(rotation([0, 0, 1], 0.1), [0.3, 0.3, 0.3])
            ),
            ValueError,
            "only translates",
        ),
        (
            lambda: rpr().ik(pose(rotation([1, 0, 0], 0.1), [0, 0, 0])),
            ValueError,
            "planar pose",
        ),
        (lambda: rpr().ik(pose(np.eye(3), [0, 0, 0.2])), ValueError, "planar pose"),
        (lambda: rrr().ik(np.eye(4), mode="++"), ValueError, "mode must be one of"),
        (lambda: rpr().fk_all([[1.0, 1, 1]] * 2), ValueError, "one input"),
        (
            lambda: parallel.stewart_gough(base=np.zeros((5, 3))),
            ValueError,
            r"base must have shape \(6, 3\)",
        ),
        (
            lambda: parallel.planar_3rpr(platform=[[0, 0], [1, "a"], [0, 1]]),
            TypeError,
            "platform must be a number or an array",
        ),
        (
            lambda: parallel.planar_3rrr(l1=-1),
            ValueError,
            "l1 must be a positive length",
        ),
        (lambda: parallel.delta(l2="long"), TypeError, "l2 must be a number"),
        (
            lambda: parallel.stewart_gough(leg_limits=[(1.0, 2.0)] * 5),
            ValueError,
            r"leg_limits must have shape \(6, 2\)",
        ),
        (
            lambda: parallel.planar_3rpr(leg_limits=[(1.0, 0.5)] * 3),
            ValueError,
            "each lower limit below its upper one",
        ),
        (
            lambda: stewart().workspace(np.zeros(4000), np.zeros(4000)),
            ValueError,
            "more than 10000000",
        ),
        (
            lambda: stewart().workspace([0.0], [0.0], chunk=0),
            ValueError,
            "chunk must be",
        ),
    ]
)


def test_catalogue_is_in_robots():
    assert sk.robots.stewart_gough is parallel.stewart_gough
    assert sk.robots.parallel_3rrr is parallel.planar_3rrr
    assert isinstance(sk.robots.delta(), parallel.ParallelManipulator)
    # the mobility analysis of the limbs at a pose agrees with the motion type
    assert sk.mobility(rpr().limbs()[0]).type == rpr().motion_type == "2T1R"
    assert sk.mobility(tripteron_robot().limbs()[0]).number == 3


def test_exact_ik_of_the_3rrr_equals_the_float_one_in_every_mode():
    T = sp.eye(4)
    T[0, 3], T[1, 3] = sp.Rational(1, 20), sp.Rational(-1, 50)
    for mode in ("+++", "-+-"):
        exact = rrr().ik(T, mode=mode)
        assert all(isinstance(t, sp.Expr) for t in exact)
        numeric = rrr().ik(np.array(T, dtype=float), mode=mode)
        assert np.max(np.abs(np.array([float(t) for t in exact]) - numeric)) < 1e-14


def test_delta_fk_all_poses_close_every_loop():
    T = pose(np.eye(3), [0.03, -0.02, -0.33])
    theta = delta_robot().ik(T)
    poses = delta_robot().fk_all(theta)
    assert min(np.max(np.abs(P - T)) for P in poses) < 1e-9
    radial = np.c_[
        np.cos(np.radians([0, 120, 240])), np.sin(np.radians([0, 120, 240])), [0] * 3
    ]
    B = 0.2 * radial + 0.2 * (
        np.cos(theta)[:, None] * radial - np.sin(theta)[:, None] * [0, 0, 1]
    )
    for P in poses:
        assert np.allclose(P[:3, :3], np.eye(3))
        C = 0.05 * radial + P[:3, 3]
        assert np.max(np.abs(np.linalg.norm(C - B, axis=1) - 0.45)) < 1e-9


def test_exact_out_of_reach_is_an_answer_or_a_clear_error():
    far = sp.eye(4)
    far[2, 3] = 3
    assert (
        stewart().ik(far) == [sp.nan] * 6
    )  # legs of 3 m: outside the limits 0.9-1.6 m
    assert "outside their limits" in stewart().ik(far, passive=True).reason
    away = sp.eye(4)
    away[0, 3] = 3
    assert all(r is sp.nan for r in rrr().ik(away))
    J = rrr().jacobian(away)
    assert all(e is sp.nan for e in J)
    with pytest.raises(ValueError, match="out of reach of leg 0"):
        rrr().singularities(away)


# ---- the package's public surface ---------------------------------------------------


def test_the_package_states_its_public_names_and_sk_reaches_them():
    assert "parallel" in sk.__all__ and sk.parallel is parallel
    missing = [name for name in parallel.__all__ if not hasattr(parallel, name)]
    assert not missing
    assert parallel.rpr_sextic in vars(parallel).values()


def test_rpr_sextic_is_a_sextic_whose_real_roots_are_the_scanned_modes():
    rho = np.array(parallel.RPR_SIX_MODES_RHO)
    poses, poly = parallel.rpr_sextic(rpr(), rho, with_polynomial=True)
    roots = poly.roots()
    real = np.abs(roots.imag) < 1e-6 * (1 + np.abs(roots))
    a, b = rpr().base_points[:, :2], rpr().platform_points[:, :2]
    assert poly.degree() == 6 and real.sum() == len(poses) == rpr_mode_count(a, b, rho)
    for T in poses:
        lengths = leg_lengths(rpr().base_points, rpr().platform_points, T)
        assert np.max(np.abs(lengths - rho)) < 1e-9


@pytest.mark.parametrize(
    "call, match",
    [
        (
            lambda: parallel.rpr_sextic(stewart(), [1.0] * 6),
            "pm must be a planar 3-RPR",
        ),
        (lambda: parallel.rpr_sextic(rrr(), [0.1] * 3), "pm must be a planar 3-RPR"),
        (lambda: parallel.rpr_sextic(rpr(), [1.0, 1.0]), "rho must be 3 leg lengths"),
    ],
)
def test_rpr_sextic_refuses_other_mechanisms_and_inputs(call, match):
    with pytest.raises(ValueError, match=match):
        call()


@pytest.mark.parametrize(
    "spoil, match",
    [
        (lambda T: T[:3, 2].__imul__(-1), "determinant"),  # a reflection
        (lambda T: T[0, :3].__imul__(1.01), "orthonormal"),
        (lambda T: T[3].__setitem__(0, 0.5), "last row"),
    ],
)
def test_one_bad_pose_in_a_large_batch_is_refused(spoil, match):
    # the batch spans two of the pose check's blocks; the bad pose is in the second
    T = np.repeat(stewart().home()[None], 10_000, axis=0)
    spoil(T[9_000])
    with pytest.raises(ValueError, match=match):
        stewart().ik(T)


def test_the_same_stewart_platform_in_millimetres_gives_the_same_answers_scaled():
    metres = parallel.stewart_gough(leg_limits=None)
    mm = parallel.stewart_gough(
        1000 * metres.base_points,
        1000 * metres.platform_points,
        height=1000,
        leg_limits=None,
    )
    T = random_stewart_pose()
    T_mm = T.copy()
    T_mm[:3, 3] *= 1000
    assert np.allclose(mm.ik(T_mm), 1000 * metres.ik(T), rtol=1e-12)
    guess_mm = mm.home()
    result, result_mm = metres.fk(metres.ik(T)), mm.fk(mm.ik(T_mm), guess=guess_mm)
    assert result.success and result_mm.success
    assert result.iterations == result_mm.iterations
    assert np.allclose(result_mm.T[:3, :3], result.T[:3, :3], atol=1e-9)
    assert np.allclose(result_mm.T[:3, 3], 1000 * result.T[:3, 3], atol=1e-6)
    modes, modes_mm = metres.fk_all(metres.ik(T)), mm.fk_all(mm.ik(T_mm))
    assert len(modes) == len(modes_mm)


# ---- how far fk_all's answer can be trusted: every mode found, or why not ----------


def test_fk_all_says_whether_it_is_complete_and_how_it_found_the_modes():
    T = random_stewart_pose()
    searched = stewart().fk_all(stewart().ik(T))
    assert isinstance(searched, parallel.AssemblyModes) and isinstance(searched, list)
    assert searched.complete is False and searched.method == "multistart search"
    assert "400 random starts" in searched.reason and not searched.continuum
    sextic = rpr().fk_all(parallel.RPR_SIX_MODES_RHO)
    assert (
        len(sextic) == 6 and not sextic.complete and "floating point" in sextic.reason
    )
    theta = delta_robot().ik(delta_robot().home())
    closed = delta_robot().fk_all(theta)
    assert closed.complete and closed.reason is None
    assert closed.method == "closed form (three spheres)"
    tri = tripteron_robot()
    rails = tri.fk_all(tri.ik(tri.home()))
    assert rails.complete and rails.method == "closed form (linear)"
    assert len(rails) == 1 and np.allclose(rails[0], tri.home(), atol=1e-12)


def three_spheres(centres, radius):
    """The points at ``radius`` from three centres, by elimination written out here:
    subtracting the first sphere's equation from the others leaves two planes, whose
    line p0 + s d meets the first sphere in a quadratic in s."""
    c0, c1, c2 = centres
    N = np.array([c1 - c0, c2 - c0])
    rhs = 0.5 * np.array([c1 @ c1 - c0 @ c0, c2 @ c2 - c0 @ c0])
    d = np.cross(N[0], N[1])
    p0 = np.linalg.lstsq(N, rhs, rcond=None)[0]  # a point of both planes
    a, b, c = d @ d, 2 * d @ (p0 - c0), (p0 - c0) @ (p0 - c0) - radius**2
    disc = b * b - 4 * a * c
    if disc < 0:
        return []
    return [p0 + (-b + s * np.sqrt(disc)) / (2 * a) * d for s in (1, -1)]


def test_delta_closed_form_finds_both_modes_of_random_crank_angles():
    counts = {0: 0, 2: 0}
    for l2 in (0.45, 0.25):  # the catalogue's links, and short ones that miss
        pm = parallel.delta(l2=l2)
        for theta in RNG.uniform(-np.pi, np.pi, (40, 3)):
            counts[len(delta_modes_checked(pm, theta, l2))] += 1
    assert counts[0] > 0 and counts[2] > 0  # both cases drawn


def delta_modes_checked(pm, theta, l2):
    """pm.fk_all(theta) checked against the spheres written out; returns it."""
    radial = np.c_[
        np.cos(np.radians([0, 120, 240])), np.sin(np.radians([0, 120, 240])), [0] * 3
    ]
    elbows = 0.2 * radial + 0.2 * (
        np.cos(theta)[:, None] * radial - np.sin(theta)[:, None] * [0, 0, 1]
    )
    expected = three_spheres(elbows - 0.05 * radial, l2)
    modes = pm.fk_all(theta)
    assert modes.complete and len(modes) == len(expected)
    for p in expected:
        assert min(np.max(np.abs(T[:3, 3] - p)) for T in modes) < 1e-12
    for T in modes:
        assert np.array_equal(T[:3, :3], np.eye(3))
    return modes


def test_delta_with_equal_cranks_returns_the_mirror_mode_above_the_base():
    # the search once returned only the mode below; the mode above (the centres'
    # mirror image) is an assembly mode too
    modes = delta_robot().fk_all(np.full(3, -0.4))
    assert len(modes) == 2
    above, below = modes
    assert above[2, 3] > 0 > below[2, 3]
    crank_height = 0.2 * np.sin(0.4)  # the elbows' common height (theta > 0 lowers)
    assert above[2, 3] + below[2, 3] == pytest.approx(2 * crank_height, abs=1e-12)


def test_a_continuum_is_reported_not_an_empty_list():
    # all platform points at one place: every rotation about it solves, so the
    # answer is a continuum, not an empty list
    pm = parallel.stewart_gough(platform=np.zeros((6, 3)), leg_limits=None)
    modes = pm.fk_all(np.full(6, 1.2))
    assert modes.continuum and not modes.complete and "continuum" in modes.reason
    assert len(modes) >= 1
    height = np.sqrt(1.2**2 - 1.0)  # the base points lie on the unit circle
    for T in modes:
        assert abs(abs(T[2, 3]) - height) < 1e-9 and np.allclose(T[:2, 3], 0)
        assert np.allclose(pm.ik(T), 1.2)


def test_a_3rpr_self_motion_is_reported_with_its_isolated_modes():
    # congruent base and platform, equal legs: the platform translates on a circle
    # of radius 0.5 without turning (a parallelogram motion)
    base = np.array(parallel.RPR_BASE, dtype=float)
    pm = parallel.planar_3rpr(base, base)
    modes = pm.fk_all([0.5, 0.5, 0.5])
    assert modes.continuum and not modes.complete
    on = [T for T in modes if np.allclose(T[:3, :3], np.eye(3), atol=1e-9)]
    assert on and all(abs(np.linalg.norm(T[:2, 3]) - 0.5) < 1e-9 for T in on)
    for T in modes:
        lengths = leg_lengths(pm.base_points, pm.platform_points, T)
        assert np.max(np.abs(lengths - 0.5)) < 1e-9
    turned = [T for T in modes if not np.allclose(T[:3, :3], np.eye(3), atol=1e-9)]
    assert turned  # the modes off the circle are kept too


def test_a_generic_input_is_not_taken_for_a_continuum():
    for T in (random_stewart_pose() for _ in range(3)):
        assert not stewart().fk_all(stewart().ik(T)).continuum
    for rho in ([0.92, 1.37, 0.9], [0.8, 1.1, 0.95]):
        assert not rpr().fk_all(rho).continuum


# ---- singularities robust to round-off and units (tolerances relative to size) ------


def test_a_stewart_leg_near_the_base_x_axis_is_classified_as_exactly_on_it():
    T = stewart().home()
    C0 = stewart().attachments(T)[0]
    answers = []
    for offset in (0.0, 1e-13, 1e-11, 1e-9, 1e-8):
        n = np.array([1.0, offset, 0.0]) / np.hypot(1.0, offset)
        base = stewart().base_points.copy()
        base[0] = C0 - 1.2 * n  # leg 0 along x, `offset` off it
        pm = parallel.stewart_gough(base=base, leg_limits=None)
        answers.append(pm.singularities(T))
    exact_base = sp.Matrix(parallel.STEWART_BASE)
    C0_exact = stewart().attachments(stewart().home_exact())[0]
    exact_base[0, :] = (C0_exact - sp.Matrix([sp.Rational(6, 5), 0, 0])).T
    exact = parallel.stewart_gough(base=exact_base, leg_limits=None)
    assert answers == [exact.singularities(exact.home_exact())] * 5


def test_a_3rrr_pose_on_a_limbs_boundary_in_floats_is_an_inverse_singularity():
    T = np.eye(4)
    T[0, 3] = -0.35  # limb 0 stretched: C_0 at l1 + l2 = 1.1 m from its pivot
    assert np.isfinite(rrr().ik(T)).all()
    assert "inverse" in rrr().singularities(T)


def test_float_poses_with_a_stretched_limb_are_inverse_singularities():
    a0, b0 = rrr().base_points[0, :2], rrr().platform_points[0, :2]
    found = 0
    for _ in range(40):
        phi = RNG.uniform(-0.2, 0.2)
        R = rotation([0, 0, 1], phi)
        angle = np.pi + RNG.uniform(-0.15, 0.15)  # limb 0 pointing inwards, straight
        C0 = a0 + 1.1 * np.array([np.cos(angle), np.sin(angle)])
        T = pose(R, [*(C0 - R[:2, :2] @ b0), 0.0])
        assert np.isfinite(rrr().ik(T)).all()
        found += "inverse" in rrr().singularities(T)
    assert found == 40


@pytest.mark.filterwarnings("ignore::PendingDeprecationWarning")  # np.matrix's own
def test_a_numpy_matrix_pose_is_read_as_an_array():
    T = random_stewart_pose()
    assert np.array_equal(stewart().ik(np.matrix(T)), stewart().ik(T))
    assert np.array_equal(stewart().jacobian(np.matrix(T)), stewart().jacobian(T))


def test_a_delta_whose_spheres_coincide_or_pair_up_reports_its_continuum():
    # equal base and platform radii and cranks pointing down (theta = pi / 2): every
    # sphere's centre B_i - b_i lies on the axis, 0.2 m below the base
    pm = parallel.delta(base_radius=0.2, platform_radius=0.2)
    radial = np.c_[
        np.cos(np.radians([0, 120, 240])), np.sin(np.radians([0, 120, 240])), [0] * 3
    ]

    def closes(T, theta):
        elbows = 0.2 * radial + 0.2 * (
            np.cos(theta)[:, None] * radial - np.sin(theta)[:, None] * [0, 0, 1]
        )
        C = 0.2 * radial + T[:3, 3]
        return np.max(np.abs(np.linalg.norm(C - elbows, axis=1) - 0.45)) < 1e-12

    theta = np.full(3, np.pi / 2)
    sphere = pm.fk_all(theta)
    assert sphere.continuum and not sphere.complete and "sphere" in sphere.reason
    assert len(sphere) == 1 and closes(sphere[0], theta)
    theta = np.array([np.pi / 2, np.pi / 2, -np.pi / 2])  # centres at z = -0.2, +0.2
    circle = pm.fk_all(theta)
    assert circle.continuum and "circle" in circle.reason
    assert len(circle) == 1 and closes(circle[0], theta)
    assert abs(circle[0][2, 3]) < 1e-12  # the circle lies midway, in the base plane
