"""Numerical inverse kinematics of any chain: Newton–Raphson on the twist of the pose
error.

The algorithm needs of a chain only what every chain offers (``fk``, ``space_jacobian``,
``body_jacobian``, ``check_q``, ``qlim``, ``joints``), so it sits below
:mod:`screwkit.chains` (as the Robotics Toolbox's kinematics mixin sits below its robot
classes): ``Chain.numeric_ik`` calls it without an import circle. Public as
:func:`screwkit.ik.numeric_ik`.
"""

from dataclasses import dataclass

import numpy as np

from .._checks import (
    as_float_array,
    check_chain,
    check_flag,
    check_poses,
    check_positive,
    check_transform,
    describe,
)
from ..lie import log_transform
from ..links import Joint
from ..tolerances import NEWTON_DAMPING, NEWTON_TOL
from ..transforms import _wrap_angle, inv

__all__ = ["NumericIKResult", "numeric_ik", "pose_error"]


@dataclass
class NumericIKResult:
    """The result of :func:`numeric_ik`, one entry per start for a batch.

    Parameters
    ----------
    q : ndarray, shape (n,) or (N, n)
        The joint vector reached (rad; m for a prismatic joint).
    success : bool or ndarray of bool, shape (N,)
        Whether the final error is below the tolerance.
    iterations : int or ndarray of int, shape (N,)
        The Newton steps taken.
    error : float or ndarray, shape (N,)
        The norm of the final error twist [omega; v] theta (rad and m).

    Examples
    --------
    >>> result = NumericIKResult(np.array([0.0, 1.5]), True, 4, 0.0)
    >>> result.success, result.iterations
    (True, 4)
    """

    q: np.ndarray
    success: bool | np.ndarray
    iterations: int | np.ndarray
    error: float | np.ndarray


def pose_error(T, T_target):
    """The twist of the motion from T to T_target: ``log_transform(inv(T) @ T_target)``.

    Parameters
    ----------
    T, T_target : array-like, shape (..., 4, 4)
        Rigid transforms (m); they broadcast.

    Returns
    -------
    ndarray, shape (..., 6)
        The twist [omega; v] theta in the body frame of T (rad and m).

    Examples
    --------
    From the identity to a quarter turn about z, then to 0.5 m up z:

    >>> turn = np.eye(4)
    >>> turn[:2, :2] = [[0.0, -1.0], [1.0, 0.0]]
    >>> np.round(pose_error(np.eye(4), turn), 6) + 0.0
    array([0.      , 0.      , 1.570796, 0.      , 0.      , 0.      ])
    >>> up = np.eye(4)
    >>> up[2, 3] = 0.5
    >>> np.round(pose_error(np.eye(4), up), 6) + 0.0
    array([0. , 0. , 0. , 0. , 0. , 0.5])
    """
    return log_transform(
        inv(check_transform(as_float_array(T, "T"), "T"))
        @ check_transform(as_float_array(T_target, "T_target"), "T_target")
    )


