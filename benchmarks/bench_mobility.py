"""Time what a user runs, ``sk.mobility(sk.robots.pm_X())`` (building the limbs
included), against pyScrew4Mobility (the paper's Table 1).

The paper reports 1.16, 5.24, 9.01 and 25.9 s (its machine); on this project's 2-core
machines the paper's code takes about 0.79, 3.55, 8.96 and 13.5 s (measured when issue
11 was filed). The goal is 100x faster than the paper's code on this machine.

Two times per mechanism:
* first call: in a fresh Python process, after ``import screwkit`` (not timed), the
  first ``sk.mobility(sk.robots.pm_X())``: SymPy's caches are cold, as in a new
  notebook;
* best of 7: the same call repeated in one process (SymPy's caches warm).

Usage: python benchmarks/bench_mobility.py
"""

import os
import subprocess
import sys
import time

import screwkit as sk

CASES = [  # name, builder, paper Table 1 (s), paper's code on this machine (s)
    ("3-PRRR", "pm_3prrr", 1.16, 0.79),
    ("3-PR(Pa)R", "pm_3prpar", 5.24, 3.55),
    ("4-PRRU", "pm_4prru", 9.01, 8.96),
    ("6-UPS", "pm_6ups", 25.9, 13.5),
]

FIRST_CALL = """
import time, screwkit as sk
start = time.perf_counter()
sk.mobility(sk.robots.{builder}())
print(time.perf_counter() - start)
"""


def first_call(builder):
    """Seconds of the first build + analysis in a fresh interpreter."""
    code = FIRST_CALL.format(builder=builder)
    output = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, check=True
    )
    return float(output.stdout.strip())


def best_of(function, repeat=7):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return min(times), result


def main():
    load = ", ".join(f"{x:.1f}" for x in os.getloadavg())
    print(f"load average (1, 5, 15 min): {load} on {os.cpu_count()} cores")
    print(
        f"{'mechanism':<11}{'type':>6}{'paper code':>12}{'goal':>9}{'first call':>12}"
        f"{'speed-up':>10}"
        f"{'best of 7':>11}{'speed-up':>10}"
    )
    print(f"{'':<11}{'':>6}{'here (s)':>12}{'(ms)':>9}{'(ms)':>12}{'':>10}{'(ms)':>11}")
    for name, builder, _table, here in CASES:
        build = getattr(sk.robots, builder)
        first = first_call(builder)
        best, result = best_of(lambda build=build: sk.mobility(build()))
        print(
            f"{name:<11}{result.type:>6}{here:>12.2f}{here * 10:>9.0f}"
            f"{first * 1e3:>12.1f}"
            f"{here / first:>9.0f}x{best * 1e3:>11.1f}{here / best:>9.0f}x"
        )


if __name__ == "__main__":
    main()
