"""Every solution of any 6R arm (screwkit.ik.general), checked independently.

The references are not screwkit's: the forward kinematics of a standard DH table and
a multi-start Newton search over 300 random starts are written here in plain NumPy
(not ``numeric_ik``); the closed form of the PUMA 560, the Kawasaki CX210L and the
UR5e (``sk.ik.analytic_ik_all``) is a second, independent solver for those arms.

The random-arm tests run a reduced set by default (the first 200 arms once for the
generating configuration; 12 arms against the search), and the issue's full set
(200 arms, 5 poses each, every one against the search) with
``SCREWKIT_IK_GENERAL_FULL=1`` (213 tests, 5 to 11 minutes on a busy two-core machine).
The default run: the 200 arms take about 2 s of CPU, the file about 18 s wall on
that machine.
"""

import os

import numpy as np
import pytest

import screwkit as sk
from screwkit.ik.general import GeneralIK, general_6r_ik

FULL = os.environ.get("SCREWKIT_IK_GENERAL_FULL") == "1"

#: The residual every returned solution must meet (the issue's goal).
RESIDUAL = 1e-9
#: Two joint vectors are one solution when they agree to this (rad, modulo a turn).
SAME = 1e-6


# ---- the independent references ------------------------------------------------------


def dh_frames(table, q):
    """Standard DH: the frames 0..6 (N, 7, 4, 4) of arms with rows (d, a, alpha) at
    joint angles q (N, 6)."""
    q = np.atleast_2d(q)
    N = q.shape[0]
    frames = np.zeros((N, 7, 4, 4))
    frames[:, 0] = np.eye(4)
    for i, (d, a, alpha) in enumerate(table):
        c, s = np.cos(q[:, i]), np.sin(q[:, i])
        ca, sa = np.cos(alpha), np.sin(alpha)
        A = np.zeros((N, 4, 4))
        A[:, 0] = np.stack([c, -s * ca, s * sa, a * c], axis=1)
        A[:, 1] = np.stack([s, c * ca, -c * sa, a * s], axis=1)
        A[:, 2, 1:] = [sa, ca, d]
        A[:, 3, 3] = 1
        frames[:, i + 1] = frames[:, i] @ A
    return frames


def dh_fk(table, q):
    return dh_frames(table, q)[:, -1]


def pose_gap(T, target):
    """|position difference| + |rotation difference| (Frobenius), per pose."""
    return np.linalg.norm(T[:, :3, 3] - target[:3, 3], axis=1) + np.linalg.norm(
        T[:, :3, :3] - target[:3, :3], axis=(1, 2)
    )


def multistart(table, target, starts=300, seed=0, iterations=150):
    """Every distinct solution Newton reaches from ``starts`` random starts.

    Plain damped Newton on the error (p* - p, (1/2) sum_k r_k x r*_k) with the
    geometric Jacobian from the DH frames; a start counts when its error ends below
    1e-12."""
    rng = np.random.default_rng(seed)
    q = rng.uniform(-np.pi, np.pi, (starts, 6))
    for _ in range(iterations):
        F = dh_frames(table, q)
        p, R = F[:, -1, :3, 3], F[:, -1, :3, :3]
        e = np.concatenate(
            [
                target[:3, 3] - p,
                0.5 * np.sum(np.cross(R, target[None, :3, :3], axis=1), axis=2),
            ],
            axis=1,
        )
        z, o = F[:, :-1, :3, 2], F[:, :-1, :3, 3]
        J = np.concatenate([np.cross(z, p[:, None] - o), z], axis=2).transpose(0, 2, 1)
        JJt = J @ J.transpose(0, 2, 1) + 1e-6 * np.eye(6)
        step = (J.transpose(0, 2, 1) @ np.linalg.solve(JJt, e[..., None]))[..., 0]
        largest = np.max(np.abs(step), axis=1, keepdims=True)
        q = q + step * np.minimum(1, 0.5 / np.maximum(largest, 1e-300))
    ok = pose_gap(dh_fk(table, q), target) < 1e-12
    found = []
    for qi in wrap(q[ok]):
        if not any(np.max(np.abs(wrap(qi - f))) < SAME for f in found):
            found.append(qi)
    return np.array(found).reshape(-1, 6)


