"""Self-checking exercises: answer keys, a check in the notebook and a box in the page.

Each chapter's answer key is package data, ``screwkit/answers/CHAPTER.toml`` (CHAPTER
is the notebook's stem, e.g. ``puma_ik``)::

    [exercise.4]
    answer = "atan2(0.4318, 0.0203)"   # a SymPy expression, or a list of them
    unit = "rad"                       # "rad", "deg", "m", "mm", "m/s", "" ...,
                                       # or one per number: ["rad/s", "m/s"]
    tolerance = 1e-3                   # absolute, in the answer's unit
    rtol = 0.0                         # optional, relative
    hint = "The elbow angle is measured from the forearm's line."
    forms = ["modulo 2pi"]             # optional: "modulo 2pi", "either sign",
                                       # "any order"
    alternatives = ["-pi/2"]           # optional: other accepted answers
    per = "N m"                        # optional: the answer per unit of this is
                                       # accepted too (a force per N m of torque)

A parametrised exercise has ``parametrised = true`` instead of ``answer``: its numbers
come from a seed and its key is computed by screwkit (:func:`variant`; seed 0 is the
chapter's statement). Its statement and the lists its numbers are drawn from are in a
sub-table ``[exercise.N.variant]`` of the same file, the key's computation in
``screwkit/_variants/CHAPTER.py`` (see ``screwkit._variants``). An assessed exercise
(book/assessed.yml) has only ``assessed = true``: its key is the teacher's, in
book/teacher_keys/CHAPTER.toml outside the package, read from a checkout of the course
(the self-study book is built there) or from the folder SCREWKIT_TEACHER_KEYS names;
an installed screwkit has none, and :func:`check` and :func:`answer_box` say that the
teacher marks it.

``check(chapter, number, answer)`` returns a :class:`Verdict` (right or wrong, and
why); ``answer_box(chapter, number)`` returns a field and a Check button for the
page, answered by ``static/exercises.js`` in the browser with the same rules, with
no kernel. Student answers are read by a small parser of numbers, ``pi``, ``sqrt``,
the trigonometric functions, units (``60 deg``, ``12 mm``) and comma-separated
vectors; it never evaluates Python code.
"""

import html
import itertools
import json
import math
import os
import re
import tomllib
from dataclasses import dataclass
from functools import cache
from importlib import resources
from pathlib import Path

import numpy as np
import sympy as sp

from ._checks import describe

# each chapter's module registers its parametrised exercises in GENERATORS
from ._variants import (  # noqa: F401
    GENERATORS,
    checked,
    configuration_space,
    draw,
    jacobians,
    kawasaki_workspace,
    lines,
    mobility,
    motion_in_time,
    parallel_kinematics,
    poe,
    puma_fk,
    puma_ik,
    redundancy,
    rigid_motions,
    screws,
    statics,
)
from .tolerances import ZERO_TOL

__all__ = [
    "Verdict",
    "AnswerBox",
    "check",
    "answer_box",
    "answer_key",
    "parse_answer",
    "variant",
]

FORMS = ("modulo 2pi", "either sign", "any order")

# Units: a factor to SI and a dimension, the exponents of (kg, m, s, rad). The radian
# is kept as a dimension of its own, so that an angle is told from a pure number and a
# missing "rad" or "deg" is caught; see _convert for where SI's radian = 1 is used.
_UNITS = {
    "rad": (1.0, (0, 0, 0, 1)),
    "deg": (math.pi / 180, (0, 0, 0, 1)),
    "°": (math.pi / 180, (0, 0, 0, 1)),
    "m": (1.0, (0, 1, 0, 0)),
    "cm": (1e-2, (0, 1, 0, 0)),
    "mm": (1e-3, (0, 1, 0, 0)),
    "s": (1.0, (0, 0, 1, 0)),
    "kg": (1.0, (1, 0, 0, 0)),
    "N": (1.0, (1, 1, -2, 0)),
    "Nm": (1.0, (1, 2, -2, 0)),
    "W": (1.0, (1, 2, -3, 0)),
    "J": (1.0, (1, 2, -2, 0)),
    "Hz": (1.0, (0, 0, -1, 0)),
    "ms": (1e-3, (0, 0, 1, 0)),
    "min": (60.0, (0, 0, 1, 0)),
    "kN": (1e3, (1, 1, -2, 0)),
    "kW": (1e3, (1, 2, -3, 0)),
    "mrad": (1e-3, (0, 0, 0, 1)),
    "km": (1e3, (0, 1, 0, 0)),
}
_UNIT_NAMES = {"degree": "deg", "degrees": "deg", "radian": "rad", "radians": "rad"}
# what a dimension is called in a message ("expected a torque (N m), found a force (N)")
_QUANTITIES = {
    (0, 0, 0, 0): "pure number",
    (0, 0, 0, 1): "angle",
    (0, 1, 0, 0): "length",
    (0, 2, 0, 0): "area",
    (0, 0, 1, 0): "time",
    (1, 0, 0, 0): "mass",
    (0, 1, -1, 0): "speed",
    (0, 0, -1, 1): "angular speed",
    (0, 0, -1, 0): "rate",
    (0, 1, -2, 0): "acceleration",
    (0, 0, -2, 1): "angular acceleration",
    (1, 1, -2, 0): "force",
    (1, 2, -2, 0): "torque",
    (1, 2, -3, 0): "power",
    (0, 1, 0, -1): "pitch",
}
# The slips a wrong answer is tested for: (key's unit, factor, message).
_SLIPS = (
    ("rad", math.pi / 180, "looks like degrees, radians expected"),
    ("deg", 180 / math.pi, "looks like radians, degrees expected"),
    ("m", 1e-3, "looks like millimetres, metres expected"),
    ("mm", 1e3, "looks like metres, millimetres expected"),
)

