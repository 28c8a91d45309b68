"""Deprecated alias of :mod:`screwkit.limbs`, the limb builders, kept for one release.

"joints" also names the joint kinds (:class:`screwkit.Joint`), a chain's ``joints`` and
the DH rows (``Link.revolute``); the builders of (s, r, h) limbs are
:mod:`screwkit.limbs`: ``sk.joints.revolute`` is ``sk.limbs.revolute``. Importing this
module, and every name read from it, emits a ``DeprecationWarning``.
"""

import warnings

from . import limbs as _limbs

__all__ = list(_limbs.__all__)

_MESSAGE = (
    "screwkit.joints is deprecated and will be removed in the next release: use "
    "screwkit.limbs (sk.limbs), which holds the same builders"
)

warnings.warn(_MESSAGE, DeprecationWarning, stacklevel=2)


def __getattr__(name):
    if name in __all__:
        warnings.warn(_MESSAGE, DeprecationWarning, stacklevel=2)
        return getattr(_limbs, name)
    raise AttributeError(f"module 'screwkit.joints' has no attribute {name!r}")
