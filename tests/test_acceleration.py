"""Second-order kinematics (screwkit.motion.acceleration,
Chain.*_jacobian_dot/*_hessian): against central differences of the Jacobians and of
FK (independent of the brackets), the Hessian against differences of the Jacobian,
exact against float, the bracket formula against SymPy's own time derivative, batches
against loops, bad input."""

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit.motion import acceleration

#: central differences with step H: error about H^2 |J'''| + eps / H, near 1e-10
H = 1e-5
DIFF_TOL = 1e-7


def screws_arm():
    """Modern Robotics' R, P and helical arm (a chain from screws, space form), with a
    base."""
    M = sk.transl(0, 6, 2) @ sk.homogeneous(sk.roty(np.pi))
    return sk.Chain.from_screws(
        [[0, 0, 1, 4, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, -1, -6, 0, -0.1]], M
    ).with_base(sk.transl(0.1, -0.2, 0.3) @ sk.homogeneous(sk.rotx(0.4)))


def body_arm():
    """A chain from body screws (RRPR), with a tool."""
    M = sk.transl(0.2, 0.1, 0.5)
    return sk.Chain.from_screws(
        [
            [0, 0, 1, 0.1, -0.2, 0],
            [1, 0, 0, 0, 0.3, 0.1],
            [0, 0, 0, 0, 0, 1],
            [0, 1, 0, -0.2, 0, 0.05],
        ],
        M,
        frame="body",
    ).with_tool(sk.transl(0, 0, 0.1) @ sk.homogeneous(sk.rotz(0.3)))


CHAINS = {
    "puma": sk.robots.puma560,
    "panda": sk.robots.panda,
    "screws": screws_arm,
    "body": body_arm,
    "modified": lambda: sk.Chain(
        [
            sk.Link.revolute(d=0.3, a=0.2, alpha=0.4),
            sk.Link.prismatic(a=0.1, alpha=-1.2),
            sk.Link.revolute(a=0.3, alpha=1.0),
        ],
        convention=sk.Convention.MODIFIED,
        tool=sk.transl(0.1, 0, 0.2),
    ),
}


@pytest.fixture(params=sorted(CHAINS))
def chain(request):
    return CHAINS[request.param]()


def sample(chain, seed=0):
    rng = np.random.default_rng(seed)
    return rng.uniform(-1.5, 1.5, chain.n), rng.uniform(-1.0, 1.0, chain.n)


JACOBIANS = ["space", "body", "geometric"]


@pytest.mark.parametrize("form", JACOBIANS)
def test_jacobian_dot_equals_central_differences_along_dq(chain, form):
    q, dq = sample(chain)
    J = getattr(chain, f"{form}_jacobian")
    expected = (J(q + H * dq) - J(q - H * dq)) / (2 * H)
    got = getattr(chain, f"{form}_jacobian_dot")(q, dq)
    np.testing.assert_allclose(got, expected, atol=DIFF_TOL)


@pytest.mark.parametrize("form", JACOBIANS)
def test_hessian_equals_central_differences_of_the_jacobian(chain, form):
    q, _ = sample(chain, 1)
    J = getattr(chain, f"{form}_jacobian")
    expected = np.array(
        [(J(q + H * e) - J(q - H * e)) / (2 * H) for e in np.eye(chain.n)]
    )
    got = getattr(chain, f"{form}_hessian")(q)
    assert got.shape == (chain.n, 6, chain.n)
    np.testing.assert_allclose(got, expected, atol=DIFF_TOL)


def test_space_hessian_is_the_bracket_of_the_columns(chain):
    q, _ = sample(chain, 2)
    J = chain.space_jacobian(q)
    H_ = chain.space_hessian(q)
    for j in range(chain.n):
        for i in range(chain.n):
            expected = sk.ad(J[:, j]) @ J[:, i] if j < i else np.zeros(6)
            np.testing.assert_allclose(H_[j, :, i], expected, atol=1e-14)


def test_geometric_hessian_position_rows_are_symmetric(chain):
    """Rows v are the second derivatives of the end point: d2p/dqi dqj = d2p/dqj dqi."""
    q, _ = sample(chain, 3)
    H_ = chain.geometric_hessian(q)[:, :3, :]
    np.testing.assert_allclose(H_, np.transpose(H_, (2, 1, 0)), atol=1e-13)


@pytest.mark.parametrize("form", JACOBIANS)
def test_hessian_contracted_with_dq_is_jacobian_dot(form):
    chain = sk.robots.puma560()
    q, dq = sample(chain, 4)
    H_ = getattr(chain, f"{form}_hessian")(q)
    np.testing.assert_allclose(
        np.einsum("jri,j->ri", H_, dq),
        getattr(chain, f"{form}_jacobian_dot")(q, dq),
        atol=1e-14,
    )


