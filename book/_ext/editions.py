"""Two editions of one book: self-study (every solution, every key) and course.

The chapters write their exercises with sphinx-exercise's directives
(``exercise``/``exercise-start``, ``solution``; tools/exercise_syntax.py), labelled
``CHAPTER-exercise-N``.

* Numbers: Sphinx numbers enumerable nodes across the whole book when the table of
  contents is not numbered (the exercises of the third chapter would be 21 to 30); each
  exercise is shown with the number of its label instead, the chapter's own.
* The course edition, ``SCREWKIT_EDITION=course`` (``make book EDITION=course``):
  sphinx-exercise's ``hide_solutions`` drops every solution, and the answer box of each
  exercise listed in ``book/assessed.yml`` loses its key (the JSON the page checks
  with) and its Check button: the page says that the teacher marks it. The other boxes
  still check. The copies of the notebooks offered for download (``_sources``) get the
  same treatment (an assessed box's plain text no longer says how to check it), and
  the pages have no launch buttons (Binder, Colab, a hub), which would open the
  repository's notebooks with their solutions, and no button to the repository (nor
  its issues, a page's source), which holds the solutions and the teacher's keys.
  Both editions show the notebooks' stored outputs (the book executes nothing).
"""

import json
import os
import re

import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
ASSESSED = os.path.normpath(os.path.join(HERE, os.pardir, "assessed.yml"))
LABEL = re.compile(r"^([a-z0-9_]+)-exercise-(\d+)$")
BOX = re.compile(
    r'<div class="sk-answer-box" id="sk-exercise-([a-z0-9_]+)-(\d+)-\d+".*?'
    r"</noscript>\n</div>",
    re.S,
)
SOLUTION = re.compile(r"^(:{3,})\{solution(?:-start)?\}")
#: sphinx-book-theme's options of the buttons that link to the repository
REPOSITORY_BUTTONS = (
    "use_repository_button",
    "use_issues_button",
    "use_edit_page_button",
    "use_source_button",
)
#: the plain text of an assessed box (AnswerBox's repr says how to check it)
PLAIN_BOX = re.compile(r"^Answer box for ([a-z0-9_]+) exercise (\d+) \(.*\)$", re.S)


def edition():
    """'course' or 'self-study', from the environment variable SCREWKIT_EDITION."""
    value = os.environ.get("SCREWKIT_EDITION", "self-study") or "self-study"
    if value not in ("course", "self-study"):
        raise ValueError(
            f"SCREWKIT_EDITION must be 'course' or 'self-study', got {value!r}"
        )
    return value


def assessed(path=ASSESSED):
    """The assessed exercises of book/assessed.yml: a set of (chapter, number)."""
    with open(path, encoding="utf-8") as f:
        table = yaml.safe_load(f) or {}
    return {(chapter, int(n)) for chapter, ns in table.items() for n in ns or []}


def strip_keys(text, marked):
    """``text`` (HTML) with each answer box of an exercise in ``marked`` replaced by a
    box with no key: its label and a note that the teacher marks the answer."""

    def replace(match):
        chapter, number = match.group(1), int(match.group(2))
        if (chapter, number) not in marked:
            return match.group(0)
        return (
            f'<div class="sk-assessed-box" style="font:14px sans-serif;margin:0.5em 0">'
            f"<p><strong>Exercise {number} is assessed:</strong> hand your answer to "
            f"your teacher; this edition of the book does not check it.</p></div>"
        )

    return BOX.sub(replace, text)


def strip_solutions(source):
    """A chapter's MyST text without its ``solution`` blocks."""
    lines, out, i = source.split("\n"), [], 0
    while i < len(lines):
        match = SOLUTION.match(lines[i])
        if not match:
            out.append(lines[i])
            i += 1
            continue
        colons, fence = match.group(1), None
        i += 1
        while i < len(lines):
            line = lines[i]
            i += 1
            if fence is not None:
                fence = None if line.strip() == fence else fence
            elif re.match(r"^(`{3,}|~{3,})", line):
                fence = re.match(r"^(`{3,}|~{3,})", line).group(1)
            elif line.strip() == colons:
                break
    return "\n".join(out)


def course_notebook(notebook, marked):
    """A notebook (as JSON) for the course edition: no solution, no assessed key.

    A code cell tagged ``solution`` (the hidden cell that draws a solution's figure,
    glued into the solution by myst-nb) goes with the solutions."""
    notebook["cells"] = [
        cell
        for cell in notebook.get("cells", [])
        if "solution" not in cell.get("metadata", {}).get("tags", [])
    ]
    for cell in notebook["cells"]:
        text = "".join(cell.get("source", ""))
        if cell.get("cell_type") == "markdown":
            cell["source"] = strip_solutions(text)
        for output in cell.get("outputs", []):
            data = output.get("data", {})
            if "text/html" in data:
                html = "".join(data["text/html"])
                data["text/html"] = strip_keys(html, marked)
            if "text/plain" in data:
                data["text/plain"] = strip_plain("".join(data["text/plain"]), marked)
    return notebook


def strip_plain(text, marked):
    """The plain text of an answer box (its repr), with an assessed one's way to
    check it replaced by a note that the teacher marks it."""
    match = PLAIN_BOX.match(text.strip())
    if match is None or (match.group(1), int(match.group(2))) not in marked:
        return text
    return (
        f"Exercise {match.group(2)} of {match.group(1)} is assessed: hand your "
        f"answer to your teacher, who marks it."
    )


def numbers_from_labels(app, env):
    """Show each exercise with the number its label carries."""
    for fignumbers in env.toc_fignumbers.values():
        for label in list(fignumbers.get("exercise", {})):
            match = LABEL.match(label)
            if match:
                fignumbers["exercise"][label] = (int(match.group(2)),)
    return []


def course_config(app, config):
    if edition() != "course":
        return
    config.hide_solutions = True
    # pages say what differs with {only} course / {only} not course (book/how_to_use.md)
    app.tags.add("course")
    # Binder, Colab and a hub would open the repository's notebooks, which hold every
    # solution: the course edition has no launch buttons, and its download button
    # offers the notebook with the solutions taken out (course_sources)
    options = dict(config.html_theme_options or {})
    options["launch_buttons"] = {}
    # nor a button to the repository (its issues, a page's source or an edit of it):
    # the repository holds the solutions and the teacher's keys (book/teacher_keys)
    for button in REPOSITORY_BUTTONS:
        options[button] = False
    config.html_theme_options = options


def course_page(app, pagename, templatename, context, doctree):
    if edition() == "course" and "body" in context:
        context["body"] = strip_keys(context["body"], assessed())


def course_sources(app, exception):
    if exception is not None or edition() != "course":
        return
    marked = assessed()
    for folder, _, files in os.walk(os.path.join(app.outdir, "_sources")):
        for name in files:
            path = os.path.join(folder, name)
            with open(path, encoding="utf-8") as f:
                text = f.read()
            if name.endswith(".ipynb"):
                new = json.dumps(
                    course_notebook(json.loads(text), marked),
                    indent=1,
                    ensure_ascii=False,
                )
            else:
                new = strip_keys(strip_solutions(text), marked)
            if new != text:
                with open(path, "w", encoding="utf-8") as f:
                    f.write(new)


def setup(app):
    app.connect("config-inited", course_config)
    app.connect("env-get-updated", numbers_from_labels, priority=900)
    app.connect("html-page-context", course_page, priority=950)
    app.connect("build-finished", course_sources)
    return {"parallel_read_safe": True, "parallel_write_safe": True}
