"""screwkit.contact: contact models, grasp matrix, form and force closure.

Every answer's certificate is checked here with NumPy alone (never by trusting the
library's own ``verify``), and the decision is compared with an independent linear
program written below in another form: the origin lies strictly inside the convex hull
of the wrenches (max t with sum lambda_i w_i = 0, sum lambda_i = 1, lambda_i >= t)."""

import numpy as np
import pytest
from scipy.optimize import linprog

import screwkit as sk
from screwkit.contact import Contact, force_closure, form_closure, grasp_matrix

#: Relative balance and separation tolerances of a certificate (as CLOSURE_TOL).
TOL = 1e-7


def independent_closed(W):
    """Closure by the hull formulation: rank full and the origin strictly inside."""
    d, k = W.shape
    Wn = W / np.linalg.norm(W, axis=0)  # directions only: positive spans are unchanged
    if np.linalg.matrix_rank(Wn, tol=1e-9) < d:
        return False
    # variables (lambda_1..k, t): maximise t
    c = np.r_[np.zeros(k), -1.0]
    A_eq = np.vstack([np.c_[Wn, np.zeros(d)], np.r_[np.ones(k), 0.0]])
    b_eq = np.r_[np.zeros(d), 1.0]
    A_ub = np.c_[-np.eye(k), np.ones(k)]  # t - lambda_i <= 0
    res = linprog(
        c,
        A_ub=A_ub,
        b_ub=np.zeros(k),
        A_eq=A_eq,
        b_eq=b_eq,
        bounds=[(None, None)] * (k + 1),
        method="highs-ipm",
    )
    assert res.status == 0
    return -res.fun > 1e-9


def check_certificate(result, contacts):
    """The certificate, checked with matrix products; also what it means for the
    contact points (the open twist moves every contact point off or along its
    finger)."""
    W = result.wrenches
    d = W.shape[0]
    if result.closed:
        k = result.forces
        assert np.all(k > 0)
        assert np.linalg.norm(W @ k) <= TOL * np.linalg.norm(W) * np.linalg.norm(k)
        Wn = W / np.linalg.norm(W, axis=0)
        assert result.rank == d == np.linalg.matrix_rank(Wn, tol=1e-9)
    else:
        y = result.wrench
        assert np.linalg.norm(y) > 0.5
        floor = -TOL * np.linalg.norm(W, axis=0) * np.linalg.norm(y)
        assert np.all(y @ W >= floor)
        # the twist Pi y: each contact point's velocity has v . n >= 0 (frictionless)
        V = result.twist
        for c in contacts:
            if d == 3:
                omega, v = V[0], V[1:]
                vel = v + omega * np.array([-c.point[1], c.point[0]])
            else:
                vel = V[3:] + np.cross(V[:3], c.point)
            if c.kind == "frictionless":
                assert vel @ c.normal >= -TOL * max(1.0, np.linalg.norm(c.point))
    assert result.verify()


def random_contacts(rng, count, planar, kind="frictionless", spread=0.7):
    dim = 2 if planar else 3
    P = rng.normal(size=(count, dim))
    P /= np.linalg.norm(P, axis=1)[:, None]
    N = -P + rng.normal(0, spread, (count, dim))
    options = {}
    if kind == "friction":
        options = {"mu": float(rng.uniform(0.1, 0.8))}
    if kind == "soft_finger":
        options = {"mu": float(rng.uniform(0.1, 0.8)), "torsion": 0.05}
    return [Contact(p, n, kind, **options) for p, n in zip(P, N)]


@pytest.mark.parametrize("planar", [True, False], ids=["planar", "spatial"])
def test_form_closure_agrees_with_an_independent_lp(planar):
    rng = np.random.default_rng(0 if planar else 1)
    outcomes = []
    for trial in range(150):
        count = rng.integers(4, 7) if planar else rng.integers(7, 13)
        contacts = random_contacts(rng, count, planar)
        r = form_closure(contacts)
        check_certificate(r, contacts)
        assert r.closed == independent_closed(r.wrenches), trial
        outcomes.append(r.closed)
    assert 15 < sum(outcomes) < len(outcomes) - 15  # both answers tested


