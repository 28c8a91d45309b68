"""book/course_plan.md against the chapters: every chapter of _toc.yml is
the chapter of one week, every exercise a week names exists in its chapter, and every
exercise of the course is assigned in some week's Exercises line."""

from pathlib import Path

import pytest
from course_plan import numbers, toc_chapters, weeks
from exercise_syntax import read_exercises

ROOT = Path(__file__).resolve().parents[2]
PLAN = (ROOT / "book" / "course_plan.md").read_text(encoding="utf-8")


def book_chapters():
    """The chapter notebooks of _toc.yml, in order."""
    return toc_chapters(ROOT)


def exercise_numbers(chapter):
    text = (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")
    return {e["number"] for e in read_exercises(text, chapter)}


def listed_problems(plan, chapters, numbers_of):
    """What is wrong with the plan's weeks: a list of sentences (empty: nothing)."""
    problems, found = [], weeks(plan)
    own = [w["chapter"] for w in found]
    for chapter in chapters:
        if own.count(chapter) != 1:
            problems.append(f"{chapter} is the chapter of {own.count(chapter)} weeks")
    if [w["number"] for w in found] != list(range(1, len(found) + 1)):
        problems.append(f"the weeks are not numbered 1, 2, ...: {own}")
    assigned = set()
    for week in found:
        for chapter, listed in week["exercises"] + week["named"]:
            if chapter not in chapters:
                problems.append(f"week {week['number']} names {chapter}, not a chapter")
                continue
            absent = sorted(set(listed) - numbers_of(chapter))
            if absent:
                problems.append(
                    f"week {week['number']} names {chapter} exercises {absent}, "
                    "which the chapter does not have"
                )
        assigned |= {(c, n) for c, listed in week["exercises"] for n in listed}
    for chapter in chapters:
        left = sorted(n for n in numbers_of(chapter) if (chapter, n) not in assigned)
        if left:
            problems.append(f"{chapter} exercises {left} are in no week's Exercises")
    return problems


def test_the_plan_matches_the_chapters():
    chapters = book_chapters()
    known = {chapter: exercise_numbers(chapter) for chapter in chapters}
    assert listed_problems(PLAN, chapters, known.__getitem__) == []


def test_numbers_reads_the_plans_ranges():
    assert numbers("1 to 9 and 11 to 21") == [*range(1, 10), *range(11, 22)]
    assert numbers("3 to 6 and 19") == [3, 4, 5, 6, 19]
    assert numbers("8 and 9") == [8, 9]
    with pytest.raises(ValueError, match="backwards"):
        numbers("9 to 3")


SYNTHETIC = """### Week 1
**Alpha.** {doc}`../notebooks/alpha`: *A section*.

- **Exercises** {doc}`alpha <../notebooks/alpha>` 1 to 3 and
  5, and {doc}`beta <../notebooks/beta>` 2 (a note).
- **Lab** Write it ({doc}`alpha <../notebooks/alpha>` exercise 7).

### Week 2
**Beta.** {doc}`../notebooks/beta`.

- **Exercises** {doc}`beta <../notebooks/beta>` 1.

## The project
"""


def test_the_plan_reader_finds_weeks_chapters_and_numbers():
    found = weeks(SYNTHETIC)
    assert [(w["number"], w["title"], w["chapter"]) for w in found] == [
        (1, "Alpha", "alpha"),
        (2, "Beta", "beta"),
    ]
    assert found[0]["exercises"] == [("alpha", [1, 2, 3, 5]), ("beta", [2])]
    assert found[0]["named"] == [("alpha", [7])]


def test_a_wrong_plan_fails():
    have = {"alpha": {1, 2, 3, 4, 5, 6, 7}, "beta": {1, 2}, "gamma": {1}}
    problems = listed_problems(SYNTHETIC, ["alpha", "beta", "gamma"], have.get)
    assert problems == [
        "gamma is the chapter of 0 weeks",
        "alpha exercises [4, 6, 7] are in no week's Exercises",
        "gamma exercises [1] are in no week's Exercises",
    ]
    have["alpha"] = {1, 2, 3}  # the plan names 5 and the lab's 7
    problems = listed_problems(SYNTHETIC, ["alpha", "beta"], have.get)
    assert problems == [
        "week 1 names alpha exercises [5], which the chapter does not have",
        "week 1 names alpha exercises [7], which the chapter does not have",
    ]
    with pytest.raises(ValueError, match="no exercise numbers"):
        weeks(SYNTHETIC.replace("1 to 3 and\n  5", "all"))
