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


def keyword_rows(id_format, call, cases):
    """Rows that each pass ``call`` one bad keyword argument.

    Parameters
    ----------
    id_format : str
        The rows' ids, ``id_format.format(case)``, e.g. ``"numeric {}"``.
    call : callable
        Takes the keyword argument, e.g. ``lambda **kw: sk.f(puma(), **kw)``.
    cases : list of tuple
        ``(case, keyword, value, error, match)``; each row's message must name the
        keyword.

    Returns
    -------
    list of Row
    """
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
