"""tools/teacher_answers.py: the exercises grouped by week of the course plan, each with
its tag and its solution's mark scheme; the students' sheets from seeds; answers.html
stands alone. Its formulas are typeset by the MathJax it carries (no file beside it, no
network), checked in headless Chromium where there is one (`make test-all`; the browser
tier); its figures are the notebooks' stored PNGs, inside it, with their alt text."""

import base64
import html
import importlib.util
import json
import re
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def tool():
    spec = importlib.util.spec_from_file_location(
        "teacher_answers", ROOT / "tools" / "teacher_answers.py"
    )
    module = importlib.util.module_from_spec(spec)
    sys.modules["teacher_answers"] = module
    spec.loader.exec_module(module)
    return module


@pytest.fixture(scope="module")
def folder(tool, tmp_path_factory):
    folder = tmp_path_factory.mktemp("answers")
    seeds = folder / "class.csv"
    seeds.write_text("student,seed\nada,3\nbob,7\n", encoding="utf-8")
    tool.main(str(folder), str(seeds))
    return folder


@pytest.fixture(scope="module")
def answers(folder):
    return (folder / "answers.html").read_text(encoding="utf-8")


def test_answers_go_week_by_week_with_their_tags(folder):
    text = (folder / "answers.md").read_text(encoding="utf-8")
    weeks = re.findall(r"^## Week (\d+): ", text, re.M)
    assert weeks == [str(n) for n in range(1, len(weeks) + 1)] and len(weeks) >= 14
    week_5 = text.split("\n## Week 5: ", 1)[1].split("\n## Week 6: ", 1)[0]
    assert "\n### Mobility of parallel manipulators (`mobility`)\n" in week_5
    # mobility exercise 3's tag, from notebooks/mobility.md, as its header
    exercise_3 = week_5.split("\n#### Exercise 3\n", 1)[1]
    assert exercise_3.startswith("\n*self-checking · difficulty 2 · practises: ")
    assert "\n#### Exercise 7 (assessed)\n" in week_5
    # a figure exercise carries its drawing (the image, then its code), an answer
    # box's cell is left out
    exercise_11 = week_5.split("\n#### Exercise 11\n", 1)[1].split("\n#### ", 1)[0]
    drawing = exercise_11.split("\n**Figure**\n", 1)[1].split("\n**Key**\n")[0]
    assert "](figures/mobility-exercise-11-1.png)" in drawing
    assert (folder / "figures" / "mobility-exercise-11-1.png").is_file()
    assert "sketch([[O, A], [A, B], [B, C]]" in drawing
    assert "answer_box" not in drawing and ":mystnb:" not in drawing
    # configuration space exercise 10 is assigned in week 2
    week_2 = text.split("\n## Week 2: ", 1)[1].split("\n## Week 3: ", 1)[0]
    assert "(`configuration_space`)\n\n#### Exercise 10\n" in week_2


def test_an_exam_problem_shows_its_points(tool):
    exam = {
        "number": 1,
        "kinds": ["exam", "by hand"],
        "difficulty": 3,
        "sections": ["Rigid bodies"],
        "solution": "Words.\n\n**Mark scheme** (5 points)\n- (a) 2 points: x\n"
        "- (b) 3 points: y",
    }
    assert tool.header(exam) == (
        "*exam, by hand · difficulty 3 · 5 points: (a) 2, (b) 3 · "
        "practises: Rigid bodies*"
    )
    assert "no mark scheme" in tool.header({**exam, "solution": "Words."})
    plan = [
        {"number": 1, "title": "A", "chapter": "a", "exercises": [("a", [1])]},
        {"number": 2, "title": "B", "chapter": "b", "exercises": [("a", [2])]},
    ]
    found = {"a": [{"number": 1}, {"number": 2}, {"number": 3}], "c": [{"number": 1}]}
    grouped = [
        (heading, [(c, [e["number"] for e in es]) for c, es in groups])
        for heading, groups in tool.by_week(found, plan)
    ]
    assert grouped == [
        ("Week 1: A", [("a", [1, 3])]),
        ("Week 2: B", [("a", [2])]),
        ("Not in the course plan", [("c", [1])]),
    ]


