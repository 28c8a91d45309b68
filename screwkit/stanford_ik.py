"""Deprecated alias of :mod:`screwkit.ik.stanford`, for one release.

The closed form of the Stanford arm. Importing this module warns
(``DeprecationWarning``): import ``screwkit.ik.stanford``, or use ``sk.ik.stanford``. It
re-exports the names of that module's ``__all__``.
"""

import warnings

from .ik.stanford import *  # noqa: F403 (the alias re-exports the module's names)
from .ik.stanford import __all__  # noqa: F401

warnings.warn(
    "screwkit.stanford_ik is deprecated and goes in the next release: import "
    "screwkit.ik.stanford (sk.ik.stanford) instead",
    DeprecationWarning,
    stacklevel=2,
)
