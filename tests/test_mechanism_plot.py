"""sk.plotting.draw_mechanism: every catalogue mechanism, what is drawn where, and bad
input."""

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402
import sympy as sp  # noqa: E402

import screwkit as sk  # noqa: E402


def _artists(ax, gid):
    return [a for a in ax.get_children() if a.get_gid() == gid]


@pytest.mark.parametrize("name", sorted(sk.robots.DRAWING_VALUES))
def test_every_catalogue_mechanism_is_drawn_with_a_marker_per_joint(name):
    limbs = getattr(sk.robots, name)()
    ax = sk.plotting.draw_mechanism(limbs, sk.robots.DRAWING_VALUES[name])
    kinds = {"revolute": 0, "prismatic": 0, "helical": 0}
    for limb in limbs:
        for _, _, h in limb:
            kinds[
                "prismatic" if h is sp.oo else "revolute" if h == 0 else "helical"
            ] += 1
    for kind, count in kinds.items():
        markers = [
            a for a in _artists(ax, f"joint-{kind}") if hasattr(a, "get_offsets")
        ]
        assert len(markers) == count, kind
    plt.close(ax.figure)


def test_the_platform_goes_through_each_limbs_last_joint():
    limbs = sk.robots.pm_4prru()
    values = sk.robots.DRAWING_VALUES["pm_4prru"]
    ax = sk.plotting.draw_mechanism(limbs, values)
    (outline,) = _artists(ax, "platform")
    x, y, z = outline.get_data_3d()
    subs = {sp.Symbol(k): v for k, v in values.items()}
    expected = [[float(e) for e in sp.Matrix(limb[-1][1]).subs(subs)] for limb in limbs]
    np.testing.assert_allclose(np.c_[x, y, z][:-1], expected, atol=1e-12)
    plt.close(ax.figure)


def test_symmetric_values_close_the_planar_3rrr_on_an_equilateral_triangle():
    # Every limb is limb 1 turned by 120 degrees, with the same angles: so are the
    # platform's corners, which makes the drawn platform an equilateral triangle.
    ax = sk.plotting.draw_mechanism(
        sk.robots.planar_3rrr(), sk.robots.DRAWING_VALUES["planar_3rrr"]
    )
    (outline,) = _artists(ax, "platform")
    corners = np.c_[outline.get_data_3d()][:3]
    sides = [np.linalg.norm(corners[k] - corners[(k + 1) % 3]) for k in range(3)]
    assert np.ptp(sides) < 1e-12 and sides[0] > 0.1
    plt.close(ax.figure)


def test_platform_twists_are_drawn_one_arrow_each():
    limbs = sk.robots.pm_3prrr()
    ax = sk.plotting.draw_mechanism(
        limbs, sk.robots.DRAWING_VALUES["pm_3prrr"], twists=sk.mobility(limbs)
    )
    assert len(_artists(ax, "twist")) == 3  # 3T: three translations
    plt.close(ax.figure)


def test_every_text_of_a_mechanism_drawing_is_at_least_9_pt_in_the_course_style():
    # The course's minimum (screwkit.plotting): legend, title, axis and tick labels
    # alike.
    limbs = sk.robots.pm_4prru()
    with plt.rc_context(sk.plotting.COURSE_STYLE):
        ax = sk.plotting.draw_mechanism(
            limbs,
            sk.robots.DRAWING_VALUES["pm_4prru"],
            twists=sk.mobility(limbs),
            title="4-PRRU: 3T1R",
        )
        ax.figure.canvas.draw()
        sizes = {
            text.get_text(): text.get_fontsize()
            for text in ax.figure.findobj(matplotlib.text.Text)
            if text.get_text()
        }
    plt.close(ax.figure)
    assert {"prismatic", "revolute", "4-PRRU: 3T1R", "x (m)"} <= set(sizes)
    assert min(sizes.values()) >= 9, sizes


@pytest.mark.parametrize(
    "limbs, values, error, phrase",
    [
        ([[]], {}, ValueError, "limb 0 must be a non-empty list"),
        ([], {}, ValueError, "limbs must be a non-empty list"),
        (
            sk.robots.planar_3rrr(),
            {"a": 1.0},
            ValueError,
            "values has no number for the symbol 'b'",
        ),
        (
            sk.robots.planar_3rrr(),
            {**sk.robots.DRAWING_VALUES["planar_3rrr"], "c": 1.0},
            ValueError,
            "values gives a number for 'c'",
        ),
        (
            sk.robots.planar_3rrr(),
            {**sk.robots.DRAWING_VALUES["planar_3rrr"], "a": "long"},
            TypeError,
            r"values\['a'\] must be a real number",
        ),
        (
            sk.robots.planar_3rrr(),
            {**sk.robots.DRAWING_VALUES["planar_3rrr"], "a": np.nan},
            ValueError,
            r"values\['a'\] must be finite",
        ),
        (sk.robots.planar_3rrr(), [1.0], TypeError, "values must be a dict"),
        (
            [[([0, 0, 1], [0, 0, 0])]],
            {},
            TypeError,
            r"limb 0, joint 0 must be an \(s, r, h\) triple",
        ),
    ],
)
def test_bad_input_names_the_symbol_or_limb(limbs, values, error, phrase):
    with pytest.raises(error, match=phrase):
        sk.plotting.draw_mechanism(limbs, values)
    plt.close("all")
