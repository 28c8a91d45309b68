"""One configuration at a time: the scalar path of FK, the Jacobians and their time
derivatives against the batch path (vectorised NumPy, another cos and sin) and against
references that share no code with either: the product of exponentials
(:meth:`Chain.fk_poe`, a loop of 4 x 4 exponentials) and central differences of it
for the Jacobians, central differences of the batch Jacobian along dq for dJ/dt.
"""

import functools
import sys
from pathlib import Path

import numpy as np
import pytest

import screwkit as sk
from screwkit.motion import _second_order

sys.path.insert(0, str(Path(__file__).resolve().parent))
from builders import random_arm  # noqa: E402

FORMS = ("space", "geometric", "body")


def _offset_arm():
    """A standard DH arm with theta and d offsets, a prismatic joint, base and tool."""
    table = [
        [0.3, 0.2, 0.1, np.pi / 2],
        [-0.4, 0.0, 0.5, 0.0],
        [0.0, 0.25, 0.0, -np.pi / 2],
        [0.2, 0.1, 0.3, np.pi / 3],
    ]
    c, s = np.cos(0.4), np.sin(0.4)
    base = np.array([[c, -s, 0, 0.1], [s, c, 0, -0.2], [0, 0, 1, 0.3], [0, 0, 0, 1]])
    return sk.Chain.from_table(
        table,
        joints="RRPR",
        base=base,
        tool=np.array(
            [[0, -1, 0, 0.05], [1, 0, 0, 0.0], [0, 0, 1, 0.12], [0, 0, 0, 1.0]]
        ),
        name="offsets",
    )


def _modified_arm():
    table = [[0.1, 0.3, 0.0, 0.0], [0.0, 0.0, 0.4, -np.pi / 2], [0.5, 0.1, 0.3, 0.7]]
    return sk.Chain.from_table(table, convention=sk.Convention.MODIFIED, name="mdh")


def _body_form(chain):
    """The same arm from its body screws (the body form of the product)."""
    return sk.Chain.from_screws(
        chain.body_screw_axes(), chain.home(), frame="body", name="body form"
    )


@functools.cache
def _chains():
    """The arms of the tests, built once on first use (never at import)."""
    rng = np.random.default_rng(44)
    arms = [
        sk.robots.puma560(),
        sk.robots.ur5e(),
        sk.robots.stanford(),
        sk.robots.panda(),
        sk.robots.planar([1.0, 0.7, 0.4]),
        _offset_arm(),
        _modified_arm(),
        random_arm("general", rng),
        random_arm("wrist", rng),
    ]
    return dict(zip(IDS, arms + [_body_form(sk.robots.ur5e())], strict=True))


IDS = [
    "puma560",
    "ur5e",
    "stanford",
    "panda",
    "planar 3R",
    "offset arm",
    "modified DH arm",
    "random general arm",
    "random wrist arm",
    "ur5e body form",
]


def _configurations(chain, count=5, seed=0):
    return np.random.default_rng(seed).uniform(-2.5, 2.5, (count, chain.n))


def _poe_jacobian(chain, q, h=1e-6):
    """The geometric Jacobian by central differences of the product of exponentials
    (rows [v; omega]; omega from dR/dq R^T)."""
    R = chain.fk_poe(q)[:3, :3]
    columns = []
    for step in h * np.eye(chain.n):
        plus, minus = chain.fk_poe(q + step), chain.fk_poe(q - step)
        v = (plus[:3, 3] - minus[:3, 3]) / (2 * h)
        W = (plus[:3, :3] - minus[:3, :3]) / (2 * h) @ R.T
        columns.append(np.concatenate([v, [W[2, 1], W[0, 2], W[1, 0]]]))
    return np.array(columns).T


@pytest.mark.parametrize("name", IDS)
def test_fk_single_matches_batch_and_product_of_exponentials(name):
    chain = _chains()[name]
    Q = _configurations(chain)
    batch = chain.fk(Q)
    for q, T_batch in zip(Q, batch):
        T = chain.fk(q)
        assert T.shape == (4, 4) and T.dtype == np.float64
        np.testing.assert_allclose(T, T_batch, rtol=0, atol=1e-12)
        np.testing.assert_allclose(T, chain.fk_poe(q), rtol=0, atol=1e-12)
        np.testing.assert_array_equal(T[3], [0.0, 0.0, 0.0, 1.0])


@pytest.mark.parametrize("name", IDS)
def test_jacobians_single_match_batch_and_differences(name):
    chain = _chains()[name]
    Q = _configurations(chain, seed=1)
    batches = {form: getattr(chain, f"{form}_jacobian")(Q) for form in FORMS}
    for k, q in enumerate(Q):
        singles = {form: getattr(chain, f"{form}_jacobian")(q) for form in FORMS}
        for form in FORMS:
            assert singles[form].shape == (6, chain.n)
            np.testing.assert_allclose(
                singles[form], batches[form][k], rtol=0, atol=1e-12
            )
        # independent: differences of the product of exponentials, and the space
        # and body Jacobians from the geometric one by their definitions
        Jg = singles["geometric"]
        np.testing.assert_allclose(Jg, _poe_jacobian(chain, q), rtol=0, atol=1e-7)
        T = chain.fk_poe(q)
        R, p = T[:3, :3], T[:3, 3]
        omega, v_point = Jg[3:], Jg[:3]
        v_origin = v_point - np.cross(omega.T, p).T  # the velocity at the base origin
        np.testing.assert_allclose(
            singles["space"], np.vstack([omega, v_origin]), rtol=0, atol=1e-12
        )
        np.testing.assert_allclose(
            singles["body"], np.vstack([R.T @ omega, R.T @ v_point]), atol=1e-12
        )


