"""The catalogue of mechanisms and robots used in the course.

Parallel manipulators are returned in the mobility paper's zeroth-step format: a list of
limbs, each a list of (s, r, h) joint screws in the fixed frame, with the paper's
symbols for lengths (a, b, L, R, ...), actuated displacements d_i and joint angles
theta_ij: each ``pm_*`` builder (and ``planar_3rrr``, ``spherical_3rrr``) returns its
limbs so, exact. Serial arms are :class:`~screwkit.chains.Chain` objects (SI units).
"""

import numpy as np
import sympy as sp

from ._checks import as_float_array, as_real_scalar, describe
from ._docstrings import fill
from .chains import Chain, Convention, Link
from .limbs import parallelogram, prismatic, revolute, rotate_limb, spherical, universal
from .parallel import delta, planar_3rpr, stewart_gough, tripteron
from .parallel import planar_3rrr as parallel_3rrr
from .transforms import rot_axis, rotx, roty, rotz, transl

__all__ = [
    "puma560",
    "kawasaki_cx210l",
    "planar",
    "two_arm_planar",
    "pm_3prrr",
    "pm_3prpar",
    "pm_4prru",
    "pm_6ups",
    "planar_3rrr",
    "pm_3rps",
    "pm_3ruu",
    "spherical_3rrr",
    "PAPER_GRUBLER_KUTZBACH",
    "DRAWING_VALUES",
]
__all__ += [
    "stewart_gough",
    "planar_3rpr",
    "parallel_3rrr",
    "delta",
    "tripteron",
]  # sk.parallel

X, Y, Z, O = (
    sp.Matrix([1, 0, 0]),
    sp.Matrix([0, 1, 0]),
    sp.Matrix([0, 0, 1]),
    sp.zeros(3, 1),
)

#: The paper's Grübler–Kutzbach inputs (links with base and platform, joints, freedoms)
#: and counts.
PAPER_GRUBLER_KUTZBACH = {
    "3-PRRR": {"links": 11, "joints": 12, "freedoms": 12, "mobility": 0},
    "3-PR(Pa)R": {"links": 17, "joints": 21, "freedoms": 21, "mobility": -9},
    "4-PRRU": {"links": 14, "joints": 16, "freedoms": 20, "mobility": 2},
    "6-UPS": {"links": 14, "joints": 18, "freedoms": 36, "mobility": 6},
}


#: Numbers (m, rad) for every symbol of each parallel mechanism, for
#: sk.plotting.draw_mechanism. Every limb gets the same values, so the symmetric limbs
#: end on a regular polygon: the drawn platform is rigid. Keys are the builders' names.
DRAWING_VALUES = {
    "pm_3prrr": {
        "a": 0.45,
        "b": 0.45,
        "L_y": 1.0,
        "L_z": 1.0,
        "d_1": 0.4,
        "d_2": 0.4,
        "d_3": 0.4,
        **{f"theta_{i}{j}": v for i in (1, 2, 3) for j, v in ((2, 0.6), (3, -0.5))},
    },
    "pm_3prpar": {
        "L": 0.7,
        "b": 0.25,
        "d_1": 0.8,
        "d_2": 0.8,
        "d_3": 0.8,
        **{f"theta_{i}{j}": v for i in (1, 2, 3) for j, v in ((2, 0.9), (3, 0.6))},
    },
    "pm_4prru": {
        "R": 1.0,
        "a": 0.35,
        "b": 0.35,
        "alpha": 0.3,
        **{f"d_{i}": 0.3 for i in (1, 2, 3, 4)},
        **{f"theta_{i}{j}": v for i in (1, 2, 3, 4) for j, v in ((2, 2.3), (3, 2.8))},
    },
    "pm_6ups": {
        "R": 1.0,
        **{f"d_{i}": 1.1 for i in range(1, 7)},
        **{f"theta_{i}{j}": v for i in range(1, 7) for j, v in ((1, 0.15), (2, -0.45))},
    },
    "planar_3rrr": {
        "a": 0.6,
        "b": 0.5,
        **{f"theta_{i}{j}": v for i in (1, 2, 3) for j, v in ((1, 2.2), (2, 3.4))},
    },
    "pm_3rps": {
        "R": 1.0,
        **{f"d_{i}": 1.0 for i in (1, 2, 3)},
        **{f"theta_{i}": 0.35 for i in (1, 2, 3)},
    },
    "pm_3ruu": {
        "R": 1.0,
        "a": 0.5,
        "b": 0.8,
        **{
            f"theta_{i}{j}": v
            for i in (1, 2, 3)
            for j, v in ((1, 0.5), (2, 0.3), (3, 2.2))
        },
    },
    "spherical_3rrr": {
        f"theta_{i}{j}": v for i in (1, 2, 3) for j, v in ((1, 0.6), (2, 0.8))
    },
}