_FUNCTIONS = {
    "sqrt": math.sqrt,
    "sin": math.sin,
    "cos": math.cos,
    "tan": math.tan,
    "asin": math.asin,
    "acos": math.acos,
    "atan": math.atan,
    "atan2": math.atan2,
    "exp": math.exp,
    "ln": math.log,
    "log": math.log,
    "abs": abs,
}
_CONSTANTS = {"pi": math.pi, "π": math.pi, "e": math.e}

_TOKEN = re.compile(
    r"\s*(?:(?P<number>(?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)"
    r"|(?P<name>[A-Za-zπ°_][A-Za-z0-9_]*)"
    r"|(?P<op>\*\*|[-+*/^(),;\[\]]))"
)


@dataclass(frozen=True)
class _Unit:
    """A unit as written: its factor to SI, its dimension and its text."""

    factor: float
    dimension: tuple
    text: str


def _is_unit(word):
    return _UNIT_NAMES.get(word, word) in _UNITS


def _article(name):
    return ("an " if name[0] in "aeiou" else "a ") + name


def _quantity(dimension):
    """What a dimension is called, with its article: "a torque", "an angle"."""
    return _article(_QUANTITIES.get(dimension, "quantity"))


def _convert(unit, key_unit):
    """The factor that takes a value in ``unit`` to ``key_unit``, or None if the two
    measure different things. Dimensions that differ only in the radian (a pitch in m
    or m/rad, a rate in 1/s or rad/s) convert, the radian being 1 in SI, except an
    angle against a pure number (a missing angle unit must be caught)."""
    if unit.dimension == key_unit.dimension:
        return unit.factor / key_unit.factor
    rest, key_rest = unit.dimension[:3], key_unit.dimension[:3]
    if rest == key_rest and any(rest):
        return unit.factor / key_unit.factor
    return None


# ---- reading an answer -------------------------------------------------------------


class _Parser:
    """Recursive descent over numbers, + - * / ^, functions, constants and units."""

    def __init__(self, text):
        text = text.replace("−", "-").replace("×", "*").replace("·", "*")
        text = text.replace("⋅", "*").replace("√", "sqrt")
        text = text.replace("²", "^2").replace("³", "^3")
        self.tokens, self.spaced = [], []
        position = 0
        while position < len(text):
            if text[position:].strip() == "":
                break
            match = _TOKEN.match(text, position)
            if match is None or match.end() == position:
                raise ValueError(f"cannot read {text[position:].strip()[:12]!r}")
            kind = match.lastgroup
            self.tokens.append((kind, match.group(kind)))
            self.spaced.append(match.start(kind) > position)  # whitespace before it
            position = match.end()
        self.at = 0

    def peek(self):
        return self.tokens[self.at] if self.at < len(self.tokens) else (None, None)

    def take(self, value=None):
        token = self.peek()
        if token[0] is None or (value is not None and token[1] != value):
            found = "the end" if token[0] is None else repr(token[1])
            raise ValueError(f"expected {value!r}, found {found}")
        self.at += 1
        return token

    def space_before(self):
        return self.at < len(self.tokens) and self.spaced[self.at]

    def starts_item(self):
        kind, token = self.peek()
        return kind in ("number", "name") or token in ("(", "[", "+", "-")

    def sign_starts_item(self):
        """A sign after whitespace, glued to what follows ("1 -2"), opens a new item."""
        glued = self.at + 1 < len(self.tokens) and not self.spaced[self.at + 1]
        return self.space_before() and glued

    def items(self):
        """Items separated by commas, semicolons or whitespace (as NumPy prints arrays);
        brackets and parentheses around several items group them and are flattened.
        Each item is a pair (value in SI, its _Unit or None). A unit written after the
        last item only applies to all of them (``2000, 0, 0 mm``)."""
        pairs = self.item()
        while True:
            if self.peek()[1] in (",", ";"):
                self.take()
            elif not (self.space_before() and self.starts_item()):
                break
            pairs += self.item()
        if len(pairs) > 1 and pairs[-1][1] is not None:
            if all(unit is None for _, unit in pairs[:-1]):
                unit = pairs[-1][1]
                pairs = [(value * unit.factor, unit) for value, _ in pairs[:-1]] + [
                    pairs[-1]
                ]
        return pairs

    def is_group(self):
        """A parenthesis that holds a list: a comma or semicolon inside it, outside
        any inner parenthesis (``(2, 0, 0)``; ``(1 + 2)/3`` and ``(atan2(1, 2))`` are
        expressions). Decided by looking ahead, so nothing is parsed twice."""
        depth = 0
        for _, token in self.tokens[self.at :]:
            if token in ("(", "["):
                depth += 1
            elif token in (")", "]"):
                depth -= 1
                if depth == 0:
                    return False
            elif token in (",", ";") and depth == 1:
                return True
        return False

    def group(self):
        """The pairs of a bracketed list, ``[1, 2]`` or ``(2, 0, 0)``."""
        closing = "]" if self.take()[1] == "[" else ")"
        pairs = self.items()
        self.take(closing)
        return pairs

    def item(self):
        if self.peek()[1] == "[" or self.peek()[1] == "(" and self.is_group():
            pairs = self.group()
            unit = self.unit()  # "(2, 0, 0) m": the unit of every entry
            if unit is not None:
                if any(u is not None for _, u in pairs):
                    raise ValueError("a unit is written twice for one number")
                pairs = [(value * unit.factor, unit) for value, _ in pairs]
            return pairs
        value = self.expression()
        unit = self.unit()
        return [(value if unit is None else value * unit.factor, unit)]

    def unit_starts(self):
        """A unit at the current token: a unit word, ``/s`` or ``1/s`` after a space."""
        if self.unit_next() or self.peek()[1] == "/" and self.unit_after():
            return True
        kind, token = self.peek()
        return (
            kind == "number"
            and token == "1"
            and self.space_before()
            and self.at + 2 < len(self.tokens)
            and self.tokens[self.at + 1][1] == "/"
            and not self.spaced[self.at + 1]
            and self.tokens[self.at + 2][0] == "name"
            and _is_unit(self.tokens[self.at + 2][1])
        )

    def unit(self):
        """The unit written after a value (``N m``, ``N*m``, ``m/s^2``, ``/s``,
        ``1/s``), as a :class:`_Unit`, or None where none is written."""
        if not self.unit_starts():
            return None
        factor, dimension, text = 1.0, (0, 0, 0, 0), ""
        if self.peek()[0] == "number":
            self.take()  # the 1 of "1/s"
        if self.peek()[1] == "/":
            text = "1"
        while True:
            sign = 1
            if self.peek()[1] in ("*", "/") and self.unit_after():
                operator = self.take()[1]
                sign = -1 if operator == "/" else 1
                text += "/" if operator == "/" else " "
            elif text and not (self.space_before() and self.unit_next()):
                break
            elif text:
                text += " "
            word = self.take()[1]
            f, d = _UNITS[_UNIT_NAMES.get(word, word)]
            text += word
            power = 1
            if self.peek()[1] in ("^", "**"):
                self.take()
                negative = self.peek()[1] == "-"
                if negative:
                    self.take()
                kind, digits = self.take()
                if kind != "number" or not digits.isdigit():
                    raise ValueError(
                        f"a unit's power must be an integer, got {digits!r}"
                    )
                power = -int(digits) if negative else int(digits)
                text += f"^{power}"
            factor *= f ** (sign * power)
            dimension = tuple(a + sign * power * b for a, b in zip(dimension, d))
        return _Unit(factor, dimension, text)

    def unit_next(self):
        kind, word = self.peek()
        return kind == "name" and _is_unit(word)

    def unit_after(self):
        """A unit word right after the operator at the current token (``/s``)."""
        after = self.at + 1
        return (
            after < len(self.tokens)
            and self.tokens[after][0] == "name"
            and _is_unit(self.tokens[after][1])
        )

    def expression(self):
        value = self.term()
        while self.peek()[1] in ("+", "-") and not self.sign_starts_item():
            sign = self.take()[1]
            value = value + self.term() if sign == "+" else value - self.term()
        return value

    def term(self):
        start = self.at
        value = self.signed()
        literal = self.at == start + 1 and self.tokens[start][0] == "number"
        while True:
            kind, token = self.peek()
            if token in ("*", "/") and self.unit_after():
                return value  # a unit follows: "10 N*m", "200/s"
            if literal and token in ("pi", "π"):
                self.take()
                value = value * math.pi  # "0.6667 pi", a number times pi
                literal = False
                continue
            if token in ("*", "/"):
                self.take()
                right = self.signed()
                value = value * right if token == "*" else value / right
            elif not self.space_before() and (
                kind == "number"
                or token == "("
                or (kind == "name" and not _is_unit(token))
            ):
                value = value * self.power()  # implicit product, written glued: 2pi
            else:
                return value

    def signed(self):
        if self.peek()[1] in ("+", "-"):
            sign = self.take()[1]
            value = self.signed()
            return value if sign == "+" else -value
        return self.power()

    def power(self):
        value = self.atom()
        if self.peek()[1] in ("^", "**"):
            self.take()
            value = value ** self.signed()
        return value

    def atom(self):
        kind, token = self.peek()
        if kind == "number":
            self.take()
            return float(token)
        if token == "(":
            self.take("(")
            value = self.expression()
            self.take(")")
            return value
        if kind == "name" and token in _FUNCTIONS:
            self.take()
            self.take("(")
            arguments = [self.expression()]
            while self.peek()[1] == ",":
                self.take()
                arguments.append(self.expression())
            self.take(")")
            try:
                return _FUNCTIONS[token](*arguments)
            except (ValueError, TypeError, OverflowError) as error:
                raise ValueError(f"cannot evaluate {token}(...): {error}") from None
        if kind == "name" and token in _CONSTANTS:
            self.take()
            return _CONSTANTS[token]
        found = "the end" if kind is None else repr(token)
        raise ValueError(f"expected a number, found {found}")


