"""Drawings of lines, named configurations of lines and the cylindroid (matplotlib).

Re-exported by :mod:`screwkit.plotting` (``sk.plotting.draw_lines``,
``draw_configuration``, ``draw_cylindroid``).

>>> import matplotlib.pyplot as plt
>>> from screwkit import plotting
>>> from screwkit.lines import Line
>>> ax = plotting.axes3d()
>>> plotting.draw_lines(ax, [Line.through([0, 0, 0], [1, 0, 0])])
>>> plt.close(ax.figure)
"""

import numpy as np
import sympy as sp

from ._checks import check_positive, describe
from .lines import Line, dependency
from .systems import ScrewSystem

__all__ = ["draw_configuration", "draw_cylindroid", "draw_lines"]

#: Colours of the lines drawn, in turn (matplotlib's tab10).
LINE_COLOURS = tuple(
    f"tab:{c}"
    for c in (
        "blue",
        "orange",
        "green",
        "red",
        "purple",
        "brown",
        "pink",
        "gray",
        "olive",
        "cyan",
    )
)


def _check_3d(ax):
    from mpl_toolkits.mplot3d import Axes3D  # noqa: PLC0415 (display layer)

    if not isinstance(ax, Axes3D):
        raise TypeError(
            f"ax must be a 3D matplotlib Axes (from axes3d()), got {describe(ax)}"
        )
    return ax


def _lines(lines):
    if isinstance(lines, Line):
        lines = [lines]
    if isinstance(lines, ScrewSystem):
        lines = list(lines.screws)
    if isinstance(lines, (str, bytes)) or not isinstance(
        lines, (list, tuple, np.ndarray)
    ):
        raise TypeError(
            f"lines must be a list of Lines or 6-vectors, got {describe(lines)}"
        )
    out = []
    for i, item in enumerate(lines):
        if not isinstance(item, Line):
            try:
                item = Line(item)
            except (TypeError, ValueError) as error:
                raise type(error)(
                    str(error).replace("plucker", f"lines[{i}]", 1)
                ) from None
        out.append(item)
    return out


def _float(v):
    return np.array([float(e) for e in v], dtype=float).reshape(-1)


def draw_lines(ax, lines, length=2.0, colors=None, labels=None, lw=1.5):
    """Draw lines as segments of ``length`` centred on their points nearest the
    origin.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    lines : Line, list of Lines or 6-vectors, or ScrewSystem of lines
        The lines.
    length : float, optional
        The length drawn of each (m).
    colors : list of str, optional
        Matplotlib colours, in turn (default ``LINE_COLOURS``).
    labels : list of str, optional
        One legend label a line.
    lw : float, optional
        Line width (points).

    Examples
    --------
    The x axis, drawn 2 m long about the origin (its point nearest the origin):

    >>> import matplotlib.pyplot as plt
    >>> from screwkit.plotting import axes3d
    >>> ax = axes3d()
    >>> draw_lines(ax, [Line.through([0, 0, 0], [1, 0, 0])], length=2.0)
    >>> np.array(ax.lines[0].get_data_3d()).round(12).tolist()
    [[-1.0, 1.0], [0.0, 0.0], [0.0, 0.0]]
    >>> plt.close(ax.figure)
    """
    _check_3d(ax)
    lines = _lines(lines)
    length = check_positive(length, "length")
    lw = check_positive(lw, "lw")
    colors = list(colors) if colors is not None else list(LINE_COLOURS)
    if labels is not None and len(labels) != len(lines):
        raise ValueError(
            f"labels must have one label a line ({len(lines)}), got {len(labels)}"
        )
    for i, line in enumerate(lines):
        u, p = _float(line.unit), _float(line.point)
        ends = np.stack([p - 0.5 * length * u, p + 0.5 * length * u])
        ax.plot(
            *ends.T,
            color=colors[i % len(colors)],
            lw=lw,
            label=None if labels is None else labels[i],
        )


def draw_configuration(ax, lines, length=2.0, size=1.0):
    """Draw lines and the geometry that names their dependency: the common point
    (a black dot), the plane (a pale square of side ``size``), the common line or
    lines (black, dashed).

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    lines : list of Lines or 6-vectors, or ScrewSystem of lines
        The lines (see :func:`screwkit.lines.dependency`).
    length : float, optional
        The length drawn of each line (m).
    size : float, optional
        The side of the plane's square (m).

    Returns
    -------
    screwkit.lines.Dependency
        The rank and the named configuration drawn.

    Examples
    --------
    The three coordinate axes meet at the origin: a star of rank 3.

    >>> import matplotlib.pyplot as plt
    >>> from screwkit.plotting import axes3d
    >>> ax = axes3d()
    >>> axes = ([1, 0, 0], [0, 1, 0], [0, 0, 1])
    >>> found = draw_configuration(ax, [Line.through([0, 0, 0], d) for d in axes])
    >>> found.rank, found.name
    (3, 'star')
    >>> plt.close(ax.figure)
    """
    _check_3d(ax)
    lines = _lines(lines)
    size = check_positive(size, "size")
    result = dependency(lines)
    draw_lines(ax, lines, length=length)
    _draw_data(ax, result, length, size)
    return result


