"""Every assembly mode of a parallel manipulator for given actuated values.

- :func:`rpr_sextic`: the planar 3-RPR's univariate polynomial (Gosselin, Sefrioui &
  Richard 1992). Two of the three loop equations minus the first are linear in the
  platform point q once the angle phi is fixed; with t = tan((phi - phi0) / 2) Cramer's
  rule gives q as ratios of polynomials in t and the first equation becomes one
  polynomial of degree 8 in t, which holds the factor (1 + t^2) (the circular points)
  and leaves the sextic. Its real roots are every real assembly mode; each is polished
  by Newton on the loop closure and checked.
- :func:`spheres`: the delta's closed form: the platform's origin is where three
  spheres of radius l2 meet (centred at the elbows less the platform points): two
  points, one or none, or a continuum when the centres are collinear;
- :func:`rails`: the Tripteron's closed form, a linear system in the platform's origin;
- :func:`continuum`: whether a mode found lies on a continuum of solutions (the
  closure's Jacobian loses rank there, and a step along its kernel projects back onto
  solutions);
- :func:`multistart`: Newton from many seeded starting poses (and their mirror images
  through the base plane, which keep every leg length when base and platform points are
  planar). Every pose returned satisfies the legs to ``PARALLEL_FK_ACCEPT_TOL`` times
  the mechanism's size; the search is not proven complete: it reports what its starts
  reached.
"""

import numpy as np

from .._checks import as_float_array, check_flag
from .._docstrings import fill
from ..orientation import rotation_from_quaternion
from ..tolerances import (
    LENGTH_TOL,
    PARALLEL_CONTINUUM_STEP,
    PARALLEL_CRAMER_TOL,
    PARALLEL_FK_ACCEPT_TOL,
    PARALLEL_FLAT_TOL,
    PARALLEL_HEIGHT_DECIMALS,
    PARALLEL_POLISH_TOL,
    PARALLEL_POLY_ZERO_TOL,
    PARALLEL_RANK_TOL,
    PARALLEL_REAL_ROOT_TOL,
    PARALLEL_SAME_POSE_TOL,
    PARALLEL_SPHERES_TOL,
)
from . import numeric as _numeric

__all__ = [
    "AssemblyModes",
    "rpr_sextic",
    "spheres",
    "rails",
    "continuum",
    "sort_modes",
    "random_starts",
    "multistart",
]


class AssemblyModes(list):
    """The assembly modes ``fk_all`` found: a list of poses that says how far to
    trust it.

    Parameters
    ----------
    poses : iterable of ndarray, shape (4, 4)
        The assembly modes (platform poses, m).
    complete : bool
        True only when the list is proven to hold every real assembly mode (a closed
        form, or a certified solver); False for a search or a float root finder.
    method : str
        How the modes were found: 'closed form (three spheres)', 'closed form
        (linear)', 'sextic (floating-point roots)', 'multistart search', ...
    reason : str or None
        Why ``complete`` is False (or what the continuum is); None when complete.
    continuum : bool
        True when the solutions include a continuum (a self-motion, a degenerate
        geometry): the poses listed are then samples of it, not every solution.

    Examples
    --------
    >>> modes = AssemblyModes([], complete=False, method="multistart search",
    ...                       reason="a search: it may miss modes")
    >>> modes, modes.complete
    ([], False)
    """

    def __init__(
        self, poses=(), complete=False, method="", reason=None, continuum=False
    ):
        super().__init__(poses)
        self.complete = bool(complete)
        self.method = method
        self.reason = reason
        self.continuum = bool(continuum)


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

    Examples
    --------
    The default 3-RPR at ``RPR_SIX_MODES_RHO``: six real roots of the sextic, six
    assembly modes (the most there can be).

    >>> from screwkit.parallel import RPR_SIX_MODES_RHO, planar_3rpr
    >>> poses, sextic = rpr_sextic(planar_3rpr(), RPR_SIX_MODES_RHO, True)
    >>> len(poses), sextic.degree()
    (6, 6)
    """
    if not (pm.planar and pm.prismatic and pm.m == 3):
        raise ValueError(
            f"pm must be a planar 3-RPR (sk.parallel.planar_3rpr()), got {pm!r}"
        )
    rho = as_float_array(rho, "rho")
    if rho.shape != (3,):
        raise ValueError(f"rho must be 3 leg lengths (m), got shape {rho.shape}")
    with_polynomial = check_flag(with_polynomial, "with_polynomial")
    poses, poly, _ = _sextic_modes(pm, rho)
    return (poses, poly) if with_polynomial else poses


def _sextic_modes(pm, rho):
    """The sextic's modes, the polynomial, and starting poses at the real roots where
    Cramer's rule fails (the platform angle of a continuum, or of a mode the two linear
    equations do not fix): the first leg's circle sampled at that angle."""
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
    candidates, stuck = [], []
    for t in real:
        phi = phi0 + 2 * np.arctan(t)
        c, s = np.cos(phi), np.sin(phi)
        R = np.array([[c, -s], [s, c]])
        q = solve_q(t)
        if q is None:  # q on leg 0's circle: Newton finds the rest, if anything
            for k in range(8):
                T = np.eye(4)
                u = np.array([np.cos(k * np.pi / 4), np.sin(k * np.pi / 4)])
                T[:2, :2], T[:2, 3] = R, a[0] + rho[0] * u - R @ b[0]
                stuck.append(T)
            continue
        T = np.eye(4)
        T[:2, :2], T[:2, 3] = R, q - R @ b[0]
        candidates.append(T)
    poses = _polish(pm, rho, candidates)
    poses.sort(key=lambda T: np.arctan2(T[1, 0], T[0, 0]))
    return poses, poly, stuck


