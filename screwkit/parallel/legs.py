"""The legs of the catalogue's parallel manipulators: inverse kinematics, loop closure
and joint screws, for all m legs at once (numeric, batched) or one pose exactly (SymPy).

Every leg joins a base point A_i to a platform point C_i = p + R b_i. Three kinds cover
the catalogue:

- :class:`Prismatic` (UPS, RPR): the actuated joint is the leg's length, rho = |C - A|;
- :class:`Revolute` (RRR, RUU): an actuated crank of length l1 about the axis u through
  A turns by theta; its tip B(theta) = A + l1 (cos theta e0 + sin theta e1) is joined to
  C by a link of length l2, so |C - B(theta)| = l2 (two working modes, the sign of the
  elbow);
- :class:`Linear` (PRRR): a carriage slides along e from A0; the planar RRR chain with
  its axes along e keeps C in the plane e . (C - A0) = d.

Numeric points are laid out component first, (3, N, m): C[k] is the k-th coordinate of
every leg's point in every pose (fast elementwise NumPy). Each kind writes its loop
closure as r(C, rho) = 0 with the gradient g = dr/dC and the derivative dr/drho; with
C' = v + w x C for the platform's space twist V = [w; v]:
rho' = -[C x g, g] V / (dr/drho),
the row of the Jacobian (the actuation wrench, swapped).
"""

import numpy as np
import sympy as sp

from ..tolerances import PARALLEL_AXIS_TOL, PARALLEL_REACH_TOL
from ..transforms import _cross

__all__ = ["Legs", "Prismatic", "Revolute", "Linear", "evaluated"]


def _dot(a, b):
    """Dot products of point arrays laid out component first: (3, ...) -> (...)."""
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def _columns(points):
    """(m, 3) points as a (3, 1, m) array (numeric layers work component first)."""
    return np.asarray(points, dtype=float).T[:, None, :].copy()


def _expand(m):
    return sp.Matrix(m).applyfunc(sp.expand)


def _floats(value):
    """Nested lists/tuples of numbers with every number as a SymPy Float."""
    if isinstance(value, (list, tuple)):
        return [_floats(v) for v in value]
    if isinstance(value, sp.MatrixBase):
        return _floats(value.tolist())
    return sp.Float(float(value))


def _across(n):
    """The universal joint's first axis for a leg along n: the base x axis, unless the
    leg runs closer to x than to y or z (the second axis n x x would then be short
    and its rank a matter of round-off); then the axis among y, z the leg is farthest
    from. Any axis not along n gives the leg its six freedoms."""
    size = [abs(float(v)) for v in n]
    if size[0] < max(size[1], size[2]):
        return sp.Matrix([1, 0, 0])
    return sp.Matrix([0, 1, 0]) if size[1] <= size[2] else sp.Matrix([0, 0, 1])


def _is_float(expression):
    """Whether a SymPy number came from floats (a float pose's layer), where a
    comparison with 0 must allow round-off."""
    return bool(expression.atoms(sp.Float))


def evaluated(legs):
    """A copy of ``legs`` whose exact layer holds Floats (for a float pose's screws).

    Parameters
    ----------
    legs : Legs

    Returns
    -------
    Legs
        The same legs, their exact geometry as SymPy Floats.

    Examples
    --------
    >>> legs = Prismatic([[0, 0, 0], [sp.Rational(1, 2), 0, 0]], planar=True)
    >>> legs.A_exact[1][0], evaluated(legs).A_exact[1][0]
    (1/2, 0.500000000000000)
    """
    copy = object.__new__(type(legs))
    copy.__dict__.update(legs.__dict__)
    if hasattr(legs, "A_exact"):
        copy.A_exact = _floats(legs.A_exact)
    if hasattr(legs, "exact"):
        copy.exact = tuple(_floats(v) for v in legs.exact)
    return copy


