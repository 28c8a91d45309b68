"""Time screwkit.parallel against a plain NumPy loop (one pose at a time, the way the
Stewart-platform scripts on GitHub compute), for what a user runs:

- Stewart-Gough IK of 100,000 poses (one ``pm.ik`` call, input checks included);
- its Jacobian for 100,000 poses (``pm.jacobian``);
- batched FK of 10,000 poses (``pm.fk`` by Newton from the home pose);
- every assembly mode of one 3-RPR input (``pm.fk_all``, the sextic);
- the assembly modes of one Stewart-Gough input (``pm.fk_all``, the multistart
  search from 400 starts, goal 50 ms; its reference is Newton from the same 400
  starts one at a time, scaled from 40).

The NumPy loops run on a slice (1,000 or 200 poses) and are scaled to the full count
(per-pose cost is constant); the 3-RPR's reference is a scan of 100,001 platform angles
solving the two linear equations at each (what one does without the sextic).
"first call" is a fresh mechanism's first call; "steady" the best of 11 repeated calls.
Usage: python benchmarks/bench_parallel.py
"""

import sys
import timeit
from pathlib import Path

import numpy as np

from screwkit import parallel

# the tests' hand-written references (tests/references.py)
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))
from references import rpr_mode_count  # noqa: E402

RNG = np.random.default_rng(0)
N_IK, N_FK = 100_000, 10_000


def best(function, number=1, repeat=11):
    return min(timeit.repeat(function, number=number, repeat=repeat)) / number


def first(function):
    return timeit.timeit(function, number=1)


def random_poses(pm, n):
    T = np.repeat(pm.home()[None], n, axis=0)
    angles = RNG.uniform(-0.15, 0.15, (n, 3))
    cx, sx = np.cos(angles[:, 0]), np.sin(angles[:, 0])
    cy, sy = np.cos(angles[:, 1]), np.sin(angles[:, 1])
    cz, sz = np.cos(angles[:, 2]), np.sin(angles[:, 2])
    T[:, 0, :3] = np.c_[cy * cz, -cy * sz, sy]
    T[:, 1, :3] = np.c_[sx * sy * cz + cx * sz, -sx * sy * sz + cx * cz, -sx * cy]
    T[:, 2, :3] = np.c_[-cx * sy * cz + sx * sz, cx * sy * sz + sx * cz, cx * cy]
    T[:, :3, 3] += RNG.uniform(-0.1, 0.1, (n, 3))
    return T


def loop_ik(pm, T):
    out = np.empty((len(T), pm.m))
    for n, t in enumerate(T):
        for i in range(pm.m):
            out[n, i] = np.linalg.norm(
                t[:3, :3] @ pm.platform_points[i] + t[:3, 3] - pm.base_points[i]
            )
    return out


def loop_jacobian(pm, T):
    out = np.empty((len(T), pm.m, 6))
    for n, t in enumerate(T):
        for i in range(pm.m):
            d = t[:3, :3] @ pm.platform_points[i] + t[:3, 3] - pm.base_points[i]
            u = d / np.linalg.norm(d)
            out[n, i] = np.r_[np.cross(pm.base_points[i], u), u]
    return out


def loop_fk(pm, rho, guess):
    out = np.empty((len(rho), 4, 4))
    for n, r in enumerate(rho):
        T = guess.copy()
        for _ in range(20):
            J = loop_jacobian(pm, T[None])[0]
            error = loop_ik(pm, T[None])[0] - r
            if np.max(np.abs(error)) < 1e-12:
                break
            step = np.linalg.solve(J, -error)
            w, v = step[:3], step[3:]
            angle = np.linalg.norm(w)
            K = np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])
            R = (
                np.eye(3) + K
                if angle < 1e-12
                else (
                    np.eye(3)
                    + np.sin(angle) / angle * K
                    + (1 - np.cos(angle)) / angle**2 * K @ K
                )
            )
            T[:3, :3] = R @ T[:3, :3]
            T[:3, 3] = T[:3, 3] + v + np.cross(w, T[:3, 3])
        out[n] = T
    return out


def scan_rpr(pm, rho, samples=100_001):
    """The 3-RPR's modes by the tests' dense scan (tests/references.py)."""
    a, b = pm.base_points[:, :2], pm.platform_points[:, :2]
    return rpr_mode_count(a, b, rho, samples)


def main():
    stewart = parallel.stewart_gough()
    T = random_poses(stewart, N_IK)
    rho = stewart.ik(T)
    assert np.allclose(loop_ik(stewart, T[:100]), rho[:100], atol=1e-12)
    assert np.allclose(loop_jacobian(stewart, T[:100]), stewart.jacobian(T[:100]))
    rho_fk, home = rho[:N_FK], stewart.home()
    check = stewart.fk(rho_fk, guess=home)
    assert check.success.all() and np.max(np.abs(check.T - T[:N_FK])) < 1e-9
    assert np.allclose(loop_fk(stewart, rho_fk[:20], home), T[:20], atol=1e-9)
    rpr = parallel.planar_3rpr()
    six = np.array(parallel.RPR_SIX_MODES_RHO)
    assert len(rpr.fk_all(six)) == scan_rpr(rpr, six) == 6

    tilted = T[7]
    rho_all = stewart.ik(tilted)
    starts = parallel.search.random_starts(stewart, rho_all, 400, 0)

    rows = [
        (
            "Stewart IK, 1e5 poses",
            lambda: parallel.stewart_gough().ik(T),
            lambda: stewart.ik(T),
            lambda: loop_ik(stewart, T[:1000]),
            100,
            0.020,
        ),
        (
            "Stewart J, 1e5 poses",
            lambda: parallel.stewart_gough().jacobian(T),
            lambda: stewart.jacobian(T),
            lambda: loop_jacobian(stewart, T[:1000]),
            100,
            0.060,
        ),
        (
            "Stewart FK, 1e4 poses",
            lambda: parallel.stewart_gough().fk(rho_fk, guess=home),
            lambda: stewart.fk(rho_fk, guess=home),
            lambda: loop_fk(stewart, rho_fk[:200], home),
            50,
            0.300,
        ),
        (
            "3-RPR fk_all, one input",
            lambda: parallel.planar_3rpr().fk_all(six),
            lambda: rpr.fk_all(six),
            lambda: scan_rpr(rpr, six),
            1,
            0.100,
        ),
        (
            "Stewart fk_all, one input",
            lambda: parallel.stewart_gough().fk_all(rho_all),
            lambda: stewart.fk_all(rho_all),
            lambda: [loop_fk(stewart, rho_all[None], T0) for T0 in starts[:40]],
            10,
            0.050,
        ),
    ]
    print(
        f"{'task':<25}{'first call':>12}{'steady':>11}{'NumPy loop':>13}{'ratio':>8}"
        f"{'goal':>10}  met"
    )
    for task, fresh, steady, loop, scale, goal in rows:
        t_first = first(fresh)
        t_steady = best(steady)
        t_loop = best(loop, repeat=2) * scale
        met = "yes" if t_steady <= goal else "NO"
        print(
            f"{task:<25}{t_first * 1e3:>9.1f} ms{t_steady * 1e3:>8.1f} ms"
            f"{t_loop * 1e3:>10.0f} ms{t_loop / t_steady:>7.0f}x"
            f"{goal * 1e3:>7.0f} ms  {met}"
        )
    print("\nNumPy loops: one pose at a time, scaled from 1,000 (IK, J) or 200 (FK)")
    print("poses; the 3-RPR reference scans 100,001 platform angles (counts modes).")


if __name__ == "__main__":
    main()
