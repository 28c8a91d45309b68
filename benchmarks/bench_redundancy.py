"""Redundancy resolution: the time of rd.resolve for 1000 steps of a 5-link planar arm,
against the goal of the redundancy issue (under 0.2 s), and the tracking accuracy on a
full circle.

Usage (from the top level): make bench,
or .venv/bin/python benchmarks/bench_redundancy.py
"""

import timeit

import numpy as np

import screwkit as sk
from screwkit import redundancy as rd

lengths = [0.3, 0.25, 0.2, 0.15, 0.1]
arm = sk.robots.planar(lengths)
limited = sk.robots.planar(lengths, qlim=np.radians([[-180, 180]] + [[-60, 60]] * 4))
circle = rd.circle(
    (0.45, 0.25), 0.15, duration=10.0, dt=0.01
)  # 1001 samples, 1000 steps
q0 = rd.start_configuration(
    arm, circle.position[0], np.radians([30, -30, -30, -30, -30])
)

cases = [
    ("pseudo-inverse only", lambda: rd.resolve(arm, circle, q0)),
    ("+ null space (k = 5)", lambda: rd.resolve(arm, circle, q0, null_space_gain=5.0)),
    (
        "+ null space + limit avoidance",
        lambda: rd.resolve(
            limited, circle, q0, null_space_gain=5.0, joint_limits="avoid"
        ),
    ),
    (
        "+ damped least squares",
        lambda: rd.resolve(arm, circle, q0, null_space_gain=5.0, damping=0.05),
    ),
]
goal = 0.2
print(
    f"{'1000 steps, 5-link arm, circle':<34}{'time':>10}{'goal':>10}  met  "
    f"{'max error':>10}"
)
for name, run in cases:
    seconds = min(timeit.repeat(run, number=1, repeat=5))
    error = run().error.max()
    print(
        f"{name:<34}{seconds * 1e3:>7.1f} ms{goal * 1e3:>7.0f} ms  "
        f"{'yes' if seconds < goal else 'NO ':<4}"
        f"{error * 1e3:>7.3f} mm"
    )
