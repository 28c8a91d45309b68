"""Closed-form inverse kinematics of the decomposable 6R arms, by subproblems 5 and 6.

A 6R arm is classified by its joint axes at q = 0 (:func:`classify`): which
consecutive axes meet, which are parallel. Two classes are solved here, every real
solution of a pose, whatever the other axes do (after Elias and Wen, "IK-Geo: unified
robot inverse kinematics using subproblem decomposition", 2022, and Ostermeier et al.,
EAIK, 2024). With G = T M^-1 = exp(xi_1 q1) ... exp(xi_6 q6):

* **spherical wrist** (axes 4, 5, 6 meet in c): joints 4-6 leave c in place, so
  exp(xi_1 q1) exp(xi_2 q2) exp(xi_3 q3) c = G c, a 3R position problem: with the
  axes through r_i, (r1 - r2) + R(w1, -q1)(G c - r1) = R(w2, q2)((r3 - r2) +
  R(w3, q3)(c - r3)), subproblem 5 (up to four); then R4 R5 w6 = R_w w6 is
  subproblem 2 (two) and q6 subproblem 1: up to eight;
* **three parallel axes 2, 3, 4** (direction u): joints 2-4 keep u-components, so
  u . R(w1, -q1) R_G w6 = u . R(w5, q5) w6 and u . (R(w1, -q1)(G p6 - r1) + r1) =
  u . exp(xi_5 q5) p6 (p6 on axis 6): subproblem 6 (up to four); then q6 by
  subproblem 1, and exp(xi_2 q2) exp(xi_3 q3) exp(xi_4 q4), a planar 3R, by
  subproblems 3 and 1 (two): up to eight.

A spherical shoulder (axes 1, 2, 3 meet) and three parallel axes 3, 4, 5 are the two
above for the reversed chain: T^-1 = exp(xi'_1 q'_1) ... exp(xi'_6 q'_6) M^-1 with
xi'_i = Ad(M^-1) xi_{7-i} and q'_i = -q_{7-i}.

The solutions are labelled 's0', 's1', ... in increasing q1, then q2, ... (no arm, elbow
or wrist meaning applies in general). Where the solutions form a continuum (an angle
free: axis 6 turned onto axis 4, a point on the axis it turns about) the pose says so.
"""

from dataclasses import dataclass

import numpy as np

from .._checks import check_chain, check_poses
from .._compiled import CHUNK, cos_sin
from .._docstrings import fill
from ..links import Joint
from ..tolerances import (
    IK_ACCEPT_TOL,
    IK_CLIP_TOL,
    IK_DUPLICATE_TOL,
    IK_ORDER_TOL,
    IK_STRUCTURE_TOL,
)
from ..transforms import _cross_last, _dot_last, _rotations_about, _turn_vectors
from ._closed_form import arm_scale, from_chain_sections, pose_residual
from .subproblems import _angle_about, meeting_points, three_cones, two_pairs

__all__ = ["DecomposedArm", "Classification", "classify"]


#: The Parameters and Returns of the engine's ``from_chain``.
_FROM_CHAIN = from_chain_sections(
    "A 6R arm whose :func:`classify` kind is not None.",
    "DecomposedArm",
    "an arm of no decomposable class",
)


def _angle_order(Q):
    """The order (N, k) that sorts each pose's solutions Q (N, k, 6) by q1, then q2,
    ..., NaN rows last. Angles are compared on a grid of IK_ORDER_TOL, so two solutions
    that share an angle (equal but for round-off) are ordered by the next one on every
    machine."""
    keys = np.round(Q[..., ::-1] / IK_ORDER_TOL)
    return np.lexsort(np.moveaxis(keys, -1, 0), axis=-1)


