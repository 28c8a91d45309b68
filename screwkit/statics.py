"""Statics by wrenches: joint torques, gravity, wrenches moved, transmission, stiffness.

The book orders a wrench (f; m), force first, and a twist (omega; v): a twist V and a
wrench w do the power V^T Pi w = omega . m + v . f, where Pi swaps the two halves of a
6-vector. Virtual work then gives the joint torques that hold a wrench at the tool:

    tau = J_s^T Pi w_s = J_b^T Pi w_b,

with w_s the wrench in the base (space) frame, its moment about the base origin, and
w_b in the tool (body) frame, its moment about the tool origin. Modern Robotics orders a
wrench (m; f) and writes tau = J^T F: the same torques, since its F is Pi w.

**Sign convention** (as Modern Robotics, ch. 5): w is the wrench **the arm applies to
the environment** at its tool, and tau the torques its motors apply to hold it still.
To hold a load of mass M (the load pulls down with M g), the arm applies the upward
force -M g; to push on a wall with force f, it applies f.

The functions share their parameters, described here once:

* ``chain`` (:class:`~screwkit.chains.Chain`): the serial chain;
* ``q`` (array-like, shape (n,) or a batch (N, n)): its joint values (rad or m).

>>> import screwkit as sk, numpy as np
>>> arm = sk.robots.planar([1.0, 1.0])
>>> tau = joint_torques(arm, [0.0, 0.0], force=[0.0, 1.0, 0.0])  # 1 N up at x = 2
>>> np.round(tau, 12).tolist()
[2.0, 1.0]
"""

from dataclasses import dataclass

import numpy as np

from ._checks import (
    array_of_shape,
    as_float_array,
    check_chain,
    check_option,
    check_transform,
    describe,
)
from .lie import adjoint
from .parallel.model import ParallelManipulator
from .screws import Screw, Wrench
from .tolerances import (
    DIVISION_FLOOR,
    EIGEN_IMAGINARY_TOL,
    STATICS_SINGULAR_TOL,
    ZERO_TOL,
    length_scale,
)

__all__ = [
    "swap",
    "joint_torques",
    "gravity_torques",
    "wrench_at",
    "transmission_index",
    "compliance_at_tool",
    "stiffness_at_tool",
    "leg_stiffness",
    "Eigenscrews",
    "eigenscrews",
]

#: Standard gravity (m/s^2), pointing down the base's z axis.
STANDARD_GRAVITY = (0.0, 0.0, -9.80665)


def swap(vector):
    """Pi x: the two halves of a 6-vector (or of each row of a batch) swapped.

    (f; m) becomes (m; f), Modern Robotics' order of a wrench, and back: the power of a
    twist V on a wrench w is V^T Pi w.

    Parameters
    ----------
    vector : array-like, shape (6,) or (N, 6)
        A wrench or twist (or a batch).

    Returns
    -------
    ndarray, shape (6,) or (N, 6)
        The vector with its halves swapped.

    Examples
    --------
    >>> swap([1, 2, 3, 4, 5, 6]).tolist()
    [4.0, 5.0, 6.0, 1.0, 2.0, 3.0]
    """
    v = _six(vector, "vector")
    return np.concatenate([v[..., 3:], v[..., :3]], axis=-1)


def _six(value, name):
    """A 6-vector (or batch of them) from an array or a Wrench, as float64."""
    if isinstance(value, Screw):
        if not isinstance(value, Wrench):
            raise TypeError(
                f"{name} must be a Wrench or a 6-vector (f; m), got a {value.noun}"
            )
        value = np.array(value.vector, dtype=float).ravel()
    v = as_float_array(value, name)
    if v.ndim not in (1, 2) or v.shape[-1] != 6:
        raise ValueError(
            f"{name} must be a 6-vector (f; m) (N, N m), shape (6,) or (N, 6), got "
            f"shape {v.shape}"
        )
    return v


def _three(value, name, what):
    return array_of_shape(value, name, (3,), f"{what}, a 3-vector")


