"""Deprecated alias of :mod:`screwkit.ik.ur`, for one release.

The closed form of a UR-type arm. Importing this module warns (``DeprecationWarning``):
import ``screwkit.ik.ur``, or use ``sk.ik.ur``. It re-exports the names of that module's
``__all__``.
"""

import warnings

from .ik.ur import *  # noqa: F403 (the alias re-exports the module's names)
from .ik.ur import __all__  # noqa: F401

warnings.warn(
    "screwkit.ur_ik is deprecated and goes in the next release: import "
    "screwkit.ik.ur (sk.ik.ur) instead",
    DeprecationWarning,
    stacklevel=2,
)
