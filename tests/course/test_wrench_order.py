"""One wrench order in the library, the notation page and the chapters.

The order is read from screwkit (the coordinates of a pure force built from its line),
the statics tau = J_s^T Pi F that the notation page states is checked against the
virtual work of the PUMA 560 by finite differences of its forward kinematics, and the
worked tau = J^T F stored in the Jacobian chapter's notebook is checked against it.
"""

import json
import re
from pathlib import Path

import numpy as np

import screwkit as sk

ROOT = Path(__file__).resolve().parents[2]
PI = np.block([[np.zeros((3, 3)), np.eye(3)], [np.eye(3), np.zeros((3, 3))]])


def library_order():
    """'(f; m)' or '(m; f)', read from the coordinates of a pure force in screwkit."""
    force, point = np.array([0.0, 0.0, 2.0]), np.array([1.0, 0.0, 0.0])
    vector = np.array(sk.Wrench.from_axis(force, point, 0).vector, dtype=float).ravel()
    moment = np.cross(point, force)  # about the origin
    if np.allclose(vector, np.r_[force, moment]):
        return "(f; m)"
    assert np.allclose(vector, np.r_[moment, force]), vector
    return "(m; f)"


def virtual_work_torques(robot, q, force, h=1e-6):
    """tau_i = f . dp/dq_i: the torques that make the tool push with `force` at its
    point (no moment), by central differences of the forward kinematics."""
    tau = np.zeros(len(q))
    for i in range(len(q)):
        step = np.zeros(len(q))
        step[i] = h
        dp = (robot.fk(q + step)[:3, 3] - robot.fk(q - step)[:3, 3]) / (2 * h)
        tau[i] = force @ dp
    return tau


def test_the_library_orders_a_wrench_force_first():
    assert library_order() == "(f; m)"


def test_the_notation_page_states_the_librarys_order_and_its_statics():
    page = (ROOT / "book" / "notation.md").read_text(encoding="utf-8")
    assert library_order() == "(f; m)"
    assert r"\mathcal F = (f; m)" in page
    assert "**force first**" in page
    assert r"\tau = J_s^\mathsf{T}\,\Pi\,\mathcal F" in page
    # Modern Robotics' order is stated as the other one, with its own formula
    assert "$(m; f)$" in page and r"$\tau = J_s^\mathsf{T}\mathcal F$" in page
    assert "[angular; linear]" not in page


def test_the_statics_of_the_notation_page_is_the_virtual_work():
    puma = sk.robots.puma560()
    q = np.radians([15.0, -30.0, 20.0, 40.0, 50.0, -60.0])
    force = np.array([3.0, -2.0, -50.0])
    p = puma.fk(q)[:3, 3]
    F = np.array(sk.Wrench.from_axis(force, p, 0).vector, dtype=float).ravel()
    expected = virtual_work_torques(puma, q, force)
    Js = puma.space_jacobian(q)
    assert np.allclose(Js.T @ PI @ F, expected, atol=1e-6)
    # without the swap the formula is wrong in this order
    assert not np.allclose(Js.T @ F, expected, atol=1e-2)


def test_the_jacobian_chapters_worked_statics_is_right():
    notebook = json.loads(
        (ROOT / "notebooks" / "jacobians.ipynb").read_text(encoding="utf-8")
    )
    (cell,) = [
        cell
        for cell in notebook["cells"]
        if "wrench = np.array" in "".join(cell["source"])
    ]
    text = "".join("".join(out.get("text", "")) for out in cell.get("outputs", []))
    printed = re.search(r"tau = J\^T F \(N m\):\n\[([^\]]*)\]", text).group(1)
    tau = np.array(printed.split(), dtype=float)
    puma = sk.robots.puma560()
    q = np.asarray(puma.configurations["nominal"], dtype=float)
    expected = virtual_work_torques(puma, q, np.array([0.0, 0.0, -50.0]))
    assert np.allclose(tau, expected, atol=2e-3)  # printed to 3 decimals
    assert "J_s^T Pi F_s = J^T F: True" in text
    assert "(Modern Robotics' formula, for its (m; f) order) = J^T F: False" in text