def cramer_octic(rows, rhs, a0, rho0):
    """The 3-RPR's elimination after the loops are made linear in q: Cramer's rule
    q = (Nx, Ny) / D on the two linear rows, put into the first loop
    ``|q - a0|^2 = rho0^2``, times D^2. Written once for NumPy polynomials (the float
    sextic) and SymPy expressions (the exact one of :mod:`screwkit.parallel.proven`).

    Returns
    -------
    D, Nx, Ny, octic
        The determinant, the numerators, and the polynomial of degree 8 in t.
    """
    (r2x, r2y), (r3x, r3y) = rows
    D = r2x * r3y - r2y * r3x
    Nx = rhs[0] * r3y - rhs[1] * r2y
    Ny = r2x * rhs[1] - r3x * rhs[0]
    octic = (Nx - a0[0] * D) ** 2 + (Ny - a0[1] * D) ** 2 - rho0**2 * D**2
    return D, Nx, Ny, octic


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
    D, Nx, Ny, octic = cramer_octic(rows, rhs, a[0], rho[0])
    sextic, remainder = divmod(octic, W)
    if np.max(np.abs(remainder.coef)) > PARALLEL_POLY_ZERO_TOL * np.max(
        np.abs(octic.coef)
    ):
        sextic = octic  # not divisible (a degenerate geometry): keep every root

    def solve_q(t):
        d = D(t)
        if abs(d) <= PARALLEL_CRAMER_TOL * np.max(np.abs(D.coef)):  # relative
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


def spheres(pm, rho):
    """The delta's assembly modes in closed form: where three spheres meet.

    With the crank angles fixed, elbow i is B_i and the platform point C_i = p + R b_i
    (R the constant rotation) lies at l2 from it: the origin p is on the sphere of
    radius l2 about c_i = B_i - R b_i. Three equal spheres meet on the line through
    the centres' circumcentre O normal to their plane, at p = O +/- h n with
    h^2 = l2^2 - |O - c_0|^2: two modes (mirror images through the centres' plane),
    one where the spheres touch, none where they miss. Collinear centres give a
    continuum (a circle, or the whole sphere where the centres coincide) or none.

    Parameters
    ----------
    pm : ParallelManipulator
        A translational mechanism with crank legs (``sk.parallel.delta()``).
    rho : ndarray, shape (3,)
        The crank angles (rad).

    Returns
    -------
    poses : list of ndarray, shape (4, 4)
        Every assembly mode (a sample of it for a continuum).
    continuum : str or None
        What the continuum is, or None for isolated modes.

    Examples
    --------
    The delta's crank angles at home: two modes, home (0.35 m below the base) and
    its mirror image through the plane of the spheres' centres.

    >>> from screwkit.parallel import delta
    >>> pm = delta()
    >>> poses, kind = spheres(pm, pm.ik(pm.home()))
    >>> sorted(round(float(T[2, 3]), 4) for T in poses), kind
    ([-0.35, 0.2357], None)
    """
    legs, home = pm._legs, pm.home()
    R = home[:3, :3]
    B, _ = legs._crank(np.asarray(rho, dtype=float)[None])
    c = (B[:, 0, :] - R @ pm.platform_points.T).T  # (3, 3): one centre a row
    l2, scale = legs.l2, pm.scale
    a, b = c[1] - c[0], c[2] - c[0]
    n = np.cross(a, b)
    area = np.linalg.norm(n)  # twice the centres' triangle's area (m^2)
    close = LENGTH_TOL * scale
    if area <= PARALLEL_RANK_TOL * max(np.dot(a, a), np.dot(b, b), close**2):
        return _collinear_spheres(c, l2, R, close)
    O = c[0] + np.cross(np.dot(a, a) * b - np.dot(b, b) * a, n) / (2 * area**2)
    h2 = l2**2 - np.dot(O - c[0], O - c[0])
    if h2 < -PARALLEL_SPHERES_TOL * l2**2:
        return [], None
    h = np.sqrt(max(h2, 0.0))
    points = (
        [O]
        if h2 <= PARALLEL_SPHERES_TOL * l2**2
        else [O + h * n / area, O - h * n / area]
    )
    return [_translation(R, p) for p in points], None