class Legs:
    """The m legs of a parallel manipulator: what every kind of leg computes.

    Numeric methods take the platform points C, shape (3, N, m) (m, base frame,
    component first) and return arrays of shape (N, m); exact methods take one pose's
    points as a list of m SymPy 3 x 1 matrices. ``signs`` (m,) holds +1 or -1 per leg,
    the working mode (the sign of each elbow; ignored by legs with one mode).

    Examples
    --------
    Two R-P-R legs from A = (0, 0, 0) and (2, 0, 0) to C = (3, 4, 0) and (2, 1, 0):
    lengths 5 and 1, unit directions (0.6, 0.8, 0) and (0, 1, 0).

    >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
    >>> C = np.array([[3.0, 4.0, 0.0], [2.0, 1.0, 0.0]]).T[:, None, :]  # (3, 1, 2)
    >>> legs.ik(C, np.ones(2))[0]
    array([[5., 1.]])
    """

    #: Each leg's working modes: ('',) for one, ('+', '-') for an elbow.
    modes = ("",)

    def scaled(self, factor):
        """The same legs with every length times ``factor``, as floats.

        Parameters
        ----------
        factor : float

        Returns
        -------
        Legs

        Examples
        --------
        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> legs.scaled(2.0).A[:, 0, :].T.tolist()  # the base points, doubled
        [[0.0, 0.0, 0.0], [4.0, 0.0, 0.0]]
        """
        raise NotImplementedError

    def ik(self, C, signs):
        """The actuated joint values that reach the points C.

        Parameters
        ----------
        C : ndarray, shape (3, N, m)
        signs : ndarray, shape (m,)

        Returns
        -------
        rho : ndarray, shape (N, m)
            Leg lengths or carriage positions (m), or crank angles (rad); NaN where out
            of reach.
        ok : ndarray of bool, shape (N, m)
            Where the leg reaches.
        None
            (room for the passive joints).

        Examples
        --------
        The legs of the class example (lengths 5 and 1):

        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> C = np.array([[3.0, 4.0, 0.0], [2.0, 1.0, 0.0]]).T[:, None, :]  # (3, 1, 2)
        >>> rho, ok, _ = legs.ik(C, np.ones(2))
        >>> rho, ok
        (array([[5., 1.]]), array([[ True,  True]]))
        """
        raise NotImplementedError

    def closure(self, C, rho):
        """The loop closure r(C, rho) = 0 of every leg, and its derivatives.

        Parameters
        ----------
        C, rho : ndarray, shapes (3, N, m) and (N, m)

        Returns
        -------
        r : ndarray, shape (N, m)
            The residual (m).
        g : ndarray, shape (3, N, m)
            dr/dC (no unit).
        dr : ndarray, shape (N, m), or float
            dr/drho (no unit, or m per rad).

        Examples
        --------
        The legs of the class example (lengths 5 and 1):

        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> C = np.array([[3.0, 4.0, 0.0], [2.0, 1.0, 0.0]]).T[:, None, :]  # (3, 1, 2)
        >>> r, g, dr = legs.closure(C, np.array([[5.0, 1.0]]))
        >>> r.tolist(), g[:, 0, :].T.round(12).tolist(), dr
        ([[0.0, 0.0]], [[0.6, 0.8, 0.0], [0.0, 1.0, 0.0]], -1.0)
        """
        raise NotImplementedError

    def rate_rows(self, C, rho):
        """-g / (dr/drho): the actuators' rates are rho' = rate_rows . C'.

        For prismatic legs, the unit leg directions; with C' = v + w x C they make the
        Jacobian's rows [C x g, g].

        Parameters
        ----------
        C, rho : as for :meth:`closure`

        Returns
        -------
        ndarray, shape (3, N, m)
            No unit for a length rho, rad per m for a crank angle.

        Examples
        --------
        The legs of the class example (lengths 5 and 1):

        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> C = np.array([[3.0, 4.0, 0.0], [2.0, 1.0, 0.0]]).T[:, None, :]  # (3, 1, 2)
        >>> legs.rate_rows(C, np.array([[5.0, 1.0]]))[:, 0, :].T.round(12).tolist()
        [[0.6, 0.8, 0.0], [0.0, 1.0, 0.0]]
        """
        raise NotImplementedError

    def passive(self, C, rho, signs):
        """The passive joints at the points C with actuated values rho.

        Parameters
        ----------
        C, rho, signs : ndarray, shapes (3, N, m), (N, m) and (m,)

        Returns
        -------
        dict of str to ndarray
            Joint angles (rad), shape (N, m), or elbow points (m), shape (3, N, m).

        Examples
        --------
        The legs of the class example (lengths 5 and 1):

        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> C = np.array([[3.0, 4.0, 0.0], [2.0, 1.0, 0.0]]).T[:, None, :]  # (3, 1, 2)
        >>> phi = legs.passive(C, np.array([[5.0, 1.0]]), np.ones(2))["phi"]
        >>> phi.round(4)  # atan2(0.8, 0.6) and 90 deg
        array([[0.9273, 1.5708]])
        """
        raise NotImplementedError

    def ik_exact(self, C, signs):
        """The actuated joint values that reach one pose's points, exactly.

        Parameters
        ----------
        C, signs : m SymPy 3 x 1 matrices, and m signs (+1 or -1)

        Returns
        -------
        list of SymPy expressions
            One per leg (m or rad); sympy.nan where out of reach.

        Examples
        --------
        The legs of the class example, exactly:

        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> C = [sp.Matrix([3, 4, 0]), sp.Matrix([2, 1, 0])]
        >>> legs.ik_exact(C, [1, 1])
        [5, 1]
        """
        raise NotImplementedError

    def rows_exact(self, C, signs):
        """Each leg's closure gradient g and dr/drho, exactly: the Jacobian's row is
        -[C x g, g] / (dr/drho).

        Parameters
        ----------
        C, signs : as for :meth:`ik_exact`

        Returns
        -------
        list of (sympy.Matrix (3, 1), SymPy expression)

        Examples
        --------
        The legs of the class example, exactly:

        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> C = [sp.Matrix([3, 4, 0]), sp.Matrix([2, 1, 0])]
        >>> [(list(g), dr) for g, dr in legs.rows_exact(C, [1, 1])]  # g = C - A
        [([3, 4, 0], -5), ([0, 1, 0], -1)]
        """
        raise NotImplementedError

    def limbs(self, C, signs):
        """The joint screws of every leg at one pose, in the mobility paper's format.

        ``sk.mobility(limbs)`` analyses the mechanism at that pose.

        Parameters
        ----------
        C, signs : as for :meth:`ik_exact`

        Returns
        -------
        limbs : list of list of (s, r, h)
            Per leg, its joints' axis direction s (3,), point r (3,) in m and pitch h.
        actuated : list of int
            The actuated joint's index in each leg.

        Examples
        --------
        R-P-R: a revolute about z at A, the slide along C - A, a revolute at C.

        >>> legs = Prismatic([[0, 0, 0], [2, 0, 0]], planar=True)
        >>> C = [sp.Matrix([3, 4, 0]), sp.Matrix([2, 1, 0])]
        >>> limbs, actuated = legs.limbs(C, [1, 1])
        >>> [h for _, _, h in limbs[0]], list(limbs[0][1][0]), actuated
        ([0, oo, 0], [3, 4, 0], [1, 1])
        """
        raise NotImplementedError


