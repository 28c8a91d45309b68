"""Redundancy resolution for planar arms: paths, resolved-rate IK with the
pseudo-inverse, and null-space motion that climbs the gradient of Yoshikawa's
manipulability.

A planar arm (``sk.robots.planar(lengths)``) has n joints and a 2D task, the point
(x, y); with n > 2 it is redundant, and the joint rates

    qdot = J+ (xdot_d + K e) + k (I - J+ J) grad w,       J+ = J^T (J J^T)^-1,

follow the path (first term; K e corrects the drift of Euler integration) and, without
disturbing the end effector, move the arm so that w = sqrt(det(J J^T)) grows
(second term). Lengths in metres, angles in radians, time in seconds. The smooth
timing is the quintic of :mod:`screwkit.motion.trajectory`, and J+ the damped
pseudo-inverse of :mod:`screwkit.motion.differential_ik`.

>>> import numpy as np, screwkit as sk
>>> arm = sk.robots.planar([0.4, 0.3, 0.2])
>>> path = circle((0.5, 0.1), 0.1, duration=5.0, dt=0.01)
>>> q0 = start_configuration(arm, path.position[0], [0.3, 0.6, 0.6])
>>> run = resolve(arm, path, q0, null_space_gain=1.0)
>>> bool(run.error.max() < 1e-4), run.q.shape
(True, (501, 3))
"""

import functools
from dataclasses import dataclass

import numpy as np

from ._checks import (
    as_float_array,
    as_real_scalar,
    check_chain,
    check_integer,
    check_option,
    check_positive,
    describe,
)
from ._docstrings import fill
from .chains import Joint
from .motion.differential_ik import _damped_pseudo_inverse
from .motion.trajectory import quintic
from .tolerances import (
    LIMIT_MARGIN,
    PATH_START_TOL,
    POSITION_TOL,
    SINGULAR_REGION,
    START_DAMPING,
    STEP_TOL,
    length_scale,
)

__all__ = [
    "Path",
    "circle",
    "line",
    "timing",
    "planar_kinematics",
    "manipulability_gradient",
    "pseudo_inverse",
    "start_configuration",
    "Resolution",
    "resolve",
]


# ---- paths ---------------------------------------------------------------------------


@dataclass(frozen=True)
class Path:
    """A sampled path of the end effector.

    The samples are uniform in time (Euler steps of one dt), at least two, and the
    arrays are copied, so changing the caller's arrays later does not change the path.

    Parameters
    ----------
    t : ndarray, shape (steps,)
        The sample times (s).
    position : ndarray, shape (steps, 2)
        The points (m).
    velocity : ndarray, shape (steps, 2)
        Their velocities (m/s).
    name : str
        Used in titles.

    Examples
    --------
    A 0.2 m line up the line x = 0.5 in 1 s, sampled every 0.25 s (smooth timing,
    so the middle sample is at the middle):

    >>> path = line((0.5, 0.0), (0.5, 0.2), duration=1.0, dt=0.25)
    >>> path.t.tolist(), path.dt
    ([0.0, 0.25, 0.5, 0.75, 1.0], 0.25)
    >>> path.position[[0, 2, 4]].round(12).tolist()
    [[0.5, 0.0], [0.5, 0.1], [0.5, 0.2]]
    """

    t: np.ndarray
    position: np.ndarray
    velocity: np.ndarray
    name: str = "path"

    def __post_init__(self):
        t = np.array(as_float_array(self.t, "t"))
        if t.ndim != 1 or t.size < 2:
            raise ValueError(
                "t must be a 1-D array of at least two sample times (s), got shape "
                f"{t.shape}"
            )
        steps = np.diff(t)
        dt = steps[0]
        if dt <= 0:
            raise ValueError(
                f"t must increase: the time step dt must be positive, got dt = {dt!r} s"
            )
        if not np.allclose(steps, dt, rtol=STEP_TOL, atol=0):
            worst = int(np.argmax(np.abs(steps - dt)))
            raise ValueError(
                f"t must be uniform (one time step dt = {dt:.6g} s), but the step "
                f"after sample {worst} is {steps[worst]:.6g} s"
            )
        for field in ("position", "velocity"):
            array = np.array(as_float_array(getattr(self, field), field))
            if array.shape != (t.size, 2):
                raise ValueError(
                    f"{field} must have shape ({t.size}, 2), one planar point per "
                    f"sample of t, got shape {array.shape}"
                )
            object.__setattr__(self, field, array)
        if not isinstance(self.name, str):
            raise TypeError(f"name must be a string, got {describe(self.name)}")
        object.__setattr__(self, "t", t)

    @property
    def dt(self):
        """The time step (s) between samples."""
        return float(self.t[1] - self.t[0])


