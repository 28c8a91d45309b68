"""Differential inverse kinematics: one step of joint rates for a wanted tool twist.

Two answers side by side (Tedrake, *Robotic Manipulation*, ch. 3):

* :func:`pseudo_inverse_step`: dq = J^T (J J^T + lambda^2 I)^-1 V, the least-norm
  (damped) least-squares rates; it knows no limits, so the step says which joints it
  would drive past theirs (it never clips them silently);
* :func:`qp_step`: the same least squares as a quadratic programme,

      minimise norm(J dq - V)^2 + lambda^2 norm(dq)^2
      subject to  max(-v_max, (q_min - q) / dt) <= dq <= min(v_max, (q_max - q) / dt),

  solved exactly by DAQP (a dual active-set solver); with ``exact=True`` the twist
  is a constraint J dq = V instead, and a step that cannot meet it within the limits
  is infeasible, with its reason.

J is the geometric Jacobian's rows ``rows`` (rows [v; omega] of the end point, or
'position', 'planar' ...), V the wanted twist in those rows.

>>> import numpy as np, screwkit as sk
>>> arm = sk.robots.planar([1.0, 1.0])
>>> step = qp_step(arm, [0.3, 1.2], [0.1, 0.0], 0.01, rows="planar", damping=0.0)
>>> bool(step.tracked), float(np.round(step.tracking_error, 12))
(True, 0.0)
"""

from dataclasses import dataclass

import daqp
import numpy as np

from .._checks import as_float_array, check_chain, check_positive, describe
from ..tolerances import PROXIMAL_STOP, PROXIMAL_WEIGHT, TRACKING_RTOL

__all__ = ["Step", "pseudo_inverse_step", "qp_step"]

#: daqp's constraint kinds: an inequality, and an equality
_INEQUALITY, _EQUALITY = 0, 5


@dataclass(frozen=True)
class Step:
    """One differential-IK step.

    Parameters
    ----------
    dq : ndarray, shape (n,)
        The joint rates (rad/s, m/s); NaN when infeasible.
    feasible : bool
        The rates respect every limit (and, with ``exact``, give V).
    tracked : bool
        J dq equals the wanted twist (to TRACKING_RTOL).
    tracking_error : float
        The norm of J dq - V (m/s and rad/s mixed as the rows are).
    limited : tuple of str
        The limits the step meets or would break ('joint 3 upper position',
        'joint 1 velocity', ...).
    reason : str or None
        Why the step is infeasible or not tracked, or None.
    method : {'pseudo-inverse', 'qp'}
        How the step was computed.

    Examples
    --------
    A planar 2R arm (unit links) with its elbow at a right angle, asked to move its
    tip up at 1 m/s: it needs 1 rad/s at each joint, above a limit of 0.5 rad/s.

    >>> from screwkit.robots import planar
    >>> arm = planar([1.0, 1.0])
    >>> step = pseudo_inverse_step(arm, [0, np.pi / 2], [0, 1], 0.01, rows="planar",
    ...                            v_max=0.5)
    >>> step.feasible, step.tracked, step.limited
    (False, True, ('joint 1 velocity', 'joint 2 velocity'))
    """

    dq: np.ndarray
    feasible: bool
    tracked: bool
    tracking_error: float
    limited: tuple
    reason: object
    method: str


def _problem(chain, q, twist, dt, rows, damping):
    check_chain(chain)
    q = chain.check_one(q)
    J = chain.jacobian_rows(q, rows)
    V = as_float_array(twist, "twist")
    if V.shape != (J.shape[0],):
        raise ValueError(
            f"twist must have {J.shape[0]} entries for rows={rows!r}, got shape "
            f"{V.shape}"
        )
    dt = check_positive(dt, "dt")
    damping = check_positive(damping, "damping", allow_zero=True)
    return q, J, V, dt, damping


def _velocity_limits(chain, v_max):
    if v_max is None:
        return np.full(chain.n, np.inf)
    v = as_float_array(v_max, "v_max")
    if v.ndim > 1 or v.size not in (1, chain.n):
        raise ValueError(
            f"v_max must be one number or {chain.n} numbers, got shape {v.shape}"
        )
    if np.any(v <= 0):
        raise ValueError(f"v_max must be positive, got {v.tolist()}")
    return np.broadcast_to(v, (chain.n,)).astype(float)


