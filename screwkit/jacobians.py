"""Jacobians of serial chains: exact (SymPy) and fast (NumPy, vectorised over a batch).

Two Jacobians, with names that say which:

* ``geometric_jacobian``: rows [v; omega], v the velocity of the end-effector point,
  both in the base frame (Spong, Siciliano, Corke's ``jacob0``);
* ``space_jacobian``: columns are the joint twists [omega; v] in the base frame, v being
  the velocity of the body point at the base origin (Lynch & Park's J_s).

From the Jacobian: singular values, Yoshikawa's manipulability sqrt(det(J J^T)), the
condition number, the rank, and the manipulability ellipsoid.

The functions share their parameters, described here once:

* ``chain`` (:class:`~screwkit.chains.Chain`): the serial chain;
* ``q`` (array-like, shape (n,) or a batch (N, n)): its joint values (rad or m);
* ``rows`` ({'all', 'position', 'orientation', 'planar'}, optional): the rows of J
  used: 'all' (6), 'position' (v, m/s per unit joint rate), 'orientation' (omega) or
  'planar' (v_x, v_y: the 2 x n Jacobian of an arm in the x-y plane).

>>> import screwkit as sk, numpy as np
>>> arm = sk.robots.planar([1.0, 1.0])
>>> w = manipulability(arm, [0.0, np.pi / 2], rows="planar")  # |l1 l2 sin q2|
>>> float(np.round(w, 12))
1.0
>>> int(rank(arm, [0.0, 0.0], rows="planar"))  # stretched: singular
1
"""

import numpy as np
import sympy as sp

from . import _compiled, _numeric
from ._checks import (
    as_sympy_matrix,
    check_chain,
    check_flag,
    check_option,
    describe,
)
from ._compiled import in_chunks
from ._docstrings import CHAIN, CHAIN_Q, fill
from .links import Joint
from .tolerances import FD_STEP
from .transforms import _cross

__all__ = [
    "joint_axes",
    "geometric_jacobian",
    "space_jacobian",
    "body_jacobian",
    "numerical_jacobian",
    "geometric_jacobian_symbolic",
    "determinant_symbolic",
    "singular_values",
    "manipulability",
    "condition_number",
    "rank",
    "ellipsoid",
]

#: Docstring passages the functions share (filled in by :func:`_docstrings.fill`).
_CHAIN_Q_ROWS = """Parameters
----------
chain, q, rows
    The chain, its joint values and the rows of J (module docstring)."""
_CHAIN_ONE_Q = """chain : Chain
    The serial chain.
q : array-like, shape (n,)
    One configuration (rad or m)."""

#: Rows of the geometric Jacobian, by name.
#: 'planar' is (v_x, v_y) in the chain's base frame, the 2 x n Jacobian of an arm that
#: moves in its base's x-y plane.
ROWS = {
    "all": slice(0, 6),
    "position": slice(0, 3),
    "orientation": slice(3, 6),
    "planar": slice(0, 2),
}


#: The Parameters section of the functions taking a chain and its joint values only
#: (they are the Chain's methods of the same names).
#: The sections of the Jacobians' docstrings (filled in by :func:`_docstrings.fill`).
_JACOBIAN_SECTIONS = f"""{CHAIN_Q}

Returns
-------
ndarray, shape (6, n) or (N, 6, n)
    The Jacobian(s)."""
_GEOMETRIC_SECTIONS = _JACOBIAN_SECTIONS.replace(
    "Jacobian(s).", "Jacobian(s), base frame, end-effector point."
)


def check_rows(rows):
    """The slice of the geometric Jacobian's rows named ``rows``
    (one of :data:`ROWS`)."""
    return ROWS[check_option(rows, "rows", tuple(ROWS))]


# ---- the Jacobians, outputs of the chain's generated program (Chain's methods) -----