def wrap(q):
    return (np.asarray(q) + np.pi) % (2 * np.pi) - np.pi


def contains(Q, q):
    """Whether the joint vector q is among the rows of Q (modulo a turn)."""
    return len(Q) > 0 and np.min(np.max(np.abs(wrap(Q - q)), axis=1)) < SAME


def random_arm(rng):
    """Random standard DH rows (d, a, alpha) and the screwkit chain of them."""
    table = np.column_stack(
        [
            rng.uniform(-1, 1, 6),
            rng.uniform(-1, 1, 6),
            rng.uniform(-np.pi, np.pi, 6),
        ]
    )
    chain = sk.Chain.from_table(np.column_stack([np.zeros(6), table]))
    return table, chain


def arms_and_poses(count, poses, seed):
    rng = np.random.default_rng(seed)
    for _ in range(count):
        table, chain = random_arm(rng)
        for _ in range(poses):
            q = rng.uniform(-np.pi, np.pi, 6)
            yield table, chain, q, dh_fk(table, q)[0]


def check_answer(result, table, target):
    """What every answer must be: sorted, in (-pi, pi], residuals below 1e-9, an
    even count of at most 16, each solution meeting the pose by the DH formula."""
    assert isinstance(result, GeneralIK)
    assert result.reason is None
    k = len(result.Q)
    assert result.Q.shape == (k, 6) and result.residuals.shape == (k,)
    assert k % 2 == 0 and k <= 16
    assert np.all(result.residuals <= RESIDUAL)
    assert np.all(result.Q > -np.pi) and np.all(result.Q <= np.pi)
    assert np.all(pose_gap(dh_fk(table, result.Q), target) < 1e-8)
    assert [tuple(r) for r in result.Q] == sorted(tuple(r) for r in result.Q)


# ---- the tests -----------------------------------------------------------------------


def test_the_references_agree_with_screwkits_forward_kinematics():
    rng = np.random.default_rng(3)
    table, chain = random_arm(rng)
    q = rng.uniform(-np.pi, np.pi, (5, 6))
    np.testing.assert_allclose(dh_fk(table, q), chain.fk(q), atol=1e-12)


def test_the_generating_configuration_is_found_on_200_random_arms():
    for table, chain, q, T in arms_and_poses(200, 5 if FULL else 1, seed=11):
        result = general_6r_ik(chain, T)
        check_answer(result, table, T)
        assert contains(result.Q, q)


def test_a_batch_finds_every_generating_configuration():
    # 100 poses of one arm in one call: the batched elimination, checked pose by pose
    rng = np.random.default_rng(21)
    table, chain = random_arm(rng)
    q = rng.uniform(-np.pi, np.pi, (100, 6))
    T = dh_fk(table, q)
    results = general_6r_ik(chain, T)
    assert isinstance(results, list) and len(results) == 100
    for result, q_k, T_k in zip(results, q, T):
        check_answer(result, table, T_k)
        assert contains(result.Q, q_k)


@pytest.mark.parametrize("arm", range(200 if FULL else 12))
def test_no_solution_of_a_300_start_search_is_missing(arm):
    # the arm's poses in one batched call (5 in the full run), each against the search
    rng = np.random.default_rng(1000 + arm)
    table, chain = random_arm(rng)
    q = rng.uniform(-np.pi, np.pi, (5 if FULL else 2, 6))
    targets = dh_fk(table, q)
    for T, result in zip(targets, general_6r_ik(chain, targets)):
        check_answer(result, table, T)
        searched = multistart(table, T, seed=arm)
        assert len(searched) >= 1  # the search finds the generating one at least
        for s in searched:
            assert contains(result.Q, s), f"the search found {s}, missing"


