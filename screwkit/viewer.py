"""Interactive figures that compute in the page: no kernel, no server, nothing from a
CDN.

Each function returns a figure object that Jupyter (Lab, Notebook 7, VS Code, Colab) and
the built book display as HTML: a ``<div>`` holding the figure's parameters as JSON and
an inline ``<script>`` (the files of ``static/viewer/`` joined, see ``VIEWER_PARTS``)
that computes the kinematics in the browser and draws it in 3D with three.js (drag to
orbit; Ctrl+wheel, pinch or the buttons to zoom; arrow keys and +/- when focused;
double-click to reset). three.js is
vendored from npm (``static/vendor/``, see ``tools/vendor_js.py``), deflated, and
shipped once: with the first 3D viewer shown in a kernel session (so once per page of
the book); later viewers use it from the page. Python hands the page only parameters: a
chain's joint screws and home pose (the product of exponentials), a screw axis, a
platform's attachment points, a mechanism's joints, or frames precomputed for a grid of
slider values.

This module builds the figures of serial chains (:func:`robot_viewer`,
:func:`trajectory_viewer`, :func:`screw_motion_viewer`); the page side (the script,
three.js, :class:`Viewer`) is :mod:`screwkit._viewer_page`, the mechanisms' figures
:mod:`screwkit._viewer_mechanisms`, and the Matplotlib figures stepped in the page
:mod:`screwkit._stepped_figure`: all public here.
"""

import math

import numpy as np

from . import _sliders
from ._checks import (
    as_float_array,
    check_chain,
    check_shape,
    check_transform,
    describe,
)
from ._stepped_figure import grid, stepped_figure
from ._viewer_mechanisms import show_mechanism, show_platform
from ._viewer_page import (  # noqa: F401 (VIEWER_PARTS, _numbers: sk.viewer's own)
    VIEWER_PARTS,
    Viewer,
    _check_size,
    _classic_three,
    _numbers,
    library_script,
    resend_library,
    viewer_script,
)
from .links import Joint
from .tolerances import LENGTH_TOL, ZERO_TOL, length_scale
from .transforms import _is_infinite_pitch, _pitch

__all__ = [
    "robot_viewer",
    "trajectory_viewer",
    "screw_motion_viewer",
    "show_platform",
    "show_mechanism",
    "stepped_figure",
    "grid",
    "Viewer",
    "resend_library",
    "library_script",
]


def _check_chain(chain):
    check_chain(chain)
    if chain.n < 1:
        raise ValueError(
            f"chain must have at least one link to be drawn, got {chain.n} links"
        )


def _span(points):
    """Centre and radius (m) of a ball around ``points`` (k, 3), never smaller than 0.1
    m."""
    low, high = points.min(axis=0), points.max(axis=0)
    return (low + high) / 2, max(float(np.linalg.norm(high - low)) / 2, 0.1)


def robot_viewer(chain, q=None, ellipsoid=False, ellipsoid_scale=0.4, size=(520, 420)):
    """The chain in 3D with one slider per joint; forward kinematics computed in the
    page.

    Parameters
    ----------
    chain : Chain, n >= 1 joints
    q : array-like, shape (n,), optional
        The first pose (rad for revolute, m for prismatic joints); default zeros.
    ellipsoid : bool
        Draw the translational manipulability ellipsoid (rows v of the geometric
        Jacobian), and print its radii and w.
    ellipsoid_scale : float, optional
        The scale of the ellipsoid's radii on the drawing (m per m/s).
    size : (width, height) of the drawing in pixels

    Returns
    -------
    Viewer, displayed as HTML. Sliders in degrees (revolute) or metres (prismatic), each
    ranging over the joint's limits with its default on the slider's grid. The tool
    frame carries a two-finger gripper along its approach axis (the tool axis nearest
    the offset from the last joint's axis point to the tool, +z when there is none), so
    that the wrist's turn shows; a pose that reaches out of the view widens the view.
    The line under the drawing gives the tool's position (m) and its orientation as
    roll, pitch, yaw (deg, R = Rz(yaw) Ry(pitch) Rx(roll), as
    :func:`screwkit.orientation.rpy_from_rotation`). Joints are coloured as in the
    mobility figures: revolute blue, prismatic orange, helical purple.

    Examples
    --------
    In a notebook it shows the arm; its text says what the sliders are:

    >>> import screwkit as sk
    >>> robot_viewer(sk.robots.planar([1.0, 0.5]))
    planar 2R: sliders q1 (deg) [-180, 180] step 1 at 0,
    q2 (deg) [-180, 180] step 1 at 0
    """
    _check_chain(chain)
    specs = _sliders.slider_specs(chain, q)
    scale = as_float_array(ellipsoid_scale, "ellipsoid_scale")
    if scale.ndim or scale <= 0:
        raise ValueError(
            f"ellipsoid_scale must be one positive number (m per m/s), "
            f"got {ellipsoid_scale!r}"
        )
    width, height = _check_size(size)
    travel = sum(abs(s.high) + abs(s.low) for s in specs if s.unit == "m")
    model = {
        "kind": "robot",
        "width": width,
        "height": height,
        **_chain_model(chain, travel),
        "sliders": [s.as_dict() for s in specs],
        "ellipsoid": bool(ellipsoid),
        "ellipsoid_scale": float(scale),
        "label": _chain_label(chain, ellipsoid),
    }
    sliders = ", ".join(
        f"{s.description} [{s.low:g}, {s.high:g}] step {s.step:g} at {s.value:g}"
        for s in specs
    )
    extra = " with its manipulability ellipsoid" if ellipsoid else ""
    return Viewer(model, f"{chain.name}{extra}: sliders {sliders}")


