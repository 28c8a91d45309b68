"""Trajectories: time scalings, joint-space motions, screw and Cartesian paths, slerp.

A trajectory is a path and a time scaling (Lynch and Park, ch. 9): the path X(s) runs
from s = 0 to s = 1, the scaling s(t) says how fast.

* time scalings: :func:`cubic`, :func:`quintic` (rest to rest) and :func:`trapezoidal`
  (constant acceleration, cruise, constant deceleration), each given a duration or
  the fastest under velocity and acceleration limits on s;
  :func:`fastest_joint_scaling` turns joint limits into limits on s;
* paths: :func:`joint_path` (straight in joint space), :func:`screw_path`
  (T0 exp(log(T0^-1 T1) s), the straight line of SE(3): one constant twist),
  :func:`cartesian_path` (the position on a straight line, the rotation by slerp), both
  for SE(3) (4 x 4) and SE(2) (3 x 3) poses; :func:`slerp` of unit quaternions;
* :func:`via_points`: cubic pieces through points at given times, velocity continuous;
* :func:`follow_path`: a path of poses through the inverse kinematics, the branch held
  continuous and the near-singular samples named.

Every function is batched over samples: s or t of shape (K,) gives (K, 4, 4) poses or
(K, n) joint vectors.

>>> import numpy as np
>>> scaling = quintic(2.0)
>>> s, ds, dds = scaling.evaluate([0.0, 1.0, 2.0])
>>> s.tolist(), ds.tolist()
([0.0, 0.5, 1.0], [0.0, 0.9375, 0.0])
"""

from dataclasses import dataclass

import numpy as np

from .. import ik
from .._checks import (
    as_float_array,
    check_chain,
    check_option,
    check_poses,
    check_result_bytes,
    check_rotation,
    describe,
    quoted,
)
from .._docstrings import fill
from ..lie import log_rotation, log_transform
from ..links import Joint
from ..tolerances import NEAR_SINGULAR, SERIES_BELOW, SLERP_LINEAR_BELOW
from ..transforms import _wrap_angle, exp_twist
from . import LAZY

# the names are listed once, in the family's table of what loads on first use
__all__ = list(LAZY["trajectory"])


# ---- time scalings ------------------------------------------------------------------


def _limit(value, name):
    """A positive limit (or None)."""
    if value is None:
        return None
    number = as_float_array(value, name)
    if number.ndim != 0:
        raise ValueError(f"{name} must be one number, got shape {number.shape}")
    if not number > 0:
        raise ValueError(f"{name} must be a positive number, got {float(number)!r}")
    return float(number)


#: Peak ds/dt times T and peak abs(d2s/dt2) times T^2 of each polynomial scaling:
#: cubic 3/2 and 6; quintic 15/8 and 10/sqrt(3) (at tau = 1/2 -+ sqrt(3)/6).
PEAKS = {"cubic": (1.5, 6.0), "quintic": (15 / 8, 10 / np.sqrt(3))}