def timing(t, duration, kind="smooth"):
    """The path parameter s(t) in [0, 1] and its rate ds/dt.

    Parameters
    ----------
    t : float or array-like
        Times (s) in [0, duration].
    duration : float
        The path's duration (s), positive.
    kind : {'smooth', 'constant'}, optional
        'smooth': the quintic s = 10 u^3 - 15 u^4 + 6 u^5 (u = t / duration), which
        starts and ends at rest with zero acceleration; 'constant': s = u.

    Returns
    -------
    s, ds_dt : ndarray, shaped like t
        The parameter (no unit) and its rate (1/s).

    Examples
    --------
    The smooth timing starts and ends at rest and peaks at 15/8 per duration:

    >>> s, ds_dt = timing([0.0, 0.5, 1.0], 1.0)
    >>> s.tolist(), ds_dt.tolist()
    ([0.0, 0.5, 1.0], [0.0, 1.875, 0.0])
    >>> timing(0.5, 1.0, "constant")[1].tolist()
    1.0
    """
    kind = check_option(kind, "kind", ("smooth", "constant"))
    duration = check_positive(duration, "duration")
    t = as_float_array(t, "t")
    if t.size and (t.min() < 0 or t.max() > duration * (1 + STEP_TOL)):
        raise ValueError(
            f"t must lie in [0, duration] = [0, {duration:g}] s, "
            f"got values from {t.min():g} to {t.max():g} s"
        )
    if kind == "smooth":  # the quintic of the trajectories; a last sample rounded
        # past the duration is its end
        s, ds, _ = quintic(duration).evaluate(np.minimum(t, duration))
        return s, ds
    return t / duration, np.full_like(t, 1.0 / duration)


#: The most time steps a path may have (its arrays then take about 0.5 GB).
MAX_SAMPLES = 10_000_000


def _samples(duration, dt):
    duration = check_positive(duration, "duration")
    dt = check_positive(dt, "dt")
    if duration / dt > MAX_SAMPLES:
        raise ValueError(
            f"duration / dt must be at most {MAX_SAMPLES:,} steps, got "
            f"{duration / dt:.3g} (duration={duration} s, dt={dt} s); use a larger dt"
        )
    steps = int(round(duration / dt))
    if steps < 1 or not np.isclose(steps * dt, duration, rtol=STEP_TOL, atol=0):
        raise ValueError(
            f"duration must be a whole number of steps dt, got duration={duration} and "
            f"dt={dt}"
        )
    return np.arange(steps + 1) * dt, duration


def _path_sections(shape):
    """The timing parameters and the Returns section of a path of this shape."""
    return f"""duration : float
    The time to go along the {shape} (s).
dt : float
    The time step (s).
timing_kind : {{'smooth', 'constant'}}, optional
    The timing along the {shape} (see :func:`timing`).

Returns
-------
Path
    The sampled {shape}."""


@fill(sections=_path_sections("circle"))
def circle(center, radius, duration, dt, timing_kind="smooth"):
    """A circle once counter-clockwise, from center + (radius, 0).

    Parameters
    ----------
    center : array-like, shape (2,)
        The centre (m).
    radius : float
        The radius (m), positive.
    {sections}

    Examples
    --------
    The unit circle at constant speed, sampled each quarter of its duration:

    >>> path = circle((0, 0), 1.0, duration=1.0, dt=0.25, timing_kind="constant")
    >>> (path.position.round(12) + 0.0).tolist()
    [[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0], [1.0, 0.0]]
    """
    check_option(timing_kind, "timing_kind", ("smooth", "constant"))
    center = _point(center, "center")
    radius = check_positive(radius, "radius")
    t, duration = _samples(duration, dt)
    s, ds = timing(t, duration, timing_kind)
    angle = 2 * np.pi * s
    direction = np.stack([np.cos(angle), np.sin(angle)], axis=-1)
    tangent = np.stack([-np.sin(angle), np.cos(angle)], axis=-1)
    return Path(
        t,
        center + radius * direction,
        (2 * np.pi * radius * ds)[:, None] * tangent,
        "circle",
    )


