"""Matplotlib drawings of frames, screw axes and screw motions (metres), in the course's
style.

Every chapter calls ``use_course_style()`` before its first figure: figures then fit the
book's content column (688 px, at most ``COLUMN_WIDTH`` inches at ``DPI``) with text of
at least 9 pt.

>>> ax = axes3d()
>>> draw_frame(ax, np.eye(4), label="0")
>>> plt.close(ax.figure)
"""

import base64
import hashlib
import html as html_module
import json
import re

import matplotlib.pyplot as plt
import numpy as np
import sympy as sp

from ._checks import (
    as_float_array,
    as_sympy_matrix,
    check_chain,
    check_integer,
    check_positive,
    check_transform,
    describe,
    is_symbolic,
)

# re-exported: sk.plotting.draw_mechanism
from ._line_plots import draw_configuration, draw_cylindroid, draw_lines  # noqa: F401
from ._mechanism_plot import draw_mechanism  # noqa: F401
from .tolerances import DRAWING_TOL, ZERO_TOL, length_scale

__all__ = [
    "COLUMN_WIDTH",
    "COURSE_STYLE",
    "DPI",
    "use_course_style",
    "axes3d",
    "draw_frame",
    "draw_screw_axis",
    "draw_screw_motion",
    "draw_chain",
    "draw_ellipsoid",
    "draw_planar",
    "animation_html",
    "draw_mechanism",
    "draw_lines",
    "draw_configuration",
    "draw_cylindroid",
]

AXIS_COLOURS = ("tab:red", "tab:green", "tab:blue")  # x, y, z

#: Pixels per inch of the course's figures.
#: A figure shows at its natural size in the book, where 1 pt of text is 100 / 72 =
#: 1.39 px, at least as large as a browser's 1.33 px per pt.
DPI = 100
#: The widest figure, in inches.
#: 660 px at ``DPI``, plus the 0.1 in margin IPython adds on each side when it trims a
#: figure (savefig.pad_inches): 680 px, within the 688 px column.
COLUMN_WIDTH = 6.6
#: The course's matplotlib style. Constrained layout keeps titles, labels and legends
#: inside the figure, so a saved figure is never wider than its figsize and IPython's
#: margin.
COURSE_STYLE = {
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "figure.figsize": (COLUMN_WIDTH, 4.0),
    "figure.constrained_layout.use": True,
    "font.size": 10.0,
    "axes.titlesize": 10.0,
    "axes.labelsize": 10.0,
    "xtick.labelsize": 9.0,
    "ytick.labelsize": 9.0,
    "legend.fontsize": 9.0,
    "legend.title_fontsize": 9.0,
    "figure.titlesize": 11.0,
}


def use_course_style():
    """Apply ``COURSE_STYLE`` to matplotlib: every figure made after the call uses it.

    Called once per chapter, before its first figure (in the book, a live notebook or
    Colab).

    Examples
    --------
    >>> use_course_style()
    >>> plt.rcParams["font.size"] == COURSE_STYLE["font.size"]
    True
    """
    plt.rcParams.update(COURSE_STYLE)


# ---- argument checks -----------------------------------------------------------------


def _check_axes(ax, three_d=True):
    """``ax`` must be a matplotlib Axes (a 3D one for the 3D drawings)."""
    from matplotlib.axes import Axes
    from mpl_toolkits.mplot3d import Axes3D

    kind, expected = (
        (Axes3D, "a 3D matplotlib Axes (from axes3d())")
        if three_d
        else (Axes, "a matplotlib Axes")
    )
    if not isinstance(ax, kind):
        raise TypeError(f"ax must be {expected}, got {describe(ax)}")
    return ax


