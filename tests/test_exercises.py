"""Self-checking exercises: every answer key against an independent computation.

Each key in ``screwkit/answers/*.toml`` was derived by hand in its chapter; here it
is recomputed another way (a formula written out in the test, a finite difference,
or screwkit on the problem as stated) and must agree far inside its tolerance. Then
the checking rules (forms, units, signs, text input) and the page's JavaScript,
which must give the same verdict as ``sk.exercises.check`` on the same text.
"""

import importlib.util
import json
import math
import shutil
import subprocess
import tomllib
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit import exercises

REFERENCES = {}


def reference(chapter, number):
    """Register the independent computation of one exercise's answer."""

    def register(function):
        REFERENCES[chapter, number] = function
        return function

    return register


def all_keys():
    folder = resources.files("screwkit").joinpath("answers")
    keys = []
    for path in sorted(folder.iterdir(), key=lambda p: p.name):
        if path.name.endswith(".toml"):
            data = tomllib.loads(path.read_text(encoding="utf-8"))
            chapter = path.name[: -len(".toml")]
            keys += [(chapter, int(n)) for n in data.get("exercise", {})]
    return keys


def rot(axis, angle):
    """An elementary rotation written out by hand (axis 'x', 'y' or 'z')."""
    c, s = math.cos(angle), math.sin(angle)
    return {
        "x": np.array([[1, 0, 0], [0, c, -s], [0, s, c]]),
        "y": np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        "z": np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    }[axis]


# ---- rigid_motions -----------------------------------------------------------------


@reference("rigid_motions", 2)
def _():
    # rotate the origin by pi about the z-line through (1, 0, 0): p' = c + Rz(pi)(p - c)
    c = np.array([1.0, 0.0, 0.0])
    return c + rot("z", math.pi) @ (np.zeros(3) - c)


@reference("rigid_motions", 5)
def _():
    # x -> y -> z -> x: the columns of R are e_y, e_z, e_x
    R = np.array([[0.0, 0, 1], [1, 0, 0], [0, 1, 0]])
    np.testing.assert_allclose(
        sk.rot_axis([1.0, 1.0, 1.0], 2 * math.pi / 3), R, atol=1e-12
    )
    return math.acos((np.trace(R) - 1) / 2)


@reference("rigid_motions", 6)
def _():
    R = rot("z", math.pi / 6) @ rot("y", math.pi / 4) @ rot("x", math.pi / 3)
    roll = math.atan2(R[2, 1], R[2, 2])
    pitch = -math.asin(R[2, 0])
    yaw = math.atan2(R[1, 0], R[0, 0])
    return [roll, pitch, yaw]


@reference("rigid_motions", 7)
def _():
    q = np.array([math.cos(math.pi / 4), 0, 0, math.sin(math.pi / 4)])
    # the Hamilton product q v q* rotates v = e_x into Rz(pi/2) e_x = e_y
    w, u = q[0], q[1:]
    v = np.array([1.0, 0, 0])
    rotated = v + 2 * w * np.cross(u, v) + 2 * np.cross(u, np.cross(u, v))
    np.testing.assert_allclose(rotated, [0, 1, 0], atol=1e-12)
    return q


@reference("rigid_motions", 10)
def _():
    # T(t): spin at 2 rad/s about the z-line through (1, 0, 0); twist from Tdot T^-1
    def pose(t):
        T = np.eye(4)
        T[:3, :3] = rot("z", 2 * t)
        T[:3, 3] = np.array([1.0, 0, 0]) - rot("z", 2 * t) @ np.array([1.0, 0, 0])
        return T

    t, h = 0.3, 1e-6
    Tdot = (pose(t + h) - pose(t - h)) / (2 * h)
    V = Tdot @ np.linalg.inv(pose(t))
    return [V[2, 1], V[0, 2], V[1, 0], *V[:3, 3]]


# ---- screws ------------------------------------------------------------------------

