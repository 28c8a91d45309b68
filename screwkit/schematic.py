"""Schematic drawings of arms, as the exercises give them: links, joints and frames.

A side or top view of an arm, in metres in the page, drawn as textbooks do: a revolute
joint whose axis leaves the page is a circle with a dot, one whose axis lies in the page
a short cylinder along it, a prismatic joint a sleeve (a square if normal to the page),
the base a hatched ground; a frame shows its x and z axes (a dot or a cross in a circle
for an axis out of or into the page).

>>> fig, ax = sketch(limits=((-0.2, 1.0), (-0.2, 0.6)))
>>> base(ax, (0, 0)); link(ax, (0, 0), (0.5, 0.3)); revolute(ax, (0, 0))
>>> [p.get_gid() for p in ax.patches]; plt.close(fig)
['joint-revolute']
"""

import matplotlib.pyplot as plt
import numpy as np

from ._checks import describe
from ._docstrings import fill

#: Colours of the links, the joints, the frames' x and z axes and the dimensions.
LINK, JOINT, X_AXIS, Z_AXIS, DIMENSION = "0.35", "k", "tab:red", "tab:blue", "0.3"
MAX_WIDTH = 6.6  #: the widest sketch (inches), plotting.COLUMN_WIDTH
_SQUARE = np.array([(-1, -1), (1, -1), (1, 1), (-1, 1)])
#: The Parameters a joint's drawing begins with (``{joint_at}``).
_JOINT_AT = """ax : matplotlib.axes.Axes
    The sketch's axes.
xy : (float, float)
    Where the joint is (m)."""


def _point(value, name):
    """Two finite numbers: a point or a direction of the page."""
    try:
        point = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be two numbers, got {describe(value)}") from None
    if point.shape != (2,) or not np.all(np.isfinite(point)):
        raise ValueError(f"{name} must be two finite numbers, got {value!r}")
    return point


def _unit(value, name):
    """The direction ``value`` of the page, of length 1."""
    direction = _point(value, name)
    if not np.hypot(*direction) > 0:
        raise ValueError(f"{name} must be a non-zero direction, got {value!r}")
    return direction / np.hypot(*direction)


def _normal_to_page(value, name, allowed):
    """True if ``value`` is one of the words ``allowed``; raise for any other word."""
    if isinstance(value, str):
        if value not in allowed:
            raise ValueError(
                f"{name} must be {' or '.join(map(repr, allowed))} or "
                f"a direction, got {value!r}"
            )
        return True
    return False


def sketch(width=3.3, height=2.6, limits=((-0.5, 1.5), (-0.3, 1.2)), title=None):
    """A figure and axes for a schematic: equal scales, no ticks, no box.

    Parameters
    ----------
    width, height : float, optional
        The figure's size (inches), at most ``MAX_WIDTH`` wide.
    limits : ((float, float), (float, float)), optional
        The page's horizontal and vertical ranges (m).
    title : str or None, optional
        The axes' title.

    Returns
    -------
    (matplotlib.figure.Figure, matplotlib.axes.Axes)
        The figure and its axes.

    Examples
    --------
    >>> fig, ax = sketch(limits=((0, 2), (0, 1)))
    >>> [float(v) for v in (*ax.get_xlim(), *ax.get_ylim(), ax.get_aspect())]
    [0.0, 2.0, 0.0, 1.0, 1.0]
    >>> plt.close(fig)
    """
    if not 0 < width <= MAX_WIDTH:
        raise ValueError(f"width must be in (0, {MAX_WIDTH}] inches, got {width!r}")
    (x0, x1), (y0, y1) = _point(limits[0], "limits[0]"), _point(limits[1], "limits[1]")
    if x1 <= x0 or y1 <= y0:
        raise ValueError(f"limits must be increasing ranges, got {limits!r}")
    fig, ax = plt.subplots(figsize=(width, height))
    ax.set(xlim=(x0, x1), ylim=(y0, y1), aspect="equal")
    ax.axis("off")
    ax.set_title(title or "")
    return fig, ax


