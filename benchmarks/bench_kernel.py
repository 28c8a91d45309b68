"""The screw kernel: first-call and steady-state speed, agreement with Modern Robotics.

Prints three tables:
(1) the first call, as a user meets it: a fresh Python process builds the chain, then
    times its first ``fk`` and first ``geometric_jacobian`` (everything set up on the
    way counts), for chains typed from data sheets (goal: under 50 ms for up to 7
    joints);
(2) agreement with the Modern Robotics library (Lynch & Park's ``modern_robotics``), run
    side by side on random screws and poses: FKinSpace, FKinBody, JacobianSpace,
    JacobianBody, MatrixLog6 and Adjoint against screwkit, with the time of one call of
    each;
(3) steady state on the PUMA 560 (goals: one FK <= 20 us, 10^5 FK <= 30 ms, 10^5
    geometric Jacobians <= 100 ms).
Usage (from the top level): make bench,
or .venv-bench/bin/python benchmarks/bench_kernel.py
"""

import json
import subprocess
import sys

import numpy as np
from _report import best, ms

import screwkit as sk

FIRST_CALL = r"""
import json, sys, time
import numpy as np
start = time.perf_counter()
import screwkit as sk
imported = time.perf_counter()
d, rng = np.pi / 2, np.random.default_rng(7)
case = sys.argv[1]
if case == "PUMA 560, alpha typed as +-1.5708":
    table = [[0, 0, 0, 1.5708], [0, 0, 0.4318, 0], [0, 0.15005, 0.0203, -1.5708],
             [0, 0.4318, 0, 1.5708], [0, 0, 0, -1.5708], [0, 0, 0, 0]]
    chain = sk.Chain.from_table(table)
elif case == "random 6R (float DH)":
    chain = sk.Chain.from_table(np.c_[rng.uniform(-3, 3, (6, 1)),
                                      rng.uniform(0, 1, (6, 2)),
                                      rng.uniform(-3, 3, (6, 1))])
elif case == "Panda-like 7R (modified DH)":
    table = [[0, 0.333, 0, 0], [0, 0, 0, -d], [0, 0.316, 0, d], [0, 0, 0.0825, d],
             [0, 0.384, -0.0825, -d], [0, 0, 0, d], [0, 0, 0.088, d]]
    chain = sk.Chain.from_table(table, convention=sk.Convention.MODIFIED)
else:  # a 6-joint chain from screws with two helical joints
    S = [[0, 0, 1, 0, 0, 0], [0, 1, 0, -0.3, 0, 0.05], [0, 1, 0, -0.8, 0, 0.4],
         [1, 0, 0, 0, 0.8, 0.1], [0, 1, 0, -0.8, 0, 0.9], [0, 0, 0, 0, 0, 1]]
    chain = sk.Chain.from_screws(S, sk.transl(1.0, 0, 0.8))
q = rng.uniform(-1, 1, chain.n)
t0 = time.perf_counter(); chain.fk(q); t1 = time.perf_counter()
chain.geometric_jacobian(q); t2 = time.perf_counter()
print(json.dumps({"import": imported - start, "build+fk": t1 - imported,
                  "jacobian": t2 - t1}))
"""

CASES = [
    "PUMA 560, alpha typed as +-1.5708",
    "random 6R (float DH)",
    "Panda-like 7R (modified DH)",
    "6 joints from screws, 2 helical",
]


def first_calls():
    print(
        "(1) first call in a fresh process "
        "(ms; goal: build + first fk + first Jacobian < 50 ms)"
    )
    print(
        f"{'chain':<36}{'import':>10}{'build+fk':>10}{'first J':>10}{'total':>10}  met"
    )
    for case in CASES:
        runs = [
            json.loads(
                subprocess.run(
                    [sys.executable, "-c", FIRST_CALL, case],
                    check=True,
                    capture_output=True,
                    text=True,
                ).stdout
            )
            for _ in range(3)
        ]
        # best of three fresh processes
        t = {k: min(r[k] for r in runs) for k in runs[0]}
        total = t["build+fk"] + t["jacobian"]
        print(
            f"{case:<36}{t['import'] * 1e3:>10.1f}{t['build+fk'] * 1e3:>10.1f}"
            f"{t['jacobian'] * 1e3:>10.1f}{total * 1e3:>10.1f}  "
            f"{'yes' if total < 0.05 else 'NO'}"
        )


