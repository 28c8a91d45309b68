"""Contact and grasping: contact wrenches, the grasp matrix, form and force closure.

A contact touches a rigid body at a point p with the unit normal n pointing **into the
body**: the contact can push along n, never pull. Its model says which wrenches it can
apply (its wrench cone, a screw system with signs):

* ``'frictionless'``: the force k n, k >= 0 (one line wrench);
* ``'friction'`` (a point with Coulomb friction mu): any force in the cone
  ``|f_t| <= mu f_n``, spanned in the plane by its two edges n +- mu t, in space
  inside by ``facets`` edges (a pyramid inscribed in the circular cone);
* ``'soft_finger'`` (space only): a force in the friction cone and a moment about the
  normal up to ``torsion`` times the normal force.

Wrenches are in the book's order (f; m), moments about the origin of the contacts'
frame; in the plane (2-vectors) a wrench is (f_x, f_y; m_z) and a twist
(omega; v_x, v_y). A twist V and a wrench w do the power V^T Pi w (Pi swaps force and
moment), so a twist with V^T Pi w_i >= 0 for every contact wrench w_i moves every
contact point away from its finger or along it: the contacts allow it.

**First-order form closure** (frictionless contacts, or the normals alone): the contact
wrenches positively span the wrench space, R^3 in the plane, R^6 in space, so that any
external wrench is resisted; it needs at least 4 contacts in the plane and 7 in space.
**Force closure**: the same for the contacts' wrench cones. Both are decided by one
linear program (SciPy's HiGHS) and come with a certificate anyone can check with a
matrix product: for a closed set, strictly positive contact force coefficients k with
W k = 0 and the rank of W; for an open one, a wrench y with w_i . y >= 0 for every
generator w_i (so no contact forces can resist the external wrench y) and the twist
Pi y every contact allows.

>>> import numpy as np, screwkit as sk
>>> square = [  # a pinwheel of four fingers on the square [-1, 1]^2
...     Contact([-1, 0.5], [1, 0]), Contact([1, -0.5], [-1, 0]),
...     Contact([0.5, -1], [0, 1]), Contact([-0.5, 1], [0, -1])]
>>> form_closure(square).closed
True
"""

from dataclasses import dataclass, field

import numpy as np
from scipy.optimize import linprog

from ._checks import as_float_array, check_integer, check_option, describe
from .tolerances import (
    CLOSURE_TOL,
    CONTACT_RANK_TOL,
    ROTATION_TOL,
    ZERO_TOL,
    length_scale,
)

__all__ = [
    "KINDS",
    "Contact",
    "Closure",
    "contact_wrenches",
    "grasp_matrix",
    "form_closure",
    "force_closure",
]

#: The contact models.
KINDS = ("frictionless", "friction", "soft_finger")


@dataclass(frozen=True)
class Contact:
    """A contact on a rigid body: a point, the normal into the body, a model.

    Parameters
    ----------
    point : array-like, shape (2,) or (3,)
        Where the contact touches (m): 2-vectors for a planar contact, 3-vectors for a
        spatial one.
    normal : array-like, shape (2,) or (3,)
        The normal pointing into the body (any nonzero length; stored as a unit
        vector).
    kind : {'frictionless', 'friction', 'soft_finger'}, optional
        The contact model.
    mu : float, optional
        The friction coefficient (>= 0), needed for 'friction' and 'soft_finger'.
    torsion : float, optional
        A soft finger's torsional coefficient (m, >= 0): its moment about the normal is
        at most torsion times its normal force.

    Examples
    --------
    >>> import screwkit as sk
    >>> c = sk.contact.Contact([0.0, 1.0], [0.0, -2.0], kind="friction", mu=0.5)
    >>> c.normal.tolist(), c.planar
    ([0.0, -1.0], True)
    """

    point: np.ndarray
    normal: np.ndarray
    kind: str = "frictionless"
    mu: float | None = None
    torsion: float | None = None
    planar: bool = field(init=False)

    def __post_init__(self):
        point = as_float_array(self.point, "point")
        if point.shape not in ((2,), (3,)):
            raise ValueError(
                f"point must be a 2-vector (planar) or a 3-vector (spatial) (m), got "
                f"shape {point.shape}"
            )
        normal = as_float_array(self.normal, "normal")
        if normal.shape != point.shape:
            raise ValueError(
                f"normal must have the shape of point, {point.shape}, got shape "
                f"{normal.shape}"
            )
        length = float(np.linalg.norm(normal))
        if length == 0.0:
            raise ValueError(
                f"normal must be a nonzero vector (into the body), got "
                f"{normal.tolist()}"
            )
        kind = check_option(self.kind, "kind", KINDS)
        mu = self.mu
        if kind == "frictionless":
            if mu is not None:
                mu = _nonnegative(mu, "mu")
        else:
            if mu is None:
                raise ValueError(
                    f"mu must be given for a '{kind}' contact (a friction coefficient "
                    ">= 0), got None"
                )
            mu = _nonnegative(mu, "mu")
        torsion = self.torsion
        if kind == "soft_finger":
            if point.shape == (2,):
                raise ValueError(
                    "kind must be 'frictionless' or 'friction' for a planar contact: a "
                    "soft finger's torsion is about the normal, out of the plane; got "
                    "'soft_finger'"
                )
            if torsion is None:
                raise ValueError(
                    "torsion must be given for a 'soft_finger' contact (m, >= 0), got "
                    "None"
                )
            torsion = _nonnegative(torsion, "torsion")
        elif torsion is not None:
            raise ValueError(
                f"torsion must be None for a '{kind}' contact (only a soft finger has "
                f"one), got {describe(torsion)}"
            )
        object.__setattr__(self, "point", point)
        object.__setattr__(self, "normal", normal / length)
        object.__setattr__(self, "kind", kind)
        object.__setattr__(self, "mu", mu)
        object.__setattr__(self, "torsion", torsion)
        object.__setattr__(self, "planar", point.shape == (2,))


