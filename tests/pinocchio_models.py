"""Pinocchio's side of the reference tests, written once: where example-robot-data's
URDFs are, and Pinocchio's configuration vector for a chain's joint values.

Pinocchio and example-robot-data are reference packages, not the course's
(``tests/reference-requirements.txt``); CI sets SCREWKIT_REFERENCES=required, and then
a missing one fails instead of skipping.
"""

import glob
import os
import sys

import numpy as np
import pytest

#: CI sets SCREWKIT_REFERENCES=required: there a missing reference fails, never skips.
REQUIRED = os.environ.get("SCREWKIT_REFERENCES") == "required"
INSTALL = "pip install -r tests/reference-requirements.txt"


def robots_folder():
    """example-robot-data's robots/ folder (skipped, or failed in CI, without it)."""
    pattern = os.path.join(
        sys.prefix,
        "lib",
        "python*",
        "site-packages",
        "cmeel.prefix",
        "share",
        "example-robot-data",
        "robots",
    )
    found = glob.glob(pattern)
    if not found:
        message = f"example-robot-data is not installed: {INSTALL}"
        if REQUIRED:
            pytest.fail(message)
        pytest.skip(message)
    return found[0]


def pinocchio_q(pin, model, chain, q):
    """Pinocchio's configuration vector (neutral elsewhere) with the chain's joints,
    named as in the URDF, set to q (a continuous joint is its (cos, sin))."""
    x = pin.neutral(model)
    for name, value in zip(chain.joint_names, q):
        joint = model.joints[model.getJointId(name)]
        if joint.nq == 2:  # a continuous joint: (cos, sin)
            x[joint.idx_q : joint.idx_q + 2] = np.cos(value), np.sin(value)
        else:
            x[joint.idx_q] = value
    return x