def _translation(R, p):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, p
    return T


def _collinear_spheres(c, l2, R, close):
    """Three spheres of radius l2 about collinear centres c (3, 3)."""
    distinct = [c[0]]
    for centre in c[1:]:
        if all(np.linalg.norm(centre - d) > close for d in distinct):
            distinct.append(centre)
    if len(distinct) == 1:  # one sphere: every point of it
        sample = c[0] + [0.0, 0.0, -l2]
        return [_translation(R, sample)], (
            f"the three spheres coincide: every point at {l2:.6g} m from "
            f"{np.round(c[0], 9).tolist()} is an assembly mode (a sphere of them)"
        )
    if len(distinct) == 3:  # equidistant from three collinear points: nowhere
        return [], None
    d = distinct[1] - distinct[0]
    half = np.linalg.norm(d) / 2
    r2 = l2**2 - half**2
    if r2 < -PARALLEL_SPHERES_TOL * l2**2:
        return [], None
    middle = distinct[0] + d / 2
    if r2 <= PARALLEL_SPHERES_TOL * l2**2:
        return [_translation(R, middle)], None
    normal = np.cross(d, [1.0, 0.0, 0.0] if abs(d[0]) < abs(d[2]) else [0, 0, 1.0])
    sample = middle + np.sqrt(r2) * normal / np.linalg.norm(normal)
    return [_translation(R, sample)], (
        f"two of the spheres coincide: the circle of radius {np.sqrt(r2):.6g} m about "
        f"{np.round(middle, 9).tolist()} normal to {np.round(d, 9).tolist()} is a "
        f"continuum of assembly modes"
    )


def rails(pm, rho):
    """The Tripteron's assembly mode in closed form: a linear system in the origin.

    Leg i's carriage sits at e_i . (p + R b_i - A_i) = rho_i, so E p = rho +
    e_i . (A_i - R b_i) with E's rows the rails' directions e_i; the mode exists when
    every leg's two links reach across (within l1 + l2 and above |l1 - l2|).

    Parameters
    ----------
    pm : ParallelManipulator
        A translational mechanism with linear legs (``sk.parallel.tripteron()``).
    rho : ndarray, shape (3,)
        The carriages' positions (m).

    Returns
    -------
    poses : list of ndarray, shape (4, 4)
        The assembly mode, or none where a leg cannot reach.
    continuum : str or None
        What the continuum is (rails in one plane), or None.

    Examples
    --------
    Three perpendicular rails: one mode, the Tripteron's home at (0.35, 0.35, 0.35).

    >>> from screwkit.parallel import tripteron
    >>> pm = tripteron()
    >>> poses, kind = rails(pm, pm.ik(pm.home()))
    >>> len(poses), poses[0][:3, 3].round(12), kind
    (1, array([0.35, 0.35, 0.35]), None)
    """
    legs, R = pm._legs, pm.home()[:3, :3]
    E = legs.e[:, 0, :].T  # (3, 3): one rail a row
    A = legs.A[:, 0, :].T
    rhs = np.asarray(rho, dtype=float) + np.einsum(
        "ij,ij->i", E, A - pm.platform_points @ R.T
    )
    singular = np.linalg.svd(E, compute_uv=False)
    if singular[-1] <= PARALLEL_RANK_TOL * singular[0]:
        p, *_ = np.linalg.lstsq(E, rhs, rcond=PARALLEL_RANK_TOL)
        if np.max(np.abs(E @ p - rhs)) > PARALLEL_FK_ACCEPT_TOL * pm.scale:
            return [], None
        poses, reason = (
            [_translation(R, p)],
            (
                "the rails are not independent: the platform slides freely along their "
                "common normal"
            ),
        )
    else:
        poses, reason = [_translation(R, np.linalg.solve(E, rhs))], None
    C = _numeric.points(R[None], poses[0][None, :3, 3], pm.platform_points)
    _, ok, _ = legs.ik(C, np.ones(pm.m))
    return (poses, reason) if ok.all() else ([], None)


