"""Interactive figures that compute in the page: no kernel, no server, nothing from a CDN.

Each function returns a figure object that Jupyter (Lab, Notebook 7, VS Code, Colab) and the
built book display as HTML: a ``<div>`` holding the figure's parameters as JSON and an inline
``<script>``, the package's ``static/viewer.js``, that computes the kinematics in the browser
and draws it on a canvas (drag to orbit, wheel to zoom, double-click to reset). Python hands
the page only parameters: a chain's joint screws and home pose (the product of exponentials),
a screw axis, or frames precomputed for a grid of slider values.
"""
import base64
import hashlib
import html
import io
import itertools
import json
import math
from importlib import resources

import numpy as np

from . import _sliders
from ._checks import as_float_array, check_positive, check_shape, check_transform

__all__ = ["robot_viewer", "screw_motion_viewer", "stepped_figure", "grid", "Viewer"]

_ids = itertools.count(1)


def viewer_script():
    """The JavaScript of every viewer (package data ``screwkit/static/viewer.js``)."""
    return resources.files("screwkit").joinpath("static/viewer.js").read_text(encoding="utf-8")


class Viewer:
    """A figure for the page: ``model`` (JSON-ready dict) drawn by ``viewer.js``.

    ``summary`` is its plain-text form (what a terminal or a text-only output shows).
    """

    def __init__(self, model, summary):
        self.model = model
        self.summary = summary
        payload = json.dumps(model, sort_keys=True, separators=(",", ":"))
        digest = hashlib.sha1(payload.encode()).hexdigest()[:10]
        self.id = f"screwkit-{digest}-{next(_ids)}"
        self._payload = payload

    def __repr__(self):
        return self.summary

    def _repr_html_(self):
        payload = self._payload.replace("</", "<\\/")
        return (
            f'<div class="screwkit-viewer" id="{self.id}" style="font:13px sans-serif">\n'
            f'<script type="application/json">{payload}</script>\n'
            f'<noscript>{html.escape(self.summary)}</noscript>\n</div>\n'
            f"<script>\n{viewer_script()}</script>\n"
            f"<script>window.screwkit.mount(document.getElementById({json.dumps(self.id)}) || "
            f"document.currentScript.parentNode.querySelector(\"[id='{self.id}']\"));</script>\n"
        )


def _numbers(array, digits=12):
    """Nested lists of floats rounded to ``digits`` significant digits (stable JSON)."""
    return np.vectorize(lambda x: float(f"{x:.{digits}g}") + 0.0)(np.asarray(array)).tolist()


def _check_chain(chain):
    from .chains import Chain

    if not isinstance(chain, Chain):
        raise TypeError(f"chain must be a screwkit Chain, got {type(chain).__name__}")
    if chain.n < 1:
        raise ValueError(f"chain must have at least one link to be drawn, got {chain.n} links")


def _span(points):
    """Centre and radius (m) of a ball around ``points`` (k, 3), never smaller than 0.1 m."""
    low, high = points.min(axis=0), points.max(axis=0)
    return (low + high) / 2, max(float(np.linalg.norm(high - low)) / 2, 0.1)


def robot_viewer(chain, q=None, ellipsoid=False, ellipsoid_scale=0.4, size=(520, 420)):
    """The chain in 3D with one slider per joint; forward kinematics computed in the page.

    Parameters
    ----------
    chain : Chain, n >= 1 joints
    q : array-like, shape (n,), optional
        The first pose (rad for revolute, m for prismatic joints); default zeros.
    ellipsoid : bool
        Draw the translational manipulability ellipsoid (rows v of the geometric Jacobian),
        its radii scaled by ``ellipsoid_scale`` (m per m/s), and print its radii and w.
    size : (width, height) of the drawing in pixels

    Returns
    -------
    Viewer, displayed as HTML. Sliders in degrees (revolute) or metres (prismatic), each
    ranging over the joint's limits with its default on the slider's grid.
    """
    _check_chain(chain)
    specs = _sliders.slider_specs(chain, q)
    scale = as_float_array(ellipsoid_scale, "ellipsoid_scale")
    if scale.ndim or scale <= 0:
        raise ValueError(f"ellipsoid_scale must be one positive number (m per m/s), "
                         f"got {ellipsoid_scale!r}")
    width, height = _check_size(size)
    zero = np.zeros(chain.n)
    axes, points = chain.joint_axes(zero)
    home = chain.home()
    reach = np.vstack([[0.0, 0.0, 0.0], points, home[:3, 3]])
    radius = float(np.sum(np.linalg.norm(np.diff(reach, axis=0), axis=1)))
    travel = sum(abs(s.high) + abs(s.low) for s in specs if s.unit == "m")
    radius = max(radius + travel, 0.1)
    model = {
        "kind": "robot", "name": chain.name, "width": width, "height": height,
        "screws": _numbers(chain.screw_axes()), "home": _numbers(home),
        "points": _numbers(points), "axes": _numbers(axes),
        "joints": [joint.value for joint in chain.joints],
        "sliders": [s.as_dict() for s in specs],
        "radius": radius, "centre": [0.0, 0.0, 0.0],
        "ellipsoid": bool(ellipsoid), "ellipsoid_scale": float(scale),
    }
    sliders = ", ".join(f"{s.description} [{s.low:g}, {s.high:g}] step {s.step:g} at {s.value:g}"
                        for s in specs)
    extra = " with its manipulability ellipsoid" if ellipsoid else ""
    return Viewer(model, f"{chain.name}{extra}: sliders {sliders}")