#: The Returns sections the mechanisms' limbs and the named arms share (filled in by
#: :func:`_docstrings.fill`); the mechanisms' ends with the heading of their Examples.
_LIMBS_SECTIONS = """Returns
-------
list of limbs
    In the zeroth-step format (module docstring).

Examples
--------"""
_ARM_RETURNS = """Returns
-------
Chain
    The arm, with its named configurations."""


def _symbols(names, limbs, first, last):
    """theta_{i j} for limbs i = 1..limbs and joints j = first..last."""
    return [
        [sp.Symbol(f"theta_{i}{j}") for j in range(first, last + 1)]
        for i in range(1, limbs + 1)
    ]


@fill(sections=_LIMBS_SECTIONS)
def pm_3prrr():
    """Tripteron, 3-PRRR: limb i has four parallel axes along X, Y, Z (paper §3.2.1).

    {sections}

    Three limbs of four joints (P, R, R, R); the platform translates (the paper's
    3T), though Grübler-Kutzbach counts 0:

    >>> from screwkit import mobility
    >>> limbs = pm_3prrr()
    >>> [len(limb) for limb in limbs], mobility(limbs).type
    ([4, 4, 4], '3T')
    >>> PAPER_GRUBLER_KUTZBACH["3-PRRR"]["mobility"]
    0
    """
    a, b, Ly, Lz = sp.symbols("a b L_y L_z")
    d = sp.symbols("d_1:4")
    theta = _symbols("theta", 3, 2, 3)
    axes = [X, Y, Z]

    # the links AB, BC start along Y, Z, X and turn about the limb's axis X, Y, Z
    def link(i, length, angle):
        c, s = length * sp.cos(angle), length * sp.sin(angle)
        return sp.Matrix([[0, c, s], [s, 0, c], [c, s, 0]][i])

    bases = [
        sp.Matrix([d[0], Ly, 0]),
        sp.Matrix([0, d[1], Lz]),
        sp.Matrix([0, 0, d[2]]),
    ]
    limbs = []
    for i in range(3):
        A = bases[i]
        B = A + link(i, a, theta[i][0])
        C = B + link(i, b, theta[i][1])
        s = axes[i]
        limbs.append(prismatic(s, A) + revolute(s, A) + revolute(s, B) + revolute(s, C))
    return limbs


