"""Workspaces by sweeping joints over grids, computed in chunks so memory stays bounded.

Joints are numbered 1..n as in the text (q1..qn); angles in radians, lengths in metres.
A sweep keeps only its end-effector points (24 bytes per configuration); the joint
values of the grid, the Jacobians, determinants and manipulabilities are computed chunk
by chunk from the grid's axes. A sweep of more than ``MAX_CONFIGURATIONS``
configurations is refused up front with its size and a suggestion.

>>> import numpy as np, screwkit as sk
>>> arm = sk.robots.planar([1.0, 0.5])
>>> s = sweep(arm, {1: (-np.pi, np.pi), 2: (-np.pi, np.pi)}, num=61)
>>> s.points.shape
(61, 61, 3)
>>> [round(v, 6) for v in s.extents()["x"]]  # the annulus 0.5 <= r <= 1.5
[-1.5, 1.5]
"""

import math
from dataclasses import dataclass

import numpy as np

from ._checks import (
    as_float_array,
    check_chain,
    check_integer,
    check_option,
    check_positive,
    describe,
)
from ._compiled import (
    CHUNK,  # the one chunk size (a module global here: tests shrink it)
)
from ._docstrings import fill
from .jacobians import check_rows, geometric_jacobian, manipulability
from .tolerances import SECTION_TOL

__all__ = ["Sweep", "sweep", "MAX_CONFIGURATIONS"]

#: The largest sweep that :func:`sweep` builds by default: 10^7 configurations, whose
#: points take 240 MB (and the grid of joint values, if asked for with ``Sweep.q``,
#: 80 MB per joint).
MAX_CONFIGURATIONS = 10_000_000


#: The largest result (bytes) that ``Sweep.q`` or ``Sweep.jacobians`` builds in one
#: array.
MAX_RESULT_BYTES = 1_000_000_000

#: The Parameters section of the Sweep methods that take only the Jacobian's rows
#: (filled in by :func:`_docstrings.fill`).
_ROWS_PARAMETERS = """Parameters
----------
rows : {'all', 'position', 'orientation', 'planar'}, optional
    The rows of J."""


