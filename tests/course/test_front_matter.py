"""The front matter cannot go stale: the introduction and the course plan follow
_toc.yml and the chapters' own exercises.

Everything is derived from ``_toc.yml`` (the chapters, in order) and from the chapters'
sources (their section headings and the numbered exercises under ``## Exercises``), so
a new chapter needs only its lines in ``book/intro.md`` and ``book/course_plan.md``.

How the plan is written, so that it can be checked:

- a week is a ``### Week N`` section; its bold title is followed by a link to the
  chapter it reads (``{doc}`../notebooks/NAME```), and it names that chapter's sections
  in italics (``*The logarithm*``);
- an exercise is cited by a link to its chapter followed by its numbers,
  ``{doc}`screws <../notebooks/screws>` 1 to 10``, or in a lab
  ``{doc}`screws <../notebooks/screws>` exercise 7``; a bare "exercise 7" is refused;
- a week's ``**Exercises**`` bullet assigns, its ``**Lab**`` bullet cites. A lab cites
  the right chapter when each exercise it cites is one to implement (the plan's labs
  are built on them) and asks for what the lab writes: the clause of the lab that
  cites it (up to a ";") names in code (``my_rot``, ``sk.exp_twist``) a name that the
  exercise's text names in code too.
"""

import re
from pathlib import Path

import pytest
from course_plan import toc_chapters
from exercise_syntax import old_syntax

ROOT = Path(__file__).resolve().parents[2]
DOC = re.compile(r"\{doc\}`(?:[^`<]*<)?\.\./notebooks/([a-z0-9_]+)>?`")
ITEM = r"\d+(?:\s*(?:to|-|–)\s*\d+)?"  # 7, or 1 to 10
NUMBERS = ITEM + r"(?:(?:\s*,\s*|\s+and\s+|\s+or\s+)" + ITEM + ")*"
CITATION = re.compile(DOC.pattern + r"\s*(?:exercises?\s+)?(" + NUMBERS + ")")
# names too common to tie a lab to an exercise
GENERIC = set("sk np sp q T J S R M F e i h r s a d pi round zeros linalg".split())
GENERIC |= set("puma arm robot fk theta rows axis".split())


def chapters():
    """The chapter notebooks of _toc.yml, in order."""
    return toc_chapters(ROOT)


def source(chapter):
    return (ROOT / "notebooks" / f"{chapter}.md").read_text(encoding="utf-8")


def exercises(chapter):
    """Exercise number -> its text (statement and solution), under ``## Exercises``."""
    text = old_syntax(source(chapter).split("\n## Exercises", 1)[1])
    parts = re.split(r"^\*\*(\d+)\.\*\*", text, flags=re.M)
    return {int(n): body for n, body in zip(parts[1::2], parts[2::2])}


def headings(chapter):
    return {
        line.lstrip("#").strip()
        for line in source(chapter).splitlines()
        if re.match(r"#{2,4} ", line)
    }


def numbers(text):
    """'1 to 5, 9 and 10' -> [1, 2, 3, 4, 5, 9, 10]."""
    out = []
    for item in re.split(r"\s*,\s*|\s+and\s+|\s+or\s+", text.strip()):
        bounds = re.split(r"\s*(?:to|-|–)\s*", item)
        out += range(int(bounds[0]), int(bounds[-1]) + 1)
    return out


def code_names(text):
    """The identifiers inside the `code` spans of a text."""
    spans = re.findall(r"(?<!`)`([^`]+)`(?!`)", re.sub(r"\{doc\}`[^`]*`", "", text))
    return {w for span in spans for w in re.findall(r"[A-Za-z_]\w*", span)} - GENERIC


PLAN = (ROOT / "book" / "course_plan.md").read_text(encoding="utf-8")
INTRO = (ROOT / "book" / "intro.md").read_text(encoding="utf-8")


