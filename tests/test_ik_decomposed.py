"""The decomposed closed form (screwkit/ik/decomposed.py) through ``sk.ik.analytic_ik``:
random decomposable 6R arms (spherical wrist without 2 || 3, spherical shoulder, three
parallel axes 2, 3, 4 and 3, 4, 5 with offsets), the zoo, 7R arms with a joint fixed.

The references are independent of screwkit's IK: the configuration that generated each
pose, the chain's forward kinematics, and a multi-start Newton search written here in
plain NumPy (its own product of exponentials, central differences, 300 starts) whose
every converged solution must be among those returned."""

import importlib
import os

import numpy as np
import pytest
from builders import arm_from_axes, random_arm

import screwkit as sk
from screwkit import ik
from screwkit.ik.decomposed import DecomposedArm, classify

STARTS = 300
RNG_SEED = 20261202


def unit(v):
    return v / np.linalg.norm(v)


def wrapped(a):
    return np.angle(np.exp(1j * np.asarray(a)))


# ---- the independent search ----------------------------------------------------------


def poe(S, M, Q):
    """T(q) = exp(S1 q1) ... exp(S6 q6) M for joint vectors Q (k, 6): (k, 4, 4)."""
    T = np.broadcast_to(np.eye(4), (len(Q), 4, 4)).copy()
    for i in range(6):
        w, v = S[i, :3], S[i, 3:]
        K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
        t = Q[:, i][:, None, None]
        R = np.eye(3) + np.sin(t) * K + (1 - np.cos(t)) * (K @ K)
        # the translation of exp([S] t) for a revolute screw: (I - R)(w x v)
        E = np.zeros((len(Q), 4, 4))
        E[:, :3, :3] = R
        E[:, :3, 3] = (np.eye(3) - R) @ np.cross(w, v)
        E[:, 3, 3] = 1
        T = T @ E
    return T @ M


def newton_search(S, M, T, rng, starts=STARTS, iterations=60):
    """Every solution a damped Gauss-Newton search finds from random starts: the
    residual is the 12 entries of [R - R_T, p - p_T], the Jacobian central
    differences."""
    Q = rng.uniform(-np.pi, np.pi, (starts, 6))

    def residual(Q):
        D = poe(S, M, Q) - T
        return np.concatenate([D[:, :3, :3].reshape(-1, 9), D[:, :3, 3]], 1)

    h = 1e-7
    for _ in range(iterations):
        F = residual(Q)
        J = np.stack(
            [
                (residual(Q + h * np.eye(6)[i]) - residual(Q - h * np.eye(6)[i]))
                / (2 * h)
                for i in range(6)
            ],
            -1,
        )
        JtJ = np.swapaxes(J, 1, 2) @ J
        damping = 1e-9 + np.sum(F**2, 1)[:, None, None]
        step = np.linalg.solve(
            JtJ + damping * np.eye(6), np.swapaxes(J, 1, 2) @ F[..., None]
        )
        Q = Q - step[..., 0]
    F = np.abs(residual(Q)).max(1)
    found = wrapped(Q[F < 1e-10])
    distinct = []
    for q in found:
        if all(np.abs(wrapped(q - d)).max() > 1e-5 for d in distinct):
            distinct.append(q)
    return distinct


# ---- the checks ----------------------------------------------------------------------


def check_pose(chain, q, rng, search=True):
    T = chain.fk(q)
    solutions = ik.analytic_ik(chain, T)
    assert solutions.reason is None, solutions.reason
    Q = np.array([s.q for s in solutions])
    # every solution reaches the pose, by the chain's own forward kinematics
    D = chain.fk(Q) - T
    assert np.abs(D).max() <= 1e-9
    assert max(s.residual for s in solutions) <= 1e-9
    # the generating configuration is among them
    assert np.abs(wrapped(Q - q)).max(1).min() <= 1e-7
    # no two the same
    for i in range(len(Q)):
        for j in range(i):
            assert np.abs(wrapped(Q[i] - Q[j])).max() > 1e-7
    if search:
        for found in newton_search(chain.screw_axes(), chain.home(), T, rng):
            assert np.abs(wrapped(Q - found)).max(1).min() <= 1e-6, found
    return len(Q)


@pytest.mark.parametrize(
    "kind, name",
    [
        ("wrist", "spherical wrist (4, 5, 6 meet)"),
        ("shoulder", "spherical shoulder (1, 2, 3 meet)"),
        ("parallel 234", "three parallel (2, 3, 4)"),
        ("parallel 345", "three parallel (3, 4, 5)"),
    ],
)
def test_random_decomposable_arms(kind, name):
    rng = np.random.default_rng(RNG_SEED + len(kind))
    counts = []
    for _ in range(4):
        chain = random_arm(kind, rng)
        assert ik.structure(chain) == name
        assert classify(chain).kind == kind.replace("wrist", "wrist")
        for k in range(3):
            q = rng.uniform(-np.pi, np.pi, 6)
            counts.append(check_pose(chain, q, rng, search=k == 0))
    assert max(counts) >= 4  # more than a pair of branches is found somewhere