@fill(sections=_path_sections("line"))
def line(start, end, duration, dt, timing_kind="smooth"):
    """A straight line from ``start`` to ``end``.

    Parameters
    ----------
    start, end : array-like, shape (2,)
        The end points (m).
    {sections}

    Examples
    --------
    1 m in 2 s at constant speed: 0.5 m/s all along.

    >>> path = line((0, 0), (1, 0), duration=2.0, dt=1.0, timing_kind="constant")
    >>> path.position.tolist(), path.velocity.tolist()
    ([[0.0, 0.0], [0.5, 0.0], [1.0, 0.0]], [[0.5, 0.0], [0.5, 0.0], [0.5, 0.0]])
    """
    check_option(timing_kind, "timing_kind", ("smooth", "constant"))
    start, end = _point(start, "start"), _point(end, "end")
    if np.allclose(start, end):
        raise ValueError(f"start and end must differ, got {start.tolist()} twice")
    t, duration = _samples(duration, dt)
    s, ds = timing(t, duration, timing_kind)
    return Path(
        t, start + s[:, None] * (end - start), ds[:, None] * (end - start), "line"
    )


def _point(value, name):
    point = as_float_array(value, name)
    if point.shape != (2,):
        raise ValueError(
            f"{name} must be a planar point (x, y), shape (2,), got shape {point.shape}"
        )
    return point


# ---- planar kinematics ---------------------------------------------------------------


def _lengths(arm):
    """The link lengths of a planar arm (a Chain of revolute links with d = 0 and
    alpha = 0)."""
    check_chain(arm, "arm")
    try:
        planar = all(
            link.joint is Joint.REVOLUTE
            and float(link.d) == 0
            and float(link.alpha) == 0
            and float(link.offset) == 0
            for link in arm.links
        )
        lengths = np.array([float(link.a) for link in arm.links])
    except (TypeError, ValueError):  # a symbolic link length
        planar = False
    if not planar or not np.allclose(arm.tool, np.eye(4)):
        raise ValueError(
            "arm must be a planar arm of revolute links about z (sk.robots.planar), "
            f"got {arm!r}"
        )
    return lengths


def _base_2d(arm):
    """The arm's base as a planar rotation (2, 2) and origin (2,); an error if it is not
    planar."""
    B = arm.base
    if not (np.allclose(B[2], [0, 0, 1, 0]) and np.allclose(B[:2, 2], 0)):
        raise ValueError(
            "arm.base must be a rotation about z and a translation in the x-y plane"
        )
    return B[:2, :2], B[:2, 3]


#: The parameters of a planar arm's kinematics (filled in by _docstrings.fill).
_LENGTHS_Q = """lengths : array-like, shape (n,)
    The link lengths (m).
q : array-like, shape (n,) or (N, n)
    Joint angles (rad)."""


@fill(lengths_q=_LENGTHS_Q)
def planar_kinematics(lengths, q):
    """Joint positions and the end-effector Jacobian of a planar arm in its own base
    frame.

    Column i of J is z x (p - o_i).

    Parameters
    ----------
    {lengths_q}

    Returns
    -------
    points : ndarray, shape (n + 1, 2) or (N, n + 1, 2)
        The base, each joint and the end effector (m).
    J : ndarray, shape (2, n) or (N, 2, n)
        The planar Jacobian (m/rad).

    Examples
    --------
    Two unit links, the elbow at a right angle: the elbow at (1, 0), the tip at
    (1, 1); column i is z x (tip - joint i).

    >>> points, J = planar_kinematics([1.0, 1.0], [0.0, np.pi / 2])
    >>> (points.round(12) + 0.0).tolist(), (J.round(12) + 0.0).tolist()
    ([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]], [[-1.0, -1.0], [1.0, 0.0]])
    """
    lengths, q = _lengths_and_q(lengths, q)
    angles = np.cumsum(q, axis=-1)
    links = lengths[:, None] * np.stack([np.cos(angles), np.sin(angles)], axis=-1)
    points = np.concatenate(
        [np.zeros(links.shape[:-2] + (1, 2)), np.cumsum(links, axis=-2)], axis=-2
    )
    r = points[..., -1:, :] - points[..., :-1, :]  # from each joint to the end effector
    J = np.stack([-r[..., 1], r[..., 0]], axis=-2)
    return points, J


