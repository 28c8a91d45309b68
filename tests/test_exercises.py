"""The exercise engine (screwkit.exercises): its checking rules (forms, units, signs,
text input) on keys written for the test, and the page's JavaScript, which must give the
same verdict as ``sk.exercises.check`` on the same text. The chapters' own keys are
recomputed in tests/course/test_answer_keys.py."""

import json
import math
import shutil
import subprocess

import numpy as np
import pytest
import sympy as sp
from browser import CHROMIUM, FLAGS

from screwkit import exercises

# ---- the rules, on keys written for the test ---------------------------------------

FAKE = {
    "1": {"answer": "pi/3", "unit": "rad", "tolerance": 1e-3, "hint": "h1"},
    "2": {"answer": "60", "unit": "deg", "tolerance": 0.1, "hint": "h2"},
    "3": {"answer": "0.15", "unit": "m", "tolerance": 1e-4, "hint": "h3"},
    "4": {
        "answer": ["0", "0", "1"],
        "unit": "",
        "tolerance": 1e-3,
        "forms": ["either sign"],
        "hint": "h4",
    },
    "5": {
        "answer": "-pi/2",
        "unit": "rad",
        "tolerance": 1e-3,
        "forms": ["modulo 2pi"],
        "hint": "h5",
    },
    "6": {
        "answer": ["0.1", "0.7", "-2.1"],
        "unit": "rad",
        "tolerance": 1e-3,
        "forms": ["any order", "modulo 2pi"],
        "hint": "h6",
    },
    "7": {"answer": "12", "unit": "mm", "tolerance": 0.01, "rtol": 0.01, "hint": "h7"},
    "9": {"answer": "0", "unit": "rad", "tolerance": 1e-3, "hint": "h9"},
    "8": {
        "answer": [["1", "2"], ["3", "4"]],
        "unit": "",
        "tolerance": 1e-6,
        "alternatives": [[["4", "3"], ["2", "1"]]],
        "hint": "h8",
    },
}


@pytest.fixture
def fake(monkeypatch):
    original = exercises._key_file
    monkeypatch.setattr(
        exercises, "_key_file", lambda c: FAKE if c == "fake" else original(c)
    )
    return lambda number, answer: exercises.check("fake", number, answer)


CASES = [
    # (exercise, answer, correct, a phrase the message must contain)
    (1, "pi/3", True, "within ±0.001 rad"),
    (1, "1.0472", True, ""),
    (1, "60 deg", True, ""),
    (1, "60°", True, ""),
    (1, 60, False, "looks like degrees, radians expected"),
    (1, "-pi/3", False, "sign is flipped"),
    (1, "pi/4", False, "h1"),
    (1, "pi/3, 0", False, "expected one number, got 2"),
    (1, "12 mm", False, "units typed are length"),
    (2, 60, True, ""),
    (2, "pi/3 rad", True, ""),
    (2, math.pi / 3, False, "looks like radians, degrees expected"),
    (3, 150, False, "looks like millimetres, metres expected"),
    (3, "150 mm", True, ""),
    (3, "15 cm", True, ""),
    (4, [0, 0, -1], True, ""),
    (4, "0, 0, 1", True, ""),
    (4, "[0, 0, 1.0005]", True, ""),
    (4, "0, 1, 0", False, "wrong order"),
    (4, "0, 0", False, "expected 3 numbers, got 2"),
    (5, "3pi/2", True, ""),
    (5, "-pi/2 + 4pi", True, ""),
    (5, "270 deg", True, ""),
    (5, "pi/2", False, "sign is flipped"),
    (6, "-2.1, 0.1, 0.7", True, ""),
    (6, [0.7, 0.1, -2.1 + 2 * math.pi], True, ""),
    (6, "0.1, 0.7", False, "expected 3 numbers"),
    (7, 12.1, True, ""),
    (7, 12.5, False, "h7"),
    (7, 0.012, False, "looks like metres, millimetres expected"),
    (8, np.array([[1, 2], [3, 4]]), True, ""),
    (8, sp.Matrix([[4, 3], [2, 1]]), True, ""),
    (8, "1, 2, 3, 4", True, ""),
    (8, "1, -2, 3, 4", False, "some signs are wrong"),
    (9, "0.05", False, "h9"),  # no "looks like degrees" for a zero answer
    (9, "0.0005", True, ""),
    # whitespace separates numbers, as NumPy prints arrays; a glued product is a product
    (4, "[ 0.   0.  -1.]", True, ""),
    (4, "0 0 1", True, ""),
    (8, "[[1. 2.]\n [3. 4.]]", True, ""),
    (8, "1 2 3 4", True, ""),
    (6, "0.1 0.7 -2.1", True, ""),
    (6, "0.1 0.7 - 2.1", False, "expected 3 numbers, got 2"),
    (1, "2pi/6", True, ""),
    (1, "2 pi/6", False, "expected one number, got 2"),
    (5, "-pi/2", True, ""),
    (5, "- pi/2", True, ""),
]


@pytest.mark.parametrize("number, answer, correct, phrase", CASES)
def test_rules(fake, number, answer, correct, phrase):
    verdict = fake(number, answer)
    assert verdict.correct is correct, verdict.message
    assert phrase.lower() in verdict.message.lower()
    assert ("✓" in repr(verdict)) is correct
    assert 'role="status"' in verdict._repr_html_()


TEXTS = [
    "",
    "   ",
    "hello",
    "import os",
    "__import__('os').system('ls')",
    "1/0",
    "sqrt(-1)",
    "pi/",
    "(1",
    "1)",
    "1,,2",
    "[1, 2",
    "2**9999",
    "9" * 400,
    "(" * 3000 + "1" + ")" * 3000,
    "atan2(1)",
    "nan",
    "inf",
    "1 + ",
    "1e",
    "π/3 rad rad",
    "😀",
    "1; 2",
    "—1",
]


