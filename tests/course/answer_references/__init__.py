"""Independent recomputations of every exercise's answer key, one module per group of
chapters; importing the package registers them all in ``REFERENCES``."""

from . import (
    arm_bank,
    bank_jacobians_workspace_redundancy,
    configuration_space,
    first_chapters,
    later_chapters,
    lines,
    mobility,
    motion_in_time,
    parallel_kinematics,
    statics,
)
from .registry import REFERENCES, all_keys, key, value

__all__ = [
    "REFERENCES",
    "all_keys",
    "arm_bank",
    "bank_jacobians_workspace_redundancy",
    "configuration_space",
    "first_chapters",
    "key",
    "later_chapters",
    "lines",
    "mobility",
    "motion_in_time",
    "parallel_kinematics",
    "statics",
    "value",
]