def _parse(text):
    """Values (in SI units where a unit is written) and per value its _Unit or None."""
    if not isinstance(text, str):
        raise TypeError(f"the answer text must be a string, got {describe(text)}")
    parser = _Parser(text)
    if not parser.tokens:
        raise ValueError("the answer is empty")
    try:
        pairs = parser.items()
    except RecursionError:
        raise ValueError("it is nested too deeply") from None
    except (ZeroDivisionError, OverflowError, TypeError) as error:
        raise ValueError(f"cannot evaluate it ({error})") from None
    if parser.peek()[0] is not None:
        raise ValueError(f"unexpected {parser.peek()[1]!r}")
    values = [value for value, _ in pairs]
    if any(isinstance(v, complex) or not math.isfinite(v) for v in values):
        raise ValueError("it is not a finite real number")
    return [float(v) for v in values], [unit for _, unit in pairs]


def parse_answer(text):
    """Read a typed answer: ``"pi/3"``, ``"60 deg"``, ``"0.1, -0.2"``, ``"-5 N m"``.

    Numbers are separated by commas, semicolons or whitespace (``"[0.5 -1.2 0.]"``, as
    NumPy prints an array; ``"1 - 2"`` with spaces on both sides is a subtraction).
    A product without ``*`` must be written glued: ``"2pi"`` is 2 pi, ``"pi/6 pi/6"``
    two numbers; a number followed by ``pi`` is a product (``"0.6667 pi"``). A unit
    follows its number: rad, deg (or °), mrad, m, cm, mm, km, s, ms, min, kg, N, kN,
    J, W, kW, Hz and their products, quotients and integer powers (``N m``, ``N*m``,
    ``Nm``, ``N·m``, ``m/s``, ``rad/s``, ``m/rad``, ``m^2``, ``200/s``, ``200 1/s``).
    Brackets or parentheses around a list group it (``(2, 0, 0) m``: the unit after
    them is every entry's), and a unit after the last number of a list where no other
    has one is every number's (``2000, 0, 0 mm``).

    Parameters
    ----------
    text : str
        The answer as typed.

    Returns
    -------
    values : list of float
        The numbers, with units converted to SI (rad, m, s, kg, N, W).
    units : list of str or None
        Per number, the quantity its unit measures (``"angle"``, ``"length"``,
        ``"torque"``...; ``"quantity"`` for one without a name), or None where no
        unit was written.

    Raises
    ------
    ValueError
        With a sentence saying what could not be read. Nothing is evaluated as
        Python.

    Examples
    --------
    >>> parse_answer("pi/2 rad, 90 deg")[0]
    [1.5707963267948966, 1.5707963267948966]
    >>> parse_answer("-5 N m")
    ([-5.0], ['torque'])
    """
    values, units = _parse(text)
    names = [
        None if u is None else _QUANTITIES.get(u.dimension, "quantity") for u in units
    ]
    return values, names