@dataclass(frozen=True)
class Classification:
    """What the joint axes of a 6R arm at q = 0 have in common.

    Parameters
    ----------
    meet : tuple of bool, length 5
        Whether axes i and i + 1 meet in one point (i = 1 ... 5; parallel axes do not).
    parallel : tuple of bool, length 5
        Whether axes i and i + 1 are parallel (collinear included).
    name : str
        The class, as ``analytic_ik`` reports it.
    kind : str or None
        The engine's case: 'wrist', 'shoulder', 'parallel 234', 'parallel 345'; None
        when no decomposition applies here (the general 6R).

    Examples
    --------
    The PUMA 560: axes 4, 5, 6 meet (a spherical wrist), 2 and 3 are parallel.

    >>> import screwkit as sk
    >>> found = classify(sk.robots.puma560())
    >>> found.kind, [bool(b) for b in found.parallel]
    ('wrist', [False, True, False, False, False])
    """

    meet: tuple
    parallel: tuple
    name: str
    kind: str | None


def _axes(chain):
    S = chain.screw_axes()
    w = S[:, :3] / np.linalg.norm(S[:, :3], axis=1)[:, None]
    return w, np.cross(w, S[:, 3:])


def _parallel(a, b):
    return np.linalg.norm(np.cross(a, b)) <= IK_STRUCTURE_TOL


def _meet(w, p, i, j, scale):
    n = np.cross(w[i], w[j])
    if np.linalg.norm(n) <= IK_STRUCTURE_TOL:
        return False
    return abs((p[j] - p[i]) @ n) / np.linalg.norm(n) <= IK_STRUCTURE_TOL * scale


def _common_point(w, p, i, j):
    """The point of axis i nearest axis j (their meeting point when they meet)."""
    d = p[j] - p[i]
    c = w[i] @ w[j]
    t = (d @ w[i] - (d @ w[j]) * c) / (1 - c * c)
    return p[i] + t * w[i]


def _three_meet(w, p, first, scale):
    i, j, k = first, first + 1, first + 2
    if not (_meet(w, p, i, j, scale) and _meet(w, p, j, k, scale)):
        return False
    c = _common_point(w, p, i, j)
    off = (c - p[k]) - w[k] * (w[k] @ (c - p[k]))
    return np.linalg.norm(off) <= IK_STRUCTURE_TOL * scale


def _three_parallel(w, p, first, scale):
    i, j, k = first, first + 1, first + 2
    if not (_parallel(w[i], w[j]) and _parallel(w[j], w[k])):
        return False
    # distinct axes: no two of them collinear (else a continuum for every pose)
    for a, b in ((i, j), (j, k)):
        off = (p[b] - p[a]) - w[a] * (w[a] @ (p[b] - p[a]))
        if np.linalg.norm(off) <= IK_STRUCTURE_TOL * scale:
            return False
    return True