def screw_motion_viewer(s, r, h, start=None, theta=None, size=(520, 420)):
    """A frame moved about the screw axis (s, r, h) by exp([xi] theta), computed in the page.

    Parameters
    ----------
    s : array-like, shape (3,), the axis direction (normalised here)
    r : array-like, shape (3,), a point of the axis (m)
    h : float, the pitch (m/rad); ``math.inf`` or ``sympy.oo`` for a pure translation along s
    start : array-like, shape (4, 4), the frame before the motion (default identity)
    theta : float, the slider's first value: deg, default 90 (or m for a translation,
        default 0.5)

    Returns
    -------
    Viewer with one slider theta in [-360, 360] deg (or d in [-1, 1] m for a translation).
    """
    s = check_shape(as_float_array(s, "s"), "s", (3,))
    r = check_shape(as_float_array(r, "r"), "r", (3,))
    if s.ndim != 1 or r.ndim != 1:
        raise ValueError(f"s and r must be single 3-vectors, got shapes {s.shape} and {r.shape}")
    norm = float(np.linalg.norm(s))
    if norm < 1e-12:
        raise ValueError(f"s must be a nonzero direction, got {s.tolist()}")
    translation = _is_infinite(h)
    if not translation:
        h = as_float_array(h, "h")
        if h.ndim:
            raise ValueError(f"h must be one number (m/rad) or infinity, got shape {h.shape}")
    start = np.eye(4) if start is None else check_transform(start, "start")
    if start.ndim != 2:
        raise ValueError(f"start must be one transform of shape (4, 4), got shape {start.shape}")
    width, height = _check_size(size)
    if theta is None:
        theta = 0.5 if translation else 90.0
    if translation:
        slider = _sliders.slider_spec("d", "m", -1.0, 1.0, theta, _sliders.LENGTH_STEPS)
    else:
        slider = _sliders.slider_spec("theta", "deg", -360.0, 360.0, theta,
                                      _sliders.ANGLE_STEPS, math.pi / 180)
    s = s / norm
    centre, radius = _span(np.vstack([np.zeros(3), r, start[:3, 3]]))
    model = {
        "kind": "screw", "width": width, "height": height, "s": _numbers(s), "r": _numbers(r),
        "h": None if translation else float(h), "start": _numbers(start),
        "slider": slider.as_dict(), "radius": radius + 0.5, "centre": _numbers(centre),
    }
    pitch = "infinite (a translation)" if translation else f"{float(h):g} m/rad"
    return Viewer(model, f"screw motion about s = {np.round(s, 3).tolist()} through "
                         f"r = {np.round(r, 3).tolist()} m, pitch {pitch}: slider "
                         f"{slider.description} [{slider.low:g}, {slider.high:g}] "
                         f"step {slider.step:g} at {slider.value:g}")


def _is_infinite(h):
    try:
        return math.isinf(float(h))
    except (TypeError, ValueError):
        raise TypeError(f"h must be a number (m/rad) or infinity, got {h!r}") from None


def _check_size(size):
    values = as_float_array(size, "size")
    if values.shape != (2,) or np.any(values < 100) or np.any(values > 2000):
        raise ValueError(f"size must be (width, height) in pixels, each in [100, 2000], got {size!r}")
    return int(values[0]), int(values[1])


