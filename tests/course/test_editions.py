"""The two editions: the exercises as the tools read them, and what the course edition
takes out.

Building the book takes minutes, so nothing is built here: .ci/check_course_edition.py
checks the built course edition (``make book EDITION=course``, in .ci/run). These tests
check the pieces it is made of on small inputs written here: the reading of the
exercises (tools/exercise_syntax.py), the stripping of assessed keys and of
solutions (book/_ext/editions.py), and that book/assessed.yml lists exercises that
exist and have an answer box.
"""

import json
import re
import sys
from pathlib import Path

import pytest
from exercise_syntax import (
    SOLUTION,
    SOLUTION_DIRECTIVE,
    exercise_directive,
    old_syntax,
    read_exercises,
)

from screwkit import exercises

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "book" / "_ext"))

import editions  # noqa: E402

NEW = """# A chapter

Text with **bold** and **2.** in the middle of a line.

## Exercises

Some words about the exercises.

:::{exercise}
:label: demo-exercise-1

*(by hand)* Show that $a = b$.
It has two lines.
:::

:::{solution} demo-exercise-1
:class: dropdown

Because $a$ is $b$.
```python
print(":::")   # a colon fence inside code is code
```
:::

:::{exercise-start}
:label: demo-exercise-2
:::

*(by hand, self-checking)* What is $h$?

```{code-cell} ipython3
sk.exercises.answer_box("screws", 4)
```

:::{exercise-end}
:::

:::{solution} demo-exercise-2
:class: dropdown

$h = 0.5$.
:::

:::{exercise}
:label: demo-exercise-3

*(implement it yourself)* Write `my_exp`, no solution yet.
:::
"""


def test_the_chapter_tests_read_each_exercise_as_its_number_and_statement():
    assert exercise_directive("demo").split(NEW)[1::2] == ["1", "2", "3"]
    assert exercise_directive("screws").search(NEW) is None
    as_old = old_syntax(NEW)
    assert "\n**1.** *(by hand)* Show that $a = b$.\n" in as_old
    assert "\n**2.** *(by hand, self-checking)* What is $h$?\n" in as_old
    assert "\n**3.** *(implement it yourself)* Write `my_exp`" in as_old
    assert len(SOLUTION_DIRECTIVE.findall(NEW)) == len(SOLUTION.findall(NEW)) == 2


def test_read_exercises_gives_number_statement_cells_and_solution():
    found = read_exercises(NEW, "demo")
    assert [e["number"] for e in found] == [1, 2, 3]
    assert found[0]["statement"] == "*(by hand)* Show that $a = b$.\nIt has two lines."
    assert found[0]["solution"].endswith(
        'print(":::")   # a colon fence inside code is code\n```'
    )
    assert found[1]["cells"][1] == 'sk.exercises.answer_box("screws", 4)'
    assert found[1]["solution"] == "$h = 0.5$."
    assert found[2]["solution"] is None


@pytest.mark.parametrize("path", sorted((ROOT / "notebooks").glob("*.md")))
def test_every_chapter_numbers_its_exercises_from_one(path):
    text = path.read_text(encoding="utf-8")
    found = read_exercises(text, path.stem)
    assert [e["number"] for e in found] == list(range(1, len(found) + 1))
    assert all(e["label"] == f"{path.stem}-exercise-{e['number']}" for e in found)
    # no exercise left in the syntax the chapters were converted from
    exercises_section = text.split("\n## Exercises", 1)[-1]
    assert not re.search(r"^\*\*\d+\.\*\*", exercises_section, re.M)


def box_html(chapter, number):
    return exercises.answer_box(chapter, number, script=False)._repr_html_()


def test_an_assessed_box_loses_its_key_and_the_others_keep_theirs():
    assessed, other = box_html("screws", 10), box_html("screws", 4)
    page = f"<p>before</p>\n{assessed}<p>between</p>\n{other}<p>after</p>"
    stripped = editions.strip_keys(page, {("screws", 10)})
    key = json.loads(re.search(r'json">(.*?)</script>', assessed, re.S).group(1))
    assert json.dumps(key["values"]) not in stripped.replace(other, "")
    assert "application/json" not in stripped.replace(other, "")
    assert "Exercise 10 is assessed" in stripped
    assert other in stripped and "<p>between</p>" in stripped
    assert stripped.endswith("<p>after</p>")
    assert editions.strip_keys(page, set()) == page


def test_solutions_are_stripped_from_a_source_and_a_notebook():
    stripped = editions.strip_solutions(NEW)
    assert "Because" not in stripped and "h = 0.5" not in stripped
    assert "print" not in stripped  # the code inside the solution went with it
    assert stripped.count(":label: demo-exercise-") == 3
    notebook = {
        "cells": [
            {"cell_type": "markdown", "source": NEW.split("```{code-cell}")[0]},
            {
                "cell_type": "code",
                "source": 'sk.exercises.answer_box("screws", 10)',
                "outputs": [{"data": {"text/html": [box_html("screws", 10)]}}],
            },
        ]
    }
    notebook["cells"].append(
        {
            "cell_type": "code",
            "metadata": {"tags": ["remove-cell", "solution"]},
            "source": 'glue("demo-exercise-1-frames", fig, display=False)',
            "outputs": [],
        }
    )
    course = editions.course_notebook(notebook, {("screws", 10)})
    assert len(course["cells"]) == 2, "the solution's figure cell went too"
    assert "Because" not in course["cells"][0]["source"]
    assert (
        "application/json" not in course["cells"][1]["outputs"][0]["data"]["text/html"]
    )


