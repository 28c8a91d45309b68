"""The teacher's answers: each exercise's statement, answer key and solution, one file.

The exercises are grouped by week of book/course_plan.md (the week whose Exercises line
lists them, else the week of their chapter), each under a header with its kinds,
difficulty and the sections it practises (its tag), an exam problem with its points;
its solution carries the mark scheme, points per part.

The course edition of the book (``make book EDITION=course``) has no solutions and no
key of the assessed exercises (book/assessed.yml); this script (``make answers``)
writes them for the teacher, chapter by chapter in the order of _toc.yml, to
``_build/answers/answers.md`` and ``answers.html``. The HTML file carries MathJax inside
it (the self-contained TeX-to-SVG build, every TeX extension, from the same
sphinx-mathjax-offline package the book serves MathJax from), so its formulas show
wherever the file is copied or mailed, with no network and no book beside it. So do
its figures: the drawings that the chapters' code cells make inside an exercise or a
solution (``exercise-start``/``-end``, ``solution-start``/``-end``) are the PNG outputs
stored in notebooks/CHAPTER.ipynb, matched to their exercise by those markers and put in
answers.html as data URIs, with the cells' alt text; answers.md shows the same images
from the files beside it, ``figures/CHAPTER-exercise-N-K.png``.

The keys of the assessed exercises are not in the package (a student's screwkit has
none): they live in book/teacher_keys/, which screwkit reads from this checkout.

With ``--seeds class.csv`` (columns ``student,seed``; ``make answers SEEDS=class.csv``)
it also writes, for the parametrised exercises (``sk.exercises.variant``), one sheet
per student with their numbers, ``OUTPUT_DIR/sheets/STUDENT.md``, and the teacher's
keys of every student, ``OUTPUT_DIR/keys.csv`` (student, seed, chapter, number, key,
unit), computed by screwkit from the seeds.

Usage: python tools/teacher_answers.py [OUTPUT_DIR] [--seeds CSV]
(default _build/answers)
"""

import argparse
import base64
import binascii
import csv
import html
import importlib.util
import json
import os
import re
import shutil
import sys

import yaml
from markdown_it import MarkdownIt
from mdit_py_plugins.dollarmath import dollarmath_plugin

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from course_plan import toc_chapters, weeks  # noqa: E402
from exercise_syntax import mark_scheme, read_exercises  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# the keys of the assessed exercises, which the package does not hold
os.environ.setdefault(
    "SCREWKIT_TEACHER_KEYS", os.path.join(ROOT, "book", "teacher_keys")
)


def chapters():
    return toc_chapters(ROOT)


def assessed():
    with open(os.path.join(ROOT, "book", "assessed.yml"), encoding="utf-8") as f:
        table = yaml.safe_load(f) or {}
    return {(c, int(n)) for c, ns in table.items() for n in ns or []}


def title(chapter):
    with open(os.path.join(ROOT, "notebooks", f"{chapter}.md"), encoding="utf-8") as f:
        for line in f:
            if line.startswith("# "):
                return line[2:].strip()
    return chapter


def key_text(chapter, number):
    """The answer key of a self-checking exercise, as a Markdown list."""
    from screwkit import exercises

    key = exercises.answer_key(chapter, number)
    if number in exercises.parametrised(chapter):
        key["exact"] = "parametrised (sk.exercises.variant): seed 0, " + key["exact"]
    lines = [f"- answer: `{key['exact']}` = {key['values']} (shape {key['shape']})"]
    if key.get("units"):
        lines.append(f"- units: {', '.join(key['units'])}")
    else:
        lines.append(f"- unit: {key['unit'] or '(none)'} ({key['quantity']})")
    lines.append(f"- tolerance: {key['tolerance']} (relative {key.get('rtol', 0)})")
    for name in ("forms", "alternatives", "hint"):
        if key.get(name):
            lines.append(f"- {name}: {key[name]}")
    if key.get("range"):
        lines.append(f"- range: {key['range']['text']}")
    return "\n".join(lines)


