"""The catalogue of :mod:`screwkit.parallel`: the Stewart-Gough platform, the planar
3-RPR and 3-RRR, the delta and the Tripteron, with their default geometry.

Each builder checks its arguments, lays out the legs and returns a
:class:`~screwkit.parallel.ParallelManipulator`; ``sk.robots`` re-exports them.
Defaults are exact SymPy numbers, so that the exact layer stays exact; the numeric layer
reads their float values. A published geometry (Dietmaier's) is kept as printed, in
floats whose shortest decimals are the printed ones.
"""

import sympy as sp
from sympy import Rational

from .._checks import as_float_array, as_sympy_scalar, describe, is_symbolic
from ..transforms import rotz
from .legs import Linear, Prismatic, Revolute
from .model import ParallelManipulator


def _geometry(value, name, m, columns, default):
    if value is None:
        return default
    if is_symbolic(value):
        rows = sp.Matrix(value)
        if rows.shape != (m, columns):
            raise ValueError(
                f"{name} must have shape ({m}, {columns}), got {rows.shape}"
            )
        rows = rows.tolist()
    else:
        array = as_float_array(value, name)
        if array.shape != (m, columns):
            raise ValueError(
                f"{name} must have shape ({m}, {columns}), got {describe(value)}"
            )
        rows = array.tolist()
    return [list(r) + [0] * (3 - columns) for r in rows]


def _length(value, name):
    """A positive length (m): exact if given exactly."""
    length = as_sympy_scalar(value, name)
    if not (length.is_number and length > 0):
        raise ValueError(f"{name} must be a positive length (m), got {value!r}")
    return length


def _circle(radius, degrees):
    return [
        [radius * sp.cos(sp.pi * d / 180), radius * sp.sin(sp.pi * d / 180), 0]
        for d in degrees
    ]


#: Default Stewart-Gough geometry: base points on a circle of radius 1 m at
#: 120 k -/+ 15 degrees, platform points on a circle of 0.5 m at 120 k -/+ 45 degrees;
#: leg i joins base point i to platform point i (each base pair reaches two platform
#: pairs).
STEWART_BASE = _circle(1, [-15, 15, 105, 135, 225, 255])
#: Default Stewart-Gough platform points (m, platform frame): on a circle of 0.5 m at
#: 120 k -/+ 45 degrees (see STEWART_BASE).
STEWART_PLATFORM = _circle(sp.Rational(1, 2), [-45, 45, 75, 165, 195, 285])

#: Default 3-RPR geometry (m): with the leg lengths RPR_SIX_MODES_RHO it has six real
#: assembly modes, the most a 3-RPR can have (the tests count them by a separate scan).
RPR_BASE = [
    [0, 0],
    [sp.Rational(3, 5), sp.Rational(-4, 5)],
    [sp.Rational(1, 5), sp.Rational(1, 2)],
]
#: Default 3-RPR platform points (m, platform frame), with RPR_BASE.
RPR_PLATFORM = [
    [0, 0],
    [sp.Rational(-1, 2), sp.Rational(3, 10)],
    [sp.Rational(1, 10), sp.Rational(-7, 10)],
]
#: Leg lengths (m) at which the default 3-RPR has six real assembly modes.
RPR_SIX_MODES_RHO = (0.92, 1.37, 0.9)

#: Dietmaier's Stewart-Gough platform with 40 real assembly modes, the most there can be
#: (P. Dietmaier, "The Stewart-Gough platform of general geometry can have 40 real
#: postures", Advances in Robot Kinematics, Kluwer 1998, pp. 7-16): base points A_i
#: (m, base frame), as printed (6 decimals); with DIETMAIER_PLATFORM and DIETMAIER_RHO.
DIETMAIER_BASE = (
    (0, 0, 0),
    (1.107915, 0, 0),
    (0.549094, 0.756063, 0),
    (0.735077, -0.223935, 0.525991),
    (0.514188, -0.526063, -0.368418),
    (0.590473, 0.094733, -0.205018),
)
#: Dietmaier's platform points b_i (m, platform frame), as printed (see DIETMAIER_BASE).
DIETMAIER_PLATFORM = (
    (0, 0, 0),
    (0.542805, 0, 0),
    (0.956919, -0.528915, 0),
    (0.665885, -0.353482, 1.402538),
    (0.478359, 1.158742, 0.107672),
    (-0.137087, -0.235121, 0.353913),
)
#: Dietmaier's leg lengths (m), as printed: with DIETMAIER_BASE and DIETMAIER_PLATFORM
#: they have 40 real assembly modes.
DIETMAIER_RHO = (1, 0.645275, 1.086284, 1.503439, 1.281933, 0.771071)


