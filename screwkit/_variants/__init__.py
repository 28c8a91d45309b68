"""Parametrised exercises: the generators, one module per chapter.

A generator takes a random generator (``None`` for seed 0: the numbers the chapter
prints) and returns the statement's numbers (``{name: (value, unit)}``), the statement
with them in plain text, and the key, computed by screwkit from those numbers and never
stored. A chapter's module registers each of its generators with :func:`register`;
``screwkit.exercises`` imports every module below, so that ``GENERATORS`` is full.
"""

import numpy as np

#: (chapter, number) -> generator
GENERATORS = {}


def register(chapter, number):
    """A decorator: the generator of exercise ``number`` of ``chapter``."""

    def add(generator):
        GENERATORS[chapter, number] = generator
        return generator

    return add


def draw(seed):
    """None for seed 0 (the numbers the chapter prints), else NumPy's generator."""
    return None if seed == 0 else np.random.default_rng([42, seed])


def pick(rng, choices, default):
    """``default`` for seed 0 (``rng`` None), else one of ``choices``, drawn."""
    return default if rng is None else choices[int(rng.integers(len(choices)))]


def units(unit, **values):
    """The statement's numbers ``{name: (value, unit)}``, all in one unit."""
    return {name: (value, unit) for name, value in values.items()}