@pytest.mark.parametrize("text", TEXTS)
def test_text_input_never_crashes(fake, text):
    verdict = fake(1, text)
    assert verdict.correct is False
    assert verdict.message


@pytest.mark.parametrize(
    "answer",
    [None, True, 1j, object(), {"a": 1}, sp.Symbol("x"), [[1, 2], [3]], float("nan")],
)
def test_odd_python_values_never_crash(fake, answer):
    verdict = fake(1, answer)
    assert verdict.correct is False and "Could not read" in verdict.message


def test_parser_reads_the_usual_forms():
    values, units = exercises.parse_answer("2pi/3, sqrt(2)/2, 90 deg, -1.5e-3, 2^3")
    np.testing.assert_allclose(
        values, [2 * math.pi / 3, math.sqrt(2) / 2, math.pi / 2, -1.5e-3, 8]
    )
    assert units == [None, None, "angle", None, None]


@pytest.mark.parametrize(
    "chapter, number, error",
    [
        ("no_such_chapter", 1, ValueError),
        ("../etc", 1, ValueError),
        (3, 1, ValueError),
        ("rigid_motions", 99, ValueError),
        ("rigid_motions", "2", TypeError),
    ],
)
def test_bad_exercise_is_refused_with_a_sentence(chapter, number, error):
    with pytest.raises(error, match="chapter|number"):
        exercises.check(chapter, number, 1)


def test_answer_box_html_is_accessible_and_carries_the_script_once():
    first = exercises.answer_box("rigid_motions", 5, script=True)
    second = exercises.answer_box("rigid_motions", 5, script=False)
    page = first._repr_html_()
    assert "<label for=" in page and 'aria-live="polite"' in page
    assert "screwkitExercises" in page and "exercises.js" not in repr(first)
    assert exercises.exercises_script() in page
    assert exercises.exercises_script() not in second._repr_html_()
    assert first.id != second.id


# ---- the page's JavaScript gives the same verdicts ---------------------------------

JS_INPUTS = [(n, a) for n, a, _, _ in CASES if isinstance(a, (str, int, float))]
JS_INPUTS += [(1, t) for t in TEXTS if len(t) < 100]


def python_verdicts(inputs):
    out = []
    for number, answer in inputs:
        verdict = exercises.check("fake", number, str(answer))
        out.append([verdict.correct, verdict.message])
    return out


def fake_keys():
    keys = {}
    original = exercises._key_file
    exercises._key_file = lambda c: FAKE if c == "fake" else original(c)
    try:
        for number in FAKE:
            keys[number] = exercises.answer_key("fake", int(number))
    finally:
        exercises._key_file = original
    return keys


NODE = shutil.which("node")


@pytest.mark.skipif(NODE is None, reason="needs Node.js")
def test_javascript_verdicts_equal_python_ones(fake):
    keys = fake_keys()
    inputs = [(n, str(a)) for n, a in JS_INPUTS]
    program = (
        "global.window = {}; global.document = {querySelectorAll: () => []};\n"
        + exercises.exercises_script()
        + f"\nconst keys = {json.dumps(keys)};\nconst inputs = {json.dumps(inputs)};\n"
        "const out = inputs.map(([n, t]) => {\n"
        "  const v = window.screwkitExercises.verdict(t, keys[String(n)]);\n"
        "  return [v.correct, v.message]; });\n"
        "console.log(JSON.stringify(out));\n"
    )
    result = subprocess.run(
        [NODE, "-e", program], capture_output=True, text=True, timeout=60, check=True
    )
    page = json.loads(result.stdout)
    python = python_verdicts(inputs)
    assert [p[0] for p in page] == [p[0] for p in python]
    for (n, text), got, want in zip(inputs, page, python):
        if not want[1].startswith("Could not read"):  # parse errors are worded apart
            assert got[1] == want[1], (n, text)


@pytest.mark.skipif(CHROMIUM is None, reason="needs Chromium")
def test_answer_boxes_answer_in_the_browser(fake):
    sync_api = pytest.importorskip("playwright.sync_api")
    boxes = [
        exercises.answer_box("fake", 1, script=True),
        exercises.answer_box("fake", 4, script=False),
        exercises.answer_box("rigid_motions", 5, script=False),
    ]
    content = (
        "<html><body>" + "".join(b._repr_html_() for b in boxes) + "</body></html>"
    )
    trials = [
        (0, "pi/3", True),
        (0, "60", False),
        (1, "0, 0, -1", True),
        (1, "hello", False),
        (2, "120 deg", True),
        (2, "2pi", False),
    ]
    with sync_api.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        try:
            page = browser.new_page()
            errors = []
            page.on("pageerror", lambda error: errors.append(str(error)))
            page.set_content(content)
            for index, text, correct in trials:
                box = f"#{boxes[index].id}"
                page.fill(f"{box} input", text)
                page.click(f"{box} button")
                shown = page.inner_text(f"{box} .sk-verdict")
                assert shown.startswith("✓ Right" if correct else "✗ Not yet"), shown
                expected = exercises.check(
                    "fake" if index < 2 else "rigid_motions", [1, 4, 5][index], text
                ).message
                if not expected.startswith("Could not read"):
                    assert expected in shown
            page.fill(f"#{boxes[0].id} input", "60 deg")
            page.press(f"#{boxes[0].id} input", "Enter")
            assert page.inner_text(f"#{boxes[0].id} .sk-verdict").startswith("✓")
            assert errors == []
        finally:
            browser.close()
