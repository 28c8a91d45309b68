"""Bad input to the general 6R inverse kinematics (screwkit.ik.general): one row per
case, the error type and the argument the message names."""

import functools

import numpy as np
from builders import planar, puma
from rows import row

import screwkit as sk
from screwkit import ik


@functools.cache
def t0():
    return puma().fk(np.zeros(6))


@functools.cache
def prismatic():
    return sk.Chain([sk.Link.prismatic()] + list(puma().links[1:]))


@functools.cache
def general_arm():
    """A 6R of no decomposable class (random DH rows)."""
    return sk.Chain.from_table(
        [
            [0, 0.3, 0.2, 1.0],
            [0, 0.1, 0.5, -0.7],
            [0, 0.2, 0.4, 1.3],
            [0, 0.25, 0.1, 0.9],
            [0, 0.1, 0.3, -1.1],
            [0, 0.2, 0.1, 0.4],
        ]
    )


ROWS = [
    row(
        "general_6r_ik-chain-not-a-chain",
        lambda: ik.general_6r_ik("puma", t0()),
        TypeError,
        "chain",
        match="chain must be a screwkit Chain",
    ),
    row(
        "general_6r_ik-chain-3R",
        lambda: ik.general_6r_ik(planar(1.0, 1.0, 1.0), t0()),
        ValueError,
        "chain",
        match=r"chain must have 6 revolute joints \(6R\), got 3 joints RRR",
    ),
    row(
        "general_6r_ik-chain-prismatic",
        lambda: ik.general_6r_ik(prismatic(), t0()),
        ValueError,
        "chain",
        match="got 6 joints PRRRRR",
    ),
    row(
        "general_6r_ik-T-not-rigid",
        lambda: ik.general_6r_ik(puma(), np.diag([1.0, 2.0, 1.0, 1.0])),
        ValueError,
        "T",
        match=r"T must .*rotation",
    ),
    row(
        "general_6r_ik-T-nan",
        lambda: ik.general_6r_ik(puma(), np.full((4, 4), np.nan)),
        ValueError,
        "T",
        match="T must be finite",
    ),
    row(
        "general_6r_ik-T-string",
        lambda: ik.general_6r_ik(puma(), "pose"),
        TypeError,
        "T",
        match="T must be",
    ),
    row(
        "general_6r_ik-T-batch-with-a-non-rigid-pose",
        lambda: ik.general_6r_ik(
            puma(), np.stack([t0(), np.diag([1.0, 2.0, 1.0, 1.0])])
        ),
        ValueError,
        "T",
        match="rotation block of T must be a rotation matrix",
    ),
    row(
        "general_6r_ik-T-wrong-shape",
        lambda: ik.general_6r_ik(puma(), np.eye(3)),
        ValueError,
        "T",
        match=r"T must have shape \(4, 4\) or \(N, 4, 4\)",
    ),
    row(
        "general_6r_ik-T-batch-of-batches",
        lambda: ik.general_6r_ik(puma(), np.zeros((2, 3, 4, 4))),
        ValueError,
        "T",
        match=r"T must have shape \(4, 4\) or \(N, 4, 4\)",
    ),
    row(
        "general_6r_ik-T-10^7-poses-broadcast",
        lambda: ik.general_6r_ik(puma(), np.broadcast_to(t0(), (10**7, 4, 4))),
        ValueError,
        "T",
        match=r"T must be a batch of at most 100,000 poses .* got 10,000,000",
    ),
    row(
        "general_6r_ik-T-list-of-10^6-poses",
        lambda: ik.general_6r_ik(puma(), [np.eye(4)] * 10**6),
        ValueError,
        "T",
        match=r"T must be a batch of at most 100,000 poses",
    ),
    row(
        "analytic_ik-general-arm-near-wrong-length",
        lambda: ik.analytic_ik(general_arm(), t0(), near=[0.0] * 5),
        ValueError,
        "near",
        match="near must be a joint vector of 6 entries",
    ),
    row(
        "analytic_ik-general-arm-within_limits-not-bool",
        lambda: ik.analytic_ik(general_arm(), t0(), within_limits=1.5),
        TypeError,
        "within_limits",
    ),
    row(
        "analytic_ik-general-arm-T-10^8-poses-broadcast",
        lambda: ik.analytic_ik(general_arm(), np.broadcast_to(t0(), (10**8, 4, 4))),
        ValueError,
        "T",
        match=r"T must be a batch of at most 100,000 poses",
    ),
    row(
        "analytic_ik_all-general-arm",
        lambda: ik.analytic_ik_all(general_arm(), t0()),
        ValueError,
        "chain",
        match="chain must be an arm whose solutions are a fixed array of eight",
    ),
]
