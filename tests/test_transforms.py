"""Rigid-body motions: exact identities, independent formulas and input checks."""

import numpy as np
import pytest
import sympy as sp
from builders import refusals
from hypothesis import given, settings
from hypothesis import strategies as st

import screwkit as sk

theta = sp.Symbol("theta", real=True)
angles = st.floats(-2 * np.pi, 2 * np.pi)
coords = st.floats(-2.0, 2.0)
points = st.tuples(coords, coords, coords).map(np.array)
directions = points.filter(lambda v: np.linalg.norm(v) > 0.1)


def matrix_exponential(A, terms=60):
    """exp(A) by its power series: an independent reference for small matrices."""
    result, term = np.eye(A.shape[0]), np.eye(A.shape[0])
    for k in range(1, terms):
        term = term @ A / k
        result = result + term
    return result


def twist_matrix(twist):
    """The 4x4 matrix [xi] = [[[w], v], [0, 0]] of a twist (w; v)."""
    w, v = np.asarray(twist[:3], float), np.asarray(twist[3:], float)
    M = np.zeros((4, 4))
    M[:3, :3] = [[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]
    M[:3, 3] = v
    return M


# --- exact (SymPy) results ------------------------------------------------------------


def test_elementary_rotations_are_the_textbook_matrices():
    c, s = sp.cos(theta), sp.sin(theta)
    assert sk.rotx(theta) == sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]])
    assert sk.roty(theta) == sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    assert sk.rotz(theta) == sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def test_quarter_turns_are_exact_integers():
    assert sk.rotz(sp.pi / 2) == sp.Matrix([[0, -1, 0], [1, 0, 0], [0, 0, 1]])
    assert sk.rotx(sp.pi) == sp.diag(1, -1, -1)


def test_rodrigues_about_the_frame_axes_gives_the_elementary_rotations():
    for axis, rot in [([1, 0, 0], sk.rotx), ([0, 1, 0], sk.roty), ([0, 0, 1], sk.rotz)]:
        assert sp.simplify(
            sk.rot_axis(sp.Matrix(axis), theta) - rot(theta)
        ) == sp.zeros(3, 3)


def test_symbolic_rotation_about_any_unit_axis_is_orthonormal():
    a, b = sp.symbols("a b", real=True)
    axis = sp.Matrix([sp.cos(a) * sp.cos(b), sp.sin(a) * sp.cos(b), sp.sin(b)])
    R = sk.rot_axis(axis, theta)
    assert sp.simplify(R.T * R - sp.eye(3)) == sp.zeros(3, 3)
    assert sp.simplify(R * axis - axis) == sp.zeros(3, 1)


def test_symbolic_revolute_motion_is_rotation_about_a_displaced_axis():
    # exp([xi] theta) for the line through r along z equals Tr(r) Rz(theta) Tr(-r).
    a, b, h = sp.symbols("a b h", real=True)
    r = sp.Matrix([a, b, 0])
    expected = sk.transl(r) * sk.homogeneous(sk.rotz(theta)) * sk.transl(-r)
    expected[2, 3] = h * theta  # the pitch advances h*theta along z
    assert sp.simplify(sk.screw_motion([0, 0, 1], r, h, theta) - expected) == sp.zeros(
        4, 4
    )


def test_symbolic_prismatic_motion_is_a_translation():
    d = sp.Symbol("d", real=True)
    s = sp.Matrix([3, 0, 4]) / 5
    assert sk.screw_motion(s, [1, 2, 3], sp.oo, d) == sk.transl(d * s)


def test_symbolic_inverse():
    T = sk.transl(sp.Matrix([1, 2, 3])) * sk.homogeneous(sk.rotx(theta))
    assert sp.simplify(sk.inv(T) * T) == sp.eye(4)


def test_twist_of_an_axis_is_s_and_r_cross_s_plus_h_s():
    r, s, h = sp.Matrix([1, 2, 3]), sp.Matrix([0, 0, 1]), sp.Rational(1, 2)
    assert sk.twist_from_axis(s, r, h) == sp.Matrix([0, 0, 1, 2, -1, sp.Rational(1, 2)])
    assert sk.twist_from_axis(s, r, sp.oo) == sp.Matrix([0, 0, 0, 0, 0, 1])


def test_integer_valued_floats_become_exact_integers_in_symbolic_results():
    T = sk.exp_twist(sk.twist_from_axis([0, 0, 1], [1, 0, 0], 0), theta)
    assert T == sk.transl(sp.Matrix([1, 0, 0])) * sk.homogeneous(
        sk.rotz(theta)
    ) * sk.transl(sp.Matrix([-1, 0, 0]))