@fill(lengths_q=_LENGTHS_Q)
def manipulability_gradient(lengths, q):
    """w = sqrt(det(J J^T)) of a planar arm and its exact gradient dw/dq.

    By Cauchy-Binet, w^2 = sum over i < j of m_ij^2 with m_ij = r_i x r_j, r_i the
    vector from joint i to the end effector. Turning joint k rotates r_i by
    z x r_max(i,k), so dm_ij/dq_k = r_i . r_max(j,k) - r_max(i,k) . r_j, and
    dw/dq_k = sum_ij m_ij dm_ij/dq_k / (2 w). Where w = 0 the gradient is returned as 0.

    Parameters
    ----------
    {lengths_q}

    Returns
    -------
    w : float or ndarray, shape (N,)
        The manipulability.
    gradient : ndarray, shape (n,) or (N, n)
        dw/dq.

    Examples
    --------
    For two links w = l1 l2 sin(q2), whose gradient is (0, l1 l2 cos(q2)): at
    q2 = 60 deg, w = 0.866 and the gradient (0, 0.5).

    >>> w, gradient = manipulability_gradient([1.0, 1.0], [0.0, np.pi / 3])
    >>> round(float(w), 4), (gradient.round(4) + 0.0).tolist()
    (0.866, [0.0, 0.5])
    """
    return _gradient(planar_kinematics(lengths, q)[0])


def _lengths_and_q(lengths, q):
    lengths = as_float_array(lengths, "lengths")
    if lengths.ndim != 1 or lengths.size < 1:
        raise ValueError(
            "lengths must be a 1-D array of link lengths (m), got shape "
            f"{lengths.shape}"
        )
    if np.any(lengths < 0):
        raise ValueError(f"lengths must be >= 0 (m), got {lengths.tolist()}")
    q = as_float_array(q, "q")
    if q.ndim not in (1, 2) or q.shape[-1] != lengths.size:
        raise ValueError(
            f"q must have {lengths.size} entries, one per length, shape "
            f"({lengths.size},) or (N, {lengths.size}), got shape {q.shape}"
        )
    return lengths, q


def _gradient(points):
    """w and dw/dq from the joint positions (..., n + 1, 2) of planar_kinematics."""
    r = points[..., -1:, :] - points[..., :-1, :]
    n = r.shape[-2]
    G = r @ np.swapaxes(r, -1, -2)  # r_i . r_j
    M = (
        r[..., :, None, 0] * r[..., None, :, 1]
        - r[..., :, None, 1] * r[..., None, :, 0]
    )  # r_i x r_j
    first, second = _gradient_indices(n)
    dM = G[(Ellipsis, *first)] - G[(Ellipsis, *second)]  # (..., k, i, j)
    w2 = 0.5 * np.sum(M**2, axis=(-1, -2))
    w = np.sqrt(w2)
    dw2 = np.sum(
        M[..., None, :, :] * dM, axis=(-1, -2)
    )  # d(w^2)/dq_k = sum_ij m_ij dm_ij
    with np.errstate(divide="ignore", invalid="ignore"):
        gradient = np.where(w[..., None] > 0, dw2 / (2 * w[..., None]), 0.0)
    return w[()], gradient


@functools.cache
def _gradient_indices(n):
    """Index pairs (i, max(j, k)) and (max(i, k), j) over (k, i, j), as flat indices
    into G (n, n)."""
    k, i, j = np.meshgrid(np.arange(n), np.arange(n), np.arange(n), indexing="ij")
    return (i, np.maximum(j, k)), (np.maximum(i, k), j)


