"""Jacobians of serial chains: exact (SymPy) and fast (NumPy, vectorised over a batch).

Two Jacobians, with names that say which:

* ``geometric_jacobian``: rows [v; omega], v the velocity of the end-effector point, both in
  the base frame (Spong, Siciliano, Corke's ``jacob0``);
* ``space_jacobian``: columns are the joint twists [omega; v] in the base frame, v being the
  velocity of the body point at the base origin (Lynch & Park's J_s).

From the Jacobian: singular values, Yoshikawa's manipulability sqrt(det(J J^T)), the
condition number, the rank, and the manipulability ellipsoid. ``rows`` selects the rows
used: 'all' (6), 'position' (v, m/s per unit joint rate), 'orientation' (omega) or 'planar'
(v_x, v_y: the 2 x n Jacobian of an arm in the x-y plane).

>>> import screwkit as sk, numpy as np
>>> arm = sk.robots.planar([1.0, 1.0])
>>> float(np.round(manipulability(arm, [0.0, np.pi / 2], rows="planar"), 12))  # |l1 l2 sin q2|
1.0
>>> int(rank(arm, [0.0, 0.0], rows="planar"))  # stretched: singular
1
"""
import numpy as np
import sympy as sp

from .chains import Joint

__all__ = [
    "joint_axes",
    "geometric_jacobian",
    "space_jacobian",
    "numerical_jacobian",
    "geometric_jacobian_symbolic",
    "determinant_symbolic",
    "singular_values",
    "manipulability",
    "condition_number",
    "rank",
    "ellipsoid",
]

#: Rows of the geometric Jacobian: 'planar' is (v_x, v_y), the 2 x n Jacobian of a planar arm.
ROWS = {"all": slice(0, 6), "position": slice(0, 3), "orientation": slice(3, 6), "planar": slice(0, 2)}


def _axes_and_point(chain, q):
    """z_i, o_i of every joint axis, each (3, n, ...), and the end-effector point p (3, ...): batch last."""
    q = chain.check_q(q)
    if q.ndim == 1:
        values = np.array(chain._evaluate(chain._axes_functions, q))
    else:
        values = np.empty((6 * chain.n + 3, q.shape[0]))
        chain._evaluate(chain._axes_functions, q, values, range(values.shape[0]))
    axes = values[:-3].reshape((chain.n, 2, 3) + values.shape[1:])
    z, o = np.swapaxes(axes[:, 0], 0, 1), np.swapaxes(axes[:, 1], 0, 1)
    return q, z, o, values[-3:]


def joint_axes(chain, q):
    """Direction z_i and a point o_i of every joint axis in the base frame, each (n, 3) or (N, n, 3)."""
    q, z, o, _ = _axes_and_point(chain, q)
    if q.ndim == 1:
        return z.T, o.T
    return z.transpose(2, 1, 0), o.transpose(2, 1, 0)


def _cross(a, b):
    """Cross product along axis 0 (arrays laid out (3, ...)), cheaper than np.cross on strided data."""
    return np.stack([a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]])


def _revolute(chain):
    return np.array([j is Joint.REVOLUTE for j in chain.joints])


def geometric_jacobian(chain, q):
    """The geometric Jacobian: q (n,) -> (6, n), Q (N, n) -> (N, 6, n); rows [v; omega].

    Column i is (z_i x (p - o_i); z_i) for a revolute joint and (z_i; 0) for a prismatic
    one, with p the end-effector point.
    """
    q, z, o, p = _axes_and_point(chain, q)
    revolute = _revolute(chain).reshape((-1,) + (1,) * (q.ndim - 1))
    J = np.empty((6,) + z.shape[1:])
    J[:3] = np.where(revolute, _cross(z, p[:, None] - o), z)
    J[3:] = np.where(revolute, z, 0.0)
    return J if q.ndim == 1 else J.transpose(2, 0, 1)


def space_jacobian(chain, q):
    """The space Jacobian: q (n,) -> (6, n), Q (N, n) -> (N, 6, n); columns [omega; v].

    Column i is the twist of joint i in the base frame: (z_i; o_i x z_i) for a revolute
    joint (the velocity of the body point at the base origin), (0; z_i) for a prismatic one.
    """
    q, z, o, _ = _axes_and_point(chain, q)
    revolute = _revolute(chain).reshape((-1,) + (1,) * (q.ndim - 1))
    J = np.empty((6,) + z.shape[1:])
    J[:3] = np.where(revolute, z, 0.0)
    J[3:] = np.where(revolute, _cross(o, z), z)
    return J if q.ndim == 1 else J.transpose(2, 0, 1)


def numerical_jacobian(chain, q, h=1e-6):
    """The geometric Jacobian (6, n) of one configuration by central differences of FK.

    Column i is ((p(q + h e_i) - p(q - h e_i)) / 2h; omega_i), omega_i read from the skew
    matrix dR/dq_i R^T. An independent check of :func:`geometric_jacobian` (error O(h^2)).
    """
    q = chain.check_q(q)
    if q.ndim != 1:
        raise ValueError(f"q must be one configuration of shape ({chain.n},), got shape {q.shape}")
    R = chain.fk(q)[:3, :3]
    columns = []
    for step in h * np.eye(chain.n):
        plus, minus = chain.fk(q + step), chain.fk(q - step)
        W = (plus[:3, :3] - minus[:3, :3]) / (2 * h) @ R.T
        columns.append(np.r_[(plus[:3, 3] - minus[:3, 3]) / (2 * h), W[2, 1], W[0, 2], W[1, 0]])
    return np.array(columns).T


# ---- exact ---------------------------------------------------------------------------------

