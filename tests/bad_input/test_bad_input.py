"""The bad-input contract, one driver for every table: each row's call raises exactly
its error with a sentence naming the argument (the format is rows.py's), and every
public function of screwkit, found by walking the package, is called by some row.

The tables are the modules ``table_*.py`` beside this file, found by that name.
"""

import importlib
import importlib.util
import inspect
import pkgutil
import re
import sys
from pathlib import Path

import pytest

import screwkit

HERE = Path(__file__).parent
TABLES = sorted(path.stem for path in HERE.glob("table_*.py"))

#: Rows held when the five old files became one contract: 143 (api) + 286
#: (core) + 34 (ik) + 72 (modules) + 79 (screws, without its one valid control call,
#: now a test of test_valid_input.py); the tables may grow, never shrink unnoticed.
ROWS_WHEN_MERGED = 614

#: Public callables with arguments that need no row, and why.
NO_ROW = {
    "screwkit.transforms.axis_coordinates": "unchecked kernel; twist_from_axis checks",
}


#: Modules of a family folder that hold its unchecked kernels: every call into them
#: comes through the folder's public names (sk.parallel's model, which checks first).
KERNEL_MODULES = {
    "screwkit.parallel.legs": "the legs' kernels, called by ParallelManipulator",
    "screwkit.parallel.numeric": "Newton on the loop closure, called by pm.fk",
    "screwkit.parallel.search": "the multistart search, called by pm.fk_all",
}


def rows():
    """(table, row) for every row of every table."""
    found = []
    for table in TABLES:
        found += [(table, r) for r in importlib.import_module(table).ROWS]
    return found


ROWS = rows()


def test_the_tables_are_found_and_keep_their_rows():
    assert len(TABLES) >= 5
    assert len(ROWS) >= ROWS_WHEN_MERGED


def test_row_ids_are_unique():
    ids = [f"{table}:{r.id}" for table, r in ROWS]
    assert sorted({i for i in ids if ids.count(i) > 1}) == []


def test_every_row_is_a_value_or_type_error_naming_an_argument():
    for table, r in ROWS:
        assert r.error in (ValueError, TypeError), f"{table}:{r.id}"
        assert callable(r.call) and r.name.strip(), f"{table}:{r.id}"


#: Rows whose message names the argument and says what is wrong, but in words other
#: than "got" or "must" (what was given or expected); each one checked to stay so.
OTHER_WORDING = {
    "table_core:draw_mechanism-values-missing": "has no number for the symbol",
    "table_screws:ScrewSystem-11": "mix floats with the symbols",
    "table_screws:mobility-10": "is a wrench",
    "table_screws:mobility-11": "mix floats with the symbols",
    "table_screws:mobility-15": "gives values for",
    "table_screws:mobility-16": "gives values for",
}
SENTENCE_WORDS = ("got", "must", "undefined", "cannot")

#: The longest message a row may raise (characters): a message names the argument and
#: says what was wrong; it quotes an input only through screwkit._checks.quoted (at
#: most QUOTE_CHARS characters), never the whole input (19.8 MB for an
#: array of out-of-range times). The longest today, about 450, explain a choice of
#: IK engines.
MAX_MESSAGE_CHARS = 600


def param(table, r):
    case_id = f"{table}:{r.id}"
    marks = [pytest.mark.xfail(strict=True, reason=r.gap)] if r.gap else []
    return pytest.param(r, case_id, marks=marks, id=case_id)


@pytest.mark.parametrize("r, case_id", [param(table, r) for table, r in ROWS])
def test_bad_input_is_a_clear_error_naming_the_argument(r, case_id):
    with pytest.raises(r.error) as raised:
        r.call()
    message = str(raised.value)
    assert type(raised.value) is r.error  # not a subclass from deep inside NumPy
    assert len(message) <= MAX_MESSAGE_CHARS, (
        f"a message of {len(message)} characters: {message[:300]}..."
    )
    assert re.search(rf"(?<![\w.]){re.escape(r.name)}(?!\w)", message), (
        f"{r.name!r} not named in: {message}"
    )
    if case_id in OTHER_WORDING:
        assert OTHER_WORDING[case_id] in message
    else:
        assert any(word in message for word in SENTENCE_WORDS), (
            f"not a sentence saying what was expected or given: {message}"
        )
    if r.match is not None:
        assert re.search(r.match, message), f"{r.match!r} not in: {message}"