def wrench_at(wrench, T):
    """The same wrench written in another frame: w_b = Ad(T_ab^-1) w_a.

    ``wrench`` is given in frame {a} (its moment about a's origin, in a's axes) and
    ``T`` is the pose T_ab of frame {b} in {a}; the result is in {b}: f_b = R^T f_a,
    m_b = R^T (m_a - p x f_a). In Modern Robotics' order (m; f) this is the adjoint
    transpose, F_b = Ad(T_ab)^T F_a; in the book's order it is Pi Ad(T_ab)^T Pi w_a,
    which equals Ad(T_ab)^-1 w_a (wrenches (f; m) move with the twists' adjoint). A pure
    translation T moves the moment's reference point to p.

    Parameters
    ----------
    wrench : Wrench or array-like, shape (6,) or (N, 6)
        (f; m) in frame {a} (N, N m).
    T : array-like, shape (4, 4) or (N, 4, 4)
        The pose of {b} in {a} (m).

    Returns
    -------
    ndarray, shape (6,) or (N, 6)
        (f; m) in frame {b} (N, N m).

    Examples
    --------
    10 N down through x = 1 m: about the origin a moment of 10 N m about y; about
    the point itself none:

    >>> import numpy as np, screwkit as sk
    >>> w = wrench_at([0, 0, -10, 0, 10, 0], sk.transl(1, 0, 0))
    >>> np.round(w, 12).tolist()
    [0.0, 0.0, -10.0, 0.0, 0.0, 0.0]
    """
    w = _six(wrench, "wrench")
    T = np.asarray(check_transform(T, "T"), dtype=float)
    A = adjoint(np.linalg.inv(T))
    return np.einsum("...ij,...j->...i", A, w)


def _point_on_tool(point):
    if isinstance(point, str):
        check_option(point, "point", ("tool",))
        return np.zeros(3)
    return _three(point, "point", "'tool' or a point of the tool in the tool frame (m)")


def joint_torques(
    chain,
    q,
    force=None,
    moment=None,
    point="tool",
    frame="space",
    wrench=None,
):
    """The joint torques that make the tool apply a wrench: tau = J_s^T Pi w_s.

    Give either a force applied at a point of the tool plus a couple (``force``,
    ``moment``, ``point``) or a whole ``wrench``. The wrench is the one **the arm
    applies to the environment** (Modern Robotics' convention): to hold a load of
    weight M g the arm applies +M g upward, to push on a wall it applies the push.

    Parameters
    ----------
    chain, q
    force : array-like, shape (3,), optional
        The force the tool applies (N), in the axes of ``frame``.
    moment : array-like, shape (3,), optional
        A couple the tool applies (N m), in the axes of ``frame``.
    point : 'tool' or array-like, shape (3,), optional
        Where the force acts: the tool frame's origin, or a point of the tool given in
        the tool frame (m).
    frame : {'space', 'body'}, optional
        The axes of ``force`` and ``moment``; for ``wrench`` also its moment's reference
        point: the base origin ('space') or the tool origin ('body').
    wrench : Wrench or array-like, shape (6,), optional
        (f; m) (N, N m), instead of ``force``, ``moment`` and ``point``.

    Returns
    -------
    ndarray, shape (n,) or (N, n)
        tau (N m for a revolute joint, N for a prismatic one).

    Raises
    ------
    ValueError
        If neither or both of (force, moment) and wrench are given, or a vector has the
        wrong length.

    Examples
    --------
    >>> import numpy as np, screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])
    >>> np.round(joint_torques(arm, [0.0, np.pi / 2], moment=[0, 0, 1.0]), 12).tolist()
    [1.0, 1.0]
    """
    chain = check_chain(chain)
    q = chain.check_q(q)
    frame = check_option(frame, "frame", ("space", "body"))
    T = chain.fk(q)
    R, p = T[..., :3, :3], T[..., :3, 3]
    if wrench is not None:
        if force is not None or moment is not None or not _is_tool(point):
            raise ValueError(
                "wrench must be given alone (not with force, moment or point): give "
                "either wrench or force, moment and point, got both"
            )
        w = _six(wrench, "wrench")
        if w.ndim != 1:
            raise ValueError(f"wrench must be one 6-vector (6,), got shape {w.shape}")
        ws = w if frame == "space" else np.einsum("...ij,j->...i", adjoint(T), w)
        f_s, m_s = ws[..., :3], ws[..., 3:]
    else:
        if force is None and moment is None:
            raise ValueError(
                "force must be given (or moment, or wrench): the wrench the tool "
                "applies, got none of them"
            )
        f = np.zeros(3) if force is None else _three(force, "force", "a force (N)")
        c = (
            np.zeros(3)
            if moment is None
            else _three(moment, "moment", "a couple (N m)")
        )
        at = _point_on_tool(point)
        if frame == "body":
            f_s, c_s = R @ f, R @ c
        else:
            f_s, c_s = np.broadcast_to(f, p.shape), np.broadcast_to(c, p.shape)
        where = p + R @ at
        m_s = np.cross(where, f_s) + c_s
    J = chain.space_jacobian(q)
    return np.einsum("...in,...i->...n", J[..., :3, :], m_s) + np.einsum(
        "...in,...i->...n", J[..., 3:, :], f_s
    )