def stewart_gough(base=None, platform=None, height=1, leg_limits=((0.9, 1.6),) * 6):
    """The 6-UPS Stewart-Gough platform.

    Leg i (universal, actuated prismatic, spherical) joins base point i to platform
    point i; its length is the actuated joint.

    Parameters
    ----------
    base : array-like, shape (6, 3), optional
        Base attachment points A_i (m, base frame). Default :data:`STEWART_BASE`
        (exact): on a circle of 1 m at 120 k -/+ 15 degrees.
    platform : array-like, shape (6, 3), optional
        Platform attachment points b_i (m, platform frame). Default
        :data:`STEWART_PLATFORM` (exact): on a circle of 0.5 m at 120 k -/+ 45
        degrees.
    height : number
        The home pose's height above the base (m).
    leg_limits : array-like, shape (6, 2), or None
        The legs' lengths' lower and upper limits (m); None for no limits.

    Returns
    -------
    ParallelManipulator
        Spatial (3T3R), six legs.

    Examples
    --------
    At home, by symmetry, the six legs are equally long: each spans a horizontal
    chord between radii 1 and 0.5 whose angles differ by 30 degrees,
    1 + 0.25 - 2 (0.5) cos 30 = 0.384 m^2, and 1 m of height: sqrt(1.384) = 1.176 m.

    >>> import numpy as np
    >>> pm = stewart_gough()
    >>> pm.ik(pm.home()).round(3)
    array([1.176, 1.176, 1.176, 1.176, 1.176, 1.176])
    """
    base = _geometry(base, "base", 6, 3, STEWART_BASE)
    platform = _geometry(platform, "platform", 6, 3, STEWART_PLATFORM)
    height = as_sympy_scalar(height, "height")
    home = sp.Matrix([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, height], [0, 0, 0, 1]])
    return _prismatic_legs("Stewart-Gough 6-UPS", base, platform, home, leg_limits)


def planar_3rpr(base=None, platform=None, home=None, leg_limits=None):
    """The planar 3-RPR: three revolute, actuated prismatic, revolute legs.

    Poses are planar 4 x 4 (a rotation about z and a translation in the xy-plane).

    Parameters
    ----------
    base : array-like, shape (3, 2), optional
        Base points A_i (m). Default :data:`RPR_BASE`.
    platform : array-like, shape (3, 2), optional
        Platform points b_i (m, platform frame). Default :data:`RPR_PLATFORM`; with
        these defaults the leg lengths :data:`RPR_SIX_MODES_RHO` have six real
        assembly modes.
    home : array-like, shape (4, 4), optional
        The home pose. Default: turned by 90 degrees, at (0.3, 0.85) m.
    leg_limits : array-like, shape (3, 2), or None
        The legs' lengths' limits (m); None for no limits.

    Returns
    -------
    ParallelManipulator
        Planar (2T1R), three legs of actuated length (m).

    Examples
    --------
    >>> pm = planar_3rpr()
    >>> pm, pm.motion_type
    (ParallelManipulator('3-RPR', 3 legs, 2T1R), '2T1R')
    """
    base = _geometry(base, "base", 3, 2, [r + [0] for r in RPR_BASE])
    platform = _geometry(platform, "platform", 3, 2, [r + [0] for r in RPR_PLATFORM])
    if home is None:
        home = sp.Matrix(rotz(sp.pi / 2)).row_join(
            sp.Matrix([sp.Rational(3, 10), sp.Rational(17, 20), 0])
        )
        home = home.col_join(sp.Matrix([[0, 0, 0, 1]]))
    return _prismatic_legs("3-RPR", base, platform, home, leg_limits, planar=True)


def _prismatic_legs(name, base, platform, home, leg_limits, planar=False):
    """The description of a mechanism whose legs are prismatic (the actuated lengths
    between base point i and platform point i)."""
    return ParallelManipulator(
        name=name,
        legs=Prismatic(base, planar=planar),
        base=base,
        platform=platform,
        motion="planar" if planar else "spatial",
        home=home,
        leg_limits=leg_limits,
    )


def _three_arms(base_radius, platform_radius, l1, l2):
    """Base and platform points on circles at 0, 120 and 240 degrees, and the two arm
    lengths: the checked geometry of the 3-RRR and the Delta (m)."""
    base = _circle(_length(base_radius, "base_radius"), [0, 120, 240])
    platform = _circle(_length(platform_radius, "platform_radius"), [0, 120, 240])
    return base, platform, _length(l1, "l1"), _length(l2, "l2")


