"""What the closed-form IK engines share (:mod:`.spherical_wrist`, :mod:`.ur`,
:mod:`.stanford`): checked public methods over each engine's unchecked kernels, the
batch solved in chunks, the arm's size, the wrist's flip measure and rotations about a
fixed axis.

An engine defines ``_measures(q)``, ``_labels(q)`` (q: float array (..., 6)),
``_solve(T)`` (one chunk of poses (N, 4, 4)) and ``_reason(T, code)`` (one pose);
:mod:`.dispatch` calls the kernels with input it has checked already, a student or a
test calls the public methods below, which check first.
"""

from dataclasses import dataclass

import numpy as np

from .._checks import as_float_array, check_chain, check_integer, check_poses
from .._compiled import CHUNK
from .._docstrings import fill
from ..transforms import _skew
from .subproblems import _dot_batch

__all__ = [
    "ClosedFormArm",
    "REASON_CODES",
    "Turn",
    "arm_scale",
    "branches",
    "flip_measure",
]

#: The reason codes of a pose no branch reaches (0 is reached): 1 shoulder, 2 out of
#: the arm's reach, 3 wrist orientation (each engine's ``reason`` says it in words).
REASON_CODES = (1, 2, 3)


def _configurations(q):
    """q as a float array (..., 6), or a clear error naming it."""
    q = as_float_array(q, "q")
    if q.ndim == 0 or q.shape[-1] != 6:
        raise ValueError(
            f"q must have 6 entries, shape (6,) or (N, 6), got shape {q.shape}"
        )
    return q


def from_chain_sections(arm, engine, refused):
    """The Parameters and Returns of an engine's ``from_chain``: the chain must be
    ``arm``; ``engine`` is the class returned, ``refused`` says which chains are a
    ValueError."""
    return f"""Parameters
----------
chain : Chain
    {arm}
name : str
    The argument's name, for the messages.

Returns
-------
{engine}
    The engine; {refused} is a ``ValueError``
    that names the condition it fails."""


#: The Parameters and Returns of the engines' ``from_chain``.
_FROM_CHAIN = from_chain_sections(
    "An arm of the engine's structure (its module says which).",
    "ClosedFormArm",
    "a chain of another structure",
)


@dataclass(frozen=True)
class ClosedFormArm:
    """The public, checked side of a closed-form engine (see the module docstring).

    A subclass is the geometry of one arm, built by :meth:`from_chain`; the methods
    below check their input and call the subclass's kernels. Every engine holds:

    Parameters
    ----------
    w : ndarray, shape (6, 3)
        The unit axis directions at q = 0 (a prismatic joint's: its direction).
    p : ndarray, shape (6, 3)
        The point of each revolute axis nearest the base origin (m).
    home : ndarray, shape (4, 4)
        The home pose M (m).
    scale : float
        The arm's size (:func:`arm_scale`, m), the length its tolerances are measured
        against.
    """

    w: np.ndarray
    p: np.ndarray
    home: np.ndarray
    scale: float

    @classmethod
    @fill(sections=_FROM_CHAIN)
    def from_chain(cls, chain, name="chain"):
        """The engine of a chain: its geometry, read from its screws.

        {sections}
        """
        check_chain(chain, name)
        return cls._from_chain(chain, name)

    def measures(self, q):
        """The signed measures the configuration labels test.

        Parameters
        ----------
        q : array-like, shape (..., 6)
            Joint vectors (rad; m for a prismatic joint).

        Returns
        -------
        tuple of three ndarrays, shape (...)
            The arm's, the elbow's (or boom's) and the wrist's measure; each engine's
            module says what they measure and in which unit.
        """
        return self._measures(_configurations(q))

    def labels(self, q):
        """The configuration labels of joint vectors q, shape (..., 6), as for
        :meth:`measures`.

        Returns
        -------
        ndarray of str, shape (...)
            Labels like 'ruf', from the signs of the measures.
        """
        return self._labels(_configurations(q))

    def solve(self, T):
        """All eight solutions of one pose or a batch, in the order of CONFIGURATIONS.

        Parameters
        ----------
        T : array-like, shape (4, 4) or (N, 4, 4)
            Tool poses (m); a single pose is a batch of one.

        Returns
        -------
        Q : ndarray, shape (N, 8, 6)
            Joint vectors in (-pi, pi] (prismatic joints in m), NaN where a branch
            does not reach the pose.
        flags : ndarray of bool, shape (N, 8, 3)
            The shoulder, elbow and wrist singularity of each solution.
        code : ndarray of int, shape (N,)
            0 where the pose is reached, else one of :data:`REASON_CODES`.
        """
        T = check_poses(T, "T")
        return self._solve_batch(T[None] if T.ndim == 2 else T)

    def reason(self, T, code):
        """A sentence saying why a pose is not reached.

        Parameters
        ----------
        T : array-like, shape (4, 4)
            The tool pose (m).
        code : int
            Its reason code, one of :data:`REASON_CODES`, as :meth:`solve` returns it.

        Returns
        -------
        str
        """
        T = check_poses(T, "T", single_only=True)
        code = check_integer(code, "code")
        if code not in REASON_CODES:
            raise ValueError(f"code must be one of {REASON_CODES}, got {code}")
        return self._reason(T, code)

    def _solve_batch(self, T):
        """:meth:`solve` of checked poses (N, 4, 4), in chunks of CHUNK poses."""
        N = T.shape[0]
        Q = np.empty((N, 8, 6))
        flags = np.empty((N, 8, 3), dtype=bool)
        code = np.empty(N, dtype=int)
        for start in range(0, N, CHUNK):
            part = slice(start, start + CHUNK)
            Q[part], flags[part], code[part] = self._solve(T[part])
        return Q, flags, code


