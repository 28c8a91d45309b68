"""Draw a parallel mechanism from the limbs :func:`screwkit.mobility` takes
(matplotlib 3D).

The limbs are lists of (s, r, h) joint screws with symbols; ``values`` gives every
symbol a number, and the drawing shows the mechanism at that configuration: the base
(the polygon through each limb's first joint), the platform (the polygon through each
limb's last joint), each limb as a polyline through its joints, and every joint's screw
axis, with revolute, prismatic and helical joints told apart by colour, marker and line
style.
"""

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp
from mpl_toolkits.mplot3d import Axes3D

from ._checks import check_positive, describe, real_number
from .limbs import check_limbs
from .screws import Screw, Wrench
from .tolerances import LENGTH_TOL, ZERO_TOL, length_scale
from .transforms import _cross, _is_infinite_pitch

__all__ = ["draw_mechanism"]

#: How each joint kind is drawn: colour, marker, axis line style. The 3D viewers
#: colour joints the same way (``static/viewer/scene.js``, ``COLOURS``; checked by
#: tests/test_viewer.py).
JOINT_STYLES = {
    "revolute": ("tab:blue", "o", "-."),
    "prismatic": ("tab:orange", "s", "-"),
    "helical": ("tab:purple", "D", ":"),
}


def _kind(h):
    if _is_infinite_pitch(h):
        return "prismatic"
    return "revolute" if sp.sympify(h) == 0 else "helical"


def _check_values(limbs, values):
    """{Symbol: float} for every symbol of the limbs; keys may be symbols or their
    names."""
    if not isinstance(values, dict):
        raise TypeError(
            f"values must be a dict {{symbol or name: number}}, got {describe(values)}"
        )
    symbols = set()
    for limb in limbs:
        for s, r, h in limb:
            for part in (s, r, h):
                symbols |= (
                    sp.sympify(part).free_symbols
                    if not isinstance(part, (list, tuple))
                    else set().union(*(sp.sympify(e).free_symbols for e in part))
                )
    by_name = {str(x): x for x in symbols}
    numbers = {}
    for key, value in values.items():
        name = str(key)
        if name not in by_name:
            raise ValueError(
                f"values gives a number for {name!r}, which is not a symbol of the "
                f"limbs (their symbols are {sorted(by_name)})"
            )
        numbers[by_name[name]] = float(real_number(value, f"values[{name!r}]"))
    missing = sorted(name for name, x in by_name.items() if x not in numbers)
    if missing:
        raise ValueError(
            f"values has no number for the symbol {missing[0]!r}"
            + (f" (nor for {missing[1:]})" if len(missing) > 1 else "")
            + ": give every symbol of the limbs a number"
        )
    return numbers


def _numeric(vector, numbers, name):
    array = np.array(sp.Matrix(vector).subs(numbers).evalf(), dtype=float).reshape(3)
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} is not finite at these values: {array.tolist()}")
    return array


def evaluate(limbs, values):
    """The joints at these values: per limb a list of (kind, unit axis (3,), point (3,))
    in m."""
    check_limbs(limbs, twists=False)
    numbers = _check_values(limbs, values)
    result = []
    for i, limb in enumerate(limbs):
        joints = []
        for j, (s, r, h) in enumerate(limb):
            axis = _numeric(s, numbers, f"limb {i}, joint {j}: s")
            norm = np.linalg.norm(axis)
            if norm < ZERO_TOL:
                raise ValueError(f"limb {i}, joint {j}: s is zero at these values")
            joints.append(
                (_kind(h), axis / norm, _numeric(r, numbers, f"limb {i}, joint {j}: r"))
            )
        result.append(joints)
    return result


def _polygon(ax, points, color, gid):
    closed = np.vstack([points, points[:1]])
    (line,) = ax.plot(*closed.T, color=color, lw=2.5, gid=gid)
    if len(points) >= 3:
        from mpl_toolkits.mplot3d.art3d import Poly3DCollection

        ax.add_collection3d(
            Poly3DCollection([points], facecolor=color, alpha=0.2, gid=gid + "-face")
        )
    return line