def plan():
    """The weeks of book/course_plan.md (tools/course_plan.py)."""
    path = os.path.join(ROOT, "book", "course_plan.md")
    with open(path, encoding="utf-8") as f:
        return weeks(f.read())


def by_week(found, plan_weeks):
    """``found`` ({chapter: exercises}, in the book's order) grouped by week:
    [(heading, [(chapter, [exercises])])], each exercise in the week whose Exercises
    line lists it, else in its chapter's week; the week's own chapter first."""
    listed, home = {}, {}
    for week in plan_weeks:
        home.setdefault(week["chapter"], week["number"])
        for chapter, numbers in week["exercises"]:
            for number in numbers:
                listed.setdefault((chapter, number), week["number"])
    headings = {w["number"]: f"Week {w['number']}: {w['title']}" for w in plan_weeks}
    groups = {}
    for chapter, exercises in found.items():
        for exercise in exercises:
            week = listed.get((chapter, exercise["number"]), home.get(chapter))
            groups.setdefault(week, {}).setdefault(chapter, []).append(exercise)
    out = []
    for week in sorted(groups, key=lambda w: (w is None, w or 0)):
        own = [w["chapter"] for w in plan_weeks if w["number"] == week]
        chapters_of = sorted(groups[week], key=lambda c: c not in own)
        heading = headings.get(week, "Not in the course plan")
        out.append((heading, [(c, groups[week][c]) for c in chapters_of]))
    return out


def header(exercise):
    """The line under an exercise's heading: its kinds, difficulty and sections."""
    if exercise["kinds"] is None:
        return "*(no tag)*"
    words = [", ".join(exercise["kinds"]), f"difficulty {exercise['difficulty']}"]
    if "exam" in exercise["kinds"]:
        try:
            total, points = mark_scheme(exercise["solution"])
            parts = ", ".join(f"({p}) {k}" for p, k in points.items())
            words.append(f"{total} points: {parts}")
        except ValueError:
            words.append("no mark scheme")
    words.append("practises: " + " / ".join(exercise["sections"]))
    return "*" + " · ".join(words) + "*"


def code_cells(lines):
    """The code of each code cell among ``lines`` (a chapter's MyST lines), its
    options (tags, alt text) left out, in order."""
    cells, current = [], None
    for line in lines:
        if current is None:
            current = [] if line.startswith("```{code-cell}") else None
        elif line.startswith("```"):
            cells.append("\n".join(current).strip())
            current = None
        elif not line.startswith(":"):  # the cell's options (tags, alt text)
            current.append(line)
    return cells


#: The opening or the end of a gated exercise or solution, whose code cells the
#: notebook runs: ``:::{exercise-start}`` (its label on a ``:label:`` line below it),
#: ``:::{solution-start} LABEL``, ``:::{exercise-end}``, ``:::{solution-end}``.
GATE = re.compile(r"^:{3,}\{(exercise|solution)-(start|end)\}\s*(\S*)\s*$")
LABEL = re.compile(r"^:label:\s*(\S+)\s*$")


def notebook_figures(chapter):
    """The figures that notebooks/CHAPTER.ipynb stores for the code cells inside its
    exercises and solutions: {(kind, label): [[(alt, png), ...] for each code cell]},
    kind ``"exercise"`` or ``"solution"``, png an image/png output (base64 text) and
    alt the cell's alt text (``mystnb: image: alt``), or None."""
    path = os.path.join(ROOT, "notebooks", f"{chapter}.ipynb")
    with open(path, encoding="utf-8") as f:
        cells = json.load(f)["cells"]
    found, block = {}, None
    for cell in cells:
        if cell["cell_type"] == "markdown":
            fenced = False
            for line in "".join(cell["source"]).split("\n"):
                fenced ^= line.startswith("```")
                gate = None if fenced else GATE.match(line)
                if gate:
                    kind, edge, label = gate.groups()
                    block = [kind, label or None] if edge == "start" else None
                elif block and block[1] is None and LABEL.match(line):
                    block[1] = LABEL.match(line).group(1)
        elif cell["cell_type"] == "code" and block:
            alt = cell["metadata"].get("mystnb", {}).get("image", {}).get("alt")
            images = []
            for output in cell.get("outputs", []):
                png = output.get("data", {}).get("image/png")
                if png:
                    png = "".join(png) if isinstance(png, list) else png
                    images.append((alt, "".join(png.split())))
            found.setdefault(tuple(block), []).append(images)
    return found


