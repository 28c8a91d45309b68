"""screwkit: exact and fast robot kinematics with screws.

The library behind the course *Robot Kinematics with Screws*. Exact where it
teaches (SymPy input gives SymPy output), fast where it computes (NumPy input
gives float64 arrays, vectorised over a leading batch axis). SI units:
metres and radians. Screws and twists are ordered [angular; linear].
"""

import importlib
import sys
import types
import warnings

from . import (
    acceleration,
    chains,
    differential_ik,
    ik,
    jacobians,
    lie,
    limbs,
    lines,
    links,
    mobility_analysis,
    orientation,
    parallel,
    redundancy,
    robots,
    screws,
    systems,
    tolerances,
    trajectory,
    transforms,
    urdf,
    workspace,
)
from .chains import Chain, Convention, Joint, Link, textbook
from .lie import ad, adjoint, log_rotation, log_transform, vee
from .lines import Line
from .mobility_analysis import Mobility, grubler_kutzbach, mobility
from .orientation import (
    euler_from_rotation,
    euler_rate_matrix,
    gimbal_lock,
    quaternion_from_rotation,
    quaternion_multiply,
    rotation_from_euler,
    rotation_from_quaternion,
    rotation_from_rpy,
    rpy_from_rotation,
)
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

# Drawing, widgets and the in-page viewer load matplotlib and ipywidgets: imported on
# first use (sk.plotting, sk.widgets, sk.viewer); sk.exercises, the display of
# self-checks, too.
_LAZY_SUBMODULES = ("plotting", "widgets", "viewer", "exercises")

#: Module paths kept for one release, {old name: new module}: each use warns.
#: sk.joints was the limb builders' first name (joints also name a chain's joint kinds);
#: screwkit.mobility, the module, was hidden by sk.mobility, the function of the API.
_DEPRECATED_MODULES = {"joints": "limbs", "mobility": "mobility_analysis"}


def __getattr__(name):
    # sk.joints loads the deprecated alias, which warns on import and on every name
    # read from it
    if name in _LAZY_SUBMODULES or name == "joints":
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module 'screwkit' has no attribute {name!r}")


def _warn_moved(old, stacklevel):
    new = _DEPRECATED_MODULES[old]
    warnings.warn(
        f"screwkit.{old} is deprecated and will be removed in the next release: "
        f"use screwkit.{new} (sk.{new}), which holds the same names",
        DeprecationWarning,
        stacklevel=stacklevel,
    )


class _MovedModule(types.ModuleType):
    """The old path of a moved module: ``from screwkit.mobility import Mobility`` still
    works, warns, and reads the name from the new module. No file stands at the old
    path, so importing it cannot rebind ``sk.mobility``, the function."""

    def __init__(self, old, new):
        super().__init__(f"{__name__}.{old}", f"Deprecated alias of {new.__name__}.")
        self._old, self._new = old, new

    def __getattr__(self, name):
        if name.startswith("__"):
            raise AttributeError(name)
        _warn_moved(self._old, stacklevel=2)
        return getattr(self._new, name)


sys.modules[f"{__name__}.mobility"] = _MovedModule("mobility", mobility_analysis)

__all__ = [
    # submodules (plotting, viewer, widgets and exercises load on first use)
    "acceleration",
    "chains",
    "differential_ik",
    "exercises",
    "ik",
    "jacobians",
    "lie",
    "limbs",
    "lines",
    "links",
    "mobility_analysis",
    "orientation",
    "parallel",
    "plotting",
    "redundancy",
    "robots",
    "screws",
    "systems",
    "tolerances",
    "trajectory",
    "transforms",
    "urdf",
    "viewer",
    "widgets",
    "workspace",
    # chains
    "Chain",
    "Convention",
    "Joint",
    "Link",
    "textbook",
    # Lie algebra
    "ad",
    "adjoint",
    "log_rotation",
    "log_transform",
    "vee",
    # screws, lines and mobility
    "Line",
    "Mobility",
    "Screw",
    "ScrewSystem",
    "Twist",
    "Wrench",
    "grubler_kutzbach",
    "mobility",
    # rigid motions
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
    # orientation
    "euler_from_rotation",
    "euler_rate_matrix",
    "gimbal_lock",
    "quaternion_from_rotation",
    "quaternion_multiply",
    "rotation_from_euler",
    "rotation_from_quaternion",
    "rotation_from_rpy",
    "rpy_from_rotation",
]
