"""Closed-form inverse kinematics of a 6R arm with a spherical wrist, from its screws.

The arm fits when its last three axes meet in a point c (the wrist centre), the axes of
joints 2 and 3 are parallel, and joint 1's axis is not parallel to them
(the PUMA 560 with any lengths and offsets, the Kawasaki CX210L, and many industrial
arms). With the joint screws xi_i at q = 0 and the home pose M, T = exp(xi_1 q1) ...
exp(xi_6 q6) M, and the wrist joints leave c where it is, so the wrist centre of the
target is w = T M^-1 c and

1. joint 1 (:func:`~.subproblems.subproblem4`): joints 2 and 3 move c in a plane
   perpendicular to their common axis direction u, so q1 must turn w back into the plane
   u . x = u . c: two angles, the arm right ('r') or left ('l');
2. joint 3 (:func:`~.subproblems.subproblem3`): the distance from axis 2 to the
   wrist centre does not depend on q2: two angles, the elbow up ('u') or down ('d');
3. joint 2 (:func:`~.subproblems.subproblem1`): turn exp(xi_3 q3) c onto w;
4. joints 4, 5 (:func:`~.subproblems.subproblem2`): the rotation left for the
   wrist takes the direction of axis 6 to where it must point: two pairs, flip ('f') or
   not ('n'); joint 6 (:func:`~.subproblems.subproblem1`): the rest.

Labels are geometric (they hold for any arm that fits, and equal Corke's for the PUMA
560), with w1 the wrist centre in the frame of link 1 (i.e. at q1 = 0) and w_i the axis
directions:

* arm 'r' when w1 lies on the side of axis 1 that w_1 x w_2 points to, 'l' otherwise;
* elbow 'u' when, seen with the arm pointing forward (w_1 x w_2 for 'r', the opposite
  for 'l'), the elbow (axis 3) lies above the line from the shoulder (axis 2) to w1:
  sigma ((w1 - p2) x (e - p2)) . w_2 > 0, with sigma = +1 for 'r' and -1 for 'l';
* wrist 'f' when (w_4 x w_6) . w_5 > 0 at the current configuration
  (for the PUMA: q5 > 0).

The singular cases, where labels tie or angles are free, follow one documented rule:

* shoulder (w1 on the plane through axis 1 spanned by w_1 and w_2: the two arm solutions
  coincide): the label is 'r'; if w1 is on axis 1 itself
  (only possible without a shoulder offset), q1 is free and the solutions take q1 = 0;
* elbow (stretched or folded: the two elbow solutions coincide): the label is 'd';
* wrist (axes 4 and 6 aligned: only q4 + q6 or q4 - q6 is fixed; the sine of the angle
  between them at most :data:`WRIST_TOL`): the 'f' solution takes q4 = 0 and the 'n'
  solution q4 = pi; a configuration there is labelled 'f' when cos q4 >= 0 and 'n'
  otherwise, so both labels round-trip.

Round-off that pushes a square-root or arccos argument just outside its range (by less
than :data:`~screwkit.tolerances.IK_CLIP_TOL`, relative) is clipped: a pose on a
singularity is solved, not dropped.
"""

from dataclasses import dataclass
from typing import NamedTuple

import numpy as np

from .._checks import as_float_array
from ..links import Joint
from ..tolerances import IK_CLIP_TOL, IK_LABEL_TOL, IK_SINGULAR_TOL, IK_STRUCTURE_TOL
from ..transforms import _cross, _rotate_vectors, _skew, _wrap_angle, inv
from ._closed_form import (
    ClosedFormArm,
    Turn,
    _apply,
    arm_scale,
    branches,
    flip_measure,
)
from .subproblems import _dot_batch as _dot
from .subproblems import distance_angles, plane_angles

__all__ = ["CONFIGURATIONS", "SphericalWristArm", "WRIST_TOL"]