SCREW = np.array([0, 0, 1, 1, 2, 0.5])


@reference("screws", 4)
def _():
    s, s0 = SCREW[:3], SCREW[3:]
    return s @ s0 / (s @ s)


@reference("screws", 5)
def _():
    s, s0 = SCREW[:3], SCREW[3:]
    r0 = np.cross(s, s0) / (s @ s)
    # the axis through r0 with the pitch of exercise 4 gives the screw back
    np.testing.assert_allclose(np.cross(r0, s) + 0.5 * s, s0, atol=1e-15)
    return r0


@reference("screws", 6)
def _():
    f, r = np.array([0.0, 10, 0]), np.array([0.5, 0, 0])
    omega, v = np.array([0.0, 0, 2]), np.zeros(3)
    power = omega @ np.cross(r, f) + v @ f
    # the lever arm: torque 0.5 m x 10 N about z, times 2 rad/s
    assert power == 0.5 * 10 * 2
    return power


@reference("screws", 10)
def _():
    twists = np.array([[1.0, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0]])  # axes x, y at 0
    rank = np.linalg.matrix_rank(twists)
    assert (
        sk.ScrewSystem([([1, 0, 0], [0, 0, 0], 0), ([0, 1, 0], [0, 0, 0], 0)]).rank == 2
    )
    return 6 - rank


# ---- poe ---------------------------------------------------------------------------


@reference("poe", 2)
def _():
    # B = Ad(M^-1) S, M a translation by p = (2, 0, 0): same omega, v = v_s + omega x p
    p = np.array([2.0, 0, 0])
    rows = []
    for w, v in (([0, 0, 1.0], [0, 0, 0.0]), ([0, 0, 1.0], [0, -1.0, 0])):
        rows.append([*w, *(np.array(v) + np.cross(w, p))])
    return rows


@reference("poe", 3)
def _():
    # the logarithm of a translation by the series log(I + N) = N - N^2/2 ..., N^2 = 0
    T = np.eye(4)
    T[:3, 3] = [1, 2, 2]
    N = T - np.eye(4)
    assert np.allclose(N @ N, 0)
    return [0, 0, 0, *N[:3, 3]]


@reference("poe", 7)
def _():
    # turn the tool point about the line x = 0, y = 6 (along -z), slide h q along -z
    p, c, q, h = np.array([0.0, 6, 2]), np.array([0.0, 6, 0]), math.pi / 2, 0.1
    p_new = c + rot("z", -q) @ (p - c) + h * q * np.array([0, 0, -1.0])
    M = np.array([[-1, 0, 0, 0], [0, 1, 0, 6], [0, 0, -1, 2], [0, 0, 0, 1.0]])
    arm = sk.Chain.from_screws(
        [[0, 0, 1, 4, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, -1, -6, 0, -0.1]], M
    )
    np.testing.assert_allclose(arm.fk([0, 0, q])[:3, 3], p_new, atol=1e-12)
    return p_new


@reference("poe", 8)
def _():
    q = 2 * math.pi / 3
    c = np.array([1.0, 0, 0])
    return c + rot("z", q) @ (np.array([2.0, 0, 0]) - c) + [0, 0, 0.05 * q]


@reference("poe", 10)
def _():
    # T [V_b] T^-1 for T a translation by (0, 2, 0), then read the twist off the matrix
    T = np.eye(4)
    T[:3, 3] = [0, 2, 0]
    V_b = np.zeros((4, 4))
    V_b[0, 1], V_b[1, 0] = -1, 1  # [omega] for omega = (0, 0, 1), v = 0
    V_a = T @ V_b @ np.linalg.inv(T)
    return [V_a[2, 1], V_a[0, 2], V_a[1, 0], *V_a[:3, 3]]


# ---- puma_fk -----------------------------------------------------------------------

