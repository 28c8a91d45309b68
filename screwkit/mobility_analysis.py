"""The mobility of a parallel manipulator by screw theory, in four steps.

Zeroth step (the user's): each limb as a list of (s, r, h) joint screws in the fixed
frame.
1. limb twist systems (LTS): the span of each limb's joint twists;
2. limb wrench systems (LWS): the wrenches reciprocal to each LTS
(the limb's constraints);
3. platform wrench system (PWS): the span of all the LWS
(every constraint on the platform);
4. platform twist system (PTS): the twists reciprocal to the PWS
(the platform's motions).

The mobility is the order of the PTS; its twists give the type (e.g. 3T1R) and
directions.

>>> import sympy as sp
>>> x, y, z = [1, 0, 0], [0, 1, 0], [0, 0, 1]
>>> cartesian = [[(x, [0, 0, 0], sp.oo)], [(y, [0, 0, 0], sp.oo)],
...              [(z, [0, 0, 0], sp.oo)]]
>>> sk_result = mobility([limb + [(x, [0, 0, 0], sp.oo), (y, [0, 0, 0], sp.oo),
...                               (z, [0, 0, 0], sp.oo)]
...                       for limb in cartesian])
>>> sk_result.number, sk_result.type, sk_result.directions
(3, '3T', ['Tx', 'Ty', 'Tz'])
"""

import numbers
from dataclasses import dataclass, field

import numpy as np
import sympy as sp

from . import _exact, _numeric
from ._checks import as_sympy_matrix, as_sympy_scalar, describe
from .limbs import check_limbs
from .screws import Screw, Twist, Wrench, axis_coordinates
from .systems import ScrewSystem, html_table, latex_table

__all__ = ["mobility", "Mobility", "grubler_kutzbach"]

_AXES = "xyz"


def grubler_kutzbach(links, joints, freedoms, order=6):
    """The Grübler–Kutzbach count M = order (links - joints - 1) + sum of freedoms.

    Parameters
    ----------
    links : int
        The number of links, the base and the platform included.
    joints : int
        The number of joints.
    freedoms : int
        The sum of the joints' freedoms.
    order : int, optional
        6 in space, 3 in the plane.

    Returns
    -------
    int
        The count M.

    Examples
    --------
    A planar four-bar (4 links, 4 revolutes) has one freedom; the Gough-Stewart
    platform (14 links, 6 legs of a U, a P and an S joint) six:

    >>> grubler_kutzbach(4, 4, 4, order=3), grubler_kutzbach(14, 18, 36)
    (1, 6)
    """
    for name, value in (
        ("links", links),
        ("joints", joints),
        ("freedoms", freedoms),
        ("order", order),
    ):
        if not isinstance(value, int) or isinstance(value, bool) or value < 0:
            raise TypeError(f"{name} must be a non-negative integer, got {value!r}")
    return order * (links - joints - 1) + freedoms


