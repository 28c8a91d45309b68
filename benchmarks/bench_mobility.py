"""Time sk.mobility on the paper's four mechanisms against pyScrew4Mobility (Table 1).

The paper reports 1.16, 5.24, 9.01 and 25.9 s (its machine); on this project's 2-core
machines the paper's code takes about 0.79, 3.55, 8.96 and 13.5 s (measured when the issue
was filed). The goal is 100x faster than the paper's code on this machine.
Usage: python benchmarks/bench_mobility.py
"""
import time

import screwkit as sk

CASES = [  # name, builder, paper Table 1 (s), paper's code on this machine (s)
    ("3-PRRR", sk.robots.pm_3prrr, 1.16, 0.79),
    ("3-PR(Pa)R", sk.robots.pm_3prpar, 5.24, 3.55),
    ("4-PRRU", sk.robots.pm_4prru, 9.01, 8.96),
    ("6-UPS", sk.robots.pm_6ups, 25.9, 13.5),
]


def best_of(function, repeat=7):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - start)
    return min(times), result


print(f"{'mechanism':<11}{'type':>6}{'Table 1 (s)':>13}{'paper code here (s)':>21}{'screwkit (s)':>14}"
      f"{'speed-up':>10}{'goal (s)':>10}")
for name, build, table, here in CASES:
    limbs = build()
    seconds, result = best_of(lambda: sk.mobility(limbs))
    print(f"{name:<11}{result.type:>6}{table:>13.2f}{here:>21.2f}{seconds:>14.3f}"
          f"{here / seconds:>9.0f}x{here / 100:>10.4f}")