def modern_robotics():
    import modern_robotics as mr

    rng = np.random.default_rng(1)
    print(
        "\n(2) agreement with the Modern Robotics library on 200 random cases, "
        "and one call each"
    )
    print(f"{'function':<16}{'max |difference|':>18}{'screwkit':>13}{'MR':>13}")
    rows = []
    for _ in range(200):
        n = rng.integers(1, 8)
        w = rng.normal(size=(n, 3))
        w /= np.linalg.norm(w, axis=1, keepdims=True)
        axes = np.c_[w, rng.normal(size=(n, 3))]  # helical joints of random pitch
        prismatic = rng.random(n) < 0.2
        axes[prismatic, :3] = 0
        axes[prismatic, 3:] /= np.linalg.norm(
            axes[prismatic, 3:], axis=1, keepdims=True
        )
        home = sk.exp_twist(rng.normal(size=6), 1.0)
        theta = rng.uniform(-3, 3, n)
        space, body = (
            sk.Chain.from_screws(axes, home),
            sk.Chain.from_screws(axes, home, frame="body"),
        )
        T = sk.exp_twist(rng.normal(size=6), rng.uniform(0, 3))
        rows.append(
            [
                np.abs(space.fk(theta) - mr.FKinSpace(home, axes.T, theta)).max(),
                np.abs(body.fk(theta) - mr.FKinBody(home, axes.T, theta)).max(),
                np.abs(
                    space.space_jacobian(theta) - mr.JacobianSpace(axes.T, theta)
                ).max(),
                np.abs(
                    body.body_jacobian(theta) - mr.JacobianBody(axes.T, theta)
                ).max(),
                np.abs(sk.log_transform(T) - mr.se3ToVec(mr.MatrixLog6(T))).max(),
                np.abs(sk.adjoint(T) - mr.Adjoint(T)).max(),
            ]
        )
    worst = np.max(rows, axis=0)
    chain = sk.Chain.from_screws(axes, home)
    body = sk.Chain.from_screws(axes, home, frame="body")
    timings = [
        (lambda: chain.fk(theta), lambda: mr.FKinSpace(home, axes.T, theta)),
        (lambda: body.fk(theta), lambda: mr.FKinBody(home, axes.T, theta)),
        (lambda: chain.space_jacobian(theta), lambda: mr.JacobianSpace(axes.T, theta)),
        (lambda: body.body_jacobian(theta), lambda: mr.JacobianBody(axes.T, theta)),
        (lambda: sk.log_transform(T), lambda: mr.MatrixLog6(T)),
        (lambda: sk.adjoint(T), lambda: mr.Adjoint(T)),
    ]
    names = [
        "FKinSpace",
        "FKinBody",
        "JacobianSpace",
        "JacobianBody",
        "MatrixLog6",
        "Adjoint",
    ]
    for name, error, (ours, theirs) in zip(names, worst, timings):
        print(f"{name:<16}{error:>18.1e}{ms(best(ours, 2000))}{ms(best(theirs, 500))}")
    print(f"(the last timed chain has {chain.n} joints)")
    return worst


def steady_state():
    puma = sk.robots.puma560()
    Q = np.random.default_rng(0).uniform(-np.pi, np.pi, (100_000, 6))
    puma.fk(Q[0]), puma.geometric_jacobian(Q[0])
    print("\n(3) steady state, PUMA 560")
    print(f"{'task':<26}{'screwkit':>13}{'goal':>13}  met")
    for task, seconds, goal in [
        ("FK, one pose", best(lambda: puma.fk(Q[0]), 5000), 20e-6),
        ("FK, 100,000 poses", best(lambda: puma.fk(Q), 1, 7), 30e-3),
        ("geometric J, one", best(lambda: puma.geometric_jacobian(Q[0]), 5000), None),
        (
            "geometric J, 100,000",
            best(lambda: puma.geometric_jacobian(Q), 1, 7),
            100e-3,
        ),
    ]:
        print(
            f"{task:<26}{ms(seconds)}{ms(goal)}  "
            f"{'' if goal is None else ('yes' if seconds < goal else 'NO')}"
        )


if __name__ == "__main__":
    first_calls()
    worst = modern_robotics()
    steady_state()
    if worst.max() > 1e-9:
        sys.exit(f"screwkit and Modern Robotics disagree by {worst.max():.1e}")