def _numeric(value, name):
    """A float array from numbers, or from SymPy entries without free symbols
    (drawings are numeric)."""
    if not is_symbolic(value):
        return as_float_array(value, name)
    if isinstance(value, sp.Basic) and not isinstance(value, sp.MatrixBase):
        raise TypeError(
            f"{name} must be an array or matrix of numbers, got {describe(value)}"
        )
    matrix = (
        sp.Matrix(value)
        if isinstance(value, sp.MatrixBase)
        else as_sympy_matrix(value, name, (len(value), 1))
    )
    if matrix.free_symbols:
        symbols = ", ".join(sorted(str(s) for s in matrix.free_symbols))
        raise TypeError(
            f"{name} must be numeric to be drawn, got the symbols {symbols}; "
            "substitute values first"
        )
    try:
        return as_float_array(np.array(matrix.evalf(), dtype=float), name)
    except TypeError:
        raise TypeError(f"{name} must hold real numbers, got {list(matrix)}") from None


def _vector(value, name, size=3):
    vector = _numeric(value, name)
    if is_symbolic(value):
        vector = vector.reshape(-1)
    if vector.shape != (size,):
        raise ValueError(f"{name} must have shape ({size},), got shape {vector.shape}")
    return vector


def _alpha(alpha):
    alpha = as_float_array(alpha, "alpha")
    if alpha.shape != () or not 0 <= alpha <= 1:
        raise ValueError(f"alpha must be one number in [0, 1], got {alpha.tolist()!r}")
    return float(alpha)


def _one_q(chain, q):
    q = chain.check_q(q, "q")
    if q.ndim != 1:
        raise ValueError(
            f"q must be one joint vector of shape ({chain.n},), got shape {q.shape}"
        )
    return q


def _links(ax, origins, color, alpha, label, lw, ms):
    """The links as one thick, round-capped line through the joint origins (K, 2) or
    (K, 3), a dot at each; the Line2D."""
    (line,) = ax.plot(
        *origins.T,
        "-o",
        color=color,
        lw=lw,
        ms=ms,
        alpha=alpha,
        label=label,
        solid_capstyle="round",
    )
    return line


def axes3d(limits=((-1, 1), (-1, 1), (0, 2)), ax=None, figsize=(5, 5)):
    """A 3D axes with equal scale on x, y, z (m) and labelled axes.

    Parameters
    ----------
    limits : ((xmin, xmax), (ymin, ymax), (zmin, zmax)), optional
        The axes' limits (m).
    ax : mpl_toolkits.mplot3d.Axes3D or None, optional
        An existing 3D axes to set up, or None to create a figure.
    figsize : (float, float), optional
        The new figure's (width, height) in inches.

    Returns
    -------
    mpl_toolkits.mplot3d.Axes3D
        The axes.

    Examples
    --------
    >>> ax = axes3d()
    >>> [float(v) for v in ax.get_xlim() + ax.get_zlim()], ax.get_xlabel()
    ([-1.0, 1.0, 0.0, 2.0], 'x (m)')
    >>> plt.close(ax.figure)
    """
    limits = as_float_array(limits, "limits")
    if limits.shape != (3, 2):
        raise ValueError(
            "limits must be three (min, max) pairs, shape (3, 2), got shape "
            f"{limits.shape}"
        )
    if np.any(limits[:, 0] >= limits[:, 1]):
        raise ValueError(
            f"limits must have min < max on each axis, got {limits.tolist()}"
        )
    if ax is None:
        size = as_float_array(figsize, "figsize")
        if size.shape != (2,) or np.any(size <= 0):
            raise ValueError(
                "figsize must be (width, height) in inches, both positive, got "
                f"{figsize!r}"
            )
        figure = plt.figure(figsize=tuple(size))
        ax = figure.add_subplot(projection="3d")
    _check_axes(ax)
    ax.set_xlim(*limits[0])
    ax.set_ylim(*limits[1])
    ax.set_zlim(*limits[2])
    ax.set_box_aspect(limits[:, 1] - limits[:, 0])
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_zlabel("z (m)")
    return ax