def _unit_of_key(text, where):
    """The _Unit of a key's unit text ("N m", "1/s", "" for a pure number)."""
    if text == "":
        return _Unit(1.0, (0, 0, 0, 0), "")
    try:
        values, units = _parse("1 " + text if not text.startswith("1/") else text)
    except ValueError:
        values, units = [], []
    if len(units) != 1 or units[0] is None or values != [units[0].factor]:
        raise ValueError(f"unit of {where} must be a unit such as 'N m', got {text!r}")
    return units[0]


# ---- answer keys -------------------------------------------------------------------


def _teacher_keys():
    """The folder of the teacher's keys of the assessed exercises, or None: the
    environment variable SCREWKIT_TEACHER_KEYS, else book/teacher_keys of the checkout
    this screwkit runs from (the self-study book is built there). An installed
    screwkit (a wheel) has neither, and no key of an assessed exercise."""
    folder = os.environ.get("SCREWKIT_TEACHER_KEYS")
    if folder:
        return Path(folder)
    root = Path(__file__).resolve().parents[1]
    if (root / "book" / "assessed.yml").is_file():
        return root / "book" / "teacher_keys"
    return None


@cache
def _key_file(chapter):
    if not isinstance(chapter, str) or not re.fullmatch(r"[a-z0-9_]+", chapter):
        raise ValueError(
            f"chapter must be a notebook name such as 'puma_ik', got "
            f"{describe(chapter)}"
        )
    path = resources.files("screwkit").joinpath(f"answers/{chapter}.toml")
    if not path.is_file():
        raise ValueError(
            f"chapter must be one with an answer key, got {chapter!r} "
            f"(no screwkit/answers/{chapter}.toml)"
        )
    exercises = tomllib.loads(path.read_text(encoding="utf-8")).get("exercise", {})
    folder = _teacher_keys()
    teacher = folder / f"{chapter}.toml" if folder is not None else None
    if teacher is not None and teacher.is_file():
        keys = tomllib.loads(teacher.read_text(encoding="utf-8")).get("exercise", {})
        for number, entry in exercises.items():
            if entry.get("assessed") and number in keys:
                exercises[number] = keys[number] | {"assessed": True}
    return exercises


def is_assessed(chapter, number):
    """Whether the teacher marks an exercise (book/assessed.yml): its key is not in
    the package, and :func:`check` and :func:`answer_box` say so.

    Parameters
    ----------
    chapter, number : str, int
        The chapter's notebook name and the exercise's number.

    Returns
    -------
    bool

    Examples
    --------
    >>> is_assessed("rigid_motions", 10), is_assessed("rigid_motions", 2)
    (True, False)
    """
    return bool(_entry(chapter, number).get("assessed", False))


def _entry(chapter, number):
    exercises = _key_file(chapter)
    if isinstance(number, bool) or not isinstance(number, (int, np.integer)):
        raise TypeError(
            f"number must be an exercise number (int), got {describe(number)}"
        )
    if str(number) not in exercises:
        raise ValueError(
            f"number must be a self-checking exercise of {chapter!r} "
            f"(one of {sorted(int(k) for k in exercises)}), got {number}"
        )
    return exercises[str(number)]


class AssessedError(LookupError):
    """The key of an assessed exercise, asked of a screwkit that has none."""


def _assessed_sentence(chapter, number):
    return (
        f"{chapter} exercise {number} is assessed: your teacher marks it. Hand your "
        f"answer to your teacher; this copy of screwkit has no key for it."
    )


def _numbers(answer):
    """Floats and shape of a key's answer: an expression string or nested lists."""
    array = np.array(answer, dtype=object)
    values = [float(sp.N(sp.sympify(v), 17)) for v in array.ravel()]
    return values, list(array.shape)


def _range(bounds, key_unit, where):
    """A key's ``range = ["-180 deg", "0"]``: the bounds in the key's unit and the text
    the box shows ("between -180 deg and 0")."""
    if not (isinstance(bounds, list) and len(bounds) == 2):
        raise ValueError(f"range of {where} must be two bounds, got {bounds!r}")
    limits = []
    for bound in bounds:
        try:
            values, units = _parse(str(bound))
        except ValueError:
            values, units = [], []
        if len(values) != 1 or units[0] and _convert(units[0], key_unit) is None:
            raise ValueError(
                f"range of {where} must be two numbers in its unit, got {bounds!r}"
            )
        if units[0] is not None:  # "-180 deg" for a key in rad
            values[0] *= _convert(units[0], key_unit) / units[0].factor
        limits.append(values[0])
    if not limits[0] < limits[1]:
        raise ValueError(f"range of {where} must be low < high, got {bounds!r}")
    return {
        "low": limits[0],
        "high": limits[1],
        "text": f"between {bounds[0]} and {bounds[1]}",
    }


def _per_text(per, key_unit, where):
    """A key's ``per = "N m"``, checked: a unit other than the key's."""
    if per == "":
        return ""
    if not isinstance(per, str) or _unit_of_key(per, where) == key_unit:
        raise ValueError(f"per of {where} must be a unit other than the key's")
    return per