def pseudo_inverse(J, damping=0.0, singular_region=SINGULAR_REGION):
    """J+ = J^T (J J^T + lambda^2 I)^-1 for J (2, n).

    lambda = 0 (the exact Moore-Penrose inverse of a full-rank J) unless
    ``damping`` > 0, then lambda^2 = damping^2 (1 - (sigma_min / singular_region)^2)
    inside the singular region sigma_min < singular_region (m): damped least squares
    that fades in near a singularity.

    Parameters
    ----------
    J : array-like, shape (2, n)
        A planar Jacobian.
    damping : float, optional
        The damping (m), >= 0.
    singular_region : float, optional
        The smallest singular value (m) below which damping fades in.

    Returns
    -------
    ndarray, shape (n, 2)
        J+.

    Examples
    --------
    A square, invertible J has J+ = J^-1:

    >>> J = [[-1.0, -1.0], [1.0, 0.0]]
    >>> (pseudo_inverse(J).round(12) + 0.0).tolist()
    [[0.0, 1.0], [-1.0, -1.0]]
    """
    J = as_float_array(J, "J")
    if J.ndim != 2 or J.shape[0] != 2 or J.shape[1] < 1:
        raise ValueError(
            f"J must be a planar Jacobian of shape (2, n), got shape {J.shape}"
        )
    damping = check_positive(damping, "damping", allow_zero=True)
    singular_region = check_positive(singular_region, "singular_region")
    damping_squared = 0.0
    if damping > 0:
        A = J @ J.T
        half_trace, det = (
            0.5 * (A[0, 0] + A[1, 1]),
            A[0, 0] * A[1, 1] - A[0, 1] * A[1, 0],
        )
        sigma_min2 = half_trace - np.sqrt(max(half_trace**2 - det, 0.0))
        if sigma_min2 < singular_region**2:
            damping_squared = damping**2 * (1 - sigma_min2 / singular_region**2)
    return _damped_pseudo_inverse(J, damping_squared)


# ---- resolution ----------------------------------------------------------------------


def start_configuration(arm, point, q_guess, tol=None, max_iterations=100):
    """Joint angles that put the end effector at ``point``.

    Newton steps with the pseudo-inverse from ``q_guess``: the nearest solution to the
    guess, roughly. A point out of reach, or one not reached in time, is a ValueError
    with the residual.

    Parameters
    ----------
    arm : Chain
        A planar arm (:func:`screwkit.robots.planar`).
    point : array-like, shape (2,)
        The target (m).
    q_guess : array-like, shape (n,)
        The first guess (rad).
    tol : float, optional
        The distance accepted (m); by default ``POSITION_TOL`` times the longest
        link.
    max_iterations : int, optional
        The Newton steps allowed (>= 1).

    Returns
    -------
    ndarray, shape (n,)
        The joint angles (rad).

    Examples
    --------
    Two unit links reach (1, 1) with the shoulder at 0 and the elbow at 90 deg:

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> start_configuration(arm, (1.0, 1.0), [0.1, 1.4]).round(4) + 0.0
    array([0.    , 1.5708])
    """
    lengths = _lengths(arm)
    q = np.array(arm.check_one(q_guess, "q_guess"))  # a copy: the caller's array stays
    point = _point(point, "point")
    if tol is None:
        tol = POSITION_TOL * length_scale(lengths)
    tol = check_positive(tol, "tol")
    max_iterations = check_integer(max_iterations, "max_iterations", minimum=1)
    R, origin = _base_2d(arm)
    target = R.T @ (point - origin)
    for _ in range(max_iterations + 1):
        points, J = planar_kinematics(lengths, q)
        error = np.linalg.norm(target - points[-1])
        if error < tol:
            return q
        q += pseudo_inverse(J, damping=START_DAMPING) @ (target - points[-1])
    raise ValueError(
        f"point must be reachable from q_guess: no configuration found that reaches "
        f"point {np.round(point, 6).tolist()} in {max_iterations} iterations, got a "
        f"residual of {error:.3g} m"
    )


@dataclass(frozen=True)
class Resolution:
    """The result of :func:`resolve`; row i belongs to the path's sample i.

    Parameters
    ----------
    t : ndarray, shape (steps,)
        Times (s).
    q : ndarray, shape (steps, n)
        Joint angles (rad).
    position : ndarray, shape (steps, 2)
        The end effector in the world frame (m).
    error : ndarray, shape (steps,)
        Its distance from the path (m).
    manipulability : ndarray, shape (steps,)
        sqrt(det(J J^T)) at q.
    limited : ndarray of bool, shape (steps,)
        True where a joint limit clamped the step that led to row i.
    path : Path
        The path followed.

    Examples
    --------
    >>> import screwkit as sk
    >>> arm = sk.robots.planar([0.4, 0.3, 0.2])
    >>> path = line((0.5, 0.0), (0.5, 0.3), duration=1.0, dt=0.01)
    >>> q0 = start_configuration(arm, path.position[0], [0.3, 0.6, 0.6])
    >>> run = resolve(arm, path, q0)
    >>> run.q.shape, bool(run.error.max() < 1e-3), bool(run.limited.any())
    ((101, 3), True, False)
    """

    t: np.ndarray
    q: np.ndarray
    position: np.ndarray
    error: np.ndarray
    manipulability: np.ndarray
    limited: np.ndarray
    path: Path


