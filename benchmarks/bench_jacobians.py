"""Jacobians, manipulability and workspace sweeps: screwkit against the Robotics Toolbox
for Python (RTB), run side by side, with the goals of the Jacobian issue.

Prints (1) agreement: RTB's jacob0 against screwkit's geometric Jacobian on random PUMA
560 configurations (RTB's model gets d1 = 0, as in screwkit); (2) a timing table.
Usage (from the top level): make bench,
or .venv-bench/bin/python benchmarks/bench_jacobians.py
"""

import warnings

import numpy as np
from _report import best, print_table

import screwkit as sk

warnings.filterwarnings("ignore")
import roboticstoolbox as rtb  # noqa: E402

N = 100_000
DEG = np.pi / 180
puma, kawasaki = sk.robots.puma560(), sk.robots.kawasaki_cx210l()
corke = rtb.models.DH.Puma560()
corke.links[0].d = 0.0
ets = corke.ets()
Q = np.random.default_rng(0).uniform(-np.pi, np.pi, (N, 6))


# ---- agreement -----------------------------------------------------------------------
ours = puma.geometric_jacobian(Q[:1000])
theirs = np.array([corke.jacob0(q) for q in Q[:1000]])
print(
    "agreement: max |J_screwkit - J_RTB| over 1000 configurations = "
    f"{np.abs(ours - theirs).max():.1e}"
)
w_theirs = np.array([corke.manipulability(q) for q in Q[:1000]])
w_ours = puma.manipulability(Q[:1000])
print(
    "           max |w_screwkit - w_RTB| (Yoshikawa, all six rows) = "
    f"{np.abs(w_ours - w_theirs).max():.1e}\n"
)

# ---- timings -------------------------------------------------------------------------
puma.geometric_jacobian(Q[:10])
t_rtb_one = best(lambda: corke.jacob0(Q[0]), 300)
t_rtb_ets_one = best(lambda: ets.jacob0(Q[0]), 3000)


def sweep():
    return sk.workspace.sweep(
        kawasaki, {2: (30 * DEG, 180 * DEG), 3: (-90 * DEG, 60 * DEG)}, num=301
    )


rows = [
    (
        "geometric J, one",
        best(lambda: puma.geometric_jacobian(Q[0]), 3000),
        t_rtb_one,
        "RTB DH jacob0",
        None,
    ),
    (
        "geometric J, one",
        best(lambda: puma.geometric_jacobian(Q[0]), 3000),
        t_rtb_ets_one,
        "RTB ETS jacob0 (C++)",
        None,
    ),
    (
        "geometric J, 100,000",
        best(lambda: puma.geometric_jacobian(Q), 1, 5),
        N * t_rtb_ets_one,
        "N x RTB ETS jacob0",
        100e-3,
    ),
    (
        "manipulability, 100,000",
        best(lambda: puma.manipulability(Q), 1, 3),
        N * best(lambda: corke.manipulability(Q[0]), 300),
        "N x RTB manipulab.",
        None,
    ),
    ("sweep 301 x 301 (FK)", best(sweep, 1, 5), None, "", 50e-3),
    ("det J over the sweep", best(lambda: sweep().determinant(), 1, 3), None, "", None),
]


print_table(rows, width=25)
