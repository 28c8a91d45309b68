"""The docstring check fails on what it claims to catch, passes numpydoc docstrings."""

import dataclasses
import importlib.util
import warnings
from pathlib import Path

SPEC = importlib.util.spec_from_file_location(
    "check_docstrings", Path(__file__).with_name("check_docstrings.py")
)
check = importlib.util.module_from_spec(SPEC)
SPEC.loader.exec_module(check)


def good(q, scale=1.0):
    """Scale a joint vector.

    Parameters
    ----------
    q : array-like, shape (n,)
        Joint values (rad or m).
    scale : float, optional
        The factor.

    Returns
    -------
    list of float
        ``scale * q``.
    """
    return [scale * x for x in q]


def undocumented(q):
    return q


def missing_parameter(q, scale=1.0):
    """Scale a joint vector.

    Parameters
    ----------
    q : array-like, shape (n,)
        Joint values.

    Returns
    -------
    list of float
        ``scale * q``.
    """
    return [scale * x for x in q]


def unknown_parameter(q):
    """Echo.

    Parameters
    ----------
    q : object
        Anything.
    p : object
        Not a parameter.

    Returns
    -------
    object
        ``q``.
    """
    return q


def no_returns(q):
    """Echo.

    Parameters
    ----------
    q : object
        Anything.
    """
    return q


def plain_text(q):
    """Echo q (any object) and return it."""
    return q


def returns_nothing(q):
    """Do nothing.

    Parameters
    ----------
    q : object
        Anything.
    """


def misspelt_section(q):
    """Echo.

    Parameters
    ----------
    q : object
        Anything.

    Return
    ------
    object
        ``q``.
    """
    return q


@dataclasses.dataclass(frozen=True)
class Result:
    """A solver's result.

    Parameters
    ----------
    q : numpy.ndarray, shape (n,)
        The joint vector (rad or m).
    success : bool
        Whether it converged.
    """

    q: object
    success: bool

    @property
    def norm(self):
        """The norm of q (rad or m)."""
        return abs(self.q)


@dataclasses.dataclass(frozen=True)
class FieldsAsAttributes:
    """A solver's result (its fields under Attributes, which the book would render
    twice: autodoc documents them too).

    Attributes
    ----------
    q : numpy.ndarray, shape (n,)
        The joint vector.
    success : bool
        Whether it converged.
    """

    q: object
    success: bool


class Base:
    """A contract."""

    def step(self, q):
        """One step.

        Parameters
        ----------
        q : float
            The joint value (rad).

        Returns
        -------
        float
            The next value (rad).
        """
        raise NotImplementedError


class Child(Base):
    """An implementation."""

    def step(self, q):
        return q


class Renamed(Base):
    """An implementation whose argument differs from its documented contract."""

    def step(self, theta):
        return theta


class Orphan:
    """No base documents its method."""

    def step(self, q):
        return q


def codes(value):
    return {code for code, _ in check.problems(value)}


def test_a_numpydoc_docstring_passes():
    assert codes(good) == set()
    assert codes(returns_nothing) == set()


def test_each_missing_part_is_reported():
    assert codes(undocumented) == {"GL08"}
    assert codes(missing_parameter) == {"PR01"}
    assert codes(unknown_parameter) == {"PR02"}
    assert codes(no_returns) == {"RT01"}
    assert codes(plain_text) == {"PR01", "RT01"}
    with warnings.catch_warnings():  # numpydoc warns of the unknown section, too
        warnings.simplefilter("ignore", UserWarning)
        assert "GL06" in codes(misspelt_section)


def test_dataclass_fields_are_parameters_and_properties_need_a_summary_only():
    assert codes(Result) == set()
    assert codes(Result.norm) == set()
    assert codes(FieldsAsAttributes) == {"PR01"}


def test_the_public_objects_include_methods_and_no_private_name():
    names = [name for name, _ in check.objects(importlib.import_module("screwkit"))]
    assert "screwkit.chains.Chain.fk" in names
    assert "screwkit.chains.Chain" in names
    assert "screwkit.ik.dispatch.analytic_ik" in names or any(
        name.endswith(".analytic_ik") for name in names
    )
    assert not any(name.rsplit(".", 1)[1].startswith("_") for name in names)


def test_an_override_inherits_its_base_docstring_checked_against_its_signature():
    assert codes(Child.step) == set()
    assert codes(Renamed.step) == {"PR01", "PR02"}
    assert codes(Orphan.step) == {"GL08"}
