"""The teacher's answers: each exercise's statement, answer key and solution, one file.

The course edition of the book (``make book EDITION=course``) has no solutions and no
key of the assessed exercises (book/assessed.yml); this script (``make answers``)
writes them for the teacher, chapter by chapter in the order of _toc.yml, to
``_build/answers/answers.md`` and ``answers.html`` (MathJax from the built book, when
``_build/html`` is there, renders the formulas).

Usage: python tools/teacher_answers.py [OUTPUT_DIR]   (default _build/answers)
"""

import html
import os
import sys

import yaml
from markdown_it import MarkdownIt
from mdit_py_plugins.dollarmath import dollarmath_plugin

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from exercise_syntax import read_exercises  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def chapters():
    with open(os.path.join(ROOT, "_toc.yml"), encoding="utf-8") as f:
        toc = yaml.safe_load(f)
    files = [c["file"] for part in toc["parts"] for c in part.get("chapters", [])]
    return [f.split("/", 1)[1] for f in files if f.startswith("notebooks/")]


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
    lines = [f"- answer: `{key['exact']}` = {key['values']} (shape {key['shape']})"]
    lines.append(f"- unit: {key['unit'] or '(none)'}")
    lines.append(f"- tolerance: {key['tolerance']} (relative {key.get('rtol', 0)})")
    for name in ("forms", "alternatives", "hint"):
        if key.get(name):
            lines.append(f"- {name}: {key[name]}")
    if key.get("range"):
        lines.append(f"- range: {key['range']['text']}")
    return "\n".join(lines)


def answers_markdown():
    marked = assessed()
    out = [
        "# Answers and solutions (for the teacher)",
        "",
        "Every exercise of the course, its answer key (self-checking exercises) and "
        "its solution. Exercises marked **assessed** (book/assessed.yml) have no key "
        "in the course edition of the book.",
    ]
    for chapter in chapters():
        with open(
            os.path.join(ROOT, "notebooks", f"{chapter}.md"), encoding="utf-8"
        ) as f:
            found = read_exercises(f.read(), chapter)
        out += ["", f"## {title(chapter)} (`{chapter}`)"]
        for exercise in found:
            number = exercise["number"]
            flag = " (assessed)" if (chapter, number) in marked else ""
            out += ["", f"### Exercise {number}{flag}", "", exercise["statement"]]
            if any("answer_box" in line for line in exercise["cells"]):
                out += ["", "**Key**", "", key_text(chapter, number)]
            out += ["", "**Solution**", "", exercise["solution"] or "(none written)"]
    return "\n".join(out) + "\n"


def answers_html(markdown, mathjax):
    parser = MarkdownIt("commonmark").enable("table").use(dollarmath_plugin)
    parser.add_render_rule(
        "math_inline", lambda r, s, i, *a: "\\(" + html.escape(s[i].content) + "\\)"
    )
    parser.add_render_rule(
        "math_block",
        lambda r, s, i, *a: "<div>\\[" + html.escape(s[i].content) + "\\]</div>\n",
    )
    config = '{"loader": {"load": ["input/tex", "output/chtml"]}}'
    script = (
        f"<script>window.MathJax = {config}</script>\n"
        f'<script defer src="{mathjax}"></script>\n'
        if mathjax
        else ""
    )
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        "<title>Answers and solutions (for the teacher)</title>\n"
        "<style>body{max-width:48rem;margin:auto;padding:1rem;font-family:sans-serif;"
        "line-height:1.5}pre{overflow-x:auto}</style>\n"
        f"{script}</head>\n<body>\n{parser.render(markdown)}</body>\n</html>\n"
    )


def main(folder):
    os.makedirs(folder, exist_ok=True)
    markdown = answers_markdown()
    with open(os.path.join(folder, "answers.md"), "w", encoding="utf-8") as f:
        f.write(markdown)
    mathjax = os.path.join(ROOT, "_build", "html", "_static", "mathjax", "startup.js")
    relative = os.path.relpath(mathjax, folder) if os.path.exists(mathjax) else None
    with open(os.path.join(folder, "answers.html"), "w", encoding="utf-8") as f:
        f.write(answers_html(markdown, relative))
    print(f"The teacher's answers: {folder}/answers.md and answers.html")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "_build", "answers"))
