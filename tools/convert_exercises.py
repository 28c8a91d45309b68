"""Rewrite the chapters' exercises into sphinx-exercise directives.

The old syntax, under a chapter's ``## Exercises``::

    **4.** *(by hand, self-checking)* A screw has ... pitch?

    ```{code-cell} ipython3
    sk.exercises.answer_box("screws", 4)
    ```

    :::{admonition} Solution
    :class: dropdown
    $h = 0.5$ m/rad.
    :::

becomes (an exercise with code cells is gated: ``exercise-start`` ... ``exercise-end``
hold the cells between them; one without is a plain ``exercise``)::

    :::{exercise-start}
    :label: screws-exercise-4
    :::

    *(by hand, self-checking)* A screw has ... pitch?

    ```{code-cell} ipython3
    sk.exercises.answer_box("screws", 4)
    ```

    :::{exercise-end}
    :::

    :::{solution} screws-exercise-4
    :class: dropdown

    $h = 0.5$ m/rad.
    :::

The label ``CHAPTER-exercise-N`` carries the exercise's number: the book shows
"Exercise N" from it (book/_ext/editions.py), so the numbers stay the chapter's own.
The course edition (``make book EDITION=course``) drops every ``solution``.

Deterministic and idempotent: only the old syntax is rewritten, text already converted
is left as it is, so the script can be run again after chapters written in the old
syntax are merged. The code cells are not changed, so each .ipynb is synced from its
.md keeping its stored outputs (no execution).

Usage: python tools/convert_exercises.py [notebooks/NAME.md ...] (default: all chapters)
"""

import glob
import os
import re
import sys

OLD_EXERCISE = re.compile(r"^\*\*(\d+)\.\*\*[ \t]*(.*)$")
OLD_SOLUTION = re.compile(r"^(:{3,})\{admonition\}\s+Solution\s*$")
CODE_CELL = re.compile(r"^```\{code-cell\}")
FENCE = re.compile(r"^(`{3,}|~{3,})")
COLONS = re.compile(r"^(:{3,})")


def _block_end(lines, start):
    """The index after a colon-fenced block opened at ``lines[start]`` (its closing
    line of the same colons), skipping code fences inside it."""
    colons = COLONS.match(lines[start]).group(1)
    fence = None
    for i in range(start + 1, len(lines)):
        line = lines[i]
        if fence is not None:
            if line.strip() == fence:
                fence = None
            continue
        match = FENCE.match(line)
        if match:
            fence = match.group(1)
        elif line.strip() == colons:
            return i + 1
    raise ValueError(f"line {start + 1}: {lines[start]!r} is never closed")


def _fence_end(lines, start):
    """The index after a code fence (a code cell) opened at ``lines[start]``."""
    fence = FENCE.match(lines[start]).group(1)
    for i in range(start + 1, len(lines)):
        if lines[i].strip() == fence:
            return i + 1
    raise ValueError(f"line {start + 1}: {lines[start]!r} is never closed")


def _colons_for(body):
    """A colon fence longer than any inside ``body``."""
    inner = [len(m.group(1)) for line in body for m in [COLONS.match(line)] if m]
    return ":" * max([3] + [n + 1 for n in inner])


def _strip_blank(block):
    while block and not block[0].strip():
        block = block[1:]
    while block and not block[-1].strip():
        block = block[:-1]
    return block


def _convert_one(chapter, number, statement, cells, solution):
    """The new lines of one exercise: its statement, the lines holding its code cells
    (or []), and its solution block's lines (or None)."""
    label = f"{chapter}-exercise-{number}"
    statement = _strip_blank(statement)
    out = []
    if cells:
        out += [":::{exercise-start}", f":label: {label}", ":::", ""]
        out += statement + [""] + _strip_blank(cells) + ["", ":::{exercise-end}", ":::"]
    else:
        colons = _colons_for(statement)
        out += [colons + "{exercise}", f":label: {label}", ""]
        out += statement + [colons]
    if solution is not None:
        colons = COLONS.match(solution[0]).group(1)
        options, i = [], 1
        while i < len(solution) - 1 and re.match(r"^:\w[\w-]*:", solution[i]):
            options.append(solution[i])
            i += 1
        body = _strip_blank(solution[i:-1])
        out += ["", f"{colons}{{solution}} {label}"] + options + [""] + body
        out.append(colons)
    return out


