"""Drawings of parallel manipulators at a pose (matplotlib): planar ones in the plane,
spatial ones in 3D, and constant-orientation workspaces with their singular curves.

Display layer (it imports matplotlib): not loaded by ``import screwkit``; the chapter
"Parallel manipulators in motion" imports it as
``from screwkit.parallel.plotting import draw_planar_platform``.
"""

import matplotlib.pyplot as plt
import numpy as np

from .._checks import check_transform, describe
from .model import ParallelManipulator, Workspace

__all__ = ["draw_planar_platform", "draw_spatial", "draw_workspace"]


def _check(pm, T):
    if not isinstance(pm, ParallelManipulator):
        raise TypeError(
            f"pm must be a ParallelManipulator (e.g. sk.parallel.planar_3rpr()), got "
            f"{type(pm).__name__}"
        )
    return pm.home() if T is None else check_transform(T, "T")


def _closed(points):
    return np.vstack([points, points[:1]])


def draw_planar_platform(
    pm, T=None, ax=None, mode=None, color="tab:blue", label=None, lines=False, alpha=1.0
):
    """Draw a planar parallel manipulator (3-RPR, 3-RRR) at the pose T in the xy-plane.

    The base triangle (grey), the platform triangle (``color``), the legs (for cranks:
    crank then distal link, the elbow marked) and, with ``lines``, each leg's line
    extended across the figure (the actuation wrenches' lines).

    Parameters
    ----------
    pm : ParallelManipulator
        A planar one (e.g. ``sk.parallel.planar_3rpr()``).
    T : array-like, shape (4, 4), optional
        The platform pose (m, base frame); default the home pose.
    ax : matplotlib Axes, optional
        Where to draw; default a new 4.5 x 4.5 inch figure.
    mode : str, optional
        The working mode whose elbows are drawn (e.g. '+-+' for the 3-RRR).
    color : matplotlib color
        The platform's and legs' color.
    label : str, optional
        The platform outline's legend label.
    lines : bool
        Also draw each leg's line, extended 3 m either way from its base point.
    alpha : float
        Opacity of the platform and legs, in [0, 1].

    Returns
    -------
    matplotlib Axes
        The axes drawn on, x and y in m, equal aspect.

    Examples
    --------
    A 3-RPR whose legs run from (0, 0) to (3, 4), from (4, 0) to (4, 4) and from
    (3, 9) to (3, 5): the last three lines drawn are the legs.

    >>> from screwkit.parallel import planar_3rpr
    >>> from screwkit.transforms import transl
    >>> pm = planar_3rpr(base=[[0, 0], [4, 0], [3, 9]],
    ...                  platform=[[0, 0], [1, 0], [0, 1]], home=transl(3, 4, 0))
    >>> ax = draw_planar_platform(pm)
    >>> [np.array(line.get_data()).T.tolist() for line in ax.lines[-3:]]
    [[[0.0, 0.0], [3.0, 4.0]], [[4.0, 0.0], [4.0, 4.0]], [[3.0, 9.0], [3.0, 5.0]]]
    >>> plt.close(ax.figure)
    """
    T = _check(pm, T)
    if ax is None:
        _, ax = plt.subplots(figsize=(4.5, 4.5))
    A = pm.base_points[:, :2]
    C = (T[:3, :3] @ pm.platform_points.T).T[:, :2] + T[:2, 3]
    ax.plot(*_closed(A).T, color="0.5", lw=1.5)
    ax.plot(A[:, 0], A[:, 1], "^", color="0.3", ms=8)
    ax.fill(*C.T, color=color, alpha=0.25 * alpha)
    ax.plot(*_closed(C).T, color=color, lw=2, alpha=alpha, label=label)
    joints = pm.ik(T, mode=mode, passive=True)
    for i in range(pm.m):
        if "elbow" in joints.passive:
            B = joints.passive["elbow"][i][:2]
            ax.plot(
                [A[i, 0], B[0], C[i, 0]],
                [A[i, 1], B[1], C[i, 1]],
                "-o",
                color=color,
                alpha=alpha,
                ms=4,
                lw=1.5,
            )
        else:
            ax.plot(
                [A[i, 0], C[i, 0]],
                [A[i, 1], C[i, 1]],
                "-",
                color=color,
                alpha=alpha,
                lw=3,
            )
        if lines:
            d = C[i] - A[i]
            d = d / np.linalg.norm(d)
            ends = np.array([A[i] - 3 * d, A[i] + 3 * d])
            ax.plot(*ends.T, ":", color=color, lw=1, alpha=alpha)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return ax