def test_many_random_poses_without_the_search():
    rng = np.random.default_rng(RNG_SEED)
    for kind in ("wrist", "shoulder", "parallel 234", "parallel 345"):
        chain = random_arm(kind, rng)
        q = rng.uniform(-np.pi, np.pi, (200, 6))
        T = chain.fk(q)
        Q = ik.analytic_ik_all(chain, T)  # (200, 8, 6)
        for k in range(200):
            rows = Q[k][~np.isnan(Q[k, :, 0])]
            assert np.abs(chain.fk(rows) - T[k]).max() <= 1e-9
            assert np.abs(wrapped(rows - q[k])).max(1).min() <= 1e-7


def test_eight_solutions_of_a_general_spherical_wrist_arm():
    """A Pieper arm (spherical wrist, no other condition) has up to 8 solutions: some
    random pose of some random arm reaches 8, each checked by forward kinematics."""
    rng = np.random.default_rng(7)
    best = 0
    for _ in range(5):
        chain = random_arm("wrist", rng)
        Q = ik.analytic_ik_all(chain, chain.fk(rng.uniform(-np.pi, np.pi, (50, 6))))
        best = max(best, int((~np.isnan(Q[..., 0])).sum(-1).max()))
    assert best == 8


def test_ur5e_urdf_decomposed_agrees_with_the_ur_engine():
    """The zoo's URDF arm (screwkit/data/ur5e.urdf): the decomposed engine (three
    parallel axes 2, 3, 4, by subproblem 6) and the UR engine (Hawkins' steps) give the
    same solution sets, and the Newton search finds nothing else."""
    chain = sk.Chain.from_urdf(
        str(sk.robots.__file__).replace("robots.py", "data/ur5e.urdf")
    )
    assert classify(chain).kind == "parallel 234"
    arm = DecomposedArm.from_chain(chain)
    rng = np.random.default_rng(5)
    q = rng.uniform(-np.pi, np.pi, (20, 6))
    T = chain.fk(q)
    Q, residual, free = arm.solve(T)
    reference = ik.analytic_ik_all(chain, T)
    for k in range(20):
        mine = Q[k][~np.isnan(Q[k, :, 0])]
        theirs = reference[k][~np.isnan(reference[k, :, 0])]
        assert len(mine) == len(theirs)
        for row in theirs:
            assert np.abs(wrapped(mine - row)).max(1).min() <= 1e-8
    for found in newton_search(chain.screw_axes(), chain.home(), T[0], rng):
        mine = Q[0][~np.isnan(Q[0, :, 0])]
        assert np.abs(wrapped(mine - found)).max(1).min() <= 1e-6


@pytest.mark.parametrize(
    "robot, joint", [("iiwa14", 2), ("iiwa14", 0), ("panda", 6), ("panda", 4)]
)
def test_7r_with_a_fixed_joint(robot, joint):
    chain = getattr(sk.robots, robot)()
    rng = np.random.default_rng(11)
    q = rng.uniform(-1.5, 1.5, 7)
    T = chain.fk(q)
    solutions = ik.analytic_ik(chain, T, fixed={joint: q[joint]})
    assert "fixed" in solutions.structure
    Q = np.array([s.q for s in solutions])
    assert Q.shape[1] == 7 and np.all(Q[:, joint] == q[joint])
    assert np.abs(chain.fk(Q) - T).max() <= 1e-9
    assert np.abs(wrapped(Q - q)).max(1).min() <= 1e-7
    within = chain.within_limits(Q)
    assert [s.within_limits for s in solutions] == list(np.atleast_1d(within))


def test_7r_without_fixed_is_refused_naming_fixed():
    chain = sk.robots.iiwa14()
    with pytest.raises(ValueError, match="fixed must name one joint"):
        ik.analytic_ik(chain, chain.fk(np.zeros(7)))


def test_a_continuum_is_said():
    """The iiwa with its elbow (joint 4) fixed: shoulder and wrist both spherical, the
    wrist centre at a fixed distance from the shoulder, so a reachable pose has a
    one-parameter family of solutions (the arm turns about the shoulder-wrist line)."""
    chain = sk.robots.iiwa14()
    q = np.array([0.3, 0.8, -0.4, 1.1, 0.5, -0.7, 0.2])
    solutions = ik.analytic_ik(chain, chain.fk(q), fixed={3: q[3]})
    assert "continuum" in solutions.reason
    assert all("continuum" in s.singular for s in solutions)
    Q = np.array([s.q for s in solutions])
    assert np.abs(chain.fk(Q) - chain.fk(q)).max() <= 1e-9


