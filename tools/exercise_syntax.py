"""How the chapters' sources write an exercise and its solution, read once for the
tools, the CI checks and the course tests.

An exercise is sphinx-exercise's directive labelled ``CHAPTER-exercise-N`` (the label
carries its number; ``exercise-start``/``exercise-end`` around one holding code cells),
its solution ``:::{solution} CHAPTER-exercise-N``. :func:`read_exercises` reads a
chapter's exercises (tools/teacher_answers.py, .ci/check_course_edition.py); the
patterns below let the course tests find them in the text, and :func:`old_syntax`
gives each its number as ``**N.**`` for tests that read the text around it.

Each exercise's statement begins with its tag::

    *(KIND[, KIND ...]; difficulty N; practises: SECTION[ / SECTION ...])*

KIND from :data:`KINDS`, N in 1 to 3, each SECTION the text of a ``##`` or ``###``
heading of the chapter. :func:`read_exercises` reads it (``kinds``, ``difficulty``,
``sections``, or ``tag_error`` saying what is wrong); :func:`exam_parts` and
:func:`mark_scheme` read an exam problem's parts and its solution's mark scheme.
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
_OPENING = re.compile(
    r"^(:{3,})\{(exercise|exercise-start|solution|solution-start)\}\s*(\S*)$"
)
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


#: The kinds of exercise a tag may name.
KINDS = (
    "by hand",
    "implement it yourself",
    "self-checking",
    "figure",
    "exam",
    "a real mechanism",
    "parametrised",
)
#: A tag at the start of a statement (it may run over several lines): its body.
TAG = re.compile(r"\A\*\((.*?)\)\*(?=\s|\Z)", re.S)
_GRAMMAR = "*(KIND[, KIND ...]; difficulty N; practises: SECTION[ / SECTION ...])*"
#: A part of an exam problem's statement, **(a)**; group 1 is its letter.
PART = re.compile(r"\*\*\(([a-z])\)\*\*")
_SCHEME = re.compile(r"^\*\*Mark scheme\*\* \((\d+) points?\)\s*$", re.M)
_SCHEME_ITEM = re.compile(r"^- \(([a-z])\) (\d+) points?: \S")


def _outside_fences(lines, start=0):
    """(index, line) of each of ``lines`` from ``start`` on that is outside a code
    fence (the fences' own lines left out)."""
    fence = None
    for i in range(start, len(lines)):
        line = lines[i]
        if fence is not None:
            if line.strip() == fence:
                fence = None
            continue
        match = FENCE.match(line)
        if match:
            fence = match.group(1)
            continue
        yield i, line


def headings(text):
    """The texts of the ``##`` and ``###`` headings of a chapter's MyST text, code
    (fenced blocks, code cells) left out."""
    found = []
    for _, line in _outside_fences(text.split("\n")):
        heading = re.match(r"^#{2,3} (.+?)\s*$", line)
        if heading:
            found.append(heading.group(1))
    return found


def parse_tag(statement, sections=None):
    """The tag at the start of ``statement``: ``(kinds, difficulty, sections, rest)``
    with ``rest`` the statement after it.

    ``sections`` (the chapter's headings) are the sections a tag may name; None
    accepts any. Raises ValueError saying what is wrong and the grammar."""
    match = TAG.match(statement)
    if not match:
        raise ValueError(f"the statement does not begin with a tag {_GRAMMAR}")
    body = " ".join(match.group(1).split())
    parts = body.split(";", 2)
    if len(parts) != 3:
        raise ValueError(f"the tag *({body})* is not of the form {_GRAMMAR}")
    kinds = [k.strip() for k in parts[0].split(",")]
    unknown = [k for k in kinds if k not in KINDS]
    if unknown:
        raise ValueError(f"the tag names {unknown}, not kinds of {list(KINDS)}")
    if len(set(kinds)) != len(kinds):
        raise ValueError(f"the tag names a kind twice: {kinds}")
    level = re.fullmatch(r"difficulty (\d+)", parts[1].strip())
    if not level or not 1 <= int(level.group(1)) <= 3:
        raise ValueError(
            f"the tag's {parts[1].strip()!r} is not 'difficulty N' with N in 1, 2, 3"
        )
    practised = re.fullmatch(r"practises: (.+)", parts[2].strip())
    if not practised:
        raise ValueError(
            f"the tag's {parts[2].strip()!r} is not 'practises: SECTION[ / ...]'"
        )
    named = [p.strip() for p in practised.group(1).split(" / ")]
    if sections is not None:
        missing = [n for n in named if n not in sections]
        if missing:
            raise ValueError(
                f"the tag practises {missing}, not ## or ### headings of the chapter"
            )
    rest = statement[match.end() :].lstrip()
    return kinds, int(level.group(1)), named, rest


def exam_parts(statement):
    """The letters of an exam problem's parts, **(a)**, **(b)**, ..., in order."""
    return PART.findall(statement)


def mark_scheme(solution):
    """A solution's ``**Mark scheme** (N points)`` and the list after it, one item
    per part, ``- (a) K points: ...`` (its text may wrap onto indented lines):
    ``(N, {part: points})``. Raises ValueError if it is missing or malformed."""
    match = _SCHEME.search(solution or "")
    if not match:
        raise ValueError("the solution has no line '**Mark scheme** (N points)'")
    points = {}
    for line in solution[match.end() :].lstrip("\n").split("\n"):
        if points and line[:1] in (" ", "\t") and line.strip():
            continue  # an item's text wrapped onto the next line
        if not line.startswith("- "):
            break
        item = _SCHEME_ITEM.match(line)
        if not item:
            raise ValueError(
                f"the mark scheme's item {line!r} is not "
                "'- (a) K points: what earns them'"
            )
        if item.group(1) in points:
            raise ValueError(f"the mark scheme marks part ({item.group(1)}) twice")
        points[item.group(1)] = int(item.group(2))
    if not points:
        raise ValueError("the mark scheme lists no '- (a) K points: ...' item")
    return int(match.group(1)), points


def read_exercises(text, chapter, strict=False):
    """The exercises of a chapter's MyST text, in order: a list of dicts with
    ``number``, ``label``, ``statement`` (after its tag), ``cells`` (the lines from
    the first code cell to exercise-end), ``solution`` (the solution's body, or
    None), and from the tag ``kinds``, ``difficulty``, ``sections`` (None, None, []
    if it is missing or malformed) and ``tag_error`` (what is wrong, or None).

    ``chapter`` names the chapter in messages; the labels carry the numbers. With
    ``strict``, a missing or malformed tag raises ValueError naming the chapter
    and the exercise."""
    lines, sections = text.split("\n"), headings(text)
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
        if kind.endswith("-start"):  # gated: the body runs to its -end directive
            body, i = _gated(lines, i, colons + "{" + kind[: -len("start")] + "end}")
        if kind.startswith("solution"):
            solutions[argument] = "\n".join(_strip_blank(body))
            continue
        label = next(
            (o.split(":", 2)[2].strip() for o in options if ":label:" in o), None
        )
        if label is None:
            raise ValueError(f"{chapter}: the {kind} at line {i} has no :label:")
        number = int(label.rsplit("-", 1)[1])
        cut = next((k for k, line in enumerate(body) if CODE_CELL.match(line)), None)
        cells = _strip_blank(body[cut:]) if cut is not None else []
        statement = "\n".join(_strip_blank(body[:cut]))
        found.append({"number": number, "label": label, "statement": statement})
        found[-1].update(_tag(statement, sections, chapter, number, strict))
        found[-1]["cells"] = cells
    for exercise in found:
        exercise["solution"] = solutions.get(exercise["label"])
    return found


def _tag(statement, sections, chapter, number, strict):
    """The fields of read_exercises that come from the statement's tag."""
    try:
        kinds, difficulty, practised, rest = parse_tag(statement, sections)
    except ValueError as error:
        message = f"{chapter} exercise {number}: {error}"
        if strict:
            raise ValueError(message) from None
        return {"kinds": None, "difficulty": None, "sections": [], "tag_error": message}
    return {
        "statement": rest,
        "kinds": kinds,
        "difficulty": difficulty,
        "sections": practised,
        "tag_error": None,
    }


def _gated(lines, i, closing):
    """The lines from ``lines[i]`` up to the directive ``closing`` (``:::{x-end}``)
    and the index after that directive's block."""
    body = []
    while i < len(lines) and not lines[i].startswith(closing):
        body.append(lines[i])
        i += 1
    return body, (_block_end(lines, i) if i < len(lines) else i)


def _block_end(lines, start):
    """The index after a colon-fenced block opened at ``lines[start]`` (its closing
    line of the same colons), skipping code fences inside it."""
    colons = COLONS.match(lines[start]).group(1)
    for i, line in _outside_fences(lines, start + 1):
        if line.strip() == colons:
            return i + 1
    raise ValueError(f"line {start + 1}: {lines[start]!r} is never closed")


def _strip_blank(block):
    while block and not block[0].strip():
        block = block[1:]
    while block and not block[-1].strip():
        block = block[:-1]
    return block