def draw_spatial(pm, T=None, ax=None, color="tab:blue", label=None):
    """Draw a spatial parallel manipulator (the Stewart-Gough platform) at T in 3D:
    base and platform polygons and the legs as straight lines.

    Parameters
    ----------
    pm : ParallelManipulator
    T : array-like, shape (4, 4), optional
        The platform pose (m, base frame); default the home pose.
    ax : matplotlib 3D Axes, optional
        Where to draw; default a new 5 x 4.5 inch figure.
    color : matplotlib color
        The platform's and legs' color.
    label : str, optional
        The platform outline's legend label.

    Returns
    -------
    matplotlib 3D Axes
        The axes drawn on, x, y and z in m.

    Examples
    --------
    The Stewart-Gough platform: the base and platform outlines and six legs.

    >>> from screwkit.parallel import stewart_gough
    >>> ax = draw_spatial(stewart_gough())
    >>> ax.name, len(ax.lines)
    ('3d', 8)
    >>> plt.close(ax.figure)
    """
    T = _check(pm, T)
    if ax is None:
        fig = plt.figure(figsize=(5, 4.5))
        ax = fig.add_subplot(projection="3d")
    A = pm.base_points
    C = (T[:3, :3] @ pm.platform_points.T).T + T[:3, 3]
    ax.plot(*_closed(A).T, color="0.5", lw=1.5)
    ax.plot(*_closed(C).T, color=color, lw=2, label=label)
    for a, c in zip(A, C):
        ax.plot(*np.array([a, c]).T, color=color, lw=2.5)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    return ax


def draw_workspace(workspace, ax=None, color="tab:green"):
    """Draw a :class:`~screwkit.parallel.Workspace`: the reachable region (shaded) and
    the direct-singularity curves, where det J changes sign inside it (black).

    Parameters
    ----------
    workspace : Workspace
        What ``pm.workspace(x, y)`` returns: grids x (nx,), y (ny,) in m, ``inside``
        and ``det`` of shape (ny, nx).
    ax : matplotlib Axes, optional
        Where to draw; default a new 4.5 x 4.5 inch figure.
    color : matplotlib color
        The reachable region's color.

    Returns
    -------
    matplotlib Axes
        The axes drawn on (x and y in m, equal aspect), the region shaded.

    Examples
    --------
    >>> from screwkit.parallel import planar_3rpr
    >>> pm = planar_3rpr()
    >>> ax = draw_workspace(pm.workspace(np.linspace(-1, 1, 5), np.linspace(-1, 1, 5)))
    >>> ax.get_xlabel(), float(ax.get_aspect())
    ('x (m)', 1.0)
    >>> plt.close(ax.figure)
    """
    if not isinstance(workspace, Workspace):
        raise TypeError(
            "workspace must be a Workspace (what pm.workspace(x, y) returns), got "
            f"{describe(workspace)}"
        )
    if ax is None:
        _, ax = plt.subplots(figsize=(4.5, 4.5))
    X, Y = np.meshgrid(workspace.x, workspace.y)
    ax.contourf(
        X,
        Y,
        workspace.inside.astype(float),
        levels=[0.5, 1.5],
        colors=[color],
        alpha=0.35,
    )
    ax.contour(X, Y, workspace.inside.astype(float), levels=[0.5], colors=[color])
    if np.any(np.isfinite(workspace.det)):
        det = np.where(workspace.inside, workspace.det, np.nan)
        if np.nanmin(det) < 0 < np.nanmax(det):
            ax.contour(X, Y, det, levels=[0.0], colors="k", linewidths=1.5)
    ax.set_aspect("equal")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    return ax