@dataclass(frozen=True)
class TimeScaling:
    """A time scaling s(t) from s(0) = 0 to s(duration) = 1, at rest at both ends.

    Build one with :func:`cubic`, :func:`quintic` or :func:`trapezoidal`.

    Parameters
    ----------
    kind : {'cubic', 'quintic', 'trapezoidal'}
        The profile.
    duration : float
        Its duration (s).
    peak_velocity : float
        The largest ds/dt (1/s).
    peak_acceleration : float
        The largest magnitude of d2s/dt2 (1/s^2).

    Examples
    --------
    A quintic over 2 s peaks at ds/dt = 15/8 / 2 = 0.9375 per second, half-way:

    >>> scaling = quintic(2.0)
    >>> scaling.kind, scaling.duration, scaling.peak_velocity
    ('quintic', 2.0, 0.9375)
    """

    kind: str
    duration: float
    peak_velocity: float
    peak_acceleration: float

    def _times(self, t):
        t = as_float_array(t, "t")
        if np.any(t < 0) or np.any(t > self.duration):
            bad = t[(t < 0) | (t > self.duration)].ravel()[0]
            raise ValueError(
                f"t must lie in [0, {self.duration:g}] s (the scaling's duration), "
                f"got {bad!r}"
            )
        return t

    def evaluate(self, t):
        """s, ds/dt and d2s/dt2 at the times t.

        Parameters
        ----------
        t : float or array-like, shape (K,), in [0, duration] (s)

        Returns
        -------
        (s, ds, dds) : three ndarrays of t's shape (1, 1/s, 1/s^2)

        Examples
        --------
        The cubic over 1 s, s = 3 t^2 - 2 t^3: ds = 6 t - 6 t^2, dds = 6 - 12 t.

        >>> s, ds, dds = cubic(1.0).evaluate([0.0, 0.5, 1.0])
        >>> s.tolist(), ds.tolist(), dds.tolist()
        ([0.0, 0.5, 1.0], [0.0, 1.5, 0.0], [6.0, 0.0, -6.0])
        """
        t = self._times(t)
        T = self.duration
        if self.kind == "trapezoidal":
            return self._trapezoid(t)
        tau = t / T
        if self.kind == "cubic":
            s = tau**2 * (3 - 2 * tau)
            ds = 6 * tau * (1 - tau) / T
            dds = (6 - 12 * tau) / T**2
        else:
            s = tau**3 * (10 - 15 * tau + 6 * tau**2)
            ds = 30 * tau**2 * (1 - tau) ** 2 / T
            dds = 60 * tau * (1 - tau) * (1 - 2 * tau) / T**2
        return s, ds, dds

    def _trapezoid(self, t):
        v, a, T = self.peak_velocity, self.peak_acceleration, self.duration
        ramp = v / a
        rising, falling = t <= ramp, t >= T - ramp
        s = np.where(
            rising,
            a * t**2 / 2,
            np.where(falling, 1 - a * (T - t) ** 2 / 2, v * t - v**2 / (2 * a)),
        )
        ds = np.where(rising, a * t, np.where(falling, a * (T - t), v))
        dds = np.where(rising, a, np.where(falling, -a, 0.0))
        # the instant of the switch itself belongs to the ramp's end value
        dds = np.where((t == ramp) & (t == T - ramp), 0.0, dds)
        return s, ds, dds

    def __call__(self, t):
        """s(t), of t's shape."""
        return self.evaluate(t)[0]

    def times(self, count):
        """Equally spaced times from 0 to the duration.

        Parameters
        ----------
        count : int
            How many (at least 2).

        Returns
        -------
        ndarray, shape (count,)
            The times (s).

        Examples
        --------
        >>> quintic(2.0).times(5)
        array([0. , 0.5, 1. , 1.5, 2. ])
        """
        if isinstance(count, bool) or not isinstance(count, (int, np.integer)):
            raise TypeError(f"count must be an integer, got {describe(count)}")
        if count < 2:
            raise ValueError(f"count must be at least 2, got {quoted(count)}")
        check_result_bytes(
            8 * count, f"count={quoted(count)} times", "ask for fewer times"
        )
        return np.linspace(0.0, self.duration, count)


def _polynomial(kind, duration, v_max, a_max):
    v_max, a_max = _limit(v_max, "v_max"), _limit(a_max, "a_max")
    peak_v, peak_a = PEAKS[kind]
    needed = [0.0]
    if v_max is not None:
        needed.append(peak_v / v_max)
    if a_max is not None:
        needed.append(np.sqrt(peak_a / a_max))
    fastest = max(needed)
    if duration is None:
        if v_max is None and a_max is None:
            raise ValueError(
                f"a {kind} scaling needs a duration or a limit (v_max, a_max), got none"
            )
        duration = fastest
    else:
        duration = _limit(duration, "duration")
        if duration < fastest:
            raise ValueError(
                f"duration must be at least the {fastest:g} s that v_max and a_max "
                f"allow for a {kind} scaling, got {duration:g} s"
            )
    return TimeScaling(kind, duration, peak_v / duration, peak_a / duration**2)


#: The sections cubic and quintic share (filled in by :func:`_docstrings.fill`).
_POLYNOMIAL_SECTIONS = """Parameters
----------
duration : float, s; None for the shortest that the limits allow
v_max : float, optional, the largest ds/dt allowed (1/s)
a_max : float, optional, the largest magnitude of d2s/dt2 allowed
    (1/s^2)

Returns
-------
TimeScaling"""


@fill(sections=_POLYNOMIAL_SECTIONS)
def cubic(duration=None, *, v_max=None, a_max=None):
    """The cubic time scaling s = 3 tau^2 - 2 tau^3, tau = t / duration.

    {sections}

    Examples
    --------
    Its peak ds/dt is 3 / (2 T): a limit of 0.75 per second needs T = 2 s.

    >>> cubic(v_max=0.75).duration
    2.0
    """
    return _polynomial("cubic", duration, v_max, a_max)


@fill(sections=_POLYNOMIAL_SECTIONS)
def quintic(duration=None, *, v_max=None, a_max=None):
    """The quintic time scaling s = 10 tau^3 - 15 tau^4 + 6 tau^5 (zero velocity and
    acceleration at both ends).

    {sections}

    Examples
    --------
    Half-way s = 1/2 and ds/dt peaks at 15 / (8 T); the ends are at rest:

    >>> s, ds, dds = quintic(1.0).evaluate([0.0, 0.5, 1.0])
    >>> s.tolist(), ds.tolist(), (dds + 0.0).tolist()
    ([0.0, 0.5, 1.0], [0.0, 1.875, 0.0], [0.0, 0.0, 0.0])
    """
    return _polynomial("quintic", duration, v_max, a_max)