def _alt_text(alt):
    """``alt`` as the text of a Markdown image: one line, its marks that Markdown
    would read escaped (no bracket ends it, no dollar opens a formula, no star or
    underscore makes emphasis, no angle bracket or ampersand makes HTML)."""
    return re.sub(r"([\\`*_\[\]<>&$!])", r"\\\1", " ".join(alt.split()))


def drawing_markdown(code, images, name, figures):
    """A code cell in Markdown: its images, files ``figures/NAME-K.png`` (K from 1;
    their base64 text kept in ``figures``, {path: png}), then its code, folded
    under them (a cell that draws nothing: its code alone)."""
    out = []
    for alt, png in images:
        drawn = sum(path.startswith(f"figures/{name}-") for path in figures)
        path = f"figures/{name}-{drawn + 1}.png"
        figures[path] = png
        alt = alt or f"A figure of {name.replace('-', ' ')} (the chapter gives no alt)"
        out += [f"![{_alt_text(alt)}]({path})", ""]
    fenced = ["```python", code, "```"]
    if not images:
        return "\n".join(fenced)
    out += ["<details><summary>Drawn in the chapter by</summary>", "", *fenced]
    return "\n".join(out + ["", "</details>"])


def figures_of(chapter, kind, label, codes, stored):
    """The image lists of the code cells of one exercise or solution, ``codes`` (from
    the .md), which ``stored`` (:func:`notebook_figures`) must match one to one."""
    images = stored.get((kind, label), [])
    if len(images) != len(codes):
        raise SystemExit(
            f"notebooks/{chapter}.ipynb has {len(images)} code cells in the {kind} "
            f"{label} and notebooks/{chapter}.md has {len(codes)}: run `make "
            f"notebooks` (or tools/execute_notebooks.py notebooks/{chapter}.md)"
        )
    return images


def exercise_figures(chapter, exercise, stored, figures):
    """The Markdown of an exercise's drawings (its answer box's cell left out)."""
    codes = code_cells(exercise["cells"])
    images = figures_of(chapter, "exercise", exercise["label"], codes, stored)
    name = f"{chapter}-exercise-{exercise['number']}"
    return "\n\n".join(
        drawing_markdown(code, pictures, name, figures)
        for code, pictures in zip(codes, images, strict=True)
        if "answer_box(" not in code
    )


def solution_markdown(chapter, exercise, stored, figures):
    """An exercise's solution, each of its code cells (a gated solution's) replaced
    by its drawings and its folded code."""
    solution = exercise["solution"]
    if solution is None:
        return "(none written)"
    lines = solution.split("\n")
    codes = code_cells(lines)
    if not codes:
        return solution
    images = iter(figures_of(chapter, "solution", exercise["label"], codes, stored))
    name = f"{chapter}-solution-{exercise['number']}"
    out, inside, k = [], False, 0
    for line in lines:
        if not inside and line.startswith("```{code-cell}"):
            inside = True
        elif inside and line.startswith("```"):
            out += ["", drawing_markdown(codes[k], next(images), name, figures), ""]
            inside, k = False, k + 1
        elif not inside:
            out.append(line)
    return "\n".join(out)