@fill(sections=_LIMBS_SECTIONS)
def pm_3prpar():
    """STAR-like 3-PR(Pa)R: P and R along X, a parallelogram, and a last R along X
    (§3.2.2).

    Limbs 2 and 3 are limb 1 turned about Z by 120 and 240 degrees.

    {sections}

    Each limb: P, R, the four hinges of the parallelogram, R (7 joints).

    >>> [len(limb) for limb in pm_3prpar()]
    [7, 7, 7]
    """
    L, b = sp.symbols("L b")
    d = sp.symbols("d_1:4")
    theta = _symbols("theta", 3, 2, 3)
    limbs = []
    for i in range(3):
        t2, t3 = theta[i]
        turn = _turn_about_z(2 * sp.pi * i / 3)
        x = turn(X)
        # the parallelogram's axes Rx(t2) Y, and its long sides Rx(t2) Ry(t3) (L, 0, 0)
        w = turn([0, sp.cos(t2), sp.sin(t2)])
        side = [
            L * sp.cos(t3),
            L * sp.sin(t2) * sp.sin(t3),
            -L * sp.cos(t2) * sp.sin(t3),
        ]
        A0, A1, A2 = ([d[i] + shift, 0, 0] for shift in (0, -b / 2, b / 2))
        B0, B1, B2 = ([p + q for p, q in zip(A, side)] for A in (A0, A1, A2))
        A0, A1, A2, B0, B1, B2 = map(turn, (A0, A1, A2, B0, B1, B2))
        limbs.append(
            prismatic(x, A0)
            + revolute(x, A0)
            + parallelogram(w, A1, A2, B1, B2)
            + revolute(x, B0)
        )
    return limbs


def _around_z(limb_of, count):
    """The limbs limb_of(0), ..., limb_of(count - 1), limb i turned about Z by
    2 pi i / count (a mechanism with count-fold symmetry)."""
    return [rotate_limb(limb_of(i), rotz(2 * sp.pi * i / count)) for i in range(count)]


def _turn_about_z(angle):
    """v -> Rz(angle) v with expanded entries, written out (no matrix product): a limb
    turned about Z, as rotate_limb(limb, rotz(angle)) gives it."""
    c, s = sp.cos(angle), sp.sin(angle)

    def turn(v):
        x, y, z = v
        return sp.Matrix(
            [sp.expand(c * x - s * y), sp.expand(s * x + c * y), sp.expand(z)]
        )

    return turn


@fill(sections=_LIMBS_SECTIONS)
def pm_4prru():
    """4-PRRU with Schönflies motion (§3.2.3, after Kong and Gosselin).

    P along Z; three R axes parallel to Rx(alpha) Y (the first one at A, tilted by alpha
    so it is not perpendicular to P); a U whose second axis is Z. Limbs are turned by
    90-degree steps about Z. The paper's code places C with the rotation N applied twice
    and never uses theta_i3; here B and C follow theta_i2 and theta_i3 about the tilted
    axis.

    {sections}

    Schönflies motion: three translations and the turn about the vertical.

    >>> from screwkit import mobility
    >>> mobility(pm_4prru()).directions
    ['Tx', 'Ty', 'Tz', 'Rz']
    """
    R, a, b, alpha = sp.symbols("R a b alpha")
    d = sp.symbols("d_1:5")
    theta = _symbols("theta", 4, 2, 3)
    w = (
        rotx(alpha) * Y
    )  # the common direction of the three parallel R axes, (0, cos, sin)

    def turned(length, angle):
        # length * X turned by angle about the unit axis w (Rodrigues, with w . X = 0):
        # cos(angle) X + sin(angle) w x X, written out so no trigonometric
        # simplification runs
        return length * sp.Matrix(
            [sp.cos(angle), sp.sin(angle) * w[2], -sp.sin(angle) * w[1]]
        )

    def limb(i):
        A = sp.Matrix([R, 0, d[i]])
        B = A + turned(a, theta[i][0])
        C = B + turned(b, theta[i][1])
        return prismatic(Z, A) + revolute(w, A) + revolute(w, B) + universal(w, Z, C)

    return _around_z(limb, 4)


