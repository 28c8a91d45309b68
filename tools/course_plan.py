"""The weeks of book/course_plan.md, read for tools/teacher_answers.py and the tests.

Each week is a section ``### Week N``: a bold title, the week's chapter (its first
``{doc}`` link to a chapter), and a bullet ``- **Exercises**`` naming chapters and
their exercise numbers, ``{doc}`lines <../notebooks/lines>` 1 to 9 and 11 to 21``.
The labs and the assessed work name exercises as ``... <../notebooks/X>` exercise 7``
or ``exercises 3 to 6 and 19``.
"""

import re
from pathlib import Path

import yaml

#: A link to a chapter; group 1 is the chapter's name.
DOC = re.compile(r"\{doc\}`(?:[^`<]*<)?\.\./notebooks/([a-z0-9_]+)>?`")
#: Numbers as the plan writes them: 1 to 9 and 11 to 21, 3, 5 and 7.
_RANGE = r"\d+(?:\s+to\s+\d+)?"
NUMBERS = re.compile(rf"{_RANGE}(?:(?:\s*,\s*(?:and\s+)?|\s+and\s+){_RANGE})*")
_WEEK = re.compile(r"^### Week (\d+)\s*$", re.M)
_NAMED = re.compile(r"\s*exercises?\s+(" + NUMBERS.pattern + ")")


def toc_chapters(root):
    """The chapters of ``root/_toc.yml`` (their names under notebooks/), in order."""
    toc = yaml.safe_load((Path(root) / "_toc.yml").read_text(encoding="utf-8"))
    files = [c["file"] for part in toc["parts"] for c in part.get("chapters", [])]
    return [f.split("/", 1)[1] for f in files if f.startswith("notebooks/")]


def numbers(text):
    """The whole numbers of ``1 to 9 and 11 to 21`` (ranges inclusive), in order."""
    out = []
    for first, last in re.findall(r"(\d+)(?:\s+to\s+(\d+))?", text):
        low, high = int(first), int(last or first)
        if high < low:
            raise ValueError(f"the range {first} to {last} runs backwards")
        out += range(low, high + 1)
    return out


def weeks(text):
    """The weeks of the plan's text, in order: dicts with ``number``, ``title``,
    ``chapter`` (the week's chapter), ``exercises`` (the Exercises line:
    ``[(chapter, [numbers])]``) and ``named`` (every ``exercise(s) N`` after a link
    in the week, as the labs and the assessed work write them)."""
    found = []
    starts = list(_WEEK.finditer(text))
    for k, match in enumerate(starts):
        end = starts[k + 1].start() if k + 1 < len(starts) else len(text)
        section = text[match.end() : end]
        section = re.split(r"^##? ", section, maxsplit=1, flags=re.M)[0]
        week = int(match.group(1))
        title = re.search(r"\*\*(.+?)\*\*", section, re.S)
        chapter = DOC.search(section)
        if not title or not chapter:
            raise ValueError(f"week {week} of the plan has no **title** or no chapter")
        flat = " ".join(section.split())
        found.append(
            {
                "number": week,
                "title": " ".join(title.group(1).split()).rstrip("."),
                "chapter": chapter.group(1),
                "exercises": _exercise_line(section, week),
                "named": _named(flat),
            }
        )
    return found


def _exercise_line(section, week):
    """The chapters and numbers of a week's ``- **Exercises**`` bullet."""
    line = re.search(r"^- \*\*Exercises\*\*(.*?)(?=^- |\Z)", section, re.M | re.S)
    if not line:
        raise ValueError(f"week {week} of the plan has no '- **Exercises**' line")
    flat = " ".join(line.group(1).split())
    links = list(DOC.finditer(flat))
    out = []
    for k, link in enumerate(links):
        end = links[k + 1].start() if k + 1 < len(links) else len(flat)
        listed = NUMBERS.match(flat[link.end() : end].lstrip())
        if not listed:
            raise ValueError(
                f"week {week}'s Exercises line names {link.group(1)} "
                "with no exercise numbers after it"
            )
        out.append((link.group(1), numbers(listed.group(0))))
    return out


def _named(flat):
    """Every ``<../notebooks/X>` exercise(s) N`` of a week's text."""
    out = []
    for link in DOC.finditer(flat):
        after = _NAMED.match(flat, link.end())
        if after:
            out.append((link.group(1), numbers(after.group(1))))
    return out