@dataclass
class Mobility:
    """The result of :func:`mobility`: the number, type and directions of the platform's
    motions.

    Parameters
    ----------
    number : int
        The platform's number of freedoms.
    type : str
        E.g. '3T1R' (translations T, rotations R), '0' for none.
    directions : list of str
        E.g. ['Tx', 'Ty', 'Tz', 'Rz'].
    limb_twist_systems, limb_wrench_systems : list of ScrewSystem
        Per limb, its twist system and the reciprocal wrench system.
    platform_wrench_system, platform_twist_system : ScrewSystem
        The union of the limbs' wrenches, and its reciprocal: the platform's twists.
    joints_per_limb : list of int
        The number of 1-freedom joints of each limb.
    limb_twist_ranks : list of int
        The rank of each limb's twist system.
    grubler_kutzbach : int
        The Grübler–Kutzbach count, for comparison.
    redundant_constraints : int
        The sum of the limbs' wrench ranks minus the platform's.
    idle_mobility : int
        The sum over limbs of joints minus twist rank.
    notes : list of str
        At a particular configuration (``at``): how it compares with the general answer.

    Examples
    --------
    Two identical planar limbs (slide x, slide y, turn about z): the platform keeps
    the 3 planar motions, though Grübler-Kutzbach counts 0 (6 links, 6 joints of one
    freedom): 3 of the limbs' constraints repeat each other.

    >>> x, y, z, origin = [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]
    >>> limb = [(x, origin, sp.oo), (y, origin, sp.oo), (z, origin, 0)]
    >>> result = mobility([limb, limb])
    >>> result.number, result.grubler_kutzbach, result.redundant_constraints
    (3, 0, 3)
    """

    number: int
    type: str
    directions: list
    limb_twist_systems: list
    limb_wrench_systems: list
    platform_wrench_system: ScrewSystem
    platform_twist_system: ScrewSystem
    joints_per_limb: list
    limb_twist_ranks: list
    grubler_kutzbach: int
    redundant_constraints: int
    idle_mobility: int
    notes: list = field(default_factory=list)

    def summary(self):
        """The four systems and the counts as plain text.

        Returns
        -------
        str
            One screw per line.

        Examples
        --------
        The last line of the summary of the class example:

        >>> x, y, z, origin = [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]
        >>> limb = [(x, origin, sp.oo), (y, origin, sp.oo), (z, origin, 0)]
        >>> print(mobility([limb, limb]).summary().splitlines()[-1])
        Mobility: 3 (2T1R) ['Tx', 'Ty', 'Rz']
        """

        def block(title, systems):
            lines = [title]
            for i, system in enumerate(systems, 1):
                prefix = f"  limb {i}: " if len(systems) > 1 else "  "
                vectors = [str(list(s.vector)) for s in system.basis()] or ["(none)"]
                lines.append(prefix + f"{system.rank}-system " + vectors[0])
                lines += [
                    " " * len(prefix + f"{system.rank}-system ") + v
                    for v in vectors[1:]
                ]
            return lines

        lines = block("Limb twist systems (LTS)", self.limb_twist_systems)
        lines += block("Limb wrench systems (LWS)", self.limb_wrench_systems)
        lines += block("Platform wrench system (PWS)", [self.platform_wrench_system])
        lines += block("Platform twist system (PTS)", [self.platform_twist_system])
        lines.append(f"Mobility: {self.number} ({self.type}) {self.directions}")
        return "\n".join(lines)

    def __repr__(self):
        return f"Mobility({self.number}, {self.type!r}, {self.directions})"

    def _systems(self):
        rows = [(f"LTS, limb {i}", s) for i, s in enumerate(self.limb_twist_systems, 1)]
        rows += [
            (f"LWS, limb {i}", s) for i, s in enumerate(self.limb_wrench_systems, 1)
        ]
        return rows + [
            ("PWS", self.platform_wrench_system),
            ("PTS", self.platform_twist_system),
        ]

    def _repr_latex_(self):
        lines = [
            rf"\text{{{name} ({s.noun} {s.rank}-system)}} & "
            f"{latex_table(s.basis())}"
            for name, s in self._systems()
        ]
        lines.append(
            rf"\text{{mobility}} & \text{{{self.number} ({self.type}): "
            f"{', '.join(self.directions)}}}"
        )
        return "$\\begin{array}{ll}" + r" \\ ".join(lines) + r"\end{array}$"

    def _repr_html_(self):
        steps = [
            ("Limb twist systems (LTS)", "limb", self.limb_twist_systems),
            ("Limb wrench systems (LWS)", "limb", self.limb_wrench_systems),
            ("Platform wrench system (PWS)", "", [self.platform_wrench_system]),
            ("Platform twist system (PTS)", "", [self.platform_twist_system]),
        ]
        rows = []
        for title, prefix, systems in steps:
            tables = "".join(
                "<div>"
                + html_table(
                    s.basis(),
                    (f"{prefix} {i}: " if prefix else "") + f"{s.noun} {s.rank}-system",
                )
                + "</div>"
                for i, s in enumerate(systems, 1)
            )
            # side by side, wrapping to the next line on a narrow page (a phone)
            box = (
                "display:flex;flex-wrap:wrap;align-items:flex-start;"
                "column-gap:1.5em;overflow-x:auto"
            )
            rows.append(f'<p><b>{title}</b></p><div style="{box}">{tables}</div>')
        title = (
            f"Mobility {self.number} ({self.type}): "
            f"{', '.join(self.directions) or 'none'}"
        )
        notes = "".join(f"<p>{note}</p>" for note in self.notes)
        return (
            f'<div class="screwkit-mobility">{"".join(rows)}'
            f"<p><b>{title}</b></p>{notes}</div>"
        )

    def as_dict(self):
        """The paper's mobility dictionary.

        Returns
        -------
        dict
            {'Number': ..., 'Type': ..., 'Direction': [...]}.

        Examples
        --------
        A platform on three identical slide-x, slide-y, slide-z limbs translates:

        >>> x, y, z, origin = [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]
        >>> limb = [(x, origin, sp.oo), (y, origin, sp.oo), (z, origin, sp.oo)]
        >>> mobility([limb] * 3).as_dict()
        {'Number': 3, 'Type': '3T', 'Direction': ['Tx', 'Ty', 'Tz']}
        """
        return {
            "Number": self.number,
            "Type": self.type,
            "Direction": list(self.directions),
        }


