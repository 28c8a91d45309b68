"""Bad input to the general 6R inverse kinematics (screwkit.ik.general): one row per
case, the error type and the argument the message names."""

import functools

import numpy as np
from builders import planar, puma
from rows import keyword_rows, row

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


#: A 4 x 4 matrix that is no rigid transform (its rotation block scales y by 2).
NOT_RIGID = np.diag([1.0, 2.0, 1.0, 1.0])
#: What general_6r_ik says of a T of the wrong shape.
SHAPE = r"T must have shape \(4, 4\) or \(N, 4, 4\)"

#: general_6r_ik(chain(), t0()) with a bad chain: (case, chain, error, match).
BAD_CHAIN = [
    (
        "not-a-chain",
        lambda: "puma",
        TypeError,
        "chain must be a screwkit Chain",
    ),
    (
        "3R",
        lambda: planar(1.0, 1.0, 1.0),
        ValueError,
        r"chain must have 6 revolute joints \(6R\), got 3 joints RRR",
    ),
    ("prismatic", prismatic, ValueError, "got 6 joints PRRRRR"),
]
#: general_6r_ik(puma(), pose()) with a bad pose: (case, pose, error, match).
BAD_POSE = [
    ("not-rigid", lambda: NOT_RIGID, ValueError, r"T must .*rotation"),
    ("nan", lambda: np.full((4, 4), np.nan), ValueError, "T must be finite"),
    ("string", lambda: "pose", TypeError, "T must be"),
    (
        "batch-with-a-non-rigid-pose",
        lambda: np.stack([t0(), NOT_RIGID]),
        ValueError,
        "rotation block of T must be a rotation matrix",
    ),
    ("wrong-shape", lambda: np.eye(3), ValueError, SHAPE),
    ("batch-of-batches", lambda: np.zeros((2, 3, 4, 4)), ValueError, SHAPE),
    (
        "10^7-poses-broadcast",
        lambda: np.broadcast_to(t0(), (10**7, 4, 4)),
        ValueError,
        r"T must be a batch of at most 100,000 poses .* got 10,000,000",
    ),
    (
        "list-of-10^6-poses",
        lambda: [np.eye(4)] * 10**6,
        ValueError,
        r"T must be a batch of at most 100,000 poses",
    ),
]

ROWS = [
    *(
        row(
            f"general_6r_ik-{case}",
            lambda chain=chain, pose=pose: ik.general_6r_ik(chain(), pose()),
            error,
            name,
            match=match,
        )
        for case, chain, pose, error, name, match in [
            *((f"chain-{c}", ch, t0, e, "chain", m) for c, ch, e, m in BAD_CHAIN),
            *((f"T-{c}", puma, pose, e, "T", m) for c, pose, e, m in BAD_POSE),
        ]
    ),
    *keyword_rows(
        "analytic_ik-general-arm-{}",
        lambda **kw: ik.analytic_ik(general_arm(), t0(), **kw),
        [
            (
                "near-wrong-length",
                "near",
                [0.0] * 5,
                ValueError,
                "near must be a joint vector of 6 entries",
            ),
            ("within_limits-not-bool", "within_limits", 1.5, TypeError, None),
        ],
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