def draw_frame(ax, T, label=None, length=0.3, alpha=1.0):
    """Draw the frame of a transform: x red, y green, z blue.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    T : array-like, shape (4, 4)
        The frame's pose (m).
    label : str or None, optional
        Written at the origin.
    length : float, optional
        The length of the axes drawn (m).
    alpha : float, optional
        Opacity.

    Examples
    --------
    Three lines, the axes x, y, z in red, green, blue, and the label:

    >>> ax = axes3d()
    >>> draw_frame(ax, np.eye(4), label="0")
    >>> [line.get_color() for line in ax.lines], len(ax.texts)
    (['tab:red', 'tab:green', 'tab:blue'], 1)
    >>> plt.close(ax.figure)
    """
    _check_axes(ax)
    T = check_transform(_numeric(T, "T"), "T")
    if T.ndim != 2:
        raise ValueError(
            f"T must be one transform of shape (4, 4), got shape {T.shape}"
        )
    length, alpha = check_positive(length, "length"), _alpha(alpha)
    origin = T[:3, 3]
    for k in range(3):
        tip = origin + length * T[:3, k]
        ax.plot(*np.stack([origin, tip]).T, color=AXIS_COLOURS[k], lw=2, alpha=alpha)
    if label is not None:
        # beside the origin, away from the x and y arrows, on a pale patch over the
        # links
        ax.text(
            *(origin - 0.35 * length * (T[:3, 0] + T[:3, 1])),
            f"{{{label}}}",
            fontsize=10,
            ha="center",
            va="center",
            bbox={
                "boxstyle": "round,pad=0.1",
                "fc": "white",
                "ec": "none",
                "alpha": 0.8,
            },
        )


def draw_screw_axis(ax, s, r, length=2.0, label=None, color="k"):
    """Draw the screw axis through point ``r`` with direction ``s`` as a dash-dot line.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    s : array-like, shape (3,)
        The direction.
    r : array-like, shape (3,)
        A point of the axis (m).
    length : float, optional
        The length drawn, centred on r (m).
    label : str or None, optional
        The legend's label.
    color : str, optional
        A matplotlib colour.

    Examples
    --------
    The vertical axis through (1, 0, 0), 2 m long, centred on that point:

    >>> ax = axes3d()
    >>> draw_screw_axis(ax, [0, 0, 1], [1, 0, 0], length=2.0)
    >>> np.array(ax.lines[0].get_data_3d()).round(12).tolist()  # x, y, z of its ends
    [[1.0, 1.0], [0.0, 0.0], [-1.0, 1.0]]
    >>> plt.close(ax.figure)
    """
    _check_axes(ax)
    s, r = _vector(s, "s"), _vector(r, "r")
    length = check_positive(length, "length")
    if np.linalg.norm(s) < ZERO_TOL:
        raise ValueError(f"s must be a non-zero 3-vector, got {s.tolist()}")
    u = s / np.linalg.norm(s)
    ends = np.stack([r - 0.5 * length * u, r + 0.5 * length * u])
    ax.plot(*ends.T, color=color, ls="-.", lw=1.2)
    ax.scatter(*r, color=color, s=12)
    if label is not None:
        ax.text(*ends[1], label, color=color)


def draw_screw_motion(ax, Ts, every=1, length=0.2):
    """Draw the path of the origin over a batch of transforms, and every k-th frame.

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    Ts : array-like, shape (N, 4, 4)
        The transforms (m).
    every : int, optional
        k: draw the frame of every k-th transform.
    length : float, optional
        The length of the frames' axes (m).

    Examples
    --------
    Five poses of a half turn about the line x = 1: one line for the path, and the
    frames of poses 0, 2 and 4 (three lines each).

    >>> import screwkit as sk
    >>> ax = axes3d()
    >>> poses = sk.exp_twist([0, 0, 1, 0, -1, 0], np.linspace(0, np.pi, 5))
    >>> draw_screw_motion(ax, poses, every=2)
    >>> len(ax.lines)
    10
    >>> plt.close(ax.figure)
    """
    _check_axes(ax)
    Ts = check_transform(as_float_array(Ts, "Ts"), "Ts")
    if Ts.ndim != 3 or len(Ts) < 1:
        raise ValueError(
            "Ts must be a batch of transforms of shape (N, 4, 4), N >= 1, got shape "
            f"{Ts.shape}"
        )
    every = check_integer(every, "every", minimum=1)
    length = check_positive(length, "length")
    ax.plot(*Ts[:, :3, 3].T, color="0.4", lw=1)
    for T in Ts[::every]:
        draw_frame(ax, T, length=length, alpha=0.6)


