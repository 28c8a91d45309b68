"""Inverse kinematics: the PUMA 560 in closed form, and any chain numerically.

Closed form (:func:`puma560_ik`): the wrist centre fixes the arm (joint 1: left or right of
the shoulder offset d3), the elbow (joints 2 and 3: a planar two-link problem, elbow above or
below the line from the shoulder to the wrist centre) and the wrist (joints 4-6: Z-Y-Z Euler
angles of 3R6, two solutions). Labels follow Corke's toolbox: l/r arm, u/d elbow, n/f wrist,
where 'n' has q5 <= 0 and 'f' has q5 >= 0 for this model's signs.

>>> import numpy as np, screwkit as sk
>>> robot = sk.robots.puma560()
>>> q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
>>> solutions = puma560_ik(robot.fk(q))
>>> [s.config for s in solutions]
['lun', 'luf', 'ldn', 'ldf', 'run', 'ruf', 'rdn', 'rdf']
>>> np.round(solutions.by_config('ruf').q, 6)
array([ 0.3,  0.5, -2. ,  0.4,  0.7,  0.2])
"""
from dataclasses import dataclass

import numpy as np
import sympy as sp

from ._checks import as_float_array, check_transform, describe
from .chains import Chain, Convention, Joint
from .transforms import inv

__all__ = ["CONFIGURATIONS", "IKSolution", "IKSolutions", "puma560_ik", "puma560_ik_all",
           "puma560_config", "NumericIKResult", "numeric_ik", "pose_error"]

#: The fixed order of the eight PUMA solutions in :func:`puma560_ik_all`.
CONFIGURATIONS = ("lun", "luf", "ldn", "ldf", "run", "ruf", "rdn", "rdf")

#: A singularity is reported when its measure (m or m^2, or |sin q5|) is below this.
SINGULAR_TOL = 1e-9


@dataclass(frozen=True)
class IKSolution:
    """One closed-form solution: joint vector ``q`` (6,) rad, its ``config`` label, the
    singularities it sits on (``'shoulder'``, ``'elbow'``, ``'wrist'``) and whether it
    respects the joint limits."""

    q: np.ndarray
    config: str
    singular: tuple = ()
    within_limits: bool = True

    def __repr__(self):
        q = ", ".join(f"{v:+.4f}" for v in self.q)
        extra = f", singular={self.singular}" if self.singular else ""
        return f"IKSolution({self.config}: q=[{q}], within_limits={self.within_limits}{extra})"


class IKSolutions(list):
    """The solutions for one pose (a list of :class:`IKSolution`); ``reason`` says why it is
    empty (out of reach) or None."""

    def __init__(self, solutions=(), reason=None):
        super().__init__(solutions)
        self.reason = reason

    def by_config(self, config):
        """The solution with this label ('lun', ...), or None."""
        return next((s for s in self if s.config == config), None)

    def nearest(self, q):
        """The solution closest to the joint vector ``q`` (wrapped angle differences), or None."""
        q = as_float_array(q, "q")
        if q.shape != (6,):
            raise ValueError(f"q must have 6 entries, got shape {q.shape}")
        if not self:
            return None
        return min(self, key=lambda s: np.linalg.norm(_wrap(s.q - q)))


def _wrap(angle):
    """Angles wrapped into (-pi, pi]."""
    return np.pi - np.mod(np.pi - angle, 2 * np.pi)


