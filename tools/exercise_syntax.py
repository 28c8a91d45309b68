"""How the chapters' sources write an exercise and its solution, read once for the
tools, the CI checks and the course tests.

An exercise is sphinx-exercise's directive labelled ``CHAPTER-exercise-N`` (the label
carries its number; ``exercise-start``/``exercise-end`` around one holding code cells),
its solution ``:::{solution} CHAPTER-exercise-N``. :func:`read_exercises` reads a
chapter's exercises (tools/teacher_answers.py, .ci/check_course_edition.py); the
patterns below let the course tests find them in the text, and :func:`old_syntax`
gives each its number as ``**N.**`` for tests that read the text around it.
"""

import re

# the directive's name, its :label: and, for a gated ``exercise-start``, its colons
_DIRECTIVE = r"^:{{3,}}\{{exercise(?:-start)?\}}\n:label: {chapter}-exercise-(\d+)\n"
_DIRECTIVE += r"(?::{{3,}}\n)?\n"

#: A solution: sphinx-exercise's directive (or an admonition titled Solution).
SOLUTION = re.compile(r"^:{3,}\{(?:admonition\} Solution|solution\})", re.M)
#: A solution as sphinx-exercise's directive only.
SOLUTION_DIRECTIVE = re.compile(r"^:{3,}\{solution\}", re.M)
#: The opening line of an exercise, a gated exercise or a solution: its colons, its
#: kind and its argument (a solution's label).
_OPENING = re.compile(r"^(:{3,})\{(exercise|exercise-start|solution)\}\s*(\S*)$")
CODE_CELL = re.compile(r"^```\{code-cell\}")
FENCE = re.compile(r"^(`{3,}|~{3,})")
COLONS = re.compile(r"^(:{3,})")


def exercise_directive(chapter=r"[a-z0-9_]+"):
    """The opening lines of an exercise of ``chapter`` (a regular expression; default
    any chapter), up to the blank line before its statement; group 1 is its number."""
    return re.compile(_DIRECTIVE.format(chapter=chapter), re.M)


#: An exercise of any chapter.
NEW_EXERCISE = exercise_directive()


def old_syntax(text):
    """``text`` with each exercise directive's opening lines read as ``**N.** ``."""
    return NEW_EXERCISE.sub(r"**\1.** ", text)


def read_exercises(text, chapter):
    """The exercises of a chapter's MyST text, in order: a list of dicts with
    ``number``, ``label``, ``statement``, ``cells`` (the code between exercise-start
    and exercise-end) and ``solution`` (the solution's body, or None).

    ``chapter`` names the chapter in messages; the labels carry the numbers."""
    lines = text.split("\n")
    found, solutions, i = [], {}, 0
    while i < len(lines):
        match = _OPENING.match(lines[i])
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
        label = next(
            (o.split(":", 2)[2].strip() for o in options if ":label:" in o), None
        )
        if label is None:
            raise ValueError(f"{chapter}: the {kind} at line {i} has no :label:")
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


def _strip_blank(block):
    while block and not block[0].strip():
        block = block[1:]
    while block and not block[-1].strip():
        block = block[:-1]
    return block
