"""Parallel manipulators in motion: legs' inverse kinematics, forward kinematics by
loop closure and every assembly mode, Jacobians from the legs' wrenches, singularity
types and workspaces.

The folder, one idea a module, bottom up:

- :mod:`~screwkit.parallel.legs`: the legs' IK, loop closure and joint screws;
- :mod:`~screwkit.parallel.numeric`: platform points of a batch, Newton on the closure;
- :mod:`~screwkit.parallel.search`: every assembly mode (the 3-RPR's sextic, and a
  multi-start search for the others);
- :mod:`~screwkit.parallel.proven`: every assembly mode with a proof of completeness
  (the Stewart-Gough platform by msolve, an optional dependency; the 3-RPR's exact
  sextic);
- :mod:`~screwkit.parallel.model`: :class:`ParallelManipulator` and its results;
- :mod:`~screwkit.parallel.catalogue`: the builders and their default geometry, and
  Dietmaier's published platform with 40 real assembly modes;
- :mod:`~screwkit.parallel.plotting`: drawings (matplotlib; loaded on first use, as
  ``sk.parallel.plotting`` or ``from screwkit.parallel.plotting import ...``).
"""

from .. import _lazy
from .catalogue import (
    DIETMAIER_BASE,
    DIETMAIER_PLATFORM,
    DIETMAIER_RHO,
    RPR_BASE,
    RPR_PLATFORM,
    RPR_SIX_MODES_RHO,
    STEWART_BASE,
    STEWART_PLATFORM,
    delta,
    planar_3rpr,
    planar_3rrr,
    stewart_gough,
    tripteron,
)
from .model import (
    MAX_FK_STARTS,
    MAX_WORKSPACE_POINTS,
    ParallelFK,
    ParallelIK,
    ParallelManipulator,
    Workspace,
)
from .proven import rpr_fk_proven, stewart_fk_proven
from .search import AssemblyModes, rpr_sextic

__all__ = [
    "ParallelManipulator",
    "ParallelIK",
    "ParallelFK",
    "Workspace",
    "AssemblyModes",
    "MAX_WORKSPACE_POINTS",
    "MAX_FK_STARTS",
    "stewart_gough",
    "planar_3rpr",
    "planar_3rrr",
    "delta",
    "tripteron",
    "rpr_sextic",
    "stewart_fk_proven",
    "rpr_fk_proven",
    "STEWART_BASE",
    "STEWART_PLATFORM",
    "RPR_BASE",
    "RPR_PLATFORM",
    "RPR_SIX_MODES_RHO",
    "DIETMAIER_BASE",
    "DIETMAIER_PLATFORM",
    "DIETMAIER_RHO",
]


# the drawings load matplotlib: imported on first use, as sk.plotting is
__getattr__ = _lazy.attach(__name__, {"plotting": ()}, globals())[0]