def test_wrist_axes_4_and_6_aligned_is_a_continuum():
    """A spherical wrist whose axes 4 and 6 coincide at q5 = 0: q4 + q6 is all that
    matters there."""
    rng = np.random.default_rng(3)
    w = np.array([unit(rng.normal(size=3)) for _ in range(6)])
    p = rng.normal(size=(6, 3)) * 0.5
    p[3:] = rng.normal(size=3)
    w[5] = w[3]
    chain = arm_from_axes(w, p, rng)
    q = np.array([0.4, -0.6, 1.0, 0.3, 0.0, 0.5])
    solutions = ik.analytic_ik(chain, chain.fk(q))
    assert "continuum" in solutions.reason
    Q = np.array([s.q for s in solutions])
    assert np.abs(chain.fk(Q) - chain.fk(q)).max() <= 1e-9


def test_out_of_reach_has_a_reason():
    rng = np.random.default_rng(4)
    chain = random_arm("wrist", rng)
    T = chain.fk(np.zeros(6))
    T[:3, 3] += 100.0
    solutions = ik.analytic_ik(chain, T)
    assert not solutions and "out of reach" in solutions.reason


def test_within_limits_flags_and_moves():
    rng = np.random.default_rng(8)
    base = random_arm("shoulder", rng)
    qlim = np.tile([-1.0, 1.0], (6, 1))
    chain = sk.Chain.from_screws(base.screw_axes(), base.home(), qlim=qlim)
    q = np.array([0.2, -0.5, 0.7, 0.1, -0.3, 0.9])
    every = ik.analytic_ik(chain, chain.fk(q))
    inside = ik.analytic_ik(chain, chain.fk(q), within_limits=True)
    assert [s.within_limits for s in every] == [
        bool(np.all(np.abs(s.q) <= 1.0)) for s in every
    ]
    assert len(inside) == sum(s.within_limits for s in every) >= 1
    assert all(np.all(np.abs(s.q) <= 1.0) for s in inside)


def test_structures_of_the_zoo():
    assert ik.structure(sk.robots.puma560()) == "spherical wrist (joints 2, 3 parallel)"
    assert ik.structure(sk.robots.ur5e()).startswith("UR-type")
    assert classify(sk.robots.puma560()).kind == "wrist"
    assert classify(sk.robots.ur5e()).kind == "parallel 234"


# ---- the peer: EAIK (.ci/nodeps-requirements.txt) ----------------------------------

REQUIRED = os.environ.get("SCREWKIT_REFERENCES") == "required"


def eaik_hp():
    """EAIK's robot class by its H, P vectors (not ``import eaik``: its package needs
    urchin for URDFs), or a skip when EAIK is not installed."""
    if REQUIRED:
        return importlib.import_module("eaik.IK_HP").HPRobot
    module = pytest.importorskip(
        "eaik.IK_HP", reason="EAIK is not installed: .ci/nodeps-requirements.txt"
    )
    return module.HPRobot


@pytest.mark.parametrize("kind", ["wrist", "shoulder", "parallel 234", "parallel 345"])
def test_every_exact_eaik_solution_is_returned(kind):
    """EAIK's solutions (those whose forward kinematics reach the pose to 1e-8: EAIK
    also returns least-squares approximations) are all among screwkit's, and
    screwkit finds at least as many. Parallel axes in one direction here: EAIK's
    answers for an antiparallel middle axis do not reach their poses."""
    HPRobot = eaik_hp()
    rng = np.random.default_rng(RNG_SEED + 34)
    chain = random_arm(kind, rng, antiparallel=False)
    S, M = chain.screw_axes(), chain.home()
    axes, points = S[:, :3], np.cross(S[:, :3], S[:, 3:])
    robot = HPRobot(
        axes, np.vstack([points[0], np.diff(points, axis=0), M[:3, 3] - points[5]])
    )
    q = rng.uniform(-np.pi, np.pi, (40, 6))
    T = chain.fk(q)
    Q = ik.analytic_ik_all(chain, T)
    for k in range(len(T)):
        pose = T[k].copy()
        pose[:3, :3] = (
            T[k][:3, :3] @ M[:3, :3].T
        )  # EAIK's tool has no rotation at q = 0
        theirs = np.array(robot.IK(pose).Q).reshape(-1, 6)
        if len(theirs):
            theirs = theirs[np.abs(chain.fk(theirs) - T[k]).max((1, 2)) < 1e-8]
        mine = Q[k][~np.isnan(Q[k, :, 0])]
        distinct = []
        for row in theirs:
            assert np.abs(wrapped(mine - row)).max(1).min() <= 1e-6
            if all(np.abs(wrapped(row - d)).max() > 1e-6 for d in distinct):
                distinct.append(row)
        assert len(mine) >= len(distinct)


