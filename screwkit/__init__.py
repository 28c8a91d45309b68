"""screwkit: exact and fast robot kinematics with screws.

The library behind the course *Robot Kinematics with Screws*. Exact where it
teaches (SymPy input gives SymPy output), fast where it computes (NumPy input
gives float64 arrays, vectorised over a leading batch axis). SI units:
metres and radians. Screws and twists are ordered [angular; linear].
"""
from . import ik, jacobians, joints, redundancy, robots, urdf, workspace
from .chains import Chain, Convention, Joint, Link, textbook
from .lie import ad, adjoint, log_rotation, log_transform, vee
from .mobility import Mobility, grubler_kutzbach, mobility
from .screws import Screw, Twist, Wrench
from .systems import ScrewSystem
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
    wrap_angle,
)

__version__ = "0.1.0"

# Drawing, widgets and the in-page viewer load matplotlib and ipywidgets: imported on first use
# (sk.plotting, sk.widgets, sk.viewer).
_LAZY_SUBMODULES = ("plotting", "widgets", "viewer")


def __getattr__(name):
    if name in _LAZY_SUBMODULES:
        import importlib

        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'screwkit' has no attribute {name!r}")


__all__ = [
    "Chain",
    "ad",
    "adjoint",
    "log_rotation",
    "log_transform",
    "vee",
    "Convention",
    "Joint",
    "Link",
    "textbook",
    "Mobility",
    "Screw",
    "ScrewSystem",
    "Twist",
    "Wrench",
    "grubler_kutzbach",
    "ik",
    "jacobians",
    "joints",
    "mobility",
    "redundancy",
    "robots",
    "urdf",
    "workspace",
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
    "wrap_angle",
]