@fill(sections=_LIMBS_SECTIONS)
def pm_6ups():
    """6-UPS (Gough–Stewart type): U at A, P along the leg, S at B; limbs turned by 60
    degrees (§3.2.4).

    {sections}

    Six legs of 2 + 1 + 3 joints: the platform moves freely (3T3R).

    >>> from screwkit import mobility
    >>> limbs = pm_6ups()
    >>> [len(limb) for limb in limbs], mobility(limbs).type
    ([6, 6, 6, 6, 6, 6], '3T3R')
    """
    R = sp.Symbol("R")
    d = sp.symbols("d_1:7")
    theta = _symbols("theta", 6, 1, 2)

    def limb(i):
        t1, t2 = theta[i]
        frame = rotx(t1) * roty(t2)  # the leg's frame after the U joint
        A = sp.Matrix([R, 0, 0])
        leg = frame * Z
        B = A + d[i] * leg
        return (
            universal(X, rotx(t1) * Y, A)
            + prismatic(leg, A)
            + spherical(B, axes=[frame * X, frame * Y, frame * Z])
        )

    return _around_z(limb, 6)


@fill(sections=_LIMBS_SECTIONS)
def planar_3rrr():
    """Planar 3-RRR: three RRR limbs with all axes along Z
    (3 motions in the plane: 2T1R).

    {sections}

    >>> from screwkit import mobility
    >>> mobility(planar_3rrr()).directions
    ['Tx', 'Ty', 'Rz']
    """
    a, b = sp.symbols("a b")
    theta = _symbols("theta", 3, 1, 2)

    def limb(i):
        A = sp.Matrix([1, 0, 0])
        B = A + rotz(theta[i][0]) * sp.Matrix([a, 0, 0])
        C = B + rotz(theta[i][1]) * sp.Matrix([b, 0, 0])
        return revolute(Z, A) + revolute(Z, B) + revolute(Z, C)

    return _around_z(limb, 3)


@fill(sections=_LIMBS_SECTIONS)
def pm_3rps():
    """3-RPS: R tangent to the base circle, P along the leg, S on the platform
    (1T2R).

    {sections}

    Each limb: R, P and the three revolutes of the ball joint.

    >>> [len(limb) for limb in pm_3rps()]
    [5, 5, 5]
    """
    R = sp.Symbol("R")
    d = sp.symbols("d_1:4")
    theta = [sp.Symbol(f"theta_{i}") for i in range(1, 4)]

    def limb(i):
        A = sp.Matrix([R, 0, 0])
        leg = rotx(theta[i]) * Z
        return revolute(X, A) + prismatic(leg, A) + spherical(A + d[i] * leg)

    return _around_z(limb, 3)


@fill(sections=_LIMBS_SECTIONS)
def pm_3ruu():
    """Delta-type translational 3-RUU (3T): the kinematic equivalent of Clavel's Delta
    with a U-U link in place of each spatial parallelogram
    (Tsai's translational conditions).

    Limb 1: R about u = Y at A = (R, 0, 0); a U at B (axes u, then v = rotation of Z
    about u by theta_12); a U at C (axes v, then u). Each limb then constrains the one
    couple along u x v. Limbs 2 and 3 are limb 1 turned about Z by 120 and 240 degrees.

    {sections}

    Each limb: R, then two U joints of two revolutes each.

    >>> [len(limb) for limb in pm_3ruu()]
    [5, 5, 5]
    """
    R, a, b = sp.symbols("R a b")

    def limb(i):
        t1, t2, t3 = sp.symbols(f"theta_{i + 1}1:{i + 1}4")
        u, A = Y, sp.Matrix([R, 0, 0])
        B = A + rot_axis(u, t1) * (a * X)
        v = rot_axis(u, t2) * Z
        C = B + rot_axis(v, t3) * (b * u.cross(v))
        return revolute(u, A) + universal(u, v, B) + universal(v, u, C)

    return _around_z(limb, 3)


@fill(sections=_LIMBS_SECTIONS)
def spherical_3rrr():
    """Spherical 3-RRR (agile eye type): every joint axis passes through the origin
    (3R).

    {sections}

    Every axis passes through the origin, so the platform only turns about it:

    >>> from screwkit import mobility
    >>> limbs = spherical_3rrr()
    >>> all(list(r) == [0, 0, 0] for limb in limbs for _, r, _ in limb)
    True
    >>> mobility(limbs).type
    '3R'
    """
    theta = _symbols("theta", 3, 1, 2)

    def limb(i):
        t1, t2 = theta[i]
        s1 = Z
        s2 = rotz(t1) * X
        s3 = rotz(t1) * rot_axis(X, t2) * Y
        return revolute(s1, O) + revolute(s2, O) + revolute(s3, O)

    return _around_z(limb, 3)