def _puma_geometry(robot):
    """(d1, a2, a3, d3, d4, d6) of a chain that has the PUMA 560's structure, else ValueError."""
    if not isinstance(robot, Chain):
        raise TypeError(f"robot must be a Chain, got {describe(robot)}")
    expected_alpha = [sp.pi / 2, 0, -sp.pi / 2, sp.pi / 2, -sp.pi / 2, 0]
    value = [[float(sp.sympify(getattr(link, key))) for key in ("d", "a", "offset")] for link in robot.links]
    ok = (
        robot.n == 6
        and all(link.joint is Joint.REVOLUTE for link in robot.links)
        and all(abs(float(sp.sympify(link.alpha)) - float(alpha)) < 1e-12
                for link, alpha in zip(robot.links, expected_alpha))
        and value[0][1] == 0 and value[1][0] == 0 and value[3][1] == value[4][1] == value[5][1] == 0
        and value[4][0] == 0 and all(v[2] == 0 for v in value)
        and robot.convention is Convention.STANDARD
    )
    if not ok:
        raise ValueError(
            "robot must have the PUMA 560's standard-DH structure (alphas 90, 0, -90, 90, -90, 0 deg, "
            f"a1 = a4 = a5 = a6 = 0, d2 = d5 = 0, no offsets), got {robot!r}"
        )
    return value[0][0], value[1][1], value[2][1], value[2][0], value[3][0], value[5][0]


def puma560_ik_all(Ts, robot=None):
    """All eight closed-form solutions for a batch of poses, in the order of CONFIGURATIONS.

    Parameters
    ----------
    Ts : array, shape (N, 4, 4) (or (4, 4)), poses of the tool in the base frame (m)
    robot : a Chain with the PUMA's structure (default ``robots.puma560()``)

    Returns
    -------
    Q : array, shape (N, 8, 6) (or (8, 6)), rad in (-pi, pi]; NaN where a pose is out of reach
    """
    from .robots import puma560

    robot = puma560() if robot is None else robot
    d1, a2, a3, d3, d4, d6 = _puma_geometry(robot)
    T = check_transform(np.asarray(Ts, dtype=float), "Ts")
    single = T.ndim == 2
    T = T[None] if single else T
    Q, _ = _solve(T, robot, d1, a2, a3, d3, d4, d6)
    return Q[0] if single else Q


def _solve(T, robot, d1, a2, a3, d3, d4, d6):
    """The vectorised closed form: (N, 8, 6) joint vectors and (N, 8, 3) singularity flags."""
    if not np.allclose(robot.base, np.eye(4)) or not np.allclose(robot.tool, np.eye(4)):
        T = inv(robot.base) @ T @ inv(robot.tool)
    R, p = T[:, :3, :3], T[:, :3, 3]
    w = p - d6 * R[:, :, 2]  # the wrist centre
    wx, wy, wz = w[:, 0], w[:, 1], w[:, 2] - d1
    r2 = wx**2 + wy**2
    with np.errstate(invalid="ignore", divide="ignore"):
        horizontal = np.sqrt(r2 - d3**2)  # NaN inside the cylinder of radius d3 about joint 1's axis
        phi, alpha = np.arctan2(wy, wx), np.arcsin(d3 / np.sqrt(r2))
        rho, beta = np.hypot(a3, d4), np.arctan2(d4, a3)
        kappa = ((r2 - d3**2 + wz**2 - a2**2 - rho**2) / (2 * a2 * rho))
        kappa = np.where(np.abs(kappa) - 1 < 1e-12, np.clip(kappa, -1, 1), kappa)  # round-off at full stretch
        gamma = np.arccos(kappa)  # NaN where the wrist centre is out of reach
    Q = np.empty((T.shape[0], 8, 6))
    flags = np.zeros((T.shape[0], 8, 3), dtype=bool)
    for k, config in enumerate(CONFIGURATIONS):
        arm = 1.0 if config[0] == "r" else -1.0
        elbow = 1.0 if config[1] == "u" else -1.0
        q1 = phi + alpha if arm > 0 else phi + np.pi - alpha
        V = arm * horizontal  # reach of the wrist centre along x1
        q3 = -beta - arm * elbow * gamma
        c3, s3 = np.cos(q3), np.sin(q3)
        q2 = np.arctan2(wz, V) - np.arctan2(a3 * s3 + d4 * c3, a2 + a3 * c3 - d4 * s3)
        q4, q5, q6, wrist_singular = _wrist(R, q1, q2 + q3, flip=config[2] == "f")
        q = _wrap(np.stack([q1, q2, q3, q4, q5, q6], axis=-1))
        Q[:, k] = np.where(np.any(np.isnan(q), axis=-1, keepdims=True), np.nan, q)
        flags[:, k] = np.stack([horizontal**2 < SINGULAR_TOL, np.abs(np.abs(kappa) - 1) < SINGULAR_TOL,
                                wrist_singular], axis=-1)
    return Q, flags


