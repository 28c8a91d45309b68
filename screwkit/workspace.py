"""Workspaces by sweeping joints over grids (vectorised: one batched FK for the whole grid).

Joints are numbered 1..n as in the text (q1..qn); angles in radians, lengths in metres.

>>> import numpy as np, screwkit as sk
>>> arm = sk.robots.planar([1.0, 0.5])
>>> s = sweep(arm, {1: (-np.pi, np.pi), 2: (-np.pi, np.pi)}, num=61)
>>> s.points.shape
(61, 61, 3)
>>> [round(v, 6) for v in s.extents()["x"]]  # the annulus 0.5 <= r <= 1.5
[-1.5, 1.5]
"""
from dataclasses import dataclass

import numpy as np

from ._checks import as_float_array, describe
from .jacobians import geometric_jacobian, manipulability

__all__ = ["Sweep", "sweep"]


@dataclass(frozen=True)
class Sweep:
    """The result of :func:`sweep`.

    chain : the swept chain
    joints : the swept joint numbers (1..n), one grid axis each
    values : the joint values of each grid axis (rad, or m for a prismatic joint)
    q : every configuration, shape grid + (n,)
    points : the end-effector point of each configuration, shape grid + (3,) (m)
    """

    chain: object
    joints: tuple
    values: tuple
    q: np.ndarray
    points: np.ndarray

    @property
    def shape(self):
        """The grid's shape: one axis per swept joint."""
        return self.q.shape[:-1]

    def extents(self):
        """{'x': (min, max), 'y': ..., 'z': ...} of the swept points (m)."""
        flat = self.points.reshape(-1, 3)
        return {axis: (float(flat[:, k].min()), float(flat[:, k].max())) for k, axis in enumerate("xyz")}

    def reach(self, centre):
        """(min, max) distance of the swept points from ``centre`` (3,), e.g. a shoulder (m)."""
        centre = as_float_array(centre, "centre")
        if centre.shape != (3,):
            raise ValueError(f"centre must be a point of shape (3,), got shape {centre.shape}")
        distance = np.linalg.norm(self.points - centre, axis=-1)
        return float(distance.min()), float(distance.max())

    def section(self, axis="y", value=0.0, tolerance=0.01):
        """The swept points within ``tolerance`` (m) of the plane ``axis`` = ``value``: (M, 3).

        For a sweep that includes joint 1 this cuts the solid workspace, e.g. axis 'y', value 0
        gives the points in the x-z plane.
        """
        if axis not in ("x", "y", "z"):
            raise ValueError(f"axis must be 'x', 'y' or 'z', got {axis!r}")
        flat = self.points.reshape(-1, 3)
        return flat[np.abs(flat[:, "xyz".index(axis)] - float(value)) <= tolerance]

    def jacobians(self):
        """The geometric Jacobian at every grid point: grid + (6, n)."""
        J = geometric_jacobian(self.chain, self.q.reshape(-1, self.chain.n))
        return J.reshape(self.shape + J.shape[-2:])

    def determinant(self):
        """det J at every grid point (a six-joint chain): shape grid. Its sign changes across
        a singular surface, so ``contour(..., levels=[0])`` draws the singular curves."""
        if self.chain.n != 6:
            raise ValueError(f"det J needs a square Jacobian (6 joints), the chain has {self.chain.n}")
        return np.linalg.det(self.jacobians())

    def singular(self):
        """A mask (shape grid) of the singular configurations: True where J has lost rank, and on
        both sides of every sign change of det J between grid neighbours (a singular surface passes
        between them). For a chain without a square Jacobian, only where J has lost rank."""
        if self.chain.n != 6:
            return self.manipulability() == 0.0
        det = self.determinant()
        mask = self.manipulability() == 0.0
        sign = np.sign(det)
        for axis in range(det.ndim):
            change = np.diff(sign, axis=axis) != 0
            before = [slice(None)] * det.ndim
            after = [slice(None)] * det.ndim
            before[axis], after[axis] = slice(0, -1), slice(1, None)
            mask[tuple(before)] |= change
            mask[tuple(after)] |= change
        return mask

    def manipulability(self, rows="all"):
        """Yoshikawa's manipulability at every grid point: shape grid (0.0 where singular)."""
        w = manipulability(self.chain, self.q.reshape(-1, self.chain.n), rows)
        return np.reshape(w, self.shape)


def sweep(chain, ranges, num=301, q=None):
    """Sweep some joints of ``chain`` over a grid and compute every end-effector point.

    ranges : {joint number (1..n): (low, high)} for each swept joint, in rad (or m)
    num : points per swept joint (an int, or one per joint)
    q : the values of the other joints, shape (n,) (default zero)
    """
    if not isinstance(ranges, dict) or not ranges:
        raise TypeError(f"ranges must be a dict {{joint number: (low, high)}}, got {describe(ranges)}")
    joints = tuple(ranges)
    for joint in joints:
        if not isinstance(joint, (int, np.integer)) or not 1 <= joint <= chain.n:
            raise ValueError(f"ranges keys must be joint numbers 1..{chain.n}, got {joint!r}")
    counts = np.broadcast_to(np.asarray(num), (len(joints),))
    if not np.issubdtype(counts.dtype, np.integer) or np.any(counts < 2):
        raise ValueError(f"num must be an integer >= 2 (or one per swept joint), got {num!r}")
    values = []
    for joint, count in zip(joints, counts):
        bounds = as_float_array(ranges[joint], f"ranges[{joint}]")
        if bounds.shape != (2,):
            raise ValueError(f"ranges[{joint}] must be (low, high), got shape {bounds.shape}")
        values.append(np.linspace(bounds[0], bounds[1], int(count)))
    fixed = np.zeros(chain.n) if q is None else chain.check_q(q, "q")
    if fixed.ndim != 1:
        raise ValueError(f"q must be one configuration of shape ({chain.n},), got shape {fixed.shape}")
    grid = np.empty(tuple(int(c) for c in counts) + (chain.n,))
    grid[...] = fixed
    for axis, (joint, v) in enumerate(zip(joints, values)):
        shape = [1] * len(joints)
        shape[axis] = v.size
        grid[..., joint - 1] = v.reshape(shape)
    points = chain.fk(grid.reshape(-1, chain.n))[:, :3, 3].reshape(grid.shape[:-1] + (3,))
    return Sweep(chain, joints, tuple(values), grid, points)