def trapezoidal(duration=None, *, v_max=None, a_max=None):
    """The trapezoidal velocity profile: accelerate at a, cruise at v, decelerate.

    Give two of the three: (v_max, a_max) gives the shortest duration,
    1/v + v/a, or 2/sqrt(a) (a triangle) when v^2 > a so that v is never reached;
    (duration, v_max) gives a = v^2 / (v T - 1), which needs 1 < v T <= 2;
    (duration, a_max) gives the cruise velocity v = (a T - sqrt(a^2 T^2 - 4 a)) / 2,
    which needs a T^2 >= 4.

    Parameters
    ----------
    duration : float, optional, s
    v_max : float, optional, cruise velocity of s (1/s)
    a_max : float, optional, acceleration of s (1/s^2)

    Returns
    -------
    TimeScaling

    Examples
    --------
    Cruise at 0.5 per second, accelerate at 1 per second squared: 1/v + v/a = 2.5 s,
    and half-way (t = 1.25 s) s = 1/2 at the cruise velocity.

    >>> scaling = trapezoidal(v_max=0.5, a_max=1.0)
    >>> s, ds, dds = scaling.evaluate(1.25)
    >>> scaling.duration, float(s), float(ds), float(dds)
    (2.5, 0.5, 0.5, 0.0)
    """
    given = [x is not None for x in (duration, v_max, a_max)]
    if sum(given) != 2:
        raise ValueError(
            "a trapezoidal scaling takes two of duration, v_max and a_max, got "
            f"{sum(given)}"
        )
    v, a = _limit(v_max, "v_max"), _limit(a_max, "a_max")
    if duration is None:
        if v * v > a:  # a triangle: the ramps meet before v is reached
            v = np.sqrt(a)
            return TimeScaling("trapezoidal", 2 / v, v, a)
        return TimeScaling("trapezoidal", 1 / v + v / a, v, a)
    T = _limit(duration, "duration")
    if a is None:
        if not 1 < v * T <= 2:
            raise ValueError(
                f"v_max * duration must lie in (1, 2] for a trapezoid (cruising at "
                f"v_max covers at most and at least half of s), got {v * T:g}"
            )
        return TimeScaling("trapezoidal", T, v, v * v / (v * T - 1))
    if a * T * T < 4:
        raise ValueError(
            f"a_max * duration^2 must be at least 4 to reach s = 1 in time, got "
            f"{a * T * T:g}"
        )
    v = (a * T - np.sqrt(a * a * T * T - 4 * a)) / 2
    return TimeScaling("trapezoidal", T, v, a)


def fastest_joint_scaling(profile, q_start, q_end, v_max, a_max):
    """The shortest scaling of the straight joint path q_start -> q_end under joint
    limits: joint i moves by d_i, so it asks ds/dt <= v_i / abs(d_i) and
    abs(d2s/dt2) <= a_i / abs(d_i); the smallest of those bound s.

    Parameters
    ----------
    profile : one of :func:`cubic`, :func:`quintic`, :func:`trapezoidal`
    q_start, q_end : array-like, shape (n,), rad (m)
    v_max, a_max : array-like, shape (n,) or one number, positive (rad/s, rad/s^2)

    Returns
    -------
    TimeScaling

    Examples
    --------
    Joint 2 moves 2 rad at most 1 rad/s and 1 rad/s^2: it bounds s by 1/2 and 1/2,
    so the trapezoid takes 1/v + v/a = 2 + 1 = 3 s.

    >>> scaling = fastest_joint_scaling(trapezoidal, [0, 0], [1, 2], 1.0, 1.0)
    >>> scaling.duration, scaling.peak_velocity
    (3.0, 0.5)
    """
    if profile not in (cubic, quintic, trapezoidal):
        raise TypeError(
            "profile must be screwkit.motion.trajectory.cubic, quintic or "
            f"trapezoidal, got {describe(profile)}"
        )
    q_start, q_end = _joint_pair(q_start, q_end)
    distance = np.abs(q_end - q_start)
    bounds = []
    for name, value in (("v_max", v_max), ("a_max", a_max)):
        value = as_float_array(value, name)
        if value.ndim > 1 or value.size not in (1, q_start.size):
            raise ValueError(
                f"{name} must be one number or {q_start.size} numbers, got shape "
                f"{value.shape}"
            )
        if np.any(value <= 0):
            raise ValueError(f"{name} must be positive, got {quoted(value)}")
        moving = distance > 0
        ratio = np.broadcast_to(value, distance.shape)[moving] / distance[moving]
        bounds.append(float(ratio.min()) if ratio.size else None)
    if bounds[0] is None:
        raise ValueError(
            "q_start and q_end must differ (a motion to time), got equal vectors"
        )
    return profile(v_max=bounds[0], a_max=bounds[1])