#: An arm (DH rows d, a, alpha) and a configuration whose pose has 16 real solutions,
#: the most a 6R arm can have (Raghavan and Roth 1993). Constructed here: random arms
#: and configurations with two-decimal numbers, then small random changes kept while
#: the count did not drop, until 16. The test does not trust that search: it counts
#: the solutions by an independent 1000-start Newton search.
SIXTEEN_TABLE = [
    [-0.74, 0.62, 0.55],
    [-0.52, 0.13, 1.67],
    [0.36, 0.91, 0.87],
    [-0.60, 0.20, -1.36],
    [-1.09, 0.57, -0.89],
    [-0.82, 0.05, 1.41],
]
SIXTEEN_Q = [-1.22, -2.14, 1.01, -1.00, -3.11, 2.68]


def test_an_arm_with_16_real_solutions_gets_all_16():
    table = np.asarray(SIXTEEN_TABLE)
    chain = sk.Chain.from_table(np.column_stack([np.zeros(6), table]))
    T = dh_fk(table, SIXTEEN_Q)[0]
    searched = multistart(table, T, starts=1000, seed=5)
    assert len(searched) == 16
    result = general_6r_ik(chain, T)
    check_answer(result, table, T)
    assert len(result.Q) == 16
    for s in searched:
        assert contains(result.Q, s)


@pytest.mark.parametrize("robot", ["puma560", "kawasaki_cx210l", "ur5e"])
def test_arms_with_a_closed_form_get_the_closed_forms_solutions(robot):
    chain = getattr(sk.robots, robot)()
    rng = np.random.default_rng(4)
    for q in rng.uniform(-2.5, 2.5, (4, 6)):
        T = chain.fk(q)
        closed = sk.ik.analytic_ik_all(chain, T)
        closed = closed[~np.isnan(closed).any(axis=1)]
        result = general_6r_ik(chain, T)
        assert result.reason is None
        assert len(result.Q) == len(closed)
        assert np.all(result.residuals <= RESIDUAL)
        for c in closed:
            assert contains(result.Q, c)


def test_lengths_in_millimetres_give_the_same_angles():
    rng = np.random.default_rng(8)
    table, chain = random_arm(rng)
    q = rng.uniform(-np.pi, np.pi, 6)
    mm = table * [1000.0, 1000.0, 1.0]
    chain_mm = sk.Chain.from_table(np.column_stack([np.zeros(6), mm]))
    metres = general_6r_ik(chain, dh_fk(table, q)[0])
    millimetres = general_6r_ik(chain_mm, dh_fk(mm, q)[0])
    assert len(metres.Q) == len(millimetres.Q) >= 2
    np.testing.assert_allclose(millimetres.Q, metres.Q, atol=1e-9)


def test_a_chain_from_screws_with_base_and_tool():
    rng = np.random.default_rng(9)
    table, chain = random_arm(rng)
    base = sk.transforms.transl(0.1, -0.2, 0.3) @ sk.transforms.homogeneous(
        sk.transforms.rotz(0.4)
    )
    tool = sk.transforms.transl(0.0, 0.05, 0.12)
    screws = sk.Chain.from_screws(
        chain.screw_axes(), chain.home(), base=base, tool=tool
    )
    q = rng.uniform(-np.pi, np.pi, 6)
    T = screws.fk(q)
    result = general_6r_ik(screws, T)
    assert result.reason is None and contains(result.Q, q)
    np.testing.assert_allclose(
        base @ dh_fk(table, result.Q) @ tool,
        np.broadcast_to(T, (len(result.Q), 4, 4)),
        atol=1e-9,
    )