#: The fixed order of the eight solutions: arm l/r, elbow u/d, wrist n/f.
CONFIGURATIONS = ("lun", "luf", "ldn", "ldf", "run", "ruf", "rdn", "rdf")

#: The wrist is singular (axes 4 and 6 aligned, q4 + q6 or q4 - q6 alone fixed) where
#: the sine of the angle between them is at most this. The sine is a unit-free measure
#: computed without cancellation (from the components of axis 6 across axis 4, not as
#: 1 - cos^2), so its round-off is a few 1e-16 whatever the arm's lengths; the labels
#: and the closed form test the same measure against the same number, so every label
#: round-trips. A pose within it is solved with q4 = 0 or pi: its orientation is then
#: off by at most this angle (rad). It is the label tolerance of every closed-form
#: engine, :data:`screwkit.tolerances.IK_LABEL_TOL`.
WRIST_TOL = IK_LABEL_TOL


class _Shoulder(NamedTuple):
    theta: np.ndarray  # (N, 2) = -q1 for the arm l, r
    ct: np.ndarray
    st: np.ndarray
    turn1: Turn
    b1: np.ndarray  # (3, N, 2) the wrist centre at q1 = 0, from axis 2
    ok: np.ndarray  # (N,) reached
    forward: np.ndarray


class _Elbow(NamedTuple):
    q3: np.ndarray  # (N, 2, 2) arm, candidate
    s3: float
    u3: np.ndarray
    cosine: np.ndarray  # (N, 2)
    ok: np.ndarray  # (N, 2)


class _Arm(NamedTuple):
    q2: np.ndarray  # (N, 2, 2) arm, elbow u/d
    c2: np.ndarray
    s2: np.ndarray
    q3: np.ndarray
    c3: np.ndarray
    s3q: np.ndarray


class _Wrist(NamedTuple):
    q4: np.ndarray  # (N, 2, 2, 2) arm, elbow, wrist n/f
    c4: np.ndarray
    s4: np.ndarray
    q5: np.ndarray
    c5: np.ndarray
    s5: np.ndarray
    b: np.ndarray
    x6: np.ndarray
    gamma2: np.ndarray
    n45: np.ndarray
    ok: np.ndarray


def _unit(v):
    return v / np.linalg.norm(v)


def _polar(y, x):
    """atan2(y, x) with its cosine and sine, without calling cos and sin
    (0 where x = y = 0)."""
    h = np.hypot(x, y)
    safe = np.where(h > 0, h, 1.0)
    return np.arctan2(y, x), np.where(h > 0, x / safe, 1.0), y / safe


