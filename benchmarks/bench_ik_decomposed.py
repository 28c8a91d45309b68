"""Inverse kinematics of decomposable 6R arms by subproblems 5 and 6, beside EAIK.

Random arms of four classes (a spherical wrist with no other condition, a spherical
shoulder, three parallel axes 2, 3, 4 and 3, 4, 5, each with offsets everywhere): all
solutions of 10,000 random poses in one call (the goal: at most 100 ms), and the
same poses through EAIK (Ostermeier et al. 2024, C++ behind pybind, one thread) when it
is installed (``pip install EAIK``; benchmarks/requirements.txt). Prints how many
solutions each finds, whether every exact EAIK solution (forward-kinematics error below
1e-8) is among screwkit's, and the times side by side: the first call (a chain built
anew: its class found, its engine and its generated forward kinematics made; EAIK's
robot built, its decomposition found) and the steady state (best of seven calls).
Usage (from the top level): .venv/bin/python benchmarks/bench_ik_decomposed.py
"""

import sys
import time
from pathlib import Path

import numpy as np
from _report import best

import screwkit as sk
from screwkit.ik.decomposed import DecomposedArm

# the tests' random arms of each structure (tests/builders.py)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from builders import random_arm  # noqa: E402

try:
    from eaik.IK_HP import HPRobot  # not eaik itself: its __init__ needs urchin
except ImportError:
    HPRobot = None

N = 10_000
REPEAT = 7  # the steady state: the best of seven calls, each side
rng = np.random.default_rng(34)


def eaik_robot(chain):
    """The chain in EAIK's H, P convention (axes, offsets between axis points, the
    tool's rotation at q = 0 taken off the poses)."""
    S, M = chain.screw_axes(), chain.home()
    w = S[:, :3]
    r = np.cross(w, S[:, 3:])
    return HPRobot(w, np.vstack([r[0], np.diff(r, axis=0), M[:3, 3] - r[5]]))


def ms(t):
    return f"{t * 1e3:>9.1f} ms" if t else f"{'-':>12}"


def wrapped(a):
    return np.angle(np.exp(1j * a))


print(
    f"{'class':<20}{'first call':>12}{'steady':>12}{'EAIK first':>12}{'steady':>12}"
    f"{'ratio':>7}  solutions (screwkit/EAIK)"
)
for kind, name in (
    ("wrist", "spherical wrist"),
    ("shoulder", "spherical shoulder"),
    ("parallel 234", "parallel 2, 3, 4"),
    ("parallel 345", "parallel 3, 4, 5"),
):
    chain = random_arm(kind, rng, antiparallel=False)
    T = chain.fk(rng.uniform(-np.pi, np.pi, (N, 6)))
    # the first call: a chain built anew, so its class, engine and kinematics are made
    fresh = sk.Chain.from_screws(chain.screw_axes(), chain.home())
    start = time.perf_counter()
    Q = sk.ik.analytic_ik_all(fresh, T)
    first_ours = time.perf_counter() - start
    DecomposedArm.from_chain(chain)  # a ValueError if the arm were not decomposable
    ours = int((~np.isnan(Q[..., 0])).sum())
    t_ours = best(lambda: sk.ik.analytic_ik_all(chain, T), 1, REPEAT)  # noqa: B023
    t_theirs = first_theirs = None
    theirs, missing = "-", "-"
    if HPRobot is not None:
        T_eaik = T.copy()
        T_eaik[:, :3, :3] = T[:, :3, :3] @ chain.home()[:3, :3].T
        poses = list(T_eaik)
        start = time.perf_counter()
        robot = eaik_robot(chain)  # EAIK finds its decomposition here
        found = robot.IK_batched(poses, 1)
        first_theirs = time.perf_counter() - start
        t_theirs = best(lambda: robot.IK_batched(poses, 1), 1, REPEAT)  # noqa: B023
        count, missing = 0, 0
        for k in range(N):
            QE = np.array(found[k].Q).reshape(-1, 6)
            if len(QE):
                QE = QE[np.abs(chain.fk(QE) - T[k]).max((1, 2)) < 1e-8]
            distinct = []
            for q in QE:
                if all(np.abs(wrapped(q - d)).max() > 1e-6 for d in distinct):
                    distinct.append(q)
            count += len(distinct)
            mine = Q[k][~np.isnan(Q[k, :, 0])]
            for q in distinct:
                if len(mine) == 0 or np.abs(wrapped(mine - q)).max(1).min() > 1e-6:
                    missing += 1
        theirs = count
    ratio = f"{t_theirs / t_ours:>6.2f}x" if t_theirs else f"{'-':>7}"
    print(
        f"{name:<20}{ms(first_ours)}{ms(t_ours)}{ms(first_theirs)}{ms(t_theirs)}"
        f"{ratio}  {ours}/{theirs} (exact EAIK solutions screwkit lacks: {missing})"
    )
print(
    f"\n{N} poses per class, one call; ratio: EAIK's steady time over screwkit's;"
    " goal: all solutions in at most 100 ms"
)
if HPRobot is None:
    print("EAIK is not installed (pip install EAIK): screwkit alone")
