"""Parametrised exercises (``sk.exercises.variant``): each seed's key, computed by
screwkit, against a formula written here from the statement's numbers; seed 0 is the
chapter's own statement; the box and the check take the seed; ``make answers
SEEDS=class.csv`` writes each student's sheet and the teacher's keys."""

import csv
import importlib
import re
import sys
from collections import Counter
from pathlib import Path

import numpy as np
import pytest

from screwkit import exercises

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tools"))

from exercise_syntax import read_exercises  # noqa: E402


def independent_references():
    """(chapter, number) -> its reference in tests/course/variant_references/."""
    found = {}
    for path in sorted((ROOT / "tests" / "course" / "variant_references").glob("*.py")):
        if path.stem != "__init__":
            module = importlib.import_module(f"variant_references.{path.stem}")
            found |= {(path.stem, n): f for n, f in module.INDEPENDENT.items()}
    return found


INDEPENDENT = independent_references()
SEEDS = range(21)


def self_checking(chapter):
    source = (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")
    return [
        e["number"]
        for e in read_exercises(source, chapter)
        if "self-checking" in (e["kinds"] or [])
    ]


def test_the_parametrised_exercises_each_have_an_independent_reference():
    assert exercises.parametrised() == sorted(INDEPENDENT)
    for chapter, number in INDEPENDENT:
        assert number in exercises.parametrised(chapter)
        assert number in self_checking(chapter)
        assert not exercises.is_assessed(chapter, number)


def test_a_third_of_the_self_checking_exercises_are_parametrised():
    chapters = sorted(p.stem for p in (ROOT / "screwkit" / "answers").glob("*.toml"))
    total = sum(len(self_checking(c)) for c in chapters)
    assert total >= 100  # the bank's self-checking exercises are all counted
    assert 3 * len(INDEPENDENT) >= total, (len(INDEPENDENT), total)


@pytest.mark.parametrize("chapter, number", sorted(INDEPENDENT))
def test_each_seed_key_equals_an_independent_computation(chapter, number):
    keys = []
    for seed in SEEDS:
        v = exercises.variant(chapter, number, seed)
        expected = np.ravel(INDEPENDENT[chapter, number](v.numbers))
        np.testing.assert_allclose(v.key["values"], expected, rtol=0, atol=1e-9)
        assert exercises.check(chapter, number, list(expected), seed=seed).correct
        keys.append(tuple(np.round(expected, 9)))
    # the seeds draw different numbers: a class gets many different keys
    assert len(set(keys)) >= 6
    assert max(Counter(keys).values()) <= 8


@pytest.mark.parametrize("chapter, number", sorted(INDEPENDENT))
def test_seed_zero_is_the_chapter_statement(chapter, number):
    source = (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")
    found = {e["number"]: e for e in read_exercises(source, chapter)}[number]
    statement = found["statement"].split("*Parametrised*")[0]
    # the tag (kinds, difficulty, sections) holds no number of the problem
    statement = re.sub(r"^\*\(.*?\)\*\s*", "", statement.strip(), flags=re.S)
    v = exercises.variant(chapter, number, 0)
    numbers = re.compile(r"(?<![\w.])\d+(?:\.\d+)?")
    assert Counter(numbers.findall(statement)) == Counter(
        numbers.findall(v.statement)
    ), (statement, v.statement)
    assert f'sk.exercises.variant("{chapter}", {number}, seed)' in found["statement"]
    # the page's box checks seed 0
    assert exercises.answer_key(chapter, number)["values"] == v.key["values"]


def test_a_seed_checks_its_own_numbers_only():
    own = exercises.variant("screws", 6, 1).key["values"][0]
    zero = exercises.variant("screws", 6, 0).key["values"][0]
    assert own != zero
    assert exercises.check("screws", 6, f"{own} W", seed=1).correct
    assert not exercises.check("screws", 6, f"{zero} W", seed=1).correct
    box = exercises.answer_box("screws", 6, script=False, seed=1)._repr_html_()
    assert f'"values": [{own}]' in box
    assert "seed 1" in repr(exercises.variant("screws", 6, 1))
    assert str(own) not in repr(exercises.variant("screws", 6, 1))  # no key shown


@pytest.mark.parametrize(
    "call, error, phrase",
    [
        (lambda: exercises.variant("screws", 4, 1), ValueError, "parametrised"),
        (lambda: exercises.variant("screws", 6, -1), ValueError, "seed must be"),
        (lambda: exercises.variant("screws", 6, 1.5), ValueError, "seed must be"),
        (lambda: exercises.answer_key("screws", 4, 3), ValueError, "seed must be 0"),
        (lambda: exercises.variant("nope", 1, 0), ValueError, "chapter must be"),
    ],
)
def test_bad_variants_are_refused_with_a_sentence(call, error, phrase):
    with pytest.raises(error, match=phrase):
        call()


def test_make_answers_writes_a_sheet_per_student_and_the_keys(tmp_path):
    import teacher_answers

    seeds = tmp_path / "class.csv"
    seeds.write_text("student,seed\nada,0\nbob,7\ncleo,12\n", encoding="utf-8")
    count = teacher_answers.sheets(tmp_path, teacher_answers.read_seeds(seeds))
    assert count == 3 * len(INDEPENDENT)
    for student in ("ada", "bob", "cleo"):
        sheet = (tmp_path / "sheets" / f"{student}.md").read_text(encoding="utf-8")
        assert sheet.count("sk.exercises.check(") == len(INDEPENDENT)
    with open(tmp_path / "keys.csv", encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == count
    for row in rows:
        chapter, number, seed = row["chapter"], int(row["number"]), int(row["seed"])
        v = exercises.variant(chapter, number, seed)
        expected = np.ravel(INDEPENDENT[chapter, number](v.numbers))
        got = [float(x) for x in row["key"].split(",")]
        np.testing.assert_allclose(got, expected, rtol=1e-5, atol=1e-9)
        assert v.statement in (tmp_path / "sheets" / f"{row['student']}.md").read_text(
            encoding="utf-8"
        )
    bad = tmp_path / "bad.csv"
    bad.write_text("student,seed\nada,x\n", encoding="utf-8")
    with pytest.raises(ValueError, match="seed must be a whole number"):
        teacher_answers.read_seeds(bad)


def test_a_variant_table_and_its_key_function_must_agree():
    from screwkit import _variants

    def table(chapter, number):
        return exercises._entry(chapter, number)["variant"]

    # motion_in_time 3 draws T: a function of another name is refused at its first call
    wrong = _variants.Generator("motion_in_time", 3, lambda duration: duration)
    with pytest.raises(ValueError, match=r"must take the draws \['T'\], got"):
        wrong(None, table("motion_in_time", 3))
    # rigid_motions 7 computes the number axis (0, 1 or 2) from the axis drawn
    mute = _variants.Generator("rigid_motions", 7, lambda angle, about: [1, 0, 0, 0])
    with pytest.raises(
        ValueError, match=r"must give the numbers it computes, \['axis'\]"
    ):
        mute(None, table("rigid_motions", 7))
    where = "[exercise.3.variant] of answers/fake.toml"
    with pytest.raises(ValueError, match="must exist and hold a statement"):
        _variants.checked({"T": {"unit": "s"}}, where)
    for entry in ({"unit": "s", "seed0": 2.0}, {"seed0": 2.0, "choices": []}, 2.0):
        with pytest.raises(ValueError, match="T of .* must be a draw"):
            _variants.checked({"statement": "T = {T}", "T": entry}, where)
    good = {"statement": "T = {T}", "T": {"unit": "s", "seed0": 2, "choices": [1]}}
    assert _variants.checked(good, where) is good