def planar_3rrr(
    base_radius=1, platform_radius=Rational(1, 4), l1=Rational(3, 5), l2=Rational(1, 2)
):
    """The planar 3-RRR: actuated cranks, distal links, platform joints.

    Crank i of length ``l1`` turns about z at base point i (on a circle, 120 degrees
    apart); a distal link of length ``l2`` reaches platform point i. Eight working
    modes '+++' ... '---' (the sign of each elbow). Also ``sk.robots.parallel_3rrr``
    (``sk.robots.planar_3rrr`` is the mobility chapter's symbolic limbs).

    Parameters
    ----------
    base_radius, platform_radius : number
        Radii of the circles of base and platform points (m).
    l1, l2 : number
        Lengths of the cranks and of the distal links (m).

    Returns
    -------
    ParallelManipulator
        Planar (2T1R), three legs; the actuated values are crank angles (rad).

    Examples
    --------
    Two elbows per leg, three legs: 2^3 = 8 working modes.

    >>> pm = planar_3rrr()
    >>> len(pm.working_modes), pm.working_modes[0], pm.working_modes[-1]
    (8, '+++', '---')
    """
    base, platform, l1, l2 = _three_arms(base_radius, platform_radius, l1, l2)
    z, x = [0, 0, 1], [1, 0, 0]
    legs = Revolute(base, [z] * 3, [x] * 3, l1, l2, spatial=False)
    return ParallelManipulator(
        name="3-RRR",
        legs=legs,
        base=base,
        platform=platform,
        motion="planar",
        home=sp.eye(4),
    )


def delta(
    base_radius=Rational(1, 5),
    platform_radius=Rational(1, 20),
    l1=Rational(1, 5),
    l2=Rational(9, 20),
    height=Rational(-7, 20),
):
    """Clavel's delta as its kinematic equivalent 3-RUU (3T).

    Crank i of length ``l1`` turns about the tangent u_i at A_i (base circle, 120
    degrees apart; theta > 0 lowers it), and a link of length ``l2`` (a U-U pair in
    place of the spatial parallelogram) reaches platform point b_i. The platform only
    translates: a tilted pose is refused. Default working mode '---' (every knee out).

    Parameters
    ----------
    base_radius, platform_radius : number
        Radii of the circles of base and platform points (m).
    l1, l2 : number
        Lengths of the cranks and of the links (m).
    height : number
        The home pose's height (m; negative: below the base).

    Returns
    -------
    ParallelManipulator
        Translational (3T), three legs driven by crank angles (rad).

    Examples
    --------
    At home the platform is centred under the base, so by symmetry the three crank
    angles are equal:

    >>> import numpy as np
    >>> pm = delta()
    >>> theta = pm.ik(pm.home())
    >>> pm.motion_type, bool(np.allclose(theta, theta[0]))
    ('3T', True)
    """
    base, platform, l1, l2 = _three_arms(base_radius, platform_radius, l1, l2)
    radial = _circle(1, [0, 120, 240])
    tangent = [[-r[1], r[0], 0] for r in radial]
    home = sp.eye(4)
    home[2, 3] = as_sympy_scalar(height, "height")
    return ParallelManipulator(
        name="delta 3-RUU",
        legs=Revolute(base, tangent, radial, l1, l2, True),
        base=base,
        platform=platform,
        motion="translational",
        home=home,
        default_mode="---",
    )


def tripteron(
    a=Rational(9, 20), b=Rational(9, 20), L=1, offset=Rational(1, 10), home=None
):
    """The 3-PRRR Tripteron of the mobility chapter, a decoupled translational
    mechanism.

    Carriage i slides along the axis e_i (x, y, z; rho_i its position), then three
    revolutes along e_i with links ``a`` and ``b`` reach platform point b_i:
    rho_i = e_i . (p + b_i) - const.

    Parameters
    ----------
    a, b : number
        The lengths of the two links of each leg (m).
    L : number
        The carriages' rails' offset from the origin (m).
    offset : number
        How far each platform point b_i lies from the platform's origin, along the
        next axis (m).
    home : array-like, shape (4, 4), optional
        The home pose (a translation). Default: at (0.35, 0.35, 0.35) m.

    Returns
    -------
    ParallelManipulator
        Translational (3T), three legs; the actuated values are carriage positions
        (m).

    Examples
    --------
    Decoupled: moving the platform 0.1 m along x moves carriage 1 alone, by 0.1 m.

    >>> from screwkit.transforms import transl
    >>> pm = tripteron()
    >>> (pm.ik(transl(0.45, 0.35, 0.35)) - pm.ik(pm.home())).round(12) + 0.0
    array([0.1, 0. , 0. ])
    """
    a, b, L = _length(a, "a"), _length(b, "b"), _length(L, "L")
    offset = _length(offset, "offset")
    carriages = [[0, L, 0], [0, 0, L], [0, 0, 0]]
    axes = [[1, 0, 0], [0, 1, 0], [0, 0, 1]]
    platform = [[0, offset, 0], [0, 0, offset], [offset, 0, 0]]
    if home is None:
        home = sp.eye(4)
        home[:3, 3] = sp.Matrix([sp.Rational(7, 20)] * 3)
    return ParallelManipulator(
        name="Tripteron 3-PRRR",
        legs=Linear(carriages, axes, a, b),
        base=carriages,
        platform=platform,
        motion="translational",
        home=home,
    )