def _is_tool(point):
    return isinstance(point, str) and point == "tool"


def gravity_torques(chain, q, masses, g=STANDARD_GRAVITY):
    """The joint torques that hold point masses on the links still against gravity.

    tau = -sum_k m_k J_k^T g, J_k the Jacobian of the point of mass k (the joints that
    move its link); it is the gradient of the potential energy, tau = dP/dq with
    P = -sum_k m_k g . p_k. A load held by the tool is a mass on link n: the arm holds
    it by applying the upward force -m g (see :func:`joint_torques`).

    Parameters
    ----------
    chain, q
    masses : sequence of (link, mass, point)
        Point masses: ``link`` an int in 0..n, the frame of ``chain.frames(q)`` the mass
        rides on (0 the base, n the tool); ``mass`` in kg (>= 0); ``point`` its position
        in that frame (m), shape (3,).
    g : array-like, shape (3,), optional
        Gravity in the base frame (m/s^2); default 9.80665 down the z axis.

    Returns
    -------
    ndarray, shape (n,) or (N, n)
        tau (N m for a revolute joint, N for a prismatic one).

    Examples
    --------
    >>> import numpy as np, screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])  # in the x-y plane: gravity along -y
    >>> tau = gravity_torques(arm, [0.0, 0.0], [(2, 1.0, [0, 0, 0])], g=[0, -10, 0])
    >>> np.round(tau, 12).tolist()  # 1 kg at x = 2 m, at x = 1 m from joint 2
    [20.0, 10.0]
    """
    chain = check_chain(chain)
    q = chain.check_q(q)
    g = _three(g, "g", "the gravity vector (m/s^2)")
    if isinstance(masses, (str, bytes)) or not hasattr(masses, "__len__"):
        raise TypeError(
            f"masses must be a sequence of (link, mass, point), got {describe(masses)}"
        )
    frames = chain.frames(q)
    J = chain.space_jacobian(q)
    tau = np.zeros(q.shape)
    for index, entry in enumerate(masses):
        name = f"masses[{index}]"
        if not isinstance(entry, (tuple, list)) or len(entry) != 3:
            raise TypeError(
                f"{name} must be a (link, mass, point) triple, got {describe(entry)}"
            )
        link, mass, point = entry
        if isinstance(link, bool) or not isinstance(link, (int, np.integer)):
            raise TypeError(f"{name}'s link must be an int, got {describe(link)}")
        if not 0 <= link <= chain.n:
            raise ValueError(
                f"{name}'s link must be between 0 and {chain.n}, got {int(link)}"
            )
        m = as_float_array(mass, f"{name}'s mass")
        if m.shape != () or m < 0:
            raise ValueError(f"{name}'s mass must be a number >= 0 (kg), got {mass!r}")
        at = _three(point, f"{name}'s point", "a point in its link's frame (m)")
        F = frames[..., link, :, :]
        where = F[..., :3, 3] + F[..., :3, :3] @ at
        f = -float(m) * g  # the force the arm applies to hold the mass
        moment = np.cross(where, f)
        part = np.einsum("...in,...i->...n", J[..., :3, :link], moment) + np.einsum(
            "...in,i->...n", J[..., 3:, :link], f
        )
        tau[..., :link] += part
    return tau


