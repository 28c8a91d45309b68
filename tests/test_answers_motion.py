"""The answer keys of the motion-in-time chapter, each recomputed independently: a
maximum found on a fine grid of differences of s(t), a duration found by bisection on a
simulated trapezoid, an acceleration by second differences of forward kinematics.

Registered with the engine's registry (tests/test_exercises.py), as
tests/test_answers_part2.py does, so that every key has a reference."""

import tomllib
from importlib import resources

import numpy as np
import pytest

import screwkit as sk

try:  # the engine's registry of references, when its tests are collected with these
    from test_exercises import REFERENCES as ENGINE_REFERENCES
except ImportError:  # pragma: no cover - run alone from elsewhere
    ENGINE_REFERENCES = {}

REFERENCES = {}
CHAPTER = "motion_in_time"


def reference(number):
    def register(function):
        REFERENCES[CHAPTER, number] = function
        ENGINE_REFERENCES[CHAPTER, number] = function
        return function

    return register


@reference(3)
def _():
    # s(t) of the quintic written here, differentiated numerically on a fine grid
    T = 2.0
    t = np.linspace(0, T, 200001)
    tau = t / T
    s = 10 * tau**3 - 15 * tau**4 + 6 * tau**5
    return np.gradient(s, t).max()


@reference(4)
def _():
    # the shortest time to cover s = 1 from rest to rest with |s''| <= 2, s' <= 0.5:
    # simulate accelerate / cruise / brake by small steps (no closed form used)
    v, a, dt = 0.5, 2.0, 1e-5
    s, speed, t = 0.0, 0.0, 0.0
    while s < 1.0:
        braking = speed * speed / (2 * a) >= 1.0 - s
        speed = max(speed - a * dt, 0.0) if braking else min(speed + a * dt, v)
        s += speed * dt
        t += dt
        if braking and speed == 0.0:
            break
    return t


@reference(5)
def _():
    arm = sk.robots.planar([1.0, 0.5])
    h = 1e-4
    p = [arm.fk([3.0 * t, 0.0])[:2, 3] for t in (-h, 0.0, h)]
    return np.linalg.norm((p[0] - 2 * p[1] + p[2]) / h**2)


def keys():
    path = resources.files("screwkit") / "answers" / f"{CHAPTER}.toml"
    return tomllib.loads(path.read_text(encoding="utf-8"))["exercise"]


def test_every_key_has_a_reference_here():
    assert {int(n) for n in keys()} == {n for _, n in REFERENCES}


@pytest.mark.parametrize("number", sorted(n for _, n in REFERENCES))
def test_key_agrees_with_its_reference(number):
    expected = float(REFERENCES[CHAPTER, number]())
    entry = keys()[str(number)]
    assert sk.exercises.check(CHAPTER, number, f"{expected:.6f}").correct
    wrong = expected + 10 * entry["tolerance"] + 1
    assert not sk.exercises.check(CHAPTER, number, repr(wrong)).correct


def test_the_chapters_problem_set_is_complete():
    """The course's rule for a problem set (tests/test_course_content.py): eight or
    more exercises numbered in order, one hidden solution each, two by hand, two to
    implement, two answer boxes with keys."""
    from test_course_content import test_problem_set_is_complete

    test_problem_set_is_complete(CHAPTER)
