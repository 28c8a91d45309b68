"""Deprecated alias of :mod:`screwkit.limbs`, the limb builders, kept for one release.

"joints" also names the joint kinds (:class:`screwkit.Joint`), a chain's ``joints`` and
the DH rows (``Link.revolute``); the builders of (s, r, h) limbs are
:mod:`screwkit.limbs`: ``sk.joints.revolute`` is ``sk.limbs.revolute``.
"""

from .limbs import (
    cylindrical,
    helical,
    parallelogram,
    prismatic,
    revolute,
    rotate_limb,
    spherical,
    translate_limb,
    universal,
)

__all__ = [
    "revolute",
    "prismatic",
    "helical",
    "cylindrical",
    "universal",
    "spherical",
    "parallelogram",
    "rotate_limb",
    "translate_limb",
]
