"""The problem bank, read from the chapters' sources as the tools read them
(tools/exercise_syntax.py).

Every exercise of every chapter of _toc.yml: (a) a well-formed tag whose sections are
headings of its chapter, difficulty 1 to 3; (b) a ``figure`` exercise shows one (a
code cell in its exercise block, or a ``{figure}``, ``{image}`` or Markdown image);
(c) an ``exam`` exercise has parts **(a)**, **(b)**, ... and a mark scheme with one
item per part, its points summing to the total; (d) ``self-checking`` exactly when the
exercise has an answer box. The chapters of ``BANK_COMPLETE`` meet the targets (at
least 25 exercises, a third by hand with a figure, 5 to implement, 6 self-checking,
and 3 exam problems at the end); the other chapters' counts are reported as warnings,
and so is the bank-wide count of frame-assignment exercises (a drawing of an arm, its
DH table or joint screws asked for, the expected frames drawn in the solution) until
``FRAME_ASSIGNMENT_ASSERTED``.
"""

import re
import warnings
from pathlib import Path

import pytest
from course_plan import toc_chapters
from exercise_syntax import exam_parts, mark_scheme, read_exercises

ROOT = Path(__file__).resolve().parents[2]

#: The chapters asserted to meet the targets: chapter -> its number of exercises when
#: it first met them (the bank of a complete chapter does not shrink unnoticed).
BANK_COMPLETE = {
    "configuration_space": 25,
    "rigid_motions": 25,
    "screws": 25,
    "lines": 29,
    "mobility": 25,
    "poe": 25,
    "puma_fk": 25,
    "puma_ik": 25,
    "jacobians": 25,
    "statics": 29,
    "kawasaki_workspace": 25,
    "redundancy": 25,
    "motion_in_time": 25,
    "parallel_kinematics": 25,
}
#: Assert the bank-wide count of frame-assignment exercises (else report it).
FRAME_ASSIGNMENT_ASSERTED = True
FRAME_ASSIGNMENT_TARGET = 8
#: A sentence that asks for a DH table (or frames) or joint screws: a verb, then the
#: thing asked for; in a statement about an arm.
FRAME_ASSIGNMENT = re.compile(
    r"\b(assign|write|give|find|list|fill|draw|read)\b[^.?]*"
    r"(\bDH\b[^.?]*\b(table|parameters|frames)\b|\b(joint|space|body) screws\b"
    r"|\bscrew axes\b|\b(two|three|four|five|six) screws\b|\\mathcal\s*\{?S\}?_\{?\d)",
    re.I,
)
ARM = re.compile(r"\b(arm|robot|gantry|manipulator)s?\b", re.I)
#: A figure in Markdown: a {figure}, {image} or {glue:figure} directive, an image.
_IMAGE = re.compile(r"^(:{3,}|`{3,})\{(figure|image|glue:figure)\}|!\[[^\]]*\]\(", re.M)


def book_chapters():
    """The chapter notebooks of _toc.yml, in order."""
    return toc_chapters(ROOT)