@fill(returns=_ARM_RETURNS)
def puma560():
    """The PUMA 560 in standard DH, Corke's parameters (the PUMA paper's Table 2), in
    metres.

    As in the paper there is no pedestal (d1 = 0: frame 0 is on the shoulder axis);
    d3 = 0.15005 m (Table 2 rounds it to 0.15). Joint limits are those of Corke's model
    (Robotics Toolbox, from Wang & Chen 1991): q2 in [-45, 225] deg and q3 in [-225, 45]
    deg. Named configurations: 'zero', 'ready', 'stretch', 'nominal'
    (the paper's eqs. 32-35).

    {returns}

    Examples
    --------
    At the zero configuration the arm reaches out along x by a2 + a3 = 0.4521 m, is
    offset by d3 = 0.15005 m along -y and lifted by d4 = 0.4318 m:

    >>> arm = puma560()
    >>> arm.fk(arm.configurations["zero"])[:3, 3].round(4)
    array([ 0.4521, -0.15  ,  0.4318])
    """
    deg = np.pi / 180
    links = [
        Link.revolute(d=0, a=0, alpha=sp.pi / 2, qlim=(-160 * deg, 160 * deg)),
        Link.revolute(d=0, a=0.4318, alpha=0, qlim=(-45 * deg, 225 * deg)),
        Link.revolute(
            d=0.15005, a=0.0203, alpha=-sp.pi / 2, qlim=(-225 * deg, 45 * deg)
        ),
        Link.revolute(d=0.4318, a=0, alpha=sp.pi / 2, qlim=(-110 * deg, 170 * deg)),
        Link.revolute(d=0, a=0, alpha=-sp.pi / 2, qlim=(-100 * deg, 100 * deg)),
        Link.revolute(d=0, a=0, alpha=0, qlim=(-266 * deg, 266 * deg)),
    ]
    configurations = {
        "zero": np.zeros(6),
        "ready": np.array([0, np.pi / 2, -np.pi / 2, 0, 0, 0]),
        "stretch": np.array([0, 0, -np.pi / 2, 0, 0, 0]),
        "nominal": np.array([0, np.pi / 4, -np.pi, 0, np.pi / 4, 0]),
    }
    return Chain(links, name="PUMA 560", configurations=configurations)


@fill(returns=_ARM_RETURNS)
def kawasaki_cx210l():
    """The Kawasaki CX210L 6R arm in standard DH (m), reconstructed from the workspace
    paper.

    Lengths are the paper's (Table 1): d1 = 0.55, a1 = 0.3, a2 = 1.19, a3 = 0.3,
    d4 = 1.19, d6 = 0.235. Twists (-90, 0, -90, 90, -90, 0) deg and the offset of 180
    deg on joint 2 are the only choice that reproduces the paper's MATLAB validation
    poses (Table 2, to 0.05 mm): alpha3 = -90 comes from the MATLAB listing
    (Table 1 prints +90), alpha5 = -90 and alpha6 = 0 from Table 1
    (the listing has +90 and 180). q2 = 90 deg is the upper arm vertical, as in the
    paper. No joint limits are set: the paper quotes only the maker's q3 >= -75 deg.
    Named configurations: 'table2_1', 'table2_2', 'table2_3'
    (q2 = 30, q3 = -90, -80, -70 deg).

    {returns}

    Examples
    --------
    The DH lengths of the paper's Table 1 (m):

    >>> arm = kawasaki_cx210l()
    >>> [float(link.a) for link in arm.links], [float(link.d) for link in arm.links]
    ([0.3, 1.19, 0.3, 0.0, 0.0, 0.0], [0.55, 0.0, 0.0, 1.19, 0.0, 0.235])
    """
    deg = sp.pi / 180
    links = [
        Link.revolute(d=0.55, a=0.3, alpha=-90 * deg),
        Link.revolute(a=1.19, offset=sp.pi),
        Link.revolute(a=0.3, alpha=-90 * deg),
        Link.revolute(d=1.19, alpha=90 * deg),
        Link.revolute(alpha=-90 * deg),
        Link.revolute(d=0.235),
    ]
    configurations = {
        f"table2_{k}": np.radians([0, 30, q3, 0, 0, 0])
        for k, q3 in enumerate((-90, -80, -70), start=1)
    }
    return Chain(links, name="Kawasaki CX210L", configurations=configurations)