def _wrist(R, q1, q23, flip):
    """Joints 4-6 from 3R6 = R03^T R = Rz(q4) Ry(-q5) Rz(q6) (Z-Y-Z Euler angles)."""
    c1, s1, c23, s23 = np.cos(q1), np.sin(q1), np.cos(q23), np.sin(q23)
    # R03 = Rz(q1) Rx(90deg) Rz(q23) Rx(-90deg); its columns x3, y3, z3
    x3 = np.stack([c1 * c23, s1 * c23, s23], axis=-1)
    y3 = np.stack([-s1, c1, np.zeros_like(q1)], axis=-1)
    z3 = np.stack([-c1 * s23, -s1 * s23, c23], axis=-1)
    R03 = np.stack([x3, y3, z3], axis=-1)
    M = np.swapaxes(R03, -1, -2) @ R
    s5 = np.hypot(M[:, 0, 2], M[:, 1, 2])
    singular = s5 < SINGULAR_TOL
    q5 = -np.arctan2(s5, M[:, 2, 2])  # 'n': q5 <= 0
    q4 = np.arctan2(M[:, 1, 2], M[:, 0, 2])
    q6 = np.arctan2(M[:, 2, 1], -M[:, 2, 0])
    # At q5 = 0 (or pi) only q4 + q6 (or q4 - q6) is fixed: the convention is q4 = 0.
    q4 = np.where(singular, 0.0, q4)
    q6 = np.where(singular, np.where(M[:, 2, 2] > 0, np.arctan2(M[:, 1, 0], M[:, 0, 0]),
                                     np.arctan2(M[:, 1, 0], M[:, 1, 1])), q6)
    if flip:
        q4, q5, q6 = q4 + np.pi, -q5, q6 + np.pi
    return q4, q5, q6, singular


def puma560_ik(T, robot=None, within_limits=False, near=None):
    """Every closed-form solution for one pose T (4, 4) of the PUMA 560.

    Parameters
    ----------
    T : array, shape (4, 4), pose of the tool in the base frame (m)
    robot : a Chain with the PUMA's structure (default ``robots.puma560()``)
    within_limits : keep only the solutions inside the joint limits (angles are shifted by
        2 pi where that brings them inside, e.g. q6 in [-266, 266] deg)
    near : a joint vector (6,): sort the solutions by their distance to it

    Returns
    -------
    IKSolutions : a list of IKSolution (eight for a generic reachable pose, none out of
        reach, with ``.reason``)
    """
    from .robots import puma560

    robot = puma560() if robot is None else robot
    geometry = _puma_geometry(robot)
    T = check_transform(np.asarray(T, dtype=float), "T")
    if near is not None:
        near = as_float_array(near, "near")
        if near.shape != (6,):
            raise ValueError(f"near must be a joint vector of 6 entries, got shape {near.shape}")
    if T.ndim != 2:
        raise ValueError(f"T must be one pose of shape (4, 4); use puma560_ik_all for a batch, got shape {T.shape}")
    Q, flags = _solve(T[None], robot, *geometry)
    if np.all(np.isnan(Q[0])):
        return IKSolutions([], reason=_why_unreachable(T, robot, *geometry))
    names = ("shoulder", "elbow", "wrist")
    solutions = []
    for q, config, flag in zip(Q[0], CONFIGURATIONS, flags[0]):
        inside = _into_limits(q, robot.qlim)
        solutions.append(IKSolution(q=inside if inside is not None else q, config=config,
                                    singular=tuple(n for n, f in zip(names, flag) if f),
                                    within_limits=inside is not None))
    if within_limits:
        solutions = [s for s in solutions if s.within_limits]
    result = IKSolutions(solutions)
    if near is not None:
        result.sort(key=lambda s: np.linalg.norm(_wrap(s.q - near)))
    if not result:
        result.reason = "every solution violates a joint limit"
    return result