def draw_chain(
    ax,
    chain,
    q,
    color="tab:gray",
    frames=False,
    label=None,
    alpha=1.0,
    frame_length=0.1,
):
    """Draw a serial chain at the joint vector q (n,) as a stick figure.

    Links join the frame origins; each joint axis is a short black segment; the tool
    frame is drawn, and with ``frames`` every link frame too, labelled once per point:
    frames that share an origin (the PUMA's {0} and {1}, or {4}, {5} and {6} at its
    wrist) get one label "{0, 1}".

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    chain : Chain
        The chain.
    q : array-like, shape (n,)
        Joint values (rad or m).
    color : str, optional
        The links' colour.
    frames : bool, optional
        Draw every link frame too.
    label : str or None, optional
        The legend's label.
    alpha : float, optional
        Opacity.
    frame_length : float, optional
        The length of the frames' axes (m).

    Returns
    -------
    ndarray, shape (n + 1, 4, 4)
        The frames, as ``chain.frames(q)``.

    Examples
    --------
    A planar 2R arm, elbow at 90 deg: its last frame is at the tip, (1, 1, 0).

    >>> import screwkit as sk
    >>> ax = axes3d()
    >>> frames = draw_chain(ax, sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> frames.shape, frames[-1][:3, 3].round(12) + 0.0
    ((3, 4, 4), array([1., 1., 0.]))
    >>> plt.close(ax.figure)
    """
    _check_axes(ax)
    chain = check_chain(chain)
    q = _one_q(chain, q)
    alpha, frame_length = _alpha(alpha), check_positive(frame_length, "frame_length")
    T = chain.frames(q)
    origins = T[:, :3, 3]
    _links(ax, origins, color, alpha, label, lw=4, ms=5)
    for z, o in zip(*chain.joint_axes(q)):
        ax.plot(
            *np.stack([o - 0.04 * z, o + 0.04 * z]).T, color="k", lw=2.5, alpha=alpha
        )
    labels = _shared_origin_labels(origins) if frames else {}
    for k, frame in enumerate(T):
        if frames or k == len(T) - 1:
            draw_frame(ax, frame, label=labels.get(k), length=frame_length, alpha=alpha)
    return T


def _shared_origin_labels(origins):
    """{index of the last frame at a point: "0, 1"} for frame origins (m) that
    coincide (to ``DRAWING_TOL`` times the frames' size)."""
    tolerance = DRAWING_TOL * length_scale(origins)
    groups = []
    for k, origin in enumerate(origins):
        for group in groups:
            if np.linalg.norm(origins[group[0]] - origin) < tolerance:
                group.append(k)
                break
        else:
            groups.append([k])
    return {group[-1]: ", ".join(str(k) for k in group) for group in groups}


def draw_ellipsoid(ax, centre, radii, axes, scale=1.0, color="tab:orange", alpha=0.35):
    """Draw the ellipsoid centre + axes @ diag(radii) u over unit vectors u
    (see jacobians.ellipsoid).

    Parameters
    ----------
    ax : mpl_toolkits.mplot3d.Axes3D
        Where to draw.
    centre : array-like, shape (3,)
        The centre (m).
    radii : array-like, shape (3,)
        The semi-axes (m/s or rad/s, as jacobians.ellipsoid gives them).
    axes : array-like, shape (3, 3)
        Their directions, as columns.
    scale : float, optional
        Converts the radii to metres on the drawing (e.g. 0.2 m per m/s).
    color : str, optional
        A matplotlib colour.
    alpha : float, optional
        Opacity.

    Returns
    -------
    mpl_toolkits.mplot3d.art3d.Poly3DCollection
        The surface.

    Examples
    --------
    >>> ax = axes3d()
    >>> surface = draw_ellipsoid(ax, [0, 0, 1], [0.5, 0.3, 0.2], np.eye(3))
    >>> type(surface).__name__
    'Poly3DCollection'
    >>> plt.close(ax.figure)
    """
    _check_axes(ax)
    centre, radii = _vector(centre, "centre"), _vector(radii, "radii")
    if np.any(radii < 0):
        raise ValueError(f"radii must be >= 0, got {radii.tolist()}")
    axes = as_float_array(axes, "axes")
    if axes.shape != (3, 3):
        raise ValueError(
            f"axes must have shape (3, 3), one axis per column, got shape {axes.shape}"
        )
    scale, alpha = check_positive(scale, "scale"), _alpha(alpha)
    u, v = np.meshgrid(np.linspace(0, 2 * np.pi, 37), np.linspace(0, np.pi, 19))
    sphere = np.stack([np.cos(u) * np.sin(v), np.sin(u) * np.sin(v), np.cos(v)])
    surface = centre[:, None, None] + scale * np.einsum(
        "ij,j,jkl->ikl", axes, radii, sphere
    )
    return ax.plot_surface(*surface, color=color, alpha=alpha, linewidth=0)


