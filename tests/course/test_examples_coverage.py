"""Every public function, class and method of screwkit has its own example.

Public means what the API page documents (book/_ext/api_reference.py, whose walk this
test uses): the names of each public module's ``__all__`` (or, lacking one, the
functions and classes it defines), and the public methods those classes define
themselves (classmethods and staticmethods included; properties are attributes and
need none). Each object is checked once, under the module that defines it.

An example is a numpydoc ``Examples`` section holding at least one ``>>>`` line;
``pytest --doctest-modules screwkit`` (``make test``) runs it, so it stays true.

Two lists, both explicit, both empty now, may let objects through
while a piece of work is under way:

* ``OTHER_OWNERS``: the modules that another piece of work rewrites at the moment
  (the split of ``Chain``, the Jacobians and the IK family); their examples come with
  that work;
* ``NOT_YET``: single objects whose examples are still to be written.

A name in either list that has gained its example fails the test too, so the lists
only shrink.
"""

import importlib.util
import inspect
import re
import sys
from pathlib import Path

import screwkit as sk

ROOT = Path(__file__).resolve().parents[2]

# Modules rewritten by another piece of work at the moment (their examples come with
# it). Empty: every public callable has its example; a name added here
# must leave again once that work has landed.
OTHER_OWNERS = ()

# Objects whose examples are still to be written (full names, where defined).
# Temporary: empty this list.
NOT_YET = ()


def _api_reference():
    name = "api_reference"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(
            name, ROOT / "book" / "_ext" / "api_reference.py"
        )
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
    return sys.modules[name]


def public_callables():
    """[(full name, object)]: each public function, class and method once."""
    api = _api_reference()
    seen, found = set(), []

    def add(name, value):
        if id(value) not in seen:
            seen.add(id(value))
            found.append((name, value))

    for module in api.public_modules(sk):
        for name in api.public_names(module):
            value = getattr(module, name)
            if not (inspect.isfunction(value) or inspect.isclass(value)):
                continue  # data: a constant, a dict
            home = getattr(value, "__module__", "") or ""
            if home.split(".")[0] != "screwkit":
                continue
            full = f"{home}.{value.__qualname__}"
            add(full, value)
            if inspect.isclass(value):
                for member, attribute in vars(value).items():
                    if isinstance(attribute, (classmethod, staticmethod)):
                        attribute = attribute.__func__
                    if not member.startswith("_") and inspect.isfunction(attribute):
                        add(f"{full}.{member}", getattr(value, member))
    return found


EXAMPLES = re.compile(r"^Examples\n-+\n(.*?)(?=^\S[^\n]*\n-{3,}\n|\Z)", re.M | re.S)


def has_example(value):
    """Whether the docstring has an Examples section with a ``>>>`` line."""
    match = EXAMPLES.search(inspect.getdoc(value) or "")
    return bool(match) and re.search(r"^\s*>>> ", match.group(1), re.M) is not None


def excused(name, value):
    """In ``NOT_YET``, or of a module of ``OTHER_OWNERS`` (where it is defined, or the
    class it is a method of: ``Chain.table`` is defined in a private module)."""
    module = getattr(value, "__module__", "") or ""
    owned = any(
        where == m or where.startswith(m + ".")
        for m in OTHER_OWNERS
        for where in (module, name)
    )
    return owned or name in NOT_YET


def test_the_walk_finds_the_public_api():
    names = {name for name, _ in public_callables()}
    assert "screwkit.transforms.rotz" in names  # a function
    assert "screwkit.screws.Screw.from_axis" in names  # a classmethod
    assert "screwkit.systems.ScrewSystem.reciprocal" in names  # a method
    assert "screwkit.systems.ScrewSystem.rank" not in names  # a property


def test_the_example_rule():
    def documented():
        """Summary.

        Examples
        --------
        >>> 1 + 1
        2
        """

    def prose_only():
        """Summary.

        Examples
        --------
        Call it.

        Notes
        -----
        >>> 1 + 1
        2
        """

    assert has_example(documented) and not has_example(prose_only)


def test_every_public_callable_has_an_example():
    missing = [
        name
        for name, value in public_callables()
        if not has_example(value) and not excused(name, value)
    ]
    assert not missing, "no Examples section with a >>> line:\n" + "\n".join(missing)


def test_the_allow_lists_only_shrink():
    callables = dict(public_callables())
    assert set(NOT_YET) <= set(callables), set(NOT_YET) - set(callables)
    done = [name for name in NOT_YET if has_example(callables[name])]
    assert not done, f"remove from NOT_YET, they have examples now: {done}"