def _size(ax):
    """The joints' size (m): 1/25 of the drawing's width."""
    x0, x1 = ax.get_xlim()
    return (x1 - x0) / 25


def base(ax, xy):
    """Draw a hatched ground under a point.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The sketch's axes.
    xy : (float, float)
        The point (m).

    Examples
    --------
    The ground line and its seven hatches:

    >>> fig, ax = sketch()
    >>> base(ax, (0, 0)); len(ax.lines); plt.close(fig)
    8
    """
    x, y = _point(xy, "xy")
    w = 3 * _size(ax)
    ax.plot([x - w, x + w], [y, y], color=JOINT, lw=1.5)
    for k in np.linspace(-w, w, 7):
        ax.plot([x + k, x + k - w / 4], [y, y - w / 4], color=JOINT, lw=0.8)


def link(ax, *points):
    """Draw a link: a thick line through two or more points.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The sketch's axes.
    *points : (float, float)
        The points (m), at least two.

    Examples
    --------
    >>> fig, ax = sketch()
    >>> link(ax, (0, 0), (0.5, 0.3), (1.0, 0.3))
    >>> ax.lines[0].get_xydata().tolist(); plt.close(fig)
    [[0.0, 0.0], [0.5, 0.3], [1.0, 0.3]]
    """
    if len(points) < 2:
        raise ValueError(f"link needs at least two points, got {len(points)}")
    xy = np.array([_point(p, f"points[{k}]") for k, p in enumerate(points)])
    ax.plot(xy[:, 0], xy[:, 1], color=LINK, lw=4, solid_capstyle="round", zorder=1)


def _box(ax, centre, along, long, fill, gid):
    """A box centred at ``centre``, ``long`` times the joint size along ``along``."""
    across = np.array([-along[1], along[0]])
    r = _size(ax)
    corners = [centre + s * long * r * along + t * r * across for s, t in _SQUARE]
    ax.add_patch(plt.Polygon(corners, fc=fill, ec=JOINT, lw=1.5, zorder=3, gid=gid))


@fill(joint_at=_JOINT_AT)
def revolute(ax, xy, axis="out"):
    """Draw a revolute joint.

    Parameters
    ----------
    {joint_at}
    axis : "out" or (float, float), optional
        "out": the axis is normal to the page (a circle with a dot); a direction of
        the page: a short cylinder along it.

    Examples
    --------
    A joint whose axis leaves the page is a circle 1/25 of the drawing wide:

    >>> fig, ax = sketch(limits=((0, 2.5), (0, 1)))
    >>> revolute(ax, (1, 0.5)); joint = ax.patches[0]
    >>> joint.get_gid(), [float(v) for v in joint.center], round(float(joint.radius), 6)
    ('joint-revolute', [1.0, 0.5], 0.1)
    >>> plt.close(fig)
    """
    centre = _point(xy, "xy")
    if _normal_to_page(axis, "axis", ("out",)):
        ax.add_patch(
            plt.Circle(
                centre,
                _size(ax),
                fc="white",
                ec=JOINT,
                lw=1.5,
                zorder=3,
                gid="joint-revolute",
            )
        )
        ax.plot(*centre, "o", color=JOINT, ms=2, zorder=4)
    else:
        _box(ax, centre, _unit(axis, "axis"), 1.3, "white", "joint-revolute")