@fill(parameters=CHAIN_Q)
def joint_axes(chain, q):
    """Direction z_i and a point o_i of every joint axis in the base frame.

    DH: joint i moves about z of frame i-1 (standard) or of frame i (modified),
    through its origin. A prismatic joint's direction is its translation; its point
    is for drawing.

    {parameters}

    Returns
    -------
    z, o : ndarray, shape (n, 3) or (N, n, 3)
        Unit directions and points (m).

    Examples
    --------
    A planar 2R arm with unit links: both axes are z, through (0, 0) and (1, 0, 0).

    >>> import screwkit as sk
    >>> z, o = joint_axes(sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> np.round(z, 6) + 0.0, np.round(o, 6) + 0.0
    (array([[0., 0., 1.],
           [0., 0., 1.]]), array([[0., 0., 0.],
           [1., 0., 0.]]))
    """
    check_chain(chain)
    q = chain.check_q(q)
    omega, v, point, _ = chain._twists_and_pose(q)
    prismatic = np.array([j is Joint.PRISMATIC for j in chain.joints])
    z = np.where(prismatic if q.ndim == 1 else prismatic[:, None], v, omega)
    z, point = np.moveaxis(z, 0, -1), np.moveaxis(point, 0, -1)  # (n[, N], 3)
    if q.ndim == 1:
        return z, point
    return np.swapaxes(z, 0, 1), np.swapaxes(point, 0, 1)


def _generated_jacobian(chain, q, outputs):
    """A Jacobian generated as straight-line code ('space' or 'geometric'): (6, n)
    or (N, 6, n)."""
    values = _compiled.one(q, chain.n)
    if values is not None:  # one configuration: the scalar path
        entries = _compiled.scalar(chain, outputs)(values)
        return np.array(entries, float).reshape(6, chain.n)
    q = chain.check_q(q)
    n, rows = chain.n, 6 * chain.n
    if q.ndim == 1:
        return np.reshape(chain._run(outputs, q), (6, n))

    def part(q_part):
        values = chain._run(
            outputs, q_part, range(rows), np.empty((rows, q_part.shape[0]))
        )
        return values.reshape(6, n, -1).transpose(2, 0, 1)

    return _compiled.in_chunks(q, part, np.empty((q.shape[0], 6, n)))


@fill(sections=_JACOBIAN_SECTIONS)
def space_jacobian(chain, q):
    """The space Jacobian, columns [omega; v].

    Column i is the twist of joint i in the base frame, Ad(G_i) X_i:
    (z_i; o_i x z_i) for a revolute joint about z_i through o_i
    (v is the velocity of the body point at the base origin), (0; z_i) for a
    prismatic one, (z_i; o_i x z_i + h z_i) for a helical one of pitch h.

    {sections}

    Examples
    --------
    A planar 2R arm with unit links: joint 2's axis is z through (1, 0, 0), so its
    column is (z; (1, 0, 0) x z) = (0, 0, 1, 0, -1, 0), whatever q.

    >>> import screwkit as sk
    >>> J = space_jacobian(sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> np.round(J.T, 6) + 0.0
    array([[ 0.,  0.,  1.,  0.,  0.,  0.],
           [ 0.,  0.,  1.,  0., -1.,  0.]])
    """
    check_chain(chain)
    return chain._generated_jacobian(q, "space")


@fill(sections=_GEOMETRIC_SECTIONS)
def geometric_jacobian(chain, q):
    """The geometric Jacobian, rows [v; omega].

    Column i is the space twist moved to the end-effector point p:
    (v_i + omega_i x p; omega_i), i.e. (z_i x (p - o_i); z_i) for a revolute joint
    and (z_i; 0) for a prismatic one.

    {sections}

    Examples
    --------
    A planar 2R arm with unit links at q = (0, pi/2): the tip p = (1, 1, 0);
    z x p = (-1, 1, 0) and z x (p - (1, 0, 0)) = (-1, 0, 0).

    >>> import screwkit as sk
    >>> J = geometric_jacobian(sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> np.round(J[:2], 6) + 0.0  # v_x, v_y
    array([[-1., -1.],
           [ 1.,  0.]])
    """
    check_chain(chain)
    return chain._generated_jacobian(q, "geometric")


def _body_columns(chain, values):
    """The body Jacobian (6, n) at one configuration (a list of n floats), in Python
    floats: each joint's twist and the pose from the generated code, then
    (R^T omega; R^T (v + omega x p)) column by column."""
    entries = _compiled.scalar(chain, "axes")(values)
    r00, r01, r02, p0, r10, r11, r12, p1, r20, r21, r22, p2 = entries[-12:]
    n = chain.n
    J = [0.0] * (6 * n)
    for i in range(n):
        w0, w1, w2, v0, v1, v2 = entries[9 * i : 9 * i + 6]
        u0 = v0 + (w1 * p2 - w2 * p1)
        u1 = v1 + (w2 * p0 - w0 * p2)
        u2 = v2 + (w0 * p1 - w1 * p0)
        J[i] = r00 * w0 + r10 * w1 + r20 * w2
        J[n + i] = r01 * w0 + r11 * w1 + r21 * w2
        J[2 * n + i] = r02 * w0 + r12 * w1 + r22 * w2
        J[3 * n + i] = r00 * u0 + r10 * u1 + r20 * u2
        J[4 * n + i] = r01 * u0 + r11 * u1 + r21 * u2
        J[5 * n + i] = r02 * u0 + r12 * u1 + r22 * u2
    return np.array(J, float).reshape(6, n)