def exercises_of(chapter):
    text = (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")
    return read_exercises(text, chapter)


def code_cells(lines):
    """The code of each code cell in ``lines``, its option lines left out."""
    cells, current = [], None
    for line in lines:
        if current is None:
            if line.startswith("```{code-cell}"):
                current = []
        elif line.startswith("```"):
            cells.append([c for c in current if not c.startswith(":")])
            current = None
        else:
            current.append(line)
    return cells


def draws(cell):
    """Whether a code cell does more than show an answer box."""
    code = [c for c in cell if c.strip() and not c.lstrip().startswith("#")]
    return any("answer_box(" not in c for c in code)


def exercise_problems(exercise, chapter):
    """What is wrong with one exercise (a list of sentences; empty: nothing)."""
    where = f"{chapter} exercise {exercise['number']}"
    if exercise["tag_error"]:
        return [exercise["tag_error"]]
    problems, kinds = [], exercise["kinds"]
    cells = code_cells(exercise["cells"])
    shown = "\n".join([exercise["statement"], *exercise["cells"]])
    if "figure" in kinds and not (any(map(draws, cells)) or _IMAGE.search(shown)):
        problems.append(
            f"{where} is tagged figure but shows none (a code cell that draws it, "
            "or a {figure}/{image}/Markdown image)"
        )
    boxed = any("answer_box(" in line for cell in cells for line in cell)
    if ("self-checking" in kinds) != boxed:
        problems.append(
            f"{where}: tagged self-checking {'self-checking' in kinds}, "
            f"has an answer box {boxed}: they go together"
        )
    if "exam" in kinds:
        problems += exam_problems(exercise, where)
    return problems


def exam_problems(exercise, where):
    parts = list(dict.fromkeys(exam_parts(exercise["statement"])))
    expected = [chr(ord("a") + k) for k in range(len(parts))]
    if len(parts) < 2 or parts != expected:
        return [f"{where} is an exam problem: its parts {parts} are not (a), (b), ..."]
    try:
        total, points = mark_scheme(exercise["solution"])
    except ValueError as error:
        return [f"{where}: {error}"]
    problems = []
    if sorted(points) != parts:
        problems.append(f"{where}: the mark scheme marks {sorted(points)}, not {parts}")
    if sum(points.values()) != total:
        problems.append(
            f"{where}: the mark scheme's points sum to {sum(points.values())}, "
            f"not its {total}"
        )
    return problems


def counts(found):
    """A chapter's counts for the targets."""
    kinds = [set(e["kinds"] or ()) for e in found]
    trailing = 0
    for k in reversed(kinds):
        if "exam" not in k:
            break
        trailing += 1
    return {
        "exercises": len(found),
        "by hand + figure": sum({"by hand", "figure"} <= k for k in kinds),
        "implement it yourself": sum("implement it yourself" in k for k in kinds),
        "self-checking": sum("self-checking" in k for k in kinds),
        "exam at the end": trailing,
    }


def unmet_targets(count):
    """The targets a chapter's counts miss (a list of sentences)."""
    minimum = {
        "exercises": 25,
        "by hand + figure": -(-count["exercises"] // 3),
        "implement it yourself": 5,
        "self-checking": 6,
        "exam at the end": 3,
    }
    return [
        f"{name}: {count[name]} < {low}"
        for name, low in minimum.items()
        if count[name] < low
    ]


def frame_assignment(exercise):
    kinds = set(exercise["kinds"] or ())
    statement = exercise["statement"]
    asks = FRAME_ASSIGNMENT.search(statement) and ARM.search(statement)
    return {"by hand", "figure"} <= kinds and bool(asks)


@pytest.mark.parametrize("chapter", book_chapters())
def test_every_exercise_is_tagged_and_true_to_its_tag(chapter):
    found = exercises_of(chapter)
    problems = [p for e in found for p in exercise_problems(e, chapter)]
    assert not problems, "\n".join(problems)


def test_the_complete_chapters_meet_the_targets_and_the_others_are_reported():
    chapters = book_chapters()
    assert set(BANK_COMPLETE) <= set(chapters)
    for chapter in chapters:
        count = counts(exercises_of(chapter))
        unmet = unmet_targets(count)
        if chapter in BANK_COMPLETE:
            assert unmet == [], (chapter, count)
            assert count["exercises"] >= BANK_COMPLETE[chapter], (chapter, count)
        elif unmet:
            untagged = sum(e["tag_error"] is not None for e in exercises_of(chapter))
            warnings.warn(
                f"problem bank of {chapter}: {'; '.join(unmet)} "
                f"({untagged} exercises without a well-formed tag)",
                stacklevel=1,
            )
        else:
            warnings.warn(
                f"{chapter} meets the targets: add it to BANK_COMPLETE", stacklevel=1
            )


def solution_draws(exercise):
    """Whether an exercise's solution shows a figure (the expected frames)."""
    solution = exercise["solution"] or ""
    cells = code_cells(solution.split("\n"))
    return any(map(draws, cells)) or bool(_IMAGE.search(solution))


def test_frame_assignment_exercises_across_the_bank():
    found = [
        (chapter, e["number"], solution_draws(e))
        for chapter in book_chapters()
        for e in exercises_of(chapter)
        if frame_assignment(e)
    ]
    drawn = [(chapter, n) for chapter, n, shown in found if shown]
    if FRAME_ASSIGNMENT_ASSERTED:
        assert len(drawn) >= FRAME_ASSIGNMENT_TARGET, found
    else:
        met = "met: assert it" if len(drawn) >= FRAME_ASSIGNMENT_TARGET else "not met"
        warnings.warn(
            f"frame-assignment exercises whose solution draws the frames: {len(drawn)} "
            f"of {FRAME_ASSIGNMENT_TARGET} ({met}): {drawn}; without a drawing: "
            f"{[(chapter, n) for chapter, n, shown in found if not shown]}",
            stacklevel=1,
        )


# --- each rule fails on a synthetic chapter ---

SYNTHETIC = """# Demo

## Rigid bodies

### The drawing

## Exercises

:::{exercise-start}
:label: demo-exercise-1
:::

*(by hand, figure; difficulty 1; practises: Rigid bodies / The drawing)* Assign the
DH frames of the arm drawn below and write its DH table.

```{code-cell} ipython3
:tags: [hide-input]

plt.plot([0, 1], [0, 1])
```

:::{exercise-end}
:::

:::{exercise-start}
:label: demo-exercise-2
:::

*(self-checking; difficulty 2; practises: Rigid bodies)* What is $h$?

```{code-cell} ipython3
sk.exercises.answer_box("demo", 2)
```

:::{exercise-end}
:::

:::{exercise}
:label: demo-exercise-3

*(exam, by hand; difficulty 3; practises: The drawing)* **(a)** Count. **(b)** Prove.
:::

:::{solution} demo-exercise-3
:class: dropdown

Words.

**Mark scheme** (5 points)
- (a) 2 points: the count
- (b) 3 points: the proof, a long item
  that wraps onto a second line
:::
"""


def problems_of(text):
    found = read_exercises(text, "demo")
    return [p for e in found for p in exercise_problems(e, "demo")]


def test_the_synthetic_chapter_passes():
    found = read_exercises(SYNTHETIC, "demo")
    assert problems_of(SYNTHETIC) == []
    assert [e["difficulty"] for e in found] == [1, 2, 3]
    assert found[0]["sections"] == ["Rigid bodies", "The drawing"]
    assert found[2]["kinds"] == ["exam", "by hand"]
    assert found[0]["statement"].startswith("Assign the\nDH frames")
    assert frame_assignment(found[0]) and not frame_assignment(found[2])
    # a statement that only mentions joint screws does not ask for them
    mentions = {**found[0], "statement": "A leg has seven joint screws. Find a motion."}
    assert not frame_assignment(mentions)
    no_arm = {**found[0], "statement": "Write the two screws' coordinates."}
    assert not frame_assignment(no_arm)
    # the expected frames drawn in the solution: a cell, a glued figure, an image
    assert not solution_draws(found[0]) and not solution_draws(found[2])
    for shown in ("```{code-cell} ipython3\nplt.plot([0, 1])\n```", "![frames](f.png)"):
        assert solution_draws({**found[0], "solution": f"The frames.\n{shown}"})
    glued = "```{glue:figure} demo-frames\n:alt: the frames\n```"
    assert solution_draws({**found[0], "solution": glued})
    for asked in ("the joint screws", "the space screws and $M$", r"$\mathcal S_1$"):
        asks = {**found[0], "statement": f"Write {asked} of the arm drawn."}
        assert frame_assignment(asks), asked
    assert counts(found)["exam at the end"] == 1


@pytest.mark.parametrize(
    "old, new, message",
    [
        ("(by hand, figure; difficulty 1;", "(by hand, figure;", "not of the form"),
        ("(by hand, figure;", "(by hand, drawing;", "not kinds of"),
        ("difficulty 1;", "difficulty 4;", "N in 1, 2, 3"),
        ("difficulty 1;", "level 1;", "N in 1, 2, 3"),
        ("practises: Rigid bodies / The", "practises: Rigid body / The", "headings"),
        ("practises: Rigid bodies /", "sections: Rigid bodies /", "practises: SECTION"),
        ("*(self-checking; difficulty 2; practises: Rigid bodies)* ", "", "a tag"),
        ("plt.plot([0, 1], [0, 1])", "# a comment", "shows none"),
        ('sk.exercises.answer_box("demo", 2)', "x = 1", "answer box False"),
        ("(by hand, figure;", "(by hand, figure, self-checking;", "answer box False"),
        ("**(b)** Prove.", "Prove.", "not (a), (b)"),
        ("**(b)** Prove.", "**(c)** Prove.", "not (a), (b)"),
        ("(5 points)", "(6 points)", "sum to 5, not its 6"),
        ("- (b) 3 points", "- (c) 3 points", "marks ['a', 'c']"),
        ("- (b) 3 points: the proof", "- (b) three: the proof", "is not '- (a)"),
        ("**Mark scheme** (5 points)", "Mark scheme: 5", "no line '**Mark scheme**"),
    ],
)
def test_each_rule_fails_on_a_broken_exercise(old, new, message):
    assert old in SYNTHETIC
    problems = problems_of(SYNTHETIC.replace(old, new, 1))
    assert len(problems) == 1 and message in problems[0], problems
    assert problems[0].startswith("demo exercise ")


def test_read_exercises_strict_names_the_chapter_and_exercise():
    broken = SYNTHETIC.replace("difficulty 2", "difficulty two")
    with pytest.raises(ValueError, match=r"^demo exercise 2: the tag's 'difficulty"):
        read_exercises(broken, "demo", strict=True)


def test_the_targets_fail_when_missed():
    found = read_exercises(SYNTHETIC, "demo")
    assert unmet_targets(counts(found)) == [
        "exercises: 3 < 25",
        "implement it yourself: 0 < 5",
        "self-checking: 1 < 6",
        "exam at the end: 1 < 3",
    ]
    full = {
        "exercises": 27,
        "by hand + figure": 9,
        "implement it yourself": 5,
        "self-checking": 6,
        "exam at the end": 3,
    }
    assert unmet_targets(full) == []
    assert unmet_targets({**full, "by hand + figure": 8}) == ["by hand + figure: 8 < 9"]
    # an exam problem that is not at the end does not count
    moved = SYNTHETIC.replace("demo-exercise-3", "demo-exercise-0")
    assert counts(read_exercises(moved, "demo"))["exam at the end"] == 1


def test_a_gated_solution_is_read_with_its_cells():
    gated = SYNTHETIC.replace(
        ":::{solution} demo-exercise-3\n:class: dropdown\n",
        ":::{solution-start} demo-exercise-3\n:class: dropdown\n:::\n\n"
        "```{code-cell} ipython3\nplt.plot([0, 1])\n```\n",
    ).replace(
        "  that wraps onto a second line\n:::",
        "  that wraps onto a second line\n\n:::{solution-end}\n:::",
    )
    exam = read_exercises(gated, "demo")[2]
    assert exam["solution"].startswith("```{code-cell} ipython3\nplt.plot([0, 1])")
    assert mark_scheme(exam["solution"]) == (5, {"a": 2, "b": 3})
    assert problems_of(gated) == []
