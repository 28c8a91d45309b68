"""Parallel manipulators in motion: legs' inverse kinematics, forward kinematics by loop
closure, Jacobians from the legs' wrenches, singularity types and workspaces.

A :class:`ParallelManipulator` is a fixed base and a moving platform joined by m limbs,
each a serial chain of joint screws from a base point A_i to a platform point b_i
(platform frame), with one actuated joint per limb. Its output is the platform pose T
(4 x 4, base frame), its input the actuated joint values rho (m,): leg lengths (m) or
crank angles (rad).

Conventions are the library's: screws [angular; linear]; V = [w; v] is the platform's
space twist (T' T^-1 = [V], as ``Chain.space_jacobian``), and ``jacobian(T)`` gives
rho' = J V. The rows of J are the actuation wrenches (force; moment) with their halves
swapped, scaled so that their power on V is the actuator's rate (Joshi & Tsai 2002): for
the Stewart platform the legs' unit line screws.

>>> from screwkit.parallel import stewart_gough
>>> pm = stewart_gough()
>>> rho = pm.ik(pm.home())
>>> bool(np.allclose(pm.fk(rho, guess=pm.home()).T, pm.home()))
True
"""

import itertools
from dataclasses import dataclass

import numpy as np
import sympy as sp

from .._checks import (
    as_float_array,
    check_flag,
    check_integer,
    check_option,
    check_poses,
    check_positive,
    check_rotation,
    check_transform,
    describe,
    is_symbolic,
)
from ..screws import Wrench
from ..systems import ScrewSystem
from ..tolerances import PARALLEL_FK_TOL, PARALLEL_MOTION_TOL
from . import numeric as _numeric
from . import proven as _proven
from . import search as _search
from .legs import Linear, Prismatic, Revolute, evaluated
from .search import AssemblyModes

#: Poses per block of the batched computations: a block's arrays stay in the cache.
_BLOCK = 4096

#: The largest workspace grid (points), as sk.workspace bounds its sweeps.
MAX_WORKSPACE_POINTS = 10_000_000

#: The most random starts fk_all's search takes: 100 000 starts hold about 30 MB of
#: Newton's arrays for a Stewart platform (10^8 would need about 12 GB).
MAX_FK_STARTS = 100_000

#: Starts projected onto the solutions by least-squares Newton when the search found
#: no mode (a continuum makes Newton's exact steps fail): a few dozen reach it.
_CONTINUUM_STARTS = 32

#: The free components of the platform twist [wx, wy, wz, vx, vy, vz] per motion type.
_FREEDOMS = {
    "spatial": [0, 1, 2, 3, 4, 5],
    "planar": [2, 3, 4],
    "translational": [3, 4, 5],
}
_TYPES = {"spatial": "3T3R", "planar": "2T1R", "translational": "3T"}


@dataclass
class ParallelIK:
    """Inverse kinematics in full: what ``pm.ik(T, passive=True)`` returns.

    Parameters
    ----------
    rho : ndarray, shape (m,) or (N, m)
        The actuated joint values (m or rad), NaN where out of reach (or a list of
        SymPy expressions for an exact pose).
    passive : dict of str to ndarray
        The passive joints by name ('phi', 'u1', 'u2', 'elbow', 'theta2'), each with
        a leading batch axis for a batch of poses.
    reachable : bool or ndarray of bool, shape (N,)
        Whether every leg reaches the pose within its limits.
    reason : str or list of str
        '' when reachable, else which legs cannot reach or leave their limits.
    mode : str
        The working mode's label.

    Examples
    --------
    A 3-RPR whose home pose has legs of 5, 4 and 4 m (A = (0, 0), (4, 0), (3, 9);
    C = (3, 4), (4, 4), (3, 5)); the passive angles of the legs are atan2(4, 3),
    90 and -90 degrees.

    >>> from screwkit.parallel import planar_3rpr
    >>> from screwkit.transforms import transl
    >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
    ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
    >>> result = pm.ik(pm.home(), passive=True)
    >>> result.rho, result.reachable, result.passive["phi"].round(4)
    (array([5., 4., 4.]), True, array([ 0.9273,  1.5708, -1.5708]))
    """

    rho: object
    passive: dict
    reachable: object
    reason: object
    mode: str


@dataclass
class ParallelFK:
    """Forward kinematics: what ``pm.fk(rho)`` returns.

    Parameters
    ----------
    T : ndarray, shape (4, 4) or (N, 4, 4)
        The platform pose(s), NaN where Newton did not converge.
    success : bool or ndarray of bool, shape (N,)
        Whether Newton converged.
    iterations : int or ndarray of int, shape (N,)
        The Newton steps taken.
    error : float or ndarray, shape (N,)
        The largest loop-closure residual of each pose (m).

    Examples
    --------
    >>> from screwkit.parallel import stewart_gough
    >>> pm = stewart_gough()
    >>> result = pm.fk(pm.ik(pm.home()))
    >>> result.success, bool(np.allclose(result.T, pm.home()))
    (True, True)
    """

    T: np.ndarray
    success: object
    iterations: object
    error: object