def _chain_model(chain, travel=0.0):
    """What the page needs to pose the chain: its joint screws and home pose (product
    of exponentials), each joint's axis and point at q = 0, the joints' kinds, the
    gripper's approach axis, and a radius (m) the arm reaches within (its links' lengths
    and ``travel``, the prismatic joints' strokes)."""
    axes, points = chain.joint_axes(np.zeros(chain.n))
    home = chain.home()
    reach = np.vstack([[0.0, 0.0, 0.0], points, home[:3, 3]])
    radius = float(np.sum(np.linalg.norm(np.diff(reach, axis=0), axis=1)))
    return {
        "name": chain.name,
        "screws": _numbers(chain.screw_axes()),
        "home": _numbers(home),
        "points": _numbers(points),
        "axes": _numbers(axes),
        "joints": [joint.value for joint in chain.joints],
        "approach": _approach(home, points[-1]),
        "radius": max(radius + travel, 0.1),
        "centre": [0.0, 0.0, 0.0],
    }


#: The time slider's candidate steps (s), coarsest first (see :func:`trajectory_viewer`)
TIME_STEPS = (0.01, 0.005, 0.001)


def _joint_paths(paths, labels, n):
    """The trajectories as (labels, arrays (K, n)), checked, with the reason when
    wrong."""
    if isinstance(paths, dict):
        if labels is not None:
            raise ValueError(
                "labels must be None when paths is a dict (its keys are the labels), "
                f"got {labels!r}"
            )
        labels, paths = list(paths), list(paths.values())
    elif isinstance(paths, np.ndarray) or hasattr(paths, "q"):
        paths = [paths]
    elif not isinstance(paths, (list, tuple)):
        raise TypeError(
            "paths must be an array (K, n) of joint values, a list of them or a dict "
            f"{{label: array}}, got {describe(paths)}"
        )
    if not 1 <= len(paths) <= 4:
        raise ValueError(f"paths must hold 1 to 4 trajectories, got {len(paths)}")
    arrays = []
    for k, path in enumerate(paths):
        name = f"paths[{k}]"
        Q = as_float_array(getattr(path, "q", path), name)
        if Q.ndim != 2 or Q.shape[1] != n or Q.shape[0] < 2:
            raise ValueError(
                f"{name} must have shape (K, {n}) with K >= 2 samples, "
                f"got shape {Q.shape}"
            )
        if arrays and Q.shape[0] != arrays[0].shape[0]:
            raise ValueError(
                f"{name} must have as many samples as paths[0], "
                f"{arrays[0].shape[0]}, got {Q.shape[0]}"
            )
        arrays.append(Q)
    if labels is None:
        labels = [f"path {k + 1}" for k in range(len(arrays))]
    labels = [labels] if isinstance(labels, str) else list(labels)
    if len(labels) != len(arrays) or not all(isinstance(x, str) for x in labels):
        raise ValueError(
            f"labels must be {len(arrays)} names (str), one per path, got {labels!r}"
        )
    return labels, arrays


