"""Every IK solution of a general 6R arm (screwkit.ik.general: the Raghavan–Roth
eigenvalue problem, Newton-polished): one pose a call, and 200 poses in one batched
call, first call (a fresh chain, so its generated kinematics are compiled) and steady
state (the goal: at most 2 ms a pose, batched), against the peers on the same
arm, the same poses and the same question (all solutions of each pose):

* IK-Geo (``pip install ik-geo``, Elias and Wen; ``Robot.gen_six_dof``: a 2-D search
  on subproblems), for the general arm;
* EAIK (``pip install EAIK``, Ostermeier et al.): decomposable arms only (it reports
  the general arm has no known decomposition), so it runs on the PUMA 560, where
  screwkit's general solver and its closed form run too.

Both peers are optional (benchmarks/requirements.txt); a missing one is a row that
says so. Usage (from the top level): .venv/bin/python benchmarks/bench_ik_general.py
"""

import time

import numpy as np
from _report import best, ms, peer

import screwkit as sk
from screwkit.ik.general import general_6r_ik

POSES = 200
rng = np.random.default_rng(0)


def cpu(function, repeat=3):
    """The best process (CPU) time of ``repeat`` calls (s): on a shared machine the
    wall time also counts the other processes' turns."""
    times = []
    for _ in range(repeat):
        start = time.process_time()
        function()
        times.append(time.process_time() - start)
    return min(times)


def wrap(q):
    return (q + np.pi) % (2 * np.pi) - np.pi


def general_arm():
    """A general 6R arm: random standard DH (d, a in [-1, 1] m, alpha any)."""
    table = np.zeros((6, 4))
    table[:, 1:3] = rng.uniform(-1, 1, (6, 2))
    table[:, 3] = rng.uniform(-np.pi, np.pi, 6)
    return table


def hp(chain):
    """H (6, 3) and P (7, 3), IK-Geo's and EAIK's description of an arm, and the home
    rotation: R(q) = R1 ... R6 there, R1 ... R6 R_home in screwkit."""
    z, o = chain.joint_axes(np.zeros(6))
    M = chain.fk(np.zeros(6))
    return z, np.vstack([o[0], np.diff(o, axis=0), M[:3, 3] - o[5]]), M[:3, :3]


def matches(Q, ours, within):
    """How many rows of Q are within ``within`` (rad, modulo a turn) of a row of
    ``ours``."""
    if len(Q) == 0 or len(ours) == 0:
        return 0
    gaps = np.abs(wrap(Q[:, None] - ours[None])).max(axis=2).min(axis=1)
    return int(np.sum(gaps < within))


def pose_errors(chain, Q, T):
    return np.abs(chain.fk(Q) - T).max(axis=(1, 2)) if len(Q) else np.zeros(0)


table = general_arm()
arm = sk.Chain.from_table(table)
T = arm.fk(rng.uniform(-np.pi, np.pi, (POSES, 6)))

# ---- screwkit: correctness at a glance, then timings ---------------------------------
start = time.perf_counter()
first_batch = general_6r_ik(sk.Chain.from_table(table), T)
first = (time.perf_counter() - start) / POSES
results = general_6r_ik(arm, T)
one_by_one = [general_6r_ik(arm, pose) for pose in T]
same = all(
    a.Q.shape == b.Q.shape and np.allclose(a.Q, b.Q, atol=1e-9)
    for a, b in zip(results, one_by_one)
)
counts = np.array([len(r.Q) for r in results])
worst = max(float(r.residuals.max(initial=0)) for r in results)
single = best(lambda: [general_6r_ik(arm, pose) for pose in T], 1, 3) / POSES
single_cpu = cpu(lambda: [general_6r_ik(arm, pose) for pose in T]) / POSES
steady = best(lambda: general_6r_ik(arm, T), 1, 5) / POSES
steady_cpu = cpu(lambda: general_6r_ik(arm, T), 5) / POSES
print(
    f"general 6R arm, {POSES} random poses: {counts.sum()} solutions, "
    f"{np.bincount(counts, minlength=17)[::2].tolist()} poses with 0, 2, ..., 16; "
    f"largest residual {worst:.1e}; batch and one-by-one answers the same: {same}"
)
print()
print(f"{'task':<44}{'per pose':>13}{'goal':>13}  met  (CPU time, per pose)")
print(
    f"{'screwkit general_6r_ik, one pose a call':<44}{ms(single)}{'':>13}       "
    f"CPU {ms(single_cpu)}"
)
print(f"{'screwkit general_6r_ik, batch, first call':<44}{ms(first)}{'':>13}")
print(
    f"{'screwkit general_6r_ik, batch, steady':<44}{ms(steady)}{ms(2e-3)}  "
    f"{'yes' if steady < 2e-3 else 'NO':<3}  CPU {ms(steady_cpu)}"
)

