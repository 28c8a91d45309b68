"""Matplotlib drawings of frames, screw axes and screw motions (metres).

>>> ax = axes3d()
>>> draw_frame(ax, np.eye(4), label="0")
>>> plt.close(ax.figure)
"""
import matplotlib.pyplot as plt
import numpy as np

from ._checks import as_float_array, check_shape, check_transform

__all__ = ["axes3d", "draw_frame", "draw_screw_axis", "draw_screw_motion", "draw_chain", "draw_ellipsoid",
           "draw_planar", "animation_html"]

AXIS_COLOURS = ("tab:red", "tab:green", "tab:blue")  # x, y, z


def axes3d(limits=((-1, 1), (-1, 1), (0, 2)), ax=None, figsize=(5, 5)):
    """A 3D axes with equal scale on x, y, z (m) and labelled axes.

    Parameters
    ----------
    limits : ((xmin, xmax), (ymin, ymax), (zmin, zmax)) in metres
    ax : an existing 3D axes to set up, or None to create a figure
    """
    if ax is None:
        figure = plt.figure(figsize=figsize)
        ax = figure.add_subplot(projection="3d")
    limits = as_float_array(limits, "limits")
    if limits.shape != (3, 2):
        raise ValueError(f"limits must be three (min, max) pairs, shape (3, 2), got shape {limits.shape}")
    ax.set_xlim(*limits[0])
    ax.set_ylim(*limits[1])
    ax.set_zlim(*limits[2])
    ax.set_box_aspect(limits[:, 1] - limits[:, 0])
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    return ax


def draw_frame(ax, T, label=None, length=0.3, alpha=1.0):
    """Draw the frame of a 4x4 transform ``T``: x red, y green, z blue, ``length`` in m."""
    T = check_transform(np.asarray(T, dtype=float), "T")
    if T.ndim != 2:
        raise ValueError(f"T must be one transform of shape (4, 4), got shape {T.shape}")
    origin = T[:3, 3]
    for k in range(3):
        tip = origin + length * T[:3, k]
        ax.plot(*np.stack([origin, tip]).T, color=AXIS_COLOURS[k], lw=2, alpha=alpha)
    if label is not None:
        ax.text(*(origin - 0.12 * length * (T[:3, 0] + T[:3, 1])), f"{{{label}}}", fontsize=10)


def draw_screw_axis(ax, s, r, length=2.0, label=None, color="k"):
    """Draw the screw axis through point ``r`` with direction ``s`` as a dash-dot line."""
    s = check_shape(as_float_array(s, "s"), "s", (3,))
    r = check_shape(as_float_array(r, "r"), "r", (3,))
    if np.linalg.norm(s) < 1e-12:
        raise ValueError(f"s must be a non-zero 3-vector, got {s.tolist()}")
    u = s / np.linalg.norm(s)
    ends = np.stack([r - 0.5 * length * u, r + 0.5 * length * u])
    ax.plot(*ends.T, color=color, ls="-.", lw=1.2)
    ax.scatter(*r, color=color, s=12)
    if label is not None:
        ax.text(*ends[1], label, color=color)


def draw_screw_motion(ax, Ts, every=1, length=0.2):
    """Draw the path of the origin over a batch of transforms ``Ts`` (N, 4, 4), and every k-th frame."""
    Ts = check_transform(np.asarray(Ts, dtype=float), "Ts")
    if Ts.ndim != 3:
        raise ValueError(f"Ts must be a batch of transforms of shape (N, 4, 4), got shape {Ts.shape}")
    ax.plot(*Ts[:, :3, 3].T, color="0.4", lw=1)
    for T in Ts[::every]:
        draw_frame(ax, T, length=length, alpha=0.6)


def draw_chain(ax, chain, q, color="tab:gray", frames=False, label=None, alpha=1.0, frame_length=0.1):
    """Draw a serial chain at the joint vector q (n,) as a stick figure.

    Links join the frame origins; each joint axis is a short black segment; the tool frame is
    drawn, and with ``frames`` every link frame too. Returns the (n + 1, 4, 4) frames.
    """
    T = chain.frames(q)
    if T.ndim != 3:
        raise ValueError(f"q must be one joint vector of shape ({chain.n},), got a batch")
    origins = T[:, :3, 3]
    ax.plot(*origins.T, "-o", color=color, lw=4, ms=5, alpha=alpha, label=label,
            solid_capstyle="round")
    for z, o in zip(*chain.joint_axes(q)):
        ax.plot(*np.stack([o - 0.04 * z, o + 0.04 * z]).T, color="k", lw=2.5, alpha=alpha)
    for k, frame in enumerate(T):
        if frames or k == len(T) - 1:
            draw_frame(ax, frame, label=str(k) if frames else None, length=frame_length, alpha=alpha)
    return T


def draw_ellipsoid(ax, centre, radii, axes, scale=1.0, color="tab:orange", alpha=0.35):
    """Draw the ellipsoid centre + axes @ diag(radii) u over unit vectors u (see jacobians.ellipsoid).

    ``scale`` converts the radii to metres on the drawing (e.g. 0.2 m per m/s).
    """
    centre = check_shape(as_float_array(centre, "centre"), "centre", (3,))
    radii = check_shape(as_float_array(radii, "radii"), "radii", (3,))
    axes = check_shape(as_float_array(axes, "axes"), "axes", (3, 3))
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 37), np.linspace(0, np.pi, 19))
    sphere = np.stack([np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v)])
    surface = centre[:, None, None] + scale * np.einsum("ij,j,jkl->ikl", axes, radii, sphere)
    return ax.plot_surface(*surface, color=color, alpha=alpha, linewidth=0)


def draw_planar(ax, chain, q, color="tab:blue", alpha=1.0, label=None, base=(0.0, 0.0)):
    """Draw a planar arm (x-y plane) at q (n,) as a 2D stick figure; returns the line."""
    origins = chain.frames(q)[:, :2, 3] + np.asarray(base, dtype=float)
    (line,) = ax.plot(*origins.T, "-o", color=color, lw=3, ms=4, alpha=alpha, label=label,
                      solid_capstyle="round")
    return line


# matplotlib's player draws its buttons with Font Awesome from a CDN: the book must work offline
_PLAYER_ICONS = {"fa fa-minus": "\u2212", "fa fa-fast-backward": "|\u25c0", "fa fa-step-backward": "\u25c1|",
                 "fa fa-play fa-flip-horizontal": "\u25c0", "fa fa-pause": "\u275a\u275a",
                 "fa fa-play": "\u25b6", "fa fa-step-forward": "|\u25b7", "fa fa-fast-forward": "\u25b6|",
                 "fa fa-plus": "+"}


def animation_html(animation):
    """A matplotlib animation as self-contained JavaScript HTML (no request leaves the page).

    Like ``animation.to_jshtml()``, with the player's Font Awesome stylesheet (a CDN link) removed
    and its icons replaced by Unicode symbols. Display it with ``IPython.display.HTML``.
    """
    import re

    html = re.sub(r'<link rel="stylesheet"\s+href="[^"]*font-awesome[^"]*">', "", animation.to_jshtml())
    for icon, text in _PLAYER_ICONS.items():
        html = html.replace(f'<i class="{icon}"></i>', text)
    if "http://" in html or "https://" in html:
        raise RuntimeError("the animation's HTML still refers to an outside address")
    return html