def _dimensionless(J, scale):
    """J with its linear rows divided by the size: comparable singular values."""
    D = J.copy()
    D[..., 3:, :] /= scale
    return D


def _jacobian(chain, q, frame):
    q = chain.check_q(q)
    if q.ndim != 1:
        raise ValueError(f"q must be one configuration ({chain.n},), got {q.shape}")
    frame = check_option(frame, "frame", ("space", "body"))
    J = chain.space_jacobian(q) if frame == "space" else chain.body_jacobian(q)
    scale = length_scale(chain.frames(q)[:, :3, 3])
    return J, scale


def _joint_stiffness(K_q, n):
    K = as_float_array(K_q, "K_q")
    if K.shape == (n,):
        if np.any(K <= 0):
            raise ValueError(f"K_q must hold stiffnesses > 0, got {K.tolist()}")
        return np.diag(K)
    if K.shape != (n, n):
        raise ValueError(
            f"K_q must be the joint stiffnesses, shape ({n},) or ({n}, {n}), got shape "
            f"{K.shape}"
        )
    if not np.allclose(K, K.T, rtol=0, atol=ZERO_TOL * np.abs(K).max()):
        raise ValueError("K_q must be symmetric, got a matrix that is not")
    if np.linalg.eigvalsh(K).min() <= 0:
        raise ValueError("K_q must be positive definite, got a matrix that is not")
    return K


def compliance_at_tool(chain, q, K_q, frame="body"):
    """The tool's compliance C = J K_q^-1 J^T Pi: the twist displacement per wrench.

    A wrench w (f; m) applied to the tool by the environment deflects the joint springs
    by dq = K_q^-1 J^T Pi w, so the tool by dX = J dq = C w, dX = (d theta; dx). It
    exists at every configuration (where J is singular, C is singular too: the tool does
    not give along the wrenches J^T Pi annihilates).

    Parameters
    ----------
    chain, q
    K_q : array-like, shape (n,) or (n, n)
        Joint stiffnesses (N m/rad or N/m): a diagonal, or a symmetric positive definite
        matrix.
    frame : {'space', 'body'}, optional
        The frame of w and dX (default the tool's).

    Returns
    -------
    ndarray, shape (6, 6)
        C (rad / N m, m / N and their mixtures).

    Examples
    --------
    >>> import numpy as np, screwkit as sk
    >>> arm = sk.robots.planar([1.0, 1.0])  # stretched along x, joints 100 N m/rad
    >>> C = compliance_at_tool(arm, [0.0, 0.0], [100.0, 100.0])
    >>> round(float(C[4, 1]), 12)  # 1 N up at the tip: (2^2 + 1^2) / 100 m up
    0.05
    """
    chain = check_chain(chain)
    J, _ = _jacobian(chain, q, frame)
    K = _joint_stiffness(K_q, chain.n)
    return J @ np.linalg.solve(K, J.T) @ _PI


#: The swap Pi as a 6 x 6 matrix.
_PI = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])


