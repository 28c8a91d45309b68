"""Interactive widgets (ipywidgets) for the chapters. They need a live kernel."""
import ipywidgets as widgets
import matplotlib.pyplot as plt
import numpy as np

from . import plotting
from ._checks import check_transform
from .transforms import screw_motion

__all__ = ["screw_motion_slider", "joint_sliders"]


def screw_motion_slider(s, r, h, start=None, limits=((-1, 1), (-1, 1), (0, 2))):
    """A slider for theta (degrees) that moves the frame ``start`` about the screw (s, r, h).

    The frame drawn is exp([xi] theta) @ start, with the twist xi of the axis through
    ``r`` along ``s`` with pitch ``h`` (m/rad). Returns the widget to display.
    """
    start = np.eye(4) if start is None else check_transform(np.asarray(start, dtype=float), "start")
    screw_motion(s, r, h, 0.0)  # check s, r, h once, before any drawing

    def draw(theta_deg):
        theta = np.radians(theta_deg)
        ax = plotting.axes3d(limits)
        plotting.draw_screw_axis(ax, s, r, label="screw axis")
        plotting.draw_frame(ax, np.eye(4), label="0", alpha=0.4)
        path = screw_motion(s, r, h, np.linspace(0.0, theta, 40)) @ start
        plotting.draw_screw_motion(ax, path, every=39)
        ax.set_title(f"theta = {theta_deg:.0f} deg, pitch h = {h} m/rad")
        plt.show()

    slider = widgets.FloatSlider(value=90.0, min=-360.0, max=360.0, step=5.0, description="theta (deg)")
    return widgets.interactive(draw, theta_deg=slider)


def joint_sliders(chain, q=None, limits=((-0.9, 0.9), (-0.9, 0.9), (-0.5, 1.0)), draw=None):
    """One slider per joint (degrees, within the joint limits) that redraws the chain.

    ``draw(ax, q)`` may add to each drawing (for example the pose's numbers). Returns the
    widget to display.
    """
    q = np.zeros(chain.n) if q is None else chain.check_q(q)
    qlim = np.degrees(np.clip(chain.qlim, -np.pi, np.pi))

    def redraw(**degrees):
        values = np.radians([degrees[f"q{i + 1}"] for i in range(chain.n)])
        ax = plotting.axes3d(limits)
        plotting.draw_chain(ax, chain, values)
        position = chain.fk(values)[:3, 3]
        ax.set_title(f"{chain.name}: tool at ({position[0]:.3f}, {position[1]:.3f}, {position[2]:.3f}) m")
        if draw is not None:
            draw(ax, values)
        plt.show()

    sliders = {
        f"q{i + 1}": widgets.FloatSlider(value=float(np.degrees(q[i])), min=float(low), max=float(high),
                                         step=1.0, description=f"q{i + 1} (deg)")
        for i, (low, high) in enumerate(qlim)
    }
    return widgets.interactive(redraw, **sliders)