def answer_key(chapter, number, seed=0):
    """The checked answer of an exercise, as a dict of floats, ready for the page.

    Parameters
    ----------
    chapter, number : str, int
        The chapter's notebook name (e.g. ``"puma_ik"``) and the exercise's number.
    seed : int, optional
        A parametrised exercise's seed (see :func:`variant`); 0 for the others.

    Returns
    -------
    dict
        ``values`` (list of float, row-major, in ``unit``), ``shape``, ``exact`` (the
        key's expression text), ``unit`` (its text: ``"rad"``, ``"N m"``, ``"1/s"``;
        ``""`` for a pure number or a vector of mixed units), ``dimension`` (its
        exponents of kg, m, s and rad) and ``quantity`` (its name, ``"torque"``),
        ``tolerance``, ``rtol``, ``hint``, ``forms``, ``alternatives`` (lists of
        float lists) and ``range`` (None, or ``low``, ``high`` in ``unit`` and the
        ``text`` the box shows),
        ``per`` (a unit: the answer per one of it is accepted too, or ``""``),
        ``assessed`` (the teacher marks it) and, for a vector of mixed units only,
        ``units`` (one per number; ``unit`` is then ``""``).

    Raises
    ------
    AssessedError
        For an assessed exercise (book/assessed.yml) where this screwkit has no key:
        an installed package holds none (see :func:`is_assessed`).

    Examples
    --------
    The angle of a rotation whose trace is 0 (1 + 2 cos(theta) = 0): 2 pi / 3.

    >>> key = answer_key("rigid_motions", 5)
    >>> key["exact"], round(key["values"][0], 4), key["unit"]
    ('2*pi/3', 2.0944, 'rad')
    """
    entry = _entry(chapter, number)
    if "answer" not in entry and entry.get("assessed"):
        raise AssessedError(_assessed_sentence(chapter, number))
    seed = _seed(seed)
    generated = (
        _generated(chapter, number, entry, seed) if entry.get("parametrised") else None
    )
    return _key(chapter, number, entry, seed, generated)


def _key(chapter, number, entry, seed, generated):
    """answer_key's dict from the key file's ``entry`` and, for a parametrised
    exercise, its ``generated`` (numbers, statement, key) for ``seed``."""
    where = f"{chapter} exercise {number}"
    if generated is not None:
        numbers, _, answer = generated
        # rounded far inside any tolerance, so that a zero prints as 0 in the page
        values = [round(float(v), 12) + 0.0 for v in np.ravel(answer)]
        shape = list(np.shape(answer))
        exact = f"computed by screwkit for seed {seed}: " + ", ".join(
            f"{name} = {value:g}" for name, (value, _) in numbers.items()
        )
        entry = entry | {"answer": exact}
    elif seed != 0:
        raise ValueError(
            f"seed must be 0 for {where}, which is not parametrised, got {seed}"
        )
    else:
        values, shape = _numbers(entry["answer"])
    forms = list(entry.get("forms", []))
    unknown = [form for form in forms if form not in FORMS]
    if unknown:
        raise ValueError(f"forms of {where} must be among {FORMS}, got {unknown}")
    unit, units = entry.get("unit", ""), None
    if isinstance(unit, list):  # a vector of mixed units: a twist in rad/s and m/s
        if len(unit) != len(values):
            raise ValueError(
                f"unit of {where} must be one unit or one per number "
                f"({len(values)}), got {len(unit)}"
            )
        units = [str(u) for u in unit]
        for u in units:
            _unit_of_key(u, where)
        unit = ""
    key_unit = _unit_of_key(unit, where)
    bounds = entry.get("range")
    key = {
        "chapter": chapter,
        "number": int(number),
        "values": values,
        "shape": shape,
        "exact": entry["answer"],
        "unit": unit,
        "dimension": list(key_unit.dimension),
        "quantity": _QUANTITIES.get(key_unit.dimension, "quantity"),
        "tolerance": float(entry["tolerance"]),
        "rtol": float(entry.get("rtol", 0.0)),
        "hint": entry.get("hint", ""),
        "forms": forms,
        "alternatives": [_numbers(a)[0] for a in entry.get("alternatives", [])],
        "range": None if bounds is None else _range(bounds, key_unit, where),
        "per": _per_text(entry.get("per", ""), key_unit, where),
        "assessed": bool(entry.get("assessed", False)),
    }
    if units is not None:
        key["units"] = units  # only where set: other boxes unchanged
    return key


# ---- parametrised exercises -------------------------------------------------------
# The draws and statements are in [exercise.N.variant] of the key files, the keys'
# computations in screwkit/_variants/, one module per chapter.


def _seed(seed):
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise ValueError(f"seed must be a whole number >= 0, got {describe(seed)}")
    return int(seed)


@dataclass(frozen=True)
class Variant:
    """One student's version of a parametrised exercise (see :func:`variant`).

    Parameters
    ----------
    chapter : str
        The chapter's notebook name.
    number : int
        The exercise's number.
    seed : int
        The seed; 0 gives the numbers the chapter prints.
    numbers : dict
        The statement's numbers, ``{name: (value, unit)}``.
    statement : str
        The statement with these numbers, in plain text.
    key : dict
        The key, as :func:`answer_key` gives it, computed by screwkit.
    """

    chapter: str
    number: int
    seed: int
    numbers: dict
    statement: str
    key: dict

    def __repr__(self):
        shown = ", ".join(
            f"{name} = {value:g}" + (f" {unit}" if unit else "")
            for name, (value, unit) in self.numbers.items()
        )
        return f"{self.chapter} exercise {self.number}, seed {self.seed}: {shown}"