def _into_limits(q, qlim):
    """q with each angle moved by a multiple of 2 pi into its limits, or None if one cannot be."""
    moved = q.copy()
    for i, (low, high) in enumerate(qlim):
        candidates = q[i] + 2 * np.pi * np.arange(-2, 3)
        inside = candidates[(candidates >= low - 1e-12) & (candidates <= high + 1e-12)]
        if inside.size == 0:
            return None
        moved[i] = inside[np.argmin(np.abs(inside))]
    return moved


def _why_unreachable(T, robot, d1, a2, a3, d3, d4, d6):
    R, p = T[:3, :3], T[:3, 3]
    w = p - d6 * R[:, 2] - np.array([0.0, 0.0, d1])
    radial = np.hypot(w[0], w[1])
    if radial < d3:
        return (f"the wrist centre is {radial:.4f} m from the axis of joint 1, closer than the "
                f"shoulder offset d3 = {d3:.5f} m")
    reach = np.sqrt(radial**2 - d3**2 + w[2] ** 2)
    rho = np.hypot(a3, d4)
    return (f"the wrist centre is {reach:.4f} m from the shoulder in the arm's plane; the arm reaches "
            f"from {abs(a2 - rho):.4f} m to {a2 + rho:.4f} m")


def puma560_config(q, robot=None):
    """The configuration label of a joint vector (6,), from the geometry alone.

    Arm 'r' if the wrist centre is in front of the shoulder along x1, i.e.
    a2 c2 + a3 c23 - d4 s23 > 0; elbow 'u' if the elbow lies above the line from the
    shoulder to the wrist centre (seen with the arm pointing forward); wrist 'n' if q5 < 0.
    """
    from .robots import puma560

    robot = puma560() if robot is None else robot
    _, a2, a3, _, d4, _ = _puma_geometry(robot)
    q = robot.check_q(q)
    if q.shape != (6,):
        raise ValueError(f"q must be one joint vector of shape (6,), got shape {q.shape}")
    q2, q3, q5 = q[..., 1], q[..., 2], q[..., 4]
    forward = a2 * np.cos(q2) + a3 * np.cos(q2 + q3) - d4 * np.sin(q2 + q3)
    wrist = np.stack([forward, a2 * np.sin(q2) + a3 * np.sin(q2 + q3) + d4 * np.cos(q2 + q3)])
    elbow = a2 * np.stack([np.cos(q2), np.sin(q2)])
    above = np.sign(forward) * (wrist[0] * elbow[1] - wrist[1] * elbow[0]) > 0
    arm = "r" if forward > 0 else "l"
    return arm + ("u" if above else "d") + ("n" if q5 < 0 else "f")


@dataclass
class NumericIKResult:
    """The result of :func:`numeric_ik`: ``q`` (n,) or (N, n) rad/m, ``success``, the
    ``iterations`` used and the final pose ``error`` (norm of [position error (m);
    rotation error (rad)]), one per start for a batch."""

    q: np.ndarray
    success: np.ndarray
    iterations: np.ndarray
    error: np.ndarray