# the PUMA 560 of Corke's table, written here: (d, a, alpha) per link
PUMA_TABLE = [
    (0, 0, math.pi / 2),
    (0, 0.4318, 0),
    (0.15005, 0.0203, -math.pi / 2),
    (0.4318, 0, math.pi / 2),
    (0, 0, -math.pi / 2),
    (0, 0, 0),
]


def dh(theta, d, a, alpha):
    ct, st, ca, sa = math.cos(theta), math.sin(theta), math.cos(alpha), math.sin(alpha)
    return np.array(
        [
            [ct, -st * ca, st * sa, a * ct],
            [st, ct * ca, -ct * sa, a * st],
            [0, sa, ca, d],
            [0, 0, 0, 1],
        ]
    )


def dh_fk(table, q):
    T = np.eye(4)
    for qi, row in zip(q, table):
        T = T @ dh(qi, *row)
    return T


@reference("puma_fk", 2)
def _():
    ready = [0, math.pi / 2, -math.pi / 2, 0, 0, 0]
    x, y, _ = dh_fk(PUMA_TABLE, ready)[:3, 3]
    return math.hypot(x, y)


@reference("puma_fk", 4)
def _():
    return dh_fk(PUMA_TABLE, np.zeros(6))[:3, 3]


@reference("puma_fk", 8)
def _():
    table = [(0.4, 0.1, -math.pi / 2), (0, 0.4, 0), (0, 0.3, 0)]
    return dh_fk(table, [0, -math.pi / 2, 0])[:3, 3]


@reference("puma_fk", 9)
def _():
    # the distance between the elbow and forearm-roll axes, from screwkit's joint screws
    axes = sk.robots.puma560().screw_axes()
    z, points = axes[:, :3], np.cross(axes[:, :3], axes[:, 3:])
    n = np.cross(z[2], z[3])
    return abs((points[3] - points[2]) @ n) / np.linalg.norm(n) * 1000


# ---- puma_ik -----------------------------------------------------------------------

D3, A2, A3, D4 = 0.15005, 0.4318, 0.0203, 0.4318


def elbow_grid():
    """The squared shoulder-to-wrist distance in the arm's plane on a grid of q3."""
    q3 = np.linspace(-math.pi, math.pi, 2_000_001)
    c3, s3 = np.cos(q3), np.sin(q3)
    return q3, (A2 + A3 * c3 - D4 * s3) ** 2 + (A3 * s3 + D4 * c3) ** 2


@reference("puma_ik", 4)
def _():
    q3, distance2 = elbow_grid()
    return q3[np.argmax(distance2)]


@reference("puma_ik", 5)
def _():
    q3, distance2 = elbow_grid()
    best = q3[np.argmax(distance2)]
    # the same through the DH table: at full stretch the wrist centre is that far from
    # the shoulder in the arm's plane, which is d3 to the side of the base origin
    p = dh_fk(PUMA_TABLE, [0.2, 0.3, best, 0, 0, 0])[:3, 3]
    np.testing.assert_allclose(
        math.sqrt(p @ p - D3**2), math.sqrt(distance2.max()), atol=1e-9
    )
    return math.sqrt(distance2.max())


def puma_limits_ok(q):
    low = np.radians([-160, -45, -225, -110, -100, -266])
    high = np.radians([160, 225, 45, 170, 100, 266])
    shifts = 2 * math.pi * np.arange(-2, 3)
    return all(
        np.any((v + shifts >= lo) & (v + shifts <= hi))
        for v, lo, hi in zip(q, low, high)
    )


