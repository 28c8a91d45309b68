"""How the chapters' sources write an exercise and its solution, for the course tests
that read them.

An exercise is sphinx-exercise's directive labelled ``CHAPTER-exercise-N``, as
tools/convert_exercises.py writes it (tests/course/test_editions.py checks that these
patterns read its output), or the old syntax ``**N.** text`` it converts from.
"""

import re

# the directive's name, its :label: and, for a gated ``exercise-start``, its colons
_DIRECTIVE = r"^:{{3,}}\{{exercise(?:-start)?\}}\n:label: {chapter}-exercise-(\d+)\n"
_DIRECTIVE += r"(?::{{3,}}\n)?\n"

#: A solution: sphinx-exercise's directive or the old syntax's admonition.
SOLUTION = re.compile(r"^:{3,}\{(?:admonition\} Solution|solution\})", re.M)
#: A solution as sphinx-exercise's directive only.
SOLUTION_DIRECTIVE = re.compile(r"^:{3,}\{solution\}", re.M)


def exercise_directive(chapter=r"[a-z0-9_]+"):
    """The opening lines of an exercise of ``chapter`` (a regular expression; default
    any chapter), up to the blank line before its statement; group 1 is its number."""
    return re.compile(_DIRECTIVE.format(chapter=chapter), re.M)


#: An exercise of any chapter.
NEW_EXERCISE = exercise_directive()


def old_syntax(text):
    """``text`` with each exercise directive's opening lines read as ``**N.** ``."""
    return NEW_EXERCISE.sub(r"**\1.** ", text)
