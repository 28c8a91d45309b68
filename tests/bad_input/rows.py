"""The one format of a bad-input row, shared by every table (``table_*.py``).

A table is a module named ``table_<topic>.py`` in this folder with a list ``ROWS`` of
:func:`row` entries; tests/bad_input/test_bad_input.py finds the tables by that name,
runs every row and checks that every public function of screwkit has one.

Each row is a call that must raise ``error`` exactly (not a subclass from deep inside
NumPy) with a sentence that names the argument ``name`` as a word, and says what was
expected or what was given; ``match`` is an optional further pattern the sentence must
contain. Robots and figures the calls need are built when the row runs (cached
builders), never when a table is imported.
"""

from collections.abc import Callable
from typing import NamedTuple


class Row(NamedTuple):
    """One bad-input case: ``call()`` must raise ``error`` naming ``name``."""

    id: str
    call: Callable[[], object]
    error: type
    name: str
    match: str | None = None
    gap: str | None = None


def row(case_id, call, error, name, match=None, gap=None):
    """One row of a bad-input table.

    Parameters
    ----------
    case_id : str
        Unique in its table: what is called and what is wrong, e.g. ``"rotz-nan"``.
    call : callable
        No arguments; calls screwkit with the bad input.
    error : type
        ``ValueError`` or ``TypeError``, raised exactly.
    name : str
        The argument the message must name (as a word).
    match : str, optional
        A regular expression the message must also contain.
    gap : str, optional
        A known gap in screwkit's check, said in a sentence: the row is expected to
        fail (strict), so that it is noticed when screwkit closes the gap.

    Returns
    -------
    Row
    """
    return Row(case_id, call, error, name, match, gap)


# ---- one call, several bad inputs: a row per case ----------------------------------
# Each builder below makes one row per entry of ``cases``, with the id
# ``id_format.format(case)`` (e.g. ``"numeric {}"``). ``call`` is a lambda written in
# the table, so that the coverage test sees the table call screwkit; ``match`` is a
# pattern or None, as for :func:`row`.


def keyword_rows(id_format, call, cases):
    """Rows that each pass ``call`` one bad keyword argument, as
    ``(case, keyword, value, error, match)`` in ``cases``; the message must name the
    keyword. E.g. ``call = lambda **kw: sk.f(puma(), **kw)``."""
    return [
        row(
            id_format.format(case),
            lambda keyword=keyword, value=value: call(**{keyword: value}),
            error,
            keyword,
            match,
        )
        for case, keyword, value, error, match in cases
    ]


def value_rows(id_format, call, name, cases):
    """Rows that each pass ``call`` one bad value of the argument ``name``, as
    ``(case, value, error, match)`` in ``cases``. E.g.
    ``call = lambda R: sk.homogeneous(R)``."""
    return [
        row(id_format.format(case), lambda value=value: call(value), error, name, match)
        for case, value, error, match in cases
    ]


def argument_rows(id_format, call, cases):
    """Rows that each call ``call(*args)``, one of the arguments bad, as
    ``(case, args, error, name, match)`` in ``cases``: ``name`` the argument the
    message must name. E.g. ``call = lambda p, q: ln.Line.through(p, q)``."""
    return [
        row(id_format.format(case), lambda args=args: call(*args), error, name, match)
        for case, args, error, name, match in cases
    ]