def test_symbolic_and_numeric_results_agree():
    f = sp.lambdify(
        theta, sk.screw_motion([1, 2, 2], [0.5, -1, 2], sp.Rational(1, 3), theta)
    )
    for value in [-2.0, 0.1, 1.3]:
        assert np.allclose(
            f(value), sk.screw_motion([1, 2, 2], [0.5, -1, 2], 1 / 3, value), atol=1e-12
        )


# --- numeric (NumPy) results ----------------------------------------------------------


@settings(max_examples=200, deadline=None)
@given(directions, points, st.floats(-1.0, 1.0), angles)
def test_exp_twist_equals_the_matrix_exponential_series(s, r, h, angle):
    twist = sk.twist_from_axis(s, r, h)
    assert np.allclose(
        sk.exp_twist(twist, angle),
        matrix_exponential(twist_matrix(twist) * angle),
        atol=1e-9,
    )


@settings(max_examples=200, deadline=None)
@given(directions, points, st.floats(-1.0, 1.0), angles)
def test_screw_motion_fixes_its_axis_and_advances_along_it(s, r, h, angle):
    u = s / np.linalg.norm(s)
    T = sk.screw_motion(s, r, h, angle)
    point_on_axis = np.append(r + 0.7 * u, 1.0)
    assert np.allclose(
        T @ point_on_axis, np.append(r + 0.7 * u + h * angle * u, 1.0), atol=1e-9
    )
    assert np.allclose(T[:3, :3], sk.rot_axis(u, angle), atol=1e-12)


@settings(max_examples=100, deadline=None)
@given(directions, points, angles, angles)
def test_exponentials_of_one_twist_compose_by_adding_angles(s, r, a, b):
    twist = sk.twist_from_axis(s, r, 0.25)
    assert np.allclose(
        sk.exp_twist(twist, a) @ sk.exp_twist(twist, b),
        sk.exp_twist(twist, a + b),
        atol=1e-9,
    )


@settings(max_examples=100, deadline=None)
@given(directions, points, angles)
def test_inverse_undoes_the_transform(s, r, angle):
    T = sk.screw_motion(s, r, 0.1, angle)
    assert np.allclose(sk.inv(T) @ T, np.eye(4), atol=1e-12)
    assert np.allclose(sk.inv(T), np.linalg.inv(T), atol=1e-9)


def test_rotations_are_vectorised_over_a_batch_of_angles():
    angles_ = np.linspace(-3, 3, 7)
    for rot in (sk.rotx, sk.roty, sk.rotz):
        batch = rot(angles_)
        assert batch.shape == (7, 3, 3)
        assert np.allclose(batch, np.stack([rot(a) for a in angles_]))
    T = sk.exp_twist([0, 1, 0, 1, 0, 0.5], angles_)
    assert T.shape == (7, 4, 4)
    assert np.allclose(
        T, np.stack([sk.exp_twist([0, 1, 0, 1, 0, 0.5], a) for a in angles_])
    )
    assert np.allclose(sk.inv(T) @ T, np.eye(4))


def test_pure_translation_twist():
    T = sk.exp_twist([0, 0, 0, 1, 2, 3], 2.0)
    assert np.array_equal(T, sk.transl(2, 4, 6))


def test_transl_forms_agree():
    assert np.array_equal(sk.transl(1, 2, 3), sk.transl([1, 2, 3]))
    assert sk.transl([[1, 2, 3], [4, 5, 6]]).shape == (2, 4, 4)


# --- bad input ------------------------------------------------------------------------


