"""Every right form of an answer is accepted, in Python and in the page, from one list.

tests/course/answer_forms.json holds typed answers and their verdicts (the forms
readers typed and were refused: vectors in parentheses, a unit after a whole vector,
1/s, Hz, J/s, radians in a box in degrees, a number times pi...); each is checked by
``sk.exercises.check`` and by the page's script (screwkit/static/exercises.js, run in
Node) with the key the page gets. A generated list adds, for every key of the book,
its value in its unit, in a scaled unit, in parentheses and with spaces: both checkers
must accept them all.
"""

import json
import math
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest
from answer_references import all_keys

from screwkit import exercises

NODE = shutil.which("node")
CASES = json.loads(
    (Path(__file__).with_name("answer_forms.json")).read_text(encoding="utf-8")
)["cases"]

#: A key's unit -> another unit of the same quantity and the factor from the first
#: to the second (1 m is 1000 mm), written here by hand.
SCALED = {
    "m": ("mm", 1e3),
    "mm": ("m", 1e-3),
    "rad": ("deg", 180 / math.pi),
    "deg": ("rad", math.pi / 180),
    "m/s": ("mm/s", 1e3),
    "rad/s": ("deg/s", 180 / math.pi),
    "N": ("kN", 1e-3),
    "N m": ("N mm", 1e3),
    "W": ("kW", 1e-3),
    "m/rad": ("mm/rad", 1e3),
    "m^2": ("mm^2", 1e6),
    "1/s": ("1/ms", 1e-3),
    "s": ("ms", 1e3),
    "m/s^2": ("mm/s^2", 1e3),
    "N/m": ("N/mm", 1e-3),
    "N m/rad": ("N mm/rad", 1e3),
}


def box_key(chapter, number):
    """The key as the page gets it: the JSON in the answer box's HTML."""
    page = exercises.answer_box(chapter, number, script=False)._repr_html_()
    payload = re.search(r'<script type="application/json">(.*?)</script>', page)
    return json.loads(payload.group(1).replace("<\\/", "</"))


def in_node(trials):
    """The page's verdicts, [correct, message], on (chapter, number, text) trials."""
    keys = {f"{c} {n}": box_key(c, n) for c, n, _ in trials}
    program = (
        "global.window = {}; global.document = {querySelectorAll: () => []};\n"
        + exercises.exercises_script()
        + f"\nconst keys = {json.dumps(keys)};\n"
        f"const trials = {json.dumps(trials)};\n"
        "console.log(JSON.stringify(trials.map(([c, n, t]) => {\n"
        "  const v = window.screwkitExercises.verdict(t, keys[c + ' ' + n]);\n"
        "  return [v.correct, v.message]; })));\n"
    )
    result = subprocess.run(
        [NODE, "-e", program], capture_output=True, text=True, timeout=60, check=True
    )
    return json.loads(result.stdout)


def number_text(value):
    return f"{value:.10g}"


def generated_forms(chapter, number):
    """The right forms of one key: in its unit, scaled, in parentheses, spaced."""
    key = exercises.answer_key(chapter, number)
    values, unit = key["values"], key["unit"]
    plain = ", ".join(number_text(v) for v in values)
    forms = [plain, "  " + " , ".join(number_text(v) for v in values) + "  "]
    if len(values) > 1:
        forms += [f"({plain})", f"[{plain}]", f"( {plain} )"]
    if unit:
        forms += [f"{plain} {unit}", f"  {plain}   {unit} "]
        forms += [", ".join(f"{number_text(v)} {unit}" for v in values)]
        if len(values) > 1:
            forms += [f"({plain}) {unit}", f" ( {plain} )  {unit}"]
        scaled, factor = SCALED[unit]
        values_scaled = ", ".join(number_text(v * factor) for v in values)
        forms += [f"{values_scaled} {scaled}", f"({values_scaled}) {scaled}"]
        forms += [", ".join(f"{number_text(v * factor)} {scaled}" for v in values)]
    if key.get("units"):  # a vector of mixed units: each number with its own unit
        forms += [
            ", ".join(f"{number_text(v)} {u}" for v, u in zip(values, key["units"]))
        ]
        forms += [
            " , ".join(
                f"{number_text(v * SCALED[u][1])} {SCALED[u][0]}"
                for v, u in zip(values, key["units"])
            )
        ]
    return forms


def test_every_key_unit_has_a_scaled_unit():
    units = set()
    for chapter, number in all_keys():
        key = exercises.answer_key(chapter, number)
        units |= {key["unit"], *key.get("units", [])}
    assert units - {""} <= set(SCALED)