def test_a_pose_out_of_reach_has_no_solution_and_says_so():
    rng = np.random.default_rng(10)
    table, chain = random_arm(rng)
    T = sk.transforms.transl(50.0, 0.0, 0.0)  # the arm is at most 6 m across
    result = general_6r_ik(chain, T)
    assert result.Q.shape == (0, 6) and result.residuals.shape == (0,)
    assert "out of reach" in result.reason


def test_a_batch_mixes_poses_in_and_out_of_reach_and_singular_ones():
    # each pose of a batch gets its own answer and reason, as when asked alone
    puma = sk.robots.puma560()
    q = np.array([[0.3, -0.5, 0.8, 0.4, 0.0, 0.2], [0.1, 0.2, -0.3, 0.4, 0.5, 0.6]])
    far = sk.transforms.transl(50.0, 0.0, 0.0)
    T = np.stack([puma.fk(q[0]), far, puma.fk(q[1])])
    singular, out, regular = general_6r_ik(puma, T)
    assert "singular configuration" in singular.reason
    assert out.Q.shape == (0, 6) and "out of reach" in out.reason
    assert regular.reason is None and contains(regular.Q, q[1])
    closed = sk.ik.analytic_ik_all(puma, T[2])
    closed = closed[~np.isnan(closed).any(axis=1)]
    assert len(regular.Q) == len(closed)
    for c in closed:
        assert contains(regular.Q, c)


def test_an_offset_wrist_arm_misses_nothing_the_search_finds():
    # a Kinova-Jaco-like arm: 60 degree wrist, no axes meeting (no closed form here)
    table = np.array(
        [
            [0.2755, 0.0, np.pi / 2],
            [0.0, 0.41, np.pi],
            [-0.0098, 0.0, np.pi / 2],
            [-0.2502, 0.0, np.pi / 3],
            [-0.0856, 0.0, np.pi / 3],
            [-0.2028, 0.0, np.pi],
        ]
    )
    chain = sk.Chain.from_table(np.column_stack([np.zeros(6), table]))
    rng = np.random.default_rng(12)
    for q in rng.uniform(-2, 2, (3, 6)):
        T = dh_fk(table, q)[0]
        result = general_6r_ik(chain, T)
        check_answer(result, table, T)
        assert contains(result.Q, q)
        for s in multistart(table, T, seed=1):
            assert contains(result.Q, s)


def test_a_wrist_singular_pose_is_answered_with_a_reason():
    # PUMA at q5 = 0: axes 4 and 6 aligned, q4 + q6 fixed, a continuum of solutions
    puma = sk.robots.puma560()
    q = np.array([0.3, -0.5, 0.8, 0.4, 0.0, 0.2])
    result = general_6r_ik(puma, puma.fk(q))
    assert "singular configuration" in result.reason
    assert np.all(result.residuals <= RESIDUAL)
    on_continuum = [s for s in result.Q if abs(wrap(s[4])) < SAME]
    assert on_continuum  # points of the continuum: q1..q3 and q4 + q6 as generated
    for s in on_continuum:
        np.testing.assert_allclose(wrap(s[:3] - q[:3]), 0, atol=SAME)
        assert abs(wrap(s[3] + s[5] - q[3] - q[5])) < SAME


def test_an_arm_every_form_of_which_is_degenerate_gets_a_reason():
    # six parallel axes: a planar arm, its poses a continuum or out of reach
    lengths = (0.3, 0.3, 0.3, 0.2, 0.2, 0.1)
    chain = sk.Chain.from_table([[0, 0, a, 0] for a in lengths])
    table = np.array([[0.0, a, 0.0] for a in lengths])
    T = chain.fk([0.3, -0.2, 0.5, 0.1, -0.4, 0.7])
    result = general_6r_ik(chain, T)
    # the search finds points of the continuum, and the reason says both
    assert "degenerate" in result.reason and "continuum" in result.reason
    assert len(result.Q) > 16  # more than a 6R's isolated solutions can be
    assert np.all(pose_gap(dh_fk(table, result.Q), T) < 1e-8)
    above = general_6r_ik(chain, sk.transforms.transl(0.0, 0.0, 0.5))  # off the plane
    assert above.Q.shape == (0, 6) and "degenerate" in above.reason


