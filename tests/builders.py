"""The robots and mechanisms the tests share, each built on first use and cached.

screwkit's models are immutable, so one instance serves every test; nothing is built
when a test file is imported (tests/test_fixtures.py checks that). conftest.py's
``puma`` and ``kawasaki`` fixtures return these same objects.
"""

import functools

import pytest

import screwkit as sk
from screwkit import parallel


@functools.cache
def puma():
    """The PUMA 560 of the catalogue (Corke's standard DH model, SI units)."""
    return sk.robots.puma560()


@functools.cache
def kawasaki():
    """The Kawasaki CX210L of the catalogue."""
    return sk.robots.kawasaki_cx210l()


@functools.cache
def stanford():
    """The Stanford arm of the catalogue."""
    return sk.robots.stanford()


@functools.cache
def ur5e():
    """The UR5e of the catalogue."""
    return sk.robots.ur5e()


@functools.cache
def planar(*lengths):
    """A planar revolute arm with these link lengths (m), e.g. ``planar(1.0, 1.0)``."""
    return sk.robots.planar(list(lengths))


@functools.cache
def stewart():
    """The Stewart-Gough platform of the catalogue, default geometry."""
    return parallel.stewart_gough()


@functools.cache
def rpr():
    """The planar 3-RPR of the catalogue."""
    return parallel.planar_3rpr()


@functools.cache
def rrr():
    """The planar 3-RRR parallel manipulator of the catalogue."""
    return parallel.planar_3rrr()


@functools.cache
def delta():
    """The Delta robot of the catalogue."""
    return parallel.delta()


@functools.cache
def tripteron():
    """The Tripteron of the catalogue."""
    return parallel.tripteron()


def refusals(cases):
    """A test that each call of ``cases`` raises its error with a message matching its
    pattern: ``cases`` is a list of (call, error type, regular expression)."""

    @pytest.mark.parametrize("call, error, match", cases)
    def test(call, error, match):
        with pytest.raises(error, match=match):
            call()

    return test
