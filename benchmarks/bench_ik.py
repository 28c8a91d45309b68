"""Inverse kinematics: the closed form for arms with a spherical wrist, and numeric IK.

Prints a timing table (all eight solutions of 10,000 random poses through the general
solver, for the PUMA 560 and the Kawasaki CX210L; one pose; numeric IK) with the issue's
goals, the peak memory of 10^6 poses solved in one call (the solver streams in chunks),
and how many of the solutions reach their pose. Needs only screwkit (no Robotics
Toolbox).
Usage (from the top level): .venv/bin/python benchmarks/bench_ik.py
"""

import tracemalloc

import numpy as np
from _report import best, print_table

import screwkit as sk

rng = np.random.default_rng(0)
puma, kawasaki = sk.robots.puma560(), sk.robots.kawasaki_cx210l()
poses = {
    name: robot.fk(rng.uniform(-np.pi, np.pi, (10_000, 6)))
    for name, robot in (("PUMA 560", puma), ("Kawasaki CX210L", kawasaki))
}
robots = {"PUMA 560": puma, "Kawasaki CX210L": kawasaki}

# ---- correctness at a glance ---------------------------------------------------------
for name, T in poses.items():
    Q = sk.ik.analytic_ik_all(robots[name], T)
    found = ~np.isnan(Q[..., 0])
    k, b = np.nonzero(found)
    error = np.abs(robots[name].fk(Q[k, b]) - T[k]).max()
    print(
        f"{name}: {found.sum()} solutions for {len(T)} poses "
        f"({found.sum(axis=1).min()} to {found.sum(axis=1).max()} per pose), "
        f"largest FK error {error:.1e}"
    )

# ---- timings -------------------------------------------------------------------------
T_one = poses["PUMA 560"][0]
q_start = puma.fk(np.zeros(6))
target_q = np.array([0.3, 0.5, -2.0, 0.4, 0.7, 0.2])
rows = [
    (
        "PUMA all 8, 10,000 poses",
        best(lambda: sk.ik.analytic_ik_all(puma, poses["PUMA 560"]), 3, 5),
        None,
        "",
        50e-3,
    ),
    (
        "Kawasaki all, 10,000 poses",
        best(lambda: sk.ik.analytic_ik_all(kawasaki, poses["Kawasaki CX210L"]), 3, 5),
        None,
        "",
        100e-3,
    ),
    (
        "PUMA all 8, one pose",
        best(lambda: sk.ik.puma560_ik(T_one), 200),
        None,
        "",
        None,
    ),
    (
        "Kawasaki all, one pose",
        best(lambda: sk.ik.analytic_ik(kawasaki, poses["Kawasaki CX210L"][0]), 200),
        None,
        "",
        None,
    ),
    (
        "numeric IK, PUMA, 1 start",
        best(lambda: sk.ik.numeric_ik(puma, puma.fk(target_q), target_q + 0.2), 20),
        None,
        "",
        None,
    ),
    (
        "numeric IK, PUMA, 100 starts",
        best(
            lambda: sk.ik.numeric_ik(
                puma, puma.fk(target_q), rng.uniform(-np.pi, np.pi, (100, 6))
            ),
            1,
            3,
        ),
        None,
        "",
        None,
    ),
]
print()
print_table(rows, width=30)

# ---- memory: 10^6 poses in one call --------------------------------------------------
many = np.repeat(poses["PUMA 560"], 100, axis=0)  # 10^6 poses, 128 MB
tracemalloc.start()
Q = sk.ik.analytic_ik_all(puma, many)
peak = tracemalloc.get_traced_memory()[1]
tracemalloc.stop()
print(
    f"\n10^6 PUMA poses, all 8 solutions: peak memory of the call "
    f"{peak / 2**20:.0f} MB "
    f"(the answer itself is {Q.nbytes / 2**20:.0f} MB; goal: under 1024 MB)"
)
