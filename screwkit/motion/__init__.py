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

import importlib

#: The modules of the family, loaded on first use; the public ones give ``sk.motion``
#: the names of their ``__all__``.
LAZY = {
    "acceleration": (),
    "trajectory": (),
    "differential_ik": (),
    "_second_order": (),
}
PUBLIC = ("acceleration", "trajectory", "differential_ik")


def _modules():
    return [importlib.import_module(f".{name}", __name__) for name in PUBLIC]


def __getattr__(name):
    if name in LAZY:
        return importlib.import_module(f".{name}", __name__)
    if name == "__all__":  # every public name of the family
        return [n for module in _modules() for n in module.__all__]
    for module in _modules():
        if name in module.__all__:
            value = globals()[name] = getattr(module, name)  # then an attribute
            return value
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__():
    return sorted({*globals(), *LAZY, *__getattr__("__all__")})