def stiffness_at_tool(chain, q, K_q, frame="body"):
    """The tool's stiffness K = Pi (J K_q^-1 J^T)^-1: the wrench per twist displacement.

    The inverse of :func:`compliance_at_tool`: a small displacement dX = (d theta; dx)
    of the tool needs the wrench w = K dX from the environment. For a square J it is
    Pi J^-T K_q J^-1 (Modern Robotics' J^-T K_q J^-1 in its order (m; f)); a redundant
    arm has one as well. Where J has rank < 6 (a singularity, or fewer than 6 joints)
    the stiffness does not exist: the tool is rigid against some wrenches, and this
    raises ValueError naming the rank (the compliance still exists).

    Parameters
    ----------
    chain, q
    K_q : array-like, shape (n,) or (n, n)
        Joint stiffnesses (N m/rad or N/m).
    frame : {'space', 'body'}, optional
        The frame of w and dX (default the tool's).

    Returns
    -------
    ndarray, shape (6, 6)
        K (N/rad, N m/rad, N/m, N m/m); Pi K is symmetric.

    Raises
    ------
    ValueError
        Where J has rank below 6.

    Examples
    --------
    >>> import numpy as np, screwkit as sk
    >>> q = [0.0, 0.3, -0.4, 0.2, 0.5, 0.1]
    >>> K = stiffness_at_tool(sk.robots.puma560(), q, [1e4] * 6)
    >>> Pi = swap(np.eye(6))
    >>> bool(np.allclose(Pi @ K, (Pi @ K).T))  # Pi K is symmetric
    True
    """
    chain = check_chain(chain)
    J, scale = _jacobian(chain, q, frame)
    K = _joint_stiffness(K_q, chain.n)
    sigma = np.linalg.svd(_dimensionless(J, scale), compute_uv=False)
    rank = int(np.sum(sigma > STATICS_SINGULAR_TOL * sigma[0]))
    if len(sigma) < 6 or rank < 6:
        raise ValueError(
            "q must be a configuration where J has rank 6 (for the tool to have a "
            f"stiffness), got one where J has rank {rank} < 6: the tool is rigid "
            "against the wrenches J^T Pi annihilates (use compliance_at_tool, which "
            "exists everywhere)"
        )
    return _PI @ np.linalg.inv(J @ np.linalg.solve(K, J.T))


def leg_stiffness(pm, T, k, mode=None):
    """A 6-leg parallel platform's stiffness from its legs: K = Pi J^T diag(k) J.

    Leg i, a spring of stiffness k_i along its actuation line, pulls back with
    k_i d rho_i = k_i J_i dX; the legs' wrenches sum to K dX (J from
    ``pm.jacobian(T)``, rows the actuation wrenches in the order (m; f)).

    Parameters
    ----------
    pm : ParallelManipulator
        A spatial mechanism with 6 legs (``sk.parallel.stewart_gough()``).
    T : array-like, shape (4, 4)
        The platform pose (m).
    k : array-like, shape (6,)
        The legs' stiffnesses (N/m for a prismatic leg, N m/rad for a crank).
    mode : str, optional
        The working mode.

    Returns
    -------
    ndarray, shape (6, 6)
        K in the base frame, w = K dX with dX = (d theta; dx) the platform's space
        twist displacement.

    Examples
    --------
    >>> import numpy as np, screwkit as sk
    >>> pm = sk.parallel.stewart_gough()
    >>> K = leg_stiffness(pm, pm.home(), [1e5] * 6)
    >>> bool(np.all(np.linalg.eigvalsh(swap(np.eye(6)) @ K) > 0))
    True
    """
    _check_pm(pm)
    if pm.motion != "spatial" or pm.m != 6:
        raise ValueError(
            f"pm must be a spatial mechanism with 6 legs, got {pm.name} "
            f"({pm.motion_type}, {pm.m} legs)"
        )
    stiff = as_float_array(k, "k")
    if stiff.shape != (6,) or np.any(stiff <= 0):
        raise ValueError(f"k must be 6 leg stiffnesses > 0, got {describe(k)}")
    J = np.asarray(pm.jacobian(T, mode), dtype=float)
    if J.ndim != 2:
        raise ValueError(f"T must be one pose (4, 4), got a batch of {len(J)}")
    return _PI @ J.T @ np.diag(stiff) @ J


def _check_pm(pm):
    if not isinstance(pm, ParallelManipulator):
        raise TypeError(
            "pm must be a ParallelManipulator (e.g. sk.parallel.planar_3rpr()), got "
            f"{describe(pm)}"
        )


