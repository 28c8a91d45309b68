"""Closed-form IK of a UR-type arm (screwkit.ik.ur): all eight solutions of 10,000 UR5e
poses in one call, against the same poses solved one call at a time (the ratio base:
no UR closed-form peer is installable from PyPI here), and against the spherical-wrist
solver on the PUMA 560 for scale. First call (the arm's geometry is found) and steady
state. Needs only screwkit.
Usage (from the top level): .venv/bin/python benchmarks/bench_ur_ik.py
"""

import time

import numpy as np
from _report import best, print_table

import screwkit as sk

rng = np.random.default_rng(0)
ur5e, puma = sk.robots.ur5e(), sk.robots.puma560()
T = ur5e.fk(rng.uniform(-np.pi, np.pi, (10_000, 6)))
T_puma = puma.fk(rng.uniform(-np.pi, np.pi, (10_000, 6)))

# ---- correctness at a glance --------------------------------------------------------
Q = sk.ik.analytic_ik_all(ur5e, T)
found = ~np.isnan(Q[..., 0])
k, b = np.nonzero(found)
error = np.abs(ur5e.fk(Q[k, b]) - T[k]).max()
counts = np.bincount(found.sum(axis=1), minlength=9)
print(
    f"UR5e: {found.sum()} solutions for {len(T)} random poses, largest FK error "
    f"{error:.1e}; poses with 8/6/4/2 solutions: {counts[8]}/{counts[6]}/{counts[4]}/"
    f"{counts[2]}"
)

# ---- timings ---------------------------------------------------------------------
fresh = sk.robots.ur5e()
start = time.perf_counter()
sk.ik.analytic_ik_all(fresh, T)
first = time.perf_counter() - start
batch = best(lambda: sk.ik.analytic_ik_all(ur5e, T), 3, 5)
loop = best(lambda: [sk.ik.analytic_ik_all(ur5e, pose) for pose in T[:1000]], 1, 3) * 10
rows = [
    ("UR5e all 8, 10,000, first call", first, None, "", 100e-3),
    ("UR5e all 8, 10,000 poses", batch, loop, "loop of 1-pose calls", 100e-3),
    (
        "UR5e labelled, one pose",
        best(lambda: sk.ik.analytic_ik(ur5e, T[0]), 200),
        None,
        "",
        None,
    ),
    (
        "PUMA all 8, 10,000 poses",
        best(lambda: sk.ik.analytic_ik_all(puma, T_puma), 3, 5),
        None,
        "",
        None,
    ),
]
print()
print_table(rows, width=32)
print("\n(the 'RTB' column here is the same 10,000 poses solved one call at a time)")