# ---- every public function has a row -------------------------------------------------


def public_modules():
    """screwkit and every module or package below it whose dotted name has no part
    starting with '_'."""
    yield screwkit
    for info in pkgutil.walk_packages(screwkit.__path__, "screwkit."):
        if any(part.startswith("_") for part in info.name.split(".")):
            continue
        if info.name in KERNEL_MODULES:
            continue
        yield importlib.import_module(info.name)


def public_functions():
    """Every function, method and classmethod with arguments that a public module lists
    in ``__all__``, each once (wherever it is defined): {function: dotted name}."""
    found = {}

    def add(function, name, method=False):
        # a method's first parameter is its instance (or class), whatever its name: a
        # Chain method that is a function of the chain names it ``chain``
        if isinstance(function, classmethod):
            function = function.__func__
        if not inspect.isfunction(function):
            return
        parameters = list(inspect.signature(function).parameters)
        if parameters[1 if method else 0 :]:
            found.setdefault(function, name)

    for module in public_modules():
        for name in getattr(module, "__all__", []):
            item = getattr(module, name)
            if not getattr(item, "__module__", "").startswith("screwkit"):
                continue
            if inspect.isclass(item):
                for key, value in vars(item).items():
                    if not key.startswith("_"):
                        add(
                            value,
                            f"{item.__module__}.{item.__qualname__}.{key}",
                            method=not isinstance(value, staticmethod),
                        )
            else:
                add(item, f"{item.__module__}.{name}")
    return found


def called_directly(calls, sources, wrappers=frozenset()):
    """The code objects that ``calls`` enter directly: called from code in the files
    ``sources`` (a row's lambda or a builder of its arguments), or from one of
    ``wrappers`` (the code of a decorator's wrapper) called from there. Exceptions are
    swallowed: which ones is the rows' own test."""
    called = set()

    def from_sources(frame):
        return frame is not None and frame.f_code.co_filename in sources

    def profile(frame, event, arg):
        if event != "call" or frame.f_back is None:
            return
        caller = frame.f_back
        if from_sources(caller) or (
            caller.f_code in wrappers and from_sources(caller.f_back)
        ):
            called.add(frame.f_code)

    for call in calls:
        sys.setprofile(profile)
        try:
            call()
        except Exception:  # noqa: BLE001
            pass
        finally:
            sys.setprofile(None)
        plt = sys.modules.get("matplotlib.pyplot")
        if plt is not None:
            plt.close("all")
    return called


def test_every_public_function_has_a_bad_input_row():
    public = public_functions()
    wrappers = {f.__code__ for f in public if inspect.unwrap(f) is not f}
    tables = {str(HERE / f"{table}.py") for table in TABLES}
    called = called_directly([r.call for _, r in ROWS], tables, wrappers)
    missing = sorted(
        name
        for function, name in public.items()
        if inspect.unwrap(function).__code__ not in called and name not in NO_ROW
    )
    assert missing == [], f"no bad-input row calls: {missing}"
    assert sorted(set(NO_ROW) - set(public.values())) == [], "NO_ROW names no function"


def test_the_trace_counts_direct_calls_only():
    """sk.rotz called from here is counted; the checks it calls inside are not."""
    entered = set()

    def every_call(frame, event, arg):
        if event == "call" and "screwkit" in frame.f_code.co_filename:
            entered.add(frame.f_code)

    sys.setprofile(every_call)
    try:
        screwkit.rotz(0.5)
    finally:
        sys.setprofile(None)
    called = called_directly([lambda: screwkit.rotz(0.5)], {__file__})
    assert called & entered == {screwkit.rotz.__code__}
    assert len(entered) > 1  # rotz's own checks and kernels, not counted


def test_the_coverage_walk_sees_every_module():
    """The walk is by rule: it finds the display layer and the families' packages too,
    and skips private modules."""
    names = {module.__name__ for module in public_modules()}
    assert {"screwkit.plotting", "screwkit.transforms", "screwkit.viewer"} <= names
    assert not any(part.startswith("_") for n in names for part in n.split(".")[1:])
