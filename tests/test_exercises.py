"""The exercise engine (screwkit.exercises): its checking rules (forms, units, signs,
text input) on keys written for the test, and the page's JavaScript, which must give the
same verdict as ``sk.exercises.check`` on the same text. The chapters' own keys are
recomputed in tests/course/test_answer_keys.py."""

import html
import json
import math
import re

import numpy as np
import pytest
import sympy as sp
from node_verdicts import NODE, node_verdicts

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
    # units of mechanics, combinations and ranges (the statics answers need them)
    "10": {"answer": "-5", "unit": "N m", "tolerance": 1e-3, "hint": "h10"},
    "11": {"answer": "4.05", "unit": "N", "tolerance": 1e-2, "hint": "h11"},
    "12": {"answer": "10", "unit": "W", "tolerance": 1e-3, "hint": "h12"},
    "13": {"answer": "0.5", "unit": "m/rad", "tolerance": 1e-3, "hint": "h13"},
    "14": {
        "answer": "atan2(-0.4318, 0.0203)",
        "unit": "rad",
        "tolerance": 1e-3,
        "range": ["-180 deg", "0"],
        "hint": "h14",
    },
    "15": {"answer": "200", "unit": "1/s", "tolerance": 0.5, "hint": "h15"},
    "16": {"answer": "sqrt(3)", "unit": "m^2", "tolerance": 1e-3, "hint": "h16"},
    "17": {"answer": "0.25", "unit": "m/s", "tolerance": 1e-3, "hint": "h17"},
    "18": {"answer": "2", "unit": "rad/s", "tolerance": 1e-3, "hint": "h18"},
    "19": {"answer": ["0.1", "0.2"], "unit": "m", "tolerance": 1e-3, "hint": "h19"},
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
    (1, "12 mm", False, "expected an angle (rad), found a length (mm)"),
    (2, 60, True, ""),
    (2, "pi/3 rad", True, ""),
    # radians in a box in degrees are right: pi/3 is 60 deg
    (2, math.pi / 3, True, "read as radians"),
    (2, "2pi/3", False, "not within"),
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
    (1, "2 pi/6", True, ""),  # a number times pi, spaced
    (1, "pi/6 pi/6", False, "expected one number, got 2"),
    (5, "-pi/2", True, ""),
    (5, "- pi/2", True, ""),
    # a torque in every spelling, converted; a unit of another dimension named as such
    (10, "-5", True, "within ±0.001 N m"),
    (10, "-5 N m", True, ""),
    (10, "-5 Nm", True, ""),
    (10, "-5 N*m", True, ""),
    (10, "-5 N·m", True, ""),
    (10, "-5 N⋅m", True, ""),
    (10, "-5000 N mm", True, ""),
    (10, "-500 N cm", True, ""),
    (10, "-5 N", False, "expected a torque (N m), found a force (N)"),
    (10, "-5 W", False, "expected a torque (N m), found a power (W)"),
    (10, "-5 m", False, "expected a torque (N m), found a length (m)"),
    (10, "5 N m", False, "sign is flipped"),
    (10, "-5,0 N m", False, "use a decimal point: -5.0 N m"),
    (11, "4.05 N", True, ""),
    (11, "4.05", True, ""),
    (11, "4,05", False, "expected one number, got 2. use a decimal point: 4.05."),
    (11, "4,05 N", False, "use a decimal point: 4.05 N"),
    (11, "4.05 kg m/s^2", True, ""),
    (11, "4.05 N m", False, "expected a force (N), found a torque (N m)"),
    (11, "4.05 kg", False, "expected a force (N), found a mass (kg)"),
    (12, "10 W", True, ""),
    (12, "10 N m/s", True, ""),
    (12, "10 N m rad/s", True, ""),  # torque times angular speed: the radian is 1
    (12, "10 N m", False, "expected a power (W), found a torque (N m)"),
    (12, "10 N/s", False, "expected a power (W), found a quantity (N/s)"),
    (13, "0.5 m/rad", True, "within ±0.001 m/rad"),
    (13, "0.5", True, ""),
    (13, "500 mm/rad", True, ""),
    (13, "0.5 m", True, ""),  # a pitch in m per radian or in m: the radian is 1
    (13, "0.5 rad", False, "expected a pitch (m/rad), found an angle (rad)"),
    (13, "0.5 m/s", False, "expected a pitch (m/rad), found a speed (m/s)"),
    # a range: the other root, 180 degrees away, is refused and the range named
    (14, "-87.31 deg", True, ""),
    (14, "atan2(-0.4318, 0.0203)", True, ""),
    (14, "92.69 deg", False, "outside the range asked for, between -180 deg and 0"),
    (14, "272.69 deg", False, "outside the range asked for"),
    (14, "-87.31", False, "looks like degrees, radians expected"),
    (14, "87.31 deg", False, "sign is flipped"),
    (14, "-1 rad", False, "not within ±0.001 rad"),
    (15, "200", True, "within ±0.5 1/s"),
    (15, "200/s", True, ""),
    (15, "200 1/s", True, ""),  # "1/s" after a space is the unit
    (15, "200 1", False, "expected one number, got 2"),
    (15, "200 s^-1", True, ""),
    (15, "200 rad/s", True, ""),
    (15, "200 s", False, "expected a rate (1/s), found a time (s)"),
    (15, "200 deg", False, "expected a rate (1/s), found an angle (deg)"),
    (16, "sqrt(3) m^2", True, ""),
    (16, "sqrt(3) m²", True, ""),
    (16, "sqrt(3) m**2", True, ""),
    (16, "17320.5 cm^2", True, ""),
    (16, "sqrt(3) m", False, "expected an area (m^2), found a length (m)"),
    (17, "0.25 m/s", True, ""),
    (17, "250 mm/s", True, ""),
    (17, "25 cm/s", True, ""),
    (17, "0.25 m/s^2", False, "expected a speed (m/s), found an acceleration (m/s^2)"),
    (17, "0.25 rad/s", False, "expected a speed (m/s), found an angular speed (rad/s)"),
    (18, "2 rad/s", True, ""),
    (18, "114.592 deg/s", True, ""),
    (18, "2 m/s", False, "expected an angular speed (rad/s), found a speed (m/s)"),
    (18, "2 rad", False, "expected an angular speed (rad/s), found an angle (rad)"),
    (19, "0.1 m, 20 cm", True, ""),
    (19, "100 mm 0.2", True, ""),
    (19, "0.1 m, 0.2 s", False, "expected a length (m), found a time (s)"),
    (
        19,
        "0,1, 0,2",
        False,
        "expected 2 numbers, got 4. use a decimal point: 0.1, 0.2.",
    ),
    (4, "1 N, 0, 0", False, "expected a pure number (no unit), found a force (N)"),
    (2, "60 N m", False, "expected an angle (deg), found a torque (N m)"),
    (1, "60 rad/s", False, "expected an angle (rad), found an angular speed (rad/s)"),
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