def draw_mechanism(limbs, values, ax=None, twists=None, axis_length=None, title=None):
    """Draw a parallel mechanism at the configuration ``values``.

    Parameters
    ----------
    limbs : list of limbs, each a list of (s, r, h) joint screws
        as :func:`screwkit.mobility` takes them (s, r in m; h = 0 revolute, sympy.oo
        prismatic, else helical in m/rad)
    values : dict {symbol or symbol name: number}: a number (m or rad) for every symbol
    ax : a 3D matplotlib axes, or None for a new figure
    twists : optional platform twists
        (Twist objects, or a Mobility whose platform twist system is drawn) at the
        platform's centre: rotations as red arrows along their axis, translations as
        green arrows
    axis_length : length (m) of the drawn joint axes; by default a fifth of the
        mechanism's size
    title : optional axes title

    Returns
    -------
    The 3D axes. Artists carry gids: 'base', 'platform', 'limb', 'joint-revolute',
    'joint-prismatic', 'joint-helical', 'twist'.

    Notes
    -----
    The base and the platform are drawn as the polygons through each limb's first and
    last joints. The drawing shows the joints where the limbs put them at these values:
    it is one rigid platform only when the values satisfy the loop-closure equations.
    The catalogue's :data:`screwkit.robots.DRAWING_VALUES` give every limb the same
    values, so the symmetric limbs close on a regular polygon.

    Examples
    --------
    The planar 3-RRR: three limbs between one base and one platform.

    >>> import matplotlib.pyplot as plt
    >>> import screwkit as sk
    >>> ax = draw_mechanism(sk.robots.planar_3rrr(),
    ...                     sk.robots.DRAWING_VALUES["planar_3rrr"])
    >>> gids = [artist.get_gid() for artist in ax.get_children()]
    >>> gids.count("limb"), gids.count("base"), gids.count("platform")
    (3, 1, 1)
    >>> plt.close(ax.figure)
    """
    joints = evaluate(limbs, values)
    if axis_length is not None:
        axis_length = check_positive(axis_length, "axis_length")
    if ax is None:
        ax = plt.figure(figsize=(5, 5)).add_subplot(projection="3d")
    elif not isinstance(ax, Axes3D):
        raise TypeError(f"ax must be a 3D matplotlib Axes, got {describe(ax)}")
    points = np.array([p for limb in joints for _, _, p in limb])
    size = float(np.ptp(points, axis=0).max())
    size = (
        size if size > LENGTH_TOL * length_scale(points) else 2.0
    )  # every joint at one point (a spherical mechanism)
    length = size / 5 if axis_length is None else float(axis_length)

    _polygon(ax, np.array([limb[0][2] for limb in joints]), "0.35", "base")
    platform = np.array([limb[-1][2] for limb in joints])
    _polygon(ax, platform, "tab:cyan", "platform")
    seen = set()
    for limb in joints:
        path = np.array([p for _, _, p in limb])
        ax.plot(*path.T, color="0.2", lw=1.5, gid="limb")
        for kind, axis, point in limb:
            colour, marker, style = JOINT_STYLES[kind]
            label = kind if kind not in seen else None
            seen.add(kind)
            ends = np.stack([point - 0.5 * length * axis, point + 0.5 * length * axis])
            ax.plot(*ends.T, color=colour, ls=style, lw=2, gid=f"joint-{kind}")
            ax.scatter(
                *point,
                color=colour,
                marker=marker,
                s=30,
                label=label,
                gid=f"joint-{kind}",
            )
    if twists is not None:
        _draw_twists(ax, twists, platform.mean(axis=0), length)
    _frame_box(
        ax, points, 1.6 * length if twists is not None else length
    )  # room for the arrows
    ax.legend(loc="upper left")  # the style's size: 9 pt in the course style
    if title:
        ax.set_title(title)
    return ax


def twist_arrows(twists, centre):
    """Where to draw the platform's twists (a list of Twists, or a Mobility's platform
    twists): per twist (kind, start (3,), unit direction (3,)) in m; a rotation
    ('rotation') along its axis through the axis point nearest ``centre``, a
    translation ('translation') from ``centre``."""
    if hasattr(twists, "platform_twist_system"):
        twists = twists.platform_twist_system.basis()
    arrows = []
    for k, twist in enumerate(twists):
        if not isinstance(twist, Screw) or isinstance(twist, Wrench):
            raise TypeError(f"twists[{k}] must be a Twist, got {describe(twist)}")
        if twist.vector.free_symbols:
            raise ValueError(
                f"twists[{k}] has symbols "
                f"{sorted(map(str, twist.vector.free_symbols))}: substitute numbers "
                "before drawing"
            )
        w = np.array([float(e) for e in twist.primary])
        v = np.array([float(e) for e in twist.secondary])
        if np.linalg.norm(w) > ZERO_TOL:
            direction = w / np.linalg.norm(w)
            start = _cross(w, v) / w.dot(w)
            start = start + direction.dot(centre - start) * direction
            arrows.append(("rotation", start, direction))
        else:
            arrows.append(("translation", centre, v / np.linalg.norm(v)))
    return arrows


def _draw_twists(ax, twists, centre, length):
    for kind, start, direction in twist_arrows(twists, centre):
        colour = "tab:red" if kind == "rotation" else "tab:green"
        ax.quiver(*start, *(1.5 * length * direction), color=colour, lw=2, gid="twist")


def _frame_box(ax, points, margin):
    low, high = points.min(axis=0) - margin, points.max(axis=0) + margin
    middle, half = (low + high) / 2, (high - low).max() / 2
    for setter, m in zip((ax.set_xlim, ax.set_ylim, ax.set_zlim), middle):
        setter(m - half, m + half)
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