@dataclass(frozen=True)
class Sweep:
    """The result of :func:`sweep`.

    Parameters
    ----------
    chain : Chain
        The swept chain.
    joints : tuple of int
        The swept joint numbers (1..n), one grid axis each.
    values : tuple of ndarray
        The joint values of each grid axis (rad, or m for a prismatic joint).
    fixed : ndarray, shape (n,)
        The values of every joint off the grid.
    points : ndarray, shape grid + (3,)
        The end-effector point of each configuration (m).

    Examples
    --------
    Links of 1 and 0.5 m, the elbow swept over 0, 90 and 180 deg (shoulder at 0):
    the tip at 1.5, then at (1, 0.5), then folded back to 0.5.

    >>> import screwkit as sk
    >>> arm = sk.robots.planar([1.0, 0.5])
    >>> swept = sweep(arm, {2: (0.0, np.pi)}, num=3)
    >>> swept.joints, (swept.points[:, :2].round(12) + 0.0).tolist()
    ((2,), [[1.5, 0.0], [1.0, 0.5], [0.5, 0.0]])
    """

    chain: object
    joints: tuple
    values: tuple
    fixed: np.ndarray
    points: np.ndarray

    @property
    def shape(self):
        """The grid's shape, one axis per swept joint."""
        return self.points.shape[:-1]

    @property
    def size(self):
        """The number of configurations in the grid."""
        return math.prod(self.shape)

    def configurations(self, start=0, stop=None):
        """The joint vectors of grid points start..stop-1, in C order.

        Parameters
        ----------
        start : int, optional
            The first grid point (flat index).
        stop : int or None, optional
            One past the last; the grid's size by default.

        Returns
        -------
        ndarray, shape (stop - start, n)
            The configurations (rad or m).

        Examples
        --------
        A 2 x 3 grid (joint 1 at 0 and 90 deg, joint 2 at 0, 90, 180 deg); its first
        row, joint 2 varying fastest:

        >>> import screwkit as sk
        >>> arm = sk.robots.planar([1.0, 0.5])
        >>> swept = sweep(arm, {1: (0.0, np.pi / 2), 2: (0.0, np.pi)}, num=(2, 3))
        >>> swept.configurations(0, 3).round(4)
        array([[0.    , 0.    ],
               [0.    , 1.5708],
               [0.    , 3.1416]])
        """
        start = check_integer(start, "start", minimum=0)
        stop = self.size if stop is None else check_integer(stop, "stop", minimum=start)
        if stop > self.size:
            raise ValueError(
                f"stop must be at most the grid's size {self.size}, got {stop}"
            )
        index = np.unravel_index(np.arange(start, stop), self.shape)
        q = np.empty((stop - start, self.chain.n))
        q[:] = self.fixed
        for axis, (joint, values) in enumerate(zip(self.joints, self.values)):
            q[:, joint - 1] = values[index[axis]]
        return q

    @property
    def q(self):
        """Every configuration, shape grid + (n,).

        Built on demand (8 bytes x n per point).
        """
        _check_result_size(
            self.size * self.chain.n * 8,
            "Sweep.q",
            "use Sweep.configurations(start, stop) for a part of the grid",
        )
        return self.configurations().reshape(self.shape + (self.chain.n,))

    def _chunks(self):
        for start in range(0, self.size, CHUNK):
            stop = min(start + CHUNK, self.size)
            yield slice(start, stop), self.configurations(start, stop)

    def _per_point(self, function):
        """``function`` (a batch (m, n) -> (m,)) at every grid point, chunk by chunk:
        shape grid."""
        out = np.empty(self.size)
        for part, q in self._chunks():
            out[part] = function(q)
        return out.reshape(self.shape)

    def extents(self):
        """The extent of the swept points along each axis.

        Returns
        -------
        dict
            {'x': (min, max), 'y': ..., 'z': ...} (m).

        Examples
        --------
        The elbow of the 1 m + 0.5 m arm swept from 0 to 180 deg: the tip stays in
        0.5 <= x <= 1.5 and 0 <= y <= 0.5.

        >>> import screwkit as sk
        >>> swept = sweep(sk.robots.planar([1.0, 0.5]), {2: (0.0, np.pi)}, num=3)
        >>> {axis: [round(v, 6) + 0.0 for v in span]
        ...  for axis, span in swept.extents().items()}
        {'x': [0.5, 1.5], 'y': [0.0, 0.5], 'z': [0.0, 0.0]}
        """
        flat = self.points.reshape(-1, 3)
        return {
            axis: (float(flat[:, k].min()), float(flat[:, k].max()))
            for k, axis in enumerate("xyz")
        }

    def reach(self, centre):
        """The nearest and farthest distance of the swept points from a point.

        Parameters
        ----------
        centre : array-like, shape (3,)
            The point, e.g. a shoulder (m).

        Returns
        -------
        (float, float)
            (min, max) distance (m).

        Examples
        --------
        The elbow swept all round: the tip spans the annulus 1 - 0.5 to 1 + 0.5 m.

        >>> import screwkit as sk
        >>> arm = sk.robots.planar([1.0, 0.5])
        >>> swept = sweep(arm, {2: (-np.pi, np.pi)}, num=5)
        >>> [round(d, 6) for d in swept.reach([0.0, 0.0, 0.0])]
        [0.5, 1.5]
        """
        centre = as_float_array(centre, "centre")
        if centre.shape != (3,):
            raise ValueError(
                f"centre must be a point of shape (3,), got shape {centre.shape}"
            )
        flat = self.points.reshape(-1, 3)
        low, high = np.inf, -np.inf
        for start in range(0, len(flat), CHUNK):
            distance = np.linalg.norm(flat[start : start + CHUNK] - centre, axis=-1)
            low, high = min(low, distance.min()), max(high, distance.max())
        return float(low), float(high)

    def section(self, axis="y", value=0.0, tolerance=SECTION_TOL):
        """The swept points near the plane ``axis`` = ``value``.

        For a sweep that includes joint 1 this cuts the solid workspace, e.g. axis 'y',
        value 0 gives the points in the x-z plane.

        Parameters
        ----------
        axis : {'x', 'y', 'z'}, optional
            The plane's normal.
        value : float, optional
            The plane's coordinate (m).
        tolerance : float, optional
            The distance from the plane accepted (m).

        Returns
        -------
        ndarray, shape (M, 3)
            The M points (m).

        Examples
        --------
        The stretched arm (1.5 m) turned by the shoulder to -180, -90, 0, 90 and
        180 deg: three of those tips lie on the x axis (y = 0).

        >>> import screwkit as sk
        >>> arm = sk.robots.planar([1.0, 0.5])
        >>> swept = sweep(arm, {1: (-np.pi, np.pi)}, num=5)
        >>> swept.section("y", 0.0)[:, 0].round(6).tolist()
        [-1.5, 1.5, -1.5]
        """
        check_option(axis, "axis", ("x", "y", "z"))
        value = as_float_array(value, "value")
        if value.shape != ():
            raise TypeError(f"value must be one number (m), got {describe(value)}")
        tolerance = check_positive(tolerance, "tolerance", allow_zero=True)
        flat = self.points.reshape(-1, 3)
        return flat[np.abs(flat[:, "xyz".index(axis)] - float(value)) <= tolerance]

    @fill(parameters=_ROWS_PARAMETERS)
    def jacobians(self, rows="all"):
        """The geometric Jacobian's ``rows`` at every grid point.

        {parameters}

        Returns
        -------
        ndarray, shape grid + (m, n)
            The Jacobians, m rows each.

        Examples
        --------
        With the elbow at 90 deg the tip is at (1, 0.5): column i is z x (tip -
        joint i), so J = [[-0.5, -0.5], [1, 0]].

        >>> import screwkit as sk
        >>> swept = sweep(sk.robots.planar([1.0, 0.5]), {2: (0.0, np.pi)}, num=3)
        >>> J = swept.jacobians("planar")
        >>> J.shape, (J[1].round(12) + 0.0).tolist()
        ((3, 2, 2), [[-0.5, -0.5], [1.0, 0.0]])
        """
        block = check_rows(rows)
        m = len(range(6)[block])
        _check_result_size(
            self.size * m * self.chain.n * 8,
            "Sweep.jacobians",
            "use determinant(), manipulability() or singular(), which stream",
        )
        out = np.empty((self.size, m, self.chain.n))
        for part, q in self._chunks():
            out[part] = geometric_jacobian(self.chain, q)[:, block]
        return out.reshape(self.shape + (m, self.chain.n))

    def determinant(self, rows="all"):
        """det J at every grid point.

        Its sign changes across a singular surface, so ``contour(..., levels=[0])``
        draws it.

        Parameters
        ----------
        rows : {'all', 'position', 'orientation', 'planar'}, optional
            The rows of J; J must be square (as many rows as joints, e.g. rows='all'
            for six joints, 'planar' for a two-link planar arm).

        Returns
        -------
        ndarray, shape grid
            det J.

        Examples
        --------
        For two links det J = l1 l2 sin(q2): 0 stretched, 0.5 at 90 deg, 0 folded.

        >>> import screwkit as sk
        >>> swept = sweep(sk.robots.planar([1.0, 0.5]), {2: (0.0, np.pi)}, num=3)
        >>> (swept.determinant("planar").round(6) + 0.0).tolist()
        [0.0, 0.5, 0.0]
        """
        block = check_rows(rows)
        m = len(range(6)[block])
        if m != self.chain.n:
            raise ValueError(
                f"rows must select {self.chain.n} rows, one per joint, for det J "
                f"(a square Jacobian), got rows={rows!r} with {m} rows; use "
                "manipulability() instead"
            )
        return self._per_point(
            lambda q: np.linalg.det(geometric_jacobian(self.chain, q)[:, block])
        )

    @fill(parameters=_ROWS_PARAMETERS)
    def manipulability(self, rows="all"):
        """Yoshikawa's manipulability of the Jacobian's ``rows`` at every grid point.

        {parameters}

        Returns
        -------
        ndarray, shape grid
            The manipulability (0.0 where singular).

        Examples
        --------
        For two links it is the absolute value of l1 l2 sin(q2):

        >>> import screwkit as sk
        >>> swept = sweep(sk.robots.planar([1.0, 0.5]), {2: (0.0, np.pi)}, num=3)
        >>> (swept.manipulability("planar").round(6) + 0.0).tolist()
        [0.0, 0.5, 0.0]
        """
        check_rows(rows)
        return self._per_point(lambda q: manipulability(self.chain, q, rows))

    @fill(parameters=_ROWS_PARAMETERS)
    def singular(self, rows="all"):
        """A mask (shape grid) of the singular configurations of the Jacobian's
        ``rows``.

        True where J has lost rank (manipulability 0), and, for a square J, on both
        sides of every strict sign change of det J between grid neighbours
        (a singular surface passes between them). ``rows`` as in
        :func:`screwkit.jacobians.manipulability`: use ``rows='planar'`` for a planar
        arm, whose six-row Jacobian never loses rank.

        {parameters}

        Returns
        -------
        ndarray of bool, shape grid
            True at singular configurations.

        Examples
        --------
        The elbow at -90, -30, 30 and 90 deg: det J changes sign between -30 and 30
        (the stretched arm, q2 = 0, lies between them), so both are marked.

        >>> import screwkit as sk
        >>> arm = sk.robots.planar([1.0, 0.5])
        >>> swept = sweep(arm, {2: (-np.pi / 2, np.pi / 2)}, num=4)
        >>> swept.singular("planar").tolist()
        [False, True, True, False]
        """
        block = check_rows(rows)
        lost = self.manipulability(rows) == 0.0
        if len(range(6)[block]) != self.chain.n:
            return lost
        sign = np.where(lost, 0.0, np.sign(self.determinant(rows)))
        mask = lost.copy()
        for axis in range(sign.ndim):
            before = [slice(None)] * sign.ndim
            after = [slice(None)] * sign.ndim
            before[axis], after[axis] = slice(0, -1), slice(1, None)
            change = sign[tuple(before)] * sign[tuple(after)] < 0
            mask[tuple(before)] |= change
            mask[tuple(after)] |= change
        return mask