def _draw_data(ax, result, length, size):
    data = result.data
    if "point" in data:
        ax.scatter(*_float(data["point"]), color="k", s=30, depthshade=False)
    if "plane" in data:
        n, d = data["plane"]
        n = _float(n)
        centre = n * float(d) / (n @ n)
        if "point" in data:
            centre = _float(data["point"])
        n = n / np.linalg.norm(n)
        e1 = np.cross(n, [1.0, 0, 0] if abs(n[0]) < 0.9 else [0, 1.0, 0])
        e1 /= np.linalg.norm(e1)
        e2 = np.cross(n, e1)
        s, t = np.meshgrid([-size / 2, size / 2], [-size / 2, size / 2])
        X = centre[:, None, None] + e1[:, None, None] * s + e2[:, None, None] * t
        ax.plot_surface(*X, color="tab:gray", alpha=0.2, linewidth=0)
    common = [data[k] for k in ("line", "axis") if k in data] + data.get("lines", [])
    for line in common:
        if _float(line.direction) @ _float(line.direction) > 0:
            u, p = _float(line.unit), _float(line.point)
            ends = np.stack([p - 0.6 * length * u, p + 0.6 * length * u])
            ax.plot(*ends.T, color="k", ls="--", lw=2)


def draw_cylindroid(ax, system, radius=1.0, steps=90, cmap="viridis"):
    """Draw the cylindroid of a 2-system: the axes of its members, coloured by pitch.

    With the principal screws along e1 (pitch h1) and e2 (pitch h2) meeting at the
    centre c, the member cos(t) $1 + sin(t) $2 has pitch h1 cos^2 t + h2 sin^2 t and
    its axis along cos(t) e1 + sin(t) e2 through c + (h2 - h1) sin t cos t e3,
    e3 = e1 x e2.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    system : ScrewSystem
        A 2-system with two different finite principal pitches.
    radius : float, optional
        How far each axis is drawn from the cylindroid's central line (m).
    steps : int, optional
        The number of members drawn over a half turn of t.
    cmap : str, optional
        A matplotlib colormap for the pitch.

    Returns
    -------
    matplotlib.collections.LineCollection
        The 3D lines drawn, a ``Line3DCollection`` (for a colorbar:
        ``ax.figure.colorbar(result, ax=ax)``).

    Examples
    --------
    A rotation about x (pitch 0) and a screw of pitch 1 along y: the members'
    pitches h1 cos^2 t + h2 sin^2 t run from 0 to 1.

    >>> import matplotlib.pyplot as plt
    >>> from screwkit.plotting import axes3d
    >>> ax = axes3d()
    >>> system = ScrewSystem([[1, 0, 0, 0, 0, 0], [0, 1, 0, 0, 1, 0]])
    >>> pitches = draw_cylindroid(ax, system, steps=12).get_array()
    >>> len(pitches), round(float(pitches.min()), 12), round(float(pitches.max()), 12)
    (12, 0.0, 1.0)
    >>> plt.close(ax.figure)
    """
    from matplotlib import colormaps  # noqa: PLC0415 (display layer)
    from mpl_toolkits.mplot3d.art3d import Line3DCollection  # noqa: PLC0415

    _check_3d(ax)
    if not isinstance(system, ScrewSystem):
        raise TypeError(f"system must be a ScrewSystem, got {describe(system)}")
    if system.rank != 2:
        raise ValueError(
            "system must be a 2-system to have a cylindroid, got a "
            f"{system.rank}-system"
        )
    radius = check_positive(radius, "radius")
    if isinstance(steps, bool) or not isinstance(steps, (int, np.integer)) or steps < 2:
        raise ValueError(f"steps must be an integer >= 2, got {steps!r}")
    principal = system.principal_screws()
    if any(h in (sp.oo, np.inf) for h in principal.pitches) or not principal.unique:
        raise ValueError(
            "system must have two different finite principal pitches to draw a "
            f"cylindroid, got pitches {principal.pitches} ({principal.reason})"
        )
    (h1, h2) = [float(h) for h in principal.pitches]
    s1, s2 = [_float(s.vector) for s in principal.screws]
    e1, e2 = s1[:3], s2[:3]
    e3 = np.cross(e1, e2)
    c1 = np.cross(e1, s1[3:] - h1 * e1)  # the point of axis 1 nearest the origin
    centre = c1 + e1 * (e1 @ (np.cross(e2, s2[3:] - h2 * e2) - c1))
    t = np.linspace(0, np.pi, steps, endpoint=False)
    d = np.cos(t)[:, None] * e1 + np.sin(t)[:, None] * e2
    p = centre + ((h2 - h1) * np.sin(t) * np.cos(t))[:, None] * e3
    segments = np.stack([p - radius * d, p + radius * d], axis=1)
    pitch = h1 * np.cos(t) ** 2 + h2 * np.sin(t) ** 2
    collection = Line3DCollection(segments, cmap=colormaps[cmap], lw=1.2)
    collection.set_array(pitch)
    ax.add_collection3d(collection)
    ax.plot(
        *np.stack([centre - abs(h2 - h1) * e3, centre + abs(h2 - h1) * e3]).T,
        color="k",
        lw=1,
    )
    return collection
