"""screwkit.schematic, the exercises' schematic drawings of arms: what each part
draws, and bad input."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from screwkit import schematic as sketch  # noqa: E402


@pytest.fixture
def ax():
    fig, ax = sketch.sketch(limits=((-0.5, 2.0), (-0.5, 1.0)))
    yield ax
    plt.close(fig)


def _patches(ax, gid):
    return [p for p in ax.patches if p.get_gid() == gid]


def test_the_axes_have_equal_scales_and_the_asked_limits(ax):
    assert ax.get_xlim() == (-0.5, 2.0) and ax.get_ylim() == (-0.5, 1.0)
    assert ax.get_aspect() == 1.0
    assert not ax.axison


def test_a_revolute_joint_normal_to_the_page_is_a_circle_at_its_point(ax):
    sketch.revolute(ax, (0.4, 0.2))
    (circle,) = _patches(ax, "joint-revolute")
    assert np.allclose(circle.center, (0.4, 0.2))
    assert circle.radius == pytest.approx(2.5 / 25)  # 1/25 of the drawing's width


def test_a_revolute_joint_in_the_page_is_a_box_along_its_axis(ax):
    sketch.revolute(ax, (1.0, 0.0), axis=(0, 2))
    (box,) = _patches(ax, "joint-revolute")
    corners = box.get_xy()[:4]
    height = np.ptp(corners[:, 1])
    width = np.ptp(corners[:, 0])
    assert height == pytest.approx(2 * 1.3 * 0.1) and width == pytest.approx(0.2)
    assert np.allclose(corners.mean(axis=0), (1.0, 0.0))


def test_a_prismatic_joint_is_a_long_sleeve_or_a_square(ax):
    sketch.prismatic(ax, (0, 0), (1, 0))
    sketch.prismatic(ax, (1, 0), "in")
    sleeve, square = _patches(ax, "joint-prismatic")
    assert np.ptp(sleeve.get_xy()[:4, 0]) == pytest.approx(2 * 2.2 * 0.1)
    assert np.ptp(square.get_xy()[:4, 0]) == pytest.approx(
        np.ptp(square.get_xy()[:4, 1])
    )


def test_a_frame_labels_its_two_axes_and_marks_one_normal_to_the_page(ax):
    sketch.frame(ax, (0, 0), "1", x=(1, 0), z="out")
    labels = [t.get_text() for t in ax.texts if t.get_gid() == "frame-1"]
    assert labels == ["$x_{1}$", "$z_{1}$"]
    arrows = [a for a in ax.texts if isinstance(a, matplotlib.text.Annotation)]
    assert len(arrows) == 1  # x drawn as an arrow, z as a dot in a circle
    assert np.allclose(arrows[0].xy, (4 * 0.1, 0))


def test_link_base_and_dimension_draw_lines(ax):
    sketch.link(ax, (0, 0), (0, 0.4), (0.4, 0.4))
    sketch.base(ax, (0, 0))
    sketch.dimension(ax, (0, 0.4), (0.4, 0.4), "0.4 m")
    assert np.allclose(ax.lines[0].get_xydata(), [(0, 0), (0, 0.4), (0.4, 0.4)])
    assert "0.4 m" in [t.get_text() for t in ax.texts]


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda ax: sketch.revolute(ax, (0, 0), axis="in"), "axis must be 'out'"),
        (lambda ax: sketch.revolute(ax, (0, 0), axis=(0, 0)), "non-zero direction"),
        (lambda ax: sketch.prismatic(ax, (0, 0), "up"), "direction must be 'in'"),
        (lambda ax: sketch.frame(ax, (0, 0), "0", z="left"), "z must be 'out'"),
        (lambda ax: sketch.link(ax, (0, 0)), "at least two points"),
        (lambda ax: sketch.link(ax, (0, 0), (1, 2, 3)), "points\\[1\\] must be two"),
        (lambda ax: sketch.base(ax, (0, np.nan)), "xy must be two finite numbers"),
    ],
)
def test_bad_input_names_the_argument(ax, call, message):
    with pytest.raises(ValueError, match=message):
        call(ax)


def test_bad_sizes_and_types_are_refused():
    with pytest.raises(ValueError, match="width must be in"):
        sketch.sketch(width=7.0)
    with pytest.raises(ValueError, match="limits must be increasing"):
        sketch.sketch(limits=((1, 0), (0, 1)))
    fig, ax = sketch.sketch()
    with pytest.raises(TypeError, match="xy must be two numbers"):
        sketch.revolute(ax, "origin")
    plt.close(fig)