def test_the_assessed_list_names_exercises_with_an_answer_box():
    marked = editions.assessed()
    assert marked
    for chapter, number in sorted(marked):
        source = (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")
        assert f'sk.exercises.answer_box("{chapter}", {number})' in source
        exercises.answer_key(chapter, number)  # has a key


def test_the_edition_comes_from_the_environment(monkeypatch):
    monkeypatch.delenv("SCREWKIT_EDITION", raising=False)
    assert editions.edition() == "self-study"
    monkeypatch.setenv("SCREWKIT_EDITION", "course")
    assert editions.edition() == "course"
    monkeypatch.setenv("SCREWKIT_EDITION", "teacher")
    with pytest.raises(ValueError, match="SCREWKIT_EDITION must be"):
        editions.edition()


def test_the_course_edition_has_no_launch_buttons(monkeypatch, tmp_path):
    # they would open the repository's notebooks, which hold the solutions
    launch = {"binderhub_url": "https://mybinder.org", "colab_url": "https://colab"}

    class Config:
        hide_solutions = False
        html_theme_options = {"launch_buttons": dict(launch), "repository_url": "r"}

    class App:
        srcdir = str(tmp_path)

        def __init__(self):
            self.tags = set()  # Sphinx's tags, for {only}

    monkeypatch.setenv("SCREWKIT_EDITION", "self-study")
    study, study_app = Config(), App()
    editions.course_config(study_app, study)
    assert study.html_theme_options["launch_buttons"] == launch
    assert not study.hide_solutions
    assert "course" not in study_app.tags
    monkeypatch.setenv("SCREWKIT_EDITION", "course")
    course, course_app = Config(), App()
    editions.course_config(course_app, course)
    assert course.html_theme_options["launch_buttons"] == {}
    assert course.html_theme_options["repository_url"] == "r"
    for button in ("use_repository_button", "use_issues_button", "use_source_button"):
        assert course.html_theme_options[button] is False  # no way to the repository
    assert "use_repository_button" not in study.html_theme_options
    assert course.hide_solutions
    assert "course" in course_app.tags  # how_to_use.md's {only} course


def test_the_launch_check_tells_a_button_from_a_mention():
    # the addresses sphinx-book-theme's header_buttons/launch.py builds for a chapter
    sys.path.insert(0, str(ROOT / ".ci"))
    from check_course_edition import LAUNCH

    buttons = [
        "https://mybinder.org/v2/gh/screwkit/rkws/main?urlpath=lab/tree/notebooks/puma_ik.ipynb",
        "https://colab.research.google.com/github/screwkit/rkws/blob/main/notebooks/x.ipynb",
        "https://hub.example.edu/hub/user-redirect/git-pull?repo=https://github.com/s/r",
    ]
    mentions = [
        'opens it on <a href="https://mybinder.org">Binder</a>',
        "[Google Colab](https://colab.research.google.com), or on your machine",
        'binderUrl: "https://mybinder.org"',  # sphinx-thebe.js's default
    ]
    assert all(LAUNCH.search(text) for text in buttons)
    assert not any(LAUNCH.search(text) for text in mentions)


# ---- the course edition keeps its secrets ---------------------------------

sys.path.insert(0, str(ROOT / ".ci"))
import check_course_edition as checker  # noqa: E402


def test_the_repository_check_tells_a_button_from_a_mention():
    url = "https://github.com/screwkit/robot-kinematics-with-screws"
    assert checker.repository_url() == url
    buttons = {
        "a": f'<a href="{url}" class="btn btn-sm btn-source-repository-button">',
        "b": f'<a href="{url}/issues/new?title=x" class="btn btn-sm">',
        "c": '<div class="dropdown dropdown-source-buttons">',
        "d": f'<a href="{url}.git">clone</a>',
    }
    mentions = {
        "e": f'%pip install --quiet "git+{url}"',  # the install cell's code, no link
        "f": '<a href="https://github.com/other/project">another</a>',
        "g": f'<a href="{url}-fork">a fork</a>',
    }
    assert sorted(checker.repository_links(buttons, url)) == ["a", "b", "c", "d"]
    assert checker.repository_links(mentions, url) == []


def test_the_assessed_keys_are_outside_the_package():
    marked = editions.assessed()
    keys = checker.teacher_keys()
    assert set(keys) == marked  # one teacher's key per assessed exercise, no other
    files = checker.package_files()
    assert "screwkit/exercises.py" in files and "screwkit/static/exercises.js" in files
    assert "screwkit/answers/screws.toml" in files
    assert checker.package_leaks(files, marked, keys) == []
    for chapter, number in marked:  # the package says which ones the teacher marks
        assert exercises.is_assessed(chapter, number)
    for chapter in {c for c, _ in marked}:
        table = exercises._key_file(chapter)
        stubs = {int(n) for n, e in table.items() if e.get("assessed")}
        assert stubs == {n for c, n in marked if c == chapter}


def test_the_package_files_are_the_wheel_files():
    # the tests below read the package's files from the source tree; the check reads
    # the wheel pip builds: the two are the same files with the same text
    wheel, source = checker.wheel_files(), checker.package_files()
    assert set(wheel) == set(source)
    assert all(wheel[name] == source[name] for name in source if name.endswith(".toml"))
    assert (
        checker.package_leaks(wheel, editions.assessed(), checker.teacher_keys()) == []
    )


def test_the_package_check_tells_a_leak_from_a_non_leak():
    marked, keys = editions.assessed(), checker.teacher_keys()
    files = checker.package_files()
    name = "screwkit/answers/screws.toml"
    leaked = dict(files)
    leaked[name] = files[name].replace(
        "[exercise.10]\n", '[exercise.10]\nanswer = "4"\n', 1
    )
    assert any("screws 10" in p for p in checker.package_leaks(leaked, marked, keys))
    # the key's answer line copied into any packaged file is a leak too
    copied = dict(files)
    line = f"answer = {json.dumps(keys['rigid_motions', 10]['answer'])}"
    copied["screwkit/robots.py"] = files["screwkit/robots.py"] + f"\n# {line}\n"
    found = checker.package_leaks(copied, marked, keys)
    assert found and "rigid_motions 10" in found[0] and "robots.py" in found[0]
    withkeys = dict(files) | {"screwkit/teacher_keys/x.toml": "[exercise.1]"}
    assert any("teacher" in p for p in checker.package_leaks(withkeys, marked, keys))


def live_trials():
    keys = checker.teacher_keys()
    trials = []
    for (chapter, number), key in sorted(keys.items())[:3]:
        answer = key["answer"]
        trials.append(
            [chapter, number, ", ".join(answer) if isinstance(answer, list) else answer]
        )
    return trials


def test_the_live_trials_are_right_answers_where_the_keys_are():
    # from this checkout screwkit reads book/teacher_keys: the trials are right, so a
    # live check that grades them (a leak) would call them right
    for chapter, number, answer in live_trials():
        assert exercises.check(chapter, number, answer).correct, (chapter, number)


def test_the_live_check_tells_a_leak_from_a_non_leak():
    files, trials = checker.package_files(), live_trials()
    control = ["screws", 4, "0.5"]
    assert checker.live_problems(files, trials, control) == []
    leaked = dict(files)
    chapter, number, _ = trials[0]
    teacher = (ROOT / "book" / "teacher_keys" / f"{chapter}.toml").read_text()
    name = f"screwkit/answers/{chapter}.toml"
    body = teacher.split(f"[exercise.{number}]", 1)[1].split("\n[exercise.")[0]
    leaked[name] = files[name].replace(
        f"[exercise.{number}]\n", f"[exercise.{number}]\n{body.strip()}\n", 1
    )
    problems = checker.live_problems(leaked, trials, control)
    assert any("the live check grades it" in p for p in problems), problems
    assert any("carries its key" in p for p in problems), problems


def test_an_assessed_box_without_its_key_says_the_teacher_marks_it(monkeypatch):
    # an installed screwkit: no teacher's keys
    monkeypatch.setenv("SCREWKIT_TEACHER_KEYS", "/nonexistent")
    exercises._key_file.cache_clear()
    try:
        verdict = exercises.check("screws", 10, "4")
        assert not verdict.correct and "teacher marks it" in verdict.message
        box = exercises.answer_box("screws", 10)
        assert "application/json" not in box._repr_html_()
        assert "sk.exercises.check" not in repr(box) and "assessed" in repr(box)
        with pytest.raises(exercises.AssessedError, match="teacher marks it"):
            exercises.answer_key("screws", 10)
        assert exercises.check("screws", 4, "0.5").correct  # the others still check
    finally:
        monkeypatch.delenv("SCREWKIT_TEACHER_KEYS")
        exercises._key_file.cache_clear()


def test_the_course_notebook_drops_an_assessed_box_way_to_check_it():
    plain = repr(exercises.answer_box("screws", 10, script=False))
    assert "sk.exercises.check" in plain  # from this checkout, with its key
    notebook = {
        "cells": [
            {
                "cell_type": "code",
                "source": 'sk.exercises.answer_box("screws", 10)',
                "outputs": [{"data": {"text/plain": [plain]}}],
            },
            {
                "cell_type": "code",
                "source": 'sk.exercises.answer_box("screws", 4)',
                "outputs": [
                    {
                        "data": {
                            "text/plain": [
                                repr(exercises.answer_box("screws", 4, script=False))
                            ]
                        }
                    }
                ],
            },
        ]
    }
    course = editions.course_notebook(notebook, {("screws", 10)})
    text = course["cells"][0]["outputs"][0]["data"]["text/plain"]
    assert "sk.exercises.check" not in text and "assessed" in text
    kept = course["cells"][1]["outputs"][0]["data"]["text/plain"]
    assert "sk.exercises.check" in kept
