"""Inverse kinematics: closed form for some 6-joint arms, numeric for any chain.

The family, one idea a module:

* :mod:`~screwkit.ik.subproblems`: the Paden–Kahan subproblems and their batched
  kernels (``sk.ik.subproblem1`` ... ``subproblem6``, ``Solutions``);
* :mod:`~screwkit.ik.newton`: numerical IK of any chain (``sk.ik.numeric_ik``,
  ``pose_error``, ``NumericIKResult``);
* :mod:`~screwkit.ik._closed_form`: what the closed-form engines share;
* the engines, each a structure solved from the chain's screws:
  :mod:`~screwkit.ik.spherical_wrist` (PUMA 560, Kawasaki CX210L),
  :mod:`~screwkit.ik.ur` (Universal Robots), :mod:`~screwkit.ik.stanford`, and
  :mod:`~screwkit.ik.decomposed` (any 6R with a spherical wrist or shoulder, or three
  parallel axes 2, 3, 4 or 3, 4, 5, by subproblems 5 and 6);
* :mod:`~screwkit.ik.dispatch`: picks the engine and labels the solutions
  (``sk.ik.analytic_ik``, ``analytic_ik_all``, ``configuration``, ``structure``,
  ``CONFIGURATIONS``, ``puma560_ik`` ...);
* :mod:`~screwkit.ik.general`: every solution of any 6R chain, by the Raghavan–Roth
  eigenvalue problem (``sk.ik.general_6r_ik``, ``GeneralIK``).

The subproblems and Newton load with the package: they sit below the chains
(``Chain.numeric_ik`` is Newton). The closed form loads on first use of one of its
names: its dispatcher takes the default PUMA from :mod:`screwkit.robots`, above the
chains, so loading it here would close an import circle through ``Chain.numeric_ik``.
"""

from .. import _lazy
from . import subproblems
from .newton import NumericIKResult, numeric_ik, pose_error
from .subproblems import *  # noqa: F403 (the Paden-Kahan subproblems, as sk.ik.*)

#: What loads on first use: each module of the family that is not loaded above, with
#: the names of ``sk.ik`` it defines (the closed form's are the dispatcher's).
LAZY = {
    "dispatch": (
        "CONFIGURATIONS",
        "IKSolution",
        "IKSolutions",
        "SINGULAR_TOL",
        "STRUCTURES",
        "analytic_ik",
        "analytic_ik_all",
        "configuration",
        "puma560_config",
        "puma560_ik",
        "puma560_ik_all",
        "structure",
    ),
    "general": ("GeneralIK", "general_6r_ik"),
    "_closed_form": (),
    "spherical_wrist": (),
    "ur": (),
    "stanford": (),
    "decomposed": (),
}

__all__ = [
    *LAZY["dispatch"],
    *LAZY["general"],
    "NumericIKResult",
    "numeric_ik",
    "pose_error",
    *subproblems.__all__,
]


__getattr__, __dir__ = _lazy.attach(__name__, LAZY, globals())