def test_solutions_sharing_an_angle_are_ordered_by_the_next_one_not_by_round_off():
    # siblings of a spherical-wrist arm share q1 (and q2, q3) in exact arithmetic; in
    # floats their q1 differ in the last bits, and which one is smaller depends on the
    # CPU's SIMD path: the order must come from q4 instead
    from screwkit.ik.decomposed import _angle_order

    q1 = 0.5
    rows = np.array(
        [
            [np.nextafter(q1, 0), -0.9, -1.8, 1.242, -1.3, -1.442],
            [np.nextafter(q1, 1), -0.9, -1.8, -1.9, 1.3, 1.7],
            [np.nan] * 6,
            [-0.2, 0.1, 0.2, 0.3, 0.4, 0.5],
        ]
    )
    for flipped in (rows, rows[[1, 0, 2, 3]]):
        order = _angle_order(flipped[None])[0]
        assert np.allclose(flipped[order][:3, 3], [0.3, -1.9, 1.242])
        assert np.isnan(flipped[order][3]).all()


def dh_chain(rows):
    """A chain of standard DH rows (d, a, alpha), no joint offsets."""
    return sk.Chain.from_table([[0.0, d, a, alpha] for d, a, alpha in rows])


#: Arms whose axes leave them fewer than six degrees of freedom: every
#: pose they reach has a continuum of solutions. (rows, degrees of freedom)
FEWER_FREEDOMS = {
    # all six axes parallel: a planar arm, 3 freedoms (the reproducer)
    "planar": ([(0, 0.3, 0)] * 6, 3),
    # axes 5 and 6 on one line (a5 = d6 = alpha5 = 0): 5 freedoms
    "coincident 5, 6": (
        [
            (0.3, 0, np.pi / 2),
            (0, 0.4, 0),
            (0, 0.1, np.pi / 2),
            (0.35, 0, -np.pi / 2),
            (0, 0, 0),
            (0, 0, 0),
        ],
        5,
    ),
    # axes 2, 3, 4, 5 parallel: 5 freedoms
    "four parallel": (
        [
            (0.3, 0, np.pi / 2),
            (0, 0.4, 0),
            (0, 0.35, 0),
            (0, 0.2, 0),
            (0, 0.15, np.pi / 2),
            (0.1, 0, 0),
        ],
        5,
    ),
}


@pytest.mark.parametrize("name", list(FEWER_FREEDOMS))
def test_a_continuum_is_never_called_out_of_reach(name):
    rows, freedoms = FEWER_FREEDOMS[name]
    chain = dh_chain(rows)
    # an independent count of the freedoms: the rank of central-difference
    # Jacobians of the pose at random configurations
    rng = np.random.default_rng(7)
    ranks = []
    for q in rng.uniform(-np.pi, np.pi, (3, 6)):
        columns = []
        for i in range(6):
            dq = np.zeros(6)
            dq[i] = 1e-6
            columns.append((chain.fk(q + dq) - chain.fk(q - dq))[:3].ravel() / 2e-6)
        sigma = np.linalg.svd(np.array(columns), compute_uv=False)
        ranks.append(int(np.sum(sigma > 1e-6 * sigma[0])))
    assert max(ranks) == freedoms
    assert f"{freedoms} degrees of freedom" in ik.structure(chain)
    if not ik.structure(chain).startswith("general"):
        with pytest.raises(ValueError, match="continuum"):
            ik.analytic_ik_all(chain, chain.fk(np.zeros(6)))
    for q in rng.uniform(-np.pi, np.pi, (3, 6)):
        T = chain.fk(q)
        solutions = ik.analytic_ik(chain, T)
        assert "out of reach" not in (solutions.reason or "")
        assert len(solutions) >= 2 and "continuum" in solutions.reason
        for s in solutions:
            np.testing.assert_allclose(chain.fk(s.q), T, atol=1e-9)


def test_a_pose_off_a_planar_arms_plane_has_no_solution():
    chain = dh_chain([(0, 0.3, 0)] * 6)
    solutions = ik.analytic_ik(chain, sk.transforms.transl(0.0, 0.0, 0.5))
    assert not solutions and "3 degrees of freedom" in solutions.reason
    assert "likely out of its reach" in solutions.reason
