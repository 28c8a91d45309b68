"""Closed-form inverse kinematics of an RRP arm with a spherical wrist (Stanford arm).

The arm fits when joints 1 and 2 are revolute with axes that meet in a point o (not
parallel), joint 3 is prismatic (direction v) and the axes of joints 4, 5, 6 meet in a
point c, the wrist centre (the Stanford arm with any lengths, base and tool). With the
joint screws xi_i at q = 0 and the home pose M, G = T M^-1 = exp(xi_1 q1) ...
exp(xi_6 q6); the wrist joints leave c where it is, so the wrist centre of the target
is w = G c and

1. joint 3 (a line meets a sphere, :func:`~.subproblems.subproblem3_prismatic`):
   joints 1 and 2 turn about o, so |c + q3 v - o| = |w - o|: two lengths, the boom
   pointing to the wrist centre ('u', the larger q3) or through the shoulder away from
   it ('d', a q3 that a real boom's travel excludes);
2. joints 1, 2 (:func:`~.subproblems.subproblem2`): turn c + q3 v onto w: two
   pairs, the arm right ('r') or left ('l');
3. joints 4, 5 (subproblem 2 on directions): the rotation left for the wrist takes the
   direction of axis 6 to where it must point: two pairs, flip ('f') or not ('n'); joint
   6 (subproblem 1): the rest.

So eight solutions, four with the boom forward: ``analytic_ik(..., within_limits=True)``
keeps the four that the prismatic joint's limits allow. Labels are geometric, with x the
wrist centre at q1 = 0 (after joints 2 and 3): arm 'r' when (x - o) . (w_1 x w_2) >= 0;
'u' when q3 + v . (c - o) >= 0 (the boom's far side holds the wrist centre); wrist 'f'
when (w_4 x w_6) . w_5 > 0 at the configuration. Singular cases: shoulder (the two arm
solutions coincide; the label is 'r'), boom (c + q3 v nearest to o: the two lengths
coincide; 'u'), wrist (axes 4 and 6 aligned: q4 = 0 and only q4 + q6 or q4 - q6 matters;
labelled by the flip measure, 'f' at a tie).
"""

from dataclasses import dataclass

import numpy as np

from ..tolerances import IK_CLIP_TOL, IK_LABEL_TOL, IK_SINGULAR_TOL, IK_STRUCTURE_TOL
from ..transforms import _rotate_vectors, _wrap_angle, inv
from ._closed_form import ClosedFormArm, arm_scale, branches, flip_measure
from .subproblems import meeting_points, rotation_angles

__all__ = ["StanfordArm", "STRUCTURE"]

#: The structure's name, as ``analytic_ik`` reports it.
STRUCTURE = "RRP arm with a spherical wrist (Stanford)"