@pytest.mark.parametrize(
    "planar, kind",
    [(True, "friction"), (False, "friction"), (False, "soft_finger")],
)
def test_force_closure_agrees_with_an_independent_lp(planar, kind):
    rng = np.random.default_rng(2)
    outcomes = []
    for trial in range(80):
        count = rng.integers(2, 4) if planar else rng.integers(3, 5)
        spread = 0.7 if planar else 0.3
        contacts = random_contacts(rng, count, planar, kind, spread)
        r = force_closure(contacts, facets=6)
        check_certificate(r, contacts)
        assert r.closed == independent_closed(r.wrenches), trial
        outcomes.append(r.closed)
    assert 10 < sum(outcomes) < len(outcomes) - 10


def test_too_few_frictionless_contacts_never_close():
    """3 in the plane and 6 in space cannot positively span R^3 / R^6 (one more than
    the dimension is needed), whatever their placement."""
    rng = np.random.default_rng(3)
    for planar, count in ((True, 3), (False, 6)):
        for _ in range(150):
            contacts = random_contacts(rng, count, planar, spread=1.5)
            r = form_closure(contacts)
            assert not r.closed
            check_certificate(r, contacts)


# ---- textbook cases -----------------------------------------------------------------


def square(pinwheel):
    """Four frictionless fingers on the square [-1, 1]^2: at the sides' middles, or
    shifted along the sides as a pinwheel (left up, right down, bottom right, top
    left). Moments (p x n): left -a, right b, bottom c, top -d; balance needs k1 = k2,
    k3 = k4 and k1 (b - a) + k3 (c - d) = 0: possible with k > 0 for the pinwheel
    (b - a = -1, c - d = 1), not for the middles (the square turns)."""
    s = 0.5 if pinwheel else 0.0
    return [
        Contact([-1, s], [1, 0]),
        Contact([1, -s], [-1, 0]),
        Contact([s, -1], [0, 1]),
        Contact([-s, 1], [0, -1]),
    ]


def test_a_square_held_by_four_fingers():
    closed = form_closure(square(True))
    assert closed.closed and closed.rank == 3
    check_certificate(closed, square(True))
    np.testing.assert_allclose(closed.forces, [1, 1, 1, 1], atol=1e-9)  # symmetric
    open_ = form_closure(square(False))
    assert not open_.closed and open_.rank == 2
    np.testing.assert_allclose(np.abs(open_.twist), [1, 0, 0], atol=1e-12)  # turning


@pytest.mark.parametrize("beta_deg, closed", [(30, True), (40, False)])
def test_two_fingers_with_friction_on_a_disc(beta_deg, closed):
    """Nguyen: two frictional fingers force-close iff the line joining them lies
    inside both friction cones. Fingers at (-1, 0) and at angle beta on the unit disc:
    the line makes beta / 2 with each normal; mu = 0.3 gives a cone half-angle of
    16.7 degrees."""
    beta = np.radians(beta_deg)
    p2 = np.array([np.cos(beta), np.sin(beta)])
    contacts = [
        Contact([-1.0, 0.0], [1.0, 0.0], "friction", mu=0.3),
        Contact(p2, -p2, "friction", mu=0.3),
    ]
    r = force_closure(contacts)
    assert r.closed is closed
    check_certificate(r, contacts)


def test_two_spatial_fingers_need_soft_contact():
    """Two antipodal point contacts with friction leave the turn about the line
    joining them; soft fingers resist it with their torsion."""
    hard = [
        Contact([0, 0, 1], [0, 0, -1], "friction", mu=0.5),
        Contact([0, 0, -1], [0, 0, 1], "friction", mu=0.5),
    ]
    r = force_closure(hard)
    assert not r.closed and r.rank == 5
    check_certificate(r, hard)
    np.testing.assert_allclose(np.abs(r.twist), [0, 0, 1, 0, 0, 0], atol=1e-12)
    soft = [
        Contact(c.point, c.normal, "soft_finger", mu=0.5, torsion=0.01) for c in hard
    ]
    r = force_closure(soft)
    assert r.closed
    check_certificate(r, soft)


def cube(pinwheel):
    """Fingers on the cube [-1, 1]^3: the 6 face centres, or 12 (two per face, shifted
    as a pinwheel so that each face pair resists turns about the other axes)."""
    contacts = []
    for axis in range(3):
        for sign in (1.0, -1.0):
            n = np.zeros(3)
            n[axis] = -sign
            p = -n.copy()
            if not pinwheel:
                contacts.append(Contact(p, n))
                continue
            for shift_axis in ((axis + 1) % 3, (axis + 2) % 3):
                q = p.copy()
                q[shift_axis] = 0.5 * sign
                contacts.append(Contact(q, n))
    return contacts


