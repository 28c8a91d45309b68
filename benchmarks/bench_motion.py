"""Motion in time: the Jacobian's time derivative and Hessian by Lie brackets, against
the Jacobian's own time and the Robotics Toolbox for Python (RTB), and a screw
trajectory against Modern Robotics' ScrewTrajectory, with the goals of issue 33.

Prints (1) agreement with RTB's jacob0_dot and hessian0 (PUMA 560, RTB's d1 = 0 as in
screwkit) and with Modern Robotics' ScrewTrajectory; (2) a table of times and ratios.
Usage (from the top level): make bench, or
.venv-bench/bin/python benchmarks/bench_motion.py
"""

import warnings

import modern_robotics as mr
import numpy as np
from _report import best, ms

import screwkit as sk
from screwkit.motion import trajectory as tr

warnings.filterwarnings("ignore")
import roboticstoolbox as rtb  # noqa: E402

N = 100_000
puma = sk.robots.puma560()
corke = rtb.models.DH.Puma560()
corke.links[0].d = 0.0
ets = corke.ets()
rng = np.random.default_rng(0)
Q, dQ = rng.uniform(-np.pi, np.pi, (N, 6)), rng.uniform(-1, 1, (N, 6))

# ---- agreement ----------------------------------------------------------------------
ours = puma.geometric_jacobian_dot(Q[:1000], dQ[:1000])
theirs = np.array([corke.jacob0_dot(q, dq) for q, dq in zip(Q[:1000], dQ[:1000])])
print(
    f"agreement: max |dJ_screwkit - RTB jacob0_dot| over 1000 configurations = "
    f"{np.abs(ours - theirs).max():.1e}"
)
hessians = np.array([ets.hessian0(q) for q in Q[:1000]])
print(
    f"           max |H_screwkit - RTB ETS hessian0| = "
    f"{np.abs(puma.geometric_hessian(Q[:1000]) - hessians).max():.1e}"
)
T0 = sk.transl(1.0, 0.0, 1.0)
T1 = np.array([[0, 0, 1, 0.1], [1, 0, 0, 0], [0, 1, 0, 4.1], [0, 0, 0, 1.0]])
scaling = tr.quintic(2.0)
times = scaling.times(1000)
reference = np.array(mr.ScrewTrajectory(T0, T1, 2.0, 1000, 5))
difference = np.abs(tr.screw_path(T0, T1, scaling(times)) - reference).max(axis=(1, 2))
print(
    f"           max |screw_path - MR ScrewTrajectory| (1000 samples) = "
    f"{difference.max():.1e}, {difference[difference > 1e-12].size} samples above "
    "1e-12:\n           MR's MatrixExp6 takes a rotation below 1e-6 rad as a "
    "translation (NearZero),\n           the first samples of a quintic; "
    f"elsewhere {difference[difference <= 1e-12].max():.1e}\n"
)

# ---- timings ------------------------------------------------------------------------
puma.geometric_jacobian_dot(Q[:10], dQ[:10])
t_J = best(lambda: puma.geometric_jacobian(Q), 1, 5)
t_Js = best(lambda: puma.space_jacobian(Q), 1, 5)
t_dJ = best(lambda: puma.geometric_jacobian_dot(Q, dQ), 1, 5)
t_dJs = best(lambda: puma.space_jacobian_dot(Q, dQ), 1, 5)
t_H = best(lambda: puma.geometric_hessian(Q), 1, 3)
t_rtb_dJ = N * best(lambda: corke.jacob0_dot(Q[0], dQ[0]), 100)
t_rtb_H = N * best(lambda: np.tensordot(ets.hessian0(Q[0]), dQ[0], (0, 0)), 2000)
t_screw = best(lambda: tr.screw_path(T0, T1, scaling(times)), 100, 7)
t_mr = best(lambda: mr.ScrewTrajectory(T0, T1, 2.0, 1000, 5), 1, 5)

W = 40
print(
    f"{'task (PUMA 560, 100,000 configurations)':<{W}}{'screwkit':>13}{'against':>13}"
    f"{'ratio':>9}  {'against what':<27}{'goal':<22} met"
)
rows = [
    (
        "geometric dJ/dt",
        t_dJ,
        t_J,
        "screwkit geometric J",
        "ratio <= 3",
        t_dJ <= 3 * t_J,
    ),
    ("space dJ/dt", t_dJs, t_Js, "screwkit space J", "ratio <= 3", t_dJs <= 3 * t_Js),
    (
        "geometric dJ/dt",
        t_dJ,
        t_rtb_dJ,
        "N x RTB DH jacob0_dot",
        "faster than RTB",
        t_dJ < t_rtb_dJ,
    ),
    (
        "geometric dJ/dt",
        t_dJ,
        t_rtb_H,
        "N x RTB ETS hessian0 . qd",
        "faster than RTB",
        t_dJ < t_rtb_H,
    ),
    (
        "geometric Hessian (n, 6, n)",
        t_H,
        N * best(lambda: ets.hessian0(Q[0]), 2000),
        "N x RTB ETS hessian0 (C++)",
        "",
        None,
    ),
    (
        "screw trajectory, 1000 samples",
        t_screw,
        t_mr,
        "MR ScrewTrajectory",
        "< 1 ms",
        t_screw < 1e-3,
    ),
]
for task, t_ours, t_other, what, goal, met in rows:
    ratio = t_ours / t_other if "screwkit" in what else t_other / t_ours
    label = "x" if "screwkit" in what else "x faster"
    met = "" if met is None else ("yes" if met else "NO")
    print(
        f"{task:<{W}}{ms(t_ours)}{ms(t_other)}{ratio:>8.2f}{label[0]}  "
        f"{what:<27}{goal:<22} {met}"
    )
print(
    "\nratio: screwkit's time over its own Jacobian's (x), or the other library's "
    "time over screwkit's (speed-up)"
)