def pose_residual(chain, Q, T, scale):
    """How far the chain's forward kinematics at each row of Q lands from its pose.

    Parameters
    ----------
    chain : Chain
    Q : array, shape (k, n), joint vectors (rad)
    T : array, shape (k, 4, 4) or (4, 4), the poses (m)
    scale : float, the arm's size (m), see :func:`arm_scale`

    Returns
    -------
    array (k,) : the largest entry of the rotation's difference and of the position's
        divided by scale
    """
    # entries first, (4, 4, k): the chain computes each entry as one row, and a
    # maximum over the leading axes is a row-by-row comparison (over the trailing 3 x 3
    # of (k, 4, 4) it is several times slower)
    T = np.moveaxis(T, (-2, -1), (0, 1)) if T.ndim == 3 else T[:, :, None]
    D = np.abs(np.moveaxis(chain.fk(Q), 0, -1) - T)
    return np.maximum(D[:3, :3].max((0, 1)), D[:3, 3].max(0) / scale)


def arm_scale(p):
    """The size of an arm, the length its tolerances are measured against.

    Parameters
    ----------
    p : array, shape (6, 3), the point of each joint axis nearest the base origin (m)

    Returns
    -------
    float : 1 + the largest distance of an axis from the base origin (m); the 1 m keeps
        it from vanishing for an arm whose axes all pass through the origin
    """
    return 1.0 + float(np.max(np.linalg.norm(p, axis=1)))


def flip_measure(w, q5):
    """The wrist's flip measure (w_4 x R(w_5, q5) w_6) . w_5: positive for the 'f'
    solutions, negative for the 'n' ones, 0 at the wrist singularity.

    Parameters
    ----------
    w : array, shape (6, 3), the unit axis directions at q = 0
    q5 : array (...), joint 5's angle (rad)

    Returns
    -------
    array (...): A cos(q5) + B sin(q5), A = (w_4 x w_6) . w_5,
        B = w_4 . w_6 - (w_4 . w_5)(w_5 . w_6) (unit-free)
    """
    A = np.cross(w[3], w[5]) @ w[4]
    B = w[3] @ w[5] - (w[3] @ w[4]) * (w[4] @ w[5])
    return A * np.cos(q5) + B * np.sin(q5)


def _apply(K, v):
    """K @ v for a fixed K (3, 3) and vectors v (3, ...): one matrix product."""
    return (K @ v.reshape(3, -1)).reshape(v.shape)


class Turn:
    """Rotations about one fixed unit direction, applied to many vectors at once.

    Rodrigues' formula on vectors, x c + (w x x) s + w (w . x)(1 - c), with the cosines
    c and sines s of the angles given (computed once, used for many vectors).

    Parameters
    ----------
    w : array, shape (3,), the unit direction of the axis (through the origin)
    """

    def __init__(self, w):
        self.w, self.K = w, _skew(w)

    def __call__(self, x, c, s):
        """Vectors x, shape (..., 3), turned by the angles of cosines c and sines s,
        shape (...) (they broadcast); returns an array (..., 3)."""
        along, cross = x @ self.w, x @ self.K.T
        c, s = c[..., None], s[..., None]
        return x * c + cross * s + self.w * (along[..., None] * (1 - c))

    def first(self, x, c, s):
        """The same for vectors laid out components first, x (3, ...), c and s (...):
        the products with w and [w] are then single matrix products; returns an array
        (3, ...)."""
        along = _dot_batch(self.w, x) * (1 - c)
        w = self.w.reshape((3,) + (1,) * along.ndim)
        return x * c + _apply(self.K, x) * s + w * along

    def fixed(self, v, c, s):
        """One vector v, shape (3,), turned by many angles, cosines c and sines s
        (...); returns an array (..., 3)."""
        c, s = c[..., None], s[..., None]
        v_along = self.w * (v @ self.w)
        return (v - v_along) * c + (self.K @ v) * s + v_along


def branches(Q, flags, reached, order=(0, 1, 2, 3)):
    """The eight branches of a batch in the order of CONFIGURATIONS.

    Parameters
    ----------
    Q : array, shape (N, 2, 2, 2, 6), the joint vectors of each pose's branches (rad,
        m for a prismatic joint), in the engine's order of the three two-way choices
    flags : array of bool, shape (N, 2, 2, 2, 3), the singularity flags of each branch
    reached : array of bool, broadcasting to (N, 2, 2, 2): which branches reach
    order : the axes of Q that hold (N, arm, elbow, wrist): a transposition of
        (0, 1, 2, 3)

    Returns
    -------
    Q : array (N, 8, 6), NaN where a branch does not reach
    flags : array of bool (N, 8, 3)
    """
    N = Q.shape[0]
    if not np.all(reached):
        Q[~np.broadcast_to(reached, Q.shape[:4])] = np.nan
    axes = (*order, 4)
    return (
        Q.transpose(axes).reshape(N, 8, 6),
        flags.transpose(axes).reshape(N, 8, 3),
    )
