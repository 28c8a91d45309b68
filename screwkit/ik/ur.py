"""Closed-form inverse kinematics of a UR-type 6R arm, from its screws.

The arm fits when the axes of joints 2, 3 and 4 are parallel (direction u), the axis of
joint 1 is not parallel to them, the axes of joints 5 and 6 meet in a point c and axis 5
is not parallel to u: the Universal Robots arms (UR3, UR5, UR10 and their e-Series) with
any lengths, base and tool. With the joint screws xi_i at q = 0 and the home pose M,
G = T M^-1 = exp(xi_1 q1) ... exp(xi_6 q6), and the solution follows Hawkins (2013),
written with Paden–Kahan subproblems on the screws instead of DH symbols:

1. joint 1 (subproblem 4): joints 5 and 6 leave c where it is and joints 2-4 move it in
   a plane perpendicular to u, so q1 turns G c back into the plane u . x = u . c: two
   angles, the shoulder right ('r') or left ('l');
2. joint 5 (subproblem 4 on directions): joints 2-4 keep the u-component of a direction,
   so u . R(w_5, q5) w_6 = u . R1^T R_G w_6: two angles, the wrist flipped ('f') or not;
3. joint 6 (subproblem 1 on directions): R(w_6, q6) R_G^T R1 u = R(w_5, -q5) u;
4. joints 2, 3, 4: what is left, exp(xi_2 q2) exp(xi_3 q3) exp(xi_4 q4), is a planar 3R
   arm: q3 from the distance of the point p4 of axis 4 to axis 2 (subproblem 3: elbow up
   'u' or down 'd'), q2 by subproblem 1, and q4 from the rotation about u that is left.

Up to eight solutions, labelled with the letters of :mod:`screwkit.ik.spherical_wrist`
(arm l/r, elbow u/d, wrist n/f) by geometric definitions, with x1 = exp(xi_2 q2)
exp(xi_3 q3) exp(xi_4 q4) c the point c at q1 = 0:

* arm 'r' when x1 lies on the side of axis 1 that w_1 x u points to, 'l' otherwise;
* elbow 'u' when sigma ((P - p2) x (E - p2)) . u > 0, with P the point of axis 4 and E
  that of axis 3 after joints 2 and 3, sigma = +1 for 'r' and -1 for 'l';
* wrist 'f' when (w_4 x w_6) . w_5 > 0 at the configuration (for the UR: sin q5 > 0).

Singular cases: shoulder (the two arm solutions coincide): label 'r'; elbow (stretched
or folded): label 'd'; wrist (axis 6 parallel to u, q5 = 0 or pi for the UR: four
parallel joints for three planar freedoms, a one-parameter family of solutions): both
wrist solutions take q6 = 0 and the label is 'f'.

Reference: K. P. Hawkins, "Analytic inverse kinematics for the Universal Robots
UR-5/UR-10 arms", Georgia Institute of Technology, 2013.
"""

from dataclasses import dataclass

import numpy as np

from ..links import Joint
from ..tolerances import IK_CLIP_TOL, IK_LABEL_TOL, IK_SINGULAR_TOL, IK_STRUCTURE_TOL
from ..transforms import _wrap_angle, inv
from ._closed_form import ClosedFormArm, Turn, arm_scale, branches
from .subproblems import plane_angles, rotation_angles, sinusoid_angles

__all__ = ["URArm", "STRUCTURE"]

#: The structure's name, as ``analytic_ik`` reports it.
STRUCTURE = "UR-type (joints 2, 3, 4 parallel, axes 5 and 6 meet)"


def _roots(A, B, C):
    """The two angles of A cos + B sin = C (..., 2), sorted later, and whether real
    (the equation's ``excess`` clipped by :data:`~screwkit.tolerances.IK_CLIP_TOL`)."""
    phi, half, excess, radius2 = sinusoid_angles(A, B, C)
    ok = excess >= -IK_CLIP_TOL * radius2
    return np.stack([phi - half, phi + half], axis=-1), ok, excess


