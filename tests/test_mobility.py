"""Mobility of parallel manipulators: the paper's four mechanisms and classic ones."""

import random

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit.mobility_analysis import grubler_kutzbach, mobility
from screwkit.transforms import rot_axis

# the paper's mobility dictionaries (its notebook's outputs, and Table/eqs. 4-6)
PAPER = {
    "pm_3prrr": {"Number": 3, "Type": "3T", "Direction": ["Tx", "Ty", "Tz"]},
    "pm_3prpar": {"Number": 3, "Type": "3T", "Direction": ["Tx", "Ty", "Tz"]},
    "pm_4prru": {"Number": 4, "Type": "3T1R", "Direction": ["Tx", "Ty", "Tz", "Rz"]},
    "pm_6ups": {
        "Number": 6,
        "Type": "3T3R",
        "Direction": ["Tx", "Ty", "Tz", "Rx", "Ry", "Rz"],
    },
}


@pytest.mark.parametrize("name", sorted(PAPER))
def test_the_paper_mechanisms_have_the_paper_mobility(name):
    assert mobility(getattr(sk.robots, name)()).as_dict() == PAPER[name]


def test_3prpar_limb_has_seven_joint_screws_but_rank_five():
    m = mobility(sk.robots.pm_3prpar())
    assert m.joints_per_limb == [7, 7, 7] and m.limb_twist_ranks == [5, 5, 5]
    assert m.idle_mobility == 6  # two idle freedoms in each parallelogram limb


def test_3prrr_systems_as_in_the_paper():
    m = mobility(sk.robots.pm_3prrr())
    assert [s.rank for s in m.limb_wrench_systems] == [
        2,
        2,
        2,
    ]  # each LWS is a couple 2-system
    assert m.platform_wrench_system.rank == 3 and m.redundant_constraints == 3
    couples = [list(w.vector) for w in m.platform_wrench_system.basis()]
    assert couples == [[0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 1]]


def test_limb_wrenches_are_reciprocal_to_limb_twists():
    m = mobility(sk.robots.pm_4prru())
    for twists, wrenches in zip(m.limb_twist_systems, m.limb_wrench_systems):
        for t in twists.screws:
            for w in wrenches.basis():
                assert sp.simplify(t @ w) == 0


@pytest.mark.parametrize(
    "name, expected",
    [
        ("planar_3rrr", ("2T1R", ["Tx", "Ty", "Rz"])),
        ("spherical_3rrr", ("3R", ["Rx", "Ry", "Rz"])),
    ],
)
def test_classic_mechanisms(name, expected):
    m = mobility(getattr(sk.robots, name)())
    assert (m.type, m.directions) == expected


def test_grubler_kutzbach_reproduces_the_paper_counts():
    for name, row in sk.robots.PAPER_GRUBLER_KUTZBACH.items():
        assert (
            grubler_kutzbach(row["links"], row["joints"], row["freedoms"])
            == row["mobility"]
        ), name
    # Counted as serial limbs of one-freedom screws, with the redundant constraints and
    # the idle freedoms that screw theory finds, the corrected count gives the true
    # mobility.
    for name in ("pm_3prrr", "pm_4prru", "pm_3prpar"):
        m = mobility(getattr(sk.robots, name)())
        assert (
            m.grubler_kutzbach + m.redundant_constraints - m.idle_mobility == m.number
        ), name


def test_mobility_does_not_depend_on_the_fixed_frame():
    # A rational rotation (3-4-5 triangles) and a shift: exact, like the symbolic model.
    R = sp.Matrix(
        [
            [sp.Rational(3, 5), -sp.Rational(4, 5), 0],
            [sp.Rational(4, 5), sp.Rational(3, 5), 0],
            [0, 0, 1],
        ]
    )
    R = R * sp.Matrix(
        [
            [1, 0, 0],
            [0, sp.Rational(5, 13), -sp.Rational(12, 13)],
            [0, sp.Rational(12, 13), sp.Rational(5, 13)],
        ]
    )
    p = sp.Matrix([1, -2, 3])
    limbs = sk.robots.pm_4prru()
    moved = [
        [(R * sp.Matrix(s), R * sp.Matrix(r) + p, h) for s, r, h in limb]
        for limb in limbs
    ]
    before, after = mobility(limbs), mobility(moved)
    assert (after.number, after.type) == (before.number, before.type)


