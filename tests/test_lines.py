"""screwkit.lines: Plücker lines, distances, common normals, intersections, the central
axis of a wrench and the named configurations of dependent lines, each checked against
an independent computation (NumPy or SymPy on points and directions, never the
module's own formulas) and against configurations built by construction."""

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit.lines import (
    Line,
    central_axis,
    common_normal,
    dependency,
    distance,
    intersection,
    mutual_moment,
)

RNG = np.random.default_rng(39)
R = sp.Rational


def random_rotation(rng):
    q = rng.normal(size=4)
    q /= np.linalg.norm(q)
    w, x, y, z = q
    return np.array(
        [
            [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
            [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
            [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
        ]
    )


def random_pose(rng):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = random_rotation(rng), rng.normal(size=3)
    return T


def f(v):
    return np.array([float(e) for e in v], dtype=float).reshape(-1)


# ---- one line ------------------------------------------------------------------------


def test_a_line_through_two_points_holds_every_point_between_them():
    for _ in range(20):
        p, q = RNG.normal(size=3), RNG.normal(size=3)
        line = Line.through(p, q)
        w, m = line.direction, line.moment
        assert abs(w @ m) < 1e-12
        for t in (-1.5, 0.0, 0.3, 2.0):
            x = p + t * (q - p)
            np.testing.assert_allclose(np.cross(x, w), m, atol=1e-12)
        # the point nearest the origin: on the line and normal to it
        np.testing.assert_allclose(np.cross(line.point, w), m, atol=1e-12)
        assert abs(line.point @ w) < 1e-12


def test_exact_constructors_agree_and_stay_exact():
    p, d = [1, R(1, 2), 3], [2, -1, R(1, 3)]
    a = Line.from_point_direction(p, d)
    b = Line.through(p, [p[i] + d[i] for i in range(3)])
    assert a.exact and b.exact
    assert a.vector == b.vector
    assert a.vector[3:, :] == sp.Matrix(p).cross(sp.Matrix(d))


def test_the_line_of_two_planes_lies_in_both():
    n1, d1, n2, d2 = [1, 2, -1], 3, [0, 1, 4], -2
    line = Line.from_planes(n1, d1, n2, d2)
    for t in (0, 1, R(-5, 2)):
        x = line.point + t * line.direction
        assert sp.Matrix(n1).dot(x) == d1 and sp.Matrix(n2).dot(x) == d2
    floats = Line.from_planes(np.array(n1) * 1.0, 3.0, n2, -2.0)
    np.testing.assert_allclose(floats.vector, f(line.vector), atol=1e-12)


def test_a_screw_is_a_line_plus_a_pitch():
    line = Line.through([1, 0, 0], [1, 0, 1])
    screw = line.screw(R(1, 2))
    assert screw.pitch == R(1, 2)
    assert screw.point == sp.Matrix([1, 0, 0])


def test_transform_moves_the_points_of_the_line():
    for _ in range(10):
        p, q, T = RNG.normal(size=3), RNG.normal(size=3), random_pose(RNG)
        moved = Line.through(p, q).transform(T)
        expected = Line.through(T[:3, :3] @ p + T[:3, 3], T[:3, :3] @ q + T[:3, 3])
        np.testing.assert_allclose(moved.vector, expected.vector, atol=1e-12)
    T = sp.Matrix([[0, 0, 1, 2], [1, 0, 0, -1], [0, 1, 0, R(1, 2)], [0, 0, 0, 1]])
    moved = Line.through([0, 0, 0], [1, 2, 3]).transform(T)
    assert moved.exact
    assert moved.vector == Line.through([2, -1, R(1, 2)], [5, 0, R(5, 2)]).vector


def test_float_lines_typed_to_7_digits_are_projected_onto_the_klein_quadric():
    u = np.array([0.6, 0.8, 0.0])
    m = np.cross([0.0, 0.0, 1.0], u) + 3e-8
    line = Line(np.concatenate([u, m]))
    assert abs(line.direction @ line.moment) < 1e-15


# ---- two lines -----------------------------------------------------------------------


def reference_distance(p1, d1, p2, d2):
    """Distance of two lines by least squares on |p1 + s d1 - p2 - t d2| (NumPy)."""
    A = np.stack([d1, -d2], axis=1)
    st = np.linalg.lstsq(A, p2 - p1, rcond=None)[0]
    return np.linalg.norm(p1 + st[0] * d1 - p2 - st[1] * d2), st


def test_distance_and_feet_agree_with_least_squares():
    for _ in range(30):
        p1, d1, p2, d2 = (RNG.normal(size=3) for _ in range(4))
        a = Line.from_point_direction(p1, d1)
        b = Line.from_point_direction(p2, d2)
        d_ref, st = reference_distance(p1, d1, p2, d2)
        assert distance(a, b) == pytest.approx(d_ref, abs=1e-12)
        cn = common_normal(a, b)
        assert cn.unique
        np.testing.assert_allclose(cn.foot_a, p1 + st[0] * d1, atol=1e-10)
        np.testing.assert_allclose(cn.foot_b, p2 + st[1] * d2, atol=1e-10)
        assert abs(cn.segment @ d1) < 1e-10 and abs(cn.segment @ d2) < 1e-10


def test_distance_of_parallel_lines_and_in_millimetres():
    a = Line.through([0, 0, 0], [0, 0, 1])
    b = Line.through([3, 4, 7], [3, 4, -2])
    assert distance(a, b) == 5
    assert common_normal(a, b).unique is False
    am = Line.through([0.0, 0.0, 0.0], [0.0, 0.0, 1000.0])
    bm = Line.through([3000.0, 4000.0, 7000.0], [3000.0, 4000.0, -2000.0])
    assert distance(am, bm) == pytest.approx(5000.0, rel=1e-14)


@pytest.mark.parametrize("d, alpha", [(1, sp.pi / 6), (R(5, 2), -sp.pi / 3), (2, 0)])
def test_mutual_moment_is_minus_d_sin_alpha(d, alpha):
    """a is the z axis, the common normal is +x, b is a's direction turned by alpha
    about x, through (d, 0, 0): the mutual moment of unit lines is -d sin(alpha)."""
    a = Line.through([0, 0, 0], [0, 0, 1])
    direction = [0, -sp.sin(alpha), sp.cos(alpha)]
    b = Line.from_point_direction([d, 0, 0], direction)
    assert sp.simplify(mutual_moment(a, b) + d * sp.sin(alpha)) == 0
    assert sp.simplify(distance(a, b) - d) == 0


def test_mutual_moment_batch_is_the_reciprocal_product_row_by_row():
    A = np.array([f(Line.through(*RNG.normal(size=(2, 3))).vector) for _ in range(5)])
    B = np.array([f(Line.through(*RNG.normal(size=(2, 3))).vector) for _ in range(5)])
    expected = np.einsum("ij,ij->i", A[:, :3], B[:, 3:]) + np.einsum(
        "ij,ij->i", A[:, 3:], B[:, :3]
    )
    np.testing.assert_allclose(mutual_moment(A, B), expected, atol=1e-14)
    assert mutual_moment(A, B[0]).shape == (5,)


@pytest.mark.parametrize("scale", [1.0, 1000.0])
def test_intersection_of_built_lines(scale):
    X = np.array([0.3, -1.2, 0.7]) * scale
    a = Line.from_point_direction(X, [1.0, 0.2, -0.4])
    b = Line.from_point_direction(X + np.array([0.0, 2.0, 1.0]) * scale, [0, 2, 1])
    np.testing.assert_allclose(intersection(a, b), X, atol=1e-9 * scale)
    lifted = Line.from_point_direction(X + [0, 0, 1e-3 * scale], [0, 2, 1])
    assert intersection(a, lifted) is None
    parallel = Line.from_point_direction(X + [0, 0, 0.5 * scale], [2.0, 0.4, -0.8])
    assert intersection(a, parallel) == "parallel"
    same = Line.from_point_direction(
        X + np.array([3.0, 0.6, -1.2]) * scale, [-2, -0.4, 0.8]
    )
    assert intersection(a, same) == "same line"


def test_exact_intersection():
    a = Line.through([0, 0, 0], [1, 1, 1])
    b = Line.through([2, 0, 2], [0, 2, 0])
    assert intersection(a, b) == sp.Matrix([1, 1, 1])
    c = Line.through([0, 0, 1], [1, 0, 1])
    assert intersection(a, c) is None  # a's points (t, t, t) have y = 0 only at z = 0
    assert intersection(c, Line.through([0, 5, 1], [3, 5, 1])) == "parallel"


# ---- the central axis ----------------------------------------------------------------


def test_central_axis_rebuilds_the_wrench():
    for _ in range(20):
        f_, m = RNG.normal(size=3), RNG.normal(size=3)
        ca = central_axis(np.concatenate([f_, m]))
        r = ca.line.point
        # force through r plus the couple along f: the moment about the origin is m
        np.testing.assert_allclose(np.cross(r, f_) + ca.couple, m, atol=1e-12)
        np.testing.assert_allclose(np.cross(ca.couple, f_), 0, atol=1e-12)
        assert ca.pitch == pytest.approx(f_ @ m / (f_ @ f_))


def test_central_axis_exact_and_of_a_couple():
    wrench = sk.Wrench.from_axis([1, 1, 0], [0, 0, 2], R(1, 4))
    ca = central_axis(wrench)
    assert ca.pitch == R(1, 4)
    assert intersection(ca.line, Line.from_point_direction([0, 0, 2], [1, 1, 0])) == (
        "same line"
    )
    couple = central_axis([0, 0, 0, 0, 0, 3])
    assert couple.line is None and couple.pitch == sp.oo


def test_two_forces_add_to_a_force_along_their_resultant_line():
    """Two forces through (0, 0, 0) and (1, 0, 0), both along z: 1 N and 3 N meet at
    (3/4, 0, 0) (the lever rule), with no couple."""
    w1 = Line.through([0, 0, 0], [0, 0, 1]).screw(0, sk.Wrench)
    w2 = 3 * Line.through([1, 0, 0], [1, 0, 1]).screw(0, sk.Wrench)
    ca = central_axis(w1 + w2)
    assert ca.pitch == 0 and ca.line.point == sp.Matrix([R(3, 4), 0, 0])


# ---- dependency: rank and the named configuration ------------------------------------


def random_int_line(rng):
    p, q = rng.integers(-5, 6, size=(2, 3))
    while (p == q).all():
        q = rng.integers(-5, 6, size=3)
    return Line.through([int(v) for v in p], [int(v) for v in q])


def test_dependency_rank_is_the_exact_rank():
    rng = np.random.default_rng(7)
    for count in range(1, 8):
        lines = [random_int_line(rng) for _ in range(count)]
        expected = sp.Matrix([list(ln.vector) for ln in lines]).rank()
        assert dependency(lines).rank == expected


def pencil(P, directions):
    return [Line.from_point_direction(P, d) for d in directions]


def test_flat_pencil_then_star_then_out_of_the_point():
    P = [1, 2, -1]
    lines = pencil(P, [[1, 0, 0], [0, 1, 0], [1, 1, 0], [2, -3, 0]])
    result = dependency(lines)
    assert (result.rank, result.name) == (2, "flat pencil")
    assert result.data["point"] == sp.Matrix(P)
    n, d = result.data["plane"]
    assert n.cross(sp.Matrix([0, 0, 1])) == sp.zeros(3, 1) and d == n.dot(sp.Matrix(P))
    star = dependency(lines + pencil(P, [[0, 1, 1]]))
    assert (star.rank, star.name, star.data["point"]) == (3, "star", sp.Matrix(P))
    off = dependency(
        lines + pencil(P, [[0, 1, 1]]) + [Line.through([0, 0, 0], [1, 5, 2])]
    )
    assert off.rank == 4 and off.name != "star"


def test_plane_and_parallel_lines():
    in_plane = [
        Line.through(p, q)
        for p, q in [
            ([0, 0, 2], [1, 0, 2]),
            ([0, 0, 2], [0, 1, 2]),
            ([1, 1, 2], [3, -1, 2]),
            ([5, 1, 2], [4, 7, 2]),
        ]
    ]
    result = dependency(in_plane)
    assert (result.rank, result.name) == (3, "plane")
    n, d = result.data["plane"]
    assert sp.Matrix([0, 0, 1]).cross(n) == sp.zeros(3, 1) and d / n[2] == 2
    parallel = [
        Line.from_point_direction(p, [1, 1, 0])
        for p in ([0, 0, 0], [0, 0, 1], [3, 1, 2], [1, 5, 0])
    ]
    result = dependency(parallel)
    assert (result.rank, result.name) == (3, "parallel lines")
    lifted = dependency(in_plane + [Line.through([0, 0, 0], [0, 0, 1])])
    assert lifted.rank == 4


def hyperboloid_lines(params):
    """Generators of x^2 + y^2 - z^2 = 1: through (c, s, 0) along (-s, c, 1), with
    (c, s) on the unit circle (rational points)."""
    return [Line.from_point_direction([c, s, 0], [-s, c, 1]) for c, s in params]


CIRCLE = [(1, 0), (R(3, 5), R(4, 5)), (R(-5, 13), R(12, 13)), (R(8, 17), R(-15, 17))]


def test_regulus_and_its_perturbation():
    lines = hyperboloid_lines(CIRCLE)
    for line in lines:  # each generator lies on the hyperboloid
        for t in (0, 1, -2):
            x, y, z = line.point + t * line.direction
            assert x**2 + y**2 - z**2 == 1
    result = dependency(lines)
    assert (result.rank, result.name) == (3, "regulus")
    moved = lines[:3] + [
        Line.from_point_direction([R(8, 17), R(-15, 17), 0], [R(15, 17), R(8, 17), 2])
    ]
    assert dependency(moved).rank == 4
    floats = [Line(f(ln.vector) * 1.0) for ln in lines]
    assert dependency(floats).name == "regulus"


def test_two_flat_pencils_share_a_line():
    P1, P2 = [0, 0, 0], [2, 0, 0]
    first = pencil(P1, [[1, 0, 0], [0, 1, 0]])  # plane z = 0
    second = pencil(P2, [[0, 0, 1], [1, 0, 1]])  # plane y = 0
    result = dependency(first + second)
    assert (result.rank, result.name) == (3, "two flat pencils")
    common = result.data["line"]
    assert intersection(common, Line.through(P1, P2)) == "same line"


def lines_meeting(l1_points, l2_points):
    return [Line.through(p, q) for p in l1_points for q in l2_points]


def test_lines_meeting_two_skew_lines_and_point_and_plane():
    l1 = Line.through([0, 0, 0], [1, 0, 0])  # the x axis
    l2 = Line.through([0, 0, 1], [0, 1, 1])  # parallel to y at height 1
    on1 = [[0, 0, 0], [1, 0, 0], [3, 0, 0]]
    on2 = [[0, 0, 1], [0, 2, 1]]
    result = dependency(lines_meeting(on1, on2))
    assert (result.rank, result.name) == (4, "lines meeting two lines")
    found = result.data["lines"]
    assert (
        sorted(
            [intersection(found[i], ln) for i in range(2) for ln in (l1, l2)], key=str
        ).count("same line")
        == 2
    )
    P = [1, 1, 0]
    star = pencil(P, [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
    plane = [Line.through([0, 0, 0], [5, 1, 0]), Line.through([2, 0, 0], [0, 3, 0])]
    result = dependency(star + plane)
    assert (result.rank, result.name) == (4, "point and plane")
    assert result.data["point"] == sp.Matrix(P)


def lines_through_axis(axis):
    """Five lines, each through a point of ``axis`` (a special complex of rank 5)."""
    return [
        Line.through(axis.point + t * axis.direction, q)
        for t, q in [
            (0, [5, 0, 0]),
            (1, [0, 3, 2]),
            (2, [1, -4, 0]),
            (-1, [2, 2, 7]),
            (3, [0, 0, -3]),
        ]
    ]


def test_special_and_general_complex():
    axis = Line.through([0, 0, 1], [1, 1, 1])
    meeting = lines_through_axis(axis)
    result = dependency(meeting)
    assert (result.rank, result.name) == (5, "special complex")
    assert intersection(result.data["line"], axis) == "same line"
    rng = np.random.default_rng(3)
    five = [random_int_line(rng) for _ in range(5)]
    result = dependency(five)
    assert (result.rank, result.name) == (5, "general complex")
    rho = result.data["axis"].screw(result.data["pitch"])
    for line in five:  # every line is reciprocal to the complex's screw
        assert sp.simplify(rho @ line.screw(0)) == 0
    assert dependency(five + [random_int_line(rng)]).name == "independent"


@pytest.mark.parametrize(
    "name, build",
    [
        ("flat pencil", lambda: pencil([1, 2, -1], [[1, 0, 0], [0, 1, 0], [1, 1, 0]])),
        (
            "star",
            lambda: pencil([1, 2, -1], [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]]),
        ),
        ("regulus", lambda: hyperboloid_lines(CIRCLE)),
        (
            "lines meeting two lines",
            lambda: lines_meeting(
                [[0, 0, 0], [1, 0, 0], [3, 0, 0]], [[0, 0, 1], [0, 2, 1]]
            ),
        ),
    ],
)
def test_the_same_name_and_scaled_data_in_metres_and_millimetres(name, build):
    lines = build()
    for scale in (1.0, 1000.0):
        moved = [
            Line(np.concatenate([f(ln.direction), f(ln.moment) * scale]))
            for ln in lines
        ]
        result = dependency(moved)
        assert result.name == name
        if "point" in result.data:
            exact = dependency(lines).data["point"]
            np.testing.assert_allclose(
                result.data["point"], f(exact) * scale, atol=1e-9 * scale
            )


def test_a_perturbed_float_pencil_is_no_longer_a_pencil():
    lines = [
        Line(f(ln.vector))
        for ln in pencil([1, 2, -1], [[1, 0, 0], [0, 1, 0], [1, 1, 0]])
    ]
    assert dependency(lines).name == "flat pencil"
    tilted = Line.from_point_direction([1, 2, -1 + 1e-4], [1.0, 1.0, 0.0])
    result = dependency(lines[:2] + [tilted])
    assert (result.rank, result.name) != (2, "flat pencil")


def test_dependency_of_screw_systems_of_lines():
    """A spherical wrist's axes through one point are a star; a leg system given as a
    ScrewSystem of wrenches is read line by line."""
    wrist = sk.ScrewSystem(
        [
            ([1, 0, 0], [0, 0, 1], 0),
            ([0, 1, 0], [0, 0, 1], 0),
            ([0, 0, 1], [0, 0, 1], 0),
            ([1, 1, 1], [0, 0, 1], 0),
        ]
    )
    result = dependency(wrist)
    assert (result.rank, result.name, result.data["point"]) == (
        3,
        "star",
        sp.Matrix([0, 0, 1]),
    )


def named_configurations():
    """One built example of every name dependency gives (ranks 1 to 5)."""
    P = [1, 2, -1]
    axis = Line.through([0, 0, 1], [1, 1, 1])
    meeting_axis = lines_through_axis(axis)
    return {
        "one line": [
            Line.through([0, 0, 0], [1, 2, 3]),
            Line.through([2, 4, 6], [1, 2, 3]),
        ],
        "two skew lines": [
            Line.through([0, 0, 0], [1, 0, 0]),
            Line.through([0, 0, 1], [0, 1, 1]),
        ],
        "flat pencil": pencil(P, [[1, 0, 0], [0, 1, 0], [1, 1, 0]]),
        "star": pencil(P, [[1, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]]),
        "parallel lines": [
            Line.from_point_direction(p, [1, 1, 0])
            for p in ([0, 0, 0], [0, 0, 1], [3, 1, 2])
        ],
        "plane": [
            Line.through(p, q)
            for p, q in [
                ([0, 0, 2], [1, 0, 2]),
                ([0, 0, 2], [0, 1, 2]),
                ([1, 1, 2], [3, -1, 2]),
            ]
        ],
        "two flat pencils": pencil([0, 0, 0], [[1, 0, 0], [0, 1, 0]])
        + pencil([2, 0, 0], [[0, 0, 1], [1, 0, 1]]),
        "regulus": hyperboloid_lines(CIRCLE),
        "lines meeting two lines": lines_meeting(
            [[0, 0, 0], [1, 0, 0], [3, 0, 0]], [[0, 0, 1], [0, 2, 1]]
        ),
        "point and plane": pencil(P, [[1, 0, 0], [0, 1, 0], [0, 0, 1]])
        + [Line.through([0, 0, -1], [5, 1, -1]), Line.through([2, 0, -1], [0, 3, -1])],
        "special complex": meeting_axis,
    }


@pytest.mark.parametrize("name", list(named_configurations()))
def test_names_survive_rigid_motions_and_units(name):
    lines = named_configurations()[name]
    assert dependency(lines).name == name
    rng = np.random.default_rng(len(name))
    for scale in (1.0, 1000.0, 0.001):
        T = random_pose(rng)
        T[:3, 3] *= scale
        moved = []
        for line in lines:
            v = f(line.vector)
            v[3:] *= scale
            moved.append(Line(v).transform(T))
        assert dependency(moved).name == name


def test_parabolic_and_elliptic_congruences_by_construction():
    """Rank 4 whose reciprocal 2-system holds one line (parabolic) or none (elliptic).

    Parabolic: lines through (0, 0, t) meeting the z axis and reciprocal to the screw of
    pitch h = 2 on the x axis: with direction d, h d_x - t d_y = 0. Elliptic: lines
    reciprocal to the pitch-1 screws on the x and y axes: m_x = -w_x, m_y = -w_y and
    m_z = (w_x^2 + w_y^2) / w_z from w . m = 0."""
    h = 2
    parabolic = [
        Line.from_point_direction([0, 0, t], [dx, R(h * dx, t), dz])
        for t, dx, dz in [(1, 1, 0), (2, 1, 1), (-1, 2, 1), (3, 1, -2), (R(1, 2), 1, 3)]
    ]
    result = dependency(parabolic)
    assert (result.rank, result.name) == (4, "parabolic congruence")
    assert intersection(result.data["line"], Line([0, 0, 1, 0, 0, 0])) == "same line"
    elliptic = [
        Line([wx, wy, wz, -wx, -wy, R(wx**2 + wy**2, wz)])
        for wx, wy, wz in [(1, 0, 1), (0, 1, 1), (1, 1, 2), (2, -1, 1), (1, 3, -1)]
    ]
    result = dependency(elliptic)
    assert (result.rank, result.name) == (4, "elliptic congruence")