# ---- IK-Geo on the same arm and poses ----------------------------------------------
print()
ik_geo = peer("ik_geo", "IK-Geo", "ik-geo")
if ik_geo is not None:
    H, P, R_home = hp(arm)
    robot = ik_geo.Robot.gen_six_dof(H, P)

    def ik_geo_all():
        # IK-Geo's bindings take the rotation transposed (row-major): checked against
        # its forward_kinematics in the lines below
        return [robot.get_ik((pose[:3, :3] @ R_home.T).T, pose[:3, 3]) for pose in T]

    R_check, _ = robot.forward_kinematics(np.zeros(6))
    assert np.allclose(np.array(R_check).T, np.eye(3))
    answers = ik_geo_all()
    theirs = [np.array([q for q, _ in a]).reshape(-1, 6) for a in answers]
    flagged = sum(sum(ls for _, ls in a) for a in answers)
    geo_time = best(ik_geo_all, 1, 3) / POSES
    geo_cpu = cpu(ik_geo_all) / POSES
    found = sum(len(Q) for Q in theirs)
    errors = np.concatenate([pose_errors(arm, Q, pose) for Q, pose in zip(theirs, T)])
    near = sum(matches(Q, r.Q, 1e-2) for Q, r in zip(theirs, results))
    ours_seen = sum(matches(r.Q, Q, 1e-2) for Q, r in zip(theirs, results))
    print(
        f"IK-Geo gen_six_dof, same arm and poses: {found} solutions returned "
        f"({flagged} flagged least-squares) against screwkit's {counts.sum()}; "
        f"pose error below 1e-6: {int(np.sum(errors < 1e-6))}, below 1e-3: "
        f"{int(np.sum(errors < 1e-3))}, largest {errors.max(initial=0):.1e}; "
        f"{near} of them within 0.01 rad of one of screwkit's, which come near "
        f"{ours_seen} of screwkit's {counts.sum()}"
    )
    print(
        f"{'IK-Geo gen_six_dof (2-D search), per pose':<44}{ms(geo_time)}"
        f"{'':>13}       CPU {ms(geo_cpu)}"
    )
    print(
        f"screwkit's batch against IK-Geo: {geo_time / steady:.1f}x faster "
        f"(CPU {geo_cpu / steady_cpu:.1f}x), and every solution"
    )

# ---- EAIK: the general arm, then the PUMA 560 ---------------------------------------
print()
eaik = peer("eaik.IK_HP", "EAIK", "EAIK")  # not eaik itself: its __init__ needs urchin
if eaik is not None:
    H, P, _ = hp(arm)
    general = eaik.HPRobot(H, P)
    print(
        f"EAIK on the general arm: known decomposition "
        f"{general.hasKnownDecomposition()} ({general.getKinematicFamily()}): "
        "no solution to compare"
    )
    puma = sk.robots.puma560()
    T_puma = puma.fk(rng.uniform(-np.pi, np.pi, (POSES, 6)))
    H, P, R_home = hp(puma)
    robot = eaik.HPRobot(H, P)
    poses = T_puma.copy()
    poses[:, :3, :3] = T_puma[:, :3, :3] @ R_home.T

    def eaik_all():
        return [robot.IK(pose) for pose in poses]

    answers = eaik_all()
    ours = general_6r_ik(puma, T_puma)
    eaik_time = best(eaik_all, 1, 3) / POSES
    eaik_cpu = cpu(eaik_all) / POSES
    puma_time = best(lambda: general_6r_ik(puma, T_puma), 1, 3)
    puma_cpu = cpu(lambda: general_6r_ik(puma, T_puma))
    closed_time = best(lambda: sk.ik.analytic_ik_all(puma, T_puma), 3, 3)
    agree = sum(
        matches(np.array(a.Q)[~np.array(a.is_LS)].reshape(-1, 6), r.Q, 1e-6)
        == len(r.Q)
        == int(np.sum(~np.array(a.is_LS)))
        for a, r in zip(answers, ours)
    )
    print(
        f"PUMA 560, {POSES} poses: EAIK's exact solution sets equal screwkit "
        f"general_6r_ik's (to 1e-6 rad) on {agree} of {POSES} poses"
    )
    print(
        f"{'EAIK (subproblems), PUMA 560, per pose':<44}{ms(eaik_time)}{'':>13}"
        f"       CPU {ms(eaik_cpu)}"
    )
    print(
        f"{'screwkit general_6r_ik, PUMA 560, batch':<44}{ms(puma_time / POSES)}"
        f"{'':>13}       CPU {ms(puma_cpu / POSES)}"
    )
    print(
        f"{'screwkit analytic_ik_all, PUMA 560, batched':<44}{ms(closed_time / POSES)}"
    )