def geometric_jacobian_symbolic(chain, point=None, symbolic_lengths=False):
    """The exact geometric Jacobian (6, n), a SymPy matrix in the joint symbols q1..qn.

    point : the reference point whose velocity the rows v give: None for the end-effector
        point, an integer k for the origin of frame k (e.g. a wrist centre), or a 3-vector
        of expressions in the base frame.
    symbolic_lengths : lengths as the symbols a_i, d_i (see ``Chain.length_symbols``).
    """
    frames = chain.frames_symbolic(symbolic_lengths)
    end = chain.fk_symbolic(symbolic_lengths=symbolic_lengths)
    if point is None:
        p = end[:3, 3]
    elif isinstance(point, (int, np.integer)):
        if not 0 <= point <= chain.n:
            raise ValueError(f"point must be a frame number 0..{chain.n}, a 3-vector or None, got {point!r}")
        p = frames[point][:3, 3]
    else:
        p = sp.Matrix(point)
        if p.shape != (3, 1):
            raise ValueError(f"point must be a frame number, a 3-vector or None, got shape {p.shape}")
    joint_frames = chain.joint_frames(frames)
    columns = []
    for kind, T in zip(chain.joints, joint_frames):
        z, o = T[:3, 2], T[:3, 3]
        if kind is Joint.REVOLUTE:
            columns.append(sp.Matrix.vstack(z.cross(p - o), z))
        else:
            columns.append(sp.Matrix.vstack(z, sp.zeros(3, 1)))
    return sp.Matrix.hstack(*columns).applyfunc(lambda e: sp.trigsimp(sp.expand(e)))


def determinant_symbolic(chain, point=None, symbolic_lengths=False):
    """det J of a six-joint chain, factorised: a SymPy expression in q1..q6.

    det J does not depend on the reference point (moving it multiplies J by a matrix of
    determinant 1), so pick ``point`` where J is simple: at a wrist centre (frame 4 of an arm
    with a spherical wrist) J is block triangular, [[A, 0], [C, D]], and det J = det A det D.
    """
    if chain.n != 6:
        raise ValueError(f"the chain must have 6 joints for a square Jacobian, got {chain.n}")
    J = geometric_jacobian_symbolic(chain, point=point, symbolic_lengths=symbolic_lengths)
    if J[:3, 3:].is_zero_matrix:
        factors = [J[:3, :3].det(method="berkowitz"), J[3:, 3:].det(method="berkowitz")]
    else:
        factors = [J.det(method="berkowitz")]
    return sp.Mul(*[sp.factor(sp.trigsimp(sp.factor(f))) for f in factors])


# ---- numbers from the Jacobian ---------------------------------------------------------------

def _rows(rows):
    if rows not in ROWS:
        raise ValueError(f"rows must be one of {sorted(ROWS)}, got {rows!r}")
    return ROWS[rows]


def _singular(sigma, rows, n):
    """True where J (of the rows ``rows``, n columns) has lost rank: NumPy's rank rule on its
    smallest singular value."""
    m = len(range(6)[_rows(rows)])
    return sigma[..., -1] <= sigma[..., 0] * max(m, n) * np.finfo(float).eps


def singular_values(chain, q, rows="all"):
    """Singular values of the geometric Jacobian's rows, largest first: (k,) or (N, k)."""
    J = geometric_jacobian(chain, q)[..., _rows(rows), :]
    return np.linalg.svd(J, compute_uv=False)


def manipulability(chain, q, rows="all"):
    """Yoshikawa's manipulability, the product of the singular values: () or (N,).

    That is sqrt(det(J J^T)) for J with no more rows than columns (sqrt(det(J^T J)) otherwise).
    Exactly 0.0 where J has lost rank (by NumPy's rank tolerance), so a singular
    configuration is an answer, not noise. With rows='all' the product mixes metres and
    radians; 'position' gives the volume factor of the velocity ellipsoid in m/s.
    """
    sigma = singular_values(chain, q, rows)
    return np.where(_singular(sigma, rows, chain.n), 0.0, np.prod(sigma, axis=-1))[()]


def condition_number(chain, q, rows="all"):
    """sigma_max / sigma_min of the Jacobian's rows (1 is isotropic); inf where singular."""
    sigma = singular_values(chain, q, rows)
    singular = _singular(sigma, rows, chain.n)
    with np.errstate(divide="ignore"):
        return np.where(singular, np.inf, sigma[..., 0] / sigma[..., -1])[()]


def rank(chain, q, rows="all"):
    """The rank of the Jacobian's rows (NumPy's tolerance): an int, or (N,) ints."""
    J = geometric_jacobian(chain, q)[..., _rows(rows), :]
    return np.linalg.matrix_rank(J)


def ellipsoid(chain, q, rows="position"):
    """The manipulability ellipsoid {J qdot : |qdot| <= 1} of one configuration q (n,).

    Returns (center, radii, axes): the end-effector point (3,), the semi-axes (3,) in
    m/s (position) or rad/s (orientation) per unit joint-rate norm, and their directions as
    the columns of axes (3, 3). A zero radius is a direction the end effector cannot move in.
    """
    q = chain.check_q(q)
    if q.ndim != 1:
        raise ValueError(f"q must be one configuration of shape ({chain.n},), got shape {q.shape}")
    if rows not in ("position", "orientation"):
        raise ValueError(f"rows must be 'position' or 'orientation' for a 3D ellipsoid, got {rows!r}")
    J = geometric_jacobian(chain, q)[_rows(rows)]
    U, sigma, _ = np.linalg.svd(J)
    radii = np.zeros(3)
    radii[: sigma.size] = sigma
    return chain.fk(q)[:3, 3], radii, U
