"""Time screwkit's rigid-motion functions: one call, and a batch of 100,000 in one call.

Prints a table; the ratio column is the per-transform speed-up of the batch over single
calls.
Usage: python benchmarks/bench_transforms.py
"""

import timeit

import numpy as np

import screwkit as sk

N = 100_000
twist = sk.twist_from_axis([1, 2, 2], [0.5, -1.0, 2.0], 0.1)
angles = np.linspace(-np.pi, np.pi, N)
transforms = sk.exp_twist(twist, angles)

cases = [
    ("rotz", lambda: sk.rotz(0.3), lambda: sk.rotz(angles)),
    (
        "exp_twist",
        lambda: sk.exp_twist(twist, 0.3),
        lambda: sk.exp_twist(twist, angles),
    ),
    ("inv", lambda: sk.inv(transforms[0]), lambda: sk.inv(transforms)),
]


def best(function, number):
    return min(timeit.repeat(function, number=number, repeat=5)) / number


print(
    f"{'function':<12}{'one call (us)':>15}{'batch of 100k (ms)':>21}"
    f"{'per item in batch (us)':>25}{'batch speed-up':>16}"
)
for name, single, batch in cases:
    t_single = best(single, 2000)
    t_batch = best(batch, 3)
    print(
        f"{name:<12}{t_single * 1e6:>15.1f}{t_batch * 1e3:>21.1f}"
        f"{t_batch / N * 1e6:>25.3f}{t_single / (t_batch / N):>15.0f}x"
    )
