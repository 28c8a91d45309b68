"""The answer keys of the motion-in-time chapter, each recomputed independently: a
maximum found on a fine grid of differences of s(t), a duration found by bisection on a
simulated trapezoid, an acceleration by second differences of forward kinematics."""

import numpy as np

import screwkit as sk

from .registry import reference
from .roots import bisect

CHAPTER = "motion_in_time"


@reference(CHAPTER, 3)
def _():
    # s(t) of the quintic written here, differentiated numerically on a fine grid
    T = 2.0
    t = np.linspace(0, T, 200001)
    tau = t / T
    s = 10 * tau**3 - 15 * tau**4 + 6 * tau**5
    return np.gradient(s, t).max()


@reference(CHAPTER, 4)
def _():
    # the shortest time to cover s = 1 from rest to rest with |s''| <= 2, s' <= 0.5:
    # simulate accelerate / cruise / brake by small steps (no closed form used)
    v, a, dt = 0.5, 2.0, 1e-5
    s, speed, t = 0.0, 0.0, 0.0
    while s < 1.0:
        braking = speed * speed / (2 * a) >= 1.0 - s
        speed = max(speed - a * dt, 0.0) if braking else min(speed + a * dt, v)
        s += speed * dt
        t += dt
        if braking and speed == 0.0:
            break
    return t


@reference(CHAPTER, 5)
def _():
    arm = sk.robots.planar([1.0, 0.5])
    h = 1e-4
    p = [arm.fk([3.0 * t, 0.0])[:2, 3] for t in (-h, 0.0, h)]
    return np.linalg.norm((p[0] - 2 * p[1] + p[2]) / h**2)


@reference(CHAPTER, 10)
def _():
    # SciPy's clamped cubic spline through the three via points, its slope at t = 1 s
    from scipy.interpolate import CubicSpline

    spline = CubicSpline([0.0, 1.0, 2.0], [0.0, 1.0, 3.0], bc_type="clamped")
    return spline(1.0, 1)


@reference(CHAPTER, 12)
def _():
    # screwkit on the problem as stated: the velocities tr.via_points chooses
    motion = sk.motion.via_points([0.0, 1.0, 2.0, 3.0], [0.0, 0.5, 1.5, 1.0])
    return motion.velocities[1, 0]


@reference(CHAPTER, 13)
def _():
    # a jerk-limited motion built another way: the trapezoid's velocity (v 0.5, a 2,
    # duration 1 / v + v / a, exercise 4), averaged over a sliding window of a / j =
    # 0.125 s. The average keeps the distance 1, ramps the acceleration at most at j
    # and bounds it by a, and lengthens the motion by the window
    v, a, j, dt = 0.5, 2.0, 16.0, 1e-6
    duration = 1 / v + v / a
    t = np.arange(0.0, duration + dt / 2, dt)
    speed = np.clip(np.minimum(a * t, a * (duration - t)), 0.0, v)
    window = int(round(a / j / dt))
    padded = np.r_[np.zeros(window), speed, np.zeros(window)]
    total = np.cumsum(np.r_[0.0, padded])
    smooth = (total[window:] - total[:-window]) / window
    acceleration = np.diff(smooth) / dt
    jerk = np.diff(acceleration) / dt
    assert abs(smooth.sum() * dt - 1.0) < 1e-5
    assert np.abs(acceleration).max() < a * (1 + 1e-6)
    assert np.abs(jerk).max() < j * (1 + 1e-3)
    moving = np.flatnonzero(smooth > 1e-12)
    return (moving[-1] - moving[0] + 1) * dt


@reference(CHAPTER, 15)
def _():
    # the phase plane: s'^2 = 4 s accelerating, 4 (1 - s) braking; their crossing by
    # bisection, and the time as the integral of ds / s' by quadrature
    from scipy.integrate import quad

    accelerating = lambda s: np.sqrt(4.0 * s)  # noqa: E731
    braking = lambda s: np.sqrt(4.0 * (1.0 - s))  # noqa: E731
    switch = bisect(lambda s: accelerating(s) - braking(s), 0.0, 1.0)
    first = quad(lambda s: 1 / accelerating(s), 0.0, switch)[0]
    return first + quad(lambda s: 1 / braking(s), switch, 1.0)[0]


@reference(CHAPTER, 19)
def _():
    # the figure's jerk integrated three times on a grid of 10 us whose nodes hold the
    # segments' ends: the jerk read at the cells' middles, then the trapezoidal rule
    edges = [0, 0.2, 0.5, 0.7, 1.2, 1.4, 1.7, 1.9]
    values = [10, 0, -10, 0, -10, 0, 10]
    t = np.linspace(0.0, 1.9, 190001)
    middle = (t[1:] + t[:-1]) / 2
    cells = [(middle >= lo) & (middle < hi) for lo, hi in zip(edges, edges[1:])]
    jerk = np.select(cells, values)

    def integral(f):
        return np.r_[0.0, np.cumsum((f[1:] + f[:-1]) / 2 * np.diff(t))]

    acceleration = np.r_[0.0, np.cumsum(jerk * np.diff(t))]
    return integral(integral(acceleration))[-1]
