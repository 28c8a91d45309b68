"""The PUMA 560: screwkit against the Robotics Toolbox for Python (RTB), run side by side.

Prints (1) agreement: RTB's ikine_a for each of the eight configuration labels against
screwkit's solution with the same label, on random poses; (2) a timing table with the
issue's goals. RTB's model gets d1 = 0 (no pedestal), as in the paper and in screwkit.
Usage (from the top level): make bench, or .venv-bench/bin/python benchmarks/bench_puma.py
"""
import time
import warnings

import numpy as np

import screwkit as sk
from _report import best, print_table

warnings.filterwarnings("ignore")
import roboticstoolbox as rtb  # noqa: E402

N_FK, N_IK = 100_000, 10_000
puma = sk.robots.puma560()
corke = rtb.models.DH.Puma560()
corke.links[0].d = 0.0
ets = corke.ets()
rng = np.random.default_rng(0)
Q = rng.uniform(-np.pi, np.pi, (N_FK, 6))



# ---- agreement ---------------------------------------------------------------------------
poses = puma.fk(Q[:200])
ours = sk.ik.puma560_ik_all(poses)
same, total = 0, 0
for T, solutions in zip(poses, ours):
    for config, q in zip(sk.ik.CONFIGURATIONS, solutions):
        theirs = corke.ikine_a(T, config).q
        total += 1
        same += np.allclose(np.angle(np.exp(1j * (theirs - q))), 0, atol=1e-8)
assert np.allclose(corke.fkine(Q[0]).A, puma.fk(Q[0]), atol=1e-12), "the two models differ"
print(f"agreement: {same} of {total} (pose, label) pairs give the same joint vector in RTB and screwkit\n")

# ---- timings -----------------------------------------------------------------------------
start = time.perf_counter()
sk.robots.puma560().fk_symbolic(symbolic_lengths=True)
t_symbolic = time.perf_counter() - start

poses_ik = puma.fk(Q[:N_IK])
rows = [
    ("FK, one pose", best(lambda: puma.fk(Q[0]), 5000), best(lambda: corke.fkine(Q[0]), 300),
     "RTB fkine (DH)", 20e-6),
    ("FK, 100,000 poses", best(lambda: puma.fk(Q), 3, 5), best(lambda: ets.fkine(Q), 1, 3),
     "RTB ETS fkine (C++)", 35e-3),
    ("IK all 8, one pose", best(lambda: sk.ik.puma560_ik(poses[0]), 500),
     8 * best(lambda: corke.ikine_a(poses[0], "lun"), 100), "8 x RTB ikine_a", None),
    ("IK all 8, 10,000 poses", best(lambda: sk.ik.puma560_ik_all(poses_ik), 3, 5), None,
     "", 100e-3),
    ("symbolic FK (simplified)", t_symbolic, None, "", 5.0),
]
theirs_fk_batch_dh = best(lambda: [corke.fkine(q) for q in Q[:2000]], 1, 1) * N_FK / 2000


print_table(rows, width=27)
print(f"\n(RTB's DH fkine for 100,000 poses one by one, extrapolated from 2,000: {theirs_fk_batch_dh:.1f} s)")
