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
    course = editions.course_notebook(notebook, {("screws", 10)})
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