def weeks():
    """Week number -> (reading paragraph, exercises bullet, lab bullet)."""
    body = PLAN.split("\n## ", 2)[1]  # the "Week by week" section
    out = {}
    for number, text in re.findall(
        r"^### Week (\d+)\n(.*?)(?=^### |\Z)", body, re.M | re.S
    ):
        reading = text.split("\n- **", 1)[0]
        bullets = dict(
            re.findall(r"^- \*\*(\w+)\*\*(.*?)(?=^- \*\*|\Z)", text, re.M | re.S)
        )
        out[int(number)] = reading, bullets.get("Exercises", ""), bullets.get("Lab", "")
    return out


WEEKS = sorted(weeks())


def test_there_are_chapters_weeks_and_exercises_to_check():
    assert len(chapters()) >= 10
    assert sorted(weeks()) == list(range(1, len(weeks()) + 1))
    assert len(weeks()) >= 10
    assert all(len(exercises(c)) >= 8 for c in chapters())


def test_numbers_reads_the_plans_lists():
    assert numbers("1 to 5, 9 and 10") == [1, 2, 3, 4, 5, 9, 10]
    assert numbers("8 or 9") == [8, 9]
    assert numbers("7") == [7]


@pytest.mark.parametrize("section", ["## The path through the course", "| chapter |"])
def test_introduction_names_every_chapter_in_order(section):
    # the path through the course, and the table of what each chapter covers
    text = INTRO.split(section, 1)[1].split("\n## ", 1)[0]
    named = list(dict.fromkeys(DOC.findall(text)))
    assert named == chapters()


def test_introduction_says_which_chapter_comes_last():
    last = chapters()[-1]
    for sentence in re.findall(r"[^.]*\bcomes? last\b[^.]*\.", INTRO):
        assert last in sentence, sentence


def read_in(reading):
    """The chapter a week reads: the link right after its bold title, or None."""
    match = re.match(r"\*\*[^*]+\*\*\s*" + DOC.pattern, reading.strip())
    return match and match.group(1)


def test_every_week_reads_chapters_in_the_order_of_the_toc():
    order = chapters()
    read = [read_in(reading) for reading, _, _ in weeks().values()]
    assert all(read[:-1]), "every week but the last (the project) reads a chapter"
    indices = [order.index(c) for c in read if c is not None]
    assert indices == sorted(indices)
    assert set(order) <= set(read)


@pytest.mark.parametrize("week", WEEKS)
def test_sections_a_week_names_are_sections_of_its_chapters(week):
    # "*The logarithm*" names the section "The logarithm: from a pose back to a twist"
    reading = weeks()[week][0]
    linked = DOC.findall(reading)
    for name in re.findall(r"(?<![*\w])\*([^*\n]+)\*(?![*\w])", reading):
        assert any(
            heading.startswith(name) for c in linked for heading in headings(c)
        ), (week, name, linked)


def sections_in(text):
    """(section, chapter) for each "*Section* in {doc}`A`, {doc}`B` and {doc}`C`": the
    plan says that each of those chapters has that section."""
    links = DOC.pattern + r"(?:(?:,\s*|\s+and\s+)" + DOC.pattern + ")*"
    pairs = []
    for match in re.finditer(r"(?<![*\w])\*([^*\n]+)\*\s+in\s+(" + links + ")", text):
        pairs += [(match.group(1), c) for c in DOC.findall(match.group(2))]
    return pairs


def test_a_section_said_to_be_in_chapters_is_in_each_of_them():
    # week 15 named *The paper, checked* in chapters that had no such section
    pairs = sections_in(PLAN) + sections_in(INTRO)
    assert pairs, "the plan's project week names the chapters' paper sections"
    missing = [
        (name, c)
        for name, c in pairs
        if not any(h.startswith(name) for h in headings(c))
    ]
    assert missing == []