@pytest.mark.parametrize("name", ["pm_3prrr", "pm_3prpar", "pm_4prru", "pm_6ups"])
def test_numeric_configurations_agree_with_the_symbolic_answer(name):
    limbs = getattr(sk.robots, name)()
    symbols = sorted(
        set().union(
            *(
                sp.Matrix(r).free_symbols | sp.Matrix(s).free_symbols
                for limb in limbs
                for s, r, _ in limb
            )
        ),
        key=str,
    )
    rng = random.Random(3)
    for _ in range(2):
        values = {
            s: sp.Rational(rng.randint(1, 90), rng.randint(7, 19)) for s in symbols
        }
        numeric = [
            [
                (sp.Matrix(s).subs(values), sp.Matrix(r).subs(values), h)
                for s, r, h in limb
            ]
            for limb in limbs
        ]
        assert mobility(numeric).as_dict() == PAPER[name]
        assert mobility(limbs, at=values).notes[0].startswith("general configuration")


def test_a_singular_configuration_differs_from_the_generic_one():
    # Tripteron limb 1 folded (theta_12 = theta_13): still 3T, the limbs stay
    # independent. A planar 3-RRR with every limb stretched straight loses a motion: the
    # answer says so.
    limbs = sk.robots.planar_3rrr()
    theta = {sp.Symbol(f"theta_{i}{j}"): 0 for i in (1, 2, 3) for j in (1, 2)}
    stretched = [
        [(s, sp.Matrix(r).subs(theta), h) for s, r, h in limb] for limb in limbs
    ]
    assert mobility(stretched).number < mobility(limbs).number


@pytest.mark.parametrize(
    "limbs, error, message",
    [
        ([], ValueError, "limbs must be a non-empty list"),
        ([[]], ValueError, "limb 0 must be a non-empty list"),
        (
            [[([0, 0, 1], [0, 0, 0])]],
            TypeError,
            r"limb 0, joint 0 must be an \(s, r, h\) triple",
        ),
        (
            [[([0, 0, 0], [0, 0, 0], 0)]],
            ValueError,
            "limb 0, joint 0: s must be a non-zero direction",
        ),
        (
            [[([0, 0, 1], [0, 0, 0], "p")]],
            TypeError,
            "limb 0, joint 0: h must be a pitch",
        ),
        ([[sk.Wrench.from_axis([0, 0, 1], [0, 0, 0], 0)]], TypeError, "is a wrench"),
    ],
)
def test_bad_limbs_are_named(limbs, error, message):
    with pytest.raises(error, match=message):
        mobility(limbs)


def test_3prpar_limb_wrenches_equal_the_papers():
    # The paper's notebook prints each LWS as (0, 0, 0, m_x, m_y, 1) with tan(theta_i2)
    # terms.
    t = [sp.Symbol(f"theta_{i}2") for i in (1, 2, 3)]
    paper = [
        [0, 0, 0, 0, -sp.tan(t[0]), 1],
        [0, 0, 0, sp.sqrt(3) * sp.tan(t[1]) / 2, sp.tan(t[1]) / 2, 1],
        [0, 0, 0, -sp.sqrt(3) * sp.tan(t[2]) / 2, sp.tan(t[2]) / 2, 1],
    ]
    m = mobility(sk.robots.pm_3prpar())
    for system, expected in zip(m.limb_wrench_systems, paper):
        (wrench,) = system.basis()
        assert sp.simplify(wrench.vector - sp.Matrix(expected)) == sp.zeros(6, 1)