def continuum(pm, rho, poses, starts=()):
    """Whether the solutions with actuated values rho include a continuum.

    At each pose (and at each of ``starts`` projected onto the solutions by
    least-squares Newton) the loop closure's Jacobian over the free twist components
    (linear columns times the scale) is checked for rank; where it loses rank, the pose
    is stepped ``PARALLEL_CONTINUUM_STEP`` along the kernel and projected back: if it
    lands on a solution that far from the first, the solutions there form a continuum
    (an isolated double mode, a direct singularity, projects back onto itself or not at
    all).

    Parameters
    ----------
    pm : ParallelManipulator
    rho : ndarray, shape (m,)
        The actuated values (m or rad).
    poses : list of ndarray, shape (4, 4)
        Assembly modes found.
    starts : sequence of ndarray, shape (4, 4)
        More starting poses, projected onto the solutions first.

    Returns
    -------
    isolated : list of ndarray, shape (4, 4)
        The poses that are not on a continuum (with the distinct regular modes the
        starts reached).
    on_continuum : ndarray, shape (4, 4), or None
        One pose of a continuum.
    reason : str or None
        The continuum's dimension (at least), or None.

    Examples
    --------
    A 3-RPR at a regular pose (legs 5, 4 and 4 m): an isolated mode.

    >>> from screwkit.parallel import planar_3rpr
    >>> from screwkit.transforms import transl
    >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
    ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
    >>> isolated, on_continuum, reason = continuum(pm, [5.0, 4.0, 4.0], [pm.home()])
    >>> len(isolated), on_continuum, reason
    (1, None, None)
    """
    candidates = list(poses)
    if len(starts):
        T, ok = _project(pm, rho, np.array(starts))
        candidates += list(T[ok])
    if not candidates:
        return [], None, None
    T = np.array(candidates)
    rhos = np.broadcast_to(rho, (len(T), pm.m))
    _, rows = _numeric.closure_rows(
        pm._legs, pm.platform_points, pm.freedoms, T, rhos, pm.scale
    )
    _, sigma, vt = np.linalg.svd(rows)
    k = rows.shape[-1]
    units = np.array([1.0, 1.0, 1.0, pm.scale, pm.scale, pm.scale])[pm.freedoms]
    isolated, found, reason = [], None, None
    for n, pose in enumerate(T):
        given = n < len(poses)
        rank = int(np.sum(sigma[n] > PARALLEL_RANK_TOL * sigma[n, 0]))
        if rank == k:  # a regular mode (one the starts reached is kept if new)
            if given or not any(_same_pose(pose, P, pm.scale) for P in isolated):
                isolated.append(pose)
            continue
        if found is not None and not given:
            continue
        step = PARALLEL_CONTINUUM_STEP * vt[n, rank:] * units  # along the kernel
        moved = np.array([_moved(pm, pose, s) for s in np.vstack([step, -step])])
        back, ok = _project(pm, rho, moved)
        if any(
            ok[i] and not _same_pose(back[i], pose, pm.scale) for i in range(len(back))
        ):
            if found is None:
                found = pose
                reason = (
                    f"a continuum of assembly modes: the loop closure's Jacobian has "
                    f"rank {rank} of {k} at the pose listed, and poses a step away "
                    f"along its kernel solve the legs too (a self-motion or a "
                    f"degenerate geometry, of dimension up to {k - rank})"
                )
        elif given:
            isolated.append(pose)
    return isolated, found, reason


def _moved(pm, T, twist):
    """T moved by the free twist components ``twist`` (first order, as Newton)."""
    V = np.zeros(6)
    V[pm.freedoms] = twist
    w, v = V[:3], V[3:]
    out = T.copy()
    out[:3, :3] = _numeric._exp_rotation(w[None])[0] @ T[:3, :3]
    out[:3, 3] = T[:3, 3] + v + np.cross(w, T[:3, 3])
    return out