def classify(chain, name="chain"):
    """The class of a 6R arm from its joint axes at q = 0.

    Parameters
    ----------
    chain : Chain
        A chain of six revolute joints (else a ``ValueError`` naming ``name``).
    name : str
        The argument's name, for the messages.

    Returns
    -------
    Classification
        Which consecutive axes meet or are parallel, the class's name and the engine's
        case (None: general).

    Examples
    --------
    A UR arm's axes 2, 3, 4 are parallel:

    >>> import screwkit as sk
    >>> found = classify(sk.robots.ur5e())
    >>> found.kind
    'parallel 234'
    >>> found.name.startswith("three parallel (2, 3, 4)")
    True
    """
    check_chain(chain, name)
    if chain.n != 6:
        raise ValueError(
            f"{name} must have 6 joints for the closed form, got {chain.n}"
        )
    if any(j is not Joint.REVOLUTE for j in chain.joints):
        raise ValueError(f"{name} must have revolute joints only")
    w, p = _axes(chain)
    scale = arm_scale(p)
    meet = tuple(_meet(w, p, i, i + 1, scale) for i in range(5))
    parallel = tuple(_parallel(w[i], w[i + 1]) for i in range(5))
    features = [f"{i + 1} || {i + 2}" for i in range(5) if parallel[i]]
    features += [f"{i + 1} and {i + 2} meet" for i in range(5) if meet[i]]
    wrist, shoulder = _three_meet(w, p, 3, scale), _three_meet(w, p, 0, scale)
    parallel_at = [f for f in range(4) if _three_parallel(w, p, f, scale)]
    kind = None
    if wrist:
        kind, head = "wrist", "spherical wrist (4, 5, 6 meet)"
        features = [f for f in features if f not in ("4 and 5 meet", "5 and 6 meet")]
    elif shoulder:
        kind, head = "shoulder", "spherical shoulder (1, 2, 3 meet)"
        features = [f for f in features if f not in ("1 and 2 meet", "2 and 3 meet")]
    elif 1 in parallel_at or 2 in parallel_at:
        f = 1 if 1 in parallel_at else 2
        kind = f"parallel {f + 1}{f + 2}{f + 3}"
        head = f"three parallel ({f + 1}, {f + 2}, {f + 3})"
        features = [
            x
            for x in features
            if x not in (f"{f + 1} || {f + 2}", f"{f + 2} || {f + 3}")
        ]
    elif parallel_at:
        f = parallel_at[0]
        head = f"general: three parallel ({f + 1}, {f + 2}, {f + 3}) at an end"
    elif any(meet[3:]) and not wrist:
        head = "general: wrist offset"
    else:
        head = "general"
    label = head + (", " + ", ".join(features) if features else "")
    return Classification(meet, parallel, label, kind)


def _motions(w, r, theta):
    """exp(xi theta) for the axis through r along w: (..., 4, 4)."""
    R = _rotations_about(w, theta)
    E = np.zeros(theta.shape + (4, 4))
    E[..., :3, :3] = R
    E[..., :3, 3] = r - R @ r
    E[..., 3, 3] = 1.0
    return E


def _inverse(T):
    out = np.zeros_like(T)
    Rt = np.swapaxes(T[..., :3, :3], -1, -2)
    out[..., :3, :3] = Rt
    out[..., :3, 3] = -(Rt @ T[..., :3, 3:])[..., 0]
    out[..., 3, 3] = 1.0
    return out


def _apply(T, x):
    """T x for transforms (..., 4, 4) and points x (..., 3) (or (3,))."""
    return (T[..., :3, :3] @ x[..., None])[..., 0] + T[..., :3, 3]


def _across(u, x):
    return x - u * (x @ u)[..., None]