def _bounds(chain, q, dt, v):
    """The box on dq from the position limits reached in dt and the rate limits."""
    low, high = chain.qlim[:, 0], chain.qlim[:, 1]
    return np.maximum(-v, (low - q) / dt), np.minimum(v, (high - q) / dt)


def _tracking(J, dq, V):
    error = float(np.linalg.norm(J @ dq - V))
    return error, bool(error <= TRACKING_RTOL * (1.0 + np.linalg.norm(V)))


def _named(dq, v, lower, upper):
    """Which limits dq meets (within round-off of the bound) or breaks."""
    names = []
    slack = TRACKING_RTOL * (1.0 + np.abs(dq))
    for k in range(dq.size):
        if dq[k] <= lower[k] + slack[k] and np.isfinite(lower[k]):
            kind = "velocity" if lower[k] == -v[k] else "lower position"
            names.append(f"joint {k + 1} {kind}")
        elif dq[k] >= upper[k] - slack[k] and np.isfinite(upper[k]):
            kind = "velocity" if upper[k] == v[k] else "upper position"
            names.append(f"joint {k + 1} {kind}")
    return tuple(names)


def _damped_pseudo_inverse(J, damping_squared):
    """J^T (J J^T + lambda^2 I)^-1 of J (m, n), (n, m); lambda^2 = 0 gives the
    Moore-Penrose pseudo-inverse (by the SVD, so a rank-deficient J is safe too)."""
    if damping_squared == 0:
        return np.linalg.pinv(J)
    return J.T @ np.linalg.inv(J @ J.T + damping_squared * np.eye(J.shape[0]))


def pseudo_inverse_step(chain, q, twist, dt, rows="all", damping=0.0, v_max=None):
    """The (damped) least-squares rates dq = J^T (J J^T + damping^2 I)^-1 V, unclipped.

    Parameters
    ----------
    chain : Chain
    q : array-like, shape (n,), the configuration (rad, m)
    twist : array-like, the wanted twist in the rows ``rows`` (m/s, rad/s)
    dt : float, the step's duration (s): q + dq dt is checked against the limits
    rows : 'all', 'position', 'orientation' or 'planar'
    damping : float >= 0, lambda (0: the pseudo-inverse)
    v_max : optional, one number or (n,), joint rate limits (rad/s), positive

    Returns
    -------
    Step : ``feasible`` is False, with the joints named, if q + dq dt leaves the
        position limits or dq a rate limit

    Examples
    --------
    The 2R arm at q = (0, 90 deg) has its tip at (1, 1) and J = [[-1, -1], [1, 0]];
    the tip straight up at 1 m/s solves J dq = (0, 1): dq = (1, -1).

    >>> from screwkit.robots import planar
    >>> arm = planar([1.0, 1.0])
    >>> step = pseudo_inverse_step(arm, [0, np.pi / 2], [0, 1], 0.01, rows="planar")
    >>> step.dq.round(6) + 0.0, step.feasible
    (array([ 1., -1.]), True)
    """
    q, J, V, dt, damping = _problem(chain, q, twist, dt, rows, damping)
    v = _velocity_limits(chain, v_max)
    dq = _damped_pseudo_inverse(J, damping**2) @ V
    lower, upper = _bounds(chain, q, dt, v)
    broken = (dq < lower) | (dq > upper)
    error, tracked = _tracking(J, dq, V)
    limited = tuple(
        f"joint {k + 1} "
        + (
            "velocity"
            if abs(dq[k]) > v[k]
            else ("lower position" if dq[k] < lower[k] else "upper position")
        )
        for k in np.flatnonzero(broken)
    )
    reason = "the step breaks the limits of " + ", ".join(limited) if limited else None
    if not tracked and reason is None:
        reason = f"J dq misses the twist by {error:.3g} (a singular or damped J)"
    return Step(dq, not limited, tracked, error, limited, reason, "pseudo-inverse")