test_bad_input_is_named_in_a_clear_error = refusals(
    [
        (lambda: sk.rotz("a"), TypeError, "theta must be a real number"),
        (lambda: sk.rotz(np.nan), ValueError, "theta must be finite"),
        (lambda: sk.rotz([0.1, np.inf]), ValueError, "theta must be finite"),
        (lambda: sk.rotz(sp.nan), ValueError, "theta must be finite"),
        (lambda: sk.rotz(None), TypeError, "theta must be a real number"),
        (lambda: sk.skew([1, 2]), ValueError, r"v must have shape \(3,\)"),
        (
            lambda: sk.rot_axis([0, 0, 0], 1.0),
            ValueError,
            "axis must be a non-zero 3-vector",
        ),
        (
            lambda: sk.rot_axis(sp.Matrix([0, 0, 0]), theta),
            ValueError,
            "axis must be a non-zero",
        ),
        (
            lambda: sk.transl(1, 2),
            TypeError,
            "transl takes a 3-vector p or three numbers",
        ),
        (lambda: sk.transl([1, 2, 3, 4]), ValueError, r"p must have shape \(3,\)"),
        (
            lambda: sk.homogeneous(np.ones((3, 3))),
            ValueError,
            "R must be a rotation matrix",
        ),
        (lambda: sk.homogeneous(np.diag([1, 1, -1])), ValueError, "determinant \\+1"),
        (lambda: sk.homogeneous(np.eye(2)), ValueError, r"R must have shape \(3, 3\)"),
        (
            lambda: sk.homogeneous(sp.Matrix([[theta, 0, 0], [0, 1, 0], [0, 0, 1]])),
            ValueError,
            "R must be a rotation matrix",
        ),
        (lambda: sk.inv(np.eye(3)), ValueError, r"T must have shape \(4, 4\)"),
        (lambda: sk.inv(np.full((4, 4), np.nan)), ValueError, "T must be finite"),
        (
            lambda: sk.inv(np.diag([1.0, 1, 1, 2])),
            ValueError,
            r"last row \[0, 0, 0, 1\]",
        ),
        (lambda: sk.inv(np.diag([2.0, 1, 1, 1])), ValueError, "rotation block of T"),
        (
            lambda: sk.exp_twist([0, 0, 1], 1.0),
            ValueError,
            r"twist must have shape \(6,\)",
        ),
        (
            lambda: sk.exp_twist(sp.Matrix([0, 0, 1]), theta),
            ValueError,
            r"twist must have shape \(6, 1\)",
        ),
        (
            lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], "x"),
            TypeError,
            "h must be a pitch",
        ),
        (
            lambda: sk.twist_from_axis([0, 0, 1], [0, 0, 0], np.nan),
            ValueError,
            "h must be a pitch",
        ),
        (
            lambda: sk.twist_from_axis([0, 0, 0], [0, 0, 0], 0),
            ValueError,
            "s must be a non-zero",
        ),
    ]
)


def test_strings_are_not_sympified_into_symbols():
    with pytest.raises(
        TypeError, match="r must hold numbers or SymPy expressions, not strings"
    ):
        sk.twist_from_axis([0, 0, 1], [theta, "x", 0], 0)
    with pytest.raises(TypeError, match="h must be a pitch"):
        sk.twist_from_axis([0, 0, 1], [theta, 0, 0], "h")


# --- edge cases that used to be silent ------------------------------------------------


@pytest.mark.parametrize(
    "axis, rot",
    [
        ([1e200, 0, 0], sk.rotx),
        ([0, -1e-11, 0], None),
        ([0, 0, 3e307], sk.rotz),
        ([1e154, 1e154, 0], None),
    ],
)
def test_huge_and_tiny_axes_are_normalised_without_overflow(axis, rot):
    u = np.array(axis) / np.max(np.abs(axis))
    u = u / np.linalg.norm(u)  # the direction, from the scaled vector
    R = sk.rot_axis(axis, 0.7)
    # Rodrigues' formula by hand: I + sin [u] + (1 - cos) [u]^2
    U = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    assert np.allclose(
        R, np.eye(3) + np.sin(0.7) * U + (1 - np.cos(0.7)) * U @ U, atol=1e-15
    )
    if rot is not None:
        assert np.allclose(R, rot(0.7), atol=1e-15)
    assert not np.allclose(R, np.eye(3))


def test_sympy_axis_with_a_float_angle_is_exact_in_exact_out():
    R = sk.rot_axis(sp.Matrix([0, 0, 1]), 0.5)
    assert isinstance(R, sp.MatrixBase)
    c, s = np.cos(0.5), np.sin(0.5)
    assert np.allclose(
        np.array(R, dtype=float), [[c, -s, 0], [s, c, 0], [0, 0, 1]], atol=1e-15
    )
    T = sk.exp_twist(sp.Matrix([0, 0, 1, 0, 0, 0]), 0.5)
    assert isinstance(T, sp.MatrixBase) and np.allclose(
        np.array(T[:3, :3], dtype=float), np.array(R, dtype=float)
    )
    # and a numeric axis with a symbolic angle
    assert sp.simplify(sk.rot_axis([0, 0, 2], theta) - sk.rotz(theta)) == sp.zeros(3, 3)


def test_an_infinite_float_pitch_is_a_translation():
    assert np.array_equal(
        sk.twist_from_axis([0, 0, 2], [5, 6, 7], np.inf), [0, 0, 0, 0, 0, 1]
    )
    assert np.array_equal(
        sk.twist_from_axis([0, 0, 2], [5, 6, 7], float("inf")),
        sk.twist_from_axis([0, 0, 1], [0, 0, 0], sp.oo),
    )