def test_solutions_sharing_the_eigenvalue_joint_are_all_found():
    # right angles and zero offsets: no form avoids a joint that pairs of solutions
    # share, so the eigenvalue problem has repeated roots (their eigenvectors mix)
    table = np.array(
        [
            [0.0, 0.0, -np.pi / 2],
            [0.0, 0.0, np.pi / 2],
            [0.3, 0.0, np.pi / 2],
            [0.0, 0.0, np.pi / 2],
            [-0.2, 0.4, -np.pi / 2],
            [0.0, 0.25, np.pi / 2],
        ]
    )
    chain = sk.Chain.from_table(np.column_stack([np.zeros(6), table]))
    rng = np.random.default_rng(13)
    targets = dh_fk(table, rng.uniform(-np.pi, np.pi, (3, 6)))
    for T, result in zip(targets, general_6r_ik(chain, targets)):  # one batch
        check_answer(result, table, T)
        searched = multistart(table, T, seed=2)
        assert len(searched) == len(result.Q)
        for s in searched:
            assert contains(result.Q, s)
        # pairs share a joint angle: the repeated roots were there to separate
        shared = np.abs(wrap(result.Q[:, None] - result.Q[None])) < SAME
        assert np.any(shared.sum(axis=(0, 1)) > len(result.Q))


def test_analytic_ik_solves_a_general_arm_with_every_solution():
    """sk.ik.analytic_ik dispatches an arm of no decomposable class to the eigenvalue
    method: the same 16 solutions as the search, each with its residual."""
    table = np.asarray(SIXTEEN_TABLE)
    chain = sk.Chain.from_table(np.column_stack([np.zeros(6), table]))
    T = dh_fk(table, SIXTEEN_Q)[0]
    solutions = sk.ik.analytic_ik(chain, T)
    assert solutions.structure.startswith("general") and solutions.reason is None
    assert len(solutions) == 16
    Q = np.array([s.q for s in solutions])
    for s in multistart(table, T, starts=300, seed=7):
        assert contains(Q, s)
    assert max(s.residual for s in solutions) <= 1e-9
    assert contains(Q, np.asarray(SIXTEEN_Q))


#: The issue's arm: three parallel axes at the base and a wrist of right angles
#: (standard DH rows d, a, alpha).
PARALLEL_BASE_TABLE = np.array(
    [
        [0.4, 0.5, 0.0],
        [0.3, 0.5, 0.0],
        [0.0, 0.0, -np.pi / 2],
        [0.0, 0.0, -np.pi / 2],
        [0.0, 0.5, 0.0],
        [0.0, 0.0, np.pi / 2],
    ]
)


def parallel_base_arm():
    table = PARALLEL_BASE_TABLE
    return table, sk.Chain.from_table(np.column_stack([np.zeros(6), table]))


def test_the_issues_parallel_base_pose_gets_all_eight_solutions():
    # 4 of 8 with reason None (the backward forms of the loop gave every
    # candidate negated, and Newton polished those onto the wrong solutions)
    table, chain = parallel_base_arm()
    q = np.array([0.864816, -2.942255, -2.991873, -1.501858, -1.792111, 2.38058])
    T = dh_fk(table, q)[0]
    result = general_6r_ik(chain, T)
    check_answer(result, table, T)
    assert contains(result.Q, q)
    searched = multistart(table, T, seed=4)
    assert len(searched) == 8 and len(result.Q) == 8
    for s in searched:
        assert contains(result.Q, s)
    solutions = sk.ik.analytic_ik(chain, T)
    assert len(solutions) == 8 and solutions.reason is None