@reference("puma_ik", 9)
def _():
    # the chapter's eight solutions by its own formulas, written again here
    q_true = np.radians([20, 40, -110, 30, 50, -20])
    T = dh_fk(PUMA_TABLE, q_true)
    wx, wy, wz = T[:3, 3]
    r, phi = math.hypot(wx, wy), math.atan2(wy, wx)
    rho, beta = math.hypot(A3, D4), math.atan2(D4, A3)
    count, found = 0, 0
    for arm in (1, -1):
        q1 = phi + math.asin(D3 / r) if arm == 1 else phi + math.pi - math.asin(D3 / r)
        V = arm * math.sqrt(r**2 - D3**2)
        cosine = (V**2 + wz**2 - A2**2 - rho**2) / (2 * A2 * rho)
        for elbow in (1, -1):
            q3 = elbow * math.acos(cosine) - beta
            c3, s3 = math.cos(q3), math.sin(q3)
            q2 = math.atan2(wz, V) - math.atan2(
                A3 * s3 + D4 * c3, A2 + A3 * c3 - D4 * s3
            )
            R03 = dh_fk(PUMA_TABLE[:3], [q1, q2, q3])[:3, :3]
            R36 = R03.T @ T[:3, :3]
            m5 = math.atan2(math.hypot(R36[0, 2], R36[1, 2]), R36[2, 2])
            q4, q6 = math.atan2(R36[1, 2], R36[0, 2]), math.atan2(R36[2, 1], -R36[2, 0])
            for q in (
                [q1, q2, q3, q4, -m5, q6],
                [q1, q2, q3, q4 + math.pi, m5, q6 + math.pi],
            ):
                np.testing.assert_allclose(dh_fk(PUMA_TABLE, q), T, atol=1e-9)
                found += 1
                count += puma_limits_ok(q)
    assert found == 8
    return count


@reference("puma_ik", 10)
def _():
    twin = [0.3 + math.pi, -0.5, 0.2 + math.pi]
    wrist = lambda q4, q5, q6: rot("z", q4) @ rot("y", -q5) @ rot("z", q6)  # noqa: E731
    np.testing.assert_allclose(wrist(*twin), wrist(0.3, 0.5, 0.2), atol=1e-12)
    return twin


# ---- the keys ----------------------------------------------------------------------


def test_every_key_has_an_independent_reference():
    missing = sorted(set(all_keys()) - set(REFERENCES))
    assert missing == []


@pytest.mark.parametrize("chapter, number", all_keys())
def test_key_agrees_with_its_reference(chapter, number):
    key = exercises.answer_key(chapter, number)
    expected = np.ravel(np.asarray(REFERENCES[chapter, number](), dtype=float))
    assert key["unit"] in ("", "rad", "deg", "m", "mm", "m/s", "rad/s")
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


# The project's one way to start a browser (.ci/harness.py): the system Chromium, fenced
# off the network
_spec = importlib.util.spec_from_file_location(
    "harness", Path(__file__).resolve().parent.parent / ".ci" / "harness.py"
)
harness = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(harness)
CHROMIUM = harness.CHROMIUM


@pytest.mark.skipif(CHROMIUM is None, reason="needs Chromium")
def test_answer_boxes_answer_in_the_browser(fake):
    pytest.importorskip("playwright.sync_api")
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
    with harness.launch() as browser:
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


@pytest.mark.skipif(CHROMIUM is None, reason="needs Chromium")
@pytest.mark.parametrize("chapter", ["rigid_motions", "puma_ik"])
def test_stored_chapter_boxes_answer_in_the_page(chapter):
    # the chapter's stored HTML outputs, in order, as the book shows them: the script is
    # inlined once, in the first box, and every box answers without a kernel
    pytest.importorskip("playwright.sync_api")
    path = Path(__file__).resolve().parent.parent / "notebooks" / f"{chapter}.ipynb"
    cells = json.loads(path.read_text(encoding="utf-8"))["cells"]
    boxes = [
        "".join(out["data"]["text/html"])
        for cell in cells
        for out in cell.get("outputs", [])
        if "sk-answer-box" in "".join(out.get("data", {}).get("text/html", ""))
    ]
    assert len(boxes) >= 2
    assert sum("window.screwkitExercises = {" in b for b in boxes) == 1
    with harness.launch() as browser:
        page = browser.new_page()
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
