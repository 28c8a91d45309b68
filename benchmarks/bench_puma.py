"""The PUMA 560: screwkit against the Robotics Toolbox for Python (RTB), side by side.

Prints (1) agreement: RTB's ikine_a for each of the eight configuration labels against
screwkit's solution with the same label, on 200 random poses, twice: RTB's model with
d1 = 0 (no pedestal, as in the paper and screwkit's puma560()) against
sk.ik.puma560_ik_all, and RTB's own Puma560 (pedestal d1 = 0.67183 m) against
sk.ik.puma560_ik(T, robot=...) with a screwkit chain built from the same DH table; (2) a
timing table with the issue's goals.
Usage (from the top level): make bench,
or .venv-bench/bin/python benchmarks/bench_puma.py
"""

import time
import warnings

import numpy as np
from _report import best, print_table

import screwkit as sk

warnings.filterwarnings("ignore")
import roboticstoolbox as rtb  # noqa: E402

N_FK, N_IK = 100_000, 10_000
puma = sk.robots.puma560()
corke = rtb.models.DH.Puma560()
corke.links[0].d = 0.0
ets = corke.ets()
rng = np.random.default_rng(0)
Q = rng.uniform(-np.pi, np.pi, (N_FK, 6))


# ---- agreement -----------------------------------------------------------------------
def wrapped(angles):
    return np.angle(np.exp(1j * angles))


def agreement(rtb_robot, screwkit_answers, poses):
    """(same, total, rtb_failed): (pose, label) pairs where RTB's ikine_a and screwkit
    give the same joint vector (mod 2 pi, to 1e-8 rad), of those where both give one."""
    same = total = failed = 0
    for T, answer in zip(poses, screwkit_answers):
        for config, q in answer:
            solution = rtb_robot.ikine_a(T, config)
            if not solution.success or q is None:
                failed += 1
                continue
            total += 1
            same += bool(np.allclose(wrapped(solution.q - q), 0, atol=1e-8))
    return same, total, failed


assert np.allclose(corke.fkine(Q[0]).A, puma.fk(Q[0]), atol=1e-12), (
    "the two models differ"
)
poses = puma.fk(Q[:200])
ours = [list(zip(sk.ik.CONFIGURATIONS, row)) for row in sk.ik.puma560_ik_all(poses)]
same, total, failed = agreement(corke, ours, poses)
print(
    f"d1 = 0: {same} of {total} (pose, label) pairs give the same joint vector in RTB "
    f"(ikine_a) and screwkit (puma560_ik_all); RTB found no solution for {failed}"
)

# RTB's own PUMA, on its pedestal, and a screwkit chain read from the same DH table
corke_pedestal = rtb.models.DH.Puma560()
pedestal = sk.Chain(
    [
        sk.Link.revolute(d=L.d, a=L.a, alpha=L.alpha, offset=L.offset)
        for L in corke_pedestal.links
    ],
    base=corke_pedestal.base.A,
    tool=corke_pedestal.tool.A,
    name="RTB Puma560",
)
assert np.allclose(corke_pedestal.fkine(Q[0]).A, pedestal.fk(Q[0]), atol=1e-12)
poses_pedestal = pedestal.fk(Q[:200])
ours = []
for T in poses_pedestal:
    answer = sk.ik.puma560_ik(T, robot=pedestal)
    ours.append(
        [
            (c, None if answer.by_config(c) is None else answer.by_config(c).q)
            for c in sk.ik.CONFIGURATIONS
        ]
    )
same, total, failed = agreement(corke_pedestal, ours, poses_pedestal)
print(
    f"d1 = {corke_pedestal.links[0].d:.5f} m (RTB's Puma560): "
    f"{same} of {total} pairs agree "
    f"(puma560_ik(T, robot=...)); RTB or screwkit found no solution for {failed}"
)
answers = [sk.ik.puma560_ik(T) for T in poses_pedestal]  # without robot=: d1 = 0
misses = [
    np.linalg.norm(pedestal.fk(sol.q)[:3, 3] - T[:3, 3])
    for T, answer in zip(poses_pedestal, answers)
    for sol in answer
]
print(
    f"  the same poses given to puma560_ik without robot= (screwkit's d1 = 0 model): "
    f"{sum(not a for a in answers)} of {len(answers)} out of reach; the {len(misses)} "
    f"solutions of the others miss their pose by {min(misses):.4f} m or more\n"
)

# ---- timings -------------------------------------------------------------------------
start = time.perf_counter()
sk.robots.puma560().fk_symbolic(symbolic_lengths=True)
t_symbolic = time.perf_counter() - start

poses_ik = puma.fk(Q[:N_IK])
rows = [
    (
        "FK, one pose",
        best(lambda: puma.fk(Q[0]), 5000),
        best(lambda: corke.fkine(Q[0]), 300),
        "RTB fkine (DH)",
        20e-6,
    ),
    (
        "FK, 100,000 poses",
        best(lambda: puma.fk(Q), 3, 5),
        best(lambda: ets.fkine(Q), 1, 3),
        "RTB ETS fkine (C++)",
        35e-3,
    ),
    (
        "IK all 8, one pose",
        best(lambda: sk.ik.puma560_ik(poses[0]), 500),
        8 * best(lambda: corke.ikine_a(poses[0], "lun"), 100),
        "8 x RTB ikine_a",
        None,
    ),
    (
        "IK all 8, 10,000 poses",
        best(lambda: sk.ik.puma560_ik_all(poses_ik), 3, 5),
        None,
        "",
        100e-3,
    ),
    ("symbolic FK (simplified)", t_symbolic, None, "", 5.0),
]
theirs_fk_batch_dh = (
    best(lambda: [corke.fkine(q) for q in Q[:2000]], 1, 1) * N_FK / 2000
)


print_table(rows, width=27)
print(
    "\n(RTB's DH fkine for 100,000 poses one by one, extrapolated from 2,000: "
    f"{theirs_fk_batch_dh:.1f} s)"
)