def pose_error(T, T_target):
    """The 6-vector [p* - p; omega] that moves T toward T_target (base frame), omega being the
    axis-angle vector of R* R^T. T, T_target: (..., 4, 4) -> (..., 6)."""
    R_error = T_target[..., :3, :3] @ np.swapaxes(T[..., :3, :3], -1, -2)
    axis = np.stack([R_error[..., 2, 1] - R_error[..., 1, 2], R_error[..., 0, 2] - R_error[..., 2, 0],
                     R_error[..., 1, 0] - R_error[..., 0, 1]], axis=-1)
    sin_angle = 0.5 * np.linalg.norm(axis, axis=-1)
    cos_angle = np.clip(0.5 * (np.trace(R_error, axis1=-2, axis2=-1) - 1), -1, 1)
    angle = np.arctan2(sin_angle, cos_angle)
    scale = np.where(sin_angle > 1e-12, angle / np.where(sin_angle > 1e-12, 2 * sin_angle, 1.0), 0.5)
    omega = scale[..., None] * axis
    # near a half turn the skew part vanishes: take the axis from the symmetric part instead
    half_turn = (cos_angle < -0.99) & (sin_angle < 1e-6)
    if np.any(half_turn):
        B = 0.5 * (R_error[half_turn] + np.eye(3))
        column = np.argmax(np.linalg.norm(B, axis=-2), axis=-1)
        u = B[np.arange(B.shape[0]), :, column]
        omega[half_turn] = np.pi * u / np.linalg.norm(u, axis=-1, keepdims=True)
    return np.concatenate([T_target[..., :3, 3] - T[..., :3, 3], omega], axis=-1)


def numeric_ik(chain, T, q0, tol=1e-10, max_iterations=200):
    """Numerical inverse kinematics by Levenberg–Marquardt, for any chain.

    Each step solves (J^T J + (E + 1e-9) I) dq = J^T e, with e the pose error of
    :func:`pose_error`, J the geometric Jacobian and E = |e|^2 / 2 (Sugihara's damping:
    strong far from the target, vanishing near it).

    Parameters
    ----------
    chain : Chain
    T : array (4, 4), the target pose
    q0 : array (n,) one start, or (N, n) several starts solved together
    tol : success when the error norm is below tol (m and rad)
    max_iterations : int

    Returns
    -------
    NumericIKResult
    """
    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a Chain, got {describe(chain)}")
    T = check_transform(np.asarray(T, dtype=float), "T")
    if T.ndim != 2:
        raise ValueError(f"T must be one pose of shape (4, 4), got shape {T.shape}")
    q = chain.check_q(q0, "q0").copy()
    if not (isinstance(max_iterations, int) and max_iterations >= 1):
        raise ValueError(f"max_iterations must be a positive integer, got {max_iterations!r}")
    if not tol > 0:
        raise ValueError(f"tol must be positive, got {tol!r}")
    single = q.ndim == 1
    q = q[None] if single else q
    iterations = np.zeros(q.shape[0], dtype=int)
    error = pose_error(chain.fk(q), T)
    norm = np.linalg.norm(error, axis=-1)
    eye = np.eye(chain.n)
    for _ in range(max_iterations):
        active = norm >= tol
        if not np.any(active):
            break
        J = chain.geometric_jacobian(q[active])
        e = error[active]
        damping = 0.5 * np.sum(e**2, axis=-1) + 1e-9
        JT = np.swapaxes(J, -1, -2)
        step = np.linalg.solve(JT @ J + damping[:, None, None] * eye, (JT @ e[..., None]))[..., 0]
        candidate = q[active] + step
        new_error = pose_error(chain.fk(candidate), T)
        new_norm = np.linalg.norm(new_error, axis=-1)
        q[active], error[active], norm[active] = candidate, new_error, new_norm
        iterations[active] += 1
    q = _wrap_revolute(chain, q)
    result = NumericIKResult(q=q, success=norm < tol, iterations=iterations, error=norm)
    if single:
        return NumericIKResult(q=q[0], success=bool(result.success[0]),
                               iterations=int(iterations[0]), error=float(norm[0]))
    return result


def _wrap_revolute(chain, q):
    revolute = np.array([j is Joint.REVOLUTE for j in chain.joints])
    q = q.copy()
    q[..., revolute] = _wrap(q[..., revolute])
    return q
