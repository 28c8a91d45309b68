"""Bad input of statics and contact: screwkit.statics and screwkit.contact.
One row per case (tests/bad_input/rows.py): the error type and the argument its sentence
names."""

import numpy as np
from builders import puma, rpr, stewart
from rows import row

from screwkit import contact as ct
from screwkit import statics as st

Q = np.zeros(6)
Q_OK = np.array([0.2, -0.5, 0.4, 0.3, 0.9, -0.2])
C2 = ([1.0, 0.0], [-1.0, 0.0])
PAIR = [ct.Contact([1.0, 0.0], [-1.0, 0.0]), ct.Contact([-1.0, 0.0], [1.0, 0.0])]

CASES = [
    # joint_torques
    row(
        "joint_torques-chain",
        lambda: st.joint_torques("puma", Q, [1, 0, 0]),
        TypeError,
        "chain",
    ),
    row(
        "joint_torques-q",
        lambda: st.joint_torques(puma(), Q[:5], [1, 0, 0]),
        ValueError,
        "q",
    ),
    row(
        "joint_torques-nothing",
        lambda: st.joint_torques(puma(), Q),
        ValueError,
        "force",
    ),
    row(
        "joint_torques-force-length",
        lambda: st.joint_torques(puma(), Q, [1, 0]),
        ValueError,
        "force",
    ),
    row(
        "joint_torques-force-nan",
        lambda: st.joint_torques(puma(), Q, [np.nan, 0, 0]),
        ValueError,
        "force",
    ),
    row(
        "joint_torques-moment-str",
        lambda: st.joint_torques(puma(), Q, moment="x"),
        TypeError,
        "moment",
    ),
    row(
        "joint_torques-point",
        lambda: st.joint_torques(puma(), Q, [1, 0, 0], point="tip"),
        ValueError,
        "point",
    ),
    row(
        "joint_torques-frame",
        lambda: st.joint_torques(puma(), Q, [1, 0, 0], frame="world"),
        ValueError,
        "frame",
    ),
    row(
        "joint_torques-wrench-length",
        lambda: st.joint_torques(puma(), Q, wrench=[1, 2, 3, 4, 5]),
        ValueError,
        "wrench",
        match=r"6-vector",
    ),
    row(
        "joint_torques-wrench-and-force",
        lambda: st.joint_torques(puma(), Q, [1, 0, 0], wrench=np.zeros(6)),
        ValueError,
        "wrench",
    ),
    # gravity_torques
    row(
        "gravity_torques-masses",
        lambda: st.gravity_torques(puma(), Q, 3.0),
        TypeError,
        "masses",
    ),
    row(
        "gravity_torques-link",
        lambda: st.gravity_torques(puma(), Q, [(7, 1.0, [0, 0, 0])]),
        ValueError,
        "masses",
    ),
    row(
        "gravity_torques-mass",
        lambda: st.gravity_torques(puma(), Q, [(2, -1.0, [0, 0, 0])]),
        ValueError,
        "masses",
    ),
    row(
        "gravity_torques-g",
        lambda: st.gravity_torques(puma(), Q, [(2, 1.0, [0, 0, 0])], g=[0, -9.8]),
        ValueError,
        "g",
    ),
    # swap, wrench_at
    row("swap-length", lambda: st.swap([1, 2, 3]), ValueError, "vector"),
    row(
        "wrench_at-nan",
        lambda: st.wrench_at([np.nan, 0, 0, 0, 0, 0], np.eye(4)),
        ValueError,
        "wrench",
    ),
    row("wrench_at-T", lambda: st.wrench_at(np.zeros(6), np.eye(3)), ValueError, "T"),
    # stiffness, compliance, eigenscrews, legs, transmission
    row(
        "stiffness_at_tool-K_q",
        lambda: st.stiffness_at_tool(puma(), Q_OK, [1.0] * 5),
        ValueError,
        "K_q",
    ),
    row(
        "stiffness_at_tool-K_q-negative",
        lambda: st.stiffness_at_tool(puma(), Q_OK, [-1.0] * 6),
        ValueError,
        "K_q",
    ),
    row(
        "stiffness_at_tool-singular",
        lambda: st.stiffness_at_tool(puma(), Q, [1.0] * 6),
        ValueError,
        "q",
        match="rank",
    ),
    row(
        "compliance_at_tool-frame",
        lambda: st.compliance_at_tool(puma(), Q, [1.0] * 6, frame="tool"),
        ValueError,
        "frame",
    ),
    row(
        "compliance_at_tool-chain",
        lambda: st.compliance_at_tool(None, Q, [1.0] * 6),
        TypeError,
        "chain",
    ),
    row("eigenscrews-shape", lambda: st.eigenscrews(np.eye(5)), ValueError, "K"),
    row(
        "eigenscrews-complex",
        lambda: st.eigenscrews(_rotation_block()),
        ValueError,
        "K",
    ),
    row(
        "leg_stiffness-pm",
        lambda: st.leg_stiffness(puma(), np.eye(4), [1.0] * 6),
        TypeError,
        "pm",
    ),
    row(
        "leg_stiffness-planar",
        lambda: st.leg_stiffness(rpr(), rpr().home(), [1.0] * 3),
        ValueError,
        "pm",
    ),
    row(
        "leg_stiffness-k",
        lambda: st.leg_stiffness(stewart(), stewart().home(), [1.0] * 5),
        ValueError,
        "k",
    ),
    row(
        "transmission_index-pm",
        lambda: st.transmission_index("3rpr", np.eye(4)),
        TypeError,
        "pm",
    ),
    # contact
    row(
        "Contact-zero-normal", lambda: ct.Contact([0, 0], [0, 0]), ValueError, "normal"
    ),
    row(
        "Contact-negative-mu",
        lambda: ct.Contact(*C2, kind="friction", mu=-0.1),
        ValueError,
        "mu",
    ),
    row("Contact-no-mu", lambda: ct.Contact(*C2, kind="friction"), ValueError, "mu"),
    row("Contact-nan", lambda: ct.Contact([np.nan, 0], [1, 0]), ValueError, "point"),
    row(
        "Contact-point-length",
        lambda: ct.Contact([0, 0, 0, 0], [1, 0, 0, 0]),
        ValueError,
        "point",
    ),
    row(
        "Contact-normal-shape",
        lambda: ct.Contact([0, 0], [1, 0, 0]),
        ValueError,
        "normal",
    ),
    row("Contact-kind", lambda: ct.Contact(*C2, kind="sticky"), ValueError, "kind"),
    row(
        "Contact-planar-soft",
        lambda: ct.Contact(*C2, kind="soft_finger", mu=0.3, torsion=0.1),
        ValueError,
        "kind",
    ),
    row(
        "Contact-soft-no-torsion",
        lambda: ct.Contact([0, 0, 1], [0, 0, -1], kind="soft_finger", mu=0.3),
        ValueError,
        "torsion",
    ),
    row("form_closure-one", lambda: ct.form_closure(PAIR[:1]), ValueError, "contacts"),
    row(
        "form_closure-not-a-list",
        lambda: ct.form_closure(PAIR[0]),
        TypeError,
        "contacts",
    ),
    row(
        "form_closure-mixed",
        lambda: ct.form_closure([PAIR[0], ct.Contact([0, 0, 1], [0, 0, -1])]),
        ValueError,
        "contacts",
    ),
    row(
        "force_closure-facets",
        lambda: ct.force_closure(PAIR, facets=2),
        ValueError,
        "facets",
    ),
    row(
        "force_closure-entry",
        lambda: ct.force_closure([PAIR[0], (0, 1)]),
        TypeError,
        "contacts",
    ),
    row(
        "grasp_matrix-frame",
        lambda: ct.grasp_matrix(PAIR, frame=np.eye(4)),
        ValueError,
        "frame",
    ),
    row(
        "contact_wrenches-one",
        lambda: ct.contact_wrenches(PAIR[:1]),
        ValueError,
        "contacts",
    ),
]


def _rotation_block():
    """A 6 x 6 matrix with complex eigenvalues (a turn in its first two
    coordinates)."""
    M = np.eye(6)
    M[0, 1], M[1, 0] = -1.0, 1.0
    return M


ROWS = CASES
