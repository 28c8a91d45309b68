"""The teacher's answers: each exercise's statement, answer key and solution, one file.

The course edition of the book (``make book EDITION=course``) has no solutions and no
key of the assessed exercises (book/assessed.yml); this script (``make answers``)
writes them for the teacher, chapter by chapter in the order of _toc.yml, to
``_build/answers/answers.md`` and ``answers.html``. The HTML file carries MathJax inside
it (the self-contained TeX-to-SVG build, every TeX extension, from the same
sphinx-mathjax-offline package the book serves MathJax from), so its formulas show
wherever the file is copied or mailed, with no network and no book beside it.

Usage: python tools/teacher_answers.py [OUTPUT_DIR]   (default _build/answers)
"""

import html
import importlib.util
import os
import sys

import yaml
from markdown_it import MarkdownIt
from mdit_py_plugins.dollarmath import dollarmath_plugin

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

from convert_exercises import read_exercises  # noqa: E402

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
    # MathJax's combined build: TeX in, SVG out (glyphs as paths, no font files), all
    # extensions (nothing is fetched later); inline, so the file stands alone. Its
    # defaults read \( \) and \[ \], as the render rules above write.
    script = f"<script>\n{mathjax}\n</script>\n" if mathjax else ""
    return (
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        "<title>Answers and solutions (for the teacher)</title>\n"
        "<style>body{max-width:48rem;margin:auto;padding:1rem;font-family:sans-serif;"
        "line-height:1.5}pre{overflow-x:auto}</style>\n"
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


def main(folder):
    os.makedirs(folder, exist_ok=True)
    markdown = answers_markdown()
    with open(os.path.join(folder, "answers.md"), "w", encoding="utf-8") as f:
        f.write(markdown)
    with open(os.path.join(folder, "answers.html"), "w", encoding="utf-8") as f:
        f.write(answers_html(markdown, mathjax_script()))
    print(f"The teacher's answers: {folder}/answers.md and answers.html")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "_build", "answers"))
