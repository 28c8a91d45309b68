"""The registry of independent recomputations of the exercises' answer keys.

A chapter's module registers one function per key with ``@reference(chapter, number)``;
the function recomputes the answer another way than the key (a formula written out, a
root found by bisection, screwkit on the problem as stated) and returns it in the key's
unit.
"""

import tomllib
from importlib import resources

import sympy as sp

#: (chapter, number) -> a function of no arguments returning the recomputed answer.
REFERENCES = {}


def reference(chapter, number):
    """Register the independent computation of one exercise's answer."""

    def register(function):
        assert (chapter, number) not in REFERENCES, (
            f"{chapter} {number} registered twice"
        )
        REFERENCES[chapter, number] = function
        return function

    return register


def _keys_file(chapter):
    path = resources.files("screwkit") / "answers" / f"{chapter}.toml"
    return tomllib.loads(path.read_text(encoding="utf-8"))


def all_keys():
    """Every (chapter, number) that has an answer key in screwkit/answers."""
    folder = resources.files("screwkit").joinpath("answers")
    keys = []
    for path in sorted(folder.iterdir(), key=lambda p: p.name):
        if path.name.endswith(".toml"):
            chapter = path.name[: -len(".toml")]
            keys += [(chapter, int(n)) for n in _keys_file(chapter).get("exercise", {})]
    return keys


def key(chapter, number):
    """The raw entry of one key, as written in its TOML file."""
    return _keys_file(chapter)["exercise"][str(number)]


def value(chapter, number):
    """The key's answer as a float, in the key's unit."""
    return float(sp.sympify(key(chapter, number)["answer"]))
