"""Motion in time: second-order kinematics, trajectories and differential IK.

The family, one idea a module:

* :mod:`~screwkit.motion.acceleration`: Jacobians in time, Hessians and end-effector
  accelerations in screw form (``sk.motion.space_jacobian_dot``,
  ``geometric_acceleration`` ...), on the kernels of
  :mod:`~screwkit.motion._second_order`;
* :mod:`~screwkit.motion.trajectory`: time scalings (``cubic``, ``quintic``,
  ``trapezoidal``), joint, screw and Cartesian paths, slerp, via points, and a path of
  poses followed by IK (``follow_path``);
* :mod:`~screwkit.motion.differential_ik`: one step of joint rates for a wanted twist,
  by the (damped) pseudo-inverse or as a QP within the limits (``pseudo_inverse_step``,
  ``qp_step``).

:mod:`screwkit.redundancy` (planar redundancy resolution) builds on these.

Each module loads on first use of one of its names: the chains compute their
second-order terms with :mod:`~screwkit.motion._second_order`, which sits below them,
while the modules of the family take a chain, above them; loading those here would
close an import circle through the chains.
"""

from .. import _lazy

#: What loads on first use: each module of the family, with the names of ``sk.motion``
#: it defines.
LAZY = {
    "acceleration": (
        "space_jacobian_dot",
        "body_jacobian_dot",
        "geometric_jacobian_dot",
        "space_hessian",
        "body_hessian",
        "geometric_hessian",
        "space_acceleration",
        "body_acceleration",
        "geometric_acceleration",
    ),
    "trajectory": (
        "TimeScaling",
        "cubic",
        "quintic",
        "trapezoidal",
        "fastest_joint_scaling",
        "joint_path",
        "screw_path",
        "cartesian_path",
        "slerp",
        "via_points",
        "ViaPoints",
        "follow_path",
        "PathIK",
    ),
    "differential_ik": ("Step", "pseudo_inverse_step", "qp_step"),
    "_second_order": (),
}

__all__ = [name for names in LAZY.values() for name in names]


__getattr__, __dir__ = _lazy.attach(__name__, LAZY, globals())