def stepped_figure(draw, label, unit=None, values=None, choices=None, value=None, dpi=None):
    """Figures computed now for a set of slider values, stepped through in the page.

    For results too heavy for the browser (a whole resolved-rate run, a mobility analysis).
    Give either ``values`` (a grid from ``grid``: a slider, with its ``unit``) or ``choices``
    (a list of names: a drop-down). ``draw(v)`` returns a matplotlib Figure or a str (shown as
    preformatted text). ``draw`` runs in the course style (``plotting.COURSE_STYLE``: its
    figure size, fonts and layout) and each Figure is embedded as a 256-colour PNG at ``dpi``
    (default ``plotting.DPI``, so that text of 9 pt shows at 9 pt in the page), then closed.
    ``value`` is the first value shown (default: the first).
    """
    if (values is None) == (choices is None):
        raise ValueError("stepped_figure needs exactly one of values (a slider grid) or choices")
    if not callable(draw):
        raise TypeError(f"draw must be a function of one value, got {type(draw).__name__}")
    from . import plotting  # matplotlib only when figures are drawn

    dpi = plotting.DPI if dpi is None else check_positive(dpi, "dpi")

    def frames(keys):
        import matplotlib

        with matplotlib.rc_context(plotting.COURSE_STYLE):
            return [_frame(draw(k), dpi) for k in keys]

    if choices is not None:
        keys = list(choices)
        if not keys or not all(isinstance(k, str) for k in keys):
            raise ValueError(f"choices must be a non-empty list of names, got {choices!r}")
        index = keys.index(value) if value is not None and value in keys else 0
        if value is not None and value not in keys:
            raise ValueError(f"value must be one of the choices {keys}, got {value!r}")
        model = {"kind": "steps", "choices": keys, "label": label, "index": index,
                 "frames": frames(keys)}
        return Viewer(model, f"{label}: {len(keys)} choices, showing {keys[index]}")
    grid = [float(v) for v in values]
    if len(grid) < 2 or len(grid) > 101:
        raise ValueError(f"values must hold 2 to 101 grid values, got {len(grid)}")
    step = grid[1] - grid[0]
    if step <= 0 or not _sliders.on_grid(grid[0], step) or not np.allclose(np.diff(grid), step):
        raise ValueError(f"values must be a grid anchored at 0 with one step (see grid()), "
                         f"got {grid}")
    spec = _sliders.slider_spec(label, unit, grid[0], grid[-1], grid[0] if value is None else value,
                                steps=(step,))
    index = int(round((spec.value - spec.low) / step))
    model = {"kind": "steps", "slider": spec.as_dict(), "values": grid, "index": index,
             "frames": frames(grid)}
    return Viewer(model, f"{spec.description}: {len(grid)} precomputed values from "
                         f"{spec.low:g} to {spec.high:g}, showing {spec.value:g}")


def grid(low, high, step):
    """Slider values low, low + step, ..., high: a grid anchored at 0 for ``stepped_figure``."""
    values = _sliders.grid_values(low, high, step)
    if not _sliders.on_grid(values[0], values[1] - values[0]):
        raise ValueError(f"low must be a multiple of step so that 0 is on the grid, "
                         f"got low={low:g}, step={step:g}")
    return values


def _frame(result, dpi):
    """One precomputed frame as an HTML fragment: a PNG of a Figure, or preformatted text."""
    if isinstance(result, str):
        return f'<pre style="margin:0">{html.escape(result)}</pre>'
    savefig = getattr(result, "savefig", None)
    if savefig is None:
        raise TypeError(f"draw must return a matplotlib Figure or a str, got {type(result).__name__}")
    buffer = io.BytesIO()
    savefig(buffer, format="png", dpi=dpi)
    import matplotlib.pyplot as plt
    from PIL import Image  # matplotlib's own dependency

    plt.close(result)
    # 256 colours (median cut, no dithering) draw a figure's flat colours and antialiased
    # edges alike at a third of the bytes: a page of stepped frames stays small.
    image = Image.open(buffer).convert("RGB")
    palette = image.quantize(colors=256, method=Image.Quantize.MEDIANCUT,
                             dither=Image.Dither.NONE)
    buffer = io.BytesIO()
    palette.save(buffer, format="png", optimize=True)
    data = base64.b64encode(buffer.getvalue()).decode("ascii")
    return f'<img alt="precomputed figure" src="data:image/png;base64,{data}">'
