"""Every assembly mode with a proof (screwkit.parallel.proven) against the search
(``fk_all``, Newton from seeded random starts), side by side, on:

- Dietmaier's 6-6 platform with 40 real modes (as printed, 6 decimals), in m and in
  mm, and as the floats' exact binary values;
- the default Stewart-Gough platform at its home pose (floats of 16-17 digits);
- three random 6-6 platforms in 3 decimals;
- the default 3-RPR (six modes): ``rpr_fk_proven`` against ``rpr_sextic``.

Columns: modes found, whether the list is proven complete, wall time and CPU time (this
process plus msolve's; the wall time counts other work on a shared machine, the CPU
time does not). The search is the default 400 starts and 2000 starts.
Usage: python benchmarks/bench_parallel_proven.py (needs screwkit[proof])
"""

import os
import resource
import time
from decimal import Decimal
from platform import machine, python_version, system

import numpy as np

import screwkit as sk
from screwkit.parallel import DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO
from screwkit.parallel.proven import rpr_fk_proven, stewart_fk_proven


def cpu():
    own = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def measure(function, *args, **kwargs):
    wall, used = time.perf_counter(), cpu()
    out = function(*args, **kwargs)
    return out, time.perf_counter() - wall, cpu() - used


def mm(values):
    return np.array(
        [[float(Decimal(repr(float(v))) * 1000) for v in row] for row in values]
    )


def instances():
    yield "Dietmaier (m)", DIETMAIER_BASE, DIETMAIER_PLATFORM, DIETMAIER_RHO, {}
    yield (
        "Dietmaier (mm)",
        mm(DIETMAIER_BASE),
        mm(DIETMAIER_PLATFORM),
        mm([DIETMAIER_RHO])[0],
        {},
    )
    yield (
        "Dietmaier, binary",
        DIETMAIER_BASE,
        DIETMAIER_PLATFORM,
        DIETMAIER_RHO,
        {"rationals": "binary"},
    )
    pm = sk.parallel.stewart_gough()
    yield "default, home", pm.base_points, pm.platform_points, pm.ik(pm.home()), {}
    rng = np.random.default_rng(7)
    for k in range(3):
        base = np.round(rng.uniform(-1, 1, (6, 3)), 3)
        platform = np.round(rng.uniform(-0.6, 0.6, (6, 3)), 3)
        lengths = np.round(rng.uniform(0.8, 1.6, 6), 3)
        yield f"random {k} (3 decimals)", base, platform, lengths, {}


def main():
    load = " ".join(f"{v:.2f}" for v in os.getloadavg())
    print(
        f"# benchmarks/bench_parallel_proven.py, measured "
        f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}\n"
        f"# on {system()} {machine()}, {os.cpu_count()} cores, "
        f"load average {load}, Python {python_version()}\n"
    )
    header = (
        f"{'instance':24} {'method':14} {'modes':>5} {'proven':>6} "
        f"{'wall s':>8} {'CPU s':>8}"
    )
    print(header)
    print("-" * len(header))
    for name, base, platform, lengths, options in instances():
        (poses, complete, _), wall, used = measure(
            stewart_fk_proven, base, platform, lengths, **options
        )
        print(
            f"{name:24} {'msolve':14} {len(poses):5d} {str(complete):>6} "
            f"{wall:8.2f} {used:8.2f}"
        )
        pm = sk.parallel.stewart_gough(
            base=np.asarray(base, float),
            platform=np.asarray(platform, float),
            leg_limits=None,
        )
        for starts in (400, 2000):
            found, wall, used = measure(
                pm.fk_all, np.asarray(lengths, float), starts=starts
            )
            print(
                f"{'':24} {f'search {starts}':14} {len(found):5d} {'no':>6} "
                f"{wall:8.2f} {used:8.2f}"
            )
    pm = sk.parallel.planar_3rpr()
    rho = np.array(sk.parallel.RPR_SIX_MODES_RHO)
    (poses, complete, _), wall, used = measure(
        lambda: rpr_fk_proven(pm.base_points[:, :2], pm.platform_points[:, :2], rho)
    )
    print(
        f"{'3-RPR default':24} {'exact sextic':14} {len(poses):5d} "
        f"{str(complete):>6} {wall:8.2f} {used:8.2f}"
    )
    found, wall, used = measure(lambda: sk.parallel.rpr_sextic(pm, rho))
    print(f"{'':24} {'rpr_sextic':14} {len(found):5d} {'-':>6} {wall:8.2f} {used:8.2f}")


if __name__ == "__main__":
    main()