def test_the_list_covers_issue_42():
    texts = {text for _, _, text, correct, _ in CASES if correct}
    for text in ("(2, 0, 0) m", "(-2, 1, 0)", "2000, 0, 0 mm", "500, 866, 104.7 mm"):
        assert text in texts
    for text in ("0.9375 1/s", "2.25 s", "13.5 m/s²", "200 1/s", "pi/2", "1.5708"):
        assert text in texts
    for text in ("0.6667 pi", "10 J/s", "200 Hz", "4.05 N/Nm", "4.05 1/m"):
        assert text in texts
    # wrong answers keep a reason of each kind: sign, unit, order, length
    reasons = " ".join(phrase for *_, correct, phrase in CASES if not correct)
    for reason in ("sign", "found a", "wrong order", "expected 3 numbers"):
        assert reason in reasons


@pytest.mark.parametrize("chapter, number, text, correct, phrase", CASES)
def test_forms_in_python(chapter, number, text, correct, phrase):
    verdict = exercises.check(chapter, number, text)
    assert verdict.correct is correct, (text, verdict.message)
    assert phrase in verdict.message.lower(), (text, verdict.message)


@pytest.mark.skipif(NODE is None, reason="needs Node.js")
def test_forms_in_the_page():
    page = in_node([[c, n, t] for c, n, t, _, _ in CASES])
    for (chapter, number, text, correct, phrase), (right, message) in zip(CASES, page):
        assert right is correct, (chapter, number, text, message)
        assert phrase in message.lower(), (chapter, number, text, message)
        assert message == exercises.check(chapter, number, text).message


@pytest.mark.parametrize("chapter, number", all_keys())
def test_generated_forms_in_python(chapter, number):
    for text in generated_forms(chapter, number):
        verdict = exercises.check(chapter, number, text)
        assert verdict.correct, (text, verdict.message)


@pytest.mark.skipif(NODE is None, reason="needs Node.js")
def test_generated_forms_in_the_page():
    trials = [[c, n, t] for c, n in all_keys() for t in generated_forms(c, n)]
    assert len(trials) > 300
    for (chapter, number, text), (right, message) in zip(trials, in_node(trials)):
        assert right, (chapter, number, text, message)


def test_scaled_forms_are_not_the_key_itself():
    # the generated test would prove little if a scaled form were the same text
    forms = generated_forms("rigid_motions", 2)
    assert "2000, 0, 0 mm" in forms and "(2, 0, 0) m" in forms
    assert np.isclose(SCALED["rad"][1] * math.pi, 180)


def random_texts(count, seed=7):
    """Typed answers put together from numbers, units, separators and brackets."""
    rng = np.random.default_rng(seed)
    numbers = ["2", "-2", "0", "0.5", "1e-3", "pi", "2pi", "0.6667 pi", "sqrt(3)/2"]
    numbers += ["(1+2)/3", "90", "200", "4.05", "13.5", "10", "-87.31", "1.5708"]
    units = ["", "", " m", " mm", " deg", " rad", " 1/s", " Hz", " N m", " J/s", "/s"]
    units += [" m/s²", " N/Nm", " s", " ms", " W", " kW", " 1/m"]
    separators = [", ", " ", "; ", " , "]
    texts = []
    for _ in range(count):
        n = int(rng.integers(1, 4))
        items = [
            str(rng.choice(numbers))
            + (str(rng.choice(units)) if rng.random() < 0.3 else "")
            for _ in range(n)
        ]
        text = str(rng.choice(separators)).join(items)
        shape = rng.random()
        if shape < 0.25:
            text = f"({text})"
        elif shape < 0.4:
            text = f"[{text}]"
        if rng.random() < 0.4:
            text += str(rng.choice(units))
        texts.append(text)
    return texts


@pytest.mark.skipif(NODE is None, reason="needs Node.js")
def test_the_page_and_python_agree_on_random_answers():
    keys = [("rigid_motions", 2), ("screws", 6), ("parallel_kinematics", 6)]
    keys += [("jacobians", 6), ("redundancy", 7), ("motion_in_time", 5)]
    keys += [("poe", 8), ("rigid_motions", 5)]
    trials = [[c, n, t] for c, n in keys for t in random_texts(150)]
    page = in_node(trials)
    right = 0
    for (chapter, number, text), (correct, message) in zip(trials, page):
        want = exercises.check(chapter, number, text)
        assert correct is want.correct, (chapter, number, text, message, want.message)
        if not want.message.startswith("Could not read"):  # parse errors worded apart
            assert message == want.message, (chapter, number, text)
        right += correct
    assert right >= 5  # some of them are right answers, not only refusals