def resolve(
    arm,
    path,
    q0,
    null_space_gain=0.0,
    feedback_gain=50.0,
    damping=0.0,
    joint_limits=None,
    limit_gain=0.1,
    max_rate=5.0,
    start_tolerance=PATH_START_TOL,
):
    """Follow ``path`` with the end effector of the planar ``arm`` from ``q0`` (n,).

    Euler steps q_{k+1} = q_k + qdot dt with qdot = J+ (xdot_d + K e) + (I - J+ J) phi,
    where K = ``feedback_gain`` (1/s; K dt < 2 for stability), e the position error, and
    phi = ``null_space_gain`` * grad w (thesis eqs. 2.37-2.38). ``damping`` > 0 uses
    damped least squares near singularities (see :func:`pseudo_inverse`).

    A path that leaves the reachable annulus, a q0 of the wrong length, or a q0 whose
    end effector is more than ``start_tolerance`` (m) from the path's start is refused
    with a ValueError; so is a q0 outside the arm's joint limits when ``joint_limits``
    is 'clamp' or 'avoid'.

    Parameters
    ----------
    arm : Chain
        A planar arm (:func:`screwkit.robots.planar`).
    path : Path
        The path to follow.
    q0 : array-like, shape (n,)
        The start (rad).
    null_space_gain : float, optional
        Of either sign (negative lowers w).
    feedback_gain : float, optional
        K (1/s), >= 0.
    damping : float, optional
        >= 0 (m); see :func:`pseudo_inverse`.
    joint_limits : {None, 'clamp', 'avoid'}, optional
        None: ignored; 'clamp': the arm's qlim cut the step (the end effector then
        leaves the path); 'avoid': clamp, and subtract limit_gain * grad H from phi,
        with H = sum (q_max - q_min)^2 / (4 (q_max - q)(q - q_min)), which is 1 per
        joint at mid-range and grows without bound at a limit: the null space pushes
        joints away from their limits.
    limit_gain : float, optional
        The gain of grad H, >= 0.
    max_rate : float, optional
        The cap on the length of the limits' push (rad/s), positive.
    start_tolerance : float, optional
        The distance (m) allowed between q0's end effector and the path's start.

    Returns
    -------
    Resolution
        The joint path and its errors, one row per sample of the path.

    Examples
    --------
    A 3R arm on a line: with a positive null-space gain it ends the path more
    manipulable than without, on the same path.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([0.4, 0.3, 0.2])
    >>> path = line((0.5, 0.0), (0.5, 0.3), duration=1.0, dt=0.01)
    >>> q0 = start_configuration(arm, path.position[0], [0.3, 0.6, 0.6])
    >>> plain, climbing = resolve(arm, path, q0), resolve(arm, path, q0, 1.0)
    >>> bool(climbing.manipulability[-1] > plain.manipulability[-1])
    True
    >>> bool(plain.error.max() < 1e-3), bool(climbing.error.max() < 1e-3)
    (True, True)
    """
    lengths = _lengths(arm)
    if not isinstance(path, Path):
        raise TypeError(
            f"path must be a Path (from circle or line), got {describe(path)}"
        )
    q = arm.check_one(q0, "q0")
    joint_limits = check_option(joint_limits, "joint_limits", (None, "clamp", "avoid"))
    null_space_gain = as_real_scalar(null_space_gain, "null_space_gain")
    feedback_gain = check_positive(feedback_gain, "feedback_gain", allow_zero=True)
    damping = check_positive(damping, "damping", allow_zero=True)
    limit_gain = check_positive(limit_gain, "limit_gain", allow_zero=True)
    max_rate = check_positive(max_rate, "max_rate")
    start_tolerance = check_positive(start_tolerance, "start_tolerance")
    dt = path.dt
    if not feedback_gain * dt < 2:
        raise ValueError(
            "feedback_gain * dt must be in [0, 2) for a stable loop, got "
            f"{feedback_gain} * {dt}"
        )
    if joint_limits is not None and not arm.within_limits(q):
        outside = [
            i for i in range(arm.n) if not arm.qlim[i, 0] <= q[i] <= arm.qlim[i, 1]
        ]
        i = outside[0]
        raise ValueError(
            "q0 must lie within the arm's joint limits when "
            f"joint_limits={joint_limits!r}, but joint {i + 1} is {q[i]:.4f} rad, "
            f"outside [{arm.qlim[i, 0]:.4f}, {arm.qlim[i, 1]:.4f}]"
        )
    R, origin = _base_2d(arm)
    target = (path.position - origin) @ R  # the path in the arm's base frame
    velocity = path.velocity @ R
    _check_reachable(lengths, target, path)
    start = planar_kinematics(lengths, q)[0][-1]
    if np.linalg.norm(start - target[0]) > start_tolerance:
        raise ValueError(
            "q0 must put the end effector within start_tolerance = "
            f"{start_tolerance} m of the path's start "
            f"{np.round(path.position[0], 4).tolist()}, got "
            f"{np.round(start @ R.T + origin, 4).tolist()} m, "
            f"{np.linalg.norm(start - target[0]):.4f} m from the path's start; "
            "use start_configuration(arm, path.position[0], q_guess)"
        )
    low, high = arm.qlim[:, 0], arm.qlim[:, 1]
    finite = np.isfinite(low) & np.isfinite(high)

    steps = len(path.t)
    Q = np.empty((steps, arm.n))
    limited = np.zeros(steps, dtype=bool)
    identity = np.eye(arm.n)
    Q[0] = q
    for k in range(steps - 1):
        points, J = planar_kinematics(lengths, q)
        J_plus = pseudo_inverse(J, damping)
        qdot = J_plus @ (velocity[k] + feedback_gain * (target[k] - points[-1]))
        phi = 0.0
        if null_space_gain:
            phi = null_space_gain * _gradient(points)[1]
        if joint_limits == "avoid":
            push = limit_gain * _limit_gradient(q, low, high, finite)
            size = np.linalg.norm(push)
            # the barrier's gradient is unbounded at a limit, an Euler step must not be:
            # cap its length (not its entries, which would turn it away from the descent
            # direction)
            phi = phi - (push if size <= max_rate else push * (max_rate / size))
        if null_space_gain or joint_limits == "avoid":
            qdot = qdot + (identity - J_plus @ J) @ phi
        q = q + qdot * dt
        if joint_limits is not None:
            clipped = np.clip(q, low, high)
            limited[k + 1] = np.any(clipped != q)
            q = clipped
        Q[k + 1] = q
    points, _ = planar_kinematics(lengths, Q)
    w, _ = _gradient(points)
    position = points[:, -1] @ R.T + origin
    return Resolution(
        path.t,
        Q,
        position,
        np.linalg.norm(position - path.position, axis=-1),
        w,
        limited,
        path,
    )