def trajectory_viewer(chain, paths, labels=None, times=None, size=(560, 460)):
    """Precomputed joint trajectories of one chain, played in the page: no kernel.

    Python computes the trajectories (a path of poses from
    :mod:`screwkit.motion.trajectory` through
    :func:`screwkit.motion.trajectory.follow_path`, or joint paths); the page poses
    one arm per trajectory by the product of exponentials, the first solid, the
    others translucent ghosts, each in its own colour (red, green, brown, pink), and
    draws each tool's path as a line in that colour, named at its middle. A play button
    runs the motion in real time; the time slider scrubs it; the line under the drawing
    gives the time and each tool's position. Between samples the page interpolates the
    joint values linearly.

    Parameters
    ----------
    chain : Chain, n >= 1 joints
    paths : array-like (K, n), or a list of up to 4 of them, or a dict {label: array};
        joint values (rad, m) at the K sample times; a
        :class:`screwkit.motion.trajectory.PathIK` (its ``q``) in place of an array
    labels : list of str, optional
        Each path's name (default 'path 1', ...; a dict's keys)
    times : array-like, shape (K,), optional
        Increasing sample times (s); default K samples over 2 s
    size : (width, height) of the drawing in pixels

    Returns
    -------
    Viewer, displayed as HTML: the arms, a play/pause button and a time slider from the
    first to the last time (s, on a grid of 0.01, 0.005 or 0.001 s that holds both).
    Revolute joints' paths are sent unwrapped (no jump of a whole turn between two
    samples, the same poses), so that the interpolation never spins a joint round.

    Examples
    --------
    One joint path of three samples, over the default 2 s:

    >>> import screwkit as sk
    >>> q = np.array([[0.0, 0.0], [0.5, 0.2], [1.0, 0.4]])
    >>> trajectory_viewer(sk.robots.planar([1.0, 0.5]), q)
    planar 2R: 1 trajectories of 3 samples over 0 to 2 s (path 1); play button and
    time slider
    """
    _check_chain(chain)
    labels, arrays = _joint_paths(paths, labels, chain.n)
    K = arrays[0].shape[0]
    if times is None:
        times = np.linspace(0.0, 2.0, K)
    times = as_float_array(times, "times")
    if times.shape != (K,) or not np.all(np.isfinite(times)):
        raise ValueError(
            f"times must be {K} finite sample times (s), one per sample, "
            f"got shape {times.shape}"
        )
    if np.any(np.diff(times) <= 0):
        raise ValueError(
            f"times must increase, got a step of {np.diff(times).min():g} s"
        )
    turning = np.array([joint is not Joint.PRISMATIC for joint in chain.joints])
    arrays = [np.where(turning, np.unwrap(Q, axis=0), Q) for Q in arrays]
    step = next(
        (
            s
            for s in TIME_STEPS
            if _sliders.on_grid(times[0], s) and _sliders.on_grid(times[-1], s)
        ),
        TIME_STEPS[-1],
    )
    slider = _sliders.slider_spec(
        "t", "s", times[0], times[-1], times[0], steps=(step,)
    )
    width, height = _check_size(size)
    model = {
        "kind": "trajectory",
        "width": width,
        "height": height,
        **_chain_model(chain),
        "paths": [
            {"label": label, "q": _numbers(Q)} for label, Q in zip(labels, arrays)
        ],
        "times": _numbers(times),
        "slider": slider.as_dict(),
    }
    colours = ("red", "green", "brown", "pink")
    named = ", ".join(
        f"{label} ({colours[k]}{', solid' if k == 0 else ', ghost'})"
        for k, label in enumerate(labels)
    )
    model["label"] = (
        f"{chain.name} following {len(labels)} precomputed trajectories over "
        f"{times[-1] - times[0]:g} s, drawn in 3D: one arm per trajectory with its "
        f"tool's path as a line, {named}. The play button below runs the motion, the "
        f"time slider sets the time; the text below gives each tool's position. Drag "
        f"or use the arrow keys to turn the view, + and - to zoom."
    )
    return Viewer(
        model,
        f"{chain.name}: {len(labels)} trajectories of {K} samples over "
        f"{times[0]:g} to {times[-1]:g} s ({', '.join(labels)}); play button and time "
        f"slider",
    )


def _approach(home, last_point):
    """The tool frame's axis the gripper is drawn along: [axis 0, 1 or 2, sign +-1].

    The axis of the home tool frame nearest the direction from the last joint's point
    to the tool (a flange offset along z, a planar arm's last link along x); +z when the
    tool sits on the last joint's axis point (the PUMA's wrist centre).
    """
    offset = home[:3, :3].T @ (home[:3, 3] - np.asarray(last_point, dtype=float))
    if np.linalg.norm(offset) < LENGTH_TOL * length_scale(home[:3, 3], last_point):
        return [2, 1]
    axis = int(np.argmax(np.abs(offset)))
    return [axis, 1 if offset[axis] > 0 else -1]