class Prismatic(Legs):
    """Legs whose actuated joint is their length (U-P-S or R-P-R).

    Parameters
    ----------
    base : list of 3 numbers, length m
        The base points A_i (m); exact entries stay exact.
    planar : bool
        R-P-R legs in the xy-plane (else U-P-S).

    Examples
    --------
    A U-P-S leg from the origin to (1, 2, 2) is 3 m long:

    >>> leg = Prismatic([[0, 0, 0]], planar=False)
    >>> leg.ik(np.array([1.0, 2.0, 2.0])[:, None, None], np.ones(1))[0]
    array([[3.]])
    """

    modes = ("",)

    def __init__(self, base, planar):
        self.A = _columns(base)
        self.A_exact = base
        self.planar = planar

    def scaled(self, factor):
        return Prismatic((factor * self.A[:, 0, :].T).tolist(), self.planar)

    def ik(self, C, signs):
        rho = np.subtract(C[0], self.A[0])  # |C - A|, in place: no temporaries
        rho *= rho
        term = np.empty_like(rho)
        for k in (1, 2):
            np.subtract(C[k], self.A[k], out=term)
            term *= term
            rho += term
        np.sqrt(rho, out=rho)
        return rho, rho > 0, None

    def closure(self, C, rho):
        d = C - self.A
        length = np.sqrt(_dot(d, d))
        with np.errstate(divide="ignore", invalid="ignore"):
            g = d * (1.0 / length)
        return length - rho, g, -1.0

    def rate_rows(self, C, rho):
        g = np.subtract(C, self.A)  # the unit leg direction
        with np.errstate(divide="ignore", invalid="ignore"):
            g *= 1.0 / rho
        return g

    def passive(self, C, rho, signs):
        n = (C - self.A) / rho
        if self.planar:
            return {"phi": np.arctan2(n[1], n[0])}
        return {"u1": np.arctan2(-n[1], n[2]), "u2": np.arcsin(np.clip(n[0], -1, 1))}

    # exact, one pose: C is a list of SymPy 3x1 matrices
    def ik_exact(self, C, signs):
        return [sp.sqrt(sp.expand((c - a).dot(c - a))) for c, a in zip(C, self._A())]

    def rows_exact(self, C, signs):
        # g = C - A unnormalised (no square root in the wrench), dr/drho scaled alike
        rho = self.ik_exact(C, signs)
        return [(_expand(c - a), -r) for c, a, r in zip(C, self._A(), rho)]

    def _A(self):
        return [sp.Matrix(a) for a in self.A_exact]

    def limbs(self, C, signs):
        limbs, actuated = [], []
        for c, a in zip(C, self._A()):
            n = c - a
            if self.planar:
                z = sp.Matrix([0, 0, 1])
                limbs.append([(z, a, 0), (n, a, sp.oo), (z, c, 0)])
                actuated.append(1)
            else:
                x = _across(n)
                second = n.cross(x)
                limbs.append(
                    [(x, a, 0), (second, a, 0), (n, a, sp.oo)]
                    + [(e, c, 0) for e in sp.eye(3).columnspace()]
                )
                actuated.append(2)
        return limbs, actuated