# ---- paths --------------------------------------------------------------------------


def _joint_pair(q_start, q_end):
    q_start = as_float_array(q_start, "q_start")
    q_end = as_float_array(q_end, "q_end")
    if q_start.ndim != 1 or q_end.shape != q_start.shape:
        raise ValueError(
            "q_start and q_end must be joint vectors of one shape (n,), got shapes "
            f"{q_start.shape} and {q_end.shape}"
        )
    return q_start, q_end


def _path_parameter(s, size, what):
    """The path parameter s, one number or (K,), with K results of ``size`` floats
    each refused before they are built if they exceed the memory limit."""
    s = as_float_array(s, "s")
    if s.ndim > 1:
        raise ValueError(f"s must be one number or shape (K,), got shape {s.shape}")
    check_result_bytes(
        8 * size * s.size, f"{what} at the {s.size} samples of s", "pass fewer s"
    )
    return s


def joint_path(q_start, q_end, scaling, t):
    """The straight joint-space motion q(t) = q_start + s(t) (q_end - q_start).

    Parameters
    ----------
    q_start, q_end : array-like, shape (n,), rad (m)
    scaling : TimeScaling
    t : float or array-like, shape (K,), s

    Returns
    -------
    (q, dq, ddq) : ndarrays, shape (n,) or (K, n) each (rad, rad/s, rad/s^2)

    Examples
    --------
    Half-way through a cubic of 1 s, each joint is half-way at 1.5 times its
    distance per second:

    >>> q, dq, ddq = joint_path([0, 0], [1, 2], cubic(1.0), 0.5)
    >>> q.tolist(), dq.tolist(), ddq.tolist()
    ([0.5, 1.0], [1.5, 3.0], [0.0, 0.0])
    """
    q_start, q_end = _joint_pair(q_start, q_end)
    if not isinstance(scaling, TimeScaling):
        raise TypeError(f"scaling must be a TimeScaling, got {describe(scaling)}")
    samples = np.size(t)  # q, dq and ddq, each (K, n)
    check_result_bytes(
        24 * samples * q_start.size,
        f"joint_path at the {samples} times t",
        "pass fewer t",
    )
    s, ds, dds = (x[..., None] for x in scaling.evaluate(t))
    d = q_end - q_start
    return q_start + s * d, ds * d, dds * d


def _check_planar(T, name):
    """An SE(2) pose (3, 3): rotation block [[c, -s], [s, c]], last row [0, 0, 1]."""
    T = as_float_array(T, name)
    if T.shape != (3, 3):
        raise ValueError(f"{name} must be a (3, 3) SE(2) pose, got shape {T.shape}")
    if not np.array_equal(T[2], [0.0, 0.0, 1.0]):
        raise ValueError(f"{name} must have last row [0, 0, 1], got {T[2].tolist()}")
    R = np.eye(3)
    R[:2, :2] = T[:2, :2]
    check_rotation(R, f"the rotation block of {name}")
    return T


def _pose_pair(T_start, T_end):
    """Two poses of one kind: SE(3) (4, 4) or SE(2) (3, 3)."""
    shape = np.shape(T_start) if not isinstance(T_start, (str, bytes)) else None
    if shape == (3, 3):
        return _check_planar(T_start, "T_start"), _check_planar(T_end, "T_end")
    T_start = check_poses(T_start, "T_start", single_only=True)
    return T_start, check_poses(T_end, "T_end", single_only=True)


def _planar_exp(theta, v, s):
    """exp of the SE(2) twist (theta; v) times s, (K, 3, 3)."""
    angle = theta * s
    c, si = np.cos(angle), np.sin(angle)
    if abs(theta) < SLERP_LINEAR_BELOW:
        p = s[:, None] * v
    else:
        # V(angle) v / theta, V = [[sin, -(1 - cos)], [1 - cos, sin]]
        one_minus = 2 * np.sin(angle / 2) ** 2
        p = np.stack([si * v[0] - one_minus * v[1], one_minus * v[0] + si * v[1]], -1)
        p = p / theta
    E = np.zeros(s.shape + (3, 3))
    E[:, 0, 0], E[:, 0, 1], E[:, 1, 0], E[:, 1, 1] = c, -si, si, c
    E[:, :2, 2], E[:, 2, 2] = p, 1.0
    return E


def _planar_log(T):
    """(theta, v) with exp((theta; v)) = T for an SE(2) pose, theta in (-pi, pi]."""
    theta = np.arctan2(T[1, 0], T[0, 0])
    p = T[:2, 2]
    if abs(theta) < SLERP_LINEAR_BELOW:
        return theta, p.copy()
    one_minus, si = 2 * np.sin(theta / 2) ** 2, np.sin(theta)
    V = np.array([[si, -one_minus], [one_minus, si]]) / theta
    return theta, np.linalg.solve(V, p)