def _chain_label(chain, ellipsoid):
    """The canvas's accessible name: what the drawing shows and how to move it."""
    kinds = [joint.value for joint in chain.joints]
    counts = ", ".join(
        f"{kinds.count(k)} {word}"
        for k, word in (("R", "revolute"), ("P", "prismatic"), ("H", "helical"))
        if kinds.count(k)
    )
    extra = (
        ", its tool's manipulability ellipsoid drawn at the tool" if ellipsoid else ""
    )
    return (
        f"{chain.name}: a serial robot arm of {chain.n} joints ({counts}), drawn in 3D "
        "on a floor with numbered joints (blue cylinders revolute, orange boxes "
        "prismatic) and "
        "the tool frame with a two-finger gripper along its approach axis"
        f"{extra}. The sliders below set the joints; drag or use the arrow "
        f"keys to turn the view, + and - to zoom."
    )


def screw_motion_viewer(s, r, h, start=None, theta=None, size=(520, 420)):
    """A frame moved about the screw axis (s, r, h) by exp([xi] theta), computed in the
    page.

    Parameters
    ----------
    s : array-like, shape (3,), the axis direction (normalised here)
    r : array-like, shape (3,), a point of the axis (m)
    h : float, the pitch (m/rad); ``math.inf`` (``np.inf``) or ``sympy.oo`` for a pure
        translation along s, the one test of :func:`screwkit.screw_motion` (a string
        such as "inf" is refused, as everywhere in screwkit)
    start : array-like, shape (4, 4), the frame before the motion (default identity)
    theta : float, the slider's first value: deg, default 90 (or m for a translation,
        default 0.5)
    size : (width, height) of the drawing in pixels

    Returns
    -------
    Viewer with one slider theta in [-360, 360] deg (or d in [-1, 1] m for a
    translation).

    Examples
    --------
    A turn about the vertical line through (1, 0, 0), starting at 90 degrees:

    >>> screw_motion_viewer([0, 0, 1], [1, 0, 0], 0)
    screw motion about s = [0.0, 0.0, 1.0] through r = [1.0, 0.0, 0.0] m,
    pitch 0 m/rad: slider theta (deg) [-360, 360] step 1 at 90
    """
    s = check_shape(as_float_array(s, "s"), "s", (3,))
    r = check_shape(as_float_array(r, "r"), "r", (3,))
    if s.ndim != 1 or r.ndim != 1:
        raise ValueError(
            f"s and r must be single 3-vectors, got shapes {s.shape} and {r.shape}"
        )
    norm = float(np.linalg.norm(s))
    if norm < ZERO_TOL:
        raise ValueError(f"s must be a nonzero direction, got {s.tolist()}")
    translation = _is_infinite_pitch(h)
    if not translation:
        h = _pitch(h, exact=False)
    start = np.eye(4) if start is None else check_transform(start, "start")
    if start.ndim != 2:
        raise ValueError(
            f"start must be one transform of shape (4, 4), got shape {start.shape}"
        )
    width, height = _check_size(size)
    if theta is None:
        theta = 0.5 if translation else 90.0
    if translation:
        slider = _sliders.slider_spec("d", "m", -1.0, 1.0, theta, _sliders.LENGTH_STEPS)
    else:
        slider = _sliders.slider_spec(
            "theta", "deg", -360.0, 360.0, theta, _sliders.ANGLE_STEPS, math.pi / 180
        )
    s = s / norm
    centre, radius = _span(np.vstack([np.zeros(3), r, start[:3, 3]]))
    model = {
        "kind": "screw",
        "width": width,
        "height": height,
        "s": _numbers(s),
        "r": _numbers(r),
        "h": None if translation else float(h),
        "start": _numbers(start),
        "slider": slider.as_dict(),
        "radius": radius + 0.5,
        "centre": _numbers(centre),
    }
    pitch = "infinite (a translation)" if translation else f"{float(h):g} m/rad"
    model["label"] = (
        f"A coordinate frame moved by a screw motion about the axis through "
        f"{np.round(r, 3).tolist()} m along {np.round(s, 3).tolist()}, pitch "
        f"{pitch}, drawn in 3D with its start frame, the axis and the path of "
        f"its origin. The slider sets the motion; drag or use the arrow keys "
        f"to turn the view, + and - to zoom."
    )
    return Viewer(
        model,
        f"screw motion about s = {np.round(s, 3).tolist()} through "
        f"r = {np.round(r, 3).tolist()} m, pitch {pitch}: slider "
        f"{slider.description} [{slider.low:g}, {slider.high:g}] "
        f"step {slider.step:g} at {slider.value:g}",
    )