@dataclass
class Workspace:
    """A constant-orientation workspace on a grid: what ``pm.workspace(x, y)`` returns.

    Parameters
    ----------
    x, y : ndarray, shapes (nx,) and (ny,)
        The grid (m, base frame).
    z : ndarray, shape ()
        Its height (m).
    inside : ndarray of bool, shape (ny, nx)
        Where every leg is reachable and within its limits.
    det : ndarray, shape (ny, nx)
        The determinant of the Jacobian's free columns (NaN outside); its zero level
        is the direct-singularity locus.
    rho : ndarray, shape (ny, nx, m)
        The actuated values (m or rad).
    rotation : ndarray, shape (3, 3)
        The platform's constant rotation.

    Examples
    --------
    One grid point, the home of a 3-RPR with legs of 5, 4 and 4 m there; the
    determinant of J's free columns (w_z, v_x, v_y) is 0.6 by hand.

    >>> from screwkit.parallel import planar_3rpr
    >>> from screwkit.transforms import transl
    >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
    ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
    >>> ws = pm.workspace([3.0], [4.0])
    >>> ws.inside, ws.rho, ws.det.round(12)
    (array([[ True]]), array([[[5., 4., 4.]]]), array([[0.6]]))
    """

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    inside: np.ndarray
    det: np.ndarray
    rho: np.ndarray
    rotation: np.ndarray