def test_a_cube():
    closed = form_closure(cube(True))
    assert closed.closed
    check_certificate(closed, cube(True))
    r = form_closure(cube(False))
    assert not r.closed and r.rank == 3
    check_certificate(r, cube(False))


def test_the_same_answers_in_millimetres():
    rng = np.random.default_rng(4)
    for planar in (True, False):
        for _ in range(25):
            count = 5 if planar else 9
            contacts = random_contacts(rng, count, planar)
            mm = [Contact(c.point * 1000, c.normal) for c in contacts]
            r, r_mm = form_closure(contacts), form_closure(mm)
            assert r.closed == r_mm.closed
            check_certificate(r_mm, mm)
            if r.closed:
                np.testing.assert_allclose(r.forces, r_mm.forces, atol=1e-6)


# ---- grasp matrix -------------------------------------------------------------------


def test_grasp_matrix_sums_the_contact_forces():
    """G c is the body's wrench: the sum of each contact's force and its moment."""
    rng = np.random.default_rng(5)
    contacts = random_contacts(rng, 3, False, "soft_finger")
    G = grasp_matrix(contacts)
    assert G.shape == (6, 12)
    c = rng.normal(size=12)
    total = np.zeros(6)
    for i, contact in enumerate(contacts):
        n = contact.normal
        a = np.cross(n, [1.0, 0, 0]) if abs(n[0]) < 0.9 else np.cross(n, [0, 1.0, 0])
        part = G[:, 4 * i : 4 * i + 4]
        # the columns: the normal force, two tangent forces at p, a couple about n
        np.testing.assert_allclose(part[:3, 0], n, atol=1e-12)
        assert abs(part[:3, 1] @ n) < 1e-12 and abs(part[:3, 2] @ n) < 1e-12
        np.testing.assert_allclose(part[:, 3], np.r_[0, 0, 0, n], atol=1e-12)
        f = part[:3, :3] @ c[4 * i : 4 * i + 3]
        total += np.r_[f, np.cross(contact.point, f) + c[4 * i + 3] * n]
        assert np.linalg.norm(a) > 0
    np.testing.assert_allclose(G @ c, total, atol=1e-12)
    # in another frame: each column moved by the direct formula
    T = sk.homogeneous(sk.rotz(0.4) @ sk.rotx(0.3), [0.2, -0.1, 0.5])
    R, p = T[:3, :3], T[:3, 3]
    moved = grasp_matrix(contacts, frame=T)
    np.testing.assert_allclose(moved[:3], R.T @ G[:3], atol=1e-12)
    np.testing.assert_allclose(
        moved[3:], R.T @ (G[3:] - np.cross(p, G[:3], axis=0)), atol=1e-12
    )


def test_planar_grasp_matrix_in_a_frame():
    contacts = [
        Contact([1.0, 2.0], [0, -1], "friction", mu=0.4),
        Contact([0, 0], [1, 0]),
    ]
    T = np.array([[0.0, -1.0, 1.0], [1.0, 0.0, 2.0], [0.0, 0.0, 1.0]])  # at (1, 2)
    G = grasp_matrix(contacts, frame=T)
    # the first contact sits at the frame's origin: no moments from it
    np.testing.assert_allclose(G[2, :2], [0, 0], atol=1e-12)
    # the normal force (0, -1) in axes turned by 90 degrees: (-1, 0)
    np.testing.assert_allclose(G[:2, 0], [-1, 0], atol=1e-12)


# ---- the exact Coulomb cone (cone='exact') -------------------------------------------


def exact_cone_separates(y, contacts):
    """The separating wrench y checked against the exact circular cones, without any
    pyramid: y . w >= 0 for every w in contact i's cone iff g = y_f + y_m x p has
    n . g >= mu |g_t| (+ torsion |y_m . n| for a soft finger), the dual cone's test."""
    y_f, y_m = y[:3], y[3:]
    for c in contacts:
        g = y_f + np.cross(y_m, c.point)
        g_n = g @ c.normal
        g_t = np.linalg.norm(g - g_n * c.normal)
        need = (c.mu or 0.0) * g_t
        if c.kind == "soft_finger":
            need += c.torsion * abs(y_m @ c.normal)
        assert g_n >= need - TOL * np.linalg.norm(y) * (1 + np.linalg.norm(c.point))