def variant(chapter, number, seed=0):
    """A parametrised exercise's numbers and key for one seed.

    The numbers are drawn from the seed (seed 0 gives those the chapter prints) and
    the key is computed by screwkit from them, never stored: a teacher gives each
    student a seed (``make answers SEEDS=class.csv`` writes each student's sheet and
    the teacher's keys), and ``check(chapter, number, answer, seed=seed)`` and
    ``answer_box(chapter, number, seed=seed)`` check that student's answer.

    Parameters
    ----------
    chapter, number : str, int
        The chapter's notebook name and the exercise's number.
    seed : int, optional
        A whole number >= 0.

    Returns
    -------
    Variant
        ``numbers`` ({name: (value, unit)}), ``statement`` (plain text) and ``key``.

    Examples
    --------
    >>> variant("motion_in_time", 3, seed=0).numbers
    {'T': (2.0, 's')}
    >>> variant("motion_in_time", 3, seed=0).key["values"]
    [0.9375]
    """
    seed = _seed(seed)
    entry = _entry(chapter, number)
    if not entry.get("parametrised"):
        raise ValueError(
            f"number must be a parametrised exercise of {chapter!r} (one of "
            f"{parametrised(chapter)}), got {number}"
        )
    generated = _generated(chapter, number, entry, seed)
    key = _key(chapter, number, entry, seed, generated)
    return Variant(chapter, int(number), seed, *generated[:2], key)


def _generated(chapter, number, entry, seed):
    """A parametrised exercise's (numbers, statement, key) for ``seed``, its draws
    and statement from ``entry["variant"]`` (``[exercise.NUMBER.variant]`` of its
    key file)."""
    if (chapter, int(number)) not in GENERATORS:
        raise ValueError(
            f"{chapter} exercise {number} is parametrised but has no generator"
        )
    table = checked(
        entry.get("variant"),
        f"[exercise.{number}.variant] of answers/{chapter}.toml",
    )
    return GENERATORS[chapter, int(number)](draw(seed), table)


def parametrised(chapter=None):
    """The parametrised exercises: of one chapter, a sorted list of numbers; of all
    (no chapter), a sorted list of (chapter, number).

    Parameters
    ----------
    chapter : str, optional
        A chapter's notebook name.

    Returns
    -------
    list
    """
    if chapter is None:
        return sorted(GENERATORS)
    return sorted(
        int(n) for n, e in _key_file(chapter).items() if e.get("parametrised")
    )


# ---- checking ----------------------------------------------------------------------


@dataclass(frozen=True)
class Verdict:
    """The result of :func:`check`: ``correct`` and a ``message`` saying why.

    Parameters
    ----------
    correct : bool
        Whether the answer is right (also the Verdict's truth value).
    message : str
        Why, in a sentence for the student.
    chapter : str, optional
        The chapter's name (the exercise's key), for the printed verdict.
    number : int, optional
        The exercise's number in its chapter.

    Examples
    --------
    A verdict is true when the answer is right (2 pi / 3 is about 2.0944 rad):

    >>> bool(check("rigid_motions", 5, "2*pi/3")), bool(check("rigid_motions", 5, "1"))
    (True, False)
    """

    correct: bool
    message: str
    chapter: str = ""
    number: int = 0

    def __bool__(self):
        return self.correct

    def __repr__(self):
        mark = "✓ right" if self.correct else "✗ not yet"
        return f"{self.chapter} exercise {self.number}: {mark}. {self.message}"

    def _repr_html_(self):
        colour = "#1a7f37" if self.correct else "#b35900"
        mark = "✓ Right" if self.correct else "✗ Not yet"
        return (
            f'<div role="status" style="color:{colour}"><b>{mark}</b> '
            f"({html.escape(self.chapter)} exercise {self.number}): "
            f"{html.escape(self.message)}</div>"
        )


def _as_values(answer):
    """Floats from whatever a student passes, and per float its _Unit or None;
    ValueError/TypeError with a reason."""
    if isinstance(answer, str):
        return _parse(answer)
    if isinstance(answer, sp.MatrixBase):
        answer = np.array(answer.tolist(), dtype=object)
    if isinstance(answer, (list, tuple, np.ndarray)):
        flat = np.array(answer, dtype=object).ravel().tolist()
        if any(isinstance(v, (list, tuple, np.ndarray)) for v in flat):
            raise ValueError("its rows have different lengths")
        values, units = [], []
        for entry in flat:
            v, u = _as_values(entry)
            values += v
            units += u
        return values, units
    if isinstance(answer, (bool, np.bool_)) or answer is None:
        raise TypeError(f"expected a number, got {describe(answer)}")
    if isinstance(answer, sp.Basic) or hasattr(answer, "__float__"):
        try:
            value = (
                float(sp.N(answer)) if isinstance(answer, sp.Basic) else float(answer)
            )
        except (TypeError, ValueError):
            raise TypeError(f"expected a real number, got {describe(answer)}") from None
        if not math.isfinite(value):
            raise ValueError(f"expected a finite number, got {value}")
        return [value], [None]
    raise TypeError(
        f"expected a number, a list of numbers or a text, got {describe(answer)}"
    )


def _unit_text(key):
    return f" {key['unit']}" if key["unit"] else ""


def _close(x, a, key):
    x, a = np.asarray(x, float), np.asarray(a, float)
    d = x - a
    if "modulo 2pi" in key["forms"]:
        period = 360.0 if key["unit"] == "deg" else 2 * math.pi
        d = (d + period / 2) % period - period / 2
    return bool(
        np.all(np.abs(d) <= key["tolerance"] + key["rtol"] * np.abs(a) + ZERO_TOL)
    )


def _wrapped_sorted(values, key):
    """Angles wrapped into half a period either side of 0, sorted (for "any order")."""
    period = 360.0 if key["unit"] == "deg" else 2 * math.pi
    return sorted((u + period / 2) % period - period / 2 for u in values)


def _matches(x, key):
    """True if ``x`` (floats in the key's unit) is one of the accepted forms."""
    candidates = [key["values"], *key["alternatives"]]
    if "either sign" in key["forms"]:
        candidates += [[-v for v in c] for c in candidates]
    for a in candidates:
        if len(a) != len(x):
            continue
        if "any order" in key["forms"]:
            if "modulo 2pi" in key["forms"]:
                if _close(_wrapped_sorted(x, key), _wrapped_sorted(a, key), key):
                    return True
            elif _close(sorted(x), sorted(a), key):
                return True
        elif _close(x, a, key):
            return True
    return False