def test_a_configuration_given_with_at_says_whether_it_is_singular():
    limbs = sk.robots.planar_3rrr()
    stretched = {sp.Symbol(f"theta_{i}{j}"): 0 for i in (1, 2, 3) for j in (1, 2)}
    special = mobility(limbs, at=stretched)
    assert special.number == 1 and special.notes[0].startswith(
        "singular configuration: the platform loses"
    )
    assert "3 (2T1R: Tx, Ty, Rz) in the general configuration" in special.notes[0]
    ordinary = mobility(
        limbs, at={sp.Symbol("theta_11"): 0.3, sp.Symbol("theta_22"): sp.pi / 7}
    )
    assert ordinary.number == 3 and ordinary.notes[0].startswith(
        "general configuration"
    )
    with pytest.raises(TypeError, match="at must be a dict"):
        mobility(limbs, at={"theta_11": 0})


def test_delta_type_3ruu_is_translational_each_limb_constraining_the_couple_u_x_v():
    limbs = sk.robots.pm_3ruu()
    m = mobility(limbs)
    assert (m.type, m.directions) == ("3T", ["Tx", "Ty", "Tz"])
    # a couple (0; c) is reciprocal to a revolute (s; r x s) iff c . s = 0: c is along u
    # x v
    theta = sp.Symbol("theta_12")
    u, v = sp.Matrix([0, 1, 0]), sp.Matrix([sp.sin(theta), 0, sp.cos(theta)])
    couple = list(m.limb_wrench_systems[0].basis()[0].vector)
    assert couple[:3] == [0, 0, 0]
    assert sp.simplify(sp.Matrix(couple[3:]).cross(u.cross(v))) == sp.zeros(3, 1)
    # with every v radial (theta_i2 = 90 deg) the three couples are parallel: a
    # constraint singularity
    radial = mobility(
        limbs, at={sp.Symbol(f"theta_{i}2"): sp.pi / 2 for i in (1, 2, 3)}
    )
    assert radial.number == 5 and "gains freedoms" in radial.notes[0]


def _tilted_planar_3rrr_from_floats():
    """A planar 3-RRR (all axes along the plane's normal) in a plane tilted with NumPy
    floats."""
    c, s = np.cos(0.4), np.sin(0.4)
    tilt = np.array([[1, 0, 0], [0, c, -s], [0, s, c]]) @ np.array(
        [[c, 0, s], [0, 1, 0], [-s, 0, c]]
    )
    values = {
        sp.Symbol(k): v for k, v in sk.robots.DRAWING_VALUES["planar_3rrr"].items()
    }
    values.update(
        {sp.Symbol("theta_21"): 1.7, sp.Symbol("theta_32"): 2.9}
    )  # not symmetric
    limbs = []
    for limb in sk.robots.planar_3rrr():
        limbs.append(
            [
                (
                    tilt @ np.array(sp.Matrix(s_).subs(values), dtype=float).ravel(),
                    tilt @ np.array(sp.Matrix(r).subs(values), dtype=float).ravel(),
                    h,
                )
                for s_, r, h in limb
            ]
        )
    return limbs, tilt


def test_a_tilted_planar_3rrr_built_from_floats_has_planar_motion():
    # Turning the fixed frame does not change the motions: in the tilted plane the
    # platform translates two ways and turns about the plane's normal (2T1R), and each
    # limb allows it.
    limbs, tilt = _tilted_planar_3rrr_from_floats()
    m = mobility(limbs)
    assert (m.number, m.type) == (3, "2T1R")
    normal = tilt @ np.array([0.0, 0.0, 1.0])
    rotation = [
        t for t in m.platform_twist_system.basis() if any(e != 0 for e in t.primary)
    ]
    (w,) = [np.array([float(e) for e in t.primary]) for t in rotation]
    np.testing.assert_allclose(
        np.cross(w, normal), 0, atol=1e-9
    )  # it turns about the normal
    assert m.limb_twist_ranks == [3, 3, 3] and m.platform_wrench_system.rank == 3