@fill(sections=_JACOBIAN_SECTIONS)
def body_jacobian(chain, q):
    """The body Jacobian, columns [omega; v].

    Column i is joint i's twist in the end-effector frame, J_b = Ad(T^-1) J_s:
    (R^T omega_i; R^T (v_i + omega_i x p)) for the pose T = (R, p).

    {sections}

    Examples
    --------
    A planar 2R arm with unit links at q = (0, pi/2): the tool's x axis is the
    base's y. Joint 2 moves the tip along the tool's y at 1 m/s; joint 1 moves it
    by z x (1, 1, 0) = (-1, 1, 0), which is (1, 1, 0) in the tool frame.

    >>> import screwkit as sk
    >>> J = body_jacobian(sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> np.round(J.T, 6) + 0.0
    array([[0., 0., 1., 1., 1., 0.],
           [0., 0., 1., 0., 1., 0.]])
    """

    check_chain(chain)
    values = _compiled.one(q, chain.n)
    if values is not None:  # one configuration: the scalar path
        return _body_columns(chain, values)

    def columns(q_part):
        omega, v, _, T = chain._twists_and_pose(q_part)
        R, linear = T[:, :3], v + _cross(omega, T[:, 3][:, None])
        rotate = "ji...,jk...->ik..."  # R^T x, column by column, batch last
        J = np.concatenate([np.einsum(rotate, R, omega), np.einsum(rotate, R, linear)])
        return J if q_part.ndim == 1 else J.transpose(2, 0, 1)

    q = chain.check_q(q)
    if q.ndim == 1:
        return columns(q)
    return _compiled.in_chunks(q, columns, np.empty((q.shape[0], 6, chain.n)))


@fill(chain=CHAIN)
def jacobian_rows(chain, q, rows="all"):
    """Some rows of the geometric Jacobian.

    'planar' reads v_x, v_y in the chain's base frame.

    {chain}
    q : array-like, shape (n,) or (N, n)
        Joint values (rad or m).
    rows : {'all', 'position', 'orientation', 'planar'}, optional
        A key of :data:`ROWS`.

    Returns
    -------
    ndarray, shape (m, n) or (N, m, n)
        The m rows (6, 3, 3 or 2).

    Examples
    --------
    The planar 2R arm with unit links at q = (0, pi/2), tip (1, 1):

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> np.round(jacobian_rows(arm, [0.0, np.pi / 2], "planar"), 6) + 0.0
    array([[-1., -1.],
           [ 1.,  0.]])
    """
    check_chain(chain)
    selected = check_rows(rows)
    J = chain.geometric_jacobian(q)
    if rows == "planar":
        R = np.asarray(chain.base)[:3, :3]
        return np.einsum("ji,...jk->...ik", R, J[..., :3, :])[..., selected, :]
    return J[..., selected, :]


@fill(chain=CHAIN)
def singular_values(chain, q, rows="all"):
    """Singular values of the geometric Jacobian's rows, largest first.

    {chain}
    q : array-like, shape (n,) or (N, n)
        Joint values (rad or m).
    rows : {'all', 'position', 'orientation', 'planar'}, optional
        The rows of J used.

    Returns
    -------
    ndarray, shape (k,) or (N, k)
        k = min(rows, n) singular values.

    Examples
    --------
    The planar 2R arm with unit links at q = (0, pi/2): J = [[-1, -1], [1, 0]], so
    J J^T = [[2, -1], [-1, 1]], whose eigenvalues (3 +- sqrt 5) / 2 are the squares
    of the golden ratio 1.618... and of its inverse.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> np.round(singular_values(arm, [0.0, np.pi / 2], "planar"), 6)
    array([1.618034, 0.618034])
    """
    check_chain(chain)
    check_rows(rows)
    q = chain.check_q(q)

    def part(q_part):
        return np.linalg.svd(chain.jacobian_rows(q_part, rows), compute_uv=False)

    return part(q) if q.ndim == 1 else _compiled.in_chunks(q, part)


