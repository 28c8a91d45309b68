"""screwkit.links: DH rows and joint screws, checked; each transform against the DH
formula written out here."""

import numpy as np
import pytest
import sympy as sp
from references import dh_modified, dh_standard

from screwkit import links
from screwkit.links import Convention, Joint, Link


@pytest.mark.parametrize(
    "convention, formula",
    [(Convention.STANDARD, dh_standard), (Convention.MODIFIED, dh_modified)],
)
def test_link_transform_against_the_dh_formula(convention, formula):
    revolute = Link.revolute(d=0.2, a=0.5, alpha=0.3, offset=0.1)
    prismatic = Link.prismatic(theta=0.4, a=0.5, alpha=-1.2, offset=0.05)
    q = 0.7
    got = np.array(revolute.transform(q, convention).evalf(), dtype=float)
    assert np.allclose(got, formula(q + 0.1, 0.2, 0.5, 0.3))
    got = np.array(prismatic.transform(q, convention).evalf(), dtype=float)
    assert np.allclose(got, formula(0.4, q + 0.05, 0.5, -1.2))


def test_dh_factors_multiply_to_the_link_transform():
    """pre exp([X] t) post is the same matrix as the exact transform (floats, any
    angle)."""
    link = Link.revolute(d=0.3, a=0.2, alpha=0.9)
    for convention in Convention:
        pre, twist, post = links.dh_factors(link, 1, convention)
        t = 1.1
        rotation = np.array(
            [
                [np.cos(t), -np.sin(t), 0, 0],
                [np.sin(t), np.cos(t), 0, 0],
                [0, 0, 1, 0],
                [0, 0, 0, 1],
            ]
        )
        assert np.array_equal(twist, [0, 0, 1, 0, 0, 0])
        expected = np.array(link.transform(t, convention).evalf(), dtype=float)
        assert np.allclose(pre @ rotation @ post, expected)


def test_quarter_turns_are_exact():
    link = Link.revolute(alpha=np.pi / 2)
    assert (
        link.transform(sp.Symbol("q"), Convention.STANDARD)[1, 1] == 0
    )  # cos(pi/2) exactly
    assert link._numbers(1)[1] == (0.0, 1.0)


def test_decimal_reads_floats_as_printed():
    assert links.decimal(0.4318) == sp.Rational(2159, 5000)
    assert links.decimal(sp.Symbol("x") + 0.5) == sp.Symbol("x") + sp.Rational(1, 2)
    assert links.decimal(sp.pi) == sp.pi


def test_check_screws_normalises_and_keeps_the_exact_forms():
    numbers, exact = links.check_screws([[0, 0, 1, 0, -1, 0], [0, 0, 0, 0, 0, 1]])
    assert np.array_equal(numbers, [[0, 0, 1, 0, -1, 0], [0, 0, 0, 0, 0, 1]])
    assert exact[0] == sp.Matrix([0, 0, 1, 0, -1, 0])


@pytest.mark.parametrize(
    "axes, error, pattern",
    [
        ([[0, 0, 2, 0, 0, 0]], ValueError, r"axes\[0\] must be a unit screw axis"),
        ([[0, 0, 0, 0, 0, 0]], ValueError, "the zero twist"),
        ([[0, 0, 0, 0, 0, 3]], ValueError, r"axes\[0\] is prismatic .* \|v\| = 1"),
        ([[0, 0, 1]], ValueError, r"axes\[0\] must be a 6-vector"),
        ([], ValueError, "at least one joint screw"),
        ("z", TypeError, "axes must be a list"),
    ],
)
def test_check_screws_refuses(axes, error, pattern):
    with pytest.raises(error, match=pattern):
        links.check_screws(axes)


def test_joint_kinds_from_screws():
    assert links.joint_kind(np.array([0, 0, 1, 0, -1, 0.0])) is Joint.REVOLUTE
    assert links.joint_kind(np.array([0, 0, 0, 0, 0, 1.0])) is Joint.PRISMATIC
    assert links.joint_kind(np.array([0, 0, 1, 0, 0, 0.1])) is Joint.HELICAL


def test_axis_points_lie_on_their_axes():
    """Each point p of a revolute axis (w; v) satisfies p x w = v (for pitch 0)."""
    screws = np.array([[0, 0, 1, 2, -1, 0], [1, 0, 0, 0, 3, -0.5], [0, 0, 0, 0, 0, 1]])
    points = links.axis_points(screws, [5.0, 5.0, 5.0])
    for (w, v), p in zip([(s[:3], s[3:]) for s in screws[:2]], points[:2]):
        assert np.allclose(np.cross(p, w), v)
    assert np.array_equal(
        points[2], points[1]
    )  # a prismatic joint keeps the previous point


@pytest.mark.parametrize(
    "value, error, pattern",
    [
        ("0.5", TypeError, "a must be a real number"),
        (None, TypeError, "a must be a real number"),
        (np.inf, ValueError, "a must be finite"),
        (sp.oo, ValueError, "a must be a finite real number"),
        (1j, TypeError, "a must be a real number"),
    ],
)
def test_link_refuses_bad_lengths(value, error, pattern):
    with pytest.raises(error, match=pattern):
        Link.revolute(a=value)


def test_limits_and_rigid_transforms():
    assert links.limits_table([[-1, 1], [-np.inf, np.inf]], 2) == [(-1.0, 1.0), None]
    with pytest.raises(ValueError, match=r"qlim must have shape \(3, 2\)"):
        links.limits_table([[-1, 1]], 3)
    T = links.rigid(np.eye(4), "base")
    assert not T.flags.writeable
    with pytest.raises(ValueError, match="base must be one pose"):
        links.rigid(np.stack([np.eye(4)] * 2), "base")