def convert_section(chapter, lines):
    """Convert the old exercises among ``lines`` (an exercises section)."""
    out, i = [], 0
    while i < len(lines):
        match = OLD_EXERCISE.match(lines[i])
        if not match:
            out.append(lines[i])
            i += 1
            continue
        number = int(match.group(1))
        statement, cells, solution = [match.group(2)], [], None
        i += 1
        # the statement: up to a code cell, a solution or the next exercise
        while i < len(lines):
            line = lines[i]
            if (
                CODE_CELL.match(line)
                or OLD_SOLUTION.match(line)
                or OLD_EXERCISE.match(line)
                or line.startswith("## ")
            ):
                break
            if COLONS.match(line):  # a note or figure inside the statement
                end = _block_end(lines, i)
                statement += lines[i:end]
                i = end
                continue
            if FENCE.match(line):  # a code block of the statement
                end = _fence_end(lines, i)
                statement += lines[i:end]
                i = end
                continue
            statement.append(line)
            i += 1
        # its code cells (answer boxes), with the blank lines between them
        while i < len(lines) and (CODE_CELL.match(lines[i]) or not lines[i].strip()):
            if CODE_CELL.match(lines[i]):
                end = _fence_end(lines, i)
                cells += lines[i:end]
                i = end
            else:
                cells.append(lines[i])
                i += 1
        cells = _strip_blank(cells)
        if i < len(lines) and OLD_SOLUTION.match(lines[i]):
            end = _block_end(lines, i)
            solution = lines[i:end]
            i = end
        new = _convert_one(chapter, number, statement, cells, solution)
        out += new
        blank = i
        while i < len(lines) and not lines[i].strip():
            i += 1
        # one blank line before what follows; at the end, the blank lines there were
        out += [""] if i < len(lines) else lines[blank:i]
    if lines and not lines[-1] and (not out or out[-1]):
        out.append("")  # the section's last line break
    return out


def convert(text, chapter):
    """The chapter's MyST text with its exercises in sphinx-exercise directives."""
    head, sep, rest = text.partition("\n## Exercises\n")
    if not sep:
        return text
    section, sep2, tail = rest.partition("\n## ")
    lines = section.split("\n")
    new = "\n".join(convert_section(chapter, lines))
    return head + sep + new + sep2 + tail


def read_exercises(text, chapter):
    """The exercises of a chapter's MyST text (either syntax), in order: a list of
    dicts with ``number``, ``statement``, ``cells`` (the code between exercise-start
    and exercise-end) and ``solution`` (the solution's body, or None)."""
    lines = convert(text, chapter).split("\n")
    found, solutions, i = [], {}, 0
    start = re.compile(r"^(:{3,})\{(exercise|exercise-start|solution)\}\s*(\S*)$")
    while i < len(lines):
        match = start.match(lines[i])
        if not match:
            i += 1
            continue
        colons, kind, argument = match.groups()
        end = _block_end(lines, i)
        block, i = lines[i + 1 : end - 1], end
        options = [line for line in block if re.match(r"^:\w[\w-]*:", line)]
        body = block[len(options) :]
        if kind == "solution":
            solutions[argument] = "\n".join(_strip_blank(body))
            continue
        label = next(o.split(":", 2)[2].strip() for o in options if ":label:" in o)
        number = int(label.rsplit("-", 1)[1])
        cells = []
        if kind == "exercise-start":  # the statement and cells up to exercise-end
            rest = []
            while i < len(lines) and not lines[i].startswith(colons + "{exercise-end}"):
                rest.append(lines[i])
                i += 1
            i = _block_end(lines, i) if i < len(lines) else i
            cut = next(
                (k for k, line in enumerate(rest) if CODE_CELL.match(line)), len(rest)
            )
            body, cells = rest[:cut], _strip_blank(rest[cut:])
        statement = "\n".join(_strip_blank(body))
        found.append(
            {"number": number, "label": label, "statement": statement, "cells": cells}
        )
    for exercise in found:
        exercise["solution"] = solutions.get(exercise["label"])
    return found


def sync_notebook(source_path):
    """Write the .ipynb of ``source_path`` with the .md's cells and the stored
    outputs of the old .ipynb (the code cells are unchanged: nothing to execute)."""
    import jupytext
    import nbformat
    from jupytext.combine import combine_inputs_with_outputs

    notebook_path = os.path.splitext(source_path)[0] + ".ipynb"
    old = nbformat.read(notebook_path, 4)
    notebook = combine_inputs_with_outputs(jupytext.read(source_path), old)
    old_code = [c.source for c in old.cells if c.cell_type == "code"]
    new_code = [c for c in notebook.cells if c.cell_type == "code"]
    if [c.source for c in new_code] != old_code:
        raise SystemExit(f"{source_path}: its code cells changed; execute it instead")
    missing = [c for c in new_code if c.execution_count is None and c.outputs == []]
    if len(missing) > sum(
        1 for c in old.cells if c.cell_type == "code" and not c.outputs
    ):
        raise SystemExit(f"{source_path}: outputs were lost in the sync")
    notebook.metadata.pop("widgets", None)
    jupytext.write(notebook, notebook_path, fmt="ipynb")


def main(paths):
    changed = []
    for path in paths:
        chapter = os.path.splitext(os.path.basename(path))[0]
        with open(path, encoding="utf-8") as f:
            text = f.read()
        new = convert(text, chapter)
        if new != text:
            with open(path, "w", encoding="utf-8") as f:
                f.write(new)
            changed.append(path)
            if os.path.exists(os.path.splitext(path)[0] + ".ipynb"):
                sync_notebook(path)
        print(f"{path}: {'converted' if new != text else 'unchanged'}")
    return changed


if __name__ == "__main__":
    main(sys.argv[1:] or sorted(glob.glob("notebooks/*.md")))