@dataclass(frozen=True)
class DecomposedArm:
    """The geometry of a decomposable 6R arm, as the solver uses it.

    Parameters
    ----------
    w : ndarray, shape (6, 3)
        Unit axis directions at q = 0, of the solved chain (the reversed one for a
        shoulder or parallel axes 3, 4, 5).
    r : ndarray, shape (6, 3)
        A point of each axis (m).
    home : ndarray, shape (4, 4)
        The home pose of the solved chain (m).
    scale : float
        The arm's size (m): pose residuals divide positions by it.
    case : str
        'wrist' or 'parallel': the engine's case after any reversal.
    reverse : bool
        Whether the chain is solved reversed.
    structure : str
        The class's name.
    chain : Chain
        The arm as given: its forward kinematics checks every solution.

    Examples
    --------
    The PUMA 560 is solved as it is (a wrist at its end, no reversal):

    >>> import screwkit as sk
    >>> arm = DecomposedArm.from_chain(sk.robots.puma560())
    >>> arm.case, arm.reverse
    ('wrist', False)
    """

    w: np.ndarray
    r: np.ndarray
    home: np.ndarray
    scale: float
    case: str
    reverse: bool
    structure: str
    chain: object

    @classmethod
    @fill(sections=_FROM_CHAIN)
    def from_chain(cls, chain, name="chain"):
        """The engine of a decomposable 6R chain.

        {sections}

        Examples
        --------
        A UR5e has three parallel axes 2, 3, 4 (no spherical wrist):

        >>> import screwkit as sk
        >>> DecomposedArm.from_chain(sk.robots.ur5e()).case
        'parallel'
        """
        found = classify(chain, name)
        if found.kind is None:
            raise ValueError(
                f"{name} must have three consecutive axes meeting at an end or three "
                f"parallel axes 2, 3, 4 or 3, 4, 5, got {found.name}"
            )
        w, r = _axes(chain)
        M = chain.home()
        reverse = found.kind in ("shoulder", "parallel 345")
        if reverse:
            Mi = _inverse(M)
            w = (Mi[:3, :3] @ w[::-1].T).T
            r = _apply(Mi, r[::-1])
            M = Mi
        case = "wrist" if found.kind in ("wrist", "shoulder") else "parallel"
        r = r.copy()
        scale = arm_scale(np.cross(w, np.cross(r, w)))
        if case == "wrist":
            if not _parallel(w[0], w[1]):  # r1, r2: the points nearest each other
                r[0], r[1] = _common_point(w, r, 0, 1), _common_point(w, r, 1, 0)
            if not _parallel(w[1], w[2]):
                r[2] = _common_point(w, r, 2, 1)
            r[3] = r[4] = r[5] = _common_point(w, r, 3, 4)
        elif not _parallel(w[4], w[5]):
            r[5] = _common_point(w, r, 5, 4)
        return cls(w, r, M, scale, case, reverse, found.name, chain)

    def solve(self, T):
        """Every solution of a batch of poses.

        Parameters
        ----------
        T : array-like, shape (N, 4, 4) (or (4, 4), a batch of one)
            Tool poses (m).

        Returns
        -------
        Q : ndarray (N, 8, 6), rad in (-pi, pi]: each pose's solutions in increasing
            q1, then q2, ..., then NaN rows
        residual : ndarray (N, 8): max |R - R_T| entry and |p - p_T| / scale (NaN rows
            as Q)
        free : ndarray of bool (N, 8): a solution with a free angle (a continuum)

        Examples
        --------
        A PUMA 560 pose: eight solutions, the vector that made it among them, each
        one reaching the pose.

        >>> import screwkit as sk
        >>> puma, q = sk.robots.puma560(), [0.1, -0.4, 0.3, 0.5, -0.6, 0.7]
        >>> Q, residual, free = DecomposedArm.from_chain(puma).solve(puma.fk(q))
        >>> Q.shape, any(np.allclose(row, q) for row in Q[0])
        ((1, 8, 6), True)
        >>> bool(np.nanmax(residual) < 1e-9)
        True
        """
        T = check_poses(T, "T")
        T = T[None] if T.ndim == 2 else T
        N = T.shape[0]
        Q, res, free = np.empty((N, 8, 6)), np.empty((N, 8)), np.empty((N, 8), bool)
        for start in range(0, N, CHUNK):
            part = slice(start, start + CHUNK)
            Q[part], res[part], free[part] = self._solve(T[part])
        # the labels s0, s1, ... do not depend on the order in which the subproblems
        # found the roots
        order = _angle_order(Q)
        Q = np.take_along_axis(Q, order[..., None], 1)
        return Q, *(np.take_along_axis(x, order, 1) for x in (res, free))

    def _solve(self, T):
        G = (_inverse(T) if self.reverse else T) @ _inverse(self.home)
        if self.case == "wrist":
            Q, ok, free = self._wrist(G)
        else:
            Q, ok, free = self._parallel(G)
        if self.reverse:
            Q = -Q[..., ::-1]
        rows, branch = np.nonzero(ok)  # the candidates' angles into (-pi, pi]
        Q[rows, branch] = np.pi - np.mod(np.pi - Q[rows, branch], 2 * np.pi)
        # branches 2i and 2i + 1 share the first subproblem's solution i, which differ
        # from each other (sinusoid_pairs drops repeats): only siblings can coincide
        gap = np.abs(Q[:, 1::2] - Q[:, 0::2])
        same = np.all(np.minimum(gap, 2 * np.pi - gap) < IK_DUPLICATE_TOL, -1)
        ok[:, 1::2] &= ~(ok[:, 0::2] & same)
        # the solution is checked by the chain's own forward kinematics
        residual = np.full(ok.shape, np.nan)
        rows, branch = np.nonzero(ok)
        residual[rows, branch] = pose_residual(
            self.chain, Q[rows, branch], T[rows], self.scale
        )
        ok &= residual <= IK_ACCEPT_TOL
        Q[~ok] = np.nan
        residual[~ok] = np.nan
        return Q, residual, free & ok

    def _wrist(self, G):
        w, r = self.w, self.r
        c = r[3]
        target = _apply(G, c)  # (N, 3)
        theta, ok, free = three_cones(
            w[0], w[1], w[2], r[0] - r[1], target - r[0], r[2] - r[1], c - r[2]
        )  # (N, 4, 3)
        # the rest only for the k solutions of subproblem 5 (about half the slots)
        rows, slot = np.nonzero(ok)
        theta, free = theta[rows, slot], free[rows, slot]  # (k, 3), (k,)
        RG = G[rows, :3, :3]
        q1, q2, q3 = -theta[:, 0], theta[:, 1], theta[:, 2]
        (c1, c2, c3), (s1, s2, s3) = cos_sin(np.stack([q1, q2, q3]))

        def back123(v):  # R3^T R2^T R1^T v
            v = _turn_vectors(w[0], c1, -s1, v)
            return _turn_vectors(w[2], c3, -s3, _turn_vectors(w[1], c2, -s2, v))

        y = back123(RG @ w[5])  # R123^T R_G w6, (k, 3)
        z, gamma2 = meeting_points(w[3], w[4], w[5], y)  # (k, 2, 3)
        reach = gamma2 >= -IK_CLIP_TOL
        q5 = _angle_about(w[4], w[5], z)
        q4 = _angle_about(w[3], z, y[:, None, :])
        off = _cross_last(y, w[3])
        aligned = np.sqrt(_dot_last(off, off)) <= IK_CLIP_TOL
        # q6 turns x to R6 x = R5^T R4^T R123^T R_G x
        x = np.cross(w[5], [1.0, 0, 0] if abs(w[5, 0]) < 0.9 else [0, 1.0, 0])
        R6x = back123(RG @ x)[:, None, :]
        (c4, c5), (s4, s5) = cos_sin(np.stack([q4, q5]))
        R6x = _turn_vectors(w[4], c5, -s5, _turn_vectors(w[3], c4, -s4, R6x))
        q6 = _angle_about(w[5], x, R6x)
        q123 = np.stack([q1, q2, q3], -1)[:, None, :]
        Q = np.concatenate(
            [np.broadcast_to(q123, q4.shape + (3,)), np.stack([q4, q5, q6], -1)], -1
        )
        return _spread(G.shape[0], rows, slot, Q, reach, free | aligned)

    def _parallel(self, G):
        w, r = self.w, self.r
        N = G.shape[0]
        u = w[1]
        y = _apply(G, r[5])
        RG = G[:, :3, :3]
        h = np.broadcast_to(u, (N, 4, 3))
        k = np.broadcast_to(np.stack([w[0], w[4], w[0], w[4]]), (N, 4, 3))
        p = np.stack(
            [
                RG @ w[5],
                np.broadcast_to(-w[5], (N, 3)),
                y - r[0],
                np.broadcast_to(r[4] - r[5], (N, 3)),
            ],
            -2,
        )
        d = np.broadcast_to([0.0, u @ (r[4] - r[0])], (N, 2))
        theta, ok, free = two_pairs(h, k, p, d)  # (N, 4, 2)
        # the rest only for the k solutions of subproblem 6
        rows, slot = np.nonzero(ok)
        theta, free = theta[rows, slot], free[rows]  # (k, 2), (k,)
        RG, tG = G[rows, :3, :3], G[rows, :3, 3]
        q1, q5 = -theta[:, 0], theta[:, 1]
        (c1, c5), (s1, s5) = cos_sin(np.stack([q1, q5]))
        a = (_turn_vectors(w[0], c1, s1, u)[:, None, :] @ RG)[:, 0]  # R_G^T R1 u
        b = _turn_vectors(w[4], c5, -s5, u)  # R5^T u
        q6 = _angle_about(w[5], a, b)
        off = _cross_last(a, w[5])
        free6 = np.sqrt(_dot_last(off, off)) <= IK_CLIP_TOL
        # H = E1^-1 G E6^-1 E5^-1 = exp(xi2 q2) exp(xi3 q3) exp(xi4 q4), a turn about u
        # by phi = q2 + q3 + q4 (signed) that takes r4 to g
        x = np.cross(u, [1.0, 0, 0] if abs(u[0]) < 0.9 else [0, 1.0, 0])
        c6, s6 = cos_sin(q6)
        Hx = _turn_vectors(w[5], c6, -s6, _turn_vectors(w[4], c5, -s5, x))
        Hx = _turn_vectors(w[0], c1, -s1, (RG @ Hx[..., None])[..., 0])
        phi = _angle_about(u, x, Hx)
        g = _turn_vectors(w[4], c5, -s5, r[3] - r[4]) + r[4]
        g = _turn_vectors(w[5], c6, -s6, g - r[5]) + r[5]
        g = (RG @ g[..., None])[..., 0] + tG
        g = _turn_vectors(w[0], c1, -s1, g - r[0]) + r[0]  # (k, 3)
        a34, a32 = _across(u, r[3] - r[2]), _across(u, r[1] - r[2])
        target = _across(u, g - r[1])
        delta2 = _dot_last(target, target)
        l1, l2 = np.linalg.norm(a34), np.linalg.norm(a32)
        cosine = (l1**2 + l2**2 - delta2) / (2 * l1 * l2)
        theta0 = np.arctan2(np.cross(a34, a32) @ u, a34 @ a32)
        reach = np.abs(cosine) <= 1 + IK_CLIP_TOL
        beta = np.arccos(np.clip(cosine, -1, 1))
        q3 = theta0 + np.stack([-beta, beta], -1)  # (k, 2), about u
        elbow = _turn_vectors(u, *cos_sin(q3), r[3] - r[2]) + r[2]  # exp(xi3 q3) r4
        q2 = _angle_about(u, elbow - r[1], g[:, None, :] - r[1])
        q4 = (phi[:, None] - q2 - q3) * np.sign(w[3] @ u)  # axes 3, 4 along +-u
        q3 = q3 * np.sign(w[2] @ u)
        free2 = np.sqrt(delta2) <= IK_CLIP_TOL * self.scale
        Q = np.stack(
            [
                np.broadcast_to(q1[:, None], q2.shape),
                q2,
                q3,
                q4,
                np.broadcast_to(q5[:, None], q2.shape),
                np.broadcast_to(q6[:, None], q2.shape),
            ],
            -1,
        )
        return _spread(N, rows, slot, Q, reach, free | free6 | free2)


def _spread(N, rows, slot, Q, ok, free):
    """The k solutions of the first subproblem (rows, slot), each with two branches
    Q (k, 2, 6), ok (k, 2) or (k,) and free (k,), back in the batch's slots:
    (N, 8, 6), (N, 8), (N, 8); branches 2i and 2i + 1 of a pose come from slot i."""
    Q_all = np.full((N, 4, 2, 6), np.nan)
    ok_all, free_all = np.zeros((N, 4, 2), bool), np.zeros((N, 4, 2), bool)
    Q_all[rows, slot] = Q
    ok_all[rows, slot] = ok if ok.ndim == 2 else ok[:, None]
    free_all[rows, slot] = free[:, None]
    return Q_all.reshape(N, 8, 6), ok_all.reshape(N, 8), free_all.reshape(N, 8)