@fill(joint_at=_JOINT_AT)
def prismatic(ax, xy, direction):
    """Draw a prismatic joint.

    Parameters
    ----------
    {joint_at}
    direction : (float, float) or "in" or "out"
        Its direction of sliding: a direction of the page (a sleeve along it), or into
        or out of the page (a square with a cross or a dot).

    Examples
    --------
    A sleeve along x, 2 x 2.2 joint sizes long and 2 wide (a joint size is 0.1 m
    here):

    >>> fig, ax = sketch(limits=((0, 2.5), (0, 1)))
    >>> prismatic(ax, (1, 0.5), (1, 0)); sleeve = ax.patches[0]
    >>> corners = sleeve.get_xy()[:4]
    >>> sleeve.get_gid(), np.round(np.ptp(corners, axis=0), 6).tolist()
    ('joint-prismatic', [0.44, 0.2])
    >>> plt.close(fig)
    """
    centre = _point(xy, "xy")
    if _normal_to_page(direction, "direction", ("in", "out")):
        _box(ax, centre, np.array([1.0, 0.0]), 1.0, "0.85", "joint-prismatic")
        ax.plot(*centre, "x" if direction == "in" else "o", color=JOINT, ms=4, zorder=4)
        return
    along = _unit(direction, "direction")
    _box(ax, centre, along, 2.2, "0.85", "joint-prismatic")
    ends = centre + np.outer([-2.2, 2.2], along) * _size(ax)
    ax.plot(ends[:, 0], ends[:, 1], color=JOINT, lw=0.8, zorder=4)


def frame(ax, xy, label, x=(1, 0), z=(0, 1)):
    """Draw a frame's x and z axes, labelled.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The sketch's axes.
    xy : (float, float)
        The frame's origin (m).
    label : str
        The frame's name, written as the axes' subscript.
    x, z : (float, float) or "out" or "in", optional
        Each axis: a direction of the page (an arrow), or out of or into the page (a
        dot or a cross in a circle).

    Examples
    --------
    >>> fig, ax = sketch()
    >>> frame(ax, (0, 0), "1", x=(0, 1), z="out")
    >>> [text.get_text() for text in ax.texts if text.get_text()]; plt.close(fig)
    ['$x_{1}$', '$z_{1}$']
    """
    origin, length = _point(xy, "xy"), 4 * _size(ax)
    for direction, name, color in ((x, "x", X_AXIS), (z, "z", Z_AXIS)):
        if _normal_to_page(direction, name, ("out", "in")):
            r = 0.5 * _size(ax)
            ax.add_patch(plt.Circle(origin, r, fc="white", ec=color, lw=1.2, zorder=5))
            ax.plot(
                *origin, "." if direction == "out" else "x", color=color, ms=4, zorder=6
            )
            where = origin + np.array([1.2, -2.8]) * r
        else:
            d = _unit(direction, name)
            tip = origin + length * d
            arrow = {"arrowstyle": "-|>", "color": color, "lw": 1.3}
            ax.annotate("", tip, origin, zorder=5, arrowprops=arrow)
            where = tip + length * (0.15 * d + 0.3 * np.array([-d[1], d[0]]))
        ax.text(
            *where,
            f"${name}_{{{label}}}$",
            color=color,
            ha="center",
            va="center",
            fontsize=9,
            zorder=6,
            gid=f"frame-{label}",
        )


def dimension(ax, start, end, text, offset=None):
    """Draw a dimension line with a label in its middle.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The sketch's axes.
    start, end : (float, float)
        The measured points (m).
    text : str
        The label, such as "0.4 m".
    offset : float or None, optional
        How far to the left of the line from ``start`` to ``end`` it is drawn (m);
        None: twice the joints' size.

    Examples
    --------
    >>> fig, ax = sketch()
    >>> dimension(ax, (0, 0), (0.4, 0), "0.4 m")
    >>> [text.get_text() for text in ax.texts if text.get_text()]; plt.close(fig)
    ['0.4 m']
    """
    p, q = _point(start, "start"), _point(end, "end")
    along = _unit(q - p, "end - start")
    shift = 2 * _size(ax) if offset is None else float(offset)
    normal = np.array([-along[1], along[0]]) * shift
    ax.annotate(
        "",
        q + normal,
        p + normal,
        arrowprops={
            "arrowstyle": "<|-|>",
            "color": DIMENSION,
            "lw": 0.8,
            "shrinkA": 0,
            "shrinkB": 0,
        },
    )
    ax.text(
        *((p + q) / 2 + 1.6 * normal),
        text,
        color=DIMENSION,
        ha="center",
        va="center",
        fontsize=9,
    )