def answers_markdown(figures=None):
    """The teacher's answers in Markdown; the drawings' images go to ``figures``
    ({path: base64 PNG text}, a dict to fill), which the Markdown names."""
    figures = {} if figures is None else figures
    marked = assessed()
    out = [
        "# Answers and solutions (for the teacher)",
        "",
        "Every exercise of the course, week by week as book/course_plan.md assigns "
        "them: its kinds, difficulty and sections, its answer key (self-checking "
        "exercises) and its solution, with the mark scheme of each exam problem. "
        "Exercises marked **assessed** (book/assessed.yml) have no key in the course "
        "edition of the book.",
    ]
    found, stored = {}, {}
    for chapter in chapters():
        path = os.path.join(ROOT, "notebooks", f"{chapter}.md")
        with open(path, encoding="utf-8") as f:
            found[chapter] = read_exercises(f.read(), chapter)
        stored[chapter] = notebook_figures(chapter)
    for heading, groups in by_week(found, plan()):
        out += ["", f"## {heading}"]
        for chapter, exercises in groups:
            out += ["", f"### {title(chapter)} (`{chapter}`)"]
            for exercise in exercises:
                number = exercise["number"]
                flag = " (assessed)" if (chapter, number) in marked else ""
                out += ["", f"#### Exercise {number}{flag}", "", header(exercise)]
                out += ["", exercise["statement"]]
                drawing = exercise_figures(chapter, exercise, stored[chapter], figures)
                if drawing:
                    out += ["", "**Figure**", "", drawing]
                if any("answer_box" in line for line in exercise["cells"]):
                    out += ["", "**Key**", "", key_text(chapter, number)]
                solution = solution_markdown(
                    chapter, exercise, stored[chapter], figures
                )
                out += ["", "**Solution**", "", solution]
    return "\n".join(out) + "\n"


def answers_html(markdown, mathjax, figures=None):
    """The page of ``markdown``, MathJax (its text) inline, and each image that
    ``figures`` holds ({path: base64 PNG text}) inline as a data URI."""
    figures = figures or {}
    parser = MarkdownIt("commonmark").enable("table").use(dollarmath_plugin)

    def image(renderer, tokens, i, options, env):
        source = tokens[i].attrGet("src")
        if source in figures:
            source = "data:image/png;base64," + figures[source]
        # the text of the alt, its escaped marks (text_special tokens) included
        alt = "".join(child.content for child in tokens[i].children or [])
        return f'<img src="{html.escape(source)}" alt="{html.escape(alt)}">'

    parser.add_render_rule("image", image)
    parser.add_render_rule(
        "math_inline", lambda r, s, i, *a: "\\(" + html.escape(s[i].content) + "\\)"
    )
    parser.add_render_rule(
        "math_block",
        lambda r, s, i, *a: "<div>\\[" + html.escape(s[i].content) + "\\]</div>\n",
    )
    # MathJax's combined build: TeX in, SVG out (glyphs as paths, no font files), all
    # extensions (nothing is fetched later); inline, so the file stands alone. Its
    # defaults read \( \) and \[ \], as the render rules above write.
    script = f"<script>\n{mathjax}\n</script>\n" if mathjax else ""
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        "<title>Answers and solutions (for the teacher)</title>\n"
        "<style>body{max-width:48rem;margin:auto;padding:1rem;font-family:sans-serif;"
        "line-height:1.5}pre{overflow-x:auto}img{max-width:100%;height:auto}"
        "</style>\n"
        f"{script}</head>\n<body>\n{parser.render(markdown)}</body>\n</html>\n"
    )


def mathjax_script():
    """The text of MathJax's tex-svg-full.js from the sphinx-mathjax-offline package
    (requirements.txt), checked to hold no end of a script element."""
    spec = importlib.util.find_spec("sphinx-mathjax-offline")
    if spec is None or not spec.submodule_search_locations:
        raise SystemExit(
            "the package sphinx-mathjax-offline is missing: "
            "run `pip install -r requirements.txt`"
        )
    folder = list(spec.submodule_search_locations)[0]
    path = os.path.join(folder, "static", "mathjax", "tex-svg-full.js")
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if "</script" in text.lower():
        raise SystemExit(f"{path} contains '</script': it cannot be inlined")
    return text