def _nonnegative(value, name):
    number = as_float_array(value, name)
    if number.shape != ():
        raise TypeError(f"{name} must be one number, got {describe(value)}")
    if number < 0:
        raise ValueError(f"{name} must be a number >= 0, got {float(number)!r}")
    return float(number)


def _tangents(n):
    """Two unit tangents (u, v), (u, v, n) right-handed, chosen deterministically."""
    axis = np.zeros(3)
    axis[int(np.argmin(np.abs(n)))] = 1.0
    u = np.cross(n, axis)
    u /= np.linalg.norm(u)
    return u, np.cross(n, u)


def _line(point, force):
    """The wrench (f; m) of a force through a point: planar (f_x, f_y, m_z) or
    spatial."""
    if len(point) == 2:
        return np.array([force[0], force[1], point[0] * force[1] - point[1] * force[0]])
    return np.concatenate([force, np.cross(point, force)])


def _generators(contact, facets, widen=1.0):
    """The columns whose nonnegative combinations are the contact's wrench cone
    (``widen`` times mu: 1 for the inscribed pyramid, 1 / cos(pi / facets) for the
    circumscribed one)."""
    p, n = contact.point, contact.normal
    if contact.kind == "frictionless":
        return [_line(p, n)]
    mu = contact.mu * (widen if not contact.planar else 1.0)
    if contact.planar:
        t = np.array([-n[1], n[0]])
        return [_line(p, n + mu * t), _line(p, n - mu * t)]
    u, v = _tangents(n)
    angles = 2 * np.pi * np.arange(facets) / facets
    edges = [n + mu * (np.cos(a) * u + np.sin(a) * v) for a in angles]
    lines = [_line(p, e) for e in edges]
    if contact.kind == "friction":
        return lines
    couple = np.concatenate([np.zeros(3), contact.torsion * n])
    return [w + s * couple for w in lines for s in (1.0, -1.0)]


def _basis(contact):
    """The columns spanning the contact's wrench system (for the grasp matrix)."""
    p, n = contact.point, contact.normal
    if contact.kind == "frictionless":
        return [_line(p, n)]
    if contact.planar:
        return [_line(p, n), _line(p, np.array([-n[1], n[0]]))]
    u, v = _tangents(n)
    columns = [_line(p, n), _line(p, u), _line(p, v)]
    if contact.kind == "soft_finger":
        columns.append(np.concatenate([np.zeros(3), n]))
    return columns


def _check_contacts(contacts):
    if isinstance(contacts, Contact) or not isinstance(contacts, (list, tuple)):
        raise TypeError(f"contacts must be a list of Contact, got {describe(contacts)}")
    for i, c in enumerate(contacts):
        if not isinstance(c, Contact):
            raise TypeError(f"contacts[{i}] must be a Contact, got {describe(c)}")
    if len(contacts) < 2:
        raise ValueError(
            f"contacts must hold at least 2 contacts (one never holds a body), got "
            f"{len(contacts)}"
        )
    planar = {c.planar for c in contacts}
    if len(planar) > 1:
        raise ValueError(
            "contacts must be all planar (2-vectors) or all spatial (3-vectors), got "
            "both"
        )
    return contacts[0].planar