def test_no_pose_of_the_parallel_base_arm_is_short():
    # 60 random poses in one batch: the generating q is always found, and every
    # solution of an independent 300-start search is among the answer's, with the
    # same count (or the answer says it may be incomplete)
    table, chain = parallel_base_arm()
    rng = np.random.default_rng(43)
    qs = rng.uniform(-np.pi, np.pi, (60, 6))
    targets = dh_fk(table, qs)
    for q, T, result in zip(qs, targets, general_6r_ik(chain, targets)):
        assert contains(result.Q, q)
        assert np.all(pose_gap(dh_fk(table, result.Q), T) < 1e-8)
        searched = multistart(table, T, seed=5, iterations=60)
        for s in searched:
            assert contains(result.Q, s), f"the search found {s}, missing"
        if result.reason is None:
            assert len(result.Q) == len(searched)
        else:
            assert "singular" in result.reason or "may be" in result.reason


def test_a_root_that_gives_no_solution_makes_the_answer_say_so(monkeypatch):
    # the old fault, put back: every candidate negated (Newton then polishes them onto
    # 4 of the 8 solutions); the roots left over must make the reason say so
    from screwkit.ik import general

    original = general._candidates

    def negated(*args):
        q, pose, consistent = original(*args)
        return -q, pose, consistent

    monkeypatch.setattr(general, "_candidates", negated)
    general._LAST_FORM.clear()
    table, chain = parallel_base_arm()
    q = np.array([0.864816, -2.942255, -2.991873, -1.501858, -1.792111, 2.38058])
    result = general_6r_ik(chain, dh_fk(table, q)[0])
    assert len(result.Q) < 8 and "may be incomplete" in result.reason


def test_a_repeated_root_short_of_one_solution_makes_the_answer_say_so(monkeypatch):
    # the parallel base arm's 8 solutions share the eigenvalue joint's angle (q5 in
    # the form that solves it) in pairs: 4 double roots. One solution lost from a
    # pair went unreported, its root's angle being matched by the other of the pair
    from screwkit.ik import general

    table, chain = parallel_base_arm()
    q = np.array([0.864816, -2.942255, -2.991873, -1.501858, -1.792111, 2.38058])
    T = dh_fk(table, q)[0]
    general._LAST_FORM.clear()
    whole = general_6r_ik(chain, T)
    assert len(whole.Q) == 8 and whole.reason is None
    assert whole.formulation == "joints 6..1 shifted by 5"  # its roots are q5's
    partners = np.abs(wrap(whole.Q[:, 4] - q[4])) < SAME
    assert np.sum(partners) == 2  # q and one other solution share q5

    original = general._polish

    def losing_q(*args):
        polished, jacobians, residuals, bounds = original(*args)
        lost = np.max(np.abs(wrap(polished - q)), axis=1) < 1e-6
        polished[lost, 0] += 0.3  # every candidate that reached q now misses T
        residuals[lost] = 1.0
        return polished, jacobians, residuals, bounds

    monkeypatch.setattr(general, "_polish", losing_q)
    general._LAST_FORM.clear()
    result = general_6r_ik(chain, T)
    assert len(result.Q) == 7 and not contains(result.Q, q)
    assert result.reason is not None and "may be incomplete" in result.reason
    assert f"{wrap(q[4]):.4f}" in result.reason  # the root short of a solution


def test_singular_solutions_are_flagged_one_by_one():
    # the reason said "singular" but no solution said which
    puma = sk.robots.puma560()
    q = np.array([0.3, -0.5, 0.8, 0.4, 0.0, 0.2])
    result = general_6r_ik(puma, puma.fk(q))
    assert result.singular.shape == (len(result.Q),)
    on_wrist = np.abs(wrap(result.Q[:, 4])) < SAME  # axes 4 and 6 aligned
    assert np.array_equal(result.singular, on_wrist) and on_wrist.any()
    regular = general_6r_ik(puma, puma.fk(np.array([0.3, -0.5, 0.8, 0.4, 0.6, 0.2])))
    assert regular.reason is None and not regular.singular.any()