def test_sections_in_reads_every_chapter_of_a_list():
    text = (
        "*The paper, checked* in {doc}`../notebooks/screws`, {doc}`a <../notebooks/"
        "poe>` and {doc}`../notebooks/mobility`, and *Other* in {doc}`../notebooks/"
        "puma_ik`."
    )
    assert sections_in(text) == [
        ("The paper, checked", "screws"),
        ("The paper, checked", "poe"),
        ("The paper, checked", "mobility"),
        ("Other", "puma_ik"),
    ]
    # the plan's week 15 once listed chapters without that section
    assert not any(h.startswith("The paper, checked") for h in headings("puma_ik"))


def test_every_citation_names_an_exercise_the_chapter_has():
    order = chapters()
    for chapter, listed in CITATION.findall(PLAN):
        assert chapter in order, chapter
        missing = set(numbers(listed)) - set(exercises(chapter))
        assert not missing, f"{chapter} has no exercise {sorted(missing)}"


def test_no_exercise_is_cited_without_its_chapter():
    bare = re.sub(CITATION.pattern, "", PLAN)
    assert re.findall(r"\bexercises? \d+", bare) == []


def test_every_exercise_is_assigned_in_some_week():
    assigned = {}
    for week, (_, listed, _) in weeks().items():
        for chapter, text in CITATION.findall(listed):
            for n in numbers(text):
                assigned.setdefault((chapter, n), week)
    missing = [
        (c, n) for c in chapters() for n in exercises(c) if (c, n) not in assigned
    ]
    assert missing == []


def lab_problems(lab):
    """Why a lab's citations are wrong: an exercise not to implement, or one that does
    not ask for anything the citing clause names in code."""
    problems = []
    for clause in lab.split(";"):
        for chapter, listed in CITATION.findall(clause):
            for n in numbers(listed):
                text = exercises(chapter)[n]
                if "implement it yourself" not in text.split("\n", 1)[0]:
                    problems.append(f"{chapter} exercise {n} is not to implement")
                elif not code_names(clause) & code_names(text):
                    problems.append(f"{chapter} exercise {n} is not about {clause!r}")
    return problems


@pytest.mark.parametrize("week", WEEKS)
def test_a_lab_cites_exercises_that_ask_for_what_it_writes(week):
    assert lab_problems(weeks()[week][2]) == []


def test_the_lab_check_catches_the_labs_of_issue_30():
    # the plan as it was, its citations written as links: rigid motions 8/9 for the
    # exponential of a twist (that is PoE 5), screws 8 for reciprocal systems
    rm = "{doc}`rigid motions <../notebooks/rigid_motions>`"
    week_2 = (
        f"Write the exponential of a twist from Rodrigues' formula ({rm} exercises 8 "
        "or 9) and compare it with `sk.screw_motion`"
    )
    week_3 = (
        "Write the reciprocal system of a set of screws as a null space ({doc}`screws "
        "<../notebooks/screws>` exercises 7 and 8) and check it against "
        "`ScrewSystem.reciprocal()`."
    )
    assert len(lab_problems(week_2)) == 2
    assert lab_problems(week_3) == [f"screws exercise 8 is not about {week_3!r}"]
    week_1_as_lab = f"Convert an orientation with screwkit ({rm} exercise 1)"
    assert lab_problems(week_1_as_lab) == [
        "rigid_motions exercise 1 is not to implement"
    ]


def test_contributing_lists_every_chapter_of_the_table_of_contents():
    """CONTRIBUTING's table "Chapters and the modules they use" has one row for each
    chapter of _toc.yml (notebooks/...), and no row for a chapter the book lacks."""
    root = ROOT
    toc = {
        line.split("file:", 1)[1].strip()
        for line in (root / "_toc.yml").read_text(encoding="utf-8").splitlines()
        if "file: notebooks/" in line
    }
    text = (root / "CONTRIBUTING.md").read_text(encoding="utf-8")
    rows = {
        line.split("|")[1].strip().strip("`")
        for line in text.splitlines()
        if line.startswith("| `notebooks/")
    }
    assert toc and rows == toc, (
        f"CONTRIBUTING.md's chapter table lacks {sorted(toc - rows)} and lists "
        f"{sorted(rows - toc)}, which _toc.yml does not"
    )