def test_seeds_give_each_student_a_sheet_and_the_teacher_every_key(folder):
    from screwkit import exercises

    found = exercises.parametrised()
    assert found, "no parametrised exercise to put on a sheet"
    rows = (folder / "keys.csv").read_text(encoding="utf-8").strip().split("\n")
    assert len(rows) == 1 + 2 * len(found)
    chapter, number = found[0]
    for student, seed in (("ada", 3), ("bob", 7)):
        sheet = (folder / "sheets" / f"{student}.md").read_text(encoding="utf-8")
        assert exercises.variant(chapter, number, seed).statement in sheet
        assert f"seed={seed})`" in sheet


def test_answers_html_loads_nothing_from_elsewhere(answers):
    assert not re.search(r"<script[^>]*\bsrc=", answers)
    assert not re.search(r"<link[^>]*\bhref=", answers)
    assert answers.count("<script>") == 1 and "MathJax" in answers
    assert "\\(" in answers and "\\[" in answers  # formulas, inline and displayed


def test_answers_html_typesets_its_formulas_alone(answers, tmp_path, chromium):
    path = tmp_path / "copied" / "answers.html"  # copied alone, elsewhere
    path.parent.mkdir()
    path.write_text(answers, encoding="utf-8")
    page = chromium.new_page()
    requests = []
    page.on("request", lambda r: requests.append(r.url))
    # generous timeouts: the file grows with the bank, and the tier shares CPUs
    page.goto(path.as_uri(), timeout=180_000)
    page.wait_for_function(
        "window.MathJax && MathJax.startup && MathJax.startup.promise",
        timeout=180_000,
    )
    page.evaluate("MathJax.startup.promise")
    typeset = page.locator("mjx-container svg").count()
    errors = page.locator("mjx-merror").count()
    # the text left untypeset, code aside (MathJax skips <pre> and <code>)
    left = page.evaluate(
        "() => { const body = document.body.cloneNode(true);"
        " body.querySelectorAll('pre, code, mjx-container')"
        ".forEach(e => e.remove()); return body.textContent; }"
    )
    # every figure decoded and drawn from the data inside the file
    broken = page.evaluate(
        "() => [...document.images].filter(i => !i.complete || !i.naturalWidth)"
        ".map(i => i.alt)"
    )
    assert [url for url in requests if url != path.as_uri()] == []
    assert typeset > 100 and errors == 0
    assert page.locator("img").count() >= 100 and broken == []
    assert "\\(" not in left and "\\[" not in left