class ParallelManipulator:
    """A parallel manipulator: m legs between a base and a platform, one actuator each.

    Built by the catalogue (``sk.parallel.stewart_gough()`` and the others); models are
    immutable.

    Its attributes, besides the parameters: ``m`` (int), the number of legs;
    ``base_points`` and ``platform_points`` (ndarray, shape (m, 3)), A_i and b_i as
    floats (m); ``working_modes`` (list of str), the labels ``ik`` accepts as ``mode``;
    and :attr:`scale`, its size (m).

    Parameters
    ----------
    name : str
        The mechanism's name, for printing.
    legs : Prismatic, Revolute or Linear
        The legs' model (:mod:`screwkit.parallel.legs`): their IK and loop closure.
    base : array-like, shape (m, 3)
        Attachment points A_i (m, base frame); SymPy entries keep the exact layer
        exact.
    platform : array-like, shape (m, 3)
        Attachment points b_i (m, platform frame).
    motion : {'spatial', 'planar', 'translational'}
        6 freedoms, or x, y and the angle about z, or the three translations.
    home : array-like, shape (4, 4)
        The home pose.
    leg_limits : array-like, shape (m, 2), optional
        Limits of the actuated joints (m or rad); None for none.
    default_mode : str, optional
        The working mode ``ik`` uses when none is given.

    Examples
    --------
    >>> from screwkit.parallel import stewart_gough
    >>> pm = stewart_gough()
    >>> pm, pm.m, pm.working_modes
    (ParallelManipulator('Stewart-Gough 6-UPS', 6 legs, 3T3R), 6, ['single'])
    """

    def __init__(
        self,
        name,
        legs,
        base,
        platform,
        motion,
        home,
        leg_limits=None,
        default_mode=None,
    ):
        self.name = name
        self._unit_model = None  # the same in scales, built on first use
        self._legs = legs
        self._legs_float = evaluated(legs)
        self._base_exact = [sp.Matrix(3, 1, list(row)) for row in base]
        self._platform_exact = [sp.Matrix(3, 1, list(row)) for row in platform]
        self.base_points = np.array([[float(v) for v in row] for row in base])
        self.platform_points = np.array([[float(v) for v in row] for row in platform])
        self.m = len(self.base_points)
        points = np.vstack([self.base_points, self.platform_points])
        #: The mechanism's size (m): its farthest attachment point from the origin of
        #: its frame; length tolerances are measured against it
        self.scale = float(np.linalg.norm(points, axis=1).max()) or 1.0
        self.motion = motion
        self.planar = motion == "planar"
        self.freedoms = _FREEDOMS[motion]
        self.motion_type = _TYPES[motion]
        self._home = (
            sp.Matrix(home) if is_symbolic(home) else np.array(home, dtype=float)
        )
        self.leg_limits = None if leg_limits is None else self._limits(leg_limits)
        self.working_modes = (
            ["single"]
            if legs.modes == ("",)
            else ["".join(m) for m in itertools.product(legs.modes, repeat=self.m)]
        )
        self.default_mode = default_mode or self.working_modes[0]
        self.prismatic = isinstance(legs, (Prismatic, Linear))
        if self._pose(self._home, "home")[1]:  # a rigid pose of this motion type
            raise ValueError(f"home must be one pose (4, 4), got {describe(home)}")

    def _limits(self, leg_limits):
        limits = as_float_array(leg_limits, "leg_limits")
        if limits.shape != (self.m, 2):
            raise ValueError(
                f"leg_limits must have shape ({self.m}, 2) (a lower and an upper limit "
                f"per leg) or be None, got shape {limits.shape}"
            )
        if np.any(limits[:, 0] >= limits[:, 1]):
            raise ValueError(
                f"leg_limits must have each lower limit below its upper one, got "
                f"{limits.tolist()}"
            )
        return limits

    def __repr__(self):
        return f"ParallelManipulator({self.name!r}, {self.m} legs, {self.motion_type})"

    def home(self):
        """The home pose.

        Returns
        -------
        ndarray, shape (4, 4)

        Examples
        --------
        The Stewart-Gough platform's home is 1 m above the base, level:

        >>> from screwkit.parallel import stewart_gough
        >>> stewart_gough().home()[:3, 3]
        array([0., 0., 1.])
        """
        return np.array(self._home, dtype=float)

    def home_exact(self):
        """The home pose, exactly.

        Returns
        -------
        sympy.Matrix, shape (4, 4)

        Examples
        --------
        >>> import sympy as sp
        >>> from screwkit.parallel import stewart_gough
        >>> stewart_gough(height=sp.Rational(1, 2)).home_exact()[2, 3]
        1/2
        """
        return sp.Matrix(self._home)

    # ---- checks ---------------------------------------------------------------------

    def _pose(self, T, name="T"):
        """T checked (rigid, and of this mechanism's motion type): (float (N, 4, 4),
        batched) or (SymPy matrix, False)."""
        # a float batch takes check_poses' fast pass; anything else (SymPy stays
        # exact) the full check
        if isinstance(T, np.matrix):  # NumPy's matrix class indexes as 2-d only
            T = np.asarray(T)
        T = (
            check_poses(T, name)
            if isinstance(T, np.ndarray) and T.ndim == 3
            else check_transform(T, name)
        )
        if isinstance(T, sp.MatrixBase):
            if T.free_symbols:
                names = ", ".join(sorted(str(x) for x in T.free_symbols))
                raise TypeError(
                    f"{name} must be a pose of numbers (exact or float), got one with "
                    f"the free symbol(s) {names}: substitute values first"
                )
            self._check_motion(np.array(T.evalf(), dtype=float)[None], name)
            return T, False
        batched = T.ndim == 3
        T = T.reshape(-1, 4, 4)
        self._check_motion(T, name)
        return T, batched

    def _check_motion(self, T, name):
        R = T[:, :3, :3]
        if self.motion == "translational":
            tilt = np.max(np.abs(R - self.home()[:3, :3]), initial=0.0)
            if tilt > PARALLEL_MOTION_TOL:
                raise ValueError(
                    f"{name} must keep the platform's orientation: the {self.name} "
                    f"only translates (3T), got a rotation block that differs from the "
                    f"home one by "
                    f"{tilt:.3g}"
                )
        elif self.motion == "planar":
            off = np.max(
                np.abs(
                    np.concatenate(
                        [
                            R[:, 2, :2],
                            R[:, :2, 2],
                            T[:, 2:3, 3] / self.scale,
                            R[:, 2:3, 2] - 1,
                        ],
                        axis=1,
                    )
                ),
                initial=0.0,
            )
            if off > PARALLEL_MOTION_TOL:
                raise ValueError(
                    f"{name} must be a planar pose (a rotation about z and a "
                    f"translation in the base xy-plane) for the {self.name}, got one "
                    f"that leaves the "
                    f"plane by "
                    f"{off:.3g}"
                )

    def _mode(self, mode):
        mode = self.default_mode if mode is None else mode
        check_option(mode, "mode", self.working_modes)
        return np.array([{"+": 1, "-": -1}.get(c, 1) for c in mode.ljust(self.m, "+")])

    def _rho(self, rho):
        if is_symbolic(rho):
            raise TypeError(
                "rho must be numbers (fk is numeric), got SymPy expressions"
            )
        values = as_float_array(rho, "rho")
        if values.ndim not in (1, 2) or values.shape[-1] != self.m:
            raise ValueError(
                f"rho must have shape ({self.m},) or (N, {self.m}) for the "
                f"{self.name}, "
                f"got shape {values.shape}"
            )
        if isinstance(self._legs, Prismatic) and np.any(values <= 0):
            raise ValueError(f"rho must be leg lengths > 0 (m), got {values.min():.6g}")
        return values

    # ---- inverse kinematics ---------------------------------------------------------

    def attachments(self, T):
        """The platform's attachment points in the base frame, C_i = p + R b_i.

        Parameters
        ----------
        T : array-like, shape (4, 4) or (N, 4, 4), or a SymPy 4 x 4
            Platform pose(s).

        Returns
        -------
        ndarray, shape (m, 3) or (N, m, 3)
            C_i (m); a list of SymPy 3 x 1 matrices for an exact pose.

        Examples
        --------
        At home the Stewart-Gough platform's points lie 1 m up, on its circle of 0.5 m:

        >>> from screwkit.parallel import stewart_gough
        >>> pm = stewart_gough()
        >>> C = pm.attachments(pm.home())
        >>> C[:, 2], np.linalg.norm(C[:, :2], axis=1).round(12)
        (array([1., 1., 1., 1., 1., 1.]), array([0.5, 0.5, 0.5, 0.5, 0.5, 0.5]))
        """
        T, batched = self._pose(T)
        if isinstance(T, sp.MatrixBase):
            return [T[:3, :3] * b + T[:3, 3] for b in self._platform_exact]
        C = np.moveaxis(
            _numeric.points(T[:, :3, :3], T[:, :3, 3], self.platform_points), 0, -1
        )
        return C if batched else C[0]

    def ik(self, T, mode=None, passive=False):
        """The actuated joint values that put the platform at T.

        Parameters
        ----------
        T : array-like, shape (4, 4) or (N, 4, 4), or a SymPy 4 x 4
            Platform pose(s) (m, base frame).
        mode : str, optional
            A working mode label from ``working_modes`` (e.g. '+-+' for the 3-RRR: the
            sign of each leg's elbow); default ``default_mode``.
        passive : bool
            Also return the passive joints and the reason a pose is out of reach.

        Returns
        -------
        rho : ndarray, shape (m,) or (N, m)
            Leg lengths (m) or crank angles (rad), NaN rows where out of reach or
            outside ``leg_limits``; a list of SymPy expressions for an exact pose
            (sympy.nan where out of reach).
        ParallelIK
            Instead, with ``passive``.

        Examples
        --------
        By Pythagoras: from (0, 0) to (3, 4) is 5, from (4, 0) to (4, 4) is 4, from
        (3, 9) to (3, 5) is 4.

        >>> from screwkit.parallel import planar_3rpr
        >>> from screwkit.transforms import transl
        >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
        ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
        >>> pm.ik(pm.home())
        array([5., 4., 4.])
        """
        signs = self._mode(mode)
        passive = check_flag(passive, "passive")
        T, batched = self._pose(T)
        if isinstance(T, sp.MatrixBase):
            rho = self._legs.ik_exact(self.attachments(T), signs)
            bad = [i for i, r in enumerate(rho) if r is sp.nan]
            reason = f"leg(s) {bad} cannot reach the pose" if bad else ""
            if self.leg_limits is not None and not bad:
                values = np.array([float(r) for r in rho])
                limits = self.leg_limits
                outside = np.flatnonzero(
                    (values < limits[:, 0]) | (values > limits[:, 1])
                )
                if len(outside):
                    bad = outside.tolist()
                    reason = _outside(bad, values, limits)
            if bad:
                rho = [sp.nan] * self.m
            if not passive:
                return rho
            return ParallelIK(rho, {}, not bad, reason, mode or self.default_mode)
        rho, ok = self._solve_legs(T, signs)  # reachable and within the limits
        reachable = ok.all(axis=1)
        bad = np.flatnonzero(~reachable)
        reasons = [""] * len(rho) if passive else None
        if passive and len(bad):  # only the rows out of reach are looked at again
            values, geometric = self._solve_legs(T[bad], signs, limits=False)
            for n, value, ok_n in zip(bad, values, geometric):
                if not ok_n.all():
                    legs = np.flatnonzero(~ok_n).tolist()
                    reasons[n] = f"leg(s) {legs} cannot reach the pose"
                else:
                    legs = np.flatnonzero(~ok[n]).tolist()
                    reasons[n] = _outside(legs, value, self.leg_limits)
        rho[bad] = np.nan
        if not passive:
            return rho if batched else rho[0]
        C = _numeric.points(T[:, :3, :3], T[:, :3, 3], self.platform_points)
        joints = {
            k: np.moveaxis(v, 0, -1) if v.ndim == 3 else v
            for k, v in self._legs.passive(C, rho, signs).items()
        }
        if not batched:
            joints = {k: v[0] for k, v in joints.items()}
            return ParallelIK(
                rho[0],
                joints,
                bool(reachable[0]),
                reasons[0],
                mode or self.default_mode,
            )
        return ParallelIK(rho, joints, reachable, reasons, mode or self.default_mode)

    def ik_all(self, T):
        """The actuated joint values in every working mode.

        Parameters
        ----------
        T : array-like, shape (4, 4) or (N, 4, 4), or a SymPy 4 x 4

        Returns
        -------
        dict of str to ndarray, shape (m,) or (N, m)
            ``{label: pm.ik(T, mode=label)}`` for every label of ``working_modes``.

        Examples
        --------
        The planar 3-RRR: two elbows per leg, eight working modes.

        >>> from screwkit.parallel import planar_3rrr
        >>> pm = planar_3rrr()
        >>> modes = pm.ik_all(pm.home())
        >>> len(modes), list(modes)[:3]
        (8, ['+++', '++-', '+-+'])
        """
        return {mode: self.ik(T, mode=mode) for mode in self.working_modes}

    # ---- Jacobian and wrenches ------------------------------------------------------

    def jacobian(self, T, mode=None):
        """The Jacobian J with rho' = J V, V = [w; v] the platform's space twist.

        Row i is the actuation wrench of leg i, (f; m) swapped to [m; f], scaled so that
        its power on V is the actuator's rate: [A_i x n_i, n_i] for a leg of unit
        direction n_i.

        Parameters
        ----------
        T : array-like, shape (4, 4) or (N, 4, 4), or a SymPy 4 x 4
        mode : str, optional
            The working mode (default ``default_mode``).

        Returns
        -------
        ndarray, shape (m, 6) or (N, m, 6)
            NaN rows where the pose is out of reach (units: m or rad per unit of the
            twist's rad/s and m/s); a SymPy matrix for an exact pose.

        Examples
        --------
        Row i is [C_i x n_i, n_i], n_i the unit leg direction: for the leg from (0, 0)
        to (3, 4), n = (0.6, 0.8) and C x n = 0; for (4, 0) to (4, 4), n = y and
        C x n = 4 z; for (3, 9) to (3, 5), n = -y and C x n = -3 z.

        >>> from screwkit.parallel import planar_3rpr
        >>> from screwkit.transforms import transl
        >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
        ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
        >>> pm.jacobian(pm.home()).round(12) + 0.0
        array([[ 0. ,  0. ,  0. ,  0.6,  0.8,  0. ],
               [ 0. ,  0. ,  4. ,  0. ,  1. ,  0. ],
               [ 0. ,  0. , -3. ,  0. , -1. ,  0. ]])
        """
        signs = self._mode(mode)
        T, batched = self._pose(T)
        if isinstance(T, sp.MatrixBase):
            C = self.attachments(T)
            rows = []
            for c, (g, dr) in zip(C, self._legs.rows_exact(C, signs)):
                rows.append([sp.simplify(-e / dr) for e in list(c.cross(g)) + list(g)])
            return sp.Matrix(rows)
        J = np.empty((6, len(T), self.m))  # component first, returned as (N, m, 6)
        for start in range(0, len(T), _BLOCK):
            part = T[start : start + _BLOCK]
            C = _numeric.points(part[:, :3, :3], part[:, :3, 3], self.platform_points)
            rho, ok = self._legs_ok(C, signs)
            g = self._legs.rate_rows(C, rho)  # rho' = g . C' = (C x g) . w + g . v
            out, term = J[:, start : start + _BLOCK], np.empty(rho.shape)
            for k, (i, j) in enumerate(((1, 2), (2, 0), (0, 1))):  # C x g, in place
                np.multiply(C[i], g[j], out=out[k])
                out[k] -= np.multiply(C[j], g[i], out=term)
            out[3:] = g
            out[:, ~ok.all(axis=1)] = np.nan
        J = np.moveaxis(J, 0, -1)
        return J if batched else np.ascontiguousarray(J[0])

    def _legs_ok(self, C, signs, limits=True):
        """rho and ok (reachable, within the limits) for the points C (3, N, m)."""
        rho, ok, _ = self._legs.ik(C, signs)
        if limits and self.leg_limits is not None:
            ok &= rho >= self.leg_limits[:, 0]
            ok &= rho <= self.leg_limits[:, 1]
        return rho, ok

    def _solve_legs(self, T, signs, limits=True):
        """rho, ok (N, m) for checked float poses T (N, 4, 4), block by block."""
        rho, ok = np.empty((len(T), self.m)), np.empty((len(T), self.m), bool)
        for start in range(0, len(T), _BLOCK):
            part = T[start : start + _BLOCK]
            C = _numeric.points(part[:, :3, :3], part[:, :3, 3], self.platform_points)
            block = slice(start, start + _BLOCK)
            rho[block], ok[block] = self._legs_ok(C, signs, limits)
        return rho, ok

    def limbs(self, T=None, mode=None):
        """The limbs' joint screws at the pose T, in the mobility paper's format.

        Parameters
        ----------
        T : array-like, shape (4, 4), optional
            One pose (default: home, exactly); exact input gives exact screws.
        mode : str, optional
            The working mode (default ``default_mode``).

        Returns
        -------
        limbs : list of list of (s, r, h)
            Per limb, its joints' axis direction s (3,), point r (3,) in m and pitch h
            (0 or sympy.oo): ``sk.mobility(limbs)`` analyses the mechanism at T.
        actuated : list of int
            The actuated joint's index in each limb.

        Examples
        --------
        Each R-P-R limb: pitches 0, oo, 0, the slide (index 1) actuated.

        >>> from screwkit.parallel import planar_3rpr
        >>> from screwkit.transforms import transl
        >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
        ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
        >>> limbs, actuated = pm.limbs()
        >>> [h for _, _, h in limbs[0]], actuated
        ([0, oo, 0], [1, 1, 1])
        """
        T = self.home_exact() if T is None else T
        signs = self._mode(mode)
        C, legs = self._exact_attachments(T)
        return legs.limbs(C, signs)

    def _exact_attachments(self, T):
        """C_i as SymPy 3-vectors (exact, or Floats for a float pose) and the matching
        legs."""
        T, batched = self._pose(T)
        if isinstance(T, sp.MatrixBase):
            return self.attachments(T), self._legs
        if batched:
            raise ValueError(f"T must be one pose (4, 4) here, got {T.shape[0]} poses")
        C = T[0, :3, :3] @ self.platform_points.T + T[0, :3, 3:]
        return [
            sp.Matrix(3, 1, [sp.Float(v) for v in col]) for col in C.T
        ], self._legs_float

    def wrenches(self, T, mode=None):
        """The actuation and constraint wrenches at T (Joshi & Tsai's 6 x 6 form).

        The actuation wrenches: one per leg, a line along the leg (or the distal link)
        through the platform point. The constraint wrenches: every wrench reciprocal to
        all joint twists of a limb, over the limbs. Together they span the platform's
        wrench space except at a direct singularity.

        Parameters
        ----------
        T : array-like, shape (4, 4), or a SymPy 4 x 4
            One pose; exact input gives exact wrenches.
        mode : str, optional
            The working mode (default ``default_mode``).

        Returns
        -------
        actuation : ScrewSystem
            m Wrenches (unit lines for a float pose).
        constraint : ScrewSystem
            The limbs' constraint Wrenches.

        Examples
        --------
        A U-P-S leg has six freedoms, so it constrains nothing; its six actuation
        lines span every wrench at a regular pose:

        >>> from screwkit.parallel import stewart_gough
        >>> pm = stewart_gough()
        >>> actuation, constraint = pm.wrenches(pm.home())
        >>> actuation.rank, constraint.rank
        (6, 0)
        """
        limbs, _ = self.limbs(T, mode)
        C, legs = self._exact_attachments(T)
        signs = self._mode(mode)
        actuation = []
        for c, (g, _) in zip(C, legs.rows_exact(C, signs)):
            if not is_symbolic(T):
                g = g / sp.sqrt(g.dot(g))  # floats: the unit line
            actuation.append(Wrench(sp.Matrix(list(g) + list(c.cross(g)))))
        constraint = []
        for limb in limbs:
            constraint += ScrewSystem(limb).reciprocal().screws
        return ScrewSystem(actuation, kind=Wrench), ScrewSystem(constraint, kind=Wrench)

    def singularities(self, T, mode=None):
        """The singularity types present at T.

        'inverse' (type I, Gosselin & Angeles): a limb's joint twists lose rank (the
        limb is at its boundary and an actuator can move with the platform held);
        'direct' (type II): the actuation and constraint wrenches together span less
        than the six wrenches (the platform gains a freedom with the actuators locked);
        'constraint': the constraint wrenches lose rank (the mechanism's mobility
        changes; Zlatanov et al. 1995). Exact ranks for exact input, SVD ranks (the
        relative tolerance of :class:`~screwkit.ScrewSystem`) for floats, computed
        with every length divided by the mechanism's :attr:`scale` so that the same
        pose in millimetres gets the same answer; a float pose on a limb's boundary
        (a leg stretched straight, to round-off) is on it.

        Parameters
        ----------
        T : array-like, shape (4, 4), or a SymPy 4 x 4
            One pose.
        mode : str, optional
            The working mode (default ``default_mode``).

        Returns
        -------
        set of str
            A subset of {'inverse', 'direct', 'constraint'}; empty at a regular pose.

        Examples
        --------
        The 3-RPR's legs at home are not concurrent (two are parallel, the third is
        not): a regular pose.

        >>> from screwkit.parallel import planar_3rpr
        >>> from screwkit.transforms import transl
        >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
        ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
        >>> pm.singularities(pm.home())
        set()
        """
        if is_symbolic(T):
            return self._singularities(T, mode)
        T, batched = self._pose(T)
        if batched:
            raise ValueError(f"T must be one pose (4, 4) here, got {T.shape[0]} poses")
        unit = self._unit()  # lengths in scales: the float ranks are unit-free
        T_unit = T[0].copy()
        T_unit[:3, 3] /= self.scale
        return unit._singularities(T_unit, mode)

    def _unit(self):
        """This mechanism with every length divided by its scale (floats), cached."""
        if self._unit_model is None:
            k = 1.0 / self.scale
            home = self.home()
            home[:3, 3] *= k
            self._unit_model = ParallelManipulator(
                self.name,
                self._legs.scaled(k),
                k * self.base_points,
                k * self.platform_points,
                self.motion,
                home,
                None,
                self.default_mode,
            )
        return self._unit_model

    def _singularities(self, T, mode):
        limbs, _ = self.limbs(T, mode)
        found = set()
        if any(ScrewSystem(limb).rank < len(limb) for limb in limbs):
            found.add("inverse")
        actuation, constraint = self.wrenches(T, mode)
        if constraint.rank < 6 - len(self.freedoms):
            found.add("constraint")
        if actuation.union(constraint).rank < 6:
            found.add("direct")
        return found

    # ---- forward kinematics ---------------------------------------------------------

    def fk(self, rho, guess=None, tol=None, max_iterations=50):
        """The pose with actuated values rho, by Newton-Raphson on the loop closure.

        Parameters
        ----------
        rho : array-like, shape (m,) or (N, m)
            Actuated joint values (m or rad).
        guess : array-like, shape (4, 4) or (N, 4, 4), optional
            Starting pose(s) (default: home); the assembly mode found is the one
            Newton reaches from it.
        tol : float, optional
            Residual (m, > 0) below which a pose is accepted; default
            ``PARALLEL_FK_TOL`` times ``scale``.
        max_iterations : int
            At least 1.

        Returns
        -------
        ParallelFK
            ``T`` (4, 4) or (N, 4, 4), NaN where not converged, with ``success``,
            ``iterations`` and ``error``.

        Examples
        --------
        From a guess 0.1 m off, Newton finds the pose whose legs are 5, 4 and 4 m:

        >>> from screwkit.parallel import planar_3rpr
        >>> from screwkit.transforms import transl
        >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
        ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
        >>> result = pm.fk([5.0, 4.0, 4.0], guess=transl(3.1, 3.9, 0))
        >>> result.T[:3, 3].round(6) + 0.0, result.success
        (array([3., 4., 0.]), True)
        """
        values = self._rho(rho)
        batched = values.ndim == 2
        values = values.reshape(-1, self.m)
        guess = self.home() if guess is None else guess
        T0, _ = self._pose(guess, "guess")
        if len(T0) not in (1, len(values)):
            raise ValueError(
                f"guess must be one pose or {len(values)} poses (one per row of "
                f"rho), got {len(T0)}"
            )
        tol = (
            PARALLEL_FK_TOL * self.scale if tol is None else check_positive(tol, "tol")
        )
        max_iterations = check_integer(max_iterations, "max_iterations", minimum=1)
        T, success, iterations, error = self._newton(values, T0, tol, max_iterations)
        if not batched:
            return ParallelFK(
                T[0], bool(success[0]), int(iterations[0]), float(error[0])
            )
        return ParallelFK(T, success, iterations, error)

    def _newton(self, rho, T0, tol, max_iterations):
        return _numeric.newton(
            self._legs,
            self.platform_points,
            self.freedoms,
            rho,
            T0,
            tol,
            max_iterations,
            self.scale,
        )

    def fk_all(self, rho, starts=None, seed=0, proof=False):
        """Every real assembly mode with actuated values rho, and how far to trust it.

        The delta solves three spheres' intersection and the Tripteron a linear
        system (closed forms: ``complete`` is True). The planar 3-RRR is the 3-RPR whose
        base points are its elbows and whose legs are its distal links: that 3-RPR's
        sextic gives its modes, up to six. The 3-RPR solves its univariate
        sextic (:func:`~screwkit.parallel.rpr_sextic`; Gosselin, Sefrioui & Richard
        1992), up to six modes, its roots found in floating point. Other mechanisms run
        a multi-start Newton search (:func:`screwkit.parallel.search.multistart`,
        ``starts`` random poses around the home pose plus their mirror images through
        the base plane, seeded): every pose it returns satisfies the legs, but it may
        miss a mode no start leads to; the general Stewart-Gough platform has up to 40
        (Dietmaier 1998 found 40 real ones). Where the closure's Jacobian loses rank at
        a solution and the solutions continue along its kernel, the result says so
        (``continuum``): a self-motion or a degenerate geometry.

        With ``proof=True`` the Stewart-Gough platform (six prismatic legs, spatial),
        the 3-RPR and the 3-RRR are solved exactly instead, with certified real roots
        (:func:`~screwkit.parallel.stewart_fk_proven`, which needs the optional
        package of ``screwkit[proof]``, and :func:`~screwkit.parallel.rpr_fk_proven`)
        for the floats given, exactly (each a binary rational): ``complete`` True
        proves that the list holds every real assembly mode of those numbers (each
        pose rounded to floats). A continuum of solutions that the exact solver
        proves (positive-dimensional: a self-motion, an architecture singularity) is
        reported with ``complete`` False, its reason, and what the usual search finds
        (``continuum`` True and a pose on it when the continuum has real poses).

        Parameters
        ----------
        rho : array-like, shape (m,)
            One input (m or rad).
        starts : int, optional
            Random starting poses of the search (default 400, at most
            ``MAX_FK_STARTS``).
        seed : int
            The search's seed.
        proof : bool
            Ask for a proof of completeness (default False: the fast path). A
            mechanism without an exact solver answers by its usual method, with
            ``complete`` False and the reason.

        Returns
        -------
        AssemblyModes
            A list of the assembly modes found (poses (4, 4)), with ``complete`` (True
            only when proven to hold every mode), ``method``, ``reason`` (why not
            complete, or what the continuum is) and ``continuum``.

        Raises
        ------
        ValueError
            If ``starts`` exceeds ``MAX_FK_STARTS`` (memory), or ``rho`` is not one
            input.

        Examples
        --------
        The default 3-RPR at the leg lengths ``RPR_SIX_MODES_RHO`` has six real
        assembly modes, the most a 3-RPR can have; the sextic's roots are floats, so
        the list is not proven complete.

        >>> from screwkit.parallel import RPR_SIX_MODES_RHO, planar_3rpr
        >>> modes = planar_3rpr().fk_all(RPR_SIX_MODES_RHO)
        >>> len(modes), modes.complete, modes.method
        (6, False, 'sextic (floating-point roots)')
        """
        values = self._rho(rho)
        if values.ndim != 1:
            raise ValueError(
                f"rho must be one input ({self.m},) for fk_all, "
                f"got shape {values.shape}"
            )
        starts = 400 if starts is None else check_integer(starts, "starts", minimum=1)
        if starts > MAX_FK_STARTS:
            raise ValueError(
                f"starts must be at most {MAX_FK_STARTS} (Newton's arrays for "
                f"{starts} starts would not fit in memory), got {starts}"
            )
        seed = check_integer(seed, "seed", minimum=0)
        proof = check_flag(proof, "proof")
        if self.planar and isinstance(self._legs, Revolute):
            return self._rrr_modes(values, proof)
        if proof and isinstance(self._legs, Prismatic):
            proven = self._fk_proven(values, starts, seed)
            if proven is not None:
                return proven
        closed = None
        three = self.motion == "translational" and self.m == 3
        if three and isinstance(self._legs, Revolute):
            closed, method = _search.spheres, "closed form (three spheres)"
        elif three and isinstance(self._legs, Linear):
            closed, method = _search.rails, "closed form (linear)"
        if closed is not None:
            poses, continuum = closed(self, values)
            return AssemblyModes(
                _search.sort_modes(self, poses),
                complete=continuum is None,
                method=method,
                reason=continuum,
                continuum=continuum is not None,
            )
        if isinstance(self._legs, Prismatic) and self.planar:
            poses, _, stuck = _search._sextic_modes(self, values)
            method = "sextic (floating-point roots)"
            reason = (
                "the sextic's real roots are found in floating point (numpy's "
                "companion matrix), not isolated with certainty"
            )
        else:
            poses = _search.multistart(self, values, starts, seed)
            method = "multistart search"
            reason = (
                f"a search from {starts} random starts (seed {seed}): it may miss "
                f"modes no start leads to"
            )
            stuck = (
                _search.random_starts(self, values, _CONTINUUM_STARTS, seed)
                if not poses
                else ()
            )
        isolated, on, continuum = _search.continuum(self, values, poses, stuck)
        poses = _search.sort_modes(self, isolated)
        if on is not None:  # one pose of the continuum, after the isolated modes
            poses, reason = poses + [on], continuum
        return AssemblyModes(
            poses,
            complete=False,
            method=method,
            reason=reason,
            continuum=on is not None,
        )

    def _rrr_modes(self, theta, proof):
        """A planar 3-RRR's modes: with the cranks at theta, each distal link turns
        about its elbow, so the platform moves as a 3-RPR's whose base points are the
        elbows and whose legs are the links' length: that 3-RPR's sextic."""
        elbows = self._legs._crank(theta)[0][:, 0, :].T
        links = np.full(3, self._legs.l2)
        if proof:
            poses, complete, reason = _proven.rpr_fk_proven(
                elbows[:, :2], self.platform_points[:, :2], links
            )
            method = "the elbows' 3-RPR sextic, real roots isolated exactly (SymPy)"
            return AssemblyModes(poses, complete=complete, method=method, reason=reason)
        equivalent = ParallelManipulator(
            name="3-RPR of the elbows",
            legs=Prismatic(elbows.tolist(), planar=True),
            base=elbows.tolist(),
            platform=self.platform_points.tolist(),
            motion="planar",
            home=np.eye(4),
        )
        modes = equivalent.fk_all(links)
        return AssemblyModes(
            modes,
            complete=False,
            method="the elbows' 3-RPR sextic (floating-point roots)",
            reason=modes.reason,
            continuum=modes.continuum,
        )

    def _fk_proven(self, values, starts, seed):
        """fk_all by an exact solver with certified roots, or None if there is none."""
        if self.planar:
            method = "sextic, real roots isolated exactly (SymPy)"
            solved = _proven.rpr_fk_proven(
                self.base_points[:, :2], self.platform_points[:, :2], values
            )
        elif self.m == 6 and self.motion == "spatial":
            method = "Study parameters, Groebner basis and certified roots (msolve)"
            solved = _proven.stewart_fk_proven(
                self.base_points, self.platform_points, values
            )
        else:
            return None
        poses, complete, reason = solved
        if not complete and reason.startswith(_proven.POSITIVE_DIMENSIONAL):
            # a continuum of complex solutions, proven: the search says whether it
            # has real poses (and lists one of them, and the isolated modes it finds)
            found = self.fk_all(values, starts=starts, seed=seed)
            return AssemblyModes(
                found,
                complete=False,
                method=f"{method}, then {found.method}",
                reason=f"{reason}; {found.method}: {found.reason}",
                continuum=found.continuum,
            )
        return AssemblyModes(
            _search.sort_modes(self, poses),
            complete=complete,
            method=method,
            reason=reason,
            continuum=False,
        )

    # ---- workspace ------------------------------------------------------------------

    def workspace(self, x, y, z=0.0, rotation=None, mode=None, chunk=20_000):
        """The constant-orientation workspace on a grid.

        Parameters
        ----------
        x : array-like, shape (nx,)
        y : array-like, shape (ny,)
            The grid (m, base frame).
        z : float
            The platform's height (m).
        rotation : array-like, shape (3, 3), optional
            The platform's rotation (default: the home one).
        mode : str, optional
            The working mode (default ``default_mode``).
        chunk : int
            Poses computed at once (memory).

        Returns
        -------
        Workspace
            The reachable points within ``leg_limits`` and det of J's free columns
            (its zero level is the direct-singularity locus).

        Examples
        --------
        Without leg limits a 3-RPR reaches every point of a small grid:

        >>> from screwkit.parallel import planar_3rpr
        >>> from screwkit.transforms import transl
        >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
        ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
        >>> ws = pm.workspace(np.linspace(2.5, 3.5, 3), np.linspace(3.5, 4.5, 3))
        >>> ws.inside.shape, bool(ws.inside.all())
        ((3, 3), True)
        """
        x, y = as_float_array(x, "x").ravel(), as_float_array(y, "y").ravel()
        z = float(as_float_array(z, "z"))
        rotation = (
            self.home()[:3, :3]
            if rotation is None
            else check_rotation(as_float_array(rotation, "rotation"), "rotation")
        )
        chunk = check_integer(chunk, "chunk", minimum=1)
        if x.size * y.size > MAX_WORKSPACE_POINTS:
            raise ValueError(
                f"x and y make a grid of {x.size * y.size} points, more than "
                f"{MAX_WORKSPACE_POINTS} (the memory bound of sk.workspace): sweep a "
                f"coarser grid or a smaller region"
            )
        X, Y = np.meshgrid(x, y, indexing="xy")
        points = np.stack([X.ravel(), Y.ravel(), np.full(X.size, z)], axis=1)
        rho = np.full((len(points), self.m), np.nan)
        det = np.full(len(points), np.nan)
        for start in range(0, len(points), chunk):
            part = points[start : start + chunk]
            T = np.zeros((len(part), 4, 4))
            T[:, :3, :3], T[:, :3, 3], T[:, 3, 3] = rotation, part, 1.0
            r = self.ik(T, mode=mode)
            rho[start : start + chunk] = r
            J = self.jacobian(T, mode=mode)[:, :, self.freedoms]
            det[start : start + chunk] = np.linalg.det(np.nan_to_num(J))
        inside = np.isfinite(rho).all(axis=1)
        det[~inside] = np.nan
        shape = X.shape
        return Workspace(
            x,
            y,
            np.array(z),
            inside.reshape(shape),
            det.reshape(shape),
            rho.reshape(shape + (self.m,)),
            rotation,
        )


def _outside(legs, rho, limits):
    """Why the legs ``legs`` are out of reach, with the first one's value and limits."""
    i = legs[0]
    return (
        f"leg(s) {legs} outside their limits "
        f"(leg {i}: {rho[i]:.4g} not in [{limits[i, 0]:g}, {limits[i, 1]:g}])"
    )