def _move(W, frame, planar):
    """Columns of W (wrenches about the origin) written in the frame whose pose is
    ``frame``."""
    if frame is None:
        return W
    T = as_float_array(frame, "frame")
    size = 3 if planar else 4
    if T.shape != (size, size):
        raise ValueError(
            f"frame must be a pose ({size}, {size}) for "
            f"{'planar' if planar else 'spatial'} contacts, got shape {T.shape}"
        )
    R, p = T[: size - 1, : size - 1], T[: size - 1, size - 1]
    if (
        not np.allclose(R.T @ R, np.eye(size - 1), atol=ROTATION_TOL)
        or np.linalg.det(R) < 0
    ):
        raise ValueError("frame must hold a rotation (orthonormal, det 1), got another")
    if planar:
        f = W[:2]
        m = W[2] - (p[0] * f[1] - p[1] * f[0])
        return np.vstack([R.T @ f, m])
    f, m = W[:3], W[3:]
    return np.vstack([R.T @ f, R.T @ (m - np.cross(p, f, axis=0))])


def _pyramid(contacts, facets, widen=1.0):
    return np.array(
        [g for c in contacts for g in _generators(c, facets, widen)], dtype=float
    ).T


def contact_wrenches(contacts, facets=8, frictionless=False):
    """The generators of the contacts' wrench cones, one column each.

    Parameters
    ----------
    contacts : list of Contact
        At least 2, all planar or all spatial.
    facets : int, optional
        Edges of each spatial friction cone's inscribed pyramid (>= 3).
    frictionless : bool, optional
        Only the normals (the wrenches of form closure).

    Returns
    -------
    W : ndarray, shape (3, k) or (6, k)
        The generators (f; m) (N per unit coefficient, N m), moments about the origin.
    owner : ndarray, shape (k,)
        The contact each column belongs to.

    Examples
    --------
    >>> import screwkit as sk
    >>> cs = [sk.contact.Contact([1, 0], [-1, 0]), sk.contact.Contact([-1, 0], [1, 0])]
    >>> W, owner = sk.contact.contact_wrenches(cs)
    >>> (W + 0.0).tolist()  # (f_x, f_y, m_z) per column
    [[-1.0, 1.0], [0.0, 0.0], [0.0, 0.0]]
    """
    _check_contacts(contacts)
    facets = check_integer(facets, "facets", minimum=3)
    columns, owner = [], []
    for i, c in enumerate(contacts):
        gens = [_line(c.point, c.normal)] if frictionless else _generators(c, facets)
        columns += gens
        owner += [i] * len(gens)
    return np.array(columns).T, np.array(owner)


def grasp_matrix(contacts, frame=None):
    """The grasp matrix G: the body's wrench from the contacts' force components.

    Column block i spans contact i's wrench system (its cone without the signs): the
    normal force n; with friction also the tangential forces (t in the plane; u, v in
    space); a soft finger also the moment about n. The body receives w = G c for the
    contact components c.

    Parameters
    ----------
    contacts : list of Contact
        At least 2, all planar or all spatial.
    frame : array-like, shape (3, 3) or (4, 4), optional
        The pose of the body's frame in the contacts' coordinates: G is written in it
        (moments about its origin). Default: the contacts' own frame.

    Returns
    -------
    ndarray, shape (3, k) or (6, k)
        G, wrenches (f; m) per unit component (N m per N for the moment rows).

    Examples
    --------
    >>> import screwkit as sk
    >>> cs = [sk.contact.Contact([1, 0], [-1, 0], "friction", mu=0.5),
    ...       sk.contact.Contact([-1, 0], [1, 0], "friction", mu=0.5)]
    >>> (sk.contact.grasp_matrix(cs) + 0.0).tolist()  # columns n1, t1, n2, t2
    [[-1.0, 0.0, 1.0, 0.0], [0.0, -1.0, 0.0, 1.0], [0.0, -1.0, 0.0, -1.0]]
    """
    planar = _check_contacts(contacts)
    G = np.array([col for c in contacts for col in _basis(c)]).T
    return _move(G, frame, planar)