@pytest.mark.parametrize("name", IDS)
def test_jacobian_dots_single_match_batch_and_differences(name):
    chain = _chains()[name]
    Q = _configurations(chain, seed=2)
    dQ = _configurations(chain, seed=3)
    h = 1e-5
    for form in FORMS:
        jacobian = getattr(chain, f"{form}_jacobian")
        dot = getattr(chain, f"{form}_jacobian_dot")
        batch = dot(Q, dQ)
        for k, (q, dq) in enumerate(zip(Q, dQ)):
            single = dot(q, dq)
            assert single.shape == (6, chain.n)
            np.testing.assert_allclose(single, batch[k], rtol=0, atol=1e-12)
            # the kernel of _second_order on the Jacobian gives the same numbers
            kernel = getattr(_second_order, f"{form}_dot")(jacobian(q), dq)
            np.testing.assert_allclose(single, kernel, rtol=0, atol=1e-13)
            # independent: dJ/dt = (J(q + h dq) - J(q - h dq)) / 2h, the batch path
            steps = np.array([q + h * dq, q - h * dq])
            plus, minus = jacobian(steps)
            np.testing.assert_allclose(
                single, (plus - minus) / (2 * h), rtol=0, atol=1e-7
            )


def test_dot_of_a_planar_arm_by_hand():
    """Planar 2R, l1 = l2 = 1, q = (0, 0), dq = (1, 0): the geometric Jacobian's
    columns are (-l1 s1 - l2 s12, l1 c1 + l2 c12, ...) and (-l2 s12, l2 c12, ...),
    their time derivatives -(l1 c1 + l2 c12) dq1 - l2 c12 dq2 = -2 and -l2 c12
    (dq1 + dq2) = -1 in the x row, 0 in the y row."""
    arm = sk.robots.planar([1.0, 1.0])
    dJ = arm.geometric_jacobian_dot([0.0, 0.0], [1.0, 0.0])
    np.testing.assert_allclose(dJ[:2], [[-2.0, -1.0], [0.0, 0.0]], atol=1e-15)
    np.testing.assert_allclose(dJ[2:], 0.0, atol=1e-15)


def test_scalar_path_agrees_with_exact():
    """dJ/dt at exact input (SymPy, the brackets in symbols) against the floats."""
    import sympy as sp

    arm = _modified_arm()
    q, dq = [0.5, -0.3, 0.2], [0.4, 1.1, -0.7]
    exact = arm.geometric_jacobian_dot(
        [sp.Rational(1, 2), sp.Rational(-3, 10), sp.Rational(1, 5)],
        [sp.Rational(2, 5), sp.Rational(11, 10), sp.Rational(-7, 10)],
    )
    np.testing.assert_allclose(
        arm.geometric_jacobian_dot(q, dq), np.array(exact, dtype=float), atol=1e-12
    )


@pytest.mark.parametrize(
    "q",
    [
        [0, 0, 0, 0, 0, 0],
        (0.1, 0.2, 0.3, 0.4, 0.5, 0.6),
        [np.float64(0.1), 0.2, 0.3, 0.4, 0.5, 0.6],
        np.arange(6, dtype=np.float32),
        np.arange(6),
        np.linspace(0, 1, 12)[::2],
    ],
    ids=["ints", "tuple", "float64 entries", "float32", "int array", "strided"],
)
def test_input_forms_give_the_full_paths_numbers(q):
    robot = sk.robots.puma560()
    reference = np.asarray(q, dtype=float)[None]
    np.testing.assert_allclose(robot.fk(q), robot.fk(reference)[0], atol=1e-12)
    np.testing.assert_allclose(
        robot.geometric_jacobian(q), robot.geometric_jacobian(reference)[0], atol=1e-12
    )
    np.testing.assert_allclose(
        robot.space_jacobian_dot(q, q),
        robot.space_jacobian_dot(reference, reference)[0],
        atol=1e-12,
    )


@pytest.mark.parametrize(
    "q, error, words",
    [
        ([0.0, np.nan, 0, 0, 0, 0], ValueError, "q must be finite"),
        ([0.0, np.inf, 0, 0, 0, 0], ValueError, "q must be finite"),
        ([True, 0, 0, 0, 0, 0], TypeError, "q must be"),
        (["0", 0, 0, 0, 0, 0], TypeError, "q must be"),
        ([0.0] * 5, ValueError, "6 entries"),
        (np.zeros(7), ValueError, "6 entries"),
        ([1e308, 1e308, 0, 0, 0, 0], None, None),  # finite: the sum's overflow is not
    ],
)
def test_refusals_of_the_full_check_are_kept(q, error, words):
    robot = sk.robots.puma560()
    if error is None:
        assert np.isfinite(robot.fk(q)).all()
        return
    for call in (
        lambda: robot.fk(q),
        lambda: robot.geometric_jacobian(q),
        lambda: robot.body_jacobian(q),
        lambda: robot.space_jacobian_dot(np.zeros(6), q),
    ):
        with pytest.raises(error, match=words.replace("q must", "")):
            call()


def test_results_are_fresh_arrays():
    robot = sk.robots.ur5e()
    q = np.full(6, 0.3)
    T = robot.fk(q)
    T[0, 0] = 99.0
    assert robot.fk(q)[0, 0] != 99.0
    J = robot.geometric_jacobian(q)
    J[:] = 0.0
    assert np.any(robot.geometric_jacobian(q))