@fill(chain=CHAIN)
def lost_rank(chain, sigma, rows="all"):
    """Whether Jacobian rows have lost rank, by NumPy's rule on the smallest
    singular value.

    {chain}
    sigma : ndarray, shape (..., k)
        Singular values, largest first, as :meth:`singular_values` returns them.
    rows : {'all', 'position', 'orientation', 'planar'}, optional
        The rows they are of.

    Returns
    -------
    bool or ndarray of bool, shape (...)
        True where the rank is below k.

    Examples
    --------
    A planar 2R arm stretched out (q2 = 0) is singular; bent (q2 = pi/2) it is not.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> sigma = singular_values(arm, [[0.0, 0.0], [0.0, np.pi / 2]], "planar")
    >>> lost_rank(arm, sigma, "planar")
    array([ True, False])
    """
    return _numeric.lost_rank(sigma, len(range(6)[check_rows(rows)]), chain.n)


@fill(chain=CHAIN)
def manipulability(chain, q, rows="all"):
    """Yoshikawa's manipulability, the product of the singular values: () or (N,).

    That is sqrt(det(J J^T)) for J with no more rows than columns
    (sqrt(det(J^T J)) otherwise). Exactly 0.0 where J has lost rank
    (by NumPy's rank tolerance), so a singular configuration is an answer, not
    noise. With rows='all' the product mixes metres and radians; 'position' gives
    the volume factor of the velocity ellipsoid in m/s.

    {chain}
    q : array-like, shape (n,) or (N, n)
        Joint values (rad or m).
    rows : {'all', 'position', 'orientation', 'planar'}, optional
        'position' (the rows v), 'orientation' (the rows omega) or 'planar'
        (v_x, v_y in the chain's base frame).

    Returns
    -------
    float or ndarray, shape (N,)
        The manipulability.

    Examples
    --------
    A planar 2R arm: w = l1 l2 ``abs(sin q2)``, 0 stretched out, 0.5 bent at pi/6.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> w = manipulability(arm, [[0.0, 0.0], [0.0, np.pi / 6]], "planar")
    >>> np.round(w, 6) + 0.0
    array([0. , 0.5])
    """
    check_chain(chain)
    sigma = chain.singular_values(q, rows)
    return np.where(chain.lost_rank(sigma, rows), 0.0, np.prod(sigma, axis=-1))[()]


@fill(chain_q=_CHAIN_ONE_Q)
def numerical_jacobian(chain, q, h=FD_STEP):
    """The geometric Jacobian of one configuration by central differences of FK.

    Column i is ((p(q + h e_i) - p(q - h e_i)) / 2h; omega_i), omega_i read from the
    skew matrix dR/dq_i R^T. An independent check of :func:`geometric_jacobian`
    (error O(h^2)).

    Parameters
    ----------
    {chain_q}
    h : float, optional
        The step (rad or m), positive.

    Returns
    -------
    ndarray, shape (6, n)
        Rows [v; omega].

    Examples
    --------
    Central differences agree with the exact Jacobian of the planar 2R arm to
    O(h^2):

    >>> import screwkit as sk
    >>> arm, q = sk.robots.planar([1.0, 1.0]), [0.3, 1.1]
    >>> difference = numerical_jacobian(arm, q) - geometric_jacobian(arm, q)
    >>> bool(np.abs(difference).max() < 1e-8)
    True
    """
    q = check_chain(chain).check_one(q)
    if (
        isinstance(h, bool)
        or not isinstance(h, (int, float, np.floating, np.integer))
        or not np.isfinite(h)
        or h <= 0
    ):
        raise ValueError(f"h must be a small positive step (rad or m), got {h!r}")
    R = chain.fk(q)[:3, :3]
    columns = []
    for step in h * np.eye(chain.n):
        plus, minus = chain.fk(q + step), chain.fk(q - step)
        W = (plus[:3, :3] - minus[:3, :3]) / (2 * h) @ R.T
        columns.append(
            np.r_[(plus[:3, 3] - minus[:3, 3]) / (2 * h), W[2, 1], W[0, 2], W[1, 0]]
        )
    return np.array(columns).T


# ---- exact ---------------------------------------------------------------------------