def planar(lengths, qlim=None):
    """An n-link planar arm (n >= 2): revolute joints about z, link i of length
    lengths[i] (m).

    Standard DH with a_i = lengths[i] and every other parameter zero, so the end
    effector moves in the x-y plane; the rows 'position' of its geometric Jacobian hold
    the 2 x n planar Jacobian in their first two rows.

    Parameters
    ----------
    lengths : sequence of n >= 2 positive floats
        The link lengths (m).
    qlim : array-like, shape (n, 2), or None, optional
        Joint limits (rad).

    Returns
    -------
    Chain
        The arm, named "planar nR".

    Examples
    --------
    Two unit links, the elbow bent a quarter turn: the tip is at (1, 1).

    >>> arm = planar([1.0, 1.0])
    >>> arm.fk([0.0, np.pi / 2])[:3, 3].round(12) + 0.0
    array([1., 1., 0.])
    """
    if lengths is None or isinstance(lengths, (str, bytes)):
        raise TypeError(
            f"lengths must be two or more positive link lengths (m), got "
            f"{describe(lengths)}"
        )
    values = as_float_array(lengths, "lengths")
    if values.ndim != 1 or values.size < 2 or np.any(values <= 0):
        raise ValueError(
            f"lengths must be two or more positive link lengths (m), got {lengths!r}"
        )
    limits = [None] * values.size if qlim is None else as_float_array(qlim, "qlim")
    if qlim is not None and limits.shape != (values.size, 2):
        raise ValueError(
            f"qlim must have shape ({values.size}, 2), got shape {limits.shape}"
        )
    links = [
        Link.revolute(a=float(a), qlim=None if lim is None else tuple(lim))
        for a, lim in zip(values, limits)
    ]
    return Chain(links, name=f"planar {values.size}R")


def two_arm_planar(lengths=(0.3, 0.25, 0.2, 0.15, 0.1), separation=0.4, qlim=None):
    """A two-arm planar robot: two copies of ``planar(lengths)``
    (links l0..l4 as in the thesis) with their bases on the x axis at x = -separation/2
    (left) and +separation/2 (right), in m.

    Parameters
    ----------
    lengths : sequence of positive floats, optional
        The link lengths of each arm (m).
    separation : float, optional
        The distance between the two bases (m).
    qlim : array-like, shape (n, 2), or None, optional
        Joint limits of each arm (rad).

    Returns
    -------
    left, right : Chain
        The two arms.

    Examples
    --------
    Stretched along x, each arm reaches 0.3 + 0.25 + 0.2 + 0.15 + 0.1 = 1 m past
    its base at x = -0.2 or x = 0.2:

    >>> left, right = two_arm_planar()
    >>> left.fk(np.zeros(5))[:3, 3].round(4), right.fk(np.zeros(5))[:3, 3].round(4)
    (array([0.8, 0. , 0. ]), array([1.2, 0. , 0. ]))
    """
    half = as_real_scalar(separation, "separation") / 2
    arms = []
    for name, x in (("left", -half), ("right", half)):
        arm = planar(lengths, qlim)
        arms.append(Chain(arm.links, base=transl(x, 0, 0), name=f"{name} arm"))
    return tuple(arms)