_NOT_FINITE = (sp.nan, sp.zoo, sp.oo, -sp.oo)


def _checked_vector(v):
    """A 3 x 1 SymPy matrix from the joint helpers, finite, as a list; None if it needs
    the full check."""
    if isinstance(v, sp.MatrixBase) and v.shape == (3, 1):
        entries = _exact.entries(v)
        if not any(e.has(*_NOT_FINITE) for e in entries):
            return entries
    return None


def _twist(joint, i, j):
    """The joint's twist (s; r x s + h s), or (0; s) for h = oo. Joints from
    :mod:`.joints` hold checked SymPy vectors and are built directly; anything else goes
    through Twist.from_axis."""
    if isinstance(joint, Screw):
        return Twist._checked(joint.vector)
    s, r, h = joint
    direction, point = _checked_vector(s), _checked_vector(r)
    if (
        direction is not None
        and point is not None
        and any(e != 0 for e in direction)
        and (h is sp.oo or h == 0)  # as the limb builders write them
    ):
        return Twist._checked(axis_coordinates(s, r, h))
    try:
        return Twist.from_axis(*joint)
    except (TypeError, ValueError) as error:
        raise type(error)(f"limb {i}, joint {j}: {error}") from None


def _describe(vector):
    """'Tx' / 'Rz' for an axis-aligned twist through the origin, else its
    coordinates."""
    nonzero = [k for k, e in enumerate(vector) if e != 0]
    if len(nonzero) == 1 and vector[nonzero[0]] == 1:
        k = nonzero[0]
        return ("R" if k < 3 else "T") + _AXES[k % 3]
    return str(list(vector))


