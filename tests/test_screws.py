"""Screws, twists, wrenches and screw systems: exact results from hand derivations."""

import pytest
import sympy as sp
from hypothesis import given, settings
from hypothesis import strategies as st

import screwkit as sk
from screwkit.screws import Screw, Twist, Wrench
from screwkit.systems import ScrewSystem

a, h = sp.symbols("a h", real=True)


def test_from_axis_is_s_and_r_cross_s_plus_h_s():
    t = Twist.from_axis([0, 0, 1], [a, 0, 0], h)
    assert t.vector == sp.Matrix([0, 0, 1, 0, -a, h])
    assert Twist.from_axis([0, 2, 0], [a, 1, 5], sp.oo).vector == sp.Matrix(
        [0, 0, 0, 0, 2, 0]
    )


def test_pitch_point_and_direction_are_recovered_exactly():
    t = Twist.from_axis([0, 0, 1], [a, 0, 0], h)
    assert t.pitch == h
    assert t.point == sp.Matrix([a, 0, 0])
    assert t.direction == sp.Matrix([0, 0, 1])
    prismatic = Twist.from_axis([1, 0, 0], [0, 0, 0], sp.oo)
    assert prismatic.pitch == sp.oo and prismatic.point is None
    assert prismatic.direction == sp.Matrix([1, 0, 0])


def test_reciprocal_product_is_the_power_of_a_wrench_on_a_twist():
    # A rotation about z through the origin at unit rate against:
    spin = Twist.from_axis([0, 0, 1], [0, 0, 0], 0)
    assert (
        spin @ Wrench.from_axis([0, 0, 1], [0, 0, 0], sp.oo) == 1
    )  # a unit couple about z
    assert (
        spin @ Wrench.from_axis([0, 0, 1], [5, 7, 0], 0) == 0
    )  # a force parallel to the axis
    assert (
        spin @ Wrench.from_axis([0, 1, 0], [a, 0, 0], 0) == a
    )  # a force with lever arm a
    slide = Twist.from_axis([1, 0, 0], [0, 0, 0], sp.oo)
    assert (
        slide @ Wrench.from_axis([1, 0, 0], [0, a, 0], 0) == 1
    )  # a force along the slide
    assert (
        slide @ Wrench.from_axis([1, 0, 0], [0, 0, 0], sp.oo) == 0
    )  # a couple does no work


def test_two_screws_of_pitch_h_on_one_axis_have_product_2h():
    s = Screw.from_axis([0, 0, 1], [a, 1, 0], h)
    assert sp.simplify(s @ s - 2 * h) == 0


def test_algebra_keeps_the_kind():
    t1, t2 = (
        Twist.from_axis([0, 0, 1], [0, 0, 0], 0),
        Twist.from_axis([1, 0, 0], [0, 0, 0], sp.oo),
    )
    assert isinstance(t1 + t2, Twist) and (t1 + t2).vector == sp.Matrix(
        [0, 0, 1, 1, 0, 0]
    )
    assert (2 * t1).vector == 2 * t1.vector and (t1 * a).vector == a * t1.vector
    assert (-t1).vector == -t1.vector and (t1 - t1).vector == sp.zeros(6, 1)


def test_mixing_twists_and_wrenches_is_refused():
    t, w = (
        Twist.from_axis([0, 0, 1], [0, 0, 0], 0),
        Wrench.from_axis([0, 0, 1], [0, 0, 0], 0),
    )
    with pytest.raises(TypeError, match="cannot add a twist and a wrench"):
        t + w
    with pytest.raises(TypeError, match="cannot subtract a wrench and a twist"):
        w - t
    with pytest.raises(TypeError, match="one kind of screw"):
        ScrewSystem([t, w])


@pytest.mark.parametrize(
    "args, error, message",
    [
        (([0, 0, 0], [0, 0, 0], 0), ValueError, "s must be a non-zero direction"),
        (([0, 0], [0, 0, 0], 0), ValueError, r"s must have shape \(3, 1\)"),
        (([0, 0, 1], [0, 0], 0), ValueError, r"r must have shape \(3, 1\)"),
        (([0, 0, 1], [0, 0, 0], "x"), TypeError, "h must be a pitch"),
        (([0, 0, 1], [0, 0, 0], None), TypeError, "h must be a pitch"),
        (([0, 0, 1], [0, 0, 0], sp.nan), ValueError, "h must be finite"),
        ((["s", 0, 1], [0, 0, 0], 0), TypeError, "s must hold numbers"),
    ],
)
def test_bad_screw_input_is_named(args, error, message):
    with pytest.raises(error, match=message):
        Twist.from_axis(*args)


def test_screw_system_rank_basis_and_reciprocal_by_hand():
    # Three parallel revolute axes along z: Rz and the translations in x and y.
    system = ScrewSystem(
        [
            ([0, 0, 1], [0, 0, 0], 0),
            ([0, 0, 1], [a, 0, 0], 0),
            ([0, 0, 1], [0, a, 0], 0),
        ]
    )
    assert system.rank == 3
    assert [list(t.vector) for t in system.basis()] == [
        [0, 0, 1, 0, 0, 0],
        [0, 0, 0, 1, 0, 0],
        [0, 0, 0, 0, 1, 0],
    ]
    wrenches = system.reciprocal()
    assert wrenches.kind is Wrench and wrenches.rank == 3
    # Its constraints: a force along z and the couples about x and y.
    assert [list(w.vector) for w in wrenches.basis()] == [
        [0, 0, 1, 0, 0, 0],
        [0, 0, 0, 1, 0, 0],
        [0, 0, 0, 0, 1, 0],
    ]


