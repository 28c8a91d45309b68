"""Drawing helpers that the chapters rely on in the static book."""
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib import animation  # noqa: E402

import screwkit as sk  # noqa: E402


def test_animation_html_needs_no_network():
    arm = sk.robots.planar([1.0, 0.5])
    fig, ax = plt.subplots(figsize=(2, 2), dpi=30)
    line = sk.plotting.draw_planar(ax, arm, [0.0, 0.0])

    def update(k):
        points = arm.frames([0.1 * k, 0.2 * k])[:, :2, 3]
        line.set_data(points[:, 0], points[:, 1])
        return (line,)

    html = sk.plotting.animation_html(animation.FuncAnimation(fig, update, frames=3))
    plt.close(fig)
    assert "font-awesome" not in html and "https://" not in html and 'class="fa ' not in html
    assert html.count("data:image/png;base64") == 3 and "\u25b6" in html   # three frames and a play button