def _check_result_size(nbytes, what, suggestion):
    if nbytes > MAX_RESULT_BYTES:
        raise ValueError(
            f"{what} would build one array of {nbytes / 1e9:.2f} GB, more than the "
            f"limit of {MAX_RESULT_BYTES / 1e9:.0f} GB; {suggestion}, or sweep a "
            "coarser grid"
        )


def sweep(chain, ranges, num=301, q=None, max_configurations=MAX_CONFIGURATIONS):
    """Sweep some joints of ``chain`` over a grid and compute every end-effector point.

    Parameters
    ----------
    chain : Chain
    ranges : {joint number (1..n): (low, high)} for each swept joint, in rad (or m)
    num : points per swept joint (an int >= 2, or a sequence of one per joint)
    q : the values of the other joints, shape (n,) (default zero)
    max_configurations : the largest grid built (default ``MAX_CONFIGURATIONS``, 10^7);
        a larger sweep is refused before anything is allocated

    Returns
    -------
    Sweep, with points of shape grid + (3,) (m), computed in chunks of ``CHUNK`` poses

    Examples
    --------
    The shoulder of a stretched 1.5 m arm swept over a quarter turn: the tip moves
    from (1.5, 0) to (0, 1.5).

    >>> import screwkit as sk
    >>> swept = sweep(sk.robots.planar([1.0, 0.5]), {1: (0.0, np.pi / 2)}, num=3)
    >>> swept.points.shape, (swept.points[[0, -1], :2].round(12) + 0.0).tolist()
    ((3, 3), [[1.5, 0.0], [0.0, 1.5]])
    """
    chain = check_chain(chain)
    if not isinstance(ranges, dict) or not ranges:
        raise TypeError(
            "ranges must be a dict {joint number: (low, high)} with at least one "
            f"joint, got {describe(ranges)}"
        )
    joints = tuple(ranges)
    for joint in joints:
        if isinstance(joint, (bool, np.bool_)) or not isinstance(
            joint, (int, np.integer)
        ):
            raise TypeError(
                f"ranges keys must be joint numbers 1..{chain.n} (integers), got "
                f"{joint!r}"
            )
        if not 1 <= joint <= chain.n:
            raise ValueError(
                f"ranges keys must be joint numbers 1..{chain.n}, got {joint!r}"
            )
    joints = tuple(int(joint) for joint in joints)
    counts = _counts(num, len(joints))
    values = []
    for joint, count in zip(joints, counts):
        bounds = as_float_array(ranges[joint], f"ranges[{joint}]")
        if bounds.shape != (2,):
            raise ValueError(
                f"ranges[{joint}] must be (low, high), got shape {bounds.shape}"
            )
        if bounds[0] == bounds[1]:
            raise ValueError(
                f"ranges[{joint}] must have low != high, got {bounds.tolist()}; "
                "to hold the joint still, give its value in q instead"
            )
        values.append(np.linspace(bounds[0], bounds[1], count))
    limit = check_integer(max_configurations, "max_configurations", minimum=1)
    size = math.prod(counts)
    if size > limit:
        grid = " x ".join(str(c) for c in counts)
        fewer = max(2, int(limit ** (1 / len(counts))))
        raise ValueError(
            f"a sweep must have at most max_configurations = {limit:,} configurations, "
            f"got {grid} = {size:,} (its points alone would take "
            f"{size * 24 / 1e9:.2f} GB); use fewer steps (e.g. num={fewer}), or sweep "
            "fewer joints and fix the others with q (a section)"
        )
    fixed = np.zeros(chain.n) if q is None else chain.check_one(q, "q")
    result = Sweep(
        chain, joints, tuple(values), fixed.copy(), np.empty(tuple(counts) + (3,))
    )
    flat = result.points.reshape(-1, 3)  # a view: the chunks fill the grid in place
    for part, configurations in result._chunks():
        flat[part] = chain.fk(configurations)[:, :3, 3]
    return result


def _counts(num, joints):
    """Points per swept joint: ``num`` is one int >= 2 or a sequence of ``joints`` of
    them."""
    if isinstance(num, (list, tuple, np.ndarray)):
        if len(num) != joints:
            raise ValueError(
                f"num must be one integer or one per swept joint ({joints}), got "
                f"{describe(num)}"
            )
        return [check_integer(n, "num", minimum=2) for n in num]
    return [check_integer(num, "num", minimum=2)] * joints