@dataclass(frozen=True)
class URArm(ClosedFormArm):
    """The geometry of a UR-type arm, from its screws; :meth:`from_chain` builds it.

    Parameters
    ----------
    w, p, home, scale
        The fields of :class:`~screwkit.ik._closed_form.ClosedFormArm`.
    c : ndarray, shape (3,)
        The point where axes 5 and 6 meet (m).

    Examples
    --------
    The UR5e at q = 0, from its DH numbers: axes 5 and 6 meet at
    (a2 + a3, -d4, d1 - d5) = (-0.425 - 0.3922, -0.1333, 0.1625 - 0.0997).

    >>> import screwkit as sk
    >>> arm = URArm.from_chain(sk.robots.ur5e())
    >>> np.round(arm.c, 5) + 0.0
    array([-0.8172, -0.1333,  0.0628])
    """

    c: np.ndarray

    structure = STRUCTURE

    @classmethod
    def _from_chain(cls, chain, name):
        """:meth:`from_chain` of a checked chain."""
        if chain.n != 6:
            raise ValueError(f"{name} must have 6 joints, got {chain.n}")
        if any(j is not Joint.REVOLUTE for j in chain.joints):
            raise ValueError(f"{name} must have revolute joints only")
        S = chain.screw_axes()
        w, v = S[:, :3], S[:, 3:]
        w = w / np.linalg.norm(w, axis=1)[:, None]
        p = np.cross(w, v)
        scale = arm_scale(p)
        u = w[1]
        for i in (2, 3):
            if np.linalg.norm(np.cross(u, w[i])) > IK_STRUCTURE_TOL:
                raise ValueError(
                    f"{name} must have parallel axes for joints 2, 3 and 4 "
                    f"(joint {i + 1} is not parallel to joint 2)"
                )
        for i, what in ((0, "1"), (4, "5")):
            if np.linalg.norm(np.cross(u, w[i])) < IK_STRUCTURE_TOL:
                raise ValueError(
                    f"{name} must have the axis of joint {what} not parallel "
                    "to the axes of joints 2, 3 and 4"
                )
        n56 = np.cross(w[4], w[5])
        if np.linalg.norm(n56) < IK_STRUCTURE_TOL:
            raise ValueError(
                f"{name} must have the axes of joints 5 and 6 not parallel"
            )
        gap = abs((p[5] - p[4]) @ n56) / np.linalg.norm(n56)
        if gap > IK_STRUCTURE_TOL * scale:
            raise ValueError(
                f"{name} must have the axes of joints 5 and 6 meeting in a "
                f"point, they miss by {gap:.3g} m"
            )
        # c: the point of axis 5 nearest to axis 6 (they meet)
        d = p[5] - p[4]
        t = (d @ w[4] - (d @ w[5]) * (w[4] @ w[5])) / (1 - (w[4] @ w[5]) ** 2)
        c = p[4] + t * w[4]
        for i, j in ((1, 2), (2, 3)):
            between = p[j] - p[i] - u * (u @ (p[j] - p[i]))
            if np.linalg.norm(between) < IK_STRUCTURE_TOL * scale:
                raise ValueError(
                    f"{name} must have distinct axes for joints {i + 1} and "
                    f"{j + 1}, got the same line"
                )
        return cls(w=w, p=p, c=c, home=chain.home(), scale=scale)

    # ---- labels ---------------------------------------------------------------------

    def _measures(self, q):
        """(forward, above, flip) of q (..., 6): the signed measures the labels test."""
        w, p, c, u = self.w, self.p, self.c, self.w[1]
        q = np.asarray(q, dtype=float)
        one = np.ones(q.shape[:-1])
        rot = [Turn(w[i]) for i in range(6)]
        angle = [(np.cos(q[..., i]), np.sin(q[..., i])) for i in range(6)]

        def move(i, x):  # exp(xi_i q_i) applied to points x (..., 3)
            return p[i] + rot[i](x - p[i], *angle[i])

        x1 = move(1, move(2, move(3, c * one[..., None])))
        P = move(1, move(2, p[3] * one[..., None]))
        E = move(1, p[2] * one[..., None])
        forward = (x1 - p[0]) @ np.cross(w[0], u)
        sigma = np.where(forward >= -IK_LABEL_TOL * self.scale, 1.0, -1.0)
        above = sigma * (np.cross(P - p[1], E - p[1]) @ u)
        w6 = rot[4](w[5] * one[..., None], *angle[4])
        flip = np.cross(w[3], w6) @ w[4]
        return forward, above, flip

    def _labels(self, q):
        """The configuration labels of q (..., 6): an array of strings like 'ruf'."""
        forward, above, flip = self._measures(q)
        tol = IK_LABEL_TOL * self.scale  # forward is a length (m), above an area (m^2)
        arm = np.where(forward >= -tol, "r", "l")
        elbow = np.where(above > tol * self.scale, "u", "d")
        wrist = np.where(flip >= -IK_LABEL_TOL, "f", "n")
        return np.char.add(np.char.add(arm, elbow), wrist)

    # ---- the closed form ------------------------------------------------------------

    def _solve(self, T):
        w, p, c = self.w, self.p, self.c
        u, w1, w5, w6 = w[1], w[0], w[4], w[5]
        s3, s4 = np.sign(w[2] @ u), np.sign(w[3] @ u)
        turn1, turn5, turn6 = Turn(w1), Turn(w5), Turn(w6)
        N = T.shape[0]
        G = T @ inv(self.home)
        RG, tG = G[:, :3, :3], G[:, :3, 3]

        # joint 1: theta = -q1 turns d = G c - p1 into the plane u . x = u . c
        d = RG @ c + tG - p[0]  # (N, 3)
        phi, half, excess1, radius1 = plane_angles(w1, u, u @ (c - p[0]), d.T)
        theta = np.stack([phi - half, phi + half], axis=-1)  # (N, 2)
        shoulder_ok = excess1 >= -IK_CLIP_TOL * radius1
        free = radius1 < (IK_CLIP_TOL * self.scale) ** 2  # c on axis 1: q1 free
        theta = np.where(free[:, None], 0.0, theta)
        ct, st = np.cos(theta), np.sin(theta)
        x1 = p[0] + turn1(d[:, None], ct, st)  # c at q1 = 0, (N, 2, 3)
        forward = (x1 - p[0]) @ np.cross(w1, u)
        order = np.argsort(forward, axis=1)  # l first, then r
        theta, ct, st, x1 = (
            np.take_along_axis(a, order if a.ndim == 2 else order[..., None], 1)
            for a in (theta, ct, st, x1)
        )

        # joint 5: u . R(w5, q5) w6 = u . R(w1, theta) RG w6, per arm branch (N, 2)
        g6 = turn1((RG @ w6)[:, None], ct, st)
        A5 = u @ w6 - (w5 @ w6) * (u @ w5)
        B5 = u @ np.cross(w5, w6)
        C5 = g6 @ u - (w5 @ w6) * (u @ w5)
        q5, wrist_ok, _ = _roots(
            np.full_like(C5, A5), np.full_like(C5, B5), C5
        )  # (N,2,2)
        n54 = np.cross(w5, w[3])
        flip = np.cos(q5) * (w6 @ n54) + np.sin(q5) * (np.cross(w5, w6) @ n54)
        order = np.argsort(flip, axis=2)  # n first, then f
        q5 = np.take_along_axis(q5, order, 2)
        c5, s5 = np.cos(q5), np.sin(q5)

        # joint 6: R(w6, q6) a = b, a = RG^T R1 u, b = R(w5, -q5) u (directions)
        R1u = turn1.fixed(u, ct, -st)  # R(w1, q1) u, q1 = -theta
        a = np.einsum("nji,nkj->nki", RG, R1u)[:, :, None]  # (N, 2, 1, 3)
        b = turn5.fixed(u, c5, -s5)
        a_perp = a - w6 * (a @ w6)[..., None]
        q6 = rotation_angles(w6, a, b)
        on_axis = np.sum(a_perp**2, -1) < IK_CLIP_TOL**2
        q6 = np.where(on_axis, 0.0, q6)
        c6, s6 = np.cos(q6), np.sin(q6)

        # joints 2-4: P = exp(xi1 -q1) G exp(xi6 -q6) exp(xi5 -q5) p4 and the angle phi
        y = p[4] + turn5.fixed(p[3] - p[4], c5, -s5)
        z = p[5] + turn6(y - p[5], c6, -s6)
        g = np.einsum("nij,nabj->nabi", RG, z) + tG[:, None, None]
        ct4, st4 = ct[..., None], st[..., None]
        P = p[0] + turn1(g - p[0], ct4, st4)  # (N, 2, 2, 3)
        x = np.cross(u, w1)
        x = x / np.linalg.norm(x)
        rx = turn5.fixed(x, c5, -s5)
        rx = turn6(rx, c6, -s6)
        rx = turn1(np.einsum("nij,nabj->nabi", RG, rx), ct4, st4)
        phi = rotation_angles(u, x, rx)

        # q3 (subproblem 3, planar): |r2 + R(w3, q3) r3| = |P - p2| across u
        def across(v):
            return v - u * (v @ u)[..., None]

        r2, r3 = across(p[2] - p[1]), across(p[3] - p[2])
        delta2 = np.sum(across(P - p[1]) ** 2, -1)
        A3, B3 = r2 @ r3, r2 @ np.cross(s3 * u, r3)
        C3 = (delta2 - r2 @ r2 - r3 @ r3) / 2
        q3, elbow_ok, excess3 = _roots(np.full_like(C3, A3), np.full_like(C3, B3), C3)
        c3, s3q = np.cos(q3), np.sin(q3)
        # q2 (subproblem 1): about u from r2 + R(w3, q3) r3 to (P - p2) across u
        turn3 = Turn(w[2])
        xs = r2 + turn3.fixed(r3, c3, s3q)
        ys = across(P - p[1])[..., None, :]
        q2 = rotation_angles(u, xs, ys)
        # above = ((P - p2) x R(u, q2) r2) . u, both across u
        above = np.cos(q2) * (np.cross(ys, r2) @ u) + np.sin(q2) * (ys @ r2)
        sigma = np.array([-1.0, 1.0])[None, :, None, None]
        order = np.argsort(-sigma * above, axis=3)  # u first, then d
        q2, q3 = np.take_along_axis(q2, order, 3), np.take_along_axis(q3, order, 3)
        q4 = s4 * (phi[..., None] - q2 - s3 * q3)

        # the answer, (N, arm, wrist, elbow) -> (N, arm, elbow, wrist) = CONFIGURATIONS
        shape = (N, 2, 2, 2)
        Q = np.empty(shape + (6,))
        Q[..., 0] = _wrap_angle(-theta)[:, :, None, None]
        Q[..., 1], Q[..., 2], Q[..., 3] = (
            _wrap_angle(q2),
            _wrap_angle(q3),
            _wrap_angle(q4),
        )
        Q[..., 4] = _wrap_angle(q5)[..., None]
        Q[..., 5] = _wrap_angle(q6)[..., None]
        reached = (
            shoulder_ok[:, None, None, None]
            & wrist_ok[..., None, None]
            & elbow_ok[..., None]
        )
        flags = np.empty(shape + (3,), dtype=bool)
        flags[..., 0] = (np.abs(excess1) < IK_SINGULAR_TOL * radius1)[
            :, None, None, None
        ]
        flags[..., 1] = (np.abs(excess3) < IK_SINGULAR_TOL * (A3**2 + B3**2))[..., None]
        flags[..., 2] = (
            on_axis[..., None] | (np.sum(a_perp**2, -1) < IK_SINGULAR_TOL)[..., None]
        )
        Q, flags = branches(Q, flags, reached, order=(0, 1, 3, 2))
        code = np.where(
            ~shoulder_ok,
            1,
            np.where(
                np.all(np.isnan(Q[..., 0]), axis=1),
                np.where(wrist_ok.any(axis=1), 2, 3),
                0,
            ),
        )
        return Q, flags, code

    def _reason(self, T, code):
        """A sentence for an unreachable pose T (4, 4) with reason code 1, 2 or 3."""
        w, p, c = self.w, self.p, self.c
        G = T @ inv(self.home)
        d = G[:3, :3] @ c + G[:3, 3] - p[0]
        radial = np.linalg.norm(d - (d @ w[0]) * w[0])
        if code == 1:
            offset = abs(w[1] @ (c - p[0]))
            return (
                f"the wrist point is {radial:.4f} m from the axis of joint 1, closer "
                f"than the shoulder offset {offset:.5f} m"
            )
        if code == 2:
            r2 = np.linalg.norm(p[2] - p[1] - w[1] * (w[1] @ (p[2] - p[1])))
            r3 = np.linalg.norm(p[3] - p[2] - w[1] * (w[1] @ (p[3] - p[2])))
            return (
                f"the axis of joint 4 cannot be placed: joints 2 and 3 reach from "
                f"{abs(r2 - r3):.4f} m to {r2 + r3:.4f} m from axis 2"
            )
        return "the wrist cannot turn the tool to this orientation"