def _diagnose(x, key):
    """Why ``x`` is wrong, where a common slip explains it."""
    unit, n = key["unit"], len(key["values"])
    # a unit slip only explains an answer that is not zero (where any small number fits)
    nonzero = any(abs(v) > key["tolerance"] for v in key["values"])
    for slip_unit, factor, text in _SLIPS:
        if nonzero and unit == slip_unit and _matches([v * factor for v in x], key):
            return text + "."
    if _matches([-v for v in x], key):
        return "the sign is flipped."
    if n > 1 and _matches_abs(x, key):
        return "the magnitudes are right but some signs are wrong."
    if (
        n > 1
        and "any order" not in key["forms"]
        and _close(sorted(x), sorted(key["values"]), key)
    ):
        return "the right numbers in the wrong order."
    if not _in_range(x, key):
        return f"the answer is outside the range asked for, {key['range']['text']}."
    return None


def _matches_abs(x, key):
    return _close(np.abs(x), np.abs(key["values"]), key)


def _in_range(x, key):
    """Every value within the key's range, if it has one (the tolerance is slack)."""
    bounds, slack = key["range"], key["tolerance"]
    return bounds is None or all(
        bounds["low"] - slack <= v <= bounds["high"] + slack for v in x
    )


def _per_unit(key):
    """The unit an answer "per unit of ``key['per']``" is in (a force per N m of
    torque: 1/m), or None where the key has no ``per``."""
    if not key.get("per"):
        return None
    where = f"{key['chapter']} exercise {key['number']}"
    key_unit = _unit_of_key(key["unit"], where)
    per = _unit_of_key(key["per"], where)
    return _Unit(
        key_unit.factor / per.factor,
        tuple(a - b for a, b in zip(key_unit.dimension, per.dimension)),
        f"{key['unit']}/({key['per']})",
    )


def _to_key_unit(x, units, key):
    """The values in the key's unit, or the sentence saying which unit does not fit.
    A key with ``per`` (the statement's bound is one of that unit) also takes the
    answer per unit of it: 4.05 N per N m of torque is 4.05 1/m."""
    where = f"{key['chapter']} exercise {key['number']}"
    texts = key.get("units") or [key["unit"]] * len(x)
    if len(texts) != len(x):
        return list(x)  # the wrong count is the answer's fault, said next
    per = _per_unit(key)
    converted = []
    for value, unit, text in zip(x, units, texts):
        if unit is None:
            converted.append(value)
            continue
        key_unit = _unit_of_key(text, where)
        factor = _convert(unit, key_unit)
        if factor is None and per is not None:
            factor = _convert(unit, per)
            factor = None if factor is None else factor * per.factor / key_unit.factor
        if factor is None:
            expected = _quantity(key_unit.dimension)
            expected += f" ({text})" if text else " (no unit)"
            found = f"{_quantity(unit.dimension)} ({unit.text})"
            return f"Expected {expected}, found {found}."
        converted.append(value / unit.factor * factor)
    return converted


def _decimal_comma(text, n):
    """A hint for "4,05" (read as two numbers), else "": only where the text with
    decimal points has the ``n`` numbers the key asks for."""
    if not isinstance(text, str) or not re.search(r"\d,\d", text):
        return ""
    fixed = re.sub(r"(\d),(\d)", r"\1.\2", text)
    try:
        if len(_parse(fixed)[0]) != n:
            return ""
    except ValueError:
        return ""
    return " Use a decimal point: " + fixed + "."


def _in_radians(x, units, key):
    """A box in degrees answered in radians without a unit (``pi/2``, ``1.5708``)
    is right when the radians are: no slip gives the radian measure of the answer."""
    nonzero = any(abs(v) > key["tolerance"] for v in key["values"])
    if key["unit"] != "deg" or not nonzero or any(u is not None for u in units):
        return False
    degrees = [math.degrees(v) for v in x]
    return _in_range(degrees, key) and _matches(degrees, key)


def _verdict(x, units, key, text=None):
    chapter, number = key["chapter"], key["number"]
    x = _to_key_unit(x, units, key)
    if isinstance(x, str):
        return Verdict(False, x, chapter, number)
    tolerance = f"±{key['tolerance']:g}{_unit_text(key)}"
    n = len(key["values"])
    if len(x) == n and _in_range(x, key) and _matches(x, key):
        return Verdict(True, f"Within {tolerance} of the answer.", chapter, number)
    if len(x) == n and _in_radians(x, units, key):
        message = f"Within {tolerance} of the answer (read as radians)."
        return Verdict(True, message, chapter, number)
    if len(x) != n:
        what = "one number" if n == 1 else f"{n} numbers"
        reason = f"expected {what}, got {len(x)}." + _decimal_comma(text, n)
    else:
        reason = _diagnose(x, key) or f"not within {tolerance} of the answer."
    hint = f" Hint: {key['hint']}" if key["hint"] else ""
    return Verdict(False, reason[0].upper() + reason[1:] + hint, chapter, number)


def check(chapter, number, answer, seed=0):
    """Check an answer to a self-checking exercise.

    Parameters
    ----------
    chapter, number : str, int
        The chapter's notebook name (e.g. ``"puma_ik"``) and the exercise's number.
    answer : number, str, sequence or array
        A number, a SymPy expression, a text (``"pi/3"``, ``"60 deg"``,
        ``"0.1, 0.2"``), or a list or array (flattened row-major). Numbers without
        a unit are in the exercise's unit.
    seed : int, optional
        A parametrised exercise's seed (:func:`variant`); 0 for the others.

    Returns
    -------
    Verdict
        ``.correct`` and ``.message`` (why a wrong answer is wrong: units, sign,
        length, order, else the exercise's hint). Text that cannot be read gives a
        wrong verdict saying so, never an exception. An assessed exercise whose key
        this screwkit does not have (an installed package) gives a verdict saying
        that the teacher marks it.

    Examples
    --------
    >>> check("rigid_motions", 2, "2, 0, 0").correct
    True
    """
    try:
        key = answer_key(chapter, number, seed)
    except AssessedError as error:
        return Verdict(False, str(error), chapter, number)
    try:
        values, units = _as_values(answer)
    except (TypeError, ValueError) as error:
        return Verdict(False, f"Could not read the answer: {error}", chapter, number)
    return _verdict(values, units, key, answer)