def in_exact_cones(W, owner, contacts):
    """Every generator of a closed answer lies in its contact's exact cone."""
    for w, i in zip(W.T, owner):
        c, f = contacts[i], w[:3]
        f_n = f @ c.normal
        assert np.linalg.norm(f - f_n * c.normal) <= (c.mu or 0.0) * f_n * (1 + 1e-12)


def soft_pair(beta_deg, mu, tilt_deg=22.5):
    """Two soft fingers on the unit sphere: at (-1, 0, 0) and at the angle beta from
    the point opposite it, in the plane through the x axis tilted by ``tilt`` from
    z = 0, both pushing towards the centre. The chord between them makes beta / 2 with
    each normal (the base angle of the isosceles triangle centre-p1-p2). The tilt of
    22.5 deg puts the chord midway between two edges of the first contact's 8-facet
    pyramid (its edges lie at multiples of 45 deg from the z axis about x)."""
    b, t = np.radians(beta_deg), np.radians(tilt_deg)
    p2 = np.array([np.cos(b), np.sin(b) * np.cos(t), np.sin(b) * np.sin(t)])
    return [
        Contact([-1, 0, 0], [1, 0, 0], "soft_finger", mu=mu, torsion=0.05),
        Contact(p2, -p2, "soft_finger", mu=mu, torsion=0.05),
    ]


@pytest.mark.parametrize("mu, closed", [(0.37, True), (0.36, False)])
def test_exact_cone_meets_the_two_soft_finger_criterion(mu, closed):
    """Murray, Li and Sastry (ch. 5): two soft fingers force-close a body iff the line
    joining the contacts lies strictly inside both friction cones. At beta = 40 deg the
    line makes 20 deg with each normal: closed iff mu > tan 20 deg = 0.3640. The
    8-facet inscribed pyramid narrows the cone by up to cos(pi / 8) and misses the
    closed grasp; the exact cone does not."""
    contacts = soft_pair(40.0, mu)
    r = force_closure(contacts, facets=8, cone="exact")
    assert r.closed is closed
    check_certificate(r, contacts)
    if closed:
        assert not force_closure(contacts, facets=8).closed  # the pyramid's miss
    else:
        exact_cone_separates(r.wrench, contacts)


def test_pyramids_converge_to_the_exact_cone():
    """As the facets double, the inscribed pyramid's answer reaches the exact cone's
    from below (closed at some k, and for every larger k), on the soft pair just above
    the threshold."""
    contacts = soft_pair(40.0, 0.37)
    answers = [force_closure(contacts, facets=k).closed for k in (4, 8, 16, 32, 64)]
    first = answers.index(True)
    assert not answers[0] and all(answers[first:])


def test_exact_cone_on_random_spatial_grasps():
    """Closed answers: every generator lies in the exact cone and balances; open
    answers: the separating wrench satisfies the exact dual-cone test. Whenever the
    8-facet pyramid closes, so does the exact cone (it contains the pyramid)."""
    rng = np.random.default_rng(7)
    outcomes = []
    for trial in range(40):
        kind = ("friction", "soft_finger")[trial % 2]
        contacts = random_contacts(rng, rng.integers(3, 5), False, kind, 0.3)
        r = force_closure(contacts, facets=8, cone="exact")
        check_certificate(r, contacts)
        if r.closed:
            each = r.wrenches.shape[1] // len(contacts)  # one kind a trial
            owner = np.repeat(np.arange(len(contacts)), each)
            in_exact_cones(r.wrenches, owner, contacts)
        else:
            exact_cone_separates(r.wrench, contacts)
            assert not force_closure(contacts, facets=8).closed
        outcomes.append(r.closed)
    assert 5 < sum(outcomes) < len(outcomes) - 5


def test_exact_cone_refuses_a_bad_option():
    contacts = soft_pair(40.0, 0.5)
    with pytest.raises(ValueError, match="cone must be one of"):
        force_closure(contacts, cone="circle")
    with pytest.raises(ValueError, match="max_facets"):
        force_closure(contacts, cone="exact", max_facets=2)