# ---- the zoo: arms of teaching labs, from their makers' published parameters ----

__all__ += ["ur5e", "panda", "stanford", "iiwa14"]


def ur5e():
    """The Universal Robots UR5e in standard DH, Universal Robots' published
    parameters.

    Source: Universal Robots, "DH parameters for calculations of kinematics and
    dynamics" (support article, UR5e row): d1 = 0.1625, a2 = -0.425, a3 = -0.3922,
    d4 = 0.1333, d5 = 0.0997, d6 = 0.0996 m; alpha = (pi/2, 0, 0, pi/2, -pi/2, 0).
    Frame 6 is the tool flange. Joint limits +-360 deg (the UR5e data sheet). Joints
    2, 3 and 4 are parallel: a UR-type arm, solved in closed form by
    :mod:`screwkit.ik.ur`.

    Returns
    -------
    Chain
        The arm, with the named configurations 'zero' and 'home'.

    Examples
    --------
    At zero the arm lies stretched along -x (a2 + a3 = -0.8172 m), offset along -y
    by d4 + d6 = 0.2329 m, at height d1 - d5 = 0.0628 m:

    >>> ur5e().fk(np.zeros(6))[:3, 3].round(4)
    array([-0.8172, -0.2329,  0.0628])
    """
    turn = (-2 * np.pi, 2 * np.pi)
    links = [
        Link.revolute(d=0.1625, a=0, alpha=sp.pi / 2, qlim=turn),
        Link.revolute(d=0, a=-0.425, alpha=0, qlim=turn),
        Link.revolute(d=0, a=-0.3922, alpha=0, qlim=turn),
        Link.revolute(d=0.1333, a=0, alpha=sp.pi / 2, qlim=turn),
        Link.revolute(d=0.0997, a=0, alpha=-sp.pi / 2, qlim=turn),
        Link.revolute(d=0.0996, a=0, alpha=0, qlim=turn),
    ]
    configurations = {
        "zero": np.zeros(6),
        "home": np.array([0, -np.pi / 2, 0, -np.pi / 2, 0, 0]),
    }
    return Chain(links, name="UR5e", configurations=configurations)


def panda():
    """The Franka Emika Panda (7 joints) in modified DH (Craig), Franka's published
    parameters, to the flange.

    Source: Franka Control Interface documentation, "Robot and interface
    specifications", Denavit–Hartenberg parameters (a_{i-1}, d_i, alpha_{i-1}): d1 =
    0.333, d3 = 0.316, a3 = 0.0825, a4 = -0.0825, d5 = 0.384, a6 = 0.088 m, alpha =
    (0, -pi/2, pi/2, pi/2, -pi/2, pi/2, pi/2), and the flange d = 0.107 m along z7
    (the tool transform). Joint limits from the same page (rad). The link frames are
    those of Franka's URDF: frames 1..6 are panda_link1..6 and the last frame, which
    carries the flange, is panda_link8.

    Returns
    -------
    Chain
        The arm to its flange (the tool), with the named configuration 'ready'.

    Examples
    --------
    At zero the flange is a6 = 0.088 m forward, at height
    0.333 + 0.316 + 0.384 - 0.107 = 0.926 m (it points down):

    >>> panda().fk(np.zeros(7))[:3, 3].round(4) + 0.0
    array([0.088, 0.   , 0.926])
    """
    h = sp.pi / 2
    rows = [
        (0, 0.333, 0, (-2.8973, 2.8973)),
        (0, 0, -h, (-1.7628, 1.7628)),
        (0, 0.316, h, (-2.8973, 2.8973)),
        (0.0825, 0, h, (-3.0718, -0.0698)),
        (-0.0825, 0.384, -h, (-2.8973, 2.8973)),
        (0, 0, h, (-0.0175, 3.7525)),
        (0.088, 0, h, (-2.8973, 2.8973)),
    ]
    links = [
        Link.revolute(d=d, a=a, alpha=alpha, qlim=limit) for a, d, alpha, limit in rows
    ]
    ready = np.array([0, -np.pi / 4, 0, -3 * np.pi / 4, 0, np.pi / 2, np.pi / 4])
    return Chain(
        links,
        convention=Convention.MODIFIED,
        tool=transl(0, 0, 0.107),
        name="Panda",
        configurations={"ready": ready},
    )