@dataclass(frozen=True)
class Closure:
    """The answer of ``form_closure`` or ``force_closure``, with its certificate.

    Parameters
    ----------
    closed : bool
        Whether the contacts resist every external wrench.
    rank : int
        The rank of ``wrenches`` (3 or 6 needed).
    wrenches : ndarray, shape (d, k)
        The generators w_i of the contacts' wrench cones (d = 3 planar, 6 spatial).
    forces : ndarray, shape (k,) or None
        Closed: strictly positive coefficients with ``wrenches @ forces`` = 0 (the
        contacts squeeze the body in balance).
    wrench : ndarray, shape (d,) or None
        Open: a wrench y with w_i . y >= 0 for every generator: no nonnegative contact
        forces balance the external wrench y.
    twist : ndarray, shape (d,) or None
        Open: Pi y, a twist every contact allows (power V^T Pi w_i >= 0: each contact
        separates or slides).

    Examples
    --------
    Two opposite fingers with friction pinch a body: closed, with strictly positive
    forces on the four edges of the two friction cones.

    >>> pinch = [Contact([1, 0], [-1, 0], "friction", mu=0.3),
    ...          Contact([-1, 0], [1, 0], "friction", mu=0.3)]
    >>> result = force_closure(pinch)
    >>> result.closed, result.rank, bool((result.forces > 0).all())
    (True, 3, True)
    """

    closed: bool
    rank: int
    wrenches: np.ndarray
    forces: np.ndarray | None = None
    wrench: np.ndarray | None = None
    twist: np.ndarray | None = None

    def verify(self):
        """Check the certificate with matrix products alone (no solver).

        Returns
        -------
        bool
            True when the certificate proves the answer (closed: positive forces
            that balance; open: a wrench that no contact force resists).

        Examples
        --------
        >>> pinch = [Contact([1, 0], [-1, 0], "friction", mu=0.3),
        ...          Contact([-1, 0], [1, 0], "friction", mu=0.3)]
        >>> force_closure(pinch).verify()
        True
        """
        W = self.wrenches
        d = W.shape[0]
        if self.closed:
            k = self.forces
            residual = np.linalg.norm(W @ k)
            bound = CLOSURE_TOL * np.linalg.norm(W) * np.linalg.norm(k)
            return bool(np.all(k > 0) and residual <= bound and self.rank == d)
        y = self.wrench
        if y is None or np.linalg.norm(y) == 0:
            return False
        powers = y @ W
        floor = -CLOSURE_TOL * np.linalg.norm(W, axis=0) * np.linalg.norm(y)
        twist_ok = np.allclose(self.twist, _swap(y), rtol=0, atol=0)
        return bool(np.all(powers >= floor) and twist_ok)


def _swap(y):
    """Pi y: a wrench's force and moment parts swapped (the twist it pairs with)."""
    if len(y) == 3:
        return np.array([y[2], y[0], y[1]])
    return np.concatenate([y[3:], y[:3]])


def _closure(contacts, W):
    """Decide whether the columns of W positively span their space, with a
    certificate."""
    d, k = W.shape
    points = np.array([c.point for c in contacts])
    scale = length_scale(points)
    D = np.ones(d)
    D[2 if d == 3 else 3 :] = 1.0 / scale  # moments per unit size
    Ws = D[:, None] * W
    U, sigma, _ = np.linalg.svd(Ws)
    rank = int(np.sum(sigma > CONTACT_RANK_TOL * sigma[0]))
    if rank < d:
        y = D * U[:, -1]  # y . w_i = 0 for every generator: free both ways
        y /= np.linalg.norm(y)
        return Closure(False, rank, W, wrench=y, twist=_swap(y))
    balance = linprog(
        np.ones(k), A_eq=Ws, b_eq=np.zeros(d), bounds=[(1.0, None)] * k, method="highs"
    )
    if balance.status == 0:
        forces = balance.x / balance.x.max()
        return Closure(True, rank, W, forces=forces)
    # Farkas: max sum_i w_i . y subject to w_i . y >= 0 and |y_j| <= 1
    separate = linprog(
        -Ws.sum(axis=1),
        A_ub=-Ws.T,
        b_ub=np.zeros(k),
        bounds=[(-1.0, 1.0)] * d,
        method="highs",
    )
    if separate.status != 0 or -separate.fun <= ZERO_TOL * k:
        raise RuntimeError(
            "the contacts sit on the boundary of closure to round-off: neither a "
            "balance nor a separating wrench was found"
        )
    y = D * separate.x
    y /= np.linalg.norm(y)
    return Closure(False, rank, W, wrench=y, twist=_swap(y))