UNITS_OF_KEYS = ("", "rad", "deg", "m", "mm", "m/s", "rad/s", "N", "N m", "W")
UNITS_OF_KEYS += ("m/rad", "m^2", "1/s", "s", "m/s^2")


def test_parser_reads_units_and_their_combinations():
    values, units = exercises.parse_answer("-5 N m, 4.05 N, 10 W, 0.5 m/rad, 2 rad/s")
    np.testing.assert_allclose(values, [-5, 4.05, 10, 0.5, 2])
    assert units == ["torque", "force", "power", "pitch", "angular speed"]
    values, units = exercises.parse_answer("5 N mm, 30 cm/s, 3 m^2, 200/s, 90 deg/s")
    np.testing.assert_allclose(values, [5e-3, 0.3, 3, 200, math.pi / 2])
    assert units == ["torque", "speed", "area", "rate", "angular speed"]


@pytest.mark.parametrize(
    "text, reason",
    [("1 m^x", "power must be an integer"), ("1 m^1.5", "power must be an integer")],
)
def test_a_unit_power_must_be_an_integer(text, reason):
    with pytest.raises(ValueError, match=reason):
        exercises.parse_answer(text)


@pytest.mark.parametrize(
    "entry, reason",
    [
        ({"unit": "furlong"}, "unit of fake exercise 1 must be a unit"),
        ({"unit": "2 m"}, "unit of fake exercise 1 must be a unit"),
        ({"range": ["0"]}, "range of fake exercise 1 must be two bounds"),
        ({"range": ["1 N", "2"]}, "two numbers in its unit"),
        ({"range": ["abc", "2"]}, "two numbers in its unit"),
        ({"range": ["1, 2", "3"]}, "two numbers in its unit"),
        ({"range": ["0", "-1"]}, "low < high"),
    ],
)
def test_a_bad_key_is_refused_with_a_sentence(monkeypatch, entry, reason):
    bad = {"1": {"answer": "1", "unit": "rad", "tolerance": 0.1, "hint": "h"} | entry}
    monkeypatch.setattr(exercises, "_key_file", lambda chapter: bad)
    with pytest.raises(ValueError, match=reason):
        exercises.answer_key("fake", 1)