def test_analytic_ik_of_a_general_arm_flags_its_singular_solutions():
    # IKSolution.singular was always () in the general engine
    table, chain = parallel_base_arm()
    q = np.array([0.3, -0.5, 0.8, 0.4, 0.0, 0.2])  # q5 = 0: the Jacobian loses rank
    F = dh_frames(table, q)[0]
    z, o, p = F[:-1, :3, 2], F[:-1, :3, 3], F[-1, :3, 3]
    J = np.concatenate([np.cross(z, p - o), z], axis=1).T
    sigma = np.linalg.svd(J, compute_uv=False)
    assert sigma[-1] < 1e-12 * sigma[0]  # singular, by the DH Jacobian
    solutions = sk.ik.analytic_ik(chain, dh_fk(table, q)[0])
    flagged = [s for s in solutions if s.singular]
    assert flagged and all(s.singular == ("singular",) for s in flagged)
    assert "singular configuration" in solutions.reason


# ---- one pose a call: its own path, the batch path's answers ------------------------


def same_answer(one, batch, tolerance=1e-9, whole_reason=True):
    """The one-pose answer is the batch path's: the same count, reason, form and
    number of singular solutions, and each regular solution one of the batch's
    (to ``tolerance`` rad, modulo a turn; the order may differ where an angle is
    near pi, which rounds to either end). ``whole_reason`` False: the reasons'
    last sentence only (the degenerate forms a reason lists first depend on the
    order the forms were tried in, which starts with the last that solved)."""
    if whole_reason:
        assert one.reason == batch.reason
    else:
        assert str(one.reason).split("; ")[-1] == str(batch.reason).split("; ")[-1]
    assert one.formulation == batch.formulation
    assert one.Q.shape == batch.Q.shape
    assert one.singular.sum() == batch.singular.sum()
    regular = one.Q[~one.singular]
    if len(regular):
        gaps = np.abs(wrap(regular[:, None] - batch.Q[None])).max(axis=2)
        assert np.all(gaps.min(axis=1) <= tolerance)


def test_one_pose_a_call_gives_the_batch_paths_answers_on_random_arms():
    # the one-pose path (a (4, 4) pose) against the batch path (the same pose among
    # others); both against the DH forward kinematics written here
    rng = np.random.default_rng(71)
    for _ in range(12):
        table, chain = random_arm(rng)
        q = rng.uniform(-np.pi, np.pi, (4, 6))
        q[1, 4] = 0.0  # a wrist-like special configuration, still regular here
        T = dh_fk(table, q)
        T[3, :3, 3] *= 6.0  # out of reach: an answer with a reason, not a crash
        batch = general_6r_ik(chain, T)
        for k in range(4):
            one = general_6r_ik(chain, T[k])
            same_answer(one, batch[k])
            if k < 3:
                check_answer(one, table, T[k])
                assert contains(one.Q, q[k])
            else:
                assert len(one.Q) == 0 and one.reason


@pytest.mark.parametrize("robot", ["puma560", "ur5e"])
def test_one_pose_a_call_of_a_named_arm_matches_the_batch_at_singular_poses(robot):
    # special geometry: shifted forms of the loop, solutions on continua (q5 = 0)
    chain = getattr(sk.robots, robot)()
    rng = np.random.default_rng(72)
    q = rng.uniform(-np.pi, np.pi, (3, 6))
    q[1, 4] = 0.0
    T = chain.fk(q)
    batch = general_6r_ik(chain, T)
    for k in range(3):
        one = general_6r_ik(chain, T[k])
        assert np.abs(chain.fk(one.Q) - T[k]).max() < 1e-9
        same_answer(one, batch[k], whole_reason=False)
        if k != 1:  # at q5 = 0, q is one point of a continuum (q4 + q6 fixed)
            assert contains(one.Q, q[k]) and not one.singular.any()
        else:
            assert one.singular.any() and "singular" in one.reason