#: The sections screw_path and cartesian_path share (filled in by fill).
_PATH_SECTIONS = """Parameters
----------
T_start, T_end : array-like, shape (4, 4) (SE(3), m) or (3, 3) (SE(2), m)
s : float or array-like, shape (K,), the path parameter (0 at T_start, 1 at T_end)

Returns
-------
ndarray, shape (4, 4) or (K, 4, 4); (3, 3) or (K, 3, 3) for SE(2)"""


@fill(sections=_PATH_SECTIONS)
def screw_path(T_start, T_end, s):
    """The screw motion from T_start to T_end: T_start exp(log(T_start^-1 T_end) s).

    One constant twist (in the moving frame) carries the body along a helix: the
    straight line of SE(3). Modern Robotics' ``ScrewTrajectory`` with s from a time
    scaling.

    {sections}

    Examples
    --------
    To a quarter turn about the vertical line through (1, 0, 0): half-way the
    origin has turned 45 degrees about that line, to (1 - cos 45, -sin 45, 0).

    >>> T_end = np.array([[0, -1, 0, 1], [1, 0, 0, -1], [0, 0, 1, 0], [0, 0, 0, 1]])
    >>> screw_path(np.eye(4), T_end, 0.5)[:3, 3].round(4) + 0.0
    array([ 0.2929, -0.7071,  0.    ])
    """
    T_start, T_end = _pose_pair(T_start, T_end)
    s = _path_parameter(s, T_start.size, "screw_path")
    samples = np.atleast_1d(s)
    if T_start.shape == (3, 3):
        relative = np.linalg.solve(T_start, T_end)
        theta, v = _planar_log(relative)
        poses = T_start @ _planar_exp(theta, v, samples)
    else:
        poses = _screw_poses(T_start, log_transform(_relative(T_start, T_end)), samples)
    return poses if s.ndim else poses[0]


def _relative(T_start, T_end):
    """T_start^-1 T_end of two checked poses, [[R0^T R1, R0^T (p1 - p0)], [0, 1]]."""
    Rt = T_start[:3, :3].T
    relative = np.eye(4)
    relative[:3, :3] = Rt @ T_end[:3, :3]
    relative[:3, 3] = Rt @ (T_end[:3, 3] - T_start[:3, 3])
    return relative


def _screw_poses(T_start, twist, s):
    """T_start exp([twist] s) for samples s (K,), written out: with the unit axis w,
    the angle a = s theta and W = [w], T_start's rotation R0 times
    I + sin(a) W + (1 - cos a) W^2 is R0 + sin(a) R0 W + (1 - cos a) R0 W^2, and the
    position p0 + R0 (a v + (1 - cos a) W v + (a - sin a) W^2 v); so every product
    with a 3 x 3 is done once, not K times."""
    R0, p0 = T_start[:3, :3], T_start[:3, 3]
    poses = np.zeros(s.shape + (4, 4))
    poses[:, 3, 3] = 1.0
    theta = np.linalg.norm(twist[:3])
    if theta < SLERP_LINEAR_BELOW:  # a translation
        poses[:, :3, :3] = R0
        poses[:, :3, 3] = p0 + s[:, None] * (R0 @ twist[3:])
        return poses
    w, v = twist[:3] / theta, twist[3:] / theta
    W = np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])
    R0W = R0 @ W
    R0W2 = R0W @ W
    a = s * theta
    sine, one_minus = np.sin(a), 2 * np.sin(a / 2) ** 2
    # a - sin(a) loses every digit to cancellation for small a: its series there
    small = np.abs(a) < SERIES_BELOW
    a_minus_sine = np.where(small, a**3 / 6 - a**5 / 120 + a**7 / 5040, a - sine)
    poses[:, :3, :3] = R0 + sine[:, None, None] * R0W + one_minus[:, None, None] * R0W2
    poses[:, :3, 3] = (
        p0
        + a[:, None] * (R0 @ v)
        + one_minus[:, None] * (R0W @ v)
        + a_minus_sine[:, None] * (R0W2 @ v)
    )
    return poses