class Revolute(Legs):
    """Legs with an actuated crank (R-R-R in the plane, R-U-U of the delta).

    Parameters
    ----------
    base : list of 3 numbers, length m
        The cranks' pivots A_i (m).
    axis : list of 3 numbers, length m
        The cranks' unit axes u_i.
    e0 : list of 3 numbers, length m
        The unit directions normal to u_i where each crank angle is zero.
    l1, l2 : number
        Lengths of the cranks and of the distal links (m).
    spatial : bool
        R-U-U legs (the delta) rather than planar R-R-R.

    Notes
    -----
    The actuated values ``rho`` of the :class:`Legs` methods are the crank angles
    theta (rad).

    Examples
    --------
    A planar R-R-R leg, unit crank and link, pivot at the origin, reaching (1, 1):
    the crank's tip B must be 1 from the origin and from (1, 1), so B = (0, 1)
    (theta = 90 deg) or B = (1, 0) (theta = 0), one for each elbow.

    >>> leg = Revolute([[0, 0, 0]], [[0, 0, 1]], [[1, 0, 0]], 1.0, 1.0, spatial=False)
    >>> C = np.array([1.0, 1.0, 0.0])[:, None, None]
    >>> [float(leg.ik(C, np.array([sign]))[0][0, 0].round(6)) + 0.0 for sign in (1, -1)]
    [1.570796, 0.0]
    """

    modes = ("+", "-")

    def __init__(self, base, axis, e0, l1, l2, spatial):
        self.A, self.u, self.e0 = (_columns(v) for v in (base, axis, e0))
        self.e1 = _cross(self.u, self.e0)
        self.l1, self.l2 = float(l1), float(l2)
        self.exact = (base, axis, e0, l1, l2)
        self.spatial = spatial
        self._axis_tol = PARALLEL_AXIS_TOL * (self.l1 + self.l2)

    def scaled(self, factor):
        rows = [v[:, 0, :].T.tolist() for v in (self.A, self.u, self.e0)]
        rows[0] = (factor * self.A[:, 0, :].T).tolist()
        return Revolute(*rows, factor * self.l1, factor * self.l2, self.spatial)

    def _crank(self, theta):
        c, s = np.cos(theta), np.sin(theta)
        return self.A + self.l1 * (c * self.e0 + s * self.e1), self.l1 * (
            -s * self.e0 + c * self.e1
        )

    def ik(self, C, signs):
        d = C - self.A
        K, L = _dot(d, self.e0), _dot(d, self.e1)
        M = (_dot(d, d) + self.l1**2 - self.l2**2) / (2 * self.l1)
        radius = np.hypot(K, L)
        ratio = M / np.where(radius > self._axis_tol, radius, np.nan)
        ok = np.abs(ratio) <= 1 + PARALLEL_REACH_TOL
        theta = np.arctan2(L, K) + signs * np.arccos(np.clip(ratio, -1, 1))
        theta = np.angle(np.exp(1j * theta))
        return np.where(ok, theta, np.nan), ok, None

    def closure(self, C, rho):
        B, dB = self._crank(rho)
        g = C - B
        r = 0.5 * (_dot(g, g) - self.l2**2) / self.l2
        return r, g / self.l2, -_dot(g, dB) / self.l2

    def rate_rows(self, C, rho):
        _, g, dr = self.closure(C, rho)
        with np.errstate(divide="ignore", invalid="ignore"):
            return g / -dr

    def passive(self, C, rho, signs):
        B, _ = self._crank(rho)
        out = {"elbow": B}
        if not self.spatial:
            w = C - B
            out["theta2"] = np.angle(np.exp(1j * (np.arctan2(w[1], w[0]) - rho)))
        return out

    def _exact_geometry(self):
        base, axis, e0, l1, l2 = self.exact
        rows = []
        for a, u, e in zip(base, axis, e0):
            a, u, e = sp.Matrix(a), sp.Matrix(u), sp.Matrix(e)
            rows.append((a, u, e, u.cross(e)))
        return rows, sp.sympify(l1), sp.sympify(l2)

    def _solve_exact(self, C, signs):
        """Per leg (theta, cos theta, sin theta, elbow B), exactly; None where out of
        reach."""
        rows, l1, l2 = self._exact_geometry()
        out = []
        for c, (a, _u, e0, e1), sign in zip(C, rows, signs):
            d = c - a
            K, L = sp.expand(d.dot(e0)), sp.expand(d.dot(e1))
            M = sp.expand((d.dot(d) + l1**2 - l2**2) / (2 * l1))
            radius2 = sp.expand(K**2 + L**2)
            excess = sp.expand(M**2 - radius2)
            if _is_float(excess) and excess.is_number:  # a float pose: round-off
                if float(radius2) <= (self._axis_tol) ** 2:
                    out.append(None)
                    continue
                band = 2 * PARALLEL_REACH_TOL * float(radius2)
                if float(excess) > band:
                    out.append(None)
                    continue
                if float(excess) >= -band:  # stretched or folded to round-off (the
                    excess = sp.Float(0)  # root would make it sqrt(eps) off the line)
            elif radius2 == 0 or sp.simplify(excess).is_positive:
                out.append(None)
                continue
            root = int(sign) * sp.sqrt(-excess)
            cos_t = sp.simplify((K * M - L * root) / radius2)
            sin_t = sp.simplify((L * M + K * root) / radius2)
            B = (a + l1 * (cos_t * e0 + sin_t * e1)).applyfunc(sp.simplify)
            out.append((sp.atan2(sin_t, cos_t), cos_t, sin_t, B))
        return out

    def ik_exact(self, C, signs):
        return [sp.nan if s is None else s[0] for s in self._solve_exact(C, signs)]

    def rows_exact(self, C, signs):
        rows, l1, _ = self._exact_geometry()
        out = []
        for c, solved, (_a, _u, e0, e1) in zip(C, self._solve_exact(C, signs), rows):
            if solved is None:
                out.append((sp.Matrix([sp.nan] * 3), sp.Integer(1)))
                continue
            _, cos_t, sin_t, B = solved
            g = _expand(c - B)
            dB = l1 * (-sin_t * e0 + cos_t * e1)
            out.append((g, sp.simplify(-g.dot(dB))))
        return out

    def limbs(self, C, signs):
        rows, _, _ = self._exact_geometry()
        limbs, actuated = [], []
        for i, (c, solved, (a, u, _e0, _e1)) in enumerate(
            zip(C, self._solve_exact(C, signs), rows)
        ):
            if solved is None:
                raise ValueError(
                    f"T is out of reach of leg {i}: it has no joint screws"
                )
            b = solved[3]
            if not self.spatial:
                limbs.append([(u, a, 0), (u, b, 0), (u, c, 0)])
            else:
                v = _expand(
                    u.cross(c - b)
                )  # the U joints' second axis: normal to u and BC
                limbs.append([(u, a, 0), (u, b, 0), (v, b, 0), (v, c, 0), (u, c, 0)])
            actuated.append(0)
        return limbs, actuated