def test_analytic_ik_of_one_pose_of_a_general_arm_is_its_batch_answer():
    table, chain = random_arm(np.random.default_rng(73))
    q = np.array([0.4, -1.1, 0.9, 2.2, -0.3, 1.7])
    T = dh_fk(table, q)[0]
    one = sk.ik.analytic_ik(chain, T, near=q)
    batch = sk.ik.analytic_ik(chain, np.stack([T, T]), near=q)[0]
    assert one.structure == batch.structure and one.reason == batch.reason
    assert [s.config for s in one] == [s.config for s in batch]
    for a, b in zip(one, batch):
        assert np.abs(wrap(a.q - b.q)).max() < 1e-9
    assert np.abs(wrap(one[0].q - q)).max() < 1e-9  # nearest first: q itself


def test_null_vectors_of_an_exactly_singular_matrix_polynomial():
    # each real root's vector is M(x)^-1 b (inverse iteration); where M(x) is
    # singular to working precision (its LU breaks down) the SVD gives it instead,
    # for that root alone. M(x) = M0 + x M1 + x^2 M2 built with known null vectors
    from screwkit.ik.general import _null_vectors

    rng = np.random.default_rng(3)
    Q, _ = np.linalg.qr(rng.standard_normal((12, 12)))
    M = np.zeros((3, 12, 12))
    M[0] = np.diag(np.r_[0.0, np.arange(1.0, 12.0)])  # M(0) e0 = 0 exactly
    M[2] = Q  # M(x) = M0 + x^2 Q: nonsingular at x = 1
    x = np.array([0.0, 1.0])
    V = _null_vectors(M, x)  # one shared polynomial, two roots
    assert abs(abs(V[0, 0]) - 1) < 1e-15 and np.all(np.abs(V[0, 1:]) < 1e-15)
    # the regular root: the solve's vector, whatever it is, is finite (no root is
    # left NaN by the other's breakdown)
    assert np.all(np.isfinite(V[1]))
    # a root of a nearly singular M(x): its vector spans the null space
    M[0, 0, 0] = 1e-14
    u = _null_vectors(M, np.array([0.0]))[0]
    assert abs(abs(u[0]) / np.linalg.norm(u) - 1) < 1e-12


def test_the_lapack_calls_give_numpys_public_results_and_errors():
    # the solver calls NumPy's LAPACK gufuncs without np.linalg's checks: the same
    # values as the public functions, and LinAlgError where those raise it
    from screwkit.ik._general_kinematics import (
        lapack_det,
        lapack_eigvals,
        lapack_solve,
        lapack_svd,
    )

    rng = np.random.default_rng(8)
    A, B = rng.standard_normal((3, 12, 12)), rng.standard_normal((3, 12, 24))
    np.testing.assert_array_equal(lapack_solve(A, B), np.linalg.solve(A, B))
    np.testing.assert_array_equal(lapack_det(A), np.linalg.det(A))
    np.testing.assert_array_equal(lapack_eigvals(A), np.linalg.eigvals(A))
    Q = rng.standard_normal((2, 14, 8))
    for mine, public in zip(lapack_svd(Q), np.linalg.svd(Q)):
        np.testing.assert_array_equal(mine, public)
    np.testing.assert_array_equal(
        lapack_svd(A, compute_uv=False), np.linalg.svd(A, compute_uv=False)
    )
    # real eigenvalues come back complex (zero imaginary parts), as the solver reads
    diagonal = np.diag([1.0, 2.0, 3.0])[None]
    assert lapack_eigvals(diagonal).dtype == complex
    np.testing.assert_array_equal(np.sort(lapack_eigvals(diagonal).real), [[1, 2, 3]])
    with pytest.raises(np.linalg.LinAlgError, match="Singular matrix"):
        lapack_solve(np.zeros((1, 3, 3)), np.ones((1, 3, 1)))
