"""Every exercise's answer key (screwkit/answers/*.toml) against an independent
recomputation (tests/course/answer_references), and the chapters' stored answer boxes in
a browser.

Each key was derived by hand in its chapter; here it is recomputed another way and must
agree far inside its tolerance, pass ``sk.exercises.check`` and refuse a wrong answer.
"""

import json
import math
from pathlib import Path

import answer_references
import builders
import numpy as np
import pytest
from answer_references import REFERENCES, all_keys

from screwkit import exercises


def test_every_key_has_an_independent_reference():
    missing = sorted(set(all_keys()) - set(REFERENCES))
    assert missing == []


#: The units the chapters' keys are written in (exercises.py reads more).
UNITS_OF_KEYS = ("", "rad", "deg", "m", "mm", "m/s", "rad/s", "N", "N m", "W")
UNITS_OF_KEYS += ("m/rad", "m^2", "1/s", "s", "m/s^2", "N/m", "N m/rad")
#: a vector of mixed units (a twist) carries one per number, its unit text is ""


def test_every_reference_has_a_key():
    assert sorted(set(REFERENCES) - set(all_keys())) == []


@pytest.mark.parametrize("chapter, number", all_keys())
def test_key_agrees_with_its_reference(chapter, number):
    key = exercises.answer_key(chapter, number)
    expected = np.ravel(np.asarray(REFERENCES[chapter, number](), dtype=float))
    assert key["unit"] in UNITS_OF_KEYS
    assert key["hint"], "every exercise needs a hint shown when the answer is wrong"
    assert len(expected) == len(key["values"])
    np.testing.assert_allclose(
        key["values"], expected, rtol=0, atol=key["tolerance"] / 100
    )
    assert exercises.check(chapter, number, expected).correct
    text = ", ".join(f"{v:.6f}" for v in expected)
    assert exercises.check(chapter, number, text).correct, text


@pytest.mark.parametrize("chapter, number", all_keys())
def test_key_refuses_a_wrong_answer(chapter, number):
    key = exercises.answer_key(chapter, number)
    wrong = np.asarray(key["values"]) + 10 * key["tolerance"] + 0.37
    verdict = exercises.check(chapter, number, wrong)
    assert not verdict.correct
    assert verdict.message


def test_jacobians_4_the_other_root_is_singular_too():
    # folded, the wrist centre is also near the shoulder plane (a2 = d4): det J touches
    # zero there without changing sign, so test the smallest singular value instead.
    # It is the root the key's range (-180 deg to 0) leaves out: atan2(d4, -a3)
    folded = math.atan2(0.4318, -0.0203)
    bounds = exercises.answer_key("jacobians", 4)["range"]
    assert not bounds["low"] <= folded <= bounds["high"]
    J = builders.puma().geometric_jacobian(np.array([0.3, 0.5, folded, 0.2, 0.9, 0]))
    assert np.linalg.svd(J, compute_uv=False)[-1] < 1e-12


def test_the_keys_match_the_chapter_geometry():
    stewart = builders.stewart()
    leg = answer_references.parallel_kinematics.leg_1_at_home()
    assert np.allclose(stewart.ik(stewart.home()), np.linalg.norm(leg), atol=1e-12)
    assert np.isclose(
        stewart.jacobian(stewart.home())[0, 5], leg[2] / np.linalg.norm(leg)
    )


@pytest.mark.parametrize("chapter", ["rigid_motions", "puma_ik"])
def test_stored_chapter_boxes_answer_in_the_page(chapter, chromium):
    # the chapter's stored HTML outputs, in order, as the book shows them: the script is
    # inlined once, in the first box, and every box answers without a kernel
    path = Path(__file__).resolve().parents[2] / "notebooks" / f"{chapter}.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    boxes = [
        "".join(out["data"]["text/html"])
        for cell in cells
        for out in cell.get("outputs", [])
        if "sk-answer-box" in "".join(out.get("data", {}).get("text/html", ""))
    ]
    assert len(boxes) >= 2
    assert sum("window.screwkitExercises = {" in b for b in boxes) == 1
    page = chromium.new_page()
    errors = []
    page.on("pageerror", lambda error: errors.append(str(error)))
    page.set_content("<html><body>" + "".join(boxes) + "</body></html>")
    ids = page.eval_on_selector_all(".sk-answer-box", "d => d.map(e => e.id)")
    assert len(ids) == len(boxes)
    for box in ids:
        number = int(box.split("-")[-2])
        key = exercises.answer_key(chapter, number)
        right = ", ".join(repr(v) for v in key["values"])
        for text, correct in ((right, True), ("1e6", False)):
            page.fill(f"[id='{box}'] input", text)
            page.click(f"[id='{box}'] button")
            shown = page.inner_text(f"[id='{box}'] .sk-verdict")
            assert shown.startswith("✓" if correct else "✗"), (box, shown)
    assert errors == []
