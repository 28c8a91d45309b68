"""Interactive widgets (ipywidgets) for a live kernel, each with a figure for pages
without one.

Every function returns a ``LiveFigure``: in JupyterLab, Notebook 7, VS Code or Colab it
is the ipywidgets slider that re-runs Python; its output also carries an HTML fallback
(the same figure computed in the page by ``screwkit.viewer``, or precomputed frames)
that the static book shows instead of a blank widget placeholder
(``nb_mime_priority_overrides`` in ``_config.yml``). Sliders follow the rules of
``screwkit._sliders``: default on the grid, 0 reachable, unit in the label.
"""

import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np

from . import _sliders, plotting, viewer
from ._checks import check_chain, check_transform
from .transforms import screw_motion

__all__ = ["LiveFigure", "screw_motion_slider", "joint_sliders", "figure_slider"]


class LiveFigure:
    """An ipywidget for live kernels plus a fallback for pages.

    Parameters
    ----------
    widget : ipywidgets.Widget
        The ipywidgets object (its ``.children`` hold the sliders).
    fallback : object with ``_repr_html_``
        What a page without a kernel shows.

    Examples
    --------
    Jupyter shows the widget; a page without a kernel shows the fallback's HTML.
    (Outside a kernel the widget's first drawing goes to the terminal: kept quiet
    here.)

    >>> import contextlib, io
    >>> with contextlib.redirect_stdout(io.StringIO()):
    ...     live = screw_motion_slider([0, 0, 1], [1, 0, 0], 0)
    >>> sorted(live._repr_mimebundle_())
    ['application/vnd.jupyter.widget-view+json', 'text/html', 'text/plain']
    >>> plt.close("all")
    """

    def __init__(self, widget, fallback):
        self.widget = widget
        self.fallback = fallback

    def __repr__(self):
        return f"LiveFigure({self.fallback!r})"

    def _repr_mimebundle_(self, include=None, exclude=None):
        bundle = dict(
            self.widget._repr_mimebundle_(include=include, exclude=exclude) or {}
        )
        bundle["text/html"] = self.fallback._repr_html_()
        bundle["text/plain"] = repr(self)
        return bundle


def _float_slider(spec):
    return widgets.FloatSlider(
        value=spec.value,
        min=spec.low,
        max=spec.high,
        step=spec.step,
        description=spec.description,
        continuous_update=False,
        style={"description_width": "initial"},
    )


def screw_motion_slider(
    s, r, h, start=None, limits=((-1, 1), (-1, 1), (0, 2)), theta=90.0
):
    """A slider for theta (deg) that moves the frame ``start`` about the screw
    (s, r, h).

    The frame drawn is exp([xi] theta) @ start, with the twist xi of the axis through
    ``r`` along ``s`` with pitch ``h`` (m/rad). Without a kernel, the same motion is
    computed in the page (``viewer.screw_motion_viewer``).

    Parameters
    ----------
    s : array-like, shape (3,)
        The axis direction.
    r : array-like, shape (3,)
        A point of the axis (m).
    h : float
        The pitch (m/rad).
    start : array-like, shape (4, 4), optional
        The frame before the motion (default identity).
    limits : ((xmin, xmax), (ymin, ymax), (zmin, zmax)), optional
        The axes' limits (m).
    theta : float, optional
        The slider's first value (deg).

    Returns
    -------
    LiveFigure
        The slider and its drawing.

    Examples
    --------
    One slider, theta in degrees, starting at 90 (outside a kernel the first
    drawing goes to the terminal: kept quiet here):

    >>> import contextlib, io
    >>> with contextlib.redirect_stdout(io.StringIO()):
    ...     live = screw_motion_slider([0, 0, 1], [1, 0, 0], 0)
    >>> [(slider.description, slider.value) for slider in live.widget.children[:-1]]
    [('theta (deg)', 90.0)]
    >>> plt.close("all")
    """
    start = (
        np.eye(4)
        if start is None
        else check_transform(np.asarray(start, dtype=float), "start")
    )
    screw_motion(s, r, h, 0.0)  # check s, r, h once, before any drawing
    fallback = viewer.screw_motion_viewer(s, r, h, start=start, theta=theta)
    spec = _sliders.slider_spec("theta", "deg", -360.0, 360.0, theta)

    def draw(theta_deg):
        angle = np.radians(theta_deg)
        ax = plotting.axes3d(limits)
        plotting.draw_screw_axis(ax, s, r, label="screw axis")
        plotting.draw_frame(ax, np.eye(4), label="0", alpha=0.4)
        path = screw_motion(s, r, h, np.linspace(0.0, angle, 40)) @ start
        plotting.draw_screw_motion(ax, path, every=39)
        ax.set_title(f"theta = {theta_deg:.0f} deg, pitch h = {h} m/rad")
        plt.show()

    return LiveFigure(
        widgets.interactive(draw, theta_deg=_float_slider(spec)), fallback
    )