def _limit_gradient(q, low, high, finite):
    """grad H of H = sum (q_max - q_min)^2 / (4 (q_max - q)(q - q_min)) over joints with
    finite limits."""
    low, high = np.where(finite, low, -1.0), np.where(finite, high, 1.0)
    inside = np.clip(q, low + LIMIT_MARGIN, high - LIMIT_MARGIN)
    gradient = (
        (high - low) ** 2
        * (2 * inside - high - low)
        / (4 * (high - inside) ** 2 * (inside - low) ** 2)
    )
    return np.where(finite, gradient, 0.0)


def _check_reachable(lengths, target, path):
    """Refuse a path that leaves the annulus r_min <= |p| <= r_max around the arm's
    base."""
    outer = lengths.sum()
    inner = max(0.0, 2 * lengths.max() - outer)
    radius = np.linalg.norm(target, axis=-1)
    outside = np.flatnonzero((radius > outer) | (radius < inner))
    if outside.size:
        i = outside[0]
        raise ValueError(
            f"path must stay in the reachable annulus {inner:.4f} m <= |p| <= "
            f"{outer:.4f} m around the arm's base, got {outside.size} of {len(radius)} "
            "samples outside it (the path leaves the reachable annulus), the first at "
            f"t = {path.t[i]:.3f} s, point {np.round(path.position[i], 4).tolist()} m, "
            f"|p| = {radius[i]:.4f} m"
        )
