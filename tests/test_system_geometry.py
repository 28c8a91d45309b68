"""ScrewSystem.principal_screws, pitch_of and classify: principal pitches against the
generalised eigenvalues of the two quadratic forms computed independently (SciPy on the
screws as given, or SymPy's determinant), the cylindroid's pitch law, invariance under
rigid motions, changes of basis and units, and the named special systems."""

import numpy as np
import pytest
import scipy.linalg
import sympy as sp

from screwkit import ScrewSystem, Twist

R = sp.Rational
O = [0, 0, 0]
RNG = np.random.default_rng(390)


def random_pose(rng):
    q = rng.normal(size=4)
    w, x, y, z = q / np.linalg.norm(q)
    T = np.eye(4)
    T[:3, :3] = [
        [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
        [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
        [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
    ]
    T[:3, 3] = rng.normal(size=3)
    return T


def adjoint(T):
    """Ad(T) for [angular; linear] screws, written out here."""
    Rm, p = T[:3, :3], T[:3, 3]
    P = np.array([[0, -p[2], p[1]], [p[2], 0, -p[0]], [-p[1], p[0], 0]])
    return np.block([[Rm, np.zeros((3, 3))], [P @ Rm, Rm]])


def moved_and_mixed(rows, rng, scale=1.0):
    """The span moved by a random rigid motion, its lengths times ``scale``, and a
    random change of basis."""
    X = np.array(rows, dtype=float) @ adjoint(random_pose(rng)).T
    X[:, 3:] *= scale
    n = X.shape[0]
    M = rng.normal(size=(n, n)) + 3 * np.eye(n)
    return [list(r) for r in M @ X]


def reference_pitches(rows):
    """Generalised eigenvalues of A c = h D c on the screws as given (SciPy)."""
    X = np.array(rows, dtype=float).T
    W, V = X[:3], X[3:]
    return np.sort(
        scipy.linalg.eigh((W.T @ V + V.T @ W) / 2, W.T @ W, eigvals_only=True)
    )


def floats(pitches):
    return np.array([float(h) for h in pitches])


@pytest.mark.parametrize("order", [2, 3])
def test_principal_pitches_are_the_generalised_eigenvalues(order):
    for _ in range(10):
        rows = RNG.normal(size=(order, 6))
        system = ScrewSystem([list(r) for r in rows])
        principal = system.principal_screws()
        np.testing.assert_allclose(
            floats(principal.pitches), reference_pitches(rows), rtol=1e-9, atol=1e-12
        )
        assert principal.unique
        for screw, h in zip(principal.screws, principal.pitches):
            assert float(screw.pitch) == pytest.approx(float(h), rel=1e-9, abs=1e-12)
            assert system.contains(screw)


def test_exact_principal_pitches_are_the_roots_of_det_a_minus_h_d():
    screws = [([1, 0, 0], O, 1), ([0, 1, 0], [0, 0, 1], 2), ([0, 0, 1], [1, 0, 0], -1)]
    system = ScrewSystem(screws)
    pitches = system.principal_screws().pitches
    X = sp.Matrix.hstack(*[Twist.from_axis(*s).vector for s in screws])
    W, V = X[:3, :], X[3:, :]
    h = sp.Symbol("h")
    det = ((W.T * V + V.T * W) / 2 - h * W.T * W).det()
    for p in pitches:
        assert abs(sp.N(det.subs(h, p), 40)) < 1e-30
    np.testing.assert_allclose(
        floats(pitches),
        reference_pitches(
            [list(map(float, Twist.from_axis(*s).vector)) for s in screws]
        ),
        rtol=1e-12,
    )


def cylindroid_rows(h1, h2):
    return [[1, 0, 0, h1, 0, 0], [0, 1, 0, 0, h2, 0]]


def test_cylindroid_pitch_law_and_its_axes():
    h1, h2 = 0.2, -0.5
    rows = moved_and_mixed(cylindroid_rows(h1, h2), RNG)
    system = ScrewSystem(rows)
    np.testing.assert_allclose(
        floats(system.principal_screws().pitches), [h2, h1], atol=1e-12
    )
    low, high = [
        np.array([float(e) for e in s.vector]) for s in system.principal_screws().screws
    ]  # pitches h2 < h1
    # the principal axes meet at right angles: orthogonal unit directions and a zero
    # mutual moment of the two axes (moments without the pitch part)
    assert low[:3] @ high[:3] == pytest.approx(0, abs=1e-12)
    axis_low, axis_high = low[3:] - h2 * low[:3], high[3:] - h1 * high[:3]
    assert low[:3] @ axis_high + high[:3] @ axis_low == pytest.approx(0, abs=1e-12)
    for t in np.linspace(0, np.pi, 7):
        member = np.cos(t) * low + np.sin(t) * high
        expected = h2 * np.cos(t) ** 2 + h1 * np.sin(t) ** 2
        assert system.pitch_of(list(member)) == pytest.approx(expected, abs=1e-12)


CASES = {
    "general cylindroid": (cylindroid_rows(0.1, 0.4), "2-IA"),
    "flat pencil of screws": (cylindroid_rows(0.3, 0.3), "2-IIA"),
    "planar motion": (
        [[0, 0, 1, 0, 0, 0], [0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0]],
        "3-IIC",
    ),
    "spherical motion": (
        [[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0], [0, 0, 1, 0, 0, 0]],
        "3-IIA",
    ),
    "spatial translations": (
        [[0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 1]],
        "3-IID",
    ),
    "Schoenflies motion": (
        [
            [0, 0, 1, 0, 0, 0],
            [0, 0, 0, 1, 0, 0],
            [0, 0, 0, 0, 1, 0],
            [0, 0, 0, 0, 0, 1],
        ],
        "4-IIC",
    ),
    "general 3-system": (
        [[1, 0, 0, 0.1, 0, 0], [0, 1, 0, 0, 0.25, 0], [0, 0, 1, 0, 0, -0.3]],
        "3-IA",
    ),
    # a rotation about z and the translation along it: every pitch on the z axis
    "coaxial screws": ([[0, 0, 1, 0, 0, 0], [0, 0, 0, 0, 0, 1]], "2-IB"),
    # the same rotation and a slide along (1, 0, 1): parallel axes in the plane x = 0
    "screw and skew translation": ([[0, 0, 1, 0, 0, 0], [0, 0, 0, 1, 0, 1]], "2-IB"),
    # rotations about x and y through the origin and the translation along z
    "planar field of lines": (
        [[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0], [0, 0, 0, 0, 0, 1]],
        "3-IIB",
    ),
}


@pytest.mark.parametrize("name", CASES)
def test_classification_is_invariant(name):
    rows, type_ = CASES[name]
    exact = ScrewSystem([[sp.nsimplify(e) for e in r] for r in rows]).classify()
    assert (exact.name, exact.type) == (name, type_)
    for scale in (1.0, 1000.0):
        moved = ScrewSystem(moved_and_mixed(rows, RNG, scale)).classify()
        assert (moved.name, moved.type, moved.order) == (name, type_, exact.order)
        np.testing.assert_allclose(
            floats(moved.pitches),
            floats(exact.pitches) * scale,
            rtol=1e-8,
            atol=1e-9 * scale,
        )


def test_pitches_of_a_random_system_are_invariant_and_scale_with_units():
    rows = RNG.normal(size=(3, 6))
    base = floats(ScrewSystem([list(r) for r in rows]).principal_screws().pitches)
    for scale in (1.0, 1000.0):
        moved = ScrewSystem(moved_and_mixed(rows, RNG, scale)).principal_screws()
        np.testing.assert_allclose(floats(moved.pitches), base * scale, rtol=1e-8)


def test_degenerate_systems_say_what_is_not_unique():
    equal = ScrewSystem(cylindroid_rows(1, 1)).principal_screws()
    assert not equal.unique and "equal" in equal.reason
    planar = ScrewSystem(CASES["planar motion"][0]).principal_screws()
    assert planar.pitches == [0, sp.oo, sp.oo] and not planar.unique
    assert "moves its axis" in planar.reason
    skew = ScrewSystem([[1, 0, 0, 1, 0, 0], [0, 0, 0, 1, 1, 0]]).principal_screws()
    assert skew.pitches == [sp.oo] and "every real pitch" in skew.reason


def test_pitch_of_refuses_a_screw_outside_the_span():
    system = ScrewSystem(cylindroid_rows(1, 2))
    assert system.pitch_of([1, 1, 0, 1, 2, 0]) == R(3, 2)
    with pytest.raises(ValueError, match="x must lie in the span"):
        system.pitch_of([0, 0, 1, 0, 0, 0])


@pytest.mark.parametrize("order", [0, 4, 5, 6])
def test_principal_screws_need_order_1_to_3(order):
    rows = np.eye(6)[:order].tolist()
    with pytest.raises(ValueError, match="system must be of order"):
        ScrewSystem(rows).principal_screws()


def test_the_cylindroid_drawn_has_the_pitch_law():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from screwkit import plotting

    h1, h2 = 0.2, -0.3
    ax = plotting.axes3d(limits=((-1, 1), (-1, 1), (-1, 1)))
    drawn = plotting.draw_cylindroid(ax, ScrewSystem(cylindroid_rows(h1, h2)), steps=8)
    t = np.linspace(0, np.pi, 8, endpoint=False)
    # the members are taken from the lower pitch (h2, along y) towards the higher
    np.testing.assert_allclose(
        drawn.get_array(), h2 * np.cos(t) ** 2 + h1 * np.sin(t) ** 2, atol=1e-12
    )
    for segment, angle in zip(drawn._segments3d, t):
        middle = np.mean(segment, axis=0)  # on the z axis at (h1 - h2) sin cos
        np.testing.assert_allclose(middle[:2], 0, atol=1e-12)
        assert abs(middle[2]) == pytest.approx(
            abs((h1 - h2) * np.sin(angle) * np.cos(angle)), abs=1e-12
        )
    plt.close(ax.figure)


def test_a_wrench_system_is_named_with_couples_and_forces():
    """Planar motion's reciprocal: a force along z and couples about x and y (worked by
    hand in the chapter's exercise 23); Schoenflies motion's: two couples."""
    planar = ScrewSystem(CASES["planar motion"][0]).reciprocal()
    kind = planar.classify()
    assert (kind.type, kind.name) == ("3-IIC", "planar-motion type")
    assert "forces along parallel axes and the couples" in kind.description
    schoenflies = ScrewSystem(CASES["Schoenflies motion"][0]).reciprocal().classify()
    assert schoenflies.name == "planar couples"


# ---- Gibson and Hunt's two projective features --------------------------------------
#
# The letter counts the independent members of infinite pitch (A none ... D three); the
# numeral is II when every member of finite pitch has one and the same pitch, else I.
# Each class below is worked out by hand in its comment from the rows, never by
# screwkit; test_the_type_agrees_with_sampled_members then checks both features
# against plain NumPy on random members of the moved systems.

Z6 = [0, 0, 1, 0, 0, 0]  # rotation about the z axis through the origin
TX, TY, TZ = [0, 0, 0, 1, 0, 0], [0, 0, 0, 0, 1, 0], [0, 0, 0, 0, 0, 1]

TEXTBOOK = {
    # Ball's cylindroid: pitches 0.1 and 0.4 on perpendicular axes; the directions are
    # independent (no translation: A) and c^2 0.1 + s^2 0.4 varies (I).
    "cylindroid": (cylindroid_rows(0.1, 0.4), "IA"),
    # equal principal pitches: every member c^2 0.3 + s^2 0.3 = 0.3 (II), the flat
    # pencil of pitch-0.3 screws.
    "planar pencil": (cylindroid_rows(0.3, 0.3), "IIA"),
    # a revolute about z and a slide along x: one translation (B), normal to the axis,
    # so a member (0, 0, a; b, 0, 0) has pitch w.m / w.w = 0 for every a != 0 (II).
    "revolute and normal slide": ([Z6, TX], "IIB"),
    # the cylindric pair: (0, 0, a; 0, 0, b) has pitch b / a, every real value (IB).
    "cylindric pair": ([Z6, TZ], "IB"),
    # a revolute about z and a slide along (1, 0, 1): (0, 0, a; b, 0, b) has pitch
    # b / a again (IB), its axis moved along y by -b / a.
    "revolute and skew slide": ([Z6, [0, 0, 0, 1, 0, 1]], "IB"),
    # two slides: two translations (C), no member of finite pitch (II).
    "two slides": ([TX, TY], "IIC"),
    # the spherical pair: three independent directions (A), every member (w; 0) of
    # pitch 0 (II).
    "spherical pair": ([[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0], Z6], "IIA"),
    # a general 3-system (principal pitches 0.1, 0.25, -0.3 on the axes): a member
    # (a, b, c; 0.1a, 0.25b, -0.3c) has pitch
    # (0.1a^2 + 0.25b^2 - 0.3c^2) / (a^2 + b^2 + c^2), which varies (IA).
    "general 3-system": (CASES["general 3-system"][0], "IA"),
    # two principal pitches equal, the third not: (a, b, c; 0.2a, 0.2b, -0.1c) still
    # varies with c (IA).
    "two equal pitches": (
        [[1, 0, 0, 0.2, 0, 0], [0, 1, 0, 0, 0.2, 0], [0, 0, 1, 0, 0, -0.1]],
        "IA",
    ),
    # a cylindric pair followed by a revolute about the x axis through (0, 0, 1):
    # members (b, 0, a; 0, b, c), one translation (B), pitch a c / (a^2 + b^2) (I).
    "cylindric pair and revolute": ([Z6, TZ, [1, 0, 0, 0, 1, 0]], "IB"),
    # the lines of the plane z = 0 (rotations about x and y through the origin) and the
    # translation along z: (a, b, 0; 0, 0, c), pitch 0 for every (a, b) != 0 (IIB).
    "planar field of lines": ([[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 0, 0], TZ], "IIB"),
    # the same lines carrying pitch 0.2: (a, b, 0; 0.2a, 0.2b, c), pitch 0.2 (IIB).
    "planar field of screws": (
        [[1, 0, 0, 0.2, 0, 0], [0, 1, 0, 0, 0.2, 0], TZ],
        "IIB",
    ),
    # the planar pair: rotation about z, slides along x and y: two translations (C),
    # (0, 0, a; b, c, 0) of pitch 0 (II).
    "planar pair": ([Z6, TX, TY], "IIC"),
    # a revolute about x and slides along x and y: (a, 0, 0; b, c, 0) has pitch b / a
    # (IC): the slide along the axis changes the pitch.
    "revolute and two slides, one along it": ([[1, 0, 0, 0, 0, 0], TX, TY], "IC"),
    # three slides (a P-P-P chain, the Delta's platform): three translations (D), no
    # member of finite pitch (II).
    "three slides": ([TX, TY, TZ], "IID"),
}


@pytest.mark.parametrize("name", TEXTBOOK)
def test_gibson_hunt_types_of_the_textbook_systems(name):
    rows, expected = TEXTBOOK[name]
    exact = ScrewSystem([[sp.nsimplify(e) for e in r] for r in rows]).classify()
    assert (exact.gibson_hunt, exact.type) == (expected, f"{len(rows)}-{expected}")
    for scale in (1.0, 1000.0):  # any rigid motion, change of basis and unit
        moved = ScrewSystem(moved_and_mixed(rows, RNG, scale)).classify()
        assert moved.gibson_hunt == expected


@pytest.mark.parametrize("name", TEXTBOOK)
def test_the_type_agrees_with_sampled_members(name):
    """Both features read off random members with NumPy alone: the letter from the rank
    of the direction rows, the numeral from the spread of the members' pitches."""
    rows, _ = TEXTBOOK[name]
    for scale in (1.0, 1000.0):
        X = np.array(moved_and_mixed(rows, RNG, scale))
        translations = len(X) - np.linalg.matrix_rank(X[:, :3], tol=1e-9)
        members = RNG.normal(size=(40, len(X))) @ X
        w, m = members[:, :3], members[:, 3:]
        ww, wm = np.einsum("ij,ij->i", w, w), np.einsum("ij,ij->i", w, m)
        finite = ww > 1e-9 * np.einsum("ij,ij->i", m, m)
        spread = np.ptp(wm[finite] / ww[finite]) / scale if finite.any() else 0.0
        letter = "ABCD"[translations]
        numeral = "II" if spread < 1e-9 else "I"
        assert ScrewSystem([list(r) for r in X]).classify().gibson_hunt == (
            numeral + letter
        )


def test_a_3_system_and_its_reciprocal_share_the_type():
    """For a 3-system both features pass to the reciprocal: the translations, since
    dim(S^perp n T) = 3 - n + dim(S n T) for the self-reciprocal 3-system T of
    translations; one pitch h, since shifting every pitch by -h maps S onto a set of
    mutually reciprocal lines, which is its own reciprocal, so S^perp has pitch -h. A
    4- or 5-system is given its reciprocal's type."""
    for rows, expected in TEXTBOOK.values():
        system = ScrewSystem([[sp.nsimplify(e) for e in r] for r in rows])
        reciprocal = system.reciprocal().classify()
        assert reciprocal.type == f"{6 - system.rank}-{expected}"
        if system.rank == 3:
            assert reciprocal.translations == system.classify().translations
            if expected.startswith("II") and expected != "IID":
                h = system.classify().pitches[0]
                assert set(reciprocal.pitches) - {sp.oo} == {-h}
    schoenflies = ScrewSystem(CASES["Schoenflies motion"][0]).classify()
    assert schoenflies.type == "4-IIC"  # its reciprocal: couples about x and y
    assert ScrewSystem([[1, 0, 0, 0, 0, 0]]).classify().type == "1-IIA"
    assert ScrewSystem([TX]).classify().type == "1-IIB"
    assert ScrewSystem(np.eye(6).tolist()).classify().gibson_hunt == ""