def mobility(limbs, at=None, tol=None):
    """The mobility of a parallel manipulator whose limbs are lists of (s, r, h) joint
    screws.

    Parameters
    ----------
    limbs : list of limbs; each limb a list of (s, r, h) triples in the fixed frame
        (s, r: 3-vectors in m, SymPy symbols allowed; h: 0, a finite pitch in m/rad, or
        sympy.oo), or Twists.
    at : optional {symbol: value}, a particular configuration.
        The result is then the mobility at those values, and its ``notes`` say whether
        it is the general answer (the symbols free) or a singular configuration that
        gains or loses freedoms. Every key must be a symbol of the limbs. Float values
        are read as the exact rationals they store (the geometry stays exact; only the
        values are particular).
    tol : relative tolerance of the ranks when the limbs are given with floats
        (default ``RANK_TOL``, 1e-9, of :mod:`screwkit.tolerances`).

    Returns
    -------
    Mobility with ``number``, ``type`` (e.g. '3T1R'), ``directions``
        (e.g. ['Tx', 'Ty', 'Tz', 'Rz']), the four screw systems, and the
        Grübler–Kutzbach comparison.

    Notes
    -----
    Exact limbs (integers, rationals, symbols, pi, square roots, sin/cos/tan of symbols)
    are computed exactly, the ranks being generic in the symbols
    (see :mod:`screwkit._exact`). Limbs given with floats and no symbols
    (say, a frame tilted with NumPy) are computed by SVD: a rank counts the singular
    values above ``tol * max(1, the largest)``, so axes that differ by round-off count
    as parallel (see :mod:`screwkit._numeric`). Floats together with symbols are refused
    with a ValueError that says how to write them exactly.

    Examples
    --------
    Two limbs that each slide along x and y and turn about z: the platform moves in
    the plane, two translations and one rotation.

    >>> x, y, z, origin = [1, 0, 0], [0, 1, 0], [0, 0, 1], [0, 0, 0]
    >>> limb = [(x, origin, sp.oo), (y, origin, sp.oo), (z, origin, 0)]
    >>> result = mobility([limb, limb])
    >>> result.number, result.type, result.directions
    (3, '2T1R', ['Tx', 'Ty', 'Rz'])
    """
    tol = _numeric.TOL if tol is None else _numeric.check_tol(tol)
    if at is not None:
        return _at_configuration(limbs, at, tol)
    check_limbs(limbs)
    twists = [
        [_twist(joint, i, j) for j, joint in enumerate(limb)]
        for i, limb in enumerate(limbs)
    ]
    numeric = _numeric.has_floats(
        [e for limb in twists for t in limb for e in _exact.entries(t.vector)]
    )
    if numeric:  # floats with symbols are refused here, naming the limbs
        for limb in twists:
            _numeric.to_array([list(t.vector) for t in limb], "limbs")
    # Steps 1 and 2, limb by limb: each limb in the smallest field that holds its own
    # symbols (exact), or by SVD (floats).
    lts = [ScrewSystem(limb, kind=Twist, tol=tol) for limb in twists]
    lws = [system.reciprocal() for system in lts]
    # Steps 3 and 4: the platform's constraints, and the motions they leave.
    constraints = [w for system in lws for w in system.screws]
    pws = ScrewSystem(constraints, kind=Wrench, tol=tol).reduced()
    pts = pws.reciprocal()
    basis = pts.basis()
    if numeric:
        angular = np.array([[float(e) for e in t.primary] for t in basis])
        rotations = _numeric.rank(angular.reshape(len(basis), 3), tol)
    else:
        rotations = (
            _exact.generic_rank([list(t.primary) for t in basis]) if basis else 0
        )
    return _result(limbs, lts, lws, pws, pts, [s.rank for s in lts], rotations)


def _limb_symbols(limbs):
    found = set()
    for limb in limbs:
        for joint in limb:
            parts = [joint.vector] if isinstance(joint, Screw) else list(joint)
            for part in parts:
                if isinstance(part, sp.Basic):
                    found |= part.free_symbols
                elif isinstance(part, sp.MatrixBase) or isinstance(
                    part, (list, tuple, np.ndarray)
                ):
                    for e in (
                        part.flat()
                        if isinstance(part, sp.MatrixBase)
                        else np.ravel(np.asarray(part, dtype=object))
                    ):
                        if isinstance(e, sp.Basic):
                            found |= e.free_symbols
    return found