@pytest.mark.parametrize("form", JACOBIANS)
def test_a_batch_equals_one_configuration_at_a_time(form):
    chain = sk.robots.panda()
    rng = np.random.default_rng(5)
    Q, dQ = rng.uniform(-2, 2, (7, 7)), rng.uniform(-1, 1, (7, 7))
    dot = getattr(chain, f"{form}_jacobian_dot")
    hessian = getattr(chain, f"{form}_hessian")
    assert dot(Q, dQ).shape == (7, 6, 7) and hessian(Q).shape == (7, 7, 6, 7)
    for k in range(7):
        np.testing.assert_allclose(dot(Q, dQ)[k], dot(Q[k], dQ[k]), atol=1e-15)
        np.testing.assert_allclose(hessian(Q)[k], hessian(Q[k]), atol=1e-15)


def test_module_functions_equal_the_chain_methods(chain):
    q, dq = sample(chain, 6)
    for form in JACOBIANS:
        np.testing.assert_array_equal(
            getattr(acceleration, f"{form}_jacobian_dot")(chain, q, dq),
            getattr(chain, f"{form}_jacobian_dot")(q, dq),
        )
        np.testing.assert_array_equal(
            getattr(acceleration, f"{form}_hessian")(chain, q),
            getattr(chain, f"{form}_hessian")(q),
        )


def test_geometric_acceleration_is_the_second_derivative_of_the_end_point(chain):
    """Along q(t) = q + dq t + ddq t^2 / 2: a from the second difference of FK's
    position, alpha from the difference of omega(t) = J_omega(q(t)) dq(t)."""
    q, dq = sample(chain, 7)
    ddq = np.random.default_rng(8).uniform(-1, 1, chain.n)
    h = 1e-4

    def at(t):
        return q + dq * t + ddq * t * t / 2, dq + ddq * t

    p = [chain.fk(at(t)[0])[:3, 3] for t in (-h, 0.0, h)]
    omega = [chain.geometric_jacobian(at(t)[0])[3:] @ at(t)[1] for t in (-h, h)]
    got = acceleration.geometric_acceleration(chain, q, dq, ddq)
    np.testing.assert_allclose(got[:3], (p[0] - 2 * p[1] + p[2]) / h**2, atol=1e-6)
    np.testing.assert_allclose(got[3:], (omega[1] - omega[0]) / (2 * h), atol=1e-7)


def test_space_and_body_accelerations_are_the_twists_derivatives(chain):
    q, dq = sample(chain, 9)
    ddq = np.random.default_rng(10).uniform(-1, 1, chain.n)

    def twists(t):
        qt, dqt = q + dq * t + ddq * t * t / 2, dq + ddq * t
        return chain.space_jacobian(qt) @ dqt, chain.body_jacobian(qt) @ dqt

    (s1, b1), (s0, b0) = twists(H), twists(-H)
    np.testing.assert_allclose(
        acceleration.space_acceleration(chain, q, dq, ddq),
        (s1 - s0) / (2 * H),
        atol=DIFF_TOL,
    )
    np.testing.assert_allclose(
        acceleration.body_acceleration(chain, q, dq, ddq),
        (b1 - b0) / (2 * H),
        atol=DIFF_TOL,
    )


def test_a_planar_arm_turning_at_constant_rate_has_its_centripetal_acceleration():
    """Hand calculation: links 1 and 0.5 straight, joint 1 at 2 rad/s: the tip on a
    circle of radius 1.5 m has a = w^2 r = 6 m/s^2 towards the base."""
    arm = sk.robots.planar([1.0, 0.5])
    a = acceleration.geometric_acceleration(arm, [0.0, 0.0], [2.0, 0.0], [0.0, 0.0])
    np.testing.assert_allclose(a, [-6.0, 0, 0, 0, 0, 0], atol=1e-14)


# ---- exact --------------------------------------------------------------------------

Q_EXACT = [sp.Rational(1, 3), sp.Rational(-1, 2), sp.Rational(2, 5)]
DQ_EXACT = [sp.Rational(1, 2), 1, sp.Rational(-3, 4)]
DDQ_EXACT = [1, -2, sp.Rational(1, 3)]


def exact_chains():
    return [CHAINS["modified"](), screws_arm()]


def as_float(matrix):
    """An exact matrix's entries evaluated by mpmath at 30 digits, as float64 (SymPy's
    adaptive evalf is slow on these long sums of products of cosines)."""
    import mpmath

    with mpmath.workdps(30):
        values = sp.lambdify([], matrix, "mpmath")()
    return np.array(values.tolist(), dtype=float)


@pytest.mark.parametrize(
    "index, form",
    # the body form of the DH chain is left out for time (about 30 s on a loaded
    # machine): the chain from screws has a base, a prismatic and a helical joint
    [(0, "space"), (0, "geometric"), (1, "space"), (1, "body"), (1, "geometric")],
)
def test_exact_and_float_forms_agree(index, form):
    chain = exact_chains()[index]
    qf = np.array([float(v) for v in Q_EXACT])
    dqf = np.array([float(v) for v in DQ_EXACT])
    ddqf = np.array([float(v) for v in DDQ_EXACT])
    exact = getattr(acceleration, f"{form}_jacobian_dot")(chain, Q_EXACT, DQ_EXACT)
    assert isinstance(exact, sp.MatrixBase)
    np.testing.assert_allclose(
        as_float(exact), getattr(chain, f"{form}_jacobian_dot")(qf, dqf), atol=1e-13
    )
    hessian = getattr(acceleration, f"{form}_hessian")(chain, Q_EXACT)
    np.testing.assert_allclose(
        np.array([as_float(h) for h in hessian]),
        getattr(chain, f"{form}_hessian")(qf),
        atol=1e-13,
    )
    accel = getattr(acceleration, f"{form}_acceleration")(
        chain, Q_EXACT, DQ_EXACT, DDQ_EXACT
    )
    np.testing.assert_allclose(
        as_float(accel).ravel(),
        getattr(acceleration, f"{form}_acceleration")(chain, qf, dqf, ddqf),
        atol=1e-13,
    )