def transmission_index(pm, T, mode=None):
    """The output transmission index of each leg: ``|cos|`` of its pressure angle.

    Leg i alone drives the platform with the twist V_i (rho'_i = 1, the other actuators
    locked; V_i = J^-1 e_i over the platform's freedoms). Its actuation wrench is a
    force of direction g_i through the platform point C_i; the index is

        eta_i = |g_i . v(C_i)| / (|g_i| |v(C_i)|) = |cos alpha_i|,

    alpha_i the pressure angle between the force and the velocity of the point it acts
    on, v(C_i) = v_i + omega_i x C_i (Wang, Wu and Liu, Mech. Mach. Theory 45, 2010:
    their output transmission index for a force). 1 transmits best; 0 at a
    direct singularity, where the actuators cannot hold the platform. It is
    independent of the frame and the unit of length.

    Parameters
    ----------
    pm : ParallelManipulator
        A mechanism of ``sk.parallel`` with as many legs as freedoms.
    T : array-like, shape (4, 4) or (N, 4, 4)
        Platform pose(s) (m).
    mode : str, optional
        The working mode (default ``pm.default_mode``).

    Returns
    -------
    ndarray, shape (m,) or (N, m)
        eta_i in [0, 1]; NaN where the pose is out of reach; 0 where J is singular.

    Examples
    --------
    >>> import numpy as np, screwkit as sk
    >>> pm = sk.parallel.planar_3rpr()
    >>> eta = transmission_index(pm, pm.home())
    >>> bool(np.all((eta > 0) & (eta <= 1)))
    True
    """
    _check_pm(pm)
    if len(pm.freedoms) != pm.m:
        raise ValueError(
            f"pm must have as many legs as freedoms, got {pm.m} legs for "
            f"{len(pm.freedoms)} freedoms"
        )
    J = np.asarray(pm.jacobian(T, mode), dtype=float)
    batched = J.ndim == 3
    J = J if batched else J[None]
    C = np.asarray(pm.attachments(T), dtype=float)
    C = C if batched else C[None]
    free = pm.freedoms
    Jr = J[:, :, free]
    eta = np.full(J.shape[:2], np.nan)
    ok = np.all(np.isfinite(Jr), axis=(1, 2))
    scale = pm.scale
    D = Jr[ok].copy()
    rotational = [k for k, axis in enumerate(free) if axis < 3]
    D[:, :, rotational] /= scale  # rows (moment; force): moments per unit size
    sigma = np.linalg.svd(D, compute_uv=False)
    regular = sigma[:, -1] > STATICS_SINGULAR_TOL * sigma[:, 0]
    index = np.flatnonzero(ok)
    eta[index[~regular]] = 0.0
    good = index[regular]
    if len(good):
        Vr = np.linalg.solve(Jr[good], np.broadcast_to(np.eye(pm.m), Jr[good].shape))
        V = np.zeros((len(good), 6, pm.m))
        V[:, free, :] = Vr  # column i: the twist of leg i alone
        omega, v = V[:, :3, :], V[:, 3:, :]
        points = np.moveaxis(C[good], 1, 2)  # (N, 3, m)
        vel = v + np.cross(omega, points, axis=1)
        g = np.moveaxis(J[good][:, :, 3:], 1, 2)  # (N, 3, m) force directions
        dot = np.abs(np.sum(g * vel, axis=1))
        eta[good] = np.clip(
            dot / (np.linalg.norm(g, axis=1) * np.linalg.norm(vel, axis=1)), 0.0, 1.0
        )
    return eta if batched else eta[0]