@fill(sections=_PATH_SECTIONS)
def cartesian_path(T_start, T_end, s):
    """The decoupled path: the position on the straight line, the rotation by slerp,
    p = p0 + s (p1 - p0), R = R0 exp(log(R0^T R1) s).

    Modern Robotics' ``CartesianTrajectory``. The origin moves on a line while a screw
    motion's origin moves on a helix; the rotations are the same.

    {sections}

    Examples
    --------
    The same quarter turn as in :func:`screw_path`: here the origin goes straight,
    half-way at the midpoint of (0, 0, 0) and (1, -1, 0).

    >>> T_end = np.array([[0, -1, 0, 1], [1, 0, 0, -1], [0, 0, 1, 0], [0, 0, 0, 1]])
    >>> cartesian_path(np.eye(4), T_end, 0.5)[:3, 3].round(4) + 0.0
    array([ 0.5, -0.5,  0. ])
    """
    T_start, T_end = _pose_pair(T_start, T_end)
    # the rotations are built twice (the turn, then the poses)
    s = _path_parameter(s, 2 * T_start.size, "cartesian_path")
    samples = np.atleast_1d(s)
    size = T_start.shape[0] - 1
    p0, p1 = T_start[:size, size], T_end[:size, size]
    if size == 2:
        start = np.arctan2(T_start[1, 0], T_start[0, 0])
        turn = _wrap_angle(np.arctan2(T_end[1, 0], T_end[0, 0]) - start)
        poses = _planar_exp(0.0, np.zeros(2), samples)
        angle = start + turn * samples
        c, si = np.cos(angle), np.sin(angle)
        poses[:, 0, 0], poses[:, 0, 1], poses[:, 1, 0], poses[:, 1, 1] = c, -si, si, c
    else:
        R0 = T_start[:3, :3]
        axis = log_rotation(R0.T @ T_end[:3, :3])
        turn = exp_twist(np.r_[axis, 0.0, 0.0, 0.0], samples)
        poses = turn.copy()
        poses[:, :3, :3] = R0 @ turn[:, :3, :3]
    poses[:, :size, size] = p0 + samples[:, None] * (p1 - p0)
    return poses if s.ndim else poses[0]


def slerp(q_start, q_end, s):
    """Spherical linear interpolation of unit quaternions (w, x, y, z), the shorter way.

    q(s) = sin((1 - s) W) / sin W q0 + sin(s W) / sin W q1 with cos W = abs(q0 . q1)
    (q1 negated if q0 . q1 < 0: q and -q are one rotation); below a tiny angle the
    normalised straight line, which equals it there to round-off.

    Parameters
    ----------
    q_start, q_end : array-like, shape (4,), unit quaternions, scalar first
    s : float or array-like, shape (K,)

    Returns
    -------
    ndarray, shape (4,) or (K, 4)

    Examples
    --------
    Half-way from no turn to a quarter turn about z is an eighth of a turn:
    (cos 22.5 deg, 0, 0, sin 22.5 deg).

    >>> quarter = [np.cos(np.pi / 4), 0.0, 0.0, np.sin(np.pi / 4)]
    >>> slerp([1.0, 0.0, 0.0, 0.0], quarter, 0.5).round(4) + 0.0
    array([0.9239, 0.    , 0.    , 0.3827])
    """
    q0 = _unit_quaternion(q_start, "q_start")
    q1 = _unit_quaternion(q_end, "q_end")
    s = _path_parameter(s, 4, "slerp")
    samples = np.atleast_1d(s)[:, None]
    dot = float(q0 @ q1)
    if dot < 0:
        q1, dot = -q1, -dot
    # the angle from the chord, accurate also near 0 (acos of a cosine near 1 is not)
    half_chord = np.linalg.norm(q1 - q0) / 2
    angle = 2 * np.arcsin(min(half_chord, 1.0))
    if angle < SLERP_LINEAR_BELOW:
        out = (1 - samples) * q0 + samples * q1
        out /= np.linalg.norm(out, axis=-1, keepdims=True)
    else:
        out = (
            np.sin((1 - samples) * angle) * q0 + np.sin(samples * angle) * q1
        ) / np.sin(angle)
    return out if s.ndim else out[0]


def _unit_quaternion(q, name):
    q = as_float_array(q, name)
    if q.shape != (4,):
        raise ValueError(f"{name} must be a quaternion of shape (4,), got {q.shape}")
    norm = np.linalg.norm(q)
    if abs(norm - 1) > SLERP_LINEAR_BELOW:
        raise ValueError(f"{name} must be a unit quaternion, got norm {norm:.6g}")
    return q / norm


# ---- via points ---------------------------------------------------------------------