def test_bracket_formula_is_sympys_time_derivative_of_the_joint_twists():
    """For q(t) symbolic, d/dt of the exact space Jacobian (SymPy differentiates the
    twists) equals the brackets [W_i, J_i], identically."""
    chain = sk.Chain(
        [
            sk.Link.revolute(d=sp.Rational(1, 2), a=1, alpha=sp.pi / 2),
            sk.Link.revolute(a=1),
            sk.Link.prismatic(alpha=-sp.pi / 2),
        ]
    )
    t = sp.Symbol("t", real=True)
    q = [sp.Function(f"q{i}", real=True)(t) for i in (1, 2, 3)]
    J = sp.Matrix.hstack(*chain.twists_symbolic(q))
    expected = J.diff(t)
    got = acceleration.space_jacobian_dot(chain, q, [qi.diff(t) for qi in q])
    assert (got - expected).applyfunc(sp.simplify) == sp.zeros(6, 3)


# ---- bad input ----------------------------------------------------------------------


def test_bad_input_is_a_clear_error():
    puma = sk.robots.puma560()
    q = np.zeros(6)
    with pytest.raises(ValueError, match="dq must have the shape of q"):
        puma.space_jacobian_dot(q, np.zeros((2, 6)))
    with pytest.raises(ValueError, match="dq must have 6 entries"):
        puma.geometric_jacobian_dot(q, np.zeros(5))
    with pytest.raises(TypeError, match="dq must be a number or an array"):
        puma.body_jacobian_dot(q, "fast")
    with pytest.raises(ValueError, match="ddq must have the shape of q"):
        acceleration.geometric_acceleration(puma, q, q, np.zeros((2, 6)))
    with pytest.raises(ValueError, match="q must have 6 entries"):
        puma.space_hessian(np.zeros(4))
    with pytest.raises(TypeError, match="chain"):
        acceleration.space_hessian("puma", q)
    with pytest.raises(ValueError, match="dq must have 6 entries"):
        acceleration.space_jacobian_dot(puma, [sp.S(0)] * 6, [1, 2])
    with pytest.raises(TypeError, match="dq must be a joint vector"):
        acceleration.space_jacobian_dot(puma, [sp.S(0)] * 6, sp.S(1))


# ---- batches too large for memory ----------------------------------------

SECOND_ORDER = {
    "space_hessian": 1,
    "body_hessian": 1,
    "geometric_hessian": 1,
    "space_jacobian_dot": 2,
    "body_jacobian_dot": 2,
    "geometric_jacobian_dot": 2,
    "space_acceleration": 3,
    "body_acceleration": 3,
    "geometric_acceleration": 3,
}


@pytest.mark.parametrize("name", sorted(SECOND_ORDER))
def test_a_batch_past_the_memory_limit_is_refused_before_any_work(name):
    # 10^8 configurations (a broadcast view, no memory): a Hessian alone would be
    # 10^8 x 6 x 6 x 6 floats, 173 GB; refused at once, naming q and what fits
    puma = sk.robots.puma560()
    q = np.broadcast_to(np.full(6, 0.3), (10**8, 6))
    function = getattr(acceleration, name)
    with pytest.raises(ValueError, match=r"q's 100000000 configurations.*at most \d+"):
        function(puma, *[q] * SECOND_ORDER[name])


@pytest.mark.parametrize("name", sorted(SECOND_ORDER))
def test_the_limit_counts_the_work_of_each_kind(name, monkeypatch):
    # with the limit lowered to 10^6 bytes, 2000 configurations of 6 joints need more
    # (a Hessian 2000 x 216 x 8 = 3.5 MB, a Jacobian derivative 2000 x 36 x 8 = 0.6 MB
    # plus its temporaries) and 10 configurations fit: the chain's own methods, which
    # compute the Jacobians first, are refused as well
    monkeypatch.setattr(sk._checks, "MAX_RESULT_BYTES", 10**6)
    puma = sk.robots.puma560()
    function = getattr(acceleration, name)
    large = np.full((2000, 6), 0.3)
    with pytest.raises(ValueError, match="must stay within the limit"):
        function(puma, *[large] * SECOND_ORDER[name])
    method = getattr(puma, name, None)
    if method is not None:
        with pytest.raises(ValueError, match="must stay within the limit"):
            method(*[large.tolist()] * SECOND_ORDER[name])
    small = np.full((10, 6), 0.3)
    assert function(puma, *[small] * SECOND_ORDER[name]).shape[0] == 10