@dataclass(frozen=True)
class SphericalWristArm(ClosedFormArm):
    """The geometry of a 6R arm with a spherical wrist, taken from its screws (build it
    with :meth:`from_chain`).

    Parameters
    ----------
    w, p, home, scale
        The fields of :class:`~screwkit.ik._closed_form.ClosedFormArm`.
    c : ndarray, shape (3,)
        The wrist centre, where axes 4, 5 and 6 meet (m).

    Examples
    --------
    The PUMA 560's wrist centre at q = 0 is its tool point there (d6 = 0), from
    its DH numbers (a2 + a3, -d3, d4) = (0.4318 + 0.0203, -0.15005, 0.4318):

    >>> import screwkit as sk
    >>> arm = SphericalWristArm.from_chain(sk.robots.puma560())
    >>> np.round(arm.c, 5) + 0.0
    array([ 0.4521 , -0.15005,  0.4318 ])
    """

    c: np.ndarray

    @classmethod
    def _from_chain(cls, chain, name):
        """:meth:`from_chain` of a checked chain."""
        if chain.n != 6:
            raise ValueError(
                f"{name} must have 6 joints for the closed form, got {chain.n}"
            )
        kinds = [i + 1 for i, j in enumerate(chain.joints) if j is not Joint.REVOLUTE]
        if kinds:
            raise ValueError(
                f"{name} must have revolute joints only, got other joints at "
                f"positions {kinds}"
            )
        S = chain.screw_axes()
        w, v = S[:, :3], S[:, 3:]
        norms = np.linalg.norm(w, axis=1)
        pitch = np.sum(w * v, axis=1) / norms**2
        w = w / norms[:, None]
        p = np.cross(
            w, v / norms[:, None]
        )  # the point of each axis nearest the base origin
        scale = arm_scale(p)
        tol = IK_STRUCTURE_TOL * scale
        if np.any(np.abs(pitch) > tol):
            i = int(np.argmax(np.abs(pitch)))
            raise ValueError(
                f"{name} must have revolute joints of pitch 0, "
                f"joint {i + 1} is helical (pitch {pitch[i]:.6g} m/rad)"
            )
        # the wrist centre: the point nearest to axes 4, 5, 6 (least squares)
        projectors = np.eye(3) - w[3:, :, None] * w[3:, None, :]
        c = np.linalg.lstsq(
            projectors.sum(0), np.einsum("kij,kj->i", projectors, p[3:]), rcond=None
        )[0]
        miss = np.linalg.norm(
            np.einsum("kij,kj->ki", projectors, c - p[3:]), axis=1
        ).max()
        parallel = [np.linalg.norm(np.cross(w[i], w[j])) for i, j in ((3, 4), (4, 5))]
        if min(parallel) < IK_STRUCTURE_TOL:
            raise ValueError(
                f"{name} must have a spherical wrist: the axes of joints 4 and 5, "
                "and of joints 5 and 6, must not be parallel"
            )
        if miss > tol:
            raise ValueError(
                f"{name} must have a spherical wrist: the axes of joints 4, 5 and "
                f"6 must meet in one point, they miss it by {miss:.3g} m"
            )
        sine23 = np.linalg.norm(np.cross(w[1], w[2]))
        if sine23 > IK_STRUCTURE_TOL:
            angle23 = np.degrees(np.arcsin(min(1.0, sine23)))
            raise ValueError(
                f"{name} must have parallel axes for joints 2 and 3, got an angle "
                f"of {angle23:.6g} deg between them"
            )
        if np.linalg.norm(np.cross(w[0], w[1])) < IK_STRUCTURE_TOL:
            raise ValueError(
                f"{name} must have the axis of joint 1 not parallel to the axes "
                "of joints 2 and 3"
            )
        gap = p[2] - p[1] - w[1] * (w[1] @ (p[2] - p[1]))
        if np.linalg.norm(gap) < tol:
            raise ValueError(
                f"{name} must have distinct axes for joints 2 and 3 (a2 > 0), "
                "got the same line"
            )
        reach = c - p[2] - w[2] * (w[2] @ (c - p[2]))
        if np.linalg.norm(reach) < tol:
            raise ValueError(
                f"{name} must have its wrist centre off the axis of joint 3"
            )
        return cls(w=w, p=p, c=c, home=chain.home(), scale=scale)

    # ---- labels ----------------------------------------------------------------------

    def _arm_plane(self, q2, q3):
        """The wrist centre w1 (..., 3) at q1 = 0 and the elbow point relative to axis
        2."""
        w, p, c = self.w, self.p, self.c
        wrist = p[2] + _rotate_vectors(
            w[2], q3, np.broadcast_to(c - p[2], q3.shape + (3,))
        )
        w1 = p[1] + _rotate_vectors(w[1], q2, wrist - p[1])
        elbow = _rotate_vectors(w[1], q2, np.broadcast_to(p[2] - p[1], q2.shape + (3,)))
        return w1, elbow

    def _measures(self, q):
        """(forward, elbow, wrist) of q (..., 6): the signed measures the labels
        test."""
        w, p = self.w, self.p
        w1, elbow = self._arm_plane(q[..., 1], q[..., 2])
        forward = (w1 - p[0]) @ np.cross(w[0], w[1])
        above = np.cross(w1 - p[1], elbow) @ w[1]
        return forward, above, flip_measure(w, q[..., 4])

    def wrist_sine(self, q5):
        """The measure of the wrist singularity (see :data:`WRIST_TOL`).

        Parameters
        ----------
        q5 : array-like, shape (...)
            Joint 5's angle (rad).

        Returns
        -------
        ndarray, shape (...)
            ``|w4 x R(w5, q5) w6|``, the sine of the angle between axes 4 and 6.

        Examples
        --------
        The PUMA's axes 4 and 6 are at the angle q5: ``abs(sin q5)``.

        >>> import screwkit as sk
        >>> arm = SphericalWristArm.from_chain(sk.robots.puma560())
        >>> np.round(arm.wrist_sine([0.0, np.pi / 2, np.pi / 6]), 6) + 0.0
        array([0. , 1. , 0.5])
        """
        return self._wrist_sine(as_float_array(q5, "q5"))

    def _wrist_sine(self, q5):
        """:meth:`wrist_sine` of a float array q5 (...)."""
        w4, w5, w6 = self.w[3], self.w[4], self.w[5]
        c5, s5 = np.cos(q5)[..., None], np.sin(q5)[..., None]
        across = (
            np.cross(w4, w6) * c5
            + np.cross(w4, np.cross(w5, w6)) * s5
            + np.cross(w4, w5) * ((w5 @ w6) * (1 - c5))
        )
        return np.linalg.norm(across, axis=-1)

    def _labels(self, q):
        """The configuration labels of q (..., 6): an array of strings like 'ruf'."""
        forward, above, flip = self._measures(q)
        tol = IK_LABEL_TOL * self.scale  # forward is a length (m), above an area (m^2)
        right = forward >= -tol
        up = np.where(right, above, -above) > tol * self.scale
        singular = self._wrist_sine(q[..., 4]) <= WRIST_TOL
        flipped = np.where(singular, np.cos(q[..., 3]) >= 0, flip > 0)
        arm = np.where(right, "r", "l")
        return np.char.add(
            np.char.add(arm, np.where(up, "u", "d")), np.where(flipped, "f", "n")
        )

    # ---- the closed form -------------------------------------------------------------

    def _solve(self, T):
        """The closed form of the poses T (N, 4, 4), one named step per joint group.

        Vectors are laid out (3, ...): their components first, so that products with the
        fixed axis directions are single BLAS calls.
        """
        G = T @ inv(self.home)
        RG = G[:, :3, :3]
        d = (
            RG @ self.c + G[:, :3, 3] - self.p[0]
        ).T  # the wrist centre of the target, from p1
        shoulder = self._joint1(d)
        elbow = self._joint3(shoulder.b1)
        arm = self._joint2(shoulder.b1, elbow)
        wrist = self._joints45(RG, shoulder, arm)
        q6 = self._joint6(wrist)
        return self._assemble(shoulder, elbow, arm, wrist, q6)

    def _joint1(self, d):
        """Joint 1 (subproblem 4): turn the wrist centre d (3, N) by theta = -q1 onto
        the plane w2 . x = w2 . c; two angles (N, 2), the arm l and r."""
        w, p, c = self.w, self.p, self.c
        w1, w2 = w[0], w[1]
        phi, half, excess, rho2 = plane_angles(w1, w2, w2 @ (c - p[0]), d)
        ok = excess >= -IK_CLIP_TOL * self.scale**2
        forward = np.sqrt(np.maximum(excess, 0.0))
        free = rho2 < (IK_CLIP_TOL * self.scale) ** 2  # the wrist centre on axis 1
        theta = np.stack([phi - half, phi + half], axis=1)  # (N, 2): arm l, r
        theta = np.where(free[:, None], 0.0, theta)
        ct, st = np.cos(theta), np.sin(theta)
        turn1 = Turn(w1)
        # b1 = w1 - p2: the wrist centre at q1 = 0 seen from axis 2, (3, N, 2)
        b1 = turn1.first(np.repeat(d[:, :, None], 2, axis=2), ct, st)
        b1 += (p[0] - p[1])[:, None, None]
        return _Shoulder(theta, ct, st, turn1, b1, ok, forward)

    def _joint3(self, b1):
        """Joint 3 (subproblem 3): |exp(xi3 q3) c - p2| = |w1 - p2|; two angles per arm,
        q3 (N, 2, 2), the elbow's two candidates."""
        w, p, c = self.w, self.p, self.c
        w2 = w[1]
        s3 = 1.0 if w2 @ w[2] > 0 else -1.0  # axis 3 is +-w2
        u3 = c - p[2] - w2 * (w2 @ (c - p[2]))
        v3 = p[1] - p[2] - w2 * (w2 @ (p[1] - p[2]))
        delta2 = np.sum(b1**2, axis=0) - (w2 @ (c - p[1])) ** 2
        theta0, cosine = distance_angles(w2, u3, v3, delta2)
        ok = np.abs(cosine) <= 1 + IK_CLIP_TOL
        cosine = np.clip(cosine, -1.0, 1.0)
        beta = np.arccos(cosine)
        theta0 = s3 * theta0
        q3 = theta0 + s3 * np.stack([-beta, beta], axis=-1)  # (N, 2, 2): arm, candidate
        return _Elbow(q3, s3, u3, cosine, ok)

    def _joint2(self, b1, elbow):
        """Joint 2 (subproblem 1): the angle about w2 from a = p3 - p2 + R3 (c - p3) to
        b1, then the two elbow solutions ordered u first, d second."""
        w, p, c = self.w, self.p, self.c
        w2 = w[1]
        s3, u3 = elbow.s3, elbow.u3
        # a = k0 + cos(q3) k1 + sin(q3) k2, and b1 . (w2 x k) = -m . k with m = w2 x b1
        c3, s3q = np.cos(s3 * elbow.q3), np.sin(s3 * elbow.q3)
        k0 = p[2] - p[1] + w2 * (w2 @ (c - p[2]))
        k1, k2 = u3, _cross(w2, u3)
        m = _apply(_skew(w2), b1)
        dots = [_dot(k, b1)[..., None] for k in (k0, k1, k2)]
        crosses = [-_dot(k, m)[..., None] for k in (k0, k1, k2)]
        along = (_dot(w2, b1) * (k0 @ w2))[..., None]
        q2, c2, s2 = _polar(
            crosses[0] + c3 * crosses[1] + s3q * crosses[2],
            dots[0] + c3 * dots[1] + s3q * dots[2] - along,
        )
        # the elbow label: above = ((w1 - p2) x R2 (p3 - p2)) . w2; the larger
        # sigma*above is 'u'
        e = p[2] - p[1] - w2 * (w2 @ (p[2] - p[1]))
        above = c2 * _dot(e, m)[..., None] + s2 * _dot(_cross(w2, e), m)[..., None]
        sigma = np.array([-1.0, 1.0])
        swap = sigma * above[..., 0] < sigma * above[..., 1]  # (N, 2)
        swap = swap[..., None]
        q2, c2, s2, q3, c3, s3q = (
            np.where(swap, v[..., ::-1], v)  # u first, then d
            for v in (q2, c2, s2, elbow.q3, c3, s3q)
        )
        return _Arm(q2, c2, s2, _wrap_angle(q3), c3, s3q)

    def _joints45(self, RG, shoulder, arm):
        """Joints 4 and 5 (subproblem 2): the rotation left for the wrist,
        Rw = R23^T R1^T RG, takes w6 to t and x6 to b; two (q4, q5) pairs per arm and
        elbow, n and f.

        At the wrist singularity (axis 6 of the target on axis 4, the sine between them
        at most :data:`WRIST_TOL`) q4 is free: 'n' takes pi, 'f' takes 0.
        """
        w = self.w
        w2, w4, w5, w6 = w[1], w[3], w[4], w[5]
        ct, st, c2, s2, c3, s3q = (
            shoulder.ct,
            shoulder.st,
            arm.c2,
            arm.s2,
            arm.c3,
            arm.s3q,
        )
        x6 = _unit(_cross(w5, w6))
        g = np.stack([RG @ w6, RG @ x6], axis=-1).transpose(1, 0, 2)  # (3, N, 2)
        g = shoulder.turn1.first(
            np.repeat(g[:, :, None], 2, axis=2), ct[..., None], st[..., None]
        )
        c23, s23 = (
            c2 * c3 - s2 * s3q,
            s2 * c3 + c2 * s3q,
        )  # of q2 + s3 q3: turn back by it
        g = Turn(w2).first(
            np.repeat(g[:, :, :, None], 2, axis=3), c23[..., None], -s23[..., None]
        )
        t, b = g[..., 0], g[..., 1]  # (3, N, 2, 2)
        c45, c46, c56 = w4 @ w5, w4 @ w6, w5 @ w6
        n45 = _cross(w4, w5)
        t4, t5, tn, tm = (_dot(v, t) for v in (w4, w5, n45, _cross(w4, n45)))
        a = (c45 * c56 - t4) / (c45**2 - 1)
        bb = (c45 * t4 - c56) / (c45**2 - 1)
        # gamma^2 = |z_perp|^2 / |n45|^2 - bb^2 with |z_perp| = |t_perp|
        # (no cancellation of 1 - t4^2 near the wrist singularity)
        gamma2 = (tn**2 + tm**2) / (n45 @ n45) ** 2 - bb**2
        sine46 = np.sqrt(tn**2 + tm**2) / np.sqrt(
            n45 @ n45
        )  # |t x w4|: the wrist's sine
        ok = gamma2 >= -IK_CLIP_TOL
        gamma = np.sqrt(np.maximum(gamma2, 0.0))[..., None] * np.array(
            [1.0, -1.0]
        )  # n, f
        a, bb, t4, t5, tn, tm = (v[..., None] for v in (a, bb, t4, t5, tn, tm))
        # q5: about w5 from w6 to z = a w4 + bb w5 + gamma n45; q4: about w4 from z to t
        n56 = _cross(w5, w6)
        # (z . t - (z . w4)(t . w4) written without the cancelling terms)
        q5, c5, s5 = _polar(
            a * (w4 @ n56) + gamma * (n45 @ n56),
            a * (c46 - c45 * c56) + gamma * (n45 @ w6),
        )
        q4, c4, s4 = _polar(bb * tn + gamma * tm, bb * (t5 - c45 * t4) + gamma * tn)
        # the wrist singularity, by the same measure and tolerance as the labels
        on_axis4 = (sine46 <= WRIST_TOL)[..., None]
        if np.any(on_axis4):
            free5 = _polar(_dot(n56, t)[..., None], _dot(w6, t)[..., None] - c56 * t5)
            q5, c5, s5 = (
                np.where(on_axis4, new, old) for new, old in zip(free5, (q5, c5, s5))
            )
            q4 = np.where(on_axis4, np.array([np.pi, 0.0]), q4)
            c4 = np.where(on_axis4, np.array([-1.0, 1.0]), c4)
            s4 = np.where(on_axis4, 0.0, s4)
        return _Wrist(q4, c4, s4, q5, c5, s5, b, x6, gamma2, n45, ok)

    def _joint6(self, wrist):
        """Joint 6 (subproblem 1): about w6 from x6 to y = R5^T R4^T b, with y . e =
        b . (R4 R5 e) expanded by Rodrigues into dot products of b with fixed vectors
        (no rotated copies of b)."""
        w4, w5, w6 = self.w[3], self.w[4], self.w[5]
        b, c4, s4, c5, s5 = wrist.b, wrist.c4, wrist.s4, wrist.c5, wrist.s5

        def turned4(f):  # b . R4 f
            return (
                _dot(f, b)[..., None] * c4
                + _dot(_cross(w4, f), b)[..., None] * s4
                + _dot(w4, b)[..., None] * (w4 @ f) * (1 - c4)
            )

        def along(e):  # b . R4 R5 e, (N, 2, 2, 2)
            return (
                turned4(e) * c5
                + turned4(_cross(w5, e)) * s5
                + turned4(w5) * (w5 @ e) * (1 - c5)
            )

        return np.arctan2(along(_cross(w6, wrist.x6)), along(wrist.x6))

    def _assemble(self, shoulder, elbow, arm, wrist, q6):
        """The answer: Q (N, 8, 6) in the order of CONFIGURATIONS
        (NaN where a branch does not reach), the singularity flags (N, 8, 3) and the
        reason codes (N,)."""
        N = shoulder.theta.shape[0]
        shape = (N, 2, 2, 2)
        Q = np.empty(shape + (6,))
        Q[..., 0] = _wrap_angle(-shoulder.theta)[:, :, None, None]
        Q[..., 1] = arm.q2[..., None]
        Q[..., 2] = arm.q3[..., None]
        Q[..., 3], Q[..., 4], Q[..., 5] = wrist.q4, wrist.q5, q6
        reached = (
            shoulder.ok[:, None, None, None]
            & elbow.ok[:, :, None, None]
            & wrist.ok[..., None]
        )
        flags = np.empty(shape + (3,), dtype=bool)
        flags[..., 0] = (shoulder.forward**2 < IK_SINGULAR_TOL * self.scale**2)[
            :, None, None, None
        ]
        flags[..., 1] = (1 - np.abs(elbow.cosine) < IK_SINGULAR_TOL)[:, :, None, None]
        flags[..., 2] = (
            np.sqrt(np.maximum(wrist.gamma2, 0)) * np.linalg.norm(wrist.n45)
            < IK_SINGULAR_TOL
        )[..., None]
        Q, flags = branches(Q, flags, reached)
        code = np.where(
            ~shoulder.ok,
            1,
            np.where(
                ~elbow.ok.any(axis=1),
                2,
                np.where(np.all(np.isnan(Q[..., 0]), axis=1), 3, 0),
            ),
        )
        return Q, flags, code

    def _reason(self, T, code):
        """A sentence for an unreachable pose T (4, 4) with reason code 1, 2 or 3."""
        w, p, c = self.w, self.p, self.c
        G = T @ inv(self.home)
        wc = G[:3, :3] @ c + G[:3, 3]
        d = wc - p[0]
        radial = np.linalg.norm(d - (d @ w[0]) * w[0])
        offset = abs(w[1] @ (c - p[0]))
        if code == 1:
            return (
                f"the wrist centre is {radial:.4f} m from the axis of joint 1, closer "
                f"than the shoulder offset {offset:.5f} m"
            )
        if code == 2:
            u3 = np.linalg.norm(c - p[2] - w[2] * (w[2] @ (c - p[2])))
            v3 = np.linalg.norm(p[1] - p[2] - w[2] * (w[2] @ (p[1] - p[2])))
            phi, half, _, _ = plane_angles(w[0], w[1], w[1] @ (c - p[0]), d)
            distances = []
            for theta in (phi - half, phi + half):
                w1 = p[0] + _rotate_vectors(w[0], np.array(theta), d)
                distances.append(
                    np.sqrt(max(np.sum((w1 - p[1]) ** 2) - (w[2] @ (c - p[1])) ** 2, 0))
                )
            return (
                f"the wrist centre is {min(distances):.4f} m from the shoulder axis "
                f"in the arm's plane; the arm reaches from {abs(u3 - v3):.4f} m to "
                f"{u3 + v3:.4f} m"
            )
        return "the wrist cannot turn the tool to this orientation"
