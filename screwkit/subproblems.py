"""Deprecated alias of :mod:`screwkit.ik.subproblems`, for one release.

The Paden–Kahan subproblems. Importing this module warns (``DeprecationWarning``):
import ``screwkit.ik.subproblems``, or use ``sk.ik.subproblems``. It re-exports the
names of that module's ``__all__``.
"""

import warnings

from .ik.subproblems import *  # noqa: F403 (the alias re-exports the module's names)
from .ik.subproblems import __all__  # noqa: F401

warnings.warn(
    "screwkit.subproblems is deprecated and goes in the next release: import "
    "screwkit.ik.subproblems (sk.ik.subproblems) instead",
    DeprecationWarning,
    stacklevel=2,
)
