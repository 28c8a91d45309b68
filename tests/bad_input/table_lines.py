"""Bad input to lines (sk.lines), the screw systems' principal screws, pitch and
classification, and their drawings: rows in the format of rows.py."""

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import sympy as sp  # noqa: E402
from rows import argument_rows, row, value_rows  # noqa: E402

from screwkit import ScrewSystem  # noqa: E402
from screwkit import lines as ln  # noqa: E402
from screwkit import plotting as pl  # noqa: E402

X_AXIS = [1, 0, 0, 0, 0, 0]
Z_AXIS = [0, 0, 1, 0, 0, 0]
a = sp.Symbol("a")


def x_axis():
    return ln.Line(X_AXIS)


def cylindroid():
    return ScrewSystem([[1, 0, 0, 1, 0, 0], [0, 1, 0, 0, 2, 0]])


ROWS = [
    *value_rows(
        "Line-{}",
        lambda p: ln.Line(p),
        "plucker",
        [
            ("zero-direction", [0, 0, 0, 1, 0, 0], ValueError, "non-zero direction"),
            ("klein", [0, 0, 1, 0, 0, 1], ValueError, "Klein quadric"),
            ("klein-float", [0, 0, 1.0, 0, 0, 0.5], ValueError, "Klein quadric"),
            ("nan", [0, 0, 1.0, np.nan, 0, 0], ValueError, "finite"),
            ("string", "x axis", TypeError, None),
            ("strings", ["0", 0, 1, 0, 0, 0], TypeError, None),
            ("symbol", [0, 0, 1, a, 0, 0], ValueError, "no value"),
            ("shape", [0, 0, 1], ValueError, "shape"),
        ],
    ),
    *argument_rows(
        "through-{}",
        lambda p, q: ln.Line.through(p, q),
        [
            ("same-point", ([1, 2, 3], [1, 2, 3]), ValueError, "q", "differ"),
            ("shape", ([1, 2], [1, 2, 3]), ValueError, "p", None),
            ("nan", ([1, 2, np.nan], [0, 0, 0.5]), ValueError, "p", "finite"),
        ],
    ),
    *argument_rows(
        "from_point_direction-{}",
        lambda p, d: ln.Line.from_point_direction(p, d),
        [
            ("zero", ([1, 2, 3], [0, 0, 0]), ValueError, "d", "non-zero"),
            ("symbol", ([a, 2, 3], [0, 0, 1]), ValueError, "p", "no value"),
        ],
    ),
    *argument_rows(
        "from_planes-{}",
        lambda *planes: ln.Line.from_planes(*planes),
        [
            ("parallel", ([0, 0, 1], 0, [0, 0, 2], 1), ValueError, "n2", "parallel"),
            ("zero", ([0, 0, 0], 0, [0, 0, 2], 1), ValueError, "n1", "non-zero"),
            ("string", ([0, 0, 1], "1", [1, 0, 0], 1), TypeError, "d1", None),
        ],
    ),
    row("screw-string", lambda: x_axis().screw("0"), TypeError, "h"),
    row("screw-kind", lambda: x_axis().screw(0, kind=str), TypeError, "kind"),
    row("transform-shape", lambda: x_axis().transform(np.eye(3)), ValueError, "T"),
    row(
        "transform-not-rigid",
        lambda: x_axis().transform(np.diag([2.0, 1, 1, 1])),
        ValueError,
        "T",
    ),
    row(
        "mutual_moment-string", lambda: ln.mutual_moment("x", x_axis()), TypeError, "a"
    ),
    row(
        "mutual_moment-lengths",
        lambda: ln.mutual_moment(np.array([X_AXIS] * 2), np.array([Z_AXIS] * 3)),
        ValueError,
        "b",
        match="as many lines",
    ),
    row(
        "common_normal-zero",
        lambda: ln.common_normal(x_axis(), [0, 0, 0, 0, 0, 1]),
        ValueError,
        "b",
        match="non-zero direction",
    ),
    row(
        "distance-klein",
        lambda: ln.distance([0, 0, 1, 0, 0, 1], x_axis()),
        ValueError,
        "a",
        match="Klein",
    ),
    row("intersection-none", lambda: ln.intersection(x_axis(), None), TypeError, "b"),
    *value_rows(
        "central_axis-{}",
        lambda wrench: ln.central_axis(wrench),
        "wrench",
        [
            ("zero", [0, 0, 0, 0, 0, 0], ValueError, "zero"),
            ("string", "wrench", TypeError, None),
            ("nan", [1.0, 0, 0, 0, np.nan, 0], ValueError, "finite"),
            ("symbol", [a, 0, 0, 0, 0, 0], ValueError, "no value"),
        ],
    ),
    row("dependency-empty", lambda: ln.dependency([]), ValueError, "lines"),
    row("dependency-string", lambda: ln.dependency("legs"), TypeError, "lines"),
    row(
        "dependency-pitch",
        lambda: ln.dependency(ScrewSystem([([0, 0, 1], [0, 0, 0], 1)])),
        ValueError,
        "lines[0]",
        match="Klein",
    ),
    row("dependency-tol", lambda: ln.dependency([X_AXIS], tol=2), ValueError, "tol"),
    row(
        "pitch_of-outside",
        lambda: cylindroid().pitch_of([0, 0, 1, 0, 0, 0]),
        ValueError,
        "x",
        match="span",
    ),
    row("pitch_of-zero", lambda: cylindroid().pitch_of([0] * 6), ValueError, "x"),
    row("pitch_of-string", lambda: cylindroid().pitch_of("screw"), TypeError, "x"),
    row(
        "principal_screws-order-0",
        lambda: ScrewSystem([]).principal_screws(),
        ValueError,
        "system",
        match="order",
    ),
    row(
        "principal_screws-order-6",
        lambda: ScrewSystem(np.eye(6, dtype=int).tolist()).principal_screws(),
        ValueError,
        "system",
        match="order",
    ),
    row("draw_lines-ax", lambda: pl.draw_lines(None, [X_AXIS]), TypeError, "ax"),
    row(
        "draw_lines-lines",
        lambda: pl.draw_lines(pl.axes3d(), "lines"),
        TypeError,
        "lines",
    ),
    row(
        "draw_lines-labels",
        lambda: pl.draw_lines(pl.axes3d(), [X_AXIS], labels=[]),
        ValueError,
        "labels",
    ),
    row(
        "draw_configuration-size",
        lambda: pl.draw_configuration(pl.axes3d(), [X_AXIS], size=-1),
        ValueError,
        "size",
    ),
    row(
        "draw_cylindroid-order",
        lambda: pl.draw_cylindroid(pl.axes3d(), ScrewSystem([X_AXIS])),
        ValueError,
        "system",
        match="2-system",
    ),
    row(
        "draw_cylindroid-equal",
        lambda: pl.draw_cylindroid(
            pl.axes3d(), ScrewSystem([[1, 0, 0, 1, 0, 0], [0, 1, 0, 0, 1, 0]])
        ),
        ValueError,
        "system",
        match="different finite",
    ),
    row(
        "draw_cylindroid-system",
        lambda: pl.draw_cylindroid(pl.axes3d(), [X_AXIS]),
        TypeError,
        "system",
    ),
]
