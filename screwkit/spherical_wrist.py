"""Deprecated alias of :mod:`screwkit.ik.spherical_wrist`, for one release.

The closed form of a 6R arm with a spherical wrist. Importing this module warns
(``DeprecationWarning``): import ``screwkit.ik.spherical_wrist``, or use
``sk.ik.spherical_wrist``. It re-exports the names of that module's ``__all__``.
"""

import warnings

from .ik.spherical_wrist import *  # noqa: F403 (the alias re-exports the module's names)
from .ik.spherical_wrist import __all__  # noqa: F401

warnings.warn(
    "screwkit.spherical_wrist is deprecated and goes in the next release: import "
    "screwkit.ik.spherical_wrist (sk.ik.spherical_wrist) instead",
    DeprecationWarning,
    stacklevel=2,
)