def qp_step(chain, q, twist, dt, rows="all", damping=0.0, v_max=None, exact=False):
    """The least-squares rates within the position and rate limits, as a QP (DAQP).

    Parameters
    ----------
    chain : Chain
    q : array-like, shape (n,), the configuration (rad, m), within its limits
    twist : array-like, the wanted twist in the rows ``rows`` (m/s, rad/s)
    dt : float, the step's duration (s): q + dq dt must stay within the limits
    rows : 'all', 'position', 'orientation' or 'planar'
    damping : float >= 0, lambda: > 0 gives the damped least squares (robust near a
        singularity); 0 (default) the least squares itself, solved by DAQP's
        proximal iterations when J^T J is singular (a redundant arm)
    v_max : optional, one number or (n,), joint rate limits (rad/s), positive
    exact : bool, require J dq = V as a constraint (infeasible if the limits forbid)

    Returns
    -------
    Step : ``feasible`` False with the ``reason`` when no rates satisfy the limits
        (q outside them by more than one step can recover, or V unreachable with
        ``exact``); ``tracked`` False with the limits met named when the rates give
        only part of V

    Examples
    --------
    The step of :func:`pseudo_inverse_step` (dq = (1, -1)) under a limit of
    0.5 rad/s: the best within the box is (0.5, -0.5), which moves the tip at only
    0.5 m/s, an error of 0.5.

    >>> from screwkit.robots import planar
    >>> arm = planar([1.0, 1.0])
    >>> step = qp_step(arm, [0, np.pi / 2], [0, 1], 0.01, rows="planar", v_max=0.5)
    >>> step.dq.round(6) + 0.0, step.tracked, round(step.tracking_error, 6)
    (array([ 0.5, -0.5]), False, 0.5)
    """
    q, J, V, dt, damping = _problem(chain, q, twist, dt, rows, damping)
    if not isinstance(exact, (bool, np.bool_)):
        raise TypeError(f"exact must be True or False, got {describe(exact)}")
    v = _velocity_limits(chain, v_max)
    lower, upper = _bounds(chain, q, dt, v)
    n = chain.n
    empty = lower > upper
    if np.any(empty):
        k = int(np.argmax(empty))
        return _infeasible(
            n,
            V,
            f"joint {k + 1} is at {q[k]:.6g}, outside its limits "
            f"[{chain.qlim[k, 0]:.6g}, {chain.qlim[k, 1]:.6g}] by more than one "
            "step at its rate limit can recover",
        )
    H = J.T @ J + damping**2 * np.eye(n)
    f = -J.T @ V
    if exact:
        A = J
        upper_all, lower_all = np.r_[upper, V], np.r_[lower, V]
        sense = np.r_[np.full(n, _INEQUALITY), np.full(V.size, _EQUALITY)]
    else:
        A = np.zeros((0, n))
        upper_all, lower_all = upper, lower
        sense = np.full(n, _INEQUALITY)
    # daqp takes no infinities in its bounds: a huge number stands for "no limit"
    big = 1e30
    dq, _, flag, _ = daqp.solve(
        np.ascontiguousarray(H),
        np.ascontiguousarray(f),
        np.ascontiguousarray(A),
        np.clip(upper_all, -big, big),
        np.clip(lower_all, -big, big),
        sense.astype(np.int32),
        # without damping H may be singular (a redundant arm): proximal iterations,
        # each a strictly convex QP, converge to an optimum of the original one
        eps_prox=0.0 if damping > 0 else PROXIMAL_WEIGHT,
        eta_prox=PROXIMAL_STOP,
    )
    if flag != 1:
        why = (
            "no joint rates give the twist within the position and rate limits "
            f"(exact=True; {_describe_limits(lower, upper)})"
            if flag == -1
            else f"the QP solver DAQP stopped with exit flag {flag}"
        )
        return _infeasible(n, V, why)
    dq = np.asarray(dq, dtype=float)
    error, tracked = _tracking(J, dq, V)
    limited = _named(dq, v, lower, upper)
    reason = None
    if not tracked:
        reason = f"J dq misses the twist by {error:.3g}: the step meets " + (
            ", ".join(limited) if limited else "no limit (a singular or damped J)"
        )
    return Step(dq, True, tracked, error, limited, reason, "qp")


def _describe_limits(lower, upper):
    """The box on dq in a sentence (for a reason)."""
    pairs = ", ".join(f"[{a:.3g}, {b:.3g}]" for a, b in zip(lower, upper))
    return f"dq within {pairs}"


def _infeasible(n, V, reason):
    return Step(
        np.full(n, np.nan), False, False, float(np.linalg.norm(V)), (), reason, "qp"
    )