def numeric_ik(
    chain,
    T,
    q0,
    tol=NEWTON_TOL,
    max_iterations=200,
    frame="body",
    damping=None,
    within_limits=True,
):
    """Numerical inverse kinematics in twist coordinates, for any chain
    (DH or product of exponentials; revolute, prismatic and helical joints).

    Each step is Newton–Raphson on the error twist: with V = log(T(q)^-1 T*)
    (body frame) or Ad(T(q)) V (space frame) and J the body (space) Jacobian, it solves
    (J^T J + lambda I) dq = J^T V. Damped least squares: by default
    lambda = |V|^2 / 2 + :data:`~screwkit.tolerances.NEWTON_DAMPING` (strong far from
    the target and near singularities, vanishing at the solution, Sugihara 2011);
    ``damping=0`` is the plain Newton–Raphson step dq = pinv(J) V (Lynch and Park,
    sec. 6.2.2). With ``within_limits`` every iterate is clipped into the joint
    limits.

    Parameters
    ----------
    chain : Chain
        Any serial chain.
    T : array-like, shape (4, 4)
        The target pose (m).
    q0 : array-like, shape (n,) or (N, n)
        One start, or N starts solved together (rad; m for a prismatic joint).
    tol : float, default :data:`~screwkit.tolerances.NEWTON_TOL`
        Success when the norm of V is below it (rad and m).
    max_iterations : int, default 200
        At least 1.
    frame : {'body', 'space'}, default 'body'
        The frame of the error twist and the Jacobian.
    damping : float or None, default None
        None: adaptive (above); or a number lambda >= 0.
    within_limits : bool, default True
        True: the answer respects the joint limits, and revolute joints without limits
        are wrapped into (-pi, pi]; False: limits ignored, every revolute angle wrapped
        into (-pi, pi].

    Returns
    -------
    NumericIKResult
        ``q`` of shape (n,) or (N, n); ``success`` is False whenever the final error is
        not below tol (an unreachable pose never reports success).

    Examples
    --------
    A planar 2R arm with unit links, from two starts to the pose of q = (0, pi/2):
    the elbow-up solution, the only one with that tool orientation.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> result = numeric_ik(arm, arm.fk([0.0, np.pi / 2]), [[0.3, 1.2], [0.2, 1.0]])
    >>> result.success, np.round(result.q, 6) + 0.0
    (array([ True,  True]), array([[0.      , 1.570796],
           [0.      , 1.570796]]))
    """
    check_chain(chain)
    T = check_poses(T, "T", single_only=True)
    q = chain.check_q(q0, "q0").copy()
    if (
        isinstance(max_iterations, bool)
        or not isinstance(max_iterations, (int, np.integer))
        or max_iterations < 1
    ):
        raise ValueError(
            f"max_iterations must be a positive integer, got {max_iterations!r}"
        )
    tol = check_positive(tol, "tol")
    if frame not in ("body", "space"):
        raise ValueError(f"frame must be 'body' or 'space', got {describe(frame)}")
    if damping is not None:
        try:
            damping = check_positive(damping, "damping", allow_zero=True)
        except (TypeError, ValueError) as error:
            raise type(error)(
                f"damping must be None or a number >= 0, got {describe(damping)}"
            ) from None
    within_limits = check_flag(within_limits, "within_limits")
    single = q.ndim == 1
    q = q[None] if single else q
    low, high = chain.qlim.T
    if within_limits:
        q = np.clip(q, low, high)
    iterations = np.zeros(q.shape[0], dtype=int)
    error = _error_twist(chain, q, T, frame)
    norm = np.linalg.norm(error, axis=-1)
    eye = np.eye(chain.n)
    for _ in range(max_iterations):
        active = norm >= tol
        if not np.any(active):
            break
        J = (
            chain.body_jacobian(q[active])
            if frame == "body"
            else chain.space_jacobian(q[active])
        )
        V = error[active]
        if damping == 0:
            step = (np.linalg.pinv(J) @ V[..., None])[..., 0]
        else:
            lam = (
                0.5 * np.sum(V**2, axis=-1) + NEWTON_DAMPING
                if damping is None
                else np.full(len(V), float(damping))
            )
            JT = np.swapaxes(J, -1, -2)
            step = np.linalg.solve(
                JT @ J + lam[:, None, None] * eye, JT @ V[..., None]
            )[..., 0]
        candidate = q[active] + step
        if within_limits:
            candidate = np.clip(candidate, low, high)
        q[active] = candidate
        error[active] = _error_twist(chain, candidate, T, frame)
        norm[active] = np.linalg.norm(error[active], axis=-1)
        iterations[active] += 1
    q = _wrap_revolute(chain, q, within_limits)
    if single:
        return NumericIKResult(
            q=q[0],
            success=bool(norm[0] < tol),
            iterations=int(iterations[0]),
            error=float(norm[0]),
        )
    return NumericIKResult(q=q, success=norm < tol, iterations=iterations, error=norm)


def _error_twist(chain, q, T, frame):
    """V (N, 6): the twist from T(q) to T, in the body frame or the space frame."""
    Tq = chain.fk(q)
    V = log_transform(inv(Tq) @ T)
    if frame == "body":
        return V
    R, p = Tq[:, :3, :3], Tq[:, :3, 3]
    omega = np.einsum("nij,nj->ni", R, V[:, :3])
    return np.concatenate(
        [omega, np.cross(p, omega) + np.einsum("nij,nj->ni", R, V[:, 3:])], -1
    )


def _wrap_revolute(chain, q, within_limits):
    """Revolute angles into (-pi, pi] (with limits: only those the wrap keeps inside
    them)."""
    revolute = np.array([j is Joint.REVOLUTE for j in chain.joints])
    wrapped = q.copy()
    wrapped[..., revolute] = _wrap_angle(q[..., revolute])
    if within_limits:
        low, high = chain.qlim.T
        keep = (wrapped >= low) & (wrapped <= high)
        wrapped = np.where(keep, wrapped, q)
    return wrapped