def test_float_tolerance_is_the_callers_to_choose():
    limbs, _ = _tilted_planar_3rrr_from_floats()
    # With a tolerance below round-off, the three limbs' axes (equal only to ~1e-16)
    # count as different directions and the platform locks: the tolerance is what
    # decides.
    assert mobility(limbs, tol=1e-300).number < 3
    with pytest.raises(ValueError, match="tol must be a positive number below 1"):
        mobility(limbs, tol=0.0)


def test_floats_and_symbols_together_are_refused_with_the_exact_way_to_write_them():
    with pytest.raises(ValueError, match=r"sympy.Rational\('0.3'\)"):
        mobility([[((0, 0, 1), (0.3, sp.Symbol("a"), 0), 0)]])


def test_exact_coordinates_with_pi_and_square_roots():
    # Three identical limbs P(x) P(y) H(z, pitch h): each allows Tx, Ty and the screw
    # motion (e_z; h e_z); so does the platform (2T1R), and the screw's twist reduced to
    # end in 1 at v_z is (0, 0, 1/h, 0, 0, 1) = (0, 0, 200 pi, 0, 0, 1).
    h = 1 / (200 * sp.pi)
    limb = (
        sk.limbs.prismatic([1, 0, 0])
        + sk.limbs.prismatic([0, 1, 0])
        + sk.limbs.helical([0, 0, 1], [0, 0, 0], h)
    )
    m = mobility([limb, limb, limb])
    assert (m.number, m.type) == (3, "2T1R")
    assert [list(t.vector) for t in m.platform_twist_system.basis()] == [
        [0, 0, 0, 1, 0, 0],
        [0, 0, 0, 0, 1, 0],
        [0, 0, 200 * sp.pi, 0, 0, 1],
    ]
    # sqrt(2)/2 directions: a revolute about the diagonal of the x-y plane, three times
    diagonal = sk.limbs.revolute([sp.sqrt(2) / 2, sp.sqrt(2) / 2, 0], [0, 0, sp.pi])
    assert mobility([diagonal, diagonal]).type == "1R"


def test_typeset_results_keep_the_plain_text_for_terminals():
    m = mobility(sk.robots.pm_3prrr())
    assert m.summary().splitlines()[-1] == "Mobility: 3 (3T) ['Tx', 'Ty', 'Tz']"
    assert repr(m) == "Mobility(3, '3T', ['Tx', 'Ty', 'Tz'])"
    html = m._repr_html_()
    assert (
        html.count('<table class="screwkit-system"') == 3 + 3 + 2
        and "Mobility 3 (3T)" in html
    )
    # a step's tables wrap onto the next line on a phone, not one row of an outer table
    assert html.count("flex-wrap:wrap") == 4 and "<tr><td" not in html
    latex = m._repr_latex_()
    assert latex.startswith("$\\begin{array}") and latex.count("matrix}") == 2 * 8