def test_reciprocal_of_reciprocal_is_the_same_span_and_intersection():
    planar = ScrewSystem(
        [
            ([0, 0, 1], [0, 0, 0], 0),
            ([1, 0, 0], [0, 0, 0], sp.oo),
            ([0, 1, 0], [0, 0, 0], sp.oo),
        ]
    )
    back = planar.reciprocal().reciprocal()
    assert back.kind is Twist and back.rank == 3
    assert all(planar.contains(t) for t in back.basis())
    x_slides = ScrewSystem(
        [([1, 0, 0], [0, 0, 0], sp.oo), ([0, 0, 1], [0, 0, 0], sp.oo)]
    )
    common = planar.intersection(x_slides)
    assert [list(t.vector) for t in common.basis()] == [[0, 0, 0, 1, 0, 0]]


small = st.integers(-3, 3)
vectors = st.tuples(small, small, small).filter(lambda v: any(v))


@settings(max_examples=40, deadline=None)
@given(
    st.lists(
        st.tuples(
            vectors, st.tuples(small, small, small), st.sampled_from([0, 1, sp.oo])
        ),
        min_size=1,
        max_size=5,
    )
)
def test_every_reciprocal_wrench_annihilates_every_twist(joints):
    system = ScrewSystem([(list(s), list(r), p) for s, r, p in joints])
    wrenches = system.reciprocal()
    assert system.rank + wrenches.rank == 6
    for t in system.screws:
        for w in wrenches.basis():
            assert sp.simplify(t @ w) == 0


def test_symbolic_reciprocal_annihilates_symbolic_twists():
    t1, t2 = sp.symbols("theta_1 theta_2")
    limb = sk.robots.pm_3prrr()[0]
    system = ScrewSystem(limb)
    for w in system.reciprocal().basis():
        for t in system.screws:
            assert sp.simplify(t @ w) == 0


def test_floats_differing_by_round_off_are_one_direction_not_two():
    nearly = ScrewSystem([([0, 0, 1], [0, 0, 0], 0), ([1e-16, 0, 1], [0, 0, 0], 0)])
    assert nearly.numeric and nearly.rank == 1
    assert (
        ScrewSystem(
            [([0, 0, 1], [0, 0, 0], 0), ([1e-6, 0, 1], [0, 0, 0], 0)], tol=1e-12
        ).rank
        == 2
    )
    # the same system exactly: two different directions through one point
    assert (
        ScrewSystem(
            [([0, 0, 1], [0, 0, 0], 0), ([sp.Rational(1, 10**16), 0, 1], [0, 0, 0], 0)]
        ).rank
        == 2
    )


def test_a_float_system_has_the_canonical_basis_of_its_exact_twin():
    # The planar system of the hand derivation above, with a = 0.6 m given as a float.
    floats = ScrewSystem(
        [
            ([0, 0, 1], [0, 0, 0], 0),
            ([0, 0, 1], [0.6, 0, 0], 0),
            ([0, 0, 1], [0, 0.6, 0], 0),
        ]
    )
    assert floats.rank == 3
    assert [list(t.vector) for t in floats.basis()] == [
        [0, 0, 1, 0, 0, 0],
        [0, 0, 0, 1, 0, 0],
        [0, 0, 0, 0, 1, 0],
    ]
    assert [list(w.vector) for w in floats.reciprocal().basis()] == [
        [0, 0, 1, 0, 0, 0],
        [0, 0, 0, 1, 0, 0],
        [0, 0, 0, 0, 1, 0],
    ]


def test_systems_typeset_as_tables_and_print_as_text():
    system = ScrewSystem([([0, 0, 1], [0, 0, 0], 0), ([0, 0, 1], [a, 0, 0], 0)])
    assert system.summary().splitlines() == [
        "twist 2-system",
        "  [0, 0, 1, 0, 0, 0]",
        "  [0, 0, 0, 0, 1, 0]",
    ]
    html = system._repr_html_()
    assert ">twist 2-system</caption>" in html and html.count("<tr>") == 6
    assert repr(system.reciprocal()) == "ScrewSystem(4 wrenches, rank 4)"
    assert system._repr_latex_().startswith(
        "$\\text{twist 2-system: }\\left[\\begin{matrix}"
    )


def test_square_roots_keep_their_products_exact():
    # (sqrt(b), sqrt(ab)) = sqrt(b) (1, sqrt(a)): rank 1. The roots' sample values must
    # satisfy sqrt(ab) = sqrt(a) sqrt(b); chosen independently, (2, 7), (3, 7) and (2,
    # 11) came out rank 2.
    for a, b in [(2, 3), (2, 7), (3, 7), (2, 11), (5, 7)]:
        first = Twist(sp.Matrix([1, sp.sqrt(a), 0, 0, 0, 0]))
        second = Twist(sp.Matrix([sp.sqrt(b), sp.sqrt(a * b), 0, 0, 0, 0]))
        assert ScrewSystem([first, second]).rank == 1
        assert ScrewSystem([first, second]).reciprocal().rank == 5
    # nested roots are algebraic numbers too (an exact rank must see them):
    # sqrt(10 - 2 sqrt 5) = sqrt 2 sqrt(5 - sqrt 5)
    nested = [
        sp.Matrix([sp.sqrt(5 - sp.sqrt(5)), 1, 0, 0, 0, 0]),
        sp.Matrix([sp.sqrt(10 - 2 * sp.sqrt(5)), sp.sqrt(2), 0, 0, 0, 0]),
    ]
    assert ScrewSystem(nested).rank == 1
    with pytest.raises(TypeError, match="algebraic numbers"):
        _ = ScrewSystem([sp.Matrix([sp.sqrt(sp.pi), 1, 0, 0, 0, 0])]).rank
