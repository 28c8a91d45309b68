"""Every assembly mode of a parallel manipulator for given actuated values.

- :func:`rpr_sextic`: the planar 3-RPR's univariate polynomial (Gosselin, Sefrioui &
  Richard 1992). Two of the three loop equations minus the first are linear in the
  platform point q once the angle phi is fixed; with t = tan((phi - phi0) / 2) Cramer's
  rule gives q as ratios of polynomials in t and the first equation becomes one
  polynomial of degree 8 in t, which holds the factor (1 + t^2) (the circular points)
  and leaves the sextic. Its real roots are every real assembly mode; each is polished
  by Newton on the loop closure and checked.
- :func:`multistart`: Newton from many seeded starting poses (and their mirror images
  through the base plane, which keep every leg length when base and platform points are
  planar). Every pose returned satisfies the legs to ``PARALLEL_FK_ACCEPT_TOL`` times
  the mechanism's size; the search is not proven complete: it reports what its starts
  reached.
"""

import numpy as np

from .._checks import as_float_array
from ..orientation import rotation_from_quaternion
from ..tolerances import (
    PARALLEL_CRAMER_TOL,
    PARALLEL_FLAT_TOL,
    PARALLEL_HEIGHT_DECIMALS,
    PARALLEL_POLISH_TOL,
    PARALLEL_POLY_ZERO_TOL,
    PARALLEL_REAL_ROOT_TOL,
    PARALLEL_SAME_POSE_TOL,
)

__all__ = ["rpr_sextic", "multistart"]

#: Newton iterations when polishing a candidate assembly mode (each starts close).
_POLISH_ITERATIONS = 30


def _poly(*coefficients):
    return np.polynomial.Polynomial(coefficients)


def rpr_sextic(pm, rho, with_polynomial=False):
    """Every real assembly mode of a planar 3-RPR, from its sextic (Gosselin, Sefrioui
    & Richard 1992).

    Complete: each real root of the sextic in t = tan((phi - phi0) / 2) is one assembly
    mode (at most six), polished by Newton on the loop closure and checked.
    ``pm.fk_all(rho)`` calls it for a 3-RPR.

    Parameters
    ----------
    pm : ParallelManipulator
        A planar 3-RPR (e.g. ``sk.parallel.planar_3rpr()``).
    rho : array-like, shape (3,)
        The leg lengths (m).
    with_polynomial : bool
        Also return the polynomial.

    Returns
    -------
    poses : list of ndarray, shape (4, 4)
        Every real assembly mode, sorted by the platform's angle phi.
    polynomial : numpy.polynomial.Polynomial
        Only with ``with_polynomial``: the sextic in t (degree 6, or 8 for a
        degenerate geometry whose octic has no factor 1 + t^2).

    Raises
    ------
    ValueError
        If ``pm`` is not a planar mechanism with prismatic legs, or ``rho`` is not
        three numbers.
    """
    if not (pm.planar and pm.prismatic and pm.m == 3):
        raise ValueError(
            f"pm must be a planar 3-RPR (sk.parallel.planar_3rpr()), got {pm!r}"
        )
    rho = as_float_array(rho, "rho")
    if rho.shape != (3,):
        raise ValueError(f"rho must be 3 leg lengths (m), got shape {rho.shape}")
    a = pm.base_points[:, :2]
    b = pm.platform_points[:, :2]
    for phi0 in (
        0.0,
        1.0,
    ):  # t = oo (phi = phi0 + pi) is a root only if the leading term dies
        poly, solve_q = _sextic(a, b - b[0], rho, phi0)
        if abs(poly.coef[-1]) > PARALLEL_POLY_ZERO_TOL * np.max(np.abs(poly.coef)):
            break
    roots = poly.roots()
    scale = 1 + np.abs(roots)
    real = roots[np.abs(roots.imag) < PARALLEL_REAL_ROOT_TOL * scale].real
    candidates = []
    for t in real:
        phi = phi0 + 2 * np.arctan(t)
        q = solve_q(t)
        if q is None:
            continue
        c, s = np.cos(phi), np.sin(phi)
        R = np.array([[c, -s], [s, c]])
        T = np.eye(4)
        T[:2, :2], T[:2, 3] = R, q - R @ b[0]
        candidates.append(T)
    poses = _polish(pm, rho, candidates)
    poses.sort(key=lambda T: np.arctan2(T[1, 0], T[0, 0]))
    return (poses, poly) if with_polynomial else poses