def stanford():
    """The Stanford arm (RRPRRR) in standard DH: a spherical wrist on a prismatic
    joint.

    Source: P. Corke, Robotics Toolbox for MATLAB, ``mdl_stanford`` (after R. Paul,
    Robot Manipulators, 1981): d1 = 0.412, d2 = 0.154 m, alpha1 = -pi/2, alpha2 =
    pi/2, joint 3 prismatic with theta3 = -pi/2 and d3 = q3 in [12, 48] inches,
    alpha4 = -pi/2, alpha5 = pi/2, d6 = 0.263 m; every a_i = 0. Revolute joints have
    no limits here.

    Returns
    -------
    Chain
        The arm, with the named configuration 'nominal'.

    Examples
    --------
    At 'nominal' the boom (q2 = 90 deg) points along x, extended 0.5 m plus the
    wrist's 0.263 m, offset d2 = 0.154 m along y, at height d1 = 0.412 m:

    >>> arm = stanford()
    >>> "".join(link.joint.value for link in arm.links)
    'RRPRRR'
    >>> arm.fk(arm.configurations["nominal"])[:3, 3].round(4)
    array([0.763, 0.154, 0.412])
    """
    h = sp.pi / 2
    links = [
        Link.revolute(d=0.412, alpha=-h),
        Link.revolute(d=0.154, alpha=h),
        Link.prismatic(theta=-h, qlim=(12 * 0.0254, 48 * 0.0254)),
        Link.revolute(alpha=-h),
        Link.revolute(alpha=h),
        Link.revolute(d=0.263),
    ]
    return Chain(
        links,
        name="Stanford arm",
        configurations={"nominal": np.array([0, np.pi / 2, 0.5, 0, 0, 0])},
    )


def iiwa14():
    """The KUKA LBR iiwa 14 R820 (7 joints) in standard DH, to the flange.

    Source: KUKA, LBR iiwa 7 R800 / 14 R820 specification (lengths 360, 420, 400 and
    126 mm from the base to the flange, axis limits +-170, +-120, +-170, +-120,
    +-170, +-120, +-175 deg), with the DH frames of Faria, Ferreira, Erlhagen,
    Monteiro and Bicho, "Position-based kinematics for 7-DoF serial manipulators
    with global configuration control, joint limit and singularity avoidance", Mech.
    Mach. Theory 121 (2018): d = (0.36, 0, 0.42, 0, 0.4, 0, 0.126) m, alpha =
    (-pi/2, pi/2, pi/2, -pi/2, -pi/2, pi/2, 0), every a_i = 0.

    Returns
    -------
    Chain
        The arm, to its flange; no named configurations.

    Examples
    --------
    At zero the arm stands straight up: 0.36 + 0.42 + 0.4 + 0.126 = 1.306 m.

    >>> iiwa14().fk(np.zeros(7))[:3, 3].round(4) + 0.0
    array([0.   , 0.   , 1.306])
    """
    h, deg = sp.pi / 2, np.pi / 180
    rows = [
        (0.36, -h, 170),
        (0, h, 120),
        (0.42, h, 170),
        (0, -h, 120),
        (0.4, -h, 170),
        (0, h, 120),
        (0.126, 0, 175),
    ]
    links = [
        Link.revolute(d=d, alpha=alpha, qlim=(-limit * deg, limit * deg))
        for d, alpha, limit in rows
    ]
    return Chain(links, name="LBR iiwa 14 R820")