@dataclass(frozen=True)
class ViaPoints:
    """Cubic pieces through points at times, velocity continuous (see
    :func:`via_points`).

    Parameters
    ----------
    times : ndarray, shape (M,)
        Increasing times (s).
    points : ndarray, shape (M, n)
        The points.
    velocities : ndarray, shape (M, n)
        The velocity at each point.

    Examples
    --------
    Up to 1 and back: the interior point is a turning point, so it is passed at
    rest.

    >>> motion = via_points([0.0, 1.0, 2.0], [0.0, 1.0, 0.0])
    >>> motion.times.tolist(), motion.velocities.ravel().tolist()
    ([0.0, 1.0, 2.0], [0.0, 0.0, 0.0])
    """

    times: np.ndarray
    points: np.ndarray
    velocities: np.ndarray

    def evaluate(self, t):
        """Position, velocity and acceleration at the times t.

        Parameters
        ----------
        t : float or array-like, shape (K,), within [times[0], times[-1]] (s)

        Returns
        -------
        (q, dq, ddq) : ndarrays, shape (n,) or (K, n) each

        Examples
        --------
        Between points at rest each piece is the cubic scaling: half-way, half the
        step at 1.5 times the step per second.

        >>> q, dq, ddq = via_points([0.0, 1.0], [0.0, 2.0]).evaluate(0.5)
        >>> q.tolist(), dq.tolist()
        ([1.0], [3.0])
        """
        t = as_float_array(t, "t")
        first, last = self.times[0], self.times[-1]
        outside = (t < first) | (t > last)
        if np.any(outside):
            index = tuple(int(i) for i in np.argwhere(outside)[0])
            where = f"t[{', '.join(map(str, index))}] = " if index else ""
            raise ValueError(
                f"t must lie in [{first:g}, {last:g}] s, got {where}"
                f"{quoted(t[index])} ({int(outside.sum())} of {t.size} outside)"
            )
        check_result_bytes(  # q, dq and ddq, each (K, n)
            24 * t.size * self.points.shape[1],
            f"ViaPoints.evaluate at the {t.size} times t",
            "pass fewer t",
        )
        k = np.clip(np.searchsorted(self.times, t, side="right") - 1, 0, None)
        k = np.minimum(k, len(self.times) - 2)
        h = (self.times[k + 1] - self.times[k])[..., None]
        u = (t - self.times[k])[..., None] / h
        p0, p1 = self.points[k], self.points[k + 1]
        m0, m1 = self.velocities[k] * h, self.velocities[k + 1] * h
        # cubic Hermite basis on u in [0, 1]
        q = (
            (2 * u**3 - 3 * u**2 + 1) * p0
            + (u**3 - 2 * u**2 + u) * m0
            + (-2 * u**3 + 3 * u**2) * p1
            + (u**3 - u**2) * m1
        )
        dq = (
            (6 * u**2 - 6 * u) * p0
            + (3 * u**2 - 4 * u + 1) * m0
            + (-6 * u**2 + 6 * u) * p1
            + (3 * u**2 - 2 * u) * m1
        ) / h
        ddq = (
            (12 * u - 6) * p0 + (6 * u - 4) * m0 + (-12 * u + 6) * p1 + (6 * u - 2) * m1
        ) / h**2
        return q, dq, ddq


def via_points(times, points, velocities=None):
    """A motion through points at given times, cubic between them, velocity
    continuous.

    With no velocities given the motion starts and ends at rest, and at an
    interior point each coordinate moves at the mean of its two neighbouring
    segments' slopes where they have one sign, and stops where they change sign
    (Craig's rule; it overshoots no via point's coordinate).

    Parameters
    ----------
    times : array-like, shape (M,), M >= 2, strictly increasing (s)
    points : array-like, shape (M,) or (M, n)
    velocities : array-like, optional, the shape of points (an exact match: not
        reshaped)

    Returns
    -------
    ViaPoints

    Examples
    --------
    Rising through 1 at t = 1 s (slopes 1 and 2 on either side): the velocity there
    is their mean, 1.5.

    >>> motion = via_points([0.0, 1.0, 2.0], [0.0, 1.0, 3.0])
    >>> q, dq, ddq = motion.evaluate(1.0)
    >>> q.tolist(), dq.tolist()
    ([1.0], [1.5])
    """
    times = as_float_array(times, "times")
    points = as_float_array(points, "points")
    if times.ndim != 1 or times.size < 2:
        raise ValueError(f"times must have shape (M,) with M >= 2, got {times.shape}")
    if np.any(np.diff(times) <= 0):
        k = int(np.argmax(np.diff(times) <= 0))
        raise ValueError(
            f"times must increase strictly, got times[{k}] = {times[k]:g} then "
            f"times[{k + 1}] = {times[k + 1]:g}"
        )
    shape = points.shape
    points = points[:, None] if points.ndim == 1 else points
    if points.ndim != 2 or points.shape[0] != times.size:
        raise ValueError(
            f"points must have {times.size} rows (one per time), got shape "
            f"{points.shape}"
        )
    if velocities is None:
        slopes = np.diff(points, axis=0) / np.diff(times)[:, None]
        velocities = np.zeros_like(points)
        same_sign = slopes[:-1] * slopes[1:] > 0
        velocities[1:-1] = np.where(same_sign, (slopes[:-1] + slopes[1:]) / 2, 0.0)
    else:
        given = as_float_array(velocities, "velocities")
        if given.shape != shape:
            raise ValueError(
                f"velocities must have the shape of points, {shape} (one velocity per "
                f"point and coordinate), got shape {given.shape}"
            )
        velocities = given.reshape(points.shape)
    return ViaPoints(times, points, velocities)