def _project(pm, rho, T0):
    """Least-squares Newton from the poses T0 onto the solutions."""
    T, ok, _, _ = _numeric.newton(
        pm._legs,
        pm.platform_points,
        pm.freedoms,
        np.broadcast_to(rho, (len(T0), pm.m)),
        T0,
        PARALLEL_POLISH_TOL * pm.scale,
        _POLISH_ITERATIONS,
        pm.scale,
        least_squares=True,
    )
    return T, ok


def sort_modes(pm, poses):
    """Assembly modes in fk_all's order.

    Spatial and translational modes by height (platform above the base first), then by
    distance from home; planar ones by the platform's angle.

    Parameters
    ----------
    pm : ParallelManipulator
    poses : list of ndarray, shape (4, 4)

    Returns
    -------
    list of ndarray, shape (4, 4)

    Examples
    --------
    The six modes of the default 3-RPR, given in reverse, come back in the order of
    the platform's angle:

    >>> from screwkit.parallel import RPR_SIX_MODES_RHO, planar_3rpr
    >>> pm = planar_3rpr()
    >>> poses = sort_modes(pm, rpr_sextic(pm, RPR_SIX_MODES_RHO)[::-1])
    >>> angles = [np.arctan2(T[1, 0], T[0, 0]) for T in poses]
    >>> angles == sorted(angles)
    True
    """
    if pm.planar:
        return sorted(poses, key=lambda T: np.arctan2(T[1, 0], T[0, 0]))
    home = pm.home()
    return sorted(
        poses,
        key=lambda T: (
            np.round(-T[2, 3] / pm.scale, PARALLEL_HEIGHT_DECIMALS),
            np.max(np.abs(T - home)),
        ),
    )


_SEARCH = """Parameters
----------
pm : ParallelManipulator
rho : ndarray, shape (m,)
    The actuated joint values (m or rad).
starts : int
    How many random starting poses.
seed : int
    The seed of the random starts (the search is deterministic)."""


@fill(search=_SEARCH)
def random_starts(pm, rho, starts, seed):
    """The search's seeded starting poses around the home pose.

    {search}

    Returns
    -------
    ndarray, shape (starts, 4, 4)

    Examples
    --------
    A planar mechanism's starts stay in its plane (z = 0), with proper rotations:

    >>> from screwkit.parallel import planar_3rpr
    >>> T0 = random_starts(planar_3rpr(), [1.0, 1.0, 1.0], starts=3, seed=0)
    >>> T0.shape, T0[:, 2, 3].tolist()
    ((3, 4, 4), [0.0, 0.0, 0.0])
    >>> bool(np.allclose(np.linalg.det(T0[:, :3, :3]), 1.0))
    True
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
    return T0


@fill(search=_SEARCH)
def multistart(pm, rho, starts, seed):
    """Assembly modes by Newton from many seeded random poses: not proven complete.

    The starts are ``starts`` poses around the home pose (random rotations for a
    spatial mechanism, random angles for a planar one; offsets within the longest leg,
    or the base's size plus the mechanism's scale for crank legs), and for a spatial
    mechanism whose base and platform points are flat, the mirror images of the poses
    found through the base plane. ``pm.fk_all(rho)`` calls it for every mechanism but
    the 3-RPR, the 3-RRR, the delta and the Tripteron.

    {search}

    Returns
    -------
    list of ndarray, shape (4, 4)
        The distinct poses found that satisfy the legs, highest platform first.

    Examples
    --------
    The Stewart-Gough platform's leg lengths at home: the search finds home among
    its modes, and its mirror image through the base (1 m below) too.

    >>> from screwkit.parallel import stewart_gough
    >>> pm = stewart_gough()
    >>> poses = multistart(pm, pm.ik(pm.home()), starts=20, seed=0)
    >>> any(np.allclose(T, pm.home(), atol=1e-8) for T in poses)
    True
    >>> any(abs(T[2, 3] + 1.0) < 1e-8 for T in poses)
    True
    """
    T0 = random_starts(pm, rho, starts, seed)
    poses = _polish(pm, rho, list(T0))
    flat = np.all(np.abs(pm.base_points[:, 2]) <= PARALLEL_FLAT_TOL * pm.scale) and (
        np.all(np.abs(pm.platform_points[:, 2]) <= PARALLEL_FLAT_TOL * pm.scale)
    )
    if pm.motion == "spatial" and flat:  # the mirror image through the base plane
        M = np.diag([1.0, 1.0, -1.0, 1.0])
        poses = _polish(pm, rho, poses + [M @ T @ M for T in poses])
    return sort_modes(pm, poses)