def read_seeds(path):
    """[(student, seed)] from a CSV with columns student and seed."""
    with open(path, encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(f))
    if not rows or not {"student", "seed"} <= set(rows[0]):
        raise ValueError(f"{path} must have the columns student and seed")
    out, seen = [], set()
    for row in rows:
        student, seed = row["student"].strip(), row["seed"].strip()
        if not re.fullmatch(r"[A-Za-z0-9_.-]+", student) or student in seen:
            raise ValueError(
                f"{path}: student names must be unique file names, got {student!r}"
            )
        if not seed.isdigit():
            raise ValueError(
                f"{path}: {student}'s seed must be a whole number >= 0, got {seed!r}"
            )
        seen.add(student)
        out.append((student, int(seed)))
    return out


def sheets(folder, seeds):
    """One sheet per student (their numbers) and keys.csv (every student's keys)."""
    from screwkit import exercises

    os.makedirs(os.path.join(folder, "sheets"), exist_ok=True)
    found = exercises.parametrised()
    with open(os.path.join(folder, "keys.csv"), "w", encoding="utf-8", newline="") as f:
        table = csv.writer(f)
        table.writerow(["student", "seed", "chapter", "number", "key", "unit"])
        for student, seed in seeds:
            lines = [f"# Your exercises ({student}, seed {seed})", ""]
            for chapter, number in found:
                v = exercises.variant(chapter, number, seed)
                lines += [f"## {title(chapter)}, exercise {number}", "", v.statement]
                lines += [
                    "",
                    f"Check it: `sk.exercises.check({chapter!r}, {number}, "
                    f"answer, seed={seed})`",
                    "",
                ]
                values = ", ".join(f"{x:.6g}" for x in v.key["values"])
                table.writerow([student, seed, chapter, number, values, v.key["unit"]])
            path = os.path.join(folder, "sheets", f"{student}.md")
            with open(path, "w", encoding="utf-8") as sheet:
                sheet.write("\n".join(lines))
    return len(seeds) * len(found)


def write_figures(folder, figures):
    """The drawings' PNG files beside answers.md (``figures/``, emptied first)."""
    shutil.rmtree(os.path.join(folder, "figures"), ignore_errors=True)
    os.makedirs(os.path.join(folder, "figures"))
    for path, png in figures.items():
        try:
            data = base64.b64decode(png, validate=True)
        except binascii.Error as error:
            raise SystemExit(f"{path}: the stored PNG is not base64: {error}") from None
        with open(os.path.join(folder, path), "wb") as f:
            f.write(data)


def main(folder, seeds=None):
    os.makedirs(folder, exist_ok=True)
    figures = {}
    markdown = answers_markdown(figures)
    with open(os.path.join(folder, "answers.md"), "w", encoding="utf-8") as f:
        f.write(markdown)
    write_figures(folder, figures)
    with open(os.path.join(folder, "answers.html"), "w", encoding="utf-8") as f:
        f.write(answers_html(markdown, mathjax_script(), figures))
    print(
        f"The teacher's answers: {folder}/answers.md (its {len(figures)} figures in "
        f"figures/) and answers.html (the figures inside it)"
    )
    if seeds:
        count = sheets(folder, read_seeds(seeds))
        print(
            f"The students' sheets: {folder}/sheets/, their keys ({count}): "
            f"{folder}/keys.csv"
        )


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "folder", nargs="?", default=os.path.join(ROOT, "_build", "answers")
    )
    parser.add_argument("--seeds", help="a CSV with columns student,seed")
    arguments = parser.parse_args()
    main(arguments.folder, arguments.seeds)