def _sextic(a, b, rho, phi0):
    """The polynomial in t and q(t); b holds the platform points relative to b_0."""
    W, Cp, Sp = _poly(1, 0, 1), _poly(1, 0, -1), _poly(0, 2)
    c0, s0 = np.cos(phi0), np.sin(phi0)
    C, S = c0 * Cp - s0 * Sp, s0 * Cp + c0 * Sp  # W cos(phi), W sin(phi)
    rows, rhs = [], []
    for k in (1, 2):
        bx, by = b[k]
        Rb = (bx * C - by * S, bx * S + by * C)  # W R b_k
        d = a[k] - a[0]
        rows.append((2 * (Rb[0] - d[0] * W), 2 * (Rb[1] - d[1] * W)))
        constant = rho[k] ** 2 - rho[0] ** 2 - b[k] @ b[k] - a[k] @ a[k] + a[0] @ a[0]
        rhs.append(constant * W + 2 * (a[k][0] * Rb[0] + a[k][1] * Rb[1]))
    (r2x, r2y), (r3x, r3y) = rows
    D = r2x * r3y - r2y * r3x
    Nx = rhs[0] * r3y - rhs[1] * r2y
    Ny = r2x * rhs[1] - r3x * rhs[0]
    octic = (Nx - a[0][0] * D) ** 2 + (Ny - a[0][1] * D) ** 2 - rho[0] ** 2 * D**2
    sextic, remainder = divmod(octic, W)
    if np.max(np.abs(remainder.coef)) > PARALLEL_POLY_ZERO_TOL * np.max(
        np.abs(octic.coef)
    ):
        sextic = octic  # not divisible (a degenerate geometry): keep every root

    def solve_q(t):
        d = D(t)
        if abs(d) < PARALLEL_CRAMER_TOL * max(1.0, np.max(np.abs(D.coef))):
            return None
        return np.array([Nx(t), Ny(t)]) / d

    return sextic, solve_q


def _polish(pm, rho, candidates):
    """Newton from each candidate; the distinct converged poses that satisfy the
    legs."""
    if not candidates:
        return []
    T0 = np.array(candidates)
    T, success, _, _ = pm._newton(
        np.broadcast_to(rho, (len(T0), pm.m)),
        T0,
        PARALLEL_POLISH_TOL * pm.scale,
        _POLISH_ITERATIONS,
    )
    poses = []
    for pose, ok in zip(T, success):
        if ok and not any(_same_pose(pose, other, pm.scale) for other in poses):
            poses.append(pose)
    return poses


def _same_pose(T1, T2, scale):
    """Whether two poses agree in rotation and, relative to ``scale``, translation."""
    rotation = np.max(np.abs(T1[:3, :3] - T2[:3, :3]))
    translation = np.max(np.abs(T1[:3, 3] - T2[:3, 3])) / scale
    return max(rotation, translation) < PARALLEL_SAME_POSE_TOL


def multistart(pm, rho, starts, seed):
    """Assembly modes by Newton from many seeded random poses: not proven complete.

    The starts are ``starts`` poses around the home pose (random rotations for a
    spatial mechanism, random angles for a planar one; offsets within the longest leg,
    or the base's size plus the mechanism's scale for crank legs), and for a spatial
    mechanism whose base and platform points are flat, the mirror images of the poses
    found through the base plane. ``pm.fk_all(rho)`` calls it for every mechanism but
    the 3-RPR.

    Parameters
    ----------
    pm : ParallelManipulator
    rho : ndarray, shape (m,)
        The actuated joint values (m or rad).
    starts : int
        How many random starting poses.
    seed : int
        The seed of the random starts (the search is deterministic).

    Returns
    -------
    list of ndarray, shape (4, 4)
        The distinct poses found that satisfy the legs, highest platform first.
    """
    rng = np.random.default_rng(seed)
    home = pm.home()
    spread = (
        float(np.max(np.abs(rho)))
        if pm.prismatic
        else float(np.max(np.linalg.norm(pm.base_points, axis=1)) + pm.scale)
    )
    T0 = np.repeat(home[None], starts, axis=0)
    if pm.motion == "spatial":
        q = rng.normal(size=(starts, 4))  # uniform on SO(3): a normal 4-vector, unit
        T0[:, :3, :3] = rotation_from_quaternion(q / np.linalg.norm(q, axis=1)[:, None])
    elif pm.motion == "planar":
        phi = rng.uniform(-np.pi, np.pi, starts)
        T0[:, 0, 0], T0[:, 0, 1], T0[:, 1, 0], T0[:, 1, 1] = (
            np.cos(phi),
            -np.sin(phi),
            np.sin(phi),
            np.cos(phi),
        )
    offset = rng.uniform(-spread, spread, (starts, 3))
    if pm.planar:
        offset[:, 2] = 0.0
    T0[:, :3, 3] = home[:3, 3] + offset
    poses = _polish(pm, rho, list(T0))
    flat = np.all(np.abs(pm.base_points[:, 2]) <= PARALLEL_FLAT_TOL * pm.scale) and (
        np.all(np.abs(pm.platform_points[:, 2]) <= PARALLEL_FLAT_TOL * pm.scale)
    )
    if pm.motion == "spatial" and flat:  # the mirror image through the base plane
        M = np.diag([1.0, 1.0, -1.0, 1.0])
        poses = _polish(pm, rho, poses + [M @ T @ M for T in poses])
    poses.sort(
        key=lambda T: (
            np.round(-T[2, 3] / pm.scale, PARALLEL_HEIGHT_DECIMALS),
            np.max(np.abs(T - home)),
        )
    )
    return poses
