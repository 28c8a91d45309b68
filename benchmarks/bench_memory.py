"""Peak memory of screwkit's batch paths for 10^6 configurations of the PUMA 560
(goal: < 1 GB).

Each task runs in a fresh subprocess, so that one task's memory does not hide another's.
Per task the child builds its input (random joint vectors, seeded; poses for the IK),
warms the compiled functions up on ten configurations, then runs the call twice:

* once plainly, for the time and the process's peak resident set (``ru_maxrss``: the
  whole interpreter, NumPy, SymPy, the input and the result: what the operating system
  sees);
* once under ``tracemalloc``, for the peak of the memory the call itself allocated on
  top of its input (NumPy reports its buffers to tracemalloc), its result included.

The goal is met when the process peak stays under 1 GB. Printed, never asserted.
Usage (from the top level): .venv/bin/python benchmarks/bench_memory.py [task ...]
"""

import json
import subprocess
import sys

N = 1_000_000
GOAL_MB = 1000.0

TASKS = {
    "fk": "puma.fk(Q)",
    "geometric_jacobian": "puma.geometric_jacobian(Q)",
    "manipulability": "puma.manipulability(Q)",
    "puma560_ik_all": "sk.ik.puma560_ik_all(T)",
    "sweep 215^3 (q1, q2, q3)": (
        "sk.workspace.sweep(puma, {1: (-3, 3), 2: (-3, 3), 3: (-3, 3)}, num=215)"
    ),
    "sweep 100^3 + singular()": (
        "sk.workspace.sweep(puma, {1: (-3, 3), 2: (-3, 3), 3: (-3, 3)}, "
        "num=100).singular()"
    ),
    "sweep 301^3 (refused)": (
        "refuse(lambda: sk.workspace.sweep(puma, {1: (0, 1), 2: (0, 1), 3: (0, 1)}))"
    ),
}

CHILD = r"""
import json, resource, sys, time, tracemalloc
import numpy as np
import screwkit as sk

def refuse(call):
    try:
        call()
    except ValueError as error:
        return str(error)
    raise AssertionError("the sweep was not refused")

puma = sk.robots.puma560()
Q = np.random.default_rng(0).uniform(-np.pi, np.pi, ({n}, 6))
T = puma.fk(Q) if "ik" in {task!r} else None
puma.fk(Q[:10]); puma.geometric_jacobian(Q[:10]); puma.manipulability(Q[:10])
sk.ik.puma560_ik_all(puma.fk(Q[:10]))
inputs = (Q.nbytes + (T.nbytes if T is not None else 0)) / 1e6
start = time.perf_counter()
result = {expression}
seconds = time.perf_counter() - start
size = result.nbytes / 1e6 if isinstance(result, np.ndarray) else (
    result.points.nbytes / 1e6 if hasattr(result, "points") else 0.0)
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
del result
tracemalloc.start()
result = {expression}
traced = tracemalloc.get_traced_memory()[1] / 1e6
tracemalloc.stop()
print(json.dumps(dict(seconds=seconds, inputs=inputs, result=size, traced=traced,
                      rss=rss)))
"""


def measure(task):
    code = CHILD.format(n=N, task=task, expression=TASKS[task])
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    if done.returncode != 0:
        return {"error": done.stderr.strip().splitlines()[-1]}
    return json.loads(done.stdout.strip().splitlines()[-1])


def main(tasks):
    print(
        f"peak memory for N = {N:,} PUMA 560 configurations "
        f"(MB; goal: process peak < {GOAL_MB:.0f} MB)"
    )
    print(
        f"{'task':<28}{'time (s)':>9}{'input':>9}{'result':>9}{'call peak':>11}"
        f"{'process peak':>14}  met"
    )
    for task in tasks:
        m = measure(task)
        if "error" in m:
            print(f"{task:<28}  failed: {m['error']}")
            continue
        met = "yes" if m["rss"] < GOAL_MB else "NO"
        print(
            f"{task:<28}{m['seconds']:>9.2f}{m['inputs']:>9.0f}{m['result']:>9.0f}{m['traced']:>11.0f}"
            f"{m['rss']:>14.0f}  {met}"
        )


if __name__ == "__main__":
    main(sys.argv[1:] or list(TASKS))