def form_closure(contacts):
    """First-order form closure: do the contact normals alone resist every wrench?

    Frictionless contacts (the normals of any contact model) hold a body in form
    closure when their wrenches positively span R^3 (plane) or R^6 (space): rank 3 or
    6 and some strictly positive forces in balance. Decided by a linear program
    (HiGHS); the result carries a certificate (see :class:`Closure`).

    Parameters
    ----------
    contacts : list of Contact
        At least 2, all planar or all spatial.

    Returns
    -------
    Closure
        ``closed``, ``rank`` and the certificate; ``verify()`` checks it.

    Examples
    --------
    >>> import screwkit as sk
    >>> C = sk.contact.Contact
    >>> middles = [C([-1, 0], [1, 0]), C([1, 0], [-1, 0]), C([0, -1], [0, 1]),
    ...            C([0, 1], [0, -1])]  # the sides' middles: the square can turn
    >>> r = sk.contact.form_closure(middles)
    >>> r.closed, r.rank, [round(float(x), 12) + 0.0 for x in r.twist]
    (False, 2, [1.0, 0.0, 0.0])
    """
    W, _ = contact_wrenches(contacts, frictionless=True)
    return _closure(contacts, W)


def force_closure(contacts, facets=8, cone="pyramid", max_facets=4096):
    """Force closure: do the contacts' wrench cones (friction included) resist every
    wrench?

    The generators of every contact's cone (frictionless: its normal; friction: its
    cone's edges, exact in the plane and ``facets`` edges of an inscribed pyramid in
    space; soft finger: those with plus and minus the torsional moment) must positively
    span the wrench space. With the inscribed pyramid a closed answer is also closed
    for the exact cone; an open one may close with more facets.

    With ``cone='exact'`` the answer is the exact circular Coulomb cone's (a
    second-order cone problem), decided by two linear programs that bracket it: the
    inscribed pyramid closed proves the cone closed (its edges lie in the cone), the
    circumscribed pyramid (edges at mu / cos(pi / k)) open proves it open (its
    separating wrench y separates the cone it contains: for every contact
    ``n . g >= mu |g_t|`` with ``g = y_f + y_m x p``, plus ``torsion |y_m . n|``
    for a soft finger); otherwise the facets double, up to ``max_facets``.

    Parameters
    ----------
    contacts : list of Contact
        At least 2, all planar or all spatial.
    facets : int, optional
        Edges of each spatial friction cone's pyramid (>= 3); with ``cone='exact'``
        the first pyramid tried.
    cone : {'pyramid', 'exact'}, optional
        The inscribed pyramid (default) or the exact circular cone.
    max_facets : int, optional
        With ``cone='exact'``, the most facets tried before the contacts are declared
        on the boundary of closure (RuntimeError).

    Returns
    -------
    Closure
        ``closed`` (for the cones' pyramids in space), ``rank`` and the certificate;
        ``verify()`` checks it.

    Examples
    --------
    >>> import screwkit as sk
    >>> C = sk.contact.Contact
    >>> pinch = [C([1, 0], [-1, 0], "friction", mu=0.3),
    ...          C([-1, 0], [1, 0], "friction", mu=0.3)]
    >>> sk.contact.force_closure(pinch).closed  # two opposite fingers with friction
    True
    """
    cone = check_option(cone, "cone", ("pyramid", "exact"))
    W, _ = contact_wrenches(contacts, facets=facets)
    if cone == "pyramid":
        return _closure(contacts, W)
    max_facets = check_integer(max_facets, "max_facets", minimum=3)
    if contacts[0].planar or all(c.kind == "frictionless" for c in contacts):
        return _closure(contacts, W)  # the planar cone's two edges are exact
    k = check_integer(facets, "facets", minimum=3)
    while True:
        inner = _closure(contacts, _pyramid(contacts, k))
        if inner.closed:
            return inner
        outer = _closure(contacts, _pyramid(contacts, k, 1.0 / np.cos(np.pi / k)))
        if not outer.closed:
            return outer
        if 2 * k > max_facets:
            raise RuntimeError(
                f"the contacts sit on the boundary of force closure: the inscribed "
                f"pyramid of {k} facets is open and the circumscribed one closed; "
                f"raise max_facets (got {max_facets}) or move a contact"
            )
        k *= 2
