"""The statics chapter's worked numbers: the PUMA's torques printed in
notebooks/statics.ipynb against virtual work on the PUMA written out here (Corke's DH
table, tests/references.py, finite differences), and the wrench order as the library
reads it: tau = J_s^T applied to (f; m) with its halves swapped."""

import json
import re
from pathlib import Path

import numpy as np
import references

import screwkit as sk

ROOT = Path(__file__).resolve().parents[2]

#: The chapter's worked example: the configuration and the push (N).
Q = np.array([0.3, -0.6, 0.4, 0.2, 0.7, -0.1])
FORCE = np.array([10.0, 0.0, -20.0])


def printed(label):
    """The vector the chapter prints after ``label`` (stored outputs)."""
    cells = json.loads((ROOT / "notebooks" / "statics.ipynb").read_text())["cells"]
    text = "".join(
        "".join(out.get("text", ""))
        for cell in cells
        for out in cell.get("outputs", [])
        if out.get("output_type") == "stream"
    )
    match = re.search(re.escape(label) + r"\s*\[([^\]]*)\]", text)
    assert match, label
    return np.array([float(v) for v in match.group(1).split()])


def virtual_work_torques(q, f, h=1e-6):
    """tau_i = f . dp/dq_i, p the PUMA's tool point from the DH table written out."""
    table = references.PUMA_TABLE
    return np.array(
        [
            f
            @ (
                references.dh_fk(table, q + h * e)[:3, 3]
                - references.dh_fk(table, q - h * e)[:3, 3]
            )
            / (2 * h)
            for e in np.eye(6)
        ]
    )


def test_the_library_reads_a_wrench_force_first():
    puma = sk.robots.puma560()
    rng = np.random.default_rng(40)
    for _ in range(5):
        q = rng.uniform(-2, 2, 6)
        w = rng.normal(size=6)  # (f; m)
        J = puma.space_jacobian(q)
        tau = sk.statics.joint_torques(puma, q, wrench=w)
        np.testing.assert_allclose(tau, J.T @ np.r_[w[3:], w[:3]], atol=1e-12)
        # and the force-first reading is the physical one: a pure force f at the
        # origin of the base does the virtual work f . v(origin)
        f = w[:3]
        at_origin = sk.statics.joint_torques(puma, q, wrench=np.r_[f, 0, 0, 0])
        np.testing.assert_allclose(at_origin, J[3:].T @ f, atol=1e-12)


def test_the_chapters_worked_torques_are_the_virtual_work():
    puma = sk.robots.puma560()
    p_table = references.dh_fk(references.PUMA_TABLE, Q)[:3, 3]
    np.testing.assert_allclose(puma.fk(Q)[:3, 3], p_table, atol=1e-12)
    expected = virtual_work_torques(Q, FORCE)
    for label in ("tau, J_s^T Pi F_s (N m):", "tau, sk.statics (N m):"):
        np.testing.assert_allclose(printed(label), expected, atol=1e-4)
    np.testing.assert_allclose(
        printed("tau from the body frame (N m):"), expected, atol=1e-4
    )
    # the sentence the chapter corrects: J_s^T F without the swap is not the torques
    wrong = printed("J_s^T F_s, the swap forgotten:")
    assert np.abs(wrong - expected).max() > 1.0


def test_the_chapters_holding_torques_are_the_weight_lifted():
    expected = virtual_work_torques(Q, np.array([0.0, 0.0, 2.0 * 9.81]))
    np.testing.assert_allclose(printed("holds 2 kg (N m):"), expected, atol=1e-4)
    pushes = virtual_work_torques(Q, np.array([0.0, 0.0, -20.0]))
    np.testing.assert_allclose(printed("pushes down 20 N (N m):"), pushes, atol=1e-4)
