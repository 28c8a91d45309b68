"""Slider grids shared by the in-page viewers and the ipywidgets: range, step and
default together.

The rules (so that every slider of the course behaves alike): the default lies on the
slider's grid and inside its range; the grid is anchored at 0 (both ends are multiples
of the step), so 0 and round values are reachable where the range holds them; a joint's
range comes from its limits, and a revolute joint without limits gets one turn placed so
that its default is not at an edge; every slider names its unit.
"""

import math
from dataclasses import dataclass

import numpy as np

from ._checks import as_float_array
from .links import Joint
from .tolerances import STEP_TOL

#: Candidate steps, coarsest first: the first on which the default lies is used.
ANGLE_STEPS = (1.0, 0.5, 0.1, 0.05, 0.01)
LENGTH_STEPS = (0.01, 0.005, 0.001, 0.0001)
_TOL = STEP_TOL


@dataclass(frozen=True)
class SliderSpec:
    """One slider: values in the displayed ``unit``; ``scale`` converts them to SI
    (value * scale).

    Attributes
    ----------
    label : str, e.g. 'q3'
    unit : str, e.g. 'deg' or 'm'
    low, high, step, value : float, in ``unit``; low <= value <= high, all multiples of
        step
    scale : float, SI units per displayed unit (pi/180 for degrees)
    """

    label: str
    unit: str
    low: float
    high: float
    step: float
    value: float
    scale: float = 1.0

    @property
    def description(self):
        """The label with its unit, as the slider shows it: 'q3 (deg)'."""
        return f"{self.label} ({self.unit})"

    def as_dict(self):
        """The fields the page's JavaScript reads (plain floats, JSON-ready)."""
        return {
            "label": self.label,
            "unit": self.unit,
            "min": self.low,
            "max": self.high,
            "step": self.step,
            "value": self.value,
            "scale": self.scale,
        }


def on_grid(x, step):
    """True if ``x`` is an integer multiple of ``step`` (to rounding)."""
    return abs(x / step - round(x / step)) < _TOL * max(1.0, abs(x / step))


def _snap(x, step):
    """``x`` on the grid of ``step``, written without binary noise
    (-87.0, not -86.99999999)."""
    return round(round(x / step) * step, 10) + 0.0


def slider_spec(label, unit, low, high, value, steps=ANGLE_STEPS, scale=1.0):
    """A slider over [low, high] (in ``unit``) starting at ``value``, obeying the rules
    above.

    The step is the coarsest of ``steps`` on which ``value`` lies
    (the finest if none: the value is then rounded to it). The ends are moved inward
    onto the grid. Raises ValueError if ``value`` is outside [low, high] or the range
    holds no grid point.
    """
    if not unit:
        raise ValueError(f"unit of slider {label!r} must name the unit, got {unit!r}")
    low, high, value = float(low), float(high), float(value)
    if not low - _TOL <= value <= high + _TOL:
        raise ValueError(
            f"the default of slider {label!r} must lie in [{low:g}, {high:g}] {unit}, "
            f"got {value:g} {unit}"
        )
    step = next((s for s in steps if on_grid(value, s)), steps[-1])
    value = _snap(value, step)
    grid_low = _snap(math.ceil(low / step - _TOL) * step, step)
    grid_high = _snap(math.floor(high / step + _TOL) * step, step)
    value = min(max(value, grid_low), grid_high)
    if grid_low >= grid_high:
        raise ValueError(
            f"the range of slider {label!r}, [{low:g}, {high:g}] {unit}, "
            f"is too short for a step of {step:g} {unit}"
        )
    return SliderSpec(label, unit, grid_low, grid_high, step, value, scale)


def _one_turn(value_deg):
    """A one-turn range for a revolute joint without limits, the default away from its
    edges."""
    # by whole turns into [-180, 180], toward zero: 540 -> 180, -540 -> -180
    wrapped = value_deg
    if wrapped > 180.0:
        wrapped -= 360.0 * math.ceil((wrapped - 180.0) / 360.0)
    elif wrapped < -180.0:
        wrapped += 360.0 * math.ceil((-180.0 - wrapped) / 360.0)
    centre = 0.0 if abs(wrapped) <= 135.0 else math.copysign(90.0, wrapped)
    return wrapped, centre - 180.0, centre + 180.0


def slider_specs(chain, q=None):
    """One SliderSpec per joint of ``chain`` at ``q`` (rad / m, default zeros).

    Revolute (and other angular) joints in degrees, prismatic joints in metres. A
    revolute default outside its limits is wrapped by whole turns into them; ValueError
    if that fails.
    """
    q = np.zeros(chain.n) if q is None else chain.check_one(q)
    specs = []
    for i, (kind, (low, high), qi) in enumerate(
        zip(chain.joints, chain.qlim, q), start=1
    ):
        if kind is Joint.PRISMATIC:
            if np.isfinite(low) and np.isfinite(high):
                specs.append(slider_spec(f"q{i}", "m", low, high, qi, LENGTH_STEPS))
            else:
                centre = 0.0 if abs(qi) < 0.4 else round(qi, 1)
                specs.append(
                    slider_spec(
                        f"q{i}", "m", centre - 0.5, centre + 0.5, qi, LENGTH_STEPS
                    )
                )
            continue
        value = math.degrees(qi)
        if np.isfinite(low) and np.isfinite(high):
            low, high = math.degrees(low), math.degrees(high)
            turns = math.floor((value - low) / 360.0)
            wrapped = value - 360.0 * turns
            if not low - _TOL <= wrapped <= high + _TOL:
                raise ValueError(
                    f"q[{i - 1}] = {value:g} deg is outside joint {i}'s limits "
                    f"[{low:g}, {high:g}] deg, even after whole turns"
                )
            value = value if low - _TOL <= value <= high + _TOL else wrapped
        else:
            value, low, high = _one_turn(value)
        specs.append(
            slider_spec(f"q{i}", "deg", low, high, value, ANGLE_STEPS, math.pi / 180)
        )
    return specs


def grid_values(low, high, step, name="values"):
    """The grid low, low + step, ..., high (inclusive) as floats; ValueError if it does
    not fit."""
    low, high, step = (float(v) for v in as_float_array([low, high, step], name))
    if step <= 0:
        raise ValueError(f"step must be a positive number, got step={step:g}")
    count = (high - low) / step
    if high <= low or abs(count - round(count)) > STEP_TOL:
        raise ValueError(
            f"{name} must be a grid low < high with (high - low) a whole number of "
            f"steps > 0, got low={low:g}, high={high:g}, step={step:g}"
        )
    return [round(low + k * step, 10) + 0.0 for k in range(int(round(count)) + 1)]


#: The old name of :func:`slider_specs` (``widgets.joint_sliders`` is the widget); for
#: one release.
joint_sliders = slider_specs
