"""What the closed-form IK engines share (:mod:`.spherical_wrist`, :mod:`.ur_ik`,
:mod:`.stanford_ik`): checked public methods over each engine's unchecked kernels, and
the batch solved in chunks.

An engine defines ``_measures(q)``, ``_labels(q)`` (q: float array (..., 6)),
``_solve(T)`` (one chunk of poses (N, 4, 4)) and ``_reason(T, code)`` (one pose);
:mod:`.ik` calls the kernels with input it has checked already, a student or a test
calls the public methods below, which check first.
"""

import numpy as np

from .._checks import as_float_array, check_integer, check_poses
from .._compiled import CHUNK

__all__ = ["ClosedFormArm", "REASON_CODES"]

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


class ClosedFormArm:
    """The public, checked side of a closed-form engine (see the module docstring)."""

    def measures(self, q):
        """The signed measures the labels test, at q (..., 6): three arrays (...)."""
        return self._measures(_configurations(q))

    def labels(self, q):
        """The configuration labels of q (..., 6): an array of strings like 'ruf'."""
        return self._labels(_configurations(q))

    def solve(self, T):
        """All eight solutions of one pose T (4, 4) or a batch (N, 4, 4), in the order
        of CONFIGURATIONS (a single pose as a batch of one).

        Returns Q (N, 8, 6) in (-pi, pi] (prismatic joints in m), NaN where a branch
        does not reach the pose; the singularity flags (N, 8, 3); and the reason code
        per pose (N,): 0 reached, else one of :data:`REASON_CODES`.
        """
        T = check_poses(T, "T")
        return self._solve_batch(T[None] if T.ndim == 2 else T)

    def reason(self, T, code):
        """A sentence saying why the pose T (4, 4) is not reached, for its reason code
        (one of :data:`REASON_CODES`, as :meth:`solve` returns it)."""
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
