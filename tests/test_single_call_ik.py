"""analytic_ik of one pose: the scalar path (screwkit.ik._one_pose) against the batch
path (the vectorised engines, reached with a batch of one pose) and against the forward
kinematics by the product of exponentials (every solution reaches the pose, the
generating configuration is among them). Regular, singular and unreachable poses, with
and without the joint limits and ``near``.
"""

import numpy as np
import pytest

import screwkit as sk
from screwkit.ik import _one_pose, dispatch


def _pedestal_puma():
    """A PUMA on a turned, raised base with a tool (any base and tool are solved)."""
    c, s = np.cos(0.7), np.sin(0.7)
    base = np.array([[c, -s, 0, 0.2], [s, c, 0, -0.1], [0, 0, 1, 0.672], [0, 0, 0, 1]])
    tool = np.eye(4)
    tool[:3, 3] = [0.01, -0.02, 0.15]
    return sk.robots.puma560().with_base(base).with_tool(tool)


def _ur_with_tool():
    tool = np.eye(4)
    tool[:3, :3] = [[0, 0, 1], [0, 1, 0], [-1, 0, 0]]
    tool[:3, 3] = [0.0, 0.05, 0.1]
    return sk.robots.ur5e().with_tool(tool)


ARMS = {
    "puma560": sk.robots.puma560,
    "pedestal puma": _pedestal_puma,
    "kawasaki": sk.robots.kawasaki_cx210l,
    "ur5e": sk.robots.ur5e,
    "ur5e with tool": _ur_with_tool,
}
SOLVERS = {
    "puma560": _one_pose.solve_wrist,
    "pedestal puma": _one_pose.solve_wrist,
    "kawasaki": _one_pose.solve_wrist,
    "ur5e": _one_pose.solve_ur,
    "ur5e with tool": _one_pose.solve_ur,
}


def _poses(chain, rng, count):
    """Poses of random configurations, some singular (q5 = 0, a stretched or folded
    elbow, joint 3 at 0 or pi), some moved out of reach."""
    Q = rng.uniform(-np.pi, np.pi, (count, 6))
    Q[::7, 4] = 0.0  # the wrist singularity of both structures (q5 = 0)
    Q[1::7, 2] = 0.0
    Q[2::7, 2] = np.pi
    T = chain.fk(Q)
    T[3::7, :3, 3] *= 4.0  # out of reach (mostly): Q no longer generates these
    Q[3::7] = np.nan
    return Q, T


def _same_answers(one, batch):
    assert one.structure == batch.structure
    # the reason's words (the degrees it lists may differ by a turn at +-180, or in
    # the sign of a 0: a joint at pi rounds to -pi on one path)
    assert str(one.reason).split(" q = ")[0] == str(batch.reason).split(" q = ")[0]
    assert [s.config for s in one] == [s.config for s in batch]
    for a, b in zip(one, batch):
        assert a.singular == b.singular and a.within_limits == b.within_limits
        # as angles (modulo 2 pi: a joint at pi may round to -pi on one path)
        difference = np.angle(np.exp(1j * (a.q - b.q)))
        assert np.abs(difference).max() <= (1e-6 if a.singular else 1e-10)
        assert abs(a.residual - b.residual) < 1e-12


@pytest.mark.parametrize("name", ARMS)
def test_kernel_matches_the_vectorised_engine(name):
    chain = ARMS[name]()
    arm = dispatch._arm(chain)
    _, T = _poses(chain, np.random.default_rng(1), 70)
    Q, flags, code = arm._solve(T)
    for k in range(T.shape[0]):
        rows, flags_one, code_one = SOLVERS[name](arm, T[k])
        assert code_one == code[k]
        rows = np.array(rows)
        np.testing.assert_array_equal(np.isnan(rows), np.isnan(Q[k]))
        difference = np.angle(np.exp(1j * (rows - Q[k])))  # angles: modulo 2 pi
        # a regular solution to 1e-10; one on a singularity (an arccos at +-1, a
        # double root) is conditioned as sqrt(eps): round-off of 1e-16 moves it 1e-8
        tolerance = np.where(flags[k].any(axis=1), 1e-6, 1e-10)[:, None]
        assert np.all(np.abs(np.nan_to_num(difference)) <= tolerance)
        np.testing.assert_array_equal(np.array(flags_one), flags[k])