def _symbolic_point(chain, point, end, frames):
    if point is None:
        return end[:3, 3]
    if isinstance(point, (bool, np.bool_, float, np.floating, str, bytes, complex)) or (
        isinstance(point, sp.Basic) and not isinstance(point, sp.MatrixBase)
    ):
        raise TypeError(
            f"point must be a frame number (an integer), a 3-vector or None, "
            f"got {describe(point)}"
        )
    if isinstance(point, (int, np.integer)):
        if frames is None:
            raise ValueError(
                "point must be None or a 3-vector for a chain built from screws "
                f"(it has no DH frames), got {point!r}"
            )
        if not 0 <= point <= chain.n:
            raise ValueError(
                f"point must be a frame number 0..{chain.n}, a 3-vector or None, got "
                f"{point!r}"
            )
        return frames[point][:3, 3]
    return as_sympy_matrix(point, "point", (3, 1))


@fill(chain=CHAIN)
def geometric_jacobian_symbolic(chain, point=None, symbolic_lengths=False):
    """The exact geometric Jacobian, in the joint symbols q1..qn.

    Column i is the joint twist (omega_i; v_i) of ``Chain.twists_symbolic`` moved to the
    point: (v_i + omega_i x p; omega_i).

    {chain}
    point : None, int or 3-vector of SymPy expressions, optional
        The reference point whose velocity the rows v give: None for the end-effector
        point, an integer k for the origin of frame k of a DH chain (e.g. a wrist
        centre), or a point in the base frame (m).
    symbolic_lengths : bool, optional
        (DH) lengths as the symbols a_i, d_i (see ``Chain.length_symbols``).

    Returns
    -------
    sympy.Matrix (6, n)
        Rows [v; omega].

    Examples
    --------
    A planar 2R arm with links a1, a2 (symbols), its elbow (the origin of frame 1)
    as the point: joint 1 moves it at a1 (-s1, c1), joint 2 not at all.

    >>> import screwkit as sk, sympy as sp
    >>> a1, a2 = sp.symbols("a1 a2", positive=True)
    >>> arm = sk.Chain([sk.Link.revolute(a=a1), sk.Link.revolute(a=a2)])
    >>> geometric_jacobian_symbolic(arm, point=1)[:2, :]
    Matrix([
    [-a1*sin(q1), 0],
    [ a1*cos(q1), 0]])
    """
    check_chain(chain)
    symbolic_lengths = check_flag(symbolic_lengths, "symbolic_lengths")
    frames = chain.frames_symbolic(symbolic_lengths) if chain.is_dh else None
    end = (
        chain.fk_symbolic(symbolic_lengths=symbolic_lengths)
        if chain.is_dh
        else chain.fk_symbolic()
    )
    p = _symbolic_point(chain, point, end, frames)
    columns = []
    if chain.is_dh:
        for kind, T in zip(chain.joints, chain.joint_frames(frames)):
            z, o = T[:3, 2], T[:3, 3]
            if kind is Joint.REVOLUTE:
                columns.append(sp.Matrix.vstack(z.cross(p - o), z))
            else:
                columns.append(sp.Matrix.vstack(z, sp.zeros(3, 1)))
    else:
        for twist in chain.twists_symbolic():
            omega, v = twist[:3, 0], twist[3:, 0]
            columns.append(sp.Matrix.vstack(v + omega.cross(p), omega))
    return sp.Matrix.hstack(*columns).applyfunc(lambda e: sp.trigsimp(sp.expand(e)))


def determinant_symbolic(chain, point=None, symbolic_lengths=False):
    """det J of a six-joint chain, factorised: a SymPy expression in q1..q6.

    det J does not depend on the reference point (moving it multiplies J by a matrix of
    determinant 1), so pick ``point`` where J is simple: at a wrist centre
    (frame 4 of an arm with a spherical wrist) J is block triangular, [[A, 0], [C, D]],
    and det J = det A det D. A DH chain's lengths are factored as symbols and only then
    replaced by their numbers, so the factors are exact (no round-off terms from decimal
    lengths).

    Parameters
    ----------
    chain : Chain
        A chain of six joints.
    point : None, int or 3-vector, optional
        The reference point, as for :func:`geometric_jacobian_symbolic`.
    symbolic_lengths : bool, optional
        Keep the DH lengths as the symbols a_i, d_i.

    Returns
    -------
    SymPy expression
        det J, factorised, in q1..q6.

    Examples
    --------
    A Cartesian arm (three prismatic joints on perpendicular axes), spherical wrist:
    the prismatic block is the identity up to sign, so det J = sin q5, the wrist's
    singularity.

    >>> import screwkit as sk, sympy as sp
    >>> P, R, half = sk.Link.prismatic, sk.Link.revolute, sp.pi / 2
    >>> arm = sk.Chain([P(alpha=-half), P(theta=-half, alpha=-half), P(),
    ...                 R(alpha=-half), R(alpha=half), R()])
    >>> determinant_symbolic(arm)
    sin(q5)
    """
    if check_chain(chain).n != 6:
        raise ValueError(
            f"the chain must have 6 joints for a square Jacobian, got {chain.n}"
        )
    lengths = {} if symbolic_lengths or not chain.is_dh else chain.length_symbols()
    J = geometric_jacobian_symbolic(
        chain, point=point, symbolic_lengths=bool(lengths) or symbolic_lengths
    )
    if J[:3, 3:].is_zero_matrix:
        factors = [J[:3, :3].det(method="berkowitz"), J[3:, 3:].det(method="berkowitz")]
    else:
        factors = [J.det(method="berkowitz")]
    result = sp.Mul(*[sp.factor(sp.trigsimp(sp.factor(f))) for f in factors])
    return result.xreplace({s: sp.sympify(v) for s, v in lengths.items()})


