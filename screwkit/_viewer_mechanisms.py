"""Viewers of parallel mechanisms: a Stewart-Gough-like platform on its legs
(:func:`show_platform`) and a mechanism of limbs and joint screws
(:func:`show_mechanism`), computed in the page (public as ``sk.viewer.*``).
"""

import math

import numpy as np

from . import _sliders
from ._checks import (
    as_float_array,
    check_positive,
    check_transform,
    describe,
)
from ._viewer_page import Viewer, _check_size, _numbers
from .tolerances import LENGTH_TOL, PARALLEL_TOL, length_scale


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

    Examples
    --------
    A spatial platform gets six sliders, a planar one three (x, y and the turn phi):

    >>> from screwkit.parallel import planar_3rpr, stewart_gough
    >>> [s["label"] for s in show_platform(stewart_gough()).model["sliders"]]
    ['x', 'y', 'z', 'roll', 'pitch', 'yaw']
    >>> [s["label"] for s in show_platform(planar_3rpr()).model["sliders"]]
    ['x', 'y', 'phi']
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

    Examples
    --------
    A catalogue mechanism by its name, at its drawing values:

    >>> show_mechanism("planar_3rrr")
    planar_3rrr: 3 limbs of 3, 3, 3 joints (revolute). Joints: blue cylinders
    revolute.
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