def _check_at(limbs, at):
    """``at`` as {symbol: exact value}: keys are symbols of the limbs, values finite
    numbers or SymPy expressions (floats become the exact rationals they store)."""
    if not isinstance(at, dict) or not all(isinstance(k, sp.Symbol) for k in at):
        raise TypeError(f"at must be a dict {{sympy.Symbol: value}}, got {at!r}")
    symbols = _limb_symbols(limbs)
    unknown = sorted(str(k) for k in at if k not in symbols)
    if unknown:
        raise ValueError(
            f"at gives values for {unknown}, which are not symbols of the limbs "
            f"(their symbols are {sorted(map(str, symbols))})"
        )
    values = {}
    for key, value in at.items():
        name = f"at[{key}]"
        if isinstance(value, (bool, np.bool_)) or isinstance(value, (str, bytes)):
            raise TypeError(
                f"{name} must be a number or a SymPy expression, got {describe(value)}"
            )
        if isinstance(value, (float, np.floating)):
            if not np.isfinite(value):
                raise ValueError(f"{name} must be finite, got {value!r}")
            values[key] = sp.Rational(float(value))
        elif isinstance(value, (numbers.Integral, np.integer)):
            values[key] = sp.Integer(int(value))
        else:
            expr = as_sympy_scalar(value, name)
            values[key] = expr.xreplace(
                {f: sp.Rational(f) for f in expr.atoms(sp.Float)}
            )
    return values


def _at_configuration(limbs, at, tol):
    """The mobility at the values ``at``, with notes comparing it with the general
    configuration."""
    check_limbs(limbs)
    values = _check_at(limbs, at)

    def substitute(joint):
        if isinstance(joint, Screw):
            return Twist(sp.Matrix(joint.vector).subs(values))
        s, r, h = joint
        h = h if h is sp.oo or not isinstance(h, sp.Basic) else h.subs(values)
        return (
            as_sympy_matrix(s, "s", (3, 1)).subs(values),
            as_sympy_matrix(r, "r", (3, 1)).subs(values),
            h,
        )

    general = mobility(limbs, tol=tol)
    special = mobility(
        [[substitute(joint) for joint in limb] for limb in limbs], tol=tol
    )
    here = f"{special.number} ({special.type}: {', '.join(special.directions)})"
    there = f"{general.number} ({general.type}: {', '.join(general.directions)})"
    if (special.number, special.type, special.directions) == (
        general.number,
        general.type,
        general.directions,
    ):
        special.notes.append(
            f"general configuration: the mobility at these values, {here}, is the "
            "general one"
        )
    else:
        change = "changes"
        if special.number != general.number:
            change = "gains" if special.number > general.number else "loses"
        special.notes.append(
            f"singular configuration: the platform {change} freedoms here, {here}, "
            f"against {there} in the general configuration"
        )
    ranks = (
        [w.rank for w in special.limb_wrench_systems],
        [w.rank for w in general.limb_wrench_systems],
    )
    if ranks[0] != ranks[1]:
        special.notes.append(
            f"limb wrench system ranks {ranks[0]} here, {ranks[1]} in general "
            "(a limb gains or loses constraints)"
        )
    if special.platform_wrench_system.rank != general.platform_wrench_system.rank:
        special.notes.append(
            f"platform wrench system rank {special.platform_wrench_system.rank} here, "
            f"{general.platform_wrench_system.rank} in general"
        )
    return special


def _result(limbs, lts, lws, pws, pts, lts_ranks, rotations):
    basis = pts.basis()
    translations = len(basis) - rotations
    kind = (f"{translations}T" if translations else "") + (
        f"{rotations}R" if rotations else ""
    ) or "0"
    names = [_describe(t.vector) for t in basis]
    directions = sorted(names, key=lambda n: (not n.startswith("T"), n))
    joints = [len(limb) for limb in limbs]
    links = sum(j - 1 for j in joints) + 2
    return Mobility(
        number=len(basis),
        type=kind,
        directions=directions,
        joints_per_limb=joints,
        grubler_kutzbach=grubler_kutzbach(links, sum(joints), sum(joints)),
        limb_twist_systems=lts,
        limb_wrench_systems=lws,
        platform_wrench_system=pws,
        platform_twist_system=pts,
        limb_twist_ranks=lts_ranks,
        redundant_constraints=sum(w.rank for w in lws) - pws.rank,
        idle_mobility=sum(j - r for j, r in zip(joints, lts_ranks)),
    )
