"""The rules every slider of the course obeys (screwkit/_sliders.py states them).

The default lies on the slider's grid and strictly inside its range; the grid is
anchored at 0 (both ends are multiples of the step), so 0 and round values are
reachable; every slider names its unit. Shared by the library's slider tests and the
chapters' (tests/course)."""


def multiple(x, step):
    return abs(x / step - round(x / step)) < 1e-9 * max(1.0, abs(x / step))


def problems(slider, starts_at_an_end=False):
    """What is wrong with one slider (dict with label, unit, min, max, step, value).

    ``starts_at_an_end``: the slider is a player's time (a trajectory viewer's, which
    starts at its first time), so its default may be the range's low end."""
    low, high, step, value = (slider[k] for k in ("min", "max", "step", "value"))
    name = f"{slider['label']} [{low}, {high}] step {step} at {value}"
    found = []
    if not slider.get("unit"):
        found.append(f"{name}: names no unit")
    if not (step > 0 and low < high):
        found.append(f"{name}: not a range")
    if not (multiple(low, step) and multiple(high, step)):
        found.append(
            f"{name}: grid not anchored at 0, so 0 and round values are unreachable"
        )
    if not multiple(value - low, step):
        found.append(f"{name}: default not on the grid")
    if not (low < value < high or (starts_at_an_end and value == low < high)):
        found.append(f"{name}: default not strictly inside the range")
    return found
