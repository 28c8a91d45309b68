"""Shared by the benchmark scripts: best-of timing, the table against the RTB, the
optional peers."""

import importlib
import timeit


def best(function, number=1, repeat=3):
    """The best time of ``repeat`` runs of ``number`` calls, per call (s)."""
    return min(timeit.repeat(function, number=number, repeat=repeat)) / number


def ms(seconds):
    return f"{seconds * 1e3:>10.3f} ms" if seconds is not None else f"{'-':>13}"


def print_table(rows, width=27):
    """rows: (task, screwkit s, RTB s or None, RTB path, goal s or None)."""
    print(
        f"{'task':<{width}}{'screwkit':>13}{'RTB':>13}{'speed-up':>9}  "
        f"{'RTB path':<21}{'goal':>13}  met"
    )
    for task, t_ours, t_theirs, path, goal in rows:
        ratio = f"{t_theirs / t_ours:>8.1f}x" if t_theirs else f"{'-':>9}"
        met = "" if goal is None else ("yes" if t_ours < goal else "NO")
        print(
            f"{task:<{width}}{ms(t_ours)}{ms(t_theirs)}{ratio}  "
            f"{path:<21}{ms(goal)}  {met}"
        )


def peer(module, title, package):
    """The module of an optional peer library, or None after saying it is not installed
    (``pip install package``): the benchmark then runs without it."""
    try:
        return importlib.import_module(module)
    except ImportError:
        print(f"{title}: not installed (pip install {package})")
        return None
