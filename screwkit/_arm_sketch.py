"""Schematic drawings of arms for the exercises: links, joint symbols and frames.

A sketch is a view of an arm in the plane of the page (a side or a top view), in the
style of the textbooks: a revolute joint whose axis leaves the page is a circle with a
dot, one whose axis lies in the page a short cylinder along it, a prismatic joint a
sleeve, the base a hatched ground. Frames show their ``x`` and ``z`` axes; an axis out
of (into) the page is a dot (a cross) in a circle. Lengths are in metres, in the
page's horizontal and vertical coordinates.

>>> fig, ax = sketch(limits=((-0.2, 1.0), (-0.2, 0.6)))
>>> base(ax, (0, 0))
>>> link(ax, (0, 0), (0.5, 0.3))
>>> revolute(ax, (0, 0))
>>> len(ax.patches) > 0
True
>>> plt.close(fig)
"""

import matplotlib.pyplot as plt
import numpy as np

from ._checks import describe

#: Colours of the parts: links, joints, frames' x and z axes, dimensions.
LINK, JOINT, X_AXIS, Z_AXIS, DIMENSION = "0.35", "k", "tab:red", "tab:blue", "0.3"


def _point(value, name):
    """Two finite numbers (a point or a direction of the page)."""
    try:
        point = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise TypeError(f"{name} must be two numbers, got {describe(value)}") from None
    if point.shape != (2,) or not np.all(np.isfinite(point)):
        raise ValueError(f"{name} must be two finite numbers, got {value!r}")
    return point


def _unit(value, name):
    direction = _point(value, name)
    norm = np.hypot(*direction)
    if norm == 0:
        raise ValueError(f"{name} must be a non-zero direction, got {value!r}")
    return direction / norm


def sketch(width=3.3, height=2.6, limits=((-0.5, 1.5), (-0.3, 1.2)), title=None):
    """A figure and axes for a schematic: equal scales, no ticks, no box.

    Parameters
    ----------
    width, height : float, optional
        The figure's size (inches); at most ``plotting.COLUMN_WIDTH`` wide.
    limits : ((float, float), (float, float)), optional
        The page's horizontal and vertical ranges (m).
    title : str or None, optional
        The axes' title.

    Returns
    -------
    (matplotlib.figure.Figure, matplotlib.axes.Axes)
    """
    (x0, x1), (y0, y1) = _point(limits[0], "limits[0]"), _point(limits[1], "limits[1]")
    if x1 <= x0 or y1 <= y0:
        raise ValueError(f"limits must be increasing ranges, got {limits!r}")
    fig, ax = plt.subplots(figsize=(width, height))
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("equal")
    ax.axis("off")
    if title:
        ax.set_title(title)
    return fig, ax


def _scale(ax):
    """A length of about 1/25 of the drawing's width (m): the joints' size."""
    x0, x1 = ax.get_xlim()
    return (x1 - x0) / 25


def base(ax, xy, width=None):
    """A hatched ground under ``xy``."""
    x, y = _point(xy, "xy")
    w = 3 * _scale(ax) if width is None else float(width)
    ax.plot([x - w, x + w], [y, y], color=JOINT, lw=1.5)
    for k in np.linspace(-w, w, 7):
        ax.plot([x + k, x + k - w / 4], [y, y - w / 4], color=JOINT, lw=0.8)


def link(ax, *points, width=4.0):
    """A link: a thick line through ``points`` (at least two)."""
    if len(points) < 2:
        raise ValueError(f"link needs at least two points, got {len(points)}")
    xy = np.array([_point(p, f"points[{k}]") for k, p in enumerate(points)])
    ax.plot(xy[:, 0], xy[:, 1], color=LINK, lw=width, solid_capstyle="round", zorder=1)