def draw_planar(ax, chain, q, color="tab:blue", alpha=1.0, label=None, base=(0.0, 0.0)):
    """Draw a planar arm (x-y plane) as a 2D stick figure.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        Where to draw.
    chain : Chain
        A planar arm (:func:`screwkit.robots.planar`).
    q : array-like, shape (n,)
        Joint angles (rad).
    color : str, optional
        A matplotlib colour.
    alpha : float, optional
        Opacity.
    label : str or None, optional
        The legend's label.
    base : (float, float), optional
        Where the arm's base is drawn (m).

    Returns
    -------
    matplotlib.lines.Line2D
        The line.

    Examples
    --------
    Base, elbow (1, 0) and tip (1, 1) of a 2R arm with the elbow at 90 deg:

    >>> import screwkit as sk
    >>> figure, ax = plt.subplots()
    >>> line = draw_planar(ax, sk.robots.planar([1.0, 1.0]), [0.0, np.pi / 2])
    >>> np.array(line.get_data()).T.round(12).tolist()
    [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]
    >>> plt.close(figure)
    """
    _check_axes(ax, three_d=False)
    chain = check_chain(chain)
    q = _one_q(chain, q)
    base, alpha = _vector(base, "base", size=2), _alpha(alpha)
    origins = chain.frames(q)[:, :2, 3] + base
    return _links(ax, origins, color, alpha, label, lw=3, ms=4)


# The player of ``animation_html``: its frames are loaded one at a time, when shown
# (the book turns them into image files, book/_ext/light_pages.py), so a page does not
# download a whole animation before its reader presses play.
_PLAYER = """<figure class="screwkit-animation" id="{id}">
<img src="{first}" alt="{alt}" width="{width}" height="{height}" data-alt="{alt_source}"
     style="max-width: 100%; height: auto">
<div class="screwkit-animation-controls" style="display: flex; gap: 0.5em; align-items: center">
<button type="button" aria-label="Play the animation" style="min-width: 2.5em">\u25b6</button>
<input type="range" min="0" max="{last}" step="1" value="0" aria-label="{label}"
       aria-valuetext="frame 1 of {count}" style="flex: 1">
<output aria-hidden="true" style="min-width: 4.5em; font-variant-numeric: tabular-nums">1 / {count}</output>
</div>
<script type="application/json" class="screwkit-animation-frames">{frames}</script>
<script>
(function () {{
  var root = document.getElementById("{id}"), img = root.querySelector("img");
  var slider = root.querySelector("input"), button = root.querySelector("button");
  var readout = root.querySelector("output");
  var frames = [img.getAttribute("src")].concat(JSON.parse(root.querySelector(
      "script.screwkit-animation-frames").textContent));
  var current = 0, timer = null;
  function show(k) {{
    current = k;
    img.src = frames[k];
    slider.value = k;
    slider.setAttribute("aria-valuetext", "frame " + (k + 1) + " of " + frames.length);
    readout.textContent = (k + 1) + " / " + frames.length;
    new Image().src = frames[(k + 1) % frames.length];  // the next one, ahead of time
  }}
  function stop() {{
    clearInterval(timer); timer = null;
    button.textContent = "\u25b6"; button.setAttribute("aria-label", "Play the animation");
  }}
  button.addEventListener("click", function () {{
    if (timer !== null) {{ stop(); return; }}
    button.textContent = "\u275a\u275a"; button.setAttribute("aria-label", "Pause the animation");
    timer = setInterval(function () {{ show((current + 1) % frames.length); }}, {interval});
  }});
  slider.addEventListener("input", function () {{ stop(); show(+slider.value); }});
}})();
</script>
</figure>"""  # noqa: E501 (HTML and JavaScript: its lines are the string's text)