def alt_in_the_source(chapter, code):
    """The alt text of the code cell of notebooks/CHAPTER.md holding ``code``: its
    folded ``alt: >-`` option, read here from the cell's option lines."""
    source = (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")
    cell = source[: source.index(code)].rsplit("```{code-cell}", 1)[1]
    folded = cell.split(":    alt: >-\n", 1)[1].split("\n\n", 1)[0]
    return " ".join(line.removeprefix(":").strip() for line in folded.split("\n"))


def png_in_the_notebook(chapter, code):
    """The image/png output stored in notebooks/CHAPTER.ipynb for the one code cell
    whose source holds ``code``."""
    notebook = json.loads(
        (ROOT / "notebooks" / f"{chapter}.ipynb").read_text(encoding="utf-8")
    )
    (cell,) = [
        c
        for c in notebook["cells"]
        if c["cell_type"] == "code" and code in "".join(c["source"])
    ]
    (png,) = [o["data"]["image/png"] for o in cell["outputs"] if "data" in o]
    return "".join("".join(png).split())


def test_a_figure_exercise_shows_its_image_with_its_alt_text(answers, folder):
    # redundancy exercise 5 draws its arm in a hide-input cell of the chapter
    code = 'sketch([1, 1, 1], [0, 90, -90], "three 1 m links'
    alt = alt_in_the_source("redundancy", code)
    assert alt.startswith("A planar three-link arm with 1 m links at q = (0, 90, -90)")
    png = png_in_the_notebook("redundancy", code)
    assert base64.b64decode(png).startswith(b"\x89PNG\r\n\x1a\n")
    chapter = answers.split("(<code>redundancy</code>)</h3>", 1)[1]
    exercise = chapter.split("<h4>Exercise 5</h4>", 1)[1].split("<h4>", 1)[0]
    image = f'<img src="data:image/png;base64,{png}" alt="{html.escape(alt)}">'
    assert image in exercise
    # inside the file, nothing beside it: every image a data URI
    assert re.findall(r'<img src="(?!data:image/png;base64,)', answers) == []
    assert answers.count("<img ") >= 100
    # answers.md shows the same image from the file beside it
    assert (folder / "figures" / "redundancy-exercise-5-1.png").read_bytes() == (
        base64.b64decode(png)
    )


def test_every_figure_exercise_shows_an_image(folder):
    text = (folder / "answers.md").read_text(encoding="utf-8")
    without, count = [], 0
    for part in re.split(r"\n### ", text)[1:]:
        chapter = re.match(r".*\(`(\w+)`\)\n", part).group(1)
        for exercise in re.split(r"\n#### ", part)[1:]:
            kinds = exercise.split("\n\n*", 1)[1].split(" · ", 1)[0].split(", ")
            if "figure" in kinds:
                count += 1
                if "](figures/" not in exercise:
                    without.append((chapter, exercise.split("\n", 1)[0]))
    assert count >= 100 and without == [], without


def test_a_gated_solution_shows_its_drawing(tool, tmp_path, monkeypatch):
    # a made-up chapter whose solution runs a drawing cell and a cell that prints
    # (solution-start/-end)
    (tmp_path / "notebooks").mkdir()
    cell = "```{code-cell} ipython3\n:tags: [hide-input]\n\nplt.plot([0, 1])\n```"
    printing = "```{code-cell} ipython3\nprint(2)\n```"
    source = (
        ":::{exercise}\n:label: demo-exercise-1\n\n*(by hand; difficulty 1; "
        "practises: A)*\nDraw it.\n:::\n\n:::{solution-start} demo-exercise-1\n"
        f":class: dropdown\n:::\n\nThe line:\n\n{cell}\n\nIts rise:\n\n{printing}\n\n"
        ":::{solution-end}\n:::\n"
    )
    png = base64.b64encode(b"\x89PNG\r\n\x1a\nmade up").decode()
    # an alt text with what Markdown and HTML would read: it comes through as written
    alt = "A [rising] *line*_x: $1$ <b> & \\ done!"
    notebook = {
        "cells": [
            {
                "cell_type": "markdown",
                "source": ":::{solution-start} demo-exercise-1\n:::\nThe line:",
            },
            {
                "cell_type": "code",
                "metadata": {"mystnb": {"image": {"alt": alt}}},
                "source": "plt.plot([0, 1])",
                "outputs": [{"data": {"image/png": png + "\n"}}],
            },
            {"cell_type": "markdown", "source": "Its rise:"},
            {
                "cell_type": "code",
                "metadata": {},
                "source": "print(2)",
                "outputs": [{"output_type": "stream", "text": "2\n"}],
            },
            {"cell_type": "markdown", "source": ":::{solution-end}\n:::"},
        ]
    }
    (tmp_path / "notebooks" / "demo.ipynb").write_text(json.dumps(notebook))
    monkeypatch.setattr(tool, "ROOT", str(tmp_path))
    stored = tool.notebook_figures("demo")
    assert stored == {("solution", "demo-exercise-1"): [[(alt, png)], []]}
    (exercise,) = tool.read_exercises(source, "demo")
    figures = {}
    text = tool.solution_markdown("demo", exercise, stored, figures)
    assert figures == {"figures/demo-solution-1-1.png": png}
    assert "{code-cell}" not in text and ":tags:" not in text
    # the drawing's code folded under its image, the other cell's code as it is
    assert text.index("](figures/demo-solution-1-1.png)") < text.index("plt.plot(")
    assert "```python\nprint(2)\n```" in text and text.count("<details>") == 1
    page = tool.answers_html(text, "", figures)
    assert f'<img src="data:image/png;base64,{png}" alt="{html.escape(alt)}">' in page
    # a notebook out of step with its source is refused, naming the command
    with pytest.raises(SystemExit, match="make notebooks"):
        tool.solution_markdown("demo", exercise, {}, {})