@dataclass(frozen=True)
class StanfordArm(ClosedFormArm):
    """The geometry of an RRP arm with a spherical wrist, from its screws. Build it
    with :meth:`from_chain`.

    Parameters
    ----------
    w, p, home, scale
        The fields of :class:`~screwkit.ik._closed_form.ClosedFormArm`; w[2] is the
        boom's direction v, p[2] is 0.
    o : ndarray, shape (3,)
        The point where axes 1 and 2 meet (m).
    c : ndarray, shape (3,)
        The wrist centre, where axes 4, 5 and 6 meet (m).

    Examples
    --------
    The Stanford arm (d1 = 0.412, d2 = 0.154 m): axes 1 and 2 meet at height d1;
    with the boom in (q3 = 0) the wrist centre is d2 to the side of it.

    >>> import screwkit as sk
    >>> arm = StanfordArm.from_chain(sk.robots.stanford())
    >>> np.round(arm.o, 5) + 0.0, np.round(arm.c, 5) + 0.0
    (array([0.   , 0.   , 0.412]), array([0.   , 0.154, 0.412]))
    """

    o: np.ndarray
    c: np.ndarray

    structure = STRUCTURE
    #: Which joints are angles (moved by whole turns into limits): all but the boom.
    revolute = np.array([True, True, False, True, True, True])

    @classmethod
    def _from_chain(cls, chain, name):
        """:meth:`from_chain` of a checked chain."""
        if chain.n != 6:
            raise ValueError(f"{name} must have 6 joints, got {chain.n}")
        kinds = "".join(j.value for j in chain.joints)
        if kinds != "RRPRRR":
            raise ValueError(
                f"{name} must have joints RRPRRR (joint 3 prismatic), got {kinds}"
            )
        S = chain.screw_axes()
        w, v = S[:, :3].copy(), S[:, 3:]
        w[2] = v[2] / np.linalg.norm(v[2])
        revolute = [0, 1, 3, 4, 5]
        w[revolute] /= np.linalg.norm(w[revolute], axis=1)[:, None]
        p = np.zeros((6, 3))
        p[revolute] = np.cross(w[revolute], v[revolute])
        scale = arm_scale(p)
        tol = IK_STRUCTURE_TOL * scale
        points = []
        for axes, what in (((0, 1), "1 and 2"), ((3, 4, 5), "4, 5 and 6")):
            projectors = np.eye(3) - w[list(axes), :, None] * w[list(axes), None, :]
            A = projectors.sum(0)
            if np.linalg.matrix_rank(A, tol=IK_STRUCTURE_TOL) < 3:
                raise ValueError(
                    f"{name} must have the axes of joints {what} meeting in "
                    "one point, got parallel axes"
                )
            point = np.linalg.solve(
                A, np.einsum("kij,kj->i", projectors, p[list(axes)])
            )
            miss = np.linalg.norm(
                np.einsum("kij,kj->ki", projectors, point - p[list(axes)]), axis=1
            ).max()
            if miss > tol:
                raise ValueError(
                    f"{name} must have the axes of joints {what} meeting in "
                    f"one point, they miss it by {miss:.3g} m"
                )
            points.append(point)
        o, c = points
        if (
            min(
                np.linalg.norm(np.cross(w[3], w[4])),
                np.linalg.norm(np.cross(w[4], w[5])),
            )
            < IK_STRUCTURE_TOL
        ):
            raise ValueError(
                f"{name} must have a spherical wrist: the axes of joints 4 and "
                "5, and of joints 5 and 6, must not be parallel"
            )
        return cls(w=w, p=p, o=o, c=c, home=chain.home(), scale=scale)

    # ---- labels ---------------------------------------------------------------------

    def _measures(self, q):
        """(forward, boom, flip) of q (..., 6): the signed measures the labels test."""
        w, o, c = self.w, self.o, self.c
        q = np.asarray(q, dtype=float)
        x = c + q[..., 2, None] * w[2] - o
        x = _rotate_vectors(w[1], q[..., 1], x)
        forward = x @ np.cross(w[0], w[1])
        boom = q[..., 2] + w[2] @ (c - o)
        return forward, boom, flip_measure(w, q[..., 4])

    def _labels(self, q):
        """The configuration labels of q (..., 6): an array of strings like 'ruf'."""
        forward, boom, flip = self._measures(q)
        tol = IK_LABEL_TOL * self.scale  # forward and boom are lengths (m)
        arm = np.where(forward >= -tol, "r", "l")
        elbow = np.where(boom >= -tol, "u", "d")
        wrist = np.where(flip >= -IK_LABEL_TOL, "f", "n")
        return np.char.add(np.char.add(arm, elbow), wrist)

    # ---- the closed form ------------------------------------------------------------

    def _solve(self, T):
        w, o, c = self.w, self.o, self.c
        v = w[2]
        N = T.shape[0]
        G = T @ inv(self.home)
        RG = G[:, :3, :3]
        y = RG @ c + G[:, :3, 3] - o  # the wrist centre of the target, from o, (N, 3)

        # joint 3: |c - o + q3 v| = |y|, the larger root first ('u', then 'd')
        b = v @ (c - o)
        disc = b**2 - ((c - o) @ (c - o) - np.sum(y * y, -1))
        boom_ok = disc >= -IK_CLIP_TOL * self.scale**2
        root = np.sqrt(np.maximum(disc, 0.0))
        q3 = -b + root[:, None] * np.array([1.0, -1.0])  # (N, 2): u, d

        # joints 1, 2: exp(xi2 q2) x = z, exp(xi1 q1) z = y with x = c - o + q3 v
        x = (c - o) + q3[..., None] * v  # (N, 2, 3)
        z, gamma2 = meeting_points(
            w[0], w[1], x, y[:, None]
        )  # (N, 2, 2, 3): boom, arm l/r
        shoulder_ok = gamma2 >= -IK_CLIP_TOL * self.scale**2
        q2 = rotation_angles(w[1], x[:, :, None], z)
        q1 = rotation_angles(w[0], z, y[:, None, None])  # (N, 2, 2)

        # the wrist: Rw = R2^T R1^T RG = R4 R5 R6; t = Rw w6
        t = np.einsum("nij,j->ni", RG, w[5])[:, None, None]
        t = _rotate_vectors(w[1], -q2, _rotate_vectors(w[0], -q1, t))  # (N, 2, 2, 3)
        zw, gamma_w = meeting_points(w[3], w[4], np.broadcast_to(w[5], t.shape), t)
        wrist_ok = gamma_w >= -IK_CLIP_TOL
        q5 = rotation_angles(w[4], w[5], zw)  # (N, 2, 2, 2)
        q4 = rotation_angles(w[3], zw, t[..., None, :])
        order = np.argsort(flip_measure(w, q5), axis=-1)  # n first, then f
        q4, q5 = np.take_along_axis(q4, order, -1), np.take_along_axis(q5, order, -1)
        # q6: about w6 from x6 to R5^T R4^T Rw x6
        x6 = np.cross(w[4], w[5])
        x6 = x6 / np.linalg.norm(x6)
        g = np.einsum("nij,j->ni", RG, x6)[:, None, None]
        g = _rotate_vectors(w[1], -q2, _rotate_vectors(w[0], -q1, g))[..., None, :]
        g = _rotate_vectors(w[4], -q5, _rotate_vectors(w[3], -q4, g))
        q6 = rotation_angles(w[5], np.broadcast_to(x6, g.shape), g)

        # the answer: (N, boom, arm, wrist) -> (N, arm, boom, wrist) = CONFIGURATIONS
        shape = (N, 2, 2, 2)
        Q = np.empty(shape + (6,))
        Q[..., 0] = _wrap_angle(q1)[..., None]
        Q[..., 1] = _wrap_angle(q2)[..., None]
        Q[..., 2] = q3[:, :, None, None]
        Q[..., 3], Q[..., 4], Q[..., 5] = (
            _wrap_angle(q4),
            _wrap_angle(q5),
            _wrap_angle(q6),
        )
        reached = (
            boom_ok[:, None, None, None]
            & shoulder_ok[..., None, None]
            & wrist_ok[..., None]
        )
        flags = np.empty(shape + (3,), dtype=bool)
        flags[..., 0] = (np.abs(gamma2) < IK_SINGULAR_TOL * self.scale**2)[
            ..., None, None
        ]
        flags[..., 1] = (np.abs(disc) < IK_SINGULAR_TOL * self.scale**2)[
            :, None, None, None
        ]
        flags[..., 2] = (np.abs(gamma_w) < IK_SINGULAR_TOL)[..., None]
        Q, flags = branches(Q, flags, reached, order=(0, 2, 1, 3))
        code = np.where(
            ~boom_ok,
            2,
            np.where(
                ~shoulder_ok.any(axis=1),
                1,
                np.where(np.all(np.isnan(Q[..., 0]), axis=1), 3, 0),
            ),
        )
        return Q, flags, code

    def _reason(self, T, code):
        """A sentence for an unreachable pose T (4, 4) with reason code 1, 2 or 3."""
        G = T @ inv(self.home)
        y = G[:3, :3] @ self.c + G[:3, 3] - self.o
        d = self.c - self.o
        line = np.linalg.norm(d - self.w[2] * (self.w[2] @ d))
        if code == 2:
            return (
                f"the wrist centre is {np.linalg.norm(y):.4f} m from the shoulder, "
                f"closer than the boom's line passes ({line:.4f} m)"
            )
        if code == 1:
            return "joints 1 and 2 cannot turn the boom to the wrist centre"
        return "the wrist cannot turn the tool to this orientation"