class Linear(Legs):
    """P-R-R-R legs (the Tripteron): carriage along e from A0, then three revolutes
    along e.

    Parameters
    ----------
    base : list of 3 numbers, length m
        The carriages' origins A0_i (m).
    axis : list of 3 numbers, length m
        The unit directions e_i of the rails (and of the revolutes).
    l1, l2 : number
        Lengths of the two links (m).

    Examples
    --------
    A rail along x from the origin: the carriage stops where C projects on it.

    >>> leg = Linear([[0, 0, 0]], [[1, 0, 0]], 1.0, 1.0)
    >>> rho, ok, _ = leg.ik(np.array([0.5, 1.0, 1.0])[:, None, None], np.ones(1))
    >>> rho, ok
    (array([[0.5]]), array([[ True]]))
    """

    modes = ("",)

    def __init__(self, base, axis, l1, l2):
        self.A, self.e = _columns(base), _columns(axis)
        self.l1, self.l2 = float(l1), float(l2)
        self.exact = (base, axis, l1, l2)

    def scaled(self, factor):
        base = (factor * self.A[:, 0, :].T).tolist()
        axis = self.e[:, 0, :].T.tolist()
        return Linear(base, axis, factor * self.l1, factor * self.l2)

    def ik(self, C, signs):
        d = C - self.A
        rho = _dot(d, self.e)
        planar = d - rho * self.e
        reach = np.sqrt(_dot(planar, planar))
        slack = PARALLEL_REACH_TOL * (self.l1 + self.l2)
        ok = (reach <= self.l1 + self.l2 + slack) & (
            reach >= abs(self.l1 - self.l2) - slack
        )
        return np.where(ok, rho, np.nan), ok, None

    def closure(self, C, rho):
        r = _dot(C - self.A, self.e) - rho
        return r, np.broadcast_to(self.e, C.shape), -1.0

    def _elbow(self, C, rho, exact=False):
        """The middle joint B of the planar R-R chain from the carriage to C (elbow
        '+')."""
        if exact:
            base, axis, l1, l2 = self.exact
            out = []
            for c, a, e, d in zip(C, base, axis, rho):
                a, e = sp.Matrix(a), sp.Matrix(e)
                start = a + d * e
                w = _expand(c - start)
                n = e.cross(w)
                dist2 = sp.expand(w.dot(w))
                along = (dist2 + sp.sympify(l1) ** 2 - sp.sympify(l2) ** 2) / (
                    2 * dist2
                )
                h2 = sp.expand(sp.sympify(l1) ** 2 / dist2 - along**2)
                if _is_float(h2) and h2.is_number:  # a float pose: round-off
                    slack = 2 * PARALLEL_REACH_TOL * float(sp.sympify(l1) ** 2 / dist2)
                    h2 = sp.Float(0) if abs(float(h2)) <= slack else h2
                if h2.is_negative:
                    raise ValueError(
                        "T is out of reach of a Tripteron leg: no joint screws"
                    )
                h = sp.sqrt(h2)
                out.append((start, _expand(start + along * w + h * n)))
            return out
        start = self.A + rho * self.e
        w = C - start
        dist2 = _dot(w, w)
        along = (dist2 + self.l1**2 - self.l2**2) / (2 * dist2)
        h = np.sqrt(np.clip(self.l1**2 / dist2 - along**2, 0, None))
        return start + along * w + h * _cross(np.broadcast_to(self.e, w.shape), w)

    def rate_rows(self, C, rho):
        return np.broadcast_to(self.e, C.shape)

    def passive(self, C, rho, signs):
        return {"elbow": self._elbow(C, rho)}

    def ik_exact(self, C, signs):
        base, axis, _, _ = self.exact
        return [
            sp.expand((c - sp.Matrix(a)).dot(sp.Matrix(e)))
            for c, a, e in zip(C, base, axis)
        ]

    def rows_exact(self, C, signs):
        return [(sp.Matrix(e), sp.Integer(-1)) for e in self.exact[1]]

    def limbs(self, C, signs):
        rho = self.ik_exact(C, signs)
        limbs = []
        for c, e, (start, b) in zip(C, self.exact[1], self._elbow(C, rho, exact=True)):
            e = sp.Matrix(e)
            limbs.append([(e, start, sp.oo), (e, start, 0), (e, b, 0), (e, c, 0)])
        return limbs, [0] * len(limbs)