def revolute(ax, xy, axis="out"):
    """A revolute joint at ``xy``: ``axis`` "out" (normal to the page) or a direction
    of the page, along which a short cylinder is drawn."""
    centre, r = _point(xy, "xy"), _scale(ax)
    if isinstance(axis, str) and axis == "out":
        ax.add_patch(
            plt.Circle(
                centre, r, fc="white", ec=JOINT, lw=1.5, zorder=3, gid="joint-revolute"
            )
        )
        ax.plot(*centre, "o", color=JOINT, ms=2, zorder=4)
        return
    if isinstance(axis, str):
        raise ValueError(f"axis must be 'out' or a direction, got {axis!r}")
    along = _unit(axis, "axis")
    across = np.array([-along[1], along[0]])
    corners = [centre + s * 1.3 * r * along + t * r * across for s, t in SQUARE]
    ax.add_patch(
        plt.Polygon(
            corners, fc="white", ec=JOINT, lw=1.5, zorder=3, gid="joint-revolute"
        )
    )


SQUARE = ((-1, -1), (1, -1), (1, 1), (-1, 1))


def prismatic(ax, xy, direction):
    """A prismatic joint at ``xy`` sliding along ``direction``: a sleeve (a box with a
    line along it), or for "in"/"out" (normal to the page) a square with a cross or
    a dot."""
    centre, r = _point(xy, "xy"), _scale(ax)
    style = {
        "fc": "0.85",
        "ec": JOINT,
        "lw": 1.5,
        "zorder": 3,
        "gid": "joint-prismatic",
    }
    if isinstance(direction, str):
        if direction not in ("in", "out"):
            raise ValueError(
                f"direction must be 'in', 'out' or a direction, got {direction!r}"
            )
        ax.add_patch(
            plt.Polygon([centre + 1.2 * r * np.array(c) for c in SQUARE], **style)
        )
        ax.plot(*centre, "x" if direction == "in" else "o", color=JOINT, ms=4, zorder=4)
        return
    along = _unit(direction, "direction")
    across = np.array([-along[1], along[0]])
    ax.add_patch(
        plt.Polygon(
            [centre + 2.2 * r * s * along + r * t * across for s, t in SQUARE], **style
        )
    )
    ends = np.array([centre - 2.2 * r * along, centre + 2.2 * r * along])
    ax.plot(ends[:, 0], ends[:, 1], color=JOINT, lw=0.8, zorder=4)


def _axis(ax, origin, direction, name, color, length):
    if isinstance(direction, str):
        if direction not in ("out", "in"):
            raise ValueError(
                f"{name} must be 'out', 'in' or a direction, got {direction!r}"
            )
        r = 0.5 * _scale(ax)
        ax.add_patch(plt.Circle(origin, r, fc="white", ec=color, lw=1.2, zorder=5))
        mark = "." if direction == "out" else "x"
        ax.plot(*origin, mark, color=color, ms=4 if mark == "x" else 3, zorder=6)
        return origin + np.array([0.6, -1.4]) * r * 2
    tip = origin + length * _unit(direction, name)
    ax.annotate(
        "",
        tip,
        origin,
        arrowprops={"arrowstyle": "-|>", "color": color, "lw": 1.3},
        zorder=5,
    )
    return tip + 0.25 * length * _unit(direction, name)


def frame(ax, xy, label, x=(1, 0), z=(0, 1), length=None):
    """A frame ``{label}`` at ``xy``: its ``x`` and ``z`` axes, each a direction of
    the page or "out"/"in" (a dot or a cross in a circle)."""
    origin = _point(xy, "xy")
    length = 4 * _scale(ax) if length is None else float(length)
    for direction, name, color in ((x, "x", X_AXIS), (z, "z", Z_AXIS)):
        where = _axis(ax, origin, direction, name, color, length)
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
    """A dimension line from ``start`` to ``end``, shifted by ``offset`` (m) to its
    left, with ``text`` in its middle."""
    p, q = _point(start, "start"), _point(end, "end")
    along = _unit(q - p, "end - start")
    shift = np.array([-along[1], along[0]]) * (
        2 * _scale(ax) if offset is None else float(offset)
    )
    a, b = p + shift, q + shift
    ax.annotate(
        "",
        b,
        a,
        arrowprops={
            "arrowstyle": "<|-|>",
            "color": DIMENSION,
            "lw": 0.8,
            "shrinkA": 0,
            "shrinkB": 0,
        },
    )
    middle = (a + b) / 2 + 0.6 * shift
    ax.text(*middle, text, color=DIMENSION, ha="center", va="center", fontsize=9)
