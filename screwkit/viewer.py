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
"""

import base64
import hashlib
import html
import io
import itertools
import json
import math
import re
import zlib
from importlib import resources

import numpy as np

from . import _sliders
from ._checks import (
    as_float_array,
    check_chain,
    check_flag,
    check_positive,
    check_shape,
    check_transform,
    describe,
)
from .links import Joint
from .tolerances import LENGTH_TOL, PARALLEL_TOL, ZERO_TOL, length_scale
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

_ids = itertools.count(1)
_library = {"shipped": False, "script": None}


#: The parts of the viewers' one script (package data ``screwkit/static/viewer/``), in
#: the order they are joined: together they are the body of one function, written once
#: per page. Each file is one concern; the join adds nothing between them.
VIEWER_PARTS = (
    "header.js",  # what the script is; the function's start; run once per page
    "kinematics.js",  # exp of a twist, a chain's FK, Jacobian, ellipsoid, platform legs
    "style.js",  # the viewers' stylesheet and a DOM element helper
    "scene.js",  # the three.js stage: renderer, camera, meshes, framing, labels
    "controls.js",  # the stage's pointer, wheel, keyboard and resize handlers
    "figures.js",  # robot, trajectory, screw motion, platform, mechanism on a stage
    "page.js",  # sliders, readouts, aria-live captions, mounting, window.screwkit
)


def viewer_script():
    """The JavaScript of every viewer: the files of ``VIEWER_PARTS`` joined in order.

    Returns
    -------
    str
        One classic script that defines ``window.screwkit`` and mounts the page's
        viewers.
    """
    folder = resources.files("screwkit").joinpath("static/viewer")
    return "".join(
        folder.joinpath(part).read_text(encoding="utf-8") for part in VIEWER_PARTS
    )


def _vendored(name):
    return (
        resources.files("screwkit")
        .joinpath(f"static/vendor/{name}")
        .read_text(encoding="utf-8")
    )


def _classic_three():
    """three.js as a classic script that sets ``window.THREE`` (once: guarded in the
    page).

    The vendored file is npm's ``three/build/three.module.min.js``, byte for byte; its
    one ``export {local as Name, ...}`` clause becomes ``window.THREE = {Name: local,
    ...}`` inside a function, so that the page needs no module loader and no URL.
    """
    source = _vendored("three.module.min.js")
    start = source.rindex("export{")
    end = source.index("}", start)
    if source[end + 1 :].strip() not in ("", ";"):
        raise RuntimeError("three.module.min.js does not end with its export clause")
    names = []
    for item in source[start + len("export{") : end].split(","):
        match = re.fullmatch(r"\s*([\w$]+)(?:\s+as\s+([\w$]+))?\s*", item)
        if match is None:
            raise RuntimeError(f"three.module.min.js: cannot read the export {item!r}")
        local, name = match.group(1), match.group(2) or match.group(1)
        names.append(f"{name}:{local}")
    return (
        'if(!window.THREE){(function(){"use strict";'
        + source[:start]
        + ";window.THREE={"
        + ",".join(names)
        + "};})();}"
    )


def library_script():
    """The script that puts three.js in the page (a classic script, deflated).

    three.js travels as raw deflate in base64 (221 kB instead of 668 kB); npm's
    tiny-inflate (vendored too) inflates it synchronously and the text runs as a script
    element, so that ``window.THREE`` exists before the next script of the page runs.
    Then it mounts every viewer that was waiting for it.

    Returns
    -------
    str
        The script's JavaScript text.
    """
    if _library["script"] is None:
        text = _classic_three().encode("utf-8")
        packer = zlib.compressobj(9, zlib.DEFLATED, -15)
        packed = base64.b64encode(packer.compress(text) + packer.flush()).decode(
            "ascii"
        )
        _library["script"] = (
            "if(!window.THREE){(function(){var module={exports:{}};"
            "(function(module){" + _vendored("tiny-inflate.js") + "\n})(module);"
            f'var b=atob("{packed}"),z=new Uint8Array(b.length),i;'
            "for(i=0;i<b.length;i++)z[i]=b.charCodeAt(i);"
            f"var t=new Uint8Array({len(text)});module.exports(z,t);"
            'var s=document.createElement("script");'
            "s.textContent=new TextDecoder().decode(t);"
            "(document.head||document.documentElement).appendChild(s);})();}"
            "if(window.screwkit)window.screwkit.mountAll();"
        )
    return _library["script"]


def resend_library():
    """Ship three.js again with the next viewer (after the output that carried it was
    cleared)."""
    _library["shipped"] = False


#: What a 3D viewer shows until three.js is in the page (removed when it mounts).
_WAITING = (
    '<div class="screwkit-note">Waiting for the 3D library, which comes with the '
    "first 3D viewer of this page or kernel session (if that output was cleared, run "
    "<code>screwkit.viewer.resend_library()</code> and show this figure again).</div>\n"
)


class Viewer:
    """A figure for the page, drawn by ``viewer.js``.

    Parameters
    ----------
    model : dict
        The figure's parameters, JSON-ready.
    summary : str
        Its plain-text form (what a terminal or a text-only output shows).
    """

    def __init__(self, model, summary):
        self.model = model
        self.summary = summary
        payload = json.dumps(model, sort_keys=True, separators=(",", ":"))
        digest = hashlib.sha1(payload.encode()).hexdigest()[:10]
        self.id = f"screwkit-{digest}-{next(_ids)}"
        self._payload = payload
        self._carries_library = None

    def __repr__(self):
        return self.summary

    def html(self, library=None):
        """The figure's HTML.

        three.js and ``viewer.js`` come together. By default (None) they come with every
        3D figure until one has been displayed on its own (``_repr_mimebundle_``, what
        Jupyter and the book call), then with that figure only: once per kernel session,
        so once per page of the book; later figures carry only their parameters and
        mount when the scripts are in the page, in whatever order the outputs are
        rendered. A figure shown as the page fallback of a live widget (``_repr_html_``)
        carries them while none has been displayed, since Lab may draw the widget
        instead. Stepped figures need no three.js and always carry ``viewer.js``.

        Parameters
        ----------
        library : bool or None, optional
            True/False: include three.js and ``viewer.js`` or not; None: as above.

        Returns
        -------
        str
            The HTML.
        """
        if library is not None:
            library = check_flag(library, "library")
        needs = self.model["kind"] != "steps"
        if library is None:
            library = self._carries_library
            if library is None:
                library = needs and not _library["shipped"]
        payload = self._payload.replace("</", "<\\/")
        note = "" if not needs else _WAITING
        parts = [
            f'<div class="screwkit-viewer" id="{self.id}">\n'
            f'<script type="application/json">{payload}</script>\n{note}'
            f"<noscript>{html.escape(self.summary)}</noscript>\n</div>\n"
        ]
        if library and needs:
            parts.append(f"<script>\n{library_script()}\n</script>\n")
        if library or not needs:  # later 3D viewers use the script already in the page
            parts.append(f"<script>\n{viewer_script()}</script>\n")
        parts.append(
            f"<script>window.screwkit && window.screwkit.mount("
            f"document.getElementById({json.dumps(self.id)}) || "
            "document.currentScript.parentNode.querySelector("
            f"\"[id='{self.id}']\"));</script>\n"
        )
        return "".join(parts)

    def _repr_html_(self):
        return self.html()

    def _repr_mimebundle_(self, include=None, exclude=None):
        if self._carries_library is None:
            self._carries_library = (
                self.model["kind"] != "steps" and not _library["shipped"]
            )
            _library["shipped"] = _library["shipped"] or self._carries_library
        return {"text/plain": self.summary, "text/html": self.html()}

    def page(self, title=None):
        """A whole HTML page holding this figure and three.js (for a file or a
        browser).

        Parameters
        ----------
        title : str or None, optional
            The page's title; by default the model's name, else "screwkit viewer".

        Returns
        -------
        str
            The page's HTML.
        """
        if title is not None and not isinstance(title, str):
            raise TypeError(f"title must be a str or None, got {describe(title)}")
        title = html.escape(title or self.model.get("name") or "screwkit viewer")
        return (
            '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8">'
            '<meta name="viewport" content="width=device-width, initial-scale=1">'
            f"<title>{title}</title></head><body>\n{self.html(library=True)}"
            "</body></html>\n"
        )


def _numbers(array, digits=12):
    """Nested lists of floats rounded to ``digits`` significant digits (stable JSON)."""
    return np.vectorize(lambda x: float(f"{x:.{digits}g}") + 0.0)(
        np.asarray(array)
    ).tolist()


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


def _points(value, name, m=None):
    """An (m, 3) array of finite floats (m), with the reason when it is not one."""
    array = as_float_array(value, name)
    if (
        array.ndim != 2
        or array.shape[1] != 3
        or (m is not None and array.shape[0] != m)
    ):
        rows = "m" if m is None else str(m)
        raise ValueError(f"{name} must have shape ({rows}, 3), got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name} must be finite, got {array.tolist()}")
    return array


def _platform_parts(pm):
    """The duck-typed parallel manipulator's parts, checked, with the reason when
    wrong."""
    missing = [
        a
        for a in (
            "base_points",
            "platform_points",
            "home",
            "leg_limits",
            "name",
            "planar",
        )
        if not hasattr(pm, a)
    ]
    if missing:
        raise TypeError(
            f"pm must be a parallel manipulator with base_points, "
            f"platform_points, home(), leg_limits, name and planar; "
            f"{describe(pm)} has no {', '.join(missing)}"
        )
    base = _points(pm.base_points, "pm.base_points")
    if base.shape[0] < 2:
        raise ValueError(
            f"pm.base_points must hold at least 2 legs, got {base.shape[0]}"
        )
    platform = _points(pm.platform_points, "pm.platform_points", base.shape[0])
    home = check_transform(pm.home(), "pm.home()")
    if home.ndim != 2:
        raise ValueError(
            f"pm.home() must be one transform of shape (4, 4), got {home.shape}"
        )
    limits = None
    if pm.leg_limits is not None:
        limits = as_float_array(pm.leg_limits, "pm.leg_limits")
        if limits.shape != (base.shape[0], 2) or np.any(limits[:, 0] > limits[:, 1]):
            raise ValueError(
                f"pm.leg_limits must be ({base.shape[0]}, 2) rows [low, high] "
                f"(m), got {limits.tolist()}"
            )
    return base, platform, home, limits


def show_platform(
    pm, pose=None, translation=None, rotation=30.0, yaw=120.0, size=(560, 480)
):
    """A parallel manipulator's platform moved by sliders; leg lengths computed in the
    page.

    Parameters
    ----------
    pm : a parallel manipulator: ``base_points`` (m, 3) in m, base frame;
        ``platform_points`` (m, 3) in m, platform frame; ``home()`` -> (4, 4) platform
        pose; ``leg_limits`` (m, 2) [low, high] in m, or None; ``name`` str; ``planar``
        bool (platform moving in the base's xy plane)
    pose : array-like, optional, the first slider values, the platform's pose itself
        (not an offset): (x, y, z, roll, pitch, yaw) in m and deg (planar: (x, y,
        phi)); default the home pose's
    translation : float, optional, each position slider's range +- (m) about home;
        default a third of the base's size
    rotation : float, the roll and pitch sliders' range +- (deg) about home
    yaw : float, the yaw (planar: phi) slider's range +- (deg) about home; the default
        120 reaches a Gough-Stewart platform's singular turn of 90 deg about its axis
    size : (width, height) in pixels: the drawing's proportions (it fills its column)

    Returns
    -------
    Viewer. The sliders are absolute: the page poses the platform at T = Trans(x, y, z)
    Rz(yaw) Ry(pitch) Rx(roll) (planar: Trans(x, y, z_home) Rz(phi), seen from
    above), draws leg i from a_i to p + R b_i, prints every length |p + R b_i - a_i|
    (m) and marks a leg outside its limits.
    """
    from .orientation import rpy_from_rotation

    base, platform, home, limits = _platform_parts(pm)
    planar = bool(pm.planar)
    width, height = _check_size(size)
    span = float(np.ptp(base, axis=0).max())
    if translation is None:
        translation = max(round(span / 3, 2), 0.01)
    reach = check_positive(translation, "translation")
    tilt = check_positive(rotation, "rotation")
    turn = check_positive(yaw, "yaw")
    for value, name in ((tilt, "rotation"), (turn, "yaw")):
        if value > 180:
            raise ValueError(f"{name} must be at most 180 deg, got {value:g}")
    angles = np.degrees(rpy_from_rotation(home[:3, :3]))
    if planar:
        names = [("x", "m", reach), ("y", "m", reach), ("phi", "deg", turn)]
        at_home = [home[0, 3], home[1, 3], angles[2]]
    else:
        names = [
            ("x", "m", reach),
            ("y", "m", reach),
            ("z", "m", reach),
            ("roll", "deg", tilt),
            ("pitch", "deg", tilt),
            ("yaw", "deg", turn),
        ]
        at_home = [*home[:3, 3], *angles]
    at_home = np.round(at_home, 9) + 0.0
    start = at_home if pose is None else as_float_array(pose, "pose")
    if start.shape != (len(names),):
        raise ValueError(
            f"pose must have {len(names)} entries "
            f"({', '.join(n for n, _, _ in names)}), got shape {start.shape}"
        )
    specs = []
    for k, ((label, unit, half), centre, value) in enumerate(
        zip(names, at_home, start)
    ):
        if not centre - half <= value <= centre + half:
            raise ValueError(
                f"pose[{k}] ({label}) must lie within +-{half:g} {unit} of the home "
                f"pose's {centre:g} {unit} (the slider's range), got {value:g} {unit}"
            )
        if unit == "m":
            steps, scale = _sliders.LENGTH_STEPS, 1.0
        else:
            steps, scale = _sliders.ANGLE_STEPS, math.pi / 180
        specs.append(
            _sliders.slider_spec(
                label, unit, centre - half, centre + half, value, steps, scale
            )
        )
    name = str(pm.name)
    legs = base.shape[0]
    limits_text = (
        "; a leg outside its length limits is drawn red" if limits is not None else ""
    )
    model = {
        "kind": "platform",
        "name": name,
        "width": width,
        "height": height,
        "base": _numbers(base),
        "platform": _numbers(platform),
        "home": _numbers(home),
        "limits": None if limits is None else _numbers(limits),
        "planar": planar,
        "sliders": [s.as_dict() for s in specs],
        "label": (
            f"{name}: a {'planar ' if planar else ''}parallel manipulator whose "
            f"platform is held by {legs} numbered legs from the base, drawn in 3D"
            f"{' from above' if planar else ''}{limits_text}. The sliders below set "
            f"the platform's pose (position in m, angles in deg); the text below "
            f"gives each leg's length. Drag or use the arrow keys to turn the view, "
            f"+ and - to zoom."
        ),
    }
    sliders = ", ".join(
        f"{s.description} [{s.low:g}, {s.high:g}] at {s.value:g}" for s in specs
    )
    return Viewer(model, f"{name}: {legs} legs; sliders {sliders}")


def _parallelograms(limb):
    """Index quadruples (i, i+1, i+2, i+3) of a limb's joints that make a
    parallelogram."""
    found = []
    i = 0
    while i + 3 < len(limb):
        (k0, s0, a1), (k1, s1, a2), (k2, s2, b1), (k3, s3, b2) = limb[i : i + 4]
        parallel = all(
            abs(abs(float(np.dot(s0, s))) - 1) < PARALLEL_TOL for s in (s1, s2, s3)
        )
        tol = LENGTH_TOL * length_scale(a1, a2, b1, b2)
        if (
            {k0, k1, k2, k3} == {"revolute"}
            and parallel
            and np.allclose(b1 - a1, b2 - a2, atol=tol)
            and np.linalg.norm(a2 - a1) > tol
            and np.linalg.norm(b1 - a1) > tol
        ):
            found.append(i)
            i += 4
        else:
            i += 1
    return found


def show_mechanism(limbs, values=None, twists=None, title=None, size=(560, 480)):
    """A parallel mechanism in 3D, rotatable in the page: base, platform, limbs, joint
    axes.

    Parameters
    ----------
    limbs : list of limbs (each a list of (s, r, h) joint screws, as
        :func:`screwkit.mobility`
        takes them), or the name of a catalogue mechanism ('pm_3prpar', ...)
    values : dict {symbol or name: number} (m, rad); default the catalogue's
        ``robots.DRAWING_VALUES`` for a named mechanism
    twists : optional platform twists (Twist objects, or a Mobility): drawn as arrows at
        the
        platform's centre, red for rotations (along their axis), green for translations
    title : the mechanism's name in the label (default the catalogue name, or
        'mechanism')
    size : (width, height) in pixels: the drawing's proportions (it fills its column)

    Returns
    -------
    Viewer: the base (polygon through each limb's first joint), the platform (through
    the last joints), each limb through its joints (a parallelogram Pa as its closed
    loop), and each joint's axis, coloured as in the mobility figures: blue cylinders
    revolute, orange boxes prismatic, purple cylinders helical.
    """
    from . import robots
    from ._mechanism_plot import evaluate, twist_arrows

    name = None
    if isinstance(limbs, str):
        name = limbs
        if name not in robots.DRAWING_VALUES:
            raise ValueError(
                f"limbs must be limbs or a catalogue mechanism's name, one of "
                f"{sorted(robots.DRAWING_VALUES)}; got {limbs!r}"
            )
        limbs = getattr(robots, name)()
        values = robots.DRAWING_VALUES[name] if values is None else values
    if values is None:
        raise ValueError(
            "values must give a number for every symbol of the limbs "
            "(only a catalogue mechanism's name has default values)"
        )
    width, height = _check_size(size)
    joints = evaluate(limbs, values)
    points = np.array([p for limb in joints for _, _, p in limb])
    extent = float(np.ptp(points, axis=0).max())
    extent = extent if extent > LENGTH_TOL * length_scale(points) else 2.0
    length = extent / 5
    base = [limb[0][2] for limb in joints]
    platform = [limb[-1][2] for limb in joints]
    drawn, segments = [], []
    for limb in joints:
        drawn.append(
            [
                {"kind": kind, "axis": _numbers(axis), "point": _numbers(point)}
                for kind, axis, point in limb
            ]
        )
        loops = _parallelograms(limb)
        pairs = [(j, j + 1) for j in range(len(limb) - 1)]
        for i in loops:  # A1 A2 B1 B2: the loop A1-A2-B2-B1, not the zigzag A2-B1
            pairs = [p for p in pairs if p != (i + 1, i + 2)] + [
                (i + 1, i + 3),
                (i, i + 2),
            ]
        segments.append(sorted(pairs))
    arrows = []
    if twists is not None:
        centre = np.mean(platform, axis=0)
        for kind, start, direction in twist_arrows(twists, centre):
            arrows.append(
                {
                    "kind": kind,
                    "start": _numbers(start),
                    "direction": _numbers(direction),
                }
            )
    title = title or name or "mechanism"
    kinds = sorted({kind for limb in joints for kind, _, _ in limb})
    loops = sum(len(_parallelograms(limb)) for limb in joints)
    pa = f", {loops} parallelograms" if loops else ""
    rotations = sum(a["kind"] == "rotation" for a in arrows)
    counts = [
        f"{count} {word}{'s' if count > 1 else ''} ({colour})"
        for count, word, colour in (
            (len(arrows) - rotations, "translation", "green arrow"),
            (rotations, "rotation", "red arrow with a ring"),
        )
        if count
    ]
    moves = f"; the platform's twists: {' and '.join(counts)}" if arrows else ""
    legend = {
        "revolute": "blue cylinders revolute",
        "prismatic": "orange boxes prismatic",
        "helical": "purple cylinders helical",
    }
    caption = (
        f"{title}: {len(joints)} limbs of {', '.join(str(len(j)) for j in joints)} "
        f"joints ({', '.join(kinds)}){pa}{moves}. Joints: "
        f"{', '.join(legend[k] for k in kinds)}."
    )
    model = {
        "kind": "mechanism",
        "name": title,
        "width": width,
        "height": height,
        "limbs": drawn,
        "segments": segments,
        "base": _numbers(base),
        "platform": _numbers(platform),
        "twists": arrows,
        "length": length,
        "caption": caption,
        "label": (
            f"{caption} Drawn in 3D: the grey base joins the limbs' first joints, the "
            f"blue platform their last joints, each limb numbered at its base. Drag or "
            f"use the arrow keys to turn the view, + and - to zoom."
        ),
    }
    return Viewer(model, caption)


def _check_size(size):
    values = as_float_array(size, "size")
    if values.shape != (2,) or np.any(values < 100) or np.any(values > 2000):
        raise ValueError(
            f"size must be (width, height) in pixels, each in [100, 2000], got {size!r}"
        )
    return int(values[0]), int(values[1])


def stepped_figure(
    draw, label, unit=None, values=None, choices=None, value=None, dpi=None, alt=None
):
    """Figures computed now for a set of slider values, stepped through in the page.

    For results too heavy for the browser (a whole resolved-rate run, a mobility
    analysis). Give either ``values`` (a grid from ``grid``: a slider, with its
    ``unit``) or ``choices`` (a list of names: a drop-down). ``draw(v)`` returns a
    matplotlib Figure or a str (shown as preformatted text). ``draw`` runs in the course
    style (``plotting.COURSE_STYLE``: its figure size, fonts and layout) and each Figure
    is embedded as a 256-colour PNG at ``dpi`` (default ``plotting.DPI``, so that text
    of 9 pt shows at 9 pt in the page), then closed. ``value`` is the first value shown
    (default: the first). ``alt`` is each image's text alternative: a str, or a function
    of the value returning one (default: the label and the value the figure was computed
    for).

    Parameters
    ----------
    draw : callable
        ``draw(v)`` returns a matplotlib Figure or a str.
    label : str
        The slider's or drop-down's label.
    unit : str or None, optional
        The unit of ``values`` (shown by the slider).
    values : list of float, optional
        A grid from :func:`grid`: a slider.
    choices : list of str, optional
        Names: a drop-down.
    value : float or str, optional
        The first value shown (default: the first).
    dpi : float or None, optional
        Resolution of the PNGs (default ``plotting.DPI``).
    alt : str or callable, optional
        Each image's text alternative, or a function of the value returning one.

    Returns
    -------
    Viewer
        The figures and their control, displayed as HTML.
    """
    if (values is None) == (choices is None):
        raise ValueError(
            "stepped_figure needs exactly one of values (a slider grid) or choices"
        )
    if not callable(draw):
        raise TypeError(
            f"draw must be a function of one value, got {type(draw).__name__}"
        )
    from . import plotting  # matplotlib only when figures are drawn

    dpi = plotting.DPI if dpi is None else check_positive(dpi, "dpi")

    def describe_frame(key):
        if callable(alt):
            return str(alt(key))
        if alt is not None:
            return (
                f"{alt} ({label} = {key:g} {unit})"
                if unit
                else f"{alt} ({label}: {key})"
            )
        shown = f"{key:g} {unit}" if unit else str(key)
        return f"Figure computed for {label} = {shown}"

    def frames(keys):
        import matplotlib

        with matplotlib.rc_context(plotting.COURSE_STYLE):
            return [_frame(draw(k), dpi, describe_frame(k)) for k in keys]

    if choices is not None:
        keys = list(choices)
        if not keys or not all(isinstance(k, str) for k in keys):
            raise ValueError(
                f"choices must be a non-empty list of names, got {choices!r}"
            )
        index = keys.index(value) if value is not None and value in keys else 0
        if value is not None and value not in keys:
            raise ValueError(f"value must be one of the choices {keys}, got {value!r}")
        model = {
            "kind": "steps",
            "choices": keys,
            "label": label,
            "index": index,
            "frames": frames(keys),
        }
        return Viewer(model, f"{label}: {len(keys)} choices, showing {keys[index]}")
    grid = [float(v) for v in values]
    if len(grid) < 2 or len(grid) > 101:
        raise ValueError(f"values must hold 2 to 101 grid values, got {len(grid)}")
    step = grid[1] - grid[0]
    if (
        step <= 0
        or not _sliders.on_grid(grid[0], step)
        or not np.allclose(np.diff(grid), step)
    ):
        raise ValueError(
            f"values must be a grid anchored at 0 with one step (see grid()), "
            f"got {grid}"
        )
    spec = _sliders.slider_spec(
        label,
        unit,
        grid[0],
        grid[-1],
        grid[0] if value is None else value,
        steps=(step,),
    )
    index = int(round((spec.value - spec.low) / step))
    model = {
        "kind": "steps",
        "slider": spec.as_dict(),
        "values": grid,
        "index": index,
        "frames": frames(grid),
    }
    return Viewer(
        model,
        f"{spec.description}: {len(grid)} precomputed values from "
        f"{spec.low:g} to {spec.high:g}, showing {spec.value:g}",
    )


def grid(low, high, step):
    """Slider values low, low + step, ..., high: a grid anchored at 0 for
    ``stepped_figure``.

    Parameters
    ----------
    low, high : float
        The ends; low must be a multiple of step, so that 0 is on the grid.
    step : float
        The spacing, positive.

    Returns
    -------
    list of float
        The values.
    """
    values = _sliders.grid_values(low, high, step)
    if not _sliders.on_grid(values[0], values[1] - values[0]):
        raise ValueError(
            f"low must be a multiple of step so that 0 is on the grid, "
            f"got low={low:g}, step={step:g}"
        )
    return values


def _frame(result, dpi, alt):
    """One precomputed frame as an HTML fragment: a PNG of a Figure, or preformatted
    text."""
    if isinstance(result, str):
        return f'<pre style="margin:0">{html.escape(result)}</pre>'
    savefig = getattr(result, "savefig", None)
    if savefig is None:
        raise TypeError(
            "draw must return a matplotlib Figure or a str, "
            f"got {type(result).__name__}"
        )
    buffer = io.BytesIO()
    savefig(buffer, format="png", dpi=dpi)
    import matplotlib.pyplot as plt
    from PIL import Image  # matplotlib's own dependency

    plt.close(result)
    # 256 colours (median cut, no dithering) draw a figure's flat colours and
    # antialiased
    # edges alike at a third of the bytes: a page of stepped frames stays small.
    image = Image.open(buffer).convert("RGB")
    palette = image.quantize(
        colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE
    )
    buffer = io.BytesIO()
    palette.save(buffer, format="png", optimize=True)
    data = base64.b64encode(buffer.getvalue()).decode("ascii")
    return f'<img alt="{html.escape(alt)}" src="data:image/png;base64,{data}">'
