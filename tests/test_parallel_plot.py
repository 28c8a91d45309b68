"""screwkit.parallel.plotting: what the drawings put where, and bad input."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from screwkit import parallel  # noqa: E402
from screwkit.parallel.plotting import (  # noqa: E402
    draw_planar_platform,
    draw_spatial,
    draw_workspace,
)


def test_planar_drawing_puts_the_platform_at_its_attachment_points():
    pm = parallel.planar_3rpr()
    T = pm.home()
    ax = draw_planar_platform(pm, T)
    platform = ax.lines[2].get_xydata()[
        :3
    ]  # base outline, base markers, platform outline
    C = (T[:2, :2] @ pm.platform_points[:, :2].T).T + T[:2, 3]
    assert np.allclose(platform, C)
    legs = ax.lines[3:6]
    for leg, a, c in zip(legs, pm.base_points[:, :2], C):
        assert np.allclose(leg.get_xydata(), [a, c])
    plt.close("all")


def test_crank_legs_are_drawn_through_their_elbows():
    pm = parallel.planar_3rrr()
    ax = draw_planar_platform(pm, pm.home(), mode="+-+")
    elbows = pm.ik(pm.home(), mode="+-+", passive=True).passive["elbow"][:, :2]
    for leg, elbow in zip(ax.lines[3:6], elbows):
        assert np.allclose(leg.get_xydata()[1], elbow)
    plt.close("all")


def test_spatial_drawing_and_workspace():
    pm = parallel.stewart_gough()
    ax = draw_spatial(pm, pm.home())
    assert len(ax.lines) == 2 + 6
    x = np.linspace(-0.5, 0.5, 21)
    ax = draw_workspace(pm.workspace(x, x, z=1.0))
    assert ax.get_xlabel() == "x (m)"
    plt.close("all")


def test_bad_input():
    with pytest.raises(TypeError, match="pm must be a ParallelManipulator"):
        draw_planar_platform([[0, 0, 1]], np.eye(4))
    with pytest.raises(ValueError, match=r"T must have shape \(4, 4\)"):
        draw_planar_platform(parallel.planar_3rpr(), np.eye(3))


def test_the_drawings_are_reached_from_the_package_as_sk_parallel_plotting():
    import screwkit as sk

    assert sk.parallel.plotting.draw_planar_platform is draw_planar_platform
    assert sk.parallel.plotting.__all__ == [
        "draw_planar_platform",
        "draw_spatial",
        "draw_workspace",
    ]
