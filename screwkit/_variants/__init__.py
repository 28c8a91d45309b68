"""Parametrised exercises: the draws in the key files, the keys' computations here.

A parametrised exercise's numbers are data: they live in its key file,
``screwkit/answers/CHAPTER.toml``, next to the key's unit, tolerance and hint, in a
sub-table ``[exercise.N.variant]``::

    [exercise.2.variant]
    statement = "... the vertical line through ({a}, {b}, 0) m ... by {angle} deg?"
    a = { unit = "m", seed0 = 1, choices = [-2, -1, 1, 2, 3] }
    b = { unit = "m", seed0 = 0, choices = [-2, -1, 0, 1, 2] }
    angle = { unit = "deg", seed0 = 180, choices = [90, 180, 270] }

Its entries, in the table's order:

- ``statement``: the statement, a ``str.format`` template of the values below;
- a draw, ``{seed0, choices}``: seed 0 takes ``seed0`` (the number the chapter
  prints), another seed one of ``choices``, drawn in the table's order; with a
  ``unit`` it is one of the statement's numbers, else a value the key needs;
- a number the key's function computes, ``{unit}`` alone.

A chapter's module holds the rest, the key's computation: a function of the drawn
values (by name) registered with :func:`register`, returning the key, or the key and
a dict of the values the statement shows that are not drawn. ``GENERATORS`` maps
(chapter, number) to a :class:`Generator`: called with a random generator (``None``
for seed 0) and the exercise's variant table (``screwkit.exercises`` reads the key
file) it returns the statement's numbers (``{name: (value, unit)}``, in the
table's order), the statement in plain text and the key, computed by screwkit and
never stored. ``screwkit.exercises`` imports every chapter's module, so that
``GENERATORS`` is full.
"""

import inspect

import numpy as np

#: (chapter, number) -> generator
GENERATORS = {}


def draw(seed):
    """None for seed 0 (the numbers the chapter prints), else NumPy's generator."""
    return None if seed == 0 else np.random.default_rng([42, seed])


def pick(rng, choices, default):
    """``default`` for seed 0 (``rng`` None), else one of ``choices``, drawn."""
    return default if rng is None else choices[int(rng.integers(len(choices)))]


#: the fields of an entry: a draw, a drawn number of the statement, a computed one
ENTRIES = ({"seed0", "choices"}, {"unit", "seed0", "choices"}, {"unit"})


def checked(table, where):
    """``table`` if it is a variant table (a statement, then draws and numbers)."""
    if not isinstance(table, dict) or not isinstance(table.get("statement"), str):
        raise ValueError(f"{where} must exist and hold a statement, got {table!r}")
    for name, entry in table.items():
        if name == "statement":
            continue
        # a computed number has no choices: a list of one, to pass the test below
        choices = entry.get("choices", [None]) if isinstance(entry, dict) else None
        if not (isinstance(choices, list) and choices and set(entry) in ENTRIES):
            raise ValueError(
                f"{name} of {where} must be a draw {{[unit, ]seed0, choices}} (a "
                f"non-empty list) or a computed number {{unit}}, got {entry!r}"
            )
    return table


class Generator:
    """An exercise's numbers, statement and key from a random generator.

    Parameters
    ----------
    chapter, number : str, int
        The exercise (named in messages).
    key : callable
        The key from the drawn values (keyword arguments), or the key and a dict of
        the values the statement shows that are not drawn.
    draws : callable, optional
        More draws, ``draws(rng) -> {name: value}``, made after the table's.
    """

    def __init__(self, chapter, number, key, draws=None):
        self.chapter, self.number, self.key, self.draws = chapter, number, key, draws

    def __call__(self, rng, table):
        """``(numbers, statement, key)`` for ``rng`` (``None``: seed 0), the draws and
        the statement from ``table``, its variant table (:func:`checked`)."""
        values = {
            name: pick(rng, entry["choices"], entry["seed0"])
            for name, entry in table.items()
            if name != "statement" and "choices" in entry
        }
        if self.draws is not None:
            values |= self.draws(rng)
        arguments = set(inspect.signature(self.key).parameters)
        if arguments != set(values):
            raise ValueError(
                f"the key of {self.chapter} exercise {self.number} must take the "
                f"draws {sorted(values)}, got {sorted(arguments)}"
            )
        result = self.key(**values)
        if isinstance(result, tuple) and isinstance(result[-1], dict):
            result, shown = result  # the key, and values the statement shows
            values |= shown
        units = {
            n: e["unit"] for n, e in table.items() if n != "statement" and "unit" in e
        }
        missing = sorted(set(units) - set(values))
        if missing:
            raise ValueError(
                f"the key of {self.chapter} exercise {self.number} must give the "
                f"numbers it computes, {missing}, got {sorted(values)}"
            )
        numbers = {name: (values[name], unit) for name, unit in units.items()}
        statement = table["statement"].format(**values)
        key = np.asarray(result, dtype=float)  # a float, or a flat list of them
        return numbers, statement, key.ravel().tolist() if key.ndim else float(key)


def register(chapter, number, draws=None):
    """A decorator: the key's computation of exercise ``number`` of ``chapter``.

    ``draws(rng) -> {name: value}`` adds draws that do not fit a list of choices; it
    is called after the table's, with ``rng`` None for seed 0.
    """

    def add(key):
        GENERATORS[chapter, number] = Generator(chapter, number, key, draws)
        return key

    return add
