"""Figures computed now for a set of slider values (Matplotlib), stepped through in the
page with no kernel: :func:`stepped_figure` and its slider :func:`grid` (public as
``sk.viewer.*``).
"""

import base64
import html
import io

import numpy as np

from . import _sliders
from ._checks import (
    check_positive,
)
from ._viewer_page import Viewer


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

    Examples
    --------
    Three values of a slider, each with its text computed now:

    >>> figure = stepped_figure(lambda k: f"k = {k:g}", "k", "1/s",
    ...                         values=grid(0, 1, 0.5))
    >>> figure
    k (1/s): 3 precomputed values from 0 to 1, showing 0
    >>> figure.model["values"]
    [0.0, 0.5, 1.0]
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

    Examples
    --------
    >>> grid(-1, 1, 0.5)
    [-1.0, -0.5, 0.0, 0.5, 1.0]
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
