"""The robots and mechanisms the tests share, each built on first use and cached.

screwkit's models are immutable, so one instance serves every test; nothing is built
when a test file is imported (tests/test_fixtures.py checks that). conftest.py's
``puma`` and ``kawasaki`` fixtures return these same objects.
"""

import functools

import numpy as np
import pytest
import sympy as sp

import screwkit as sk


def _catalogue(family, name, what):
    """A cached builder of the catalogue's ``sk.<family>.<name>()`` (``what``, for its
    docstring), looked up and built on first use."""

    @functools.cache
    def build():
        return getattr(getattr(sk, family), name)()

    build.__doc__ = f"{what} of the catalogue (``sk.{family}.{name}()``)."
    return build


puma = _catalogue("robots", "puma560", "The PUMA 560 (Corke's standard DH model, SI)")
kawasaki = _catalogue("robots", "kawasaki_cx210l", "The Kawasaki CX210L")
stanford = _catalogue("robots", "stanford", "The Stanford arm")
ur5e = _catalogue("robots", "ur5e", "The UR5e")
stewart = _catalogue("parallel", "stewart_gough", "The Stewart-Gough platform")
rpr = _catalogue("parallel", "planar_3rpr", "The planar 3-RPR")
rrr = _catalogue("parallel", "planar_3rrr", "The planar 3-RRR")
delta = _catalogue("parallel", "delta", "The Delta robot")
tripteron = _catalogue("parallel", "tripteron", "The Tripteron")


@functools.cache
def planar(*lengths):
    """A planar revolute arm with these link lengths (m), e.g. ``planar(1.0, 1.0)``."""
    return sk.robots.planar(list(lengths))


@functools.cache
def puma_offset_wrist():
    """The PUMA 560 with a4 = 0.1 m: its wrist axes 4, 5, 6 do not meet."""
    return sk.Chain(
        list(puma().links[:3])
        + [sk.Link.revolute(d=0.4318, a=0.1, alpha=sp.pi / 2)]
        + list(puma().links[4:])
    )


def refusals(cases):
    """A test that each call of ``cases`` raises its error with a message matching its
    pattern: ``cases`` is a list of (call, error type, regular expression)."""

    @pytest.mark.parametrize("call, error, match", cases)
    def test(call, error, match):
        with pytest.raises(error, match=match):
            call()

    return test


def _unit(v):
    return v / np.linalg.norm(v)


def arm_from_axes(w, p, rng):
    """A 6R chain from unit axes w (6, 3) through points p (6, 3) and a random home."""
    S = np.hstack([w, np.cross(p, w)])
    M = np.eye(4)
    axis, angle = _unit(rng.normal(size=3)), rng.uniform(-np.pi, np.pi)
    K = np.array(
        [[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]]
    )
    M[:3, :3] = np.eye(3) + np.sin(angle) * K + (1 - np.cos(angle)) * K @ K
    M[:3, 3] = rng.normal(size=3) * 0.3
    return sk.Chain.from_screws(S, M)


def random_arm(kind, rng, antiparallel=True):
    """A random 6R arm of a structure the decomposed IK solves: 'wrist' (axes 4, 5, 6
    meet), 'shoulder' (1, 2, 3 meet), 'parallel 234' or 'parallel 345' (three parallel
    axes; with ``antiparallel`` the middle of 2, 3, 4 points the other way); any other
    kind, a general 6R. Axes, points and home drawn from ``rng``."""
    w = np.array([_unit(rng.normal(size=3)) for _ in range(6)])
    p = rng.normal(size=(6, 3)) * 0.5
    if kind == "wrist":
        p[3:] = rng.normal(size=3)
    elif kind == "shoulder":
        p[:3] = rng.normal(size=3)
    elif kind == "parallel 234":
        w[1:4] = w[1] * (np.array([[1], [-1], [1]]) if antiparallel else 1)
    elif kind == "parallel 345":
        w[2:5] = w[2]
    return arm_from_axes(w, p, rng)