def test_builders_write_the_limbs_their_rotation_matrices_give():
    """The builders write entries directly; the reference turns the paper's limbs with
    SymPy's matrix products (rotx, roty, rotz) and expands, as the paper's code does."""
    from screwkit.limbs import parallelogram, prismatic, revolute
    from screwkit.transforms import rotx, roty, rotz

    X, Y, Z = sp.Matrix([1, 0, 0]), sp.Matrix([0, 1, 0]), sp.Matrix([0, 0, 1])

    def turned(limb, R):
        return [((R * s).expand(), (R * r).expand(), h) for s, r, h in limb]

    L, b = sp.symbols("L b")
    expected = []
    for i in range(3):
        d, t2, t3 = (
            sp.Symbol(f"d_{i + 1}"),
            sp.Symbol(f"theta_{i + 1}2"),
            sp.Symbol(f"theta_{i + 1}3"),
        )
        A0, A1, A2 = (sp.Matrix([d + shift, 0, 0]) for shift in (0, -b / 2, b / 2))
        side = rotx(t2) * roty(t3) * sp.Matrix([L, 0, 0])
        limb = (
            prismatic(X, A0)
            + revolute(X, A0)
            + parallelogram(rotx(t2) * Y, A1, A2, A1 + side, A2 + side)
            + revolute(X, A0 + side)
        )
        expected.append(turned(limb, rotz(2 * sp.pi * i / 3)))
    assert _as_lists(sk.robots.pm_3prpar()) == _as_lists(expected)

    a, b, Ly, Lz = sp.symbols("a b L_y L_z")
    expected = []
    bases = [
        sp.Matrix([sp.Symbol("d_1"), Ly, 0]),
        sp.Matrix([0, sp.Symbol("d_2"), Lz]),
        sp.Matrix([0, 0, sp.Symbol("d_3")]),
    ]
    for i, (axis, rotation, offset) in enumerate(
        zip([X, Y, Z], [rotx, roty, rotz], [Y, Z, X])
    ):
        t2, t3 = sp.Symbol(f"theta_{i + 1}2"), sp.Symbol(f"theta_{i + 1}3")
        A = bases[i]
        B = A + rotation(t2) * (a * offset)
        C = B + rotation(t3) * (b * offset)
        expected.append(
            prismatic(axis, A)
            + revolute(axis, A)
            + revolute(axis, B)
            + revolute(axis, C)
        )
    assert _as_lists(sk.robots.pm_3prrr()) == _as_lists(expected)


def _as_lists(limbs):
    return [
        [(list(s.expand()), list(r.expand()), h) for s, r, h in limb] for limb in limbs
    ]


def test_rotate_limb_is_the_matrix_product():
    from screwkit.limbs import rotate_limb
    from screwkit.transforms import rotz

    t, c = sp.symbols("t c")
    limb = [
        (sp.Matrix([sp.cos(t), sp.sin(t), 1]), sp.Matrix([c, c / 3, sp.sqrt(2)]), 0),
        (sp.Matrix([0, 0, 1]), sp.Matrix([1, 2, 3]), sp.oo),
    ]
    for R in (rotz(2 * sp.pi / 3), rot_axis([1, 1, 1], sp.pi / 3)):
        R = sp.Matrix(R).applyfunc(sp.nsimplify)
        got = rotate_limb(limb, R)
        for (s, r, h), (s2, r2, h2) in zip(limb, got):
            assert (R * s - s2).expand() == sp.zeros(3, 1) and (
                R * r - r2
            ).expand() == sp.zeros(3, 1)
            assert h2 == h


def test_null_space_of_rows_with_fractions_and_denominators():
    """Rows with rational coefficients and rational-function entries: the exact null
    space is checked by M N^T = 0 and by its canonical form (each basis row ends in its
    own 1)."""
    from screwkit import _exact

    a, t = sp.symbols("a t")
    rows = [
        [1, a / 3, 0, sp.sin(t) / 2, 0, 1 / (a + 1)],
        [0, 1, sp.Rational(2, 7), 0, a * sp.cos(t), 0],
        [sp.Rational(1, 5), 0, 1, a / (1 + a**2), 0, 0],
    ]
    field = _exact.Field([e for row in rows for e in row])
    N = _exact.null_space(field, field.matrix(rows))
    basis = [[field.to_sympy(e) for e in row] for row in N.to_list()]
    assert len(basis) == 3
    for x in basis:
        for row in rows:
            assert sp.simplify(sum(sp.sympify(m) * e for m, e in zip(row, x))) == 0
    last = [max(k for k, e in enumerate(x) if e != 0) for x in basis]
    assert [basis[i][k] for i, k in enumerate(last)] == [1, 1, 1] and len(
        set(last)
    ) == 3