def test_keys_with_a_quantity_state_their_unit_and_range():
    # torque, force and power boxes say their unit; the roots asked "between -180 deg
    # and 0" (or in the swept range) are boxes with that range, and only that root
    stated = {
        ("jacobians", 5): "N m",
        ("jacobians", 6): "N",
        ("screws", 4): "m/rad",
        ("screws", 6): "W",
        ("redundancy", 5): "m^2",
        ("redundancy", 7): "1/s",
    }
    for (chapter, number), unit in stated.items():
        try:
            key = exercises.answer_key(chapter, number)
        except exercises.AssessedError:
            # an installed screwkit holds no assessed key (jacobians 6): the teacher's
            assert exercises.is_assessed(chapter, number)
            continue
        assert key["unit"] == unit
        label = exercises.answer_box(chapter, number, script=False)._repr_html_()
        assert f"your answer ({html.escape(unit)}):" in label
        assert "no unit" not in label
    ranged = {
        ("jacobians", 4): (-math.pi, 0),
        ("kawasaki_workspace", 3): (math.pi / 6, math.pi),
        ("kawasaki_workspace", 5): (-math.pi, 0),
        ("kawasaki_workspace", 8): (-math.pi, 0),
    }
    for (chapter, number), (low, high) in ranged.items():
        try:
            key = exercises.answer_key(chapter, number)
        except exercises.AssessedError:  # kawasaki_workspace 8, as above
            assert exercises.is_assessed(chapter, number)
            continue
        assert key["range"]["low"] == pytest.approx(low)
        assert key["range"]["high"] == pytest.approx(high)
        label = exercises.answer_box(chapter, number, script=False)._repr_html_()
        assert f"(rad, {key['range']['text']})" in label
        # the other root of each equation is 180 degrees from the key's (jacobians 4,
        # kawasaki 5 and 8) or outside the swept range (kawasaki 3: 240.4 deg)
        other = key["values"][0] + math.pi
        verdict = exercises.check(chapter, number, other)
        assert not verdict and "outside the range" in verdict.message
    assert not exercises.check("jacobians", 4, "92.69 deg")
    assert exercises.check("jacobians", 4, "-87.31 deg")
    assert not exercises.check("kawasaki_workspace", 3, "240.4 deg")
    assert exercises.check("kawasaki_workspace", 3, "42.34 deg")


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


def box_key(chapter, number):
    """The key as the page gets it: the JSON in the answer box's HTML."""
    page = exercises.answer_box(chapter, number, script=False)._repr_html_()
    payload = re.search(r'<script type="application/json">(.*?)</script>', page)
    return json.loads(payload.group(1).replace("<\\/", "</"))


def fake_keys():
    keys = {}
    original = exercises._key_file
    exercises._key_file = lambda c: FAKE if c == "fake" else original(c)
    try:
        for number in FAKE:
            keys[number] = box_key("fake", int(number))
    finally:
        exercises._key_file = original
    return keys


@pytest.mark.skipif(NODE is None, reason="needs Node.js")
def test_javascript_verdicts_equal_python_ones(fake):
    keys = fake_keys()
    inputs = [(n, str(a)) for n, a in JS_INPUTS]
    as_sent = json.loads(json.dumps(keys))  # the keys as the page reads them
    page = node_verdicts([[text, as_sent[str(n)]] for n, text in inputs])
    python = python_verdicts(inputs)
    assert [p[0] for p in page] == [p[0] for p in python]
    for (n, text), got, want in zip(inputs, page, python):
        if not want[1].startswith("Could not read"):  # parse errors are worded apart
            assert got[1] == want[1], (n, text)


def test_answer_boxes_answer_in_the_browser(fake, chromium):
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
    page = chromium.new_page()
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
