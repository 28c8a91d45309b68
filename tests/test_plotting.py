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
    assert (
        "font-awesome" not in html
        and "https://" not in html
        and 'class="fa ' not in html
    )
    assert (
        html.count("data:image/png;base64") == 3 and "\u25b6" in html
    )  # three frames and a play button


# ---- the course's style: figures that fit the book's 688 px column, text >= 9 pt -----

BOOK_COLUMN_PX = 688  # the content column of the book at 1280 px (pydata-sphinx-theme)


def png_width(data):
    """Width in pixels from a PNG's IHDR chunk (bytes 16-19, big-endian)."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    return int.from_bytes(data[16:20], "big")


def a_busy_figure():
    """Column-wide, with a long title, a legend, a colourbar and labels with units."""
    fig, (ax, ax_map) = plt.subplots(2, 1, figsize=(sk.plotting.COLUMN_WIDTH, 6))
    t = np.linspace(0, 1, 50)
    ax.plot(t, t**2, label="w without null-space motion")
    ax.plot(t, t, label="w with null-space motion")
    ax.set_title("manipulability over time on the circle, position rows x and y")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("w (m$^2$)")
    ax.legend()
    mesh = ax_map.pcolormesh(np.arange(12).reshape(3, 4))
    fig.colorbar(mesh, ax=ax_map, label="|det J| (m$^3$)")
    return fig


def test_a_column_wide_figure_in_the_course_style_fits_the_column():
    import io

    with plt.rc_context(sk.plotting.COURSE_STYLE):
        fig = a_busy_figure()
        buffer = io.BytesIO()
        fig.savefig(
            buffer, format="png", bbox_inches="tight"
        )  # as IPython shows a figure
        plt.close(fig)
    width = png_width(buffer.getvalue())
    assert width <= BOOK_COLUMN_PX, f"{width} px"


def test_every_text_of_a_course_figure_is_at_least_9_pt():
    with plt.rc_context(sk.plotting.COURSE_STYLE):
        fig = a_busy_figure()
        fig.canvas.draw()
        sizes = {
            text.get_text(): text.get_fontsize()
            for text in fig.findobj(matplotlib.text.Text)
            if text.get_text()
        }
        plt.close(fig)
    assert len(sizes) > 10 and min(sizes.values()) >= 9, sizes


def test_use_course_style_sets_the_column_width_and_dpi():
    with plt.rc_context():
        sk.plotting.use_course_style()
        width, _ = plt.rcParams["figure.figsize"]
        assert width * plt.rcParams["figure.dpi"] <= BOOK_COLUMN_PX
        assert plt.rcParams["figure.dpi"] == 100 and plt.rcParams["savefig.dpi"] == 100


def test_frames_that_share_an_origin_get_one_label():
    # PUMA 560, standard DH, q = 0: d1 = a1 = 0 puts {1} on {0}; a4 = a5 = d5 = d6 = 0
    # puts {4}, {5} and {6} on the wrist centre; {2} and {3} are apart (a2 = 0.4318 m,
    # a3 = 0.0203 m).
    ax = sk.plotting.axes3d()
    sk.plotting.draw_chain(ax, sk.robots.puma560(), np.zeros(6), frames=True)
    labels = [text.get_text() for text in ax.texts]
    plt.close(ax.figure)
    assert labels == ["{0, 1}", "{2}", "{3}", "{4, 5, 6}"]


def test_frames_apart_get_one_label_each_and_no_frames_no_labels():
    arm = sk.robots.planar([1.0, 0.5])
    ax = sk.plotting.axes3d()
    sk.plotting.draw_chain(ax, arm, [0.3, 0.2], frames=True)
    assert [text.get_text() for text in ax.texts] == ["{0}", "{1}", "{2}"]
    plt.close(ax.figure)
    ax = sk.plotting.axes3d()
    sk.plotting.draw_chain(ax, arm, [0.3, 0.2])
    assert len(ax.texts) == 0
    plt.close(ax.figure)
