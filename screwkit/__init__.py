"""screwkit: exact and fast robot kinematics with screws.

The library behind the course *Robot Kinematics with Screws*. Exact where it
teaches (SymPy input gives SymPy output), fast where it computes (NumPy input
gives float64 arrays, vectorised over a leading batch axis). SI units:
metres and radians. Screws and twists are ordered [angular; linear].
"""
from .transforms import (
    exp_twist,
    homogeneous,
    inv,
    rot_axis,
    rotx,
    roty,
    rotz,
    screw_motion,
    skew,
    transl,
    twist_from_axis,
)

__version__ = "0.1.0"

__all__ = [
    "exp_twist",
    "homogeneous",
    "inv",
    "rot_axis",
    "rotx",
    "roty",
    "rotz",
    "screw_motion",
    "skew",
    "transl",
    "twist_from_axis",
]