def joint_sliders(
    chain, q=None, limits=((-0.9, 0.9), (-0.9, 0.9), (-0.5, 1.0)), draw=None
):
    """One slider per joint (deg, or m for prismatic joints, within the limits) that
    redraws.

    Without a kernel, the chain is drawn and moved in the page
    (``viewer.robot_viewer``).

    Parameters
    ----------
    chain : Chain
        The chain.
    q : array-like, shape (n,), optional
        The first pose (rad or m); zeros by default.
    limits : ((xmin, xmax), (ymin, ymax), (zmin, zmax)), optional
        The axes' limits (m).
    draw : callable, optional
        ``draw(ax, q)`` may add to each drawing (for example the pose's numbers).

    Returns
    -------
    LiveFigure
        The sliders and their drawing.

    Examples
    --------
    A planar 2R arm without joint limits: two sliders over a whole turn (outside a
    kernel the first drawing goes to the terminal: kept quiet here).

    >>> import contextlib, io
    >>> import screwkit as sk
    >>> with contextlib.redirect_stdout(io.StringIO()):
    ...     live = joint_sliders(sk.robots.planar([1.0, 0.5]))
    >>> [(s.description, s.min, s.max) for s in live.widget.children[:-1]]
    [('q1 (deg)', -180.0, 180.0), ('q2 (deg)', -180.0, 180.0)]
    >>> plt.close("all")
    """
    specs = _sliders.slider_specs(check_chain(chain), q)
    fallback = viewer.robot_viewer(chain, q)

    def redraw(**values):
        q = np.array([values[s.label] * s.scale for s in specs])
        ax = plotting.axes3d(limits)
        plotting.draw_chain(ax, chain, q)
        x, y, z = chain.fk(q)[:3, 3]
        ax.set_title(f"{chain.name}: tool at ({x:.3f}, {y:.3f}, {z:.3f}) m")
        if draw is not None:
            draw(ax, q)
        plt.show()

    sliders = {spec.label: _float_slider(spec) for spec in specs}
    return LiveFigure(widgets.interactive(redraw, **sliders), fallback)


def figure_slider(draw, label, unit=None, values=None, choices=None, value=None):
    """A slider over a grid ``values`` (or a drop-down over ``choices``) that shows
    ``draw(v)``.

    ``draw(v)`` returns a matplotlib Figure or a str. With a kernel, every grid value is
    computed when chosen; without one, the page steps through the figures computed now
    for each value (``viewer.stepped_figure``).

    Parameters
    ----------
    draw, label, unit, values, choices, value
        As for :func:`screwkit.viewer.stepped_figure`, which makes the page's figures.

    Returns
    -------
    LiveFigure
        The control and its figure.

    See Also
    --------
    screwkit.viewer.stepped_figure : the same figure without a kernel.

    Examples
    --------
    A text per value of k; the page's fallback holds the three precomputed values
    (outside a kernel the first one is printed to the terminal: kept quiet here).

    >>> import contextlib, io
    >>> with contextlib.redirect_stdout(io.StringIO()):
    ...     live = figure_slider(lambda k: f"k = {k:g}", "k", "1/s",
    ...                          values=viewer.grid(0, 1, 0.5))
    >>> live
    LiveFigure(k (1/s): 3 precomputed values from 0 to 1, showing 0)
    """
    fallback = viewer.stepped_figure(
        draw, label, unit, values=values, choices=choices, value=value
    )
    model = fallback.model

    def show(v):
        result = draw(v)
        if isinstance(result, str):
            print(result)
        else:
            plt.show()

    if choices is not None:
        control = widgets.Dropdown(
            options=model["choices"],
            description=label,
            value=model["choices"][model["index"]],
        )
    else:
        spec = model["slider"]
        control = _float_slider(
            _sliders.SliderSpec(
                label, unit, spec["min"], spec["max"], spec["step"], spec["value"]
            )
        )
    return LiveFigure(widgets.interactive(show, v=control), fallback)
