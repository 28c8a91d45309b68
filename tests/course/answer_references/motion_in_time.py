"""The answer keys of the motion-in-time chapter, each recomputed independently: a
maximum found on a fine grid of differences of s(t), a duration found by bisection on a
simulated trapezoid, an acceleration by second differences of forward kinematics."""

import numpy as np

import screwkit as sk

from .registry import reference

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
