"""screwkit: exact and fast robot kinematics with screws.

The library behind the course *Robot Kinematics with Screws*. Exact where it
teaches (SymPy input gives SymPy output), fast where it computes (NumPy input
gives float64 arrays, vectorised over a leading batch axis). SI units:
metres and radians. Screws and twists are ordered [angular; linear].
"""

from . import (
    _lazy,
    chains,
    ik,
    jacobians,
    lie,
    limbs,
    lines,
    links,
    mobility_analysis,
    motion,
    orientation,
    parallel,
    redundancy,
    robots,
    screws,
    statics,
    systems,
    tolerances,
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
# first use (sk.plotting, sk.schematic, sk.widgets, sk.viewer); sk.exercises, the
# display of self-checks, too; and sk.contact, whose linear programs load
# scipy.optimize (about half of screwkit's own import time).
_LAZY_SUBMODULES = (
    "plotting",
    "schematic",
    "widgets",
    "viewer",
    "exercises",
    "contact",
)


__getattr__ = _lazy.attach(__name__, dict.fromkeys(_LAZY_SUBMODULES, ()), globals())[0]


__all__ = [
    # submodules (plotting, viewer, widgets, exercises and contact load on first use)
    "chains",
    "contact",
    "exercises",
    "ik",
    "jacobians",
    "lie",
    "limbs",
    "lines",
    "links",
    "mobility_analysis",
    "motion",
    "orientation",
    "parallel",
    "plotting",
    "redundancy",
    "robots",
    "schematic",
    "screws",
    "statics",
    "systems",
    "tolerances",
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