# ---- numbers from the Jacobian -------------------------------------------------------


@fill(parameters=_CHAIN_Q_ROWS)
def condition_number(chain, q, rows="all"):
    """The condition number sigma_max / sigma_min of the Jacobian's rows.

    {parameters}

    Returns
    -------
    float or ndarray, shape (N,)
        1 where isotropic, inf where singular.

    Examples
    --------
    The planar 2R arm with unit links at q = (0, pi/2): sigma = 1.618... and 0.618...
    (see :func:`singular_values`), whose ratio is the golden ratio squared, 2.618...;
    stretched out it is singular.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> kappa = condition_number(arm, [[0.0, np.pi / 2], [0.0, 0.0]], "planar")
    >>> np.round(kappa, 6)
    array([2.618034,      inf])
    """
    sigma = singular_values(chain, q, rows)
    singular = check_chain(chain).lost_rank(sigma, rows)
    with np.errstate(divide="ignore"):
        return np.where(singular, np.inf, sigma[..., 0] / sigma[..., -1])[()]


@fill(parameters=_CHAIN_Q_ROWS)
def rank(chain, q, rows="all"):
    """The rank of the Jacobian's rows (NumPy's tolerance).

    {parameters}

    Returns
    -------
    int or ndarray of int, shape (N,)
        The rank.

    Examples
    --------
    A planar 2R arm loses a rank stretched out (q2 = 0) and has full rank bent:

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> rank(arm, [[0.0, 0.0], [0.0, np.pi / 2]], "planar")
    array([1, 2])
    """
    check_rows(rows)
    q = check_chain(chain).check_q(q)

    def part(q_part):
        return np.linalg.matrix_rank(chain.jacobian_rows(q_part, rows))

    return part(q) if q.ndim == 1 else in_chunks(q, part)


@fill(chain_q=_CHAIN_ONE_Q)
def ellipsoid(chain, q, rows="position"):
    """The manipulability ellipsoid {J qdot : |qdot| <= 1} of one configuration q (n,).

    A zero radius is a direction the end effector cannot move in.

    Parameters
    ----------
    {chain_q}
    rows : {'position', 'orientation'}, optional
        Which ellipsoid: of the point's velocity or of the angular velocity.

    Returns
    -------
    center : ndarray, shape (3,)
        The end-effector point (m).
    radii : ndarray, shape (3,)
        The semi-axes, in m/s (position) or rad/s (orientation) per unit joint-rate
        norm.
    axes : ndarray, shape (3, 3)
        Their directions, as columns.

    Examples
    --------
    The planar 2R arm with unit links at q = (0, pi/2): the radii are the singular
    values of its planar Jacobian (see :func:`singular_values`), none along z.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> center, radii, axes = ellipsoid(arm, [0.0, np.pi / 2])
    >>> np.round(center, 6) + 0.0, np.round(radii, 6) + 0.0
    (array([1., 1., 0.]), array([1.618034, 0.618034, 0.      ]))
    """
    q = check_chain(chain).check_one(q)
    if rows not in ("position", "orientation"):
        raise ValueError(
            f"rows must be 'position' or 'orientation' for a 3D ellipsoid, got {rows!r}"
        )
    J = geometric_jacobian(chain, q)[check_rows(rows)]
    U, sigma, _ = np.linalg.svd(J)
    radii = np.zeros(3)
    radii[: sigma.size] = sigma
    return chain.fk(q)[:3, 3], radii, U