@pytest.mark.parametrize("name", ARMS)
@pytest.mark.parametrize("within_limits", [False, True])
def test_one_pose_answers_as_the_batch_and_reaches_the_pose(name, within_limits):
    chain = ARMS[name]()
    rng = np.random.default_rng(2)
    Q, T = _poses(chain, rng, 42)
    batch = sk.ik.analytic_ik(chain, T, within_limits=within_limits)
    scale = dispatch._arm(chain).scale
    for q, pose, expected in zip(Q, T, batch):
        answer = sk.ik.analytic_ik(chain, pose, within_limits=within_limits)
        _same_answers(answer, expected)
        for solution in answer:  # independent: the product of exponentials
            reached = chain.fk_poe(solution.q)
            error = np.abs(reached - pose)
            worst = max(error[:3, :3].max(), error[:3, 3].max() / scale)
            assert abs(solution.residual - worst) < 1e-12  # the residual it reports
            # regular: 1e-8; on a singularity the closed form is good to sqrt(eps)
            assert worst < (1e-6 if solution.singular else 1e-8)
        generated = not np.isnan(q[0])
        if generated and not within_limits and not any(s.singular for s in answer):
            nearest = answer.nearest(q)
            np.testing.assert_allclose(
                np.angle(np.exp(1j * (nearest.q - q))), 0.0, atol=1e-8
            )


def test_near_sorts_as_the_batch():
    chain = sk.robots.ur5e()
    q = np.array([0.3, -1.2, 1.4, -0.5, 0.9, 2.0])
    T = chain.fk(q)
    one = sk.ik.analytic_ik(chain, T, near=q + 0.01)
    _same_answers(one, sk.ik.analytic_ik(chain, T[None], near=q + 0.01)[0])
    np.testing.assert_allclose(one[0].q, q, atol=1e-9)


def test_outside_the_limits_the_reason_names_them():
    chain = sk.robots.puma560()
    q = np.array([0.0, 0.2, -0.3, 0.0, 0.5, 0.0])
    T = chain.fk(q)
    limits = np.array([[-0.1, 0.1]] * 6)
    narrow = sk.Chain.from_screws(chain.screw_axes(), chain.home(), qlim=limits)
    one = sk.ik.analytic_ik(narrow, T, within_limits=True)
    batch = sk.ik.analytic_ik(narrow, T[None], within_limits=True)[0]
    assert not one and not batch
    assert one.reason.startswith("every solution violates a joint limit")
    assert batch.reason.startswith("every solution violates a joint limit")
    assert one.reason.count(" q = ") == batch.reason.count(" q = ") == 8


@pytest.mark.parametrize(
    "T, error",
    [
        (np.full((4, 4), np.nan), ValueError),
        (np.eye(4) * 2.0, ValueError),
        (np.diag([1.0, 1.0, -1.0, 1.0]), ValueError),  # a reflection
        ("pose", TypeError),
    ],
)
def test_bad_poses_are_refused_as_before(T, error):
    with pytest.raises(error, match="T"):
        sk.ik.analytic_ik(sk.robots.puma560(), T)


def test_one_pose_check():
    from screwkit._checks import one_pose

    T = sk.robots.ur5e().fk(np.full(6, 0.4))
    assert one_pose(T) is T
    bad = T.copy()
    bad[3, 0] = 1e-9
    assert one_pose(bad) is None
    assert one_pose(T.astype(np.float32)) is None
    assert one_pose(T[None]) is None
    assert one_pose(np.diag([1.0, 1.0, -1.0, 1.0])) is None


def test_into_limits_on_floats_matches_the_array_version():
    """_one_pose.into_limits (the smallest whole turn first) against
    dispatch._into_limits (all seven turns k = -3 ... 3 compared): the same flag and,
    where every angle fits, the same angles bit for bit; limits narrow, wide (both -k
    and k fit) and unreachable, angles inside, in the slack and outside."""
    rng = np.random.default_rng(7)
    slack = dispatch.IK_JOINT_LIMIT_SLACK
    for _ in range(400):
        centre = rng.uniform(-8, 8, 6)
        width = rng.choice([0.5, 2.0, 5.0, 4 * np.pi + 0.1, 13.0], 6)
        limits = np.column_stack([centre - width / 2, centre + width / 2])
        q = rng.uniform(-np.pi, np.pi, 6)
        q[0] = limits[0, 1] + slack / 2  # in the slack above the upper limit
        q[1] = 0.0 if width[1] > 4 * np.pi else q[1]  # -2 pi and 2 pi may both fit
        moved, ok = _one_pose.into_limits(q.tolist(), limits.tolist(), slack)
        expected, inside = dispatch._into_limits(q[None], limits)
        assert ok == bool(inside[0])
        if ok:  # else the moved angles are not used (the array version's are junk)
            assert np.array_equal(np.array(moved), expected[0])


def test_one_pose_solutions_pickle_and_copy_with_their_residuals():
    """The scalar path computes a solution's residual when asked: a pickled or copied
    solution carries the same fields, the residual included."""
    import copy
    import pickle

    chain = sk.robots.ur5e()
    q = np.array([0.3, -1.1, 1.4, -0.2, 0.9, 0.5])
    T = chain.fk(q)
    for solution in sk.ik.analytic_ik(chain, T):
        for twin in (pickle.loads(pickle.dumps(solution)), copy.deepcopy(solution)):
            assert type(twin) is sk.ik.IKSolution
            assert np.array_equal(twin.q, solution.q) and twin.config == solution.config
            assert twin.residual == solution.residual
        assert solution.residual < 1e-9  # every closed-form solution reaches T