# ---- the box in the page -----------------------------------------------------------

_ids = itertools.count(1)
_script_sent = False


def exercises_script():
    """The JavaScript of the answer boxes (package data ``static/exercises.js``), with
    this module's table of units written into it (one table for both checkers)."""
    script = (
        resources.files("screwkit")
        .joinpath("static/exercises.js")
        .read_text(encoding="utf-8")
    )
    tables = {
        "units": {name: [f, list(d)] for name, (f, d) in _UNITS.items()},
        "names": _UNIT_NAMES,
        "quantities": {",".join(map(str, d)): q for d, q in _QUANTITIES.items()},
    }
    slot = "/*SCREWKIT-UNIT-TABLES*/ {units: {}, names: {}, quantities: {}}"
    if slot not in script:
        raise RuntimeError("static/exercises.js has lost its slot for the unit tables")
    return script.replace(slot, json.dumps(tables, ensure_ascii=False))


class AnswerBox:
    """A field and a Check button in the page, checked by ``exercises.js``, no kernel.

    The script is inlined into the first box of a kernel session (one page) and
    defines ``window.screwkitExercises``; every box mounts itself with it.

    Parameters
    ----------
    key : dict
        The exercise's key, as the answer files store it (``chapter``, ``number``,
        ``values``, ``shape``, ``unit``, ...).
    script : str
        The JavaScript of ``exercises.js``, inlined into the page.

    Examples
    --------
    >>> box = answer_box("rigid_motions", 5, script=False)
    >>> box.key["exact"], box.key["unit"]
    ('2*pi/3', 'rad')
    """

    def __init__(self, key, script):
        self.key = key
        self.script = script
        self.id = f"sk-exercise-{key['chapter']}-{key['number']}-{next(_ids)}"

    def __repr__(self):
        return (
            f"Answer box for {self.key['chapter']} exercise {self.key['number']} "
            f"(check it in the notebook with sk.exercises.check("
            f"{self.key['chapter']!r}, {self.key['number']}, answer))"
        )

    def _repr_html_(self):
        key = {
            k: self.key[k]
            for k in (
                "values",
                "shape",
                "unit",
                "tolerance",
                "rtol",
                "hint",
                "forms",
                "alternatives",
            )
        }
        unit = html.escape(self.key["unit"]) or "no unit"
        bounds = ""
        if self.key["range"] is not None:
            key["range"] = self.key["range"]  # only where set: other boxes unchanged
            bounds = ", " + html.escape(self.key["range"]["text"])
        if self.key.get("per"):
            key["per"] = self.key["per"]
        if self.key.get("units"):
            key["units"] = self.key["units"]
            unit = html.escape(", ".join(self.key["units"]))
        payload = json.dumps(key, sort_keys=True).replace("</", "<\\/")
        ident = self.id
        script = f"<script>\n{exercises_script()}</script>\n" if self.script else ""
        return (
            f'<div class="sk-answer-box" id="{ident}" style="font:14px sans-serif;'
            f'margin:0.5em 0">\n'
            f'<script type="application/json">{payload}</script>\n'
            f'<label for="{ident}-input">Exercise {self.key["number"]}, your answer '
            f"({unit}{bounds}): </label>\n"
            f'<input id="{ident}-input" type="text" size="28" autocomplete="off" '
            f'spellcheck="false">\n'
            f'<button type="button">Check</button>\n'
            f'<div class="sk-verdict" role="status" aria-live="polite"></div>\n'
            f"<noscript>Check your answer in the notebook: sk.exercises.check("
            f"{html.escape(repr(self.key['chapter']))}, {self.key['number']}, answer)"
            f"</noscript>\n</div>\n{script}"
            f"<script>window.screwkitExercises && window.screwkitExercises.mountAll();"
            f"</script>\n"
        )


class AssessedBox:
    """The box of an assessed exercise where screwkit has no key: it says that the
    teacher marks the answer, and has no key and no Check button.

    Parameters
    ----------
    chapter, number : str, int
        The chapter's notebook name and the exercise's number.
    """

    def __init__(self, chapter, number):
        self.chapter, self.number = chapter, int(number)

    def __repr__(self):
        return (
            f"Exercise {self.number} of {self.chapter} is assessed: hand your answer "
            f"to your teacher, who marks it."
        )

    def _repr_html_(self):
        return (
            f'<div class="sk-assessed-box" style="font:14px sans-serif;margin:0.5em 0">'
            f"<p><strong>Exercise {self.number} is assessed:</strong> hand your answer "
            f"to your teacher; this edition of the book does not check it.</p></div>"
        )


def answer_box(chapter, number, script=None, seed=0):
    """A self-checking answer box for the page.

    Parameters
    ----------
    chapter, number : as in :func:`check`.
    script : bool, optional
        Inline ``exercises.js`` with this box; by default only the first box of the
        session carries it (once per page).
    seed : int, optional
        A parametrised exercise's seed (:func:`variant`); the page shows seed 0.

    Returns
    -------
    AnswerBox or AssessedBox
        An assessed exercise whose key this screwkit does not have gives an
        :class:`AssessedBox`, which says that the teacher marks it. Otherwise
        displayed as an HTML field, a Check button and a verdict announced to
        screen readers; the check runs in the browser with the key's tolerance,
        forms and hint.

    Examples
    --------
    In a notebook the box shows as a field and a Check button; its text says how to
    check in Python:

    >>> print(answer_box("rigid_motions", 5, script=False))
    Answer box for rigid_motions exercise 5 (check it in the notebook with
    sk.exercises.check('rigid_motions', 5, answer))
    """
    global _script_sent
    try:
        key = answer_key(chapter, number, seed)
    except AssessedError:
        return AssessedBox(chapter, number)
    if script is None:
        script, _script_sent = not _script_sent, True
    return AnswerBox(key, bool(script))
