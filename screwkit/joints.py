"""Deprecated alias of :mod:`screwkit.limbs`, the limb builders, kept for one release.

"joints" also names the joint kinds (:class:`screwkit.Joint`), a chain's ``joints`` and
the DH rows (``Link.revolute``); the builders of (s, r, h) limbs are
:mod:`screwkit.limbs`: ``sk.joints.revolute`` is ``sk.limbs.revolute``. Importing this
module (or reading ``sk.joints``) emits a ``DeprecationWarning``.
"""

import warnings

from .limbs import *  # noqa: F403 (the alias re-exports every limb builder)
from .limbs import __all__  # noqa: F401

warnings.warn(
    "screwkit.joints is deprecated and will be removed in the next release: use "
    "screwkit.limbs (sk.limbs), which holds the same builders",
    DeprecationWarning,
    stacklevel=2,
)