@dataclass(frozen=True)
class Eigenscrews:
    """The eigenscrews of a stiffness or compliance matrix: what ``eigenscrews``
    returns.

    Parameters
    ----------
    values : ndarray, shape (6,)
        The eigenvalues lambda, largest first (N/rad for a stiffness, rad/N for a
        compliance).
    screws : ndarray, shape (6, 6)
        Column j the eigenscrew of ``values[j]`` in the book's order [angular;
        linear], its angular part a unit vector (its linear part, for pitch infinity).
    pitches : ndarray, shape (6,)
        Their pitches (m/rad); inf for a screw of pure translation.

    Examples
    --------
    A unit spring in every direction, decoupled (f = dx, m = dtheta): the eigenscrews
    have pitch +1 (lambda = 1) and -1 (lambda = -1) (see :func:`eigenscrews`).

    >>> Z, I = np.zeros((3, 3)), np.eye(3)
    >>> e = eigenscrews(np.block([[Z, I], [I, Z]]))
    >>> np.round(e.values, 12).tolist(), np.round(e.pitches, 12).tolist()
    ([1.0, 1.0, 1.0, -1.0, -1.0, -1.0], [1.0, 1.0, 1.0, -1.0, -1.0, -1.0])
    """

    values: np.ndarray
    screws: np.ndarray
    pitches: np.ndarray


def eigenscrews(K):
    """The eigenscrews of a 6 x 6 stiffness (or compliance) matrix: K x = lambda x.

    In the book's orders a twist (omega; v) and a wrench (f; m) on the same screw have
    proportional vectors, so an eigenscrew is an eigenvector of K (w = K dX): a twist
    displacement about it meets a wrench on the same screw, lambda times it. In Modern
    Robotics' wrench order, where S = Pi K is symmetric, this is Patterson and Lipkin's
    generalised eigenproblem S x = lambda Pi x (Patterson & Lipkin, ASME J. Mech. Des.
    115, 1993; Dimentberg's "eigenscrews"). For a positive definite S the six lambda are
    real, three positive and three negative. A compliance C = K^-1 has the same screws
    with the eigenvalues 1 / lambda.

    Parameters
    ----------
    K : array-like, shape (6, 6)
        w = K dX (``stiffness_at_tool``, ``leg_stiffness``), or dX = C w.

    Returns
    -------
    Eigenscrews
        ``values``, ``screws`` (columns) and ``pitches``.

    Raises
    ------
    ValueError
        If K has complex eigenvalues (it is not a stiffness or compliance).

    Examples
    --------
    >>> import numpy as np
    >>> kr, kt = 4.0, 1.0  # N m/rad and N/m, decoupled: m = kr dtheta, f = kt dx
    >>> Z, I = np.zeros((3, 3)), np.eye(3)
    >>> K = np.block([[Z, kt * I], [kr * I, Z]])
    >>> e = eigenscrews(K)
    >>> np.round(e.values, 12).tolist()  # +- sqrt(kr kt)
    [2.0, 2.0, 2.0, -2.0, -2.0, -2.0]
    >>> np.round(e.pitches, 12).tolist()  # +- sqrt(kr / kt)
    [2.0, 2.0, 2.0, -2.0, -2.0, -2.0]
    """
    M = as_float_array(K, "K")
    if M.shape != (6, 6):
        raise ValueError(f"K must be a 6 x 6 matrix, got shape {M.shape}")
    values, vectors = np.linalg.eig(M)
    size = max(np.abs(values).max(), np.abs(M).max() * ZERO_TOL, DIVISION_FLOOR)
    if np.abs(values.imag).max() > EIGEN_IMAGINARY_TOL * size:
        raise ValueError(
            "K must be a stiffness or compliance (real eigenvalues), got complex "
            f"eigenvalues {np.round(values, 6).tolist()}"
        )
    values, vectors = values.real, vectors.real
    order = np.argsort(-values, kind="stable")
    values, vectors = values[order], vectors[:, order]
    screws = np.empty((6, 6))
    pitches = np.empty(6)
    for j in range(6):
        x = vectors[:, j]
        s = np.linalg.norm(x[:3])
        if s > ZERO_TOL * np.linalg.norm(x):
            x = x / s
            pitches[j] = x[:3] @ x[3:]
        else:
            x = x / np.linalg.norm(x[3:])
            pitches[j] = np.inf
        screws[:, j] = x
    return Eigenscrews(values=values, screws=screws, pitches=pitches)