# ---- a path through the inverse kinematics ------------------------------------------


@dataclass(frozen=True)
class PathIK:
    """The joint path of a path of poses (see :func:`follow_path`).

    Parameters
    ----------
    q : ndarray, shape (K, n)
        Joint values, continuous (no jump of a whole turn).
    reached : ndarray of bool, shape (K,)
        The IK found the pose.
    singular : ndarray of bool, shape (K,)
        The Jacobian's smallest singular value is below NEAR_SINGULAR times its
        largest, or the closed form flags a singularity.
    condition : ndarray, shape (K,)
        The Jacobian's condition number.
    config : list of str
        The closed-form branch of each sample ('' for numeric IK).
    reason : str or None
        Why some pose was not reached, or None.

    Examples
    --------
    >>> from screwkit.robots import planar
    >>> arm = planar([1.0, 1.0])
    >>> q_path = np.array([[0.2, 1.0], [0.4, 0.8], [0.6, 0.6]])
    >>> result = follow_path(arm, arm.fk(q_path), q_path[0], method="numeric")
    >>> result.reached.tolist(), result.singular.tolist(), result.reason
    ([True, True, True], [False, False, False], None)
    """

    q: np.ndarray
    reached: np.ndarray
    singular: np.ndarray
    condition: np.ndarray
    config: list
    reason: object = None


def follow_path(chain, poses, q_start=None, method="closed_form"):
    """The joint path of a path of poses, the IK branch held continuous.

    Each sample takes the closed-form solution nearest the previous one
    (``method='closed_form'``, :func:`screwkit.ik.analytic_ik`), or Newton's method
    started there (``'numeric'``, :func:`screwkit.ik.numeric_ik`); angles are unwrapped
    so that q has no jump of a whole turn.

    Parameters
    ----------
    chain : Chain
    poses : array-like, shape (K, 4, 4), the path (m)
    q_start : array-like, shape (n,), optional: the branch to start on (needed for
        'numeric'; for 'closed_form' the first pose's first solution by default)
    method : 'closed_form' or 'numeric'

    Returns
    -------
    PathIK

    Examples
    --------
    The poses of a known joint path of a planar 2R arm give that path back:

    >>> from screwkit.robots import planar
    >>> arm = planar([1.0, 1.0])
    >>> q_path = np.array([[0.2, 1.0], [0.4, 0.8], [0.6, 0.6]])
    >>> result = follow_path(arm, arm.fk(q_path), q_path[0], method="numeric")
    >>> result.q.round(6) + 0.0
    array([[0.2, 1. ],
           [0.4, 0.8],
           [0.6, 0.6]])
    """
    check_chain(chain)
    method = check_option(method, "method", ("closed_form", "numeric"))
    poses = check_poses(poses, "poses")
    if poses.ndim != 3:
        raise ValueError(f"poses must have shape (K, 4, 4), got shape {poses.shape}")
    if q_start is not None:
        q_start = chain.check_one(q_start, "q_start")
    elif method == "numeric":
        raise ValueError("q_start is needed for method='numeric' (Newton's start)")
    K = poses.shape[0]
    Q = np.full((K, chain.n), np.nan)
    reached = np.zeros(K, dtype=bool)
    flagged = np.zeros(K, dtype=bool)
    config = [""] * K
    reason = None
    previous = q_start
    turning = np.array([joint is not Joint.PRISMATIC for joint in chain.joints])
    answers = ik.analytic_ik(chain, poses) if method == "closed_form" else None
    for k in range(K):
        if method == "closed_form":
            solutions = answers[k]
            if not solutions:
                reason = reason or f"pose {k}: {solutions.reason}"
                continue
            best = solutions[0] if previous is None else solutions.nearest(previous)
            q, config[k], flagged[k] = best.q, best.config, bool(best.singular)
        else:
            result = ik.numeric_ik(chain, poses[k], previous)
            if not result.success:
                reason = reason or f"pose {k}: Newton's method did not converge"
                continue
            q = result.q
        if previous is not None:
            q = np.where(turning, previous + _wrap_angle(q - previous), q)
        Q[k], reached[k], previous = q, True, q
    sigma = np.full((K, min(6, chain.n)), np.nan)
    if reached.any():
        sigma[reached] = chain.singular_values(Q[reached])
    with np.errstate(divide="ignore", invalid="ignore"):
        condition = sigma[:, 0] / sigma[:, -1]
    singular = flagged | (reached & ~(condition * NEAR_SINGULAR < 1))
    return PathIK(Q, reached, singular, condition, config, reason)
