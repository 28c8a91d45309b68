"""Every public function, class and method of screwkit has a numpydoc docstring.

Public means what the API page documents (book/_ext/api_reference.py): each public
module of the package (no part of its dotted name starts with an underscore), and in it
the names of its ``__all__`` (or, lacking one, the functions and classes it defines),
with the public methods and properties of those classes. Each object is checked once,
wherever it is re-exported.

Each docstring goes through numpydoc's own validator (``numpydoc.validate``, pinned in
.ci/lint-requirements.txt), keeping this subset of its checks (``CHECKS``):

* GL08: the object has a docstring;
* GL06, GL07: its sections are numpydoc sections ("Parameters", "Returns", ...), in
  numpydoc's order (a "Return:" or "Args:" section fails);
* PR01, PR02: the Parameters section names every parameter, and only those (a class
  documents its constructor's: a dataclass, its fields);
* RT01: a function or method that returns something has a Returns section.

A method that overrides a documented method of a base class and has no docstring of
its own inherits the base's, as Python (``inspect.getdoc``) and the API page (autodoc)
show it; that docstring is then checked against the override's own signature (the
parallel legs implement :class:`~screwkit.parallel.legs.Legs` so).

A property needs a summary only (numpydoc documents it as an attribute). The summary
style checks (SS*), extended summaries, examples and "See Also" are not enforced.

Usage: python .ci/check_docstrings.py  (make lint); exits 1 listing each failure.
"""

import enum
import functools
import importlib
import inspect
import sys
from pathlib import Path

from numpydoc.docscrape import get_doc_object
from numpydoc.validate import validate

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "book" / "_ext"))
# what the API page documents: its public modules, and their public names
from api_reference import public_modules, public_names  # noqa: E402

PACKAGE = "screwkit"

CHECKS = {"GL06", "GL07", "GL08", "PR01", "PR02", "RT01"}


def members(cls):
    """The public methods and properties a class defines itself.

    Parameters
    ----------
    cls : type
        A public class of the package.

    Returns
    -------
    list of (str, object)
        (name, the function or property object) pairs, in definition order; an
        Enum's members and a class's data attributes are left out.
    """
    found = []
    for name, value in vars(cls).items():
        if name.startswith("_"):
            continue
        if isinstance(value, (classmethod, staticmethod)):
            value = value.__func__
        if inspect.isfunction(value) or isinstance(value, property):
            found.append((name, value))
    return found


def objects(package):
    """Every object to check: (full name, object), each object once.

    Parameters
    ----------
    package : module
        The package, imported.

    Returns
    -------
    list of (str, object)
        Functions, classes, methods and properties, named where they are defined.
    """
    seen, found = set(), []

    def add(name, value):
        if id(value) not in seen:
            seen.add(id(value))
            found.append((name, value))

    for module in public_modules(package):
        for name in public_names(module):
            value = getattr(module, name)
            if not (inspect.isfunction(value) or inspect.isclass(value)):
                continue
            home = getattr(value, "__module__", "") or ""
            if not home.startswith(PACKAGE):
                continue
            full = f"{home}.{value.__qualname__}"
            add(full, value)
            if inspect.isclass(value):
                for member_name, member in members(value):
                    add(f"{full}.{member_name}", member)
    return found


def inherited(function):
    """A stand-in for an undocumented override, holding its base's docstring.

    Parameters
    ----------
    function : function
        A method without a docstring whose base class documents the same method.

    Returns
    -------
    function
        A function with ``function``'s name and signature and the inherited docstring.
    """
    stand_in = functools.update_wrapper(lambda *args, **kwargs: None, function)
    stand_in.__doc__ = inspect.getdoc(function)
    return stand_in


def problems(value):
    """The failed checks of one object's docstring.

    Parameters
    ----------
    value : function, type or property
        The object to check.

    Returns
    -------
    list of (str, str)
        (numpydoc check code, message) pairs, empty when the docstring passes.
    """
    if inspect.isfunction(value) and value.__doc__ is None and inspect.getdoc(value):
        value = inherited(value)
    errors = [
        (code, text)
        for code, text in validate(get_doc_object(value))["errors"]
        if code in CHECKS
    ]
    if inspect.isclass(value) and issubclass(value, enum.Enum):
        # an Enum's "parameters" are those of Enum's own constructor, not its members
        errors = [(code, text) for code, text in errors if code not in ("PR01", "PR02")]
    return errors


def main():
    package = importlib.import_module(PACKAGE)
    failures = [
        f"{name}: {code} {text}"
        for name, value in objects(package)
        for code, text in problems(value)
    ]
    for line in failures:
        print(line)
    if failures:
        print(
            f"{len(failures)} docstring problems: write numpydoc docstrings "
            "(CONTRIBUTING.md, 'Docstrings')",
            file=sys.stderr,
        )
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