def _describe_figure(figure, count):
    """A sentence on what an animated figure shows, from its axes' titles, labels and
    legends."""
    panels = []
    for ax in figure.get_axes():
        words = ax.get_title() or (
            f"{ax.get_ylabel()} against {ax.get_xlabel()}"
            if ax.get_xlabel() and ax.get_ylabel()
            else ""
        )
        legend = ax.get_legend()
        if legend is not None:
            names = ", ".join(t.get_text() for t in legend.get_texts())
            words = f"{words} ({names})" if words else names
        if words:
            panels.append(words)
    what = "; ".join(panels) if panels else "a matplotlib figure"
    what = re.sub(
        r"[$\\{}^]", "", what.replace("$^2$", "\u00b2").replace("$^3$", "\u00b3")
    )
    return f"An animation of {count} frames: {what}."


def animation_html(animation, alt=None, label="Frame of the animation"):
    """A matplotlib animation as self-contained HTML with a small player
    (no request leaves the page).

    The frames are rendered by matplotlib (as ``animation.to_jshtml()`` does) and
    embedded as PNG data; the page shows one at a time, with a play/pause button and a
    slider. The output depends only on the frames, so it is the same at every run.
    Display it with ``IPython.display.HTML``.

    Parameters
    ----------
    animation : matplotlib.animation.Animation
        The animation.
    alt : str or None, optional
        The image's text for readers who do not see it (default: a sentence built
        from the axes' titles, labels and legends; the book replaces it by the cell's
        ``mystnb.image.alt``).
    label : str, optional
        Names the slider.

    Returns
    -------
    str
        The HTML.

    Examples
    --------
    A dot moving in three frames: three PNG frames and a player that starts at 1 / 3.

    >>> from matplotlib.animation import FuncAnimation
    >>> figure, ax = plt.subplots(figsize=(2, 2))
    >>> (dot,) = ax.plot([0], [0], "o")
    >>> animation = FuncAnimation(figure, lambda k: dot.set_data([k], [k]), frames=3)
    >>> html = animation_html(animation, alt="A dot moving")
    >>> html.count("data:image/png"), "1 / 3" in html, "A dot moving" in html
    (3, True, True)
    >>> plt.close(figure)
    """
    from matplotlib.animation import Animation

    if not isinstance(animation, Animation):
        raise TypeError(
            "animation must be a matplotlib Animation (e.g. FuncAnimation), got "
            f"{describe(animation)}"
        )
    for value, name in ((alt, "alt"), (label, "label")):
        if value is not None and not (isinstance(value, str) and value.strip()):
            raise TypeError(f"{name} must be a non-empty string, got {describe(value)}")
    exported = animation.to_jshtml()
    frames = [
        uri.replace("\\\n", "")
        for uri in re.findall(
            r'frames\[\d+\] = "(data:image/\w+;base64,[^"]*)"', exported, re.S
        )
    ]
    if not frames:
        raise RuntimeError("matplotlib exported the animation without frames")
    png = base64.b64decode(frames[0].split(",", 1)[1][:48])  # the header: width, height
    width, height = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    count = len(frames)
    text = alt if alt is not None else _describe_figure(animation._fig, count)
    digest = hashlib.sha256("".join(frames).encode()).hexdigest()[:12]
    return _PLAYER.format(
        id=f"screwkit-animation-{digest}",
        first=frames[0],
        width=width,
        height=height,
        alt=html_module.escape(text, quote=True),
        alt_source="given" if alt else "auto",
        label=html_module.escape(label, quote=True),
        last=count - 1,
        count=count,
        frames=json.dumps(frames[1:]),
        interval=int(round(animation._interval)),
    )
