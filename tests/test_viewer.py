"""The in-page viewers, Python side: what the page is given, the slider grids, bad
input.

The page's own kinematics is compared with screwkit's in Chromium by
.ci/test_viewer_browser.py.
"""

import hashlib
import json
import math
import pathlib
import re

import numpy as np
import pytest
import sympy as sp

import screwkit as sk
from screwkit import _sliders, viewer


def model_of(figure):
    """The JSON the page receives, read back from the HTML (as the browser does)."""
    html = figure._repr_html_()
    match = re.search(r'<script type="application/json">(.*?)</script>', html, re.S)
    return json.loads(match.group(1).replace("<\\/", "</"))


def test_the_script_ships_inside_the_package_and_is_small():
    script = viewer.viewer_script()
    assert "window.screwkit" in script
    assert len(script.encode()) < 100_000
    assert (
        "http://" not in script and "https://" not in script
    )  # nothing from the network


VENDOR = pathlib.Path(viewer.__file__).parent / "static" / "vendor"


def test_the_vendored_files_are_the_pinned_npm_files():
    # tools/vendor_js.py took them from the npm tarballs (integrity checked) and
    # recorded each file's sha256; --check compares with the registry again. Here,
    # offline: the bytes
    # still have the recorded hashes, and three's file is its release r159.
    record = json.loads((VENDOR / "vendor.json").read_text())
    assert {p: r["version"] for p, r in record.items()} == {
        "three": "0.159.0",
        "tiny-inflate": "1.0.3",
    }
    tool = (pathlib.Path(__file__).parents[1] / "tools" / "vendor_js.py").read_text()
    tool = re.sub(r'"\s*\n\s*"', "", tool)  # the pins' strings, joined
    for package in record.values():
        for name, digest in package["sha256"].items():
            assert hashlib.sha256((VENDOR / name).read_bytes()).hexdigest() == digest, (
                name
            )
        assert f'"{package["version"]}"' in tool
        assert f'"{package["integrity"]}"' in tool  # the pins, as the tool checks them
    assert 'const t="159"' in (VENDOR / "three.module.min.js").read_text()[:400]
    for licence in ("three.LICENSE", "tiny-inflate.LICENSE"):
        assert (
            "MIT" in (VENDOR / licence).read_text()
            or "Permission is hereby granted" in (VENDOR / licence).read_text()
        )


def test_three_becomes_a_classic_script_that_sets_window_three():
    script = viewer._classic_three()
    assert script.startswith("if(!window.THREE){(function(){")
    assert "export{" not in script and "import " not in script[:2000]
    exports = re.search(r"window\.THREE=\{(.*?)\};\}\)\(\);\}$", script).group(1)
    names = dict(item.split(":") for item in exports.split(","))
    for name in (
        "WebGLRenderer",
        "PerspectiveCamera",
        "Scene",
        "MeshStandardMaterial",
        "CylinderGeometry",
        "BoxGeometry",
        "GridHelper",
        "TubeGeometry",
    ):
        assert name in names
    # every export of the module is there, each name once
    source = (VENDOR / "three.module.min.js").read_text()
    clause = source[source.rindex("export{") + 7 : source.rindex("}")]
    assert len(names) == clause.count(",") + 1


def test_the_library_travels_deflated_and_inflates_to_the_classic_script():
    import base64
    import zlib

    script = viewer.library_script()
    packed = re.search(r'atob\("([A-Za-z0-9+/=]+)"\)', script).group(1)
    size = int(re.search(r"new Uint8Array\((\d+)\);module\.exports", script).group(1))
    text = zlib.decompress(base64.b64decode(packed), -15)
    assert text.decode() == viewer._classic_three() and len(text) == size
    assert len(script) < 0.4 * len(viewer._classic_three())


def test_html_is_self_contained_and_names_its_root():
    figure = viewer.robot_viewer(sk.robots.planar([0.3, 0.2]))
    html = figure.html(library=True)
    assert f'id="{figure.id}"' in html
    assert viewer.viewer_script() in html and viewer.library_script() in html
    assert "<script src" not in html and "<link" not in html
    later = figure.html(
        library=False
    )  # only its parameters: the scripts are in the page
    assert viewer.library_script() not in later and viewer.viewer_script() not in later
    assert f'id="{figure.id}"' in later and "window.screwkit.mount(" in later


def test_three_js_is_shipped_once_per_session():
    planar = sk.robots.planar([0.3, 0.2])
    library = viewer.library_script()
    viewer.resend_library()
    fallback = viewer.robot_viewer(
        planar
    )  # a live widget's page fallback, never displayed
    assert library in fallback._repr_html_()
    first, second = viewer.robot_viewer(planar), viewer.robot_viewer(planar)
    steps = viewer.stepped_figure(str, "k", "1/s", values=viewer.grid(0, 1, 0.5))
    assert library not in steps._repr_mimebundle_()["text/html"]  # no 3D: no library
    assert library in first._repr_mimebundle_()["text/html"]
    assert library not in second._repr_mimebundle_()["text/html"]
    assert (
        library in first._repr_mimebundle_()["text/html"]
    )  # shown again: still carries it
    assert library not in viewer.robot_viewer(planar)._repr_html_()
    viewer.resend_library()  # its carrier was cleared: the next one carries it
    assert library in viewer.robot_viewer(planar)._repr_mimebundle_()["text/html"]


def test_robot_payload_is_the_product_of_exponentials():
    # planar 2R, lengths 0.3 and 0.2: joint 1 about z through 0, joint 2 about z through
    # (0.3, 0, 0); at q = 0 the tool is at (0.5, 0, 0). Screws (z; p x z) by hand.
    model = model_of(viewer.robot_viewer(sk.robots.planar([0.3, 0.2])))
    np.testing.assert_allclose(
        model["screws"], [[0, 0, 1, 0, 0, 0], [0, 0, 1, 0, -0.3, 0]], atol=1e-12
    )
    np.testing.assert_allclose(
        model["home"],
        [[1, 0, 0, 0.5], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]],
        atol=1e-12,
    )
    np.testing.assert_allclose(model["points"], [[0, 0, 0], [0.3, 0, 0]], atol=1e-12)
    assert model["joints"] == ["R", "R"]
    assert [s["label"] for s in model["sliders"]] == ["q1", "q2"]
    assert all(
        s["unit"] == "deg" and s["scale"] == pytest.approx(math.pi / 180)
        for s in model["sliders"]
    )


def test_payload_rebuilds_the_chain_fk():
    # The product of exponentials of the payload, evaluated here with screwkit's own
    # exponential, is the chain's DH forward kinematics.
    puma = sk.robots.puma560()
    model = model_of(viewer.robot_viewer(puma))
    q = np.radians([10, 20, -30, 40, 50, 60])
    T = np.eye(4)
    for S, qi in zip(model["screws"], q):
        T = T @ sk.exp_twist(np.array(S), qi)
    np.testing.assert_allclose(T @ np.array(model["home"]), puma.fk(q), atol=1e-10)


def test_the_gripper_points_along_the_tool_axis_that_leaves_the_last_joint():
    # The gripper is drawn along the tool frame's axis nearest the offset from the last
    # joint's point to the tool at q = 0, read off each model's table: the planar 2R's
    # tool lies 0.2 m along its own x past joint 2; the Panda's flange 0.107 m along its
    # own z past joint 7; the PUMA's tool is the wrist centre itself (d6 = 0), so +z.
    planar = sk.robots.planar([0.3, 0.2])
    assert model_of(viewer.robot_viewer(planar))["approach"] == [0, 1]
    panda = sk.robots.panda()
    panda_viewer = viewer.robot_viewer(panda, panda.configurations["ready"])
    assert model_of(panda_viewer)["approach"] == [2, 1]
    assert model_of(viewer.robot_viewer(sk.robots.puma560()))["approach"] == [2, 1]
    # a tool turned by pi about y, 0.4 m along the base x from its joint: along its -x
    flipped = sk.Chain.from_screws(
        [[0, 0, 1, 0, 0, 0]],
        np.array([[-1, 0, 0, 0.4], [0, 1, 0, 0], [0, 0, -1, 0], [0, 0, 0, 1.0]]),
    )
    assert model_of(viewer.robot_viewer(flipped))["approach"] == [0, -1]


def test_same_figure_gives_the_same_payload_and_distinct_ids():
    puma = sk.robots.puma560()
    first, second = viewer.robot_viewer(puma), viewer.robot_viewer(puma)
    assert first._payload == second._payload
    assert first.id != second.id


def test_screw_payload_normalises_the_axis_and_marks_a_translation():
    model = model_of(viewer.screw_motion_viewer([0, 0, 2], [1, 0, 0], 0.5))
    assert model["s"] == [0.0, 0.0, 1.0] and model["h"] == 0.5
    assert model["slider"]["unit"] == "deg"
    for infinity in (math.inf, sp.oo):
        model = model_of(
            viewer.screw_motion_viewer([0, 0, 1], [0, 0, 0], infinity, theta=0.2)
        )
        assert model["h"] is None and model["slider"]["unit"] == "m"
        assert model["slider"]["value"] == 0.2


def test_a_chain_with_no_links_is_refused():
    class Empty(sk.Chain):
        n = 0  # a chain with no links cannot be built; a subclass can still claim it

    empty = object.__new__(Empty)
    with pytest.raises(
        ValueError, match="chain must have at least one link to be drawn, got 0"
    ):
        viewer.robot_viewer(empty)


@pytest.mark.parametrize(
    ("call", "error", "message"),
    [
        (
            lambda: viewer.robot_viewer("puma"),
            TypeError,
            r"^chain must be a screwkit Chain .*, got 'puma' \(str\)$",
        ),
        (
            lambda: viewer.robot_viewer(sk.robots.planar([1, 1]), q=[0, 0, 0]),
            ValueError,
            "q must have 2 entries",
        ),
        (
            lambda: viewer.robot_viewer(sk.robots.planar([1, 1]), ellipsoid_scale=-1),
            ValueError,
            "ellipsoid_scale must be one positive number",
        ),
        (
            lambda: viewer.robot_viewer(sk.robots.planar([1, 1]), size=(10, 10)),
            ValueError,
            r"size must be \(width, height\) in pixels",
        ),
        (
            lambda: viewer.screw_motion_viewer([0, 0, 0], [0, 0, 0], 0),
            ValueError,
            "s must be a nonzero direction",
        ),
        (
            lambda: viewer.screw_motion_viewer([0, 1], [0, 0, 0], 0),
            ValueError,
            r"s must have shape \(3,\)",
        ),
        (
            lambda: viewer.screw_motion_viewer([0, 0, 1], [0, 0, 0], "x"),
            TypeError,
            "h must be a pitch",
        ),
        (
            lambda: viewer.screw_motion_viewer([0, 0, 1], [0, 0, 0], 0, theta=400),
            ValueError,
            r"default of slider 'theta' must lie in \[-360, 360\] deg, got 400 deg",
        ),
        (
            lambda: viewer.stepped_figure(str, "k", "1/s"),
            ValueError,
            "exactly one of values",
        ),
        (
            lambda: viewer.stepped_figure(str, "k", "1/s", values=[0.5, 1.5]),
            ValueError,
            "grid anchored at 0",
        ),
        (
            lambda: viewer.stepped_figure(str, "pick", choices=["a"], value="b"),
            ValueError,
            "value must be one of the choices",
        ),
        (
            lambda: viewer.stepped_figure(lambda v: 3, "k", "1/s", values=[0, 1]),
            TypeError,
            "draw must return a matplotlib Figure or a str, got int",
        ),
        (
            lambda: viewer.grid(0.5, 2.5, 1),
            ValueError,
            "low must be a multiple of step",
        ),
    ],
)
def test_bad_input_is_refused_with_the_reason(call, error, message):
    with pytest.raises(error, match=message):
        call()


def test_a_pose_outside_the_limits_is_refused_with_the_joint_named():
    arm = sk.robots.planar([1, 1], qlim=np.radians([[-90, 90], [-90, 90]]))
    with pytest.raises(
        ValueError, match=r"q\[1\] = 120 deg is outside joint 2's limits"
    ):
        viewer.robot_viewer(arm, np.radians([0, 120]))


def test_stepped_figure_embeds_one_frame_per_value():
    figure = viewer.stepped_figure(
        lambda k: f"k = {k:.1f}", "k", "1/s", values=viewer.grid(0, 2, 0.5), value=1.0
    )
    model = model_of(figure)
    assert model["values"] == [0.0, 0.5, 1.0, 1.5, 2.0]
    assert model["index"] == 2
    assert model["frames"][2] == '<pre style="margin:0">k = 1.0</pre>'
    choice = model_of(
        viewer.stepped_figure(
            lambda m: m.upper(), "mechanism", choices=["a<b", "c"], value="c"
        )
    )
    assert (
        choice["index"] == 1
        and choice["frames"][0] == '<pre style="margin:0">A&lt;B</pre>'
    )


def _frame_images(figure):
    """The PNG frames of a stepped figure, decoded (Pillow, matplotlib's own
    dependency)."""
    import base64
    import io

    from PIL import Image

    return [
        Image.open(io.BytesIO(base64.b64decode(data)))
        for data in re.findall(r"base64,([^\"]+)", "".join(model_of(figure)["frames"]))
    ]


def test_stepped_frames_are_drawn_in_the_course_style_at_its_dpi():
    # A figure made with matplotlib's defaults inside draw gets the course's size and
    # fonts, and is rendered at the course's DPI: 6.6 in x 4 in at 100 px/in is
    # 660 x 400 px, so a
    # 9 pt text is 12.5 px high in the page, no less than the browser's 9 pt (12 px).
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    font_sizes = []

    def draw(k):
        fig, ax = plt.subplots()
        ax.plot([0, k], [0, 1])
        font_sizes.append(ax.xaxis.label.get_fontsize())
        return fig

    before, open_before = (
        dict(plt.rcParams),
        set(plt.get_fignums()),
    )  # other tests may leave some
    figure = viewer.stepped_figure(draw, "k", "1/s", values=viewer.grid(0, 1, 0.5))
    images = _frame_images(figure)
    assert [image.size for image in images] == [(660, 400)] * 3
    assert font_sizes == [sk.plotting.COURSE_STYLE["axes.labelsize"]] * 3 == [10.0] * 3
    assert dict(plt.rcParams) == before  # the style holds inside draw only
    assert set(plt.get_fignums()) <= open_before  # every frame's figure is closed


def test_stepped_frames_keep_a_figure_size_and_its_colours_exactly():
    # 256 colours keep the page small; a flat colour must come through unchanged: the
    # background stays white (255, 255, 255) and tab:blue stays #1f77b4
    # = (31, 119, 180).
    import matplotlib.pyplot as plt

    def draw(name):
        fig, (blank, blue) = plt.subplots(1, 2, figsize=(3, 2))
        blank.set_axis_off()
        blue.set_facecolor("tab:blue")
        blue.set_xticks([])
        blue.set_yticks([])
        return fig

    (image,) = _frame_images(viewer.stepped_figure(draw, "pick", choices=["one"]))
    assert image.size == (300, 200) and image.mode == "P"
    rgb = image.convert("RGB")
    assert rgb.getpixel((50, 100)) == (255, 255, 255)
    assert rgb.getpixel((230, 100)) == (31, 119, 180)


def test_stepped_figure_renders_at_a_given_dpi_and_refuses_a_bad_one():
    import matplotlib.pyplot as plt

    def draw(name):
        return plt.figure(figsize=(2, 1))

    (image,) = _frame_images(
        viewer.stepped_figure(draw, "pick", choices=["a"], dpi=150)
    )
    assert image.size == (300, 150)
    with pytest.raises(ValueError, match="dpi must be a positive number, got -80.0"):
        viewer.stepped_figure(draw, "pick", choices=["a"], dpi=-80)


# ---- slider grids (issue 18, item 4; tests/test_sliders.py checks the chapters) ----


def test_slider_grid_holds_default_and_zero():
    # The Jacobians chapter's old q3 slider: min -87.3, step 0.5, default -20.
    spec = _sliders.slider_spec("q3", "deg", -87.3, 60, -20)
    assert (spec.low, spec.high, spec.step, spec.value) == (-87.0, 60.0, 1.0, -20.0)
    spec = _sliders.slider_spec("q3", "deg", -87.3, 60, -20.5)
    assert (spec.low, spec.step, spec.value) == (-87.0, 0.5, -20.5)
    spec = _sliders.slider_spec(
        "q3", "deg", -87.3, 60, -87.3
    )  # at the limit, on purpose
    assert (spec.low, spec.step, spec.value) == (-87.3, 0.1, -87.3)


def test_puma_nominal_q3_is_inside_its_limits_not_at_an_edge():
    puma = sk.robots.puma560()
    q3 = _sliders.joint_sliders(puma, puma.configurations["nominal"])[2]
    assert (q3.low, q3.high, q3.value) == (-225.0, 45.0, -180.0)


@pytest.mark.parametrize(
    ("degrees", "expected"),
    [
        (0, (-180, 180, 0)),
        (100, (-180, 180, 100)),
        (180, (-90, 270, 180)),
        (-180, (-270, 90, -180)),
        (540, (-90, 270, 180)),
        (-190, (-90, 270, 170)),
    ],
)
def test_a_joint_without_limits_gets_one_turn_around_its_default(degrees, expected):
    arm = sk.robots.planar([1, 1])
    spec = _sliders.joint_sliders(arm, np.radians([degrees, 0]))[0]
    assert (spec.low, spec.high, spec.value) == pytest.approx(expected)


# ---- platforms (duck-typed: what sk.robots.stewart_gough() / planar_3rpr() offer) ----


class Platform:
    """A stand-in parallel manipulator: three legs, base and platform triangles."""

    name = "stand-in 3-leg platform"
    planar = False
    base_points = np.array([[1.0, 0.0, 0.0], [-0.5, 0.8, 0.0], [-0.5, -0.8, 0.0]])
    platform_points = np.array(
        [[0.3, 0.0, 0.0], [-0.15, 0.25, 0.0], [-0.15, -0.25, 0.0]]
    )
    leg_limits = np.array([[0.5, 1.5]] * 3)

    def home(self):
        return sk.transl(0.0, 0.0, 0.8)


def test_platform_payload_and_sliders():
    model = model_of(viewer.show_platform(Platform(), pose=[0.1, 0, 0.8, 0, 0, 5]))
    assert model["kind"] == "platform" and model["planar"] is False
    np.testing.assert_array_equal(model["base"], Platform.base_points)
    np.testing.assert_array_equal(model["platform"], Platform.platform_points)
    assert model["home"][2][3] == 0.8 and model["limits"] == [[0.5, 1.5]] * 3
    # the pose itself (absolute): translations +- a third of the base's size (1.6 m / 3,
    # to the cm inward) about home (0, 0, 0.8) m; roll and pitch +- 30 deg, yaw +- 120
    # deg about home's 0
    assert [(s["label"], s["unit"]) for s in model["sliders"]] == [
        ("x", "m"),
        ("y", "m"),
        ("z", "m"),
        ("roll", "deg"),
        ("pitch", "deg"),
        ("yaw", "deg"),
    ]
    assert [(s["min"], s["max"], s["value"]) for s in model["sliders"]] == [
        (-0.53, 0.53, 0.1),
        (-0.53, 0.53, 0.0),
        (0.27, 1.33, 0.8),
        (-30.0, 30.0, 0.0),
        (-30.0, 30.0, 0.0),
        (-120.0, 120.0, 5.0),
    ]
    assert "3 numbered legs" in model["label"]


def test_planar_platform_has_x_y_phi():
    planar = Platform()
    planar.planar, planar.leg_limits = True, None
    model = model_of(viewer.show_platform(planar, translation=0.2, yaw=45))
    assert [s["label"] for s in model["sliders"]] == ["x", "y", "phi"]
    assert model["sliders"][2]["max"] == 45.0 and model["limits"] is None


def test_platform_sliders_start_at_the_home_pose_itself():
    # The 3-RPR's home is turned by 90 deg about z at (0.3, 0.85) m (its catalogue
    # entry): the sliders read those values, and phi reaches +-120 deg about them.
    model = model_of(viewer.show_platform(sk.robots.planar_3rpr()))
    assert [(s["label"], s["value"]) for s in model["sliders"]] == [
        ("x", 0.3),
        ("y", 0.85),
        ("phi", 90.0),
    ]
    assert (model["sliders"][2]["min"], model["sliders"][2]["max"]) == (-30.0, 210.0)
    # the Stewart-Gough platform at 1 m; yaw reaches Fichter's singular 90 deg
    model = model_of(viewer.show_platform(sk.robots.stewart_gough()))
    z, yaw = model["sliders"][2], model["sliders"][5]
    assert z["value"] == 1.0 and yaw["min"] <= -90 and yaw["max"] >= 90


@pytest.mark.parametrize(
    ("change", "error", "message"),
    [
        (
            {"base_points": None},
            TypeError,
            "pm must be a parallel manipulator with base_points",
        ),
        (
            {"platform_points": np.zeros((2, 3))},
            ValueError,
            r"pm.platform_points must have shape \(3, 3\), got shape \(2, 3\)",
        ),
        (
            {"base_points": np.zeros((3, 2))},
            ValueError,
            r"pm.base_points must have shape \(m, 3\)",
        ),
        (
            {"leg_limits": [[1, 0]] * 3},
            ValueError,
            r"pm.leg_limits must be \(3, 2\) rows",
        ),
    ],
)
def test_a_bad_platform_is_refused_with_the_reason(change, error, message):
    pm = Platform()
    for key, value in change.items():
        if value is None:
            pm = type(
                "Bare",
                (),
                {
                    k: getattr(Platform, k)
                    for k in ("name", "planar", "platform_points", "leg_limits", "home")
                },
            )()
        else:
            setattr(pm, key, value)
    with pytest.raises(error, match=message):
        viewer.show_platform(pm)


def test_platform_pose_of_the_wrong_length_is_refused():
    with pytest.raises(
        ValueError, match=r"pose must have 6 entries \(x, y, z, roll, pitch, yaw\)"
    ):
        viewer.show_platform(Platform(), pose=[0, 0, 0])
    with pytest.raises(
        ValueError,
        match=r"pose\[2\] \(z\) must lie within \+-0.2 m of the home pose's 0.8 m "
        r"\(the slider's range\), got 0 m",
    ):
        viewer.show_platform(Platform(), pose=[0] * 6, translation=0.2)
    with pytest.raises(ValueError, match="yaw must be at most 180 deg, got 200"):
        viewer.show_platform(Platform(), yaw=200)


# ---- mechanisms: base, platform, limbs, parallelograms ----


def test_a_parallelogram_is_drawn_as_its_closed_loop():
    # Pa with corners A1 = (0,0,0), A2 = (1,0,0), B1 = (0,0,1), B2 = (1,0,1), axes
    # along y, after a prismatic joint: the loop A1-A2-B2-B1 (joints 1-2-4-3), not the
    # zigzag 2-3.
    limb = [([0, 0, 1], [0, 0, -1], sp.oo)] + sk.limbs.parallelogram(
        [0, 1, 0], [0, 0, 0], [1, 0, 0], [0, 0, 1], [1, 0, 1]
    )
    model = model_of(viewer.show_mechanism([limb, limb], {}))
    assert model["segments"][0] == [[0, 1], [1, 2], [1, 3], [2, 4], [3, 4]]
    assert [j["kind"] for j in model["limbs"][0]] == ["prismatic"] + ["revolute"] * 4


def test_catalogue_mechanism_by_name_with_its_drawing_values():
    model = model_of(viewer.show_mechanism("pm_3prpar"))
    assert model["kind"] == "mechanism" and len(model["limbs"]) == 3
    assert model["caption"].startswith("pm_3prpar: 3 limbs of 7, 7, 7 joints")
    assert "3 parallelograms" in model["caption"]
    assert len(model["base"]) == 3 and len(model["platform"]) == 3


def test_mechanism_twists_become_arrows():
    limbs = sk.robots.pm_3prrr()
    twists = sk.mobility(limbs)
    model = model_of(
        viewer.show_mechanism(
            limbs,
            sk.robots.DRAWING_VALUES["pm_3prrr"],
            twists=twists,
            title="Tripteron",
        )
    )
    assert [a["kind"] for a in model["twists"]] == ["translation"] * 3  # 3T
    assert "the platform's twists: 3 translations (green arrow)." in model["caption"]
    schoenflies = sk.mobility(sk.robots.pm_4prru())
    model = model_of(viewer.show_mechanism("pm_4prru", twists=schoenflies))
    assert (
        sorted(a["kind"] for a in model["twists"]) == ["rotation"] + ["translation"] * 3
    )
    assert (
        "3 translations (green arrow) and 1 rotation (red arrow with a ring)"
        in model["caption"]
    )


def test_an_unknown_mechanism_name_is_refused():
    with pytest.raises(
        ValueError, match="limbs must be limbs or a catalogue mechanism's name"
    ):
        viewer.show_mechanism("pm_9xyz")
    with pytest.raises(ValueError, match="values must give a number for every symbol"):
        viewer.show_mechanism(sk.robots.pm_3prrr())


def test_stepped_frames_say_what_they_show():
    import matplotlib.pyplot as plt

    figure = viewer.stepped_figure(
        lambda k: plt.figure(figsize=(1, 1)),
        "k",
        "1/s",
        values=viewer.grid(0, 1, 0.5),
        alt=lambda k: f"joint paths for a gain of {k:g} 1/s",
    )
    alts = re.findall(r'alt="([^"]*)"', "".join(model_of(figure)["frames"]))
    assert alts == [f"joint paths for a gain of {k} 1/s" for k in ("0", "0.5", "1")]
    default = viewer.stepped_figure(
        lambda k: plt.figure(figsize=(1, 1)), "pick", choices=["a", "b"]
    )
    assert re.findall(r'alt="([^"]*)"', "".join(model_of(default)["frames"])) == [
        "Figure computed for pick = a",
        "Figure computed for pick = b",
    ]


def test_a_figure_as_a_whole_page_carries_everything_it_needs():
    figure = viewer.show_mechanism("pm_6ups")
    page = figure.page()
    assert page.startswith("<!DOCTYPE html>") and "<title>pm_6ups</title>" in page
    assert viewer.library_script() in page and viewer.viewer_script() in page
    assert 'name="viewport" content="width=device-width' in page


# ---- joint colours: one scheme in the 3D viewers and the mobility figures ----


def test_joints_are_coloured_as_in_the_mobility_figures():
    # scene.js's COLOURS for each joint kind are the matplotlib colours of
    # screwkit._mechanism_plot.JOINT_STYLES (revolute tab:blue, prismatic tab:orange,
    # helical tab:purple), read from both files.
    from matplotlib.colors import to_hex

    from screwkit._mechanism_plot import JOINT_STYLES

    scene = (
        pathlib.Path(viewer.__file__).parent / "static/viewer/scene.js"
    ).read_text()
    for kind, (colour, _, _) in JOINT_STYLES.items():
        found = re.search(rf"\b{kind}: 0x([0-9a-f]{{6}})", scene).group(1)
        assert "#" + found == to_hex(colour), kind


# ---- trajectories: precomputed joint paths played in the page ----


def test_trajectory_payload_carries_the_chain_and_every_path():
    puma = sk.robots.puma560()
    Q = np.linspace(np.zeros(6), np.radians([90, -20, 30, 60, 45, 120]), 11)
    figure = viewer.trajectory_viewer(
        puma, [Q, Q[::-1]], labels=["out", "back"], times=np.linspace(0, 2.5, 11)
    )
    model = model_of(figure)
    robot = model_of(viewer.robot_viewer(puma))
    for key in ("screws", "home", "points", "axes", "joints", "approach"):
        assert model[key] == robot[key], key  # the same chain as the robot viewer's
    assert [p["label"] for p in model["paths"]] == ["out", "back"]
    np.testing.assert_allclose(model["paths"][1]["q"], Q[::-1], atol=1e-11)  # 12 digits
    assert model["times"][-1] == 2.5 and len(model["times"]) == 11
    assert model["slider"] == {
        "label": "t",
        "unit": "s",
        "min": 0.0,
        "max": 2.5,
        "step": 0.01,
        "value": 0.0,
        "scale": 1.0,
    }
    assert "out (red, solid), back (green, ghost)" in model["label"]


def test_trajectory_takes_a_dict_or_follow_path_results_and_unwraps_turns():
    # follow_path's result in place of its q; a revolute joint that crosses +-pi
    # between two samples is sent unwrapped (the same pose, no spin in between);
    # a prismatic joint is sent as it is.
    arm = sk.robots.planar([0.3, 0.2])
    q = np.array([[3.0, 0.1], [-3.0, 0.2], [-2.9, 0.3]])
    path = sk.motion.PathIK(q, np.ones(3, bool), np.zeros(3, bool), np.ones(3), [])
    model = model_of(viewer.trajectory_viewer(arm, {"wrapped": path}))
    sent = np.array(model["paths"][0]["q"])
    np.testing.assert_allclose(sent[:, 0], [3.0, 2 * np.pi - 3.0, 2 * np.pi - 2.9])
    np.testing.assert_allclose(arm.fk(sent), arm.fk(q), atol=1e-12)
    assert model["times"] == [0.0, 1.0, 2.0]  # default: the samples over 2 s
    slide = sk.Chain.from_screws(
        [[0, 0, 0, 1, 0, 0]], np.eye(4), qlim=[[-5.0, 5.0]], name="slide"
    )
    model = model_of(viewer.trajectory_viewer(slide, np.array([[3.0], [-3.0]])))
    assert model["paths"][0]["q"] == [[3.0], [-3.0]]


@pytest.mark.parametrize(
    ("call", "error", "message"),
    [
        (
            lambda: viewer.trajectory_viewer(sk.robots.puma560(), "q"),
            TypeError,
            r"paths must be an array \(K, n\) of joint values, a list of them or a "
            r"dict \{label: array\}, got 'q' \(str\)",
        ),
        (
            lambda: viewer.trajectory_viewer(sk.robots.puma560(), np.zeros((5, 5))),
            ValueError,
            r"paths\[0\] must have shape \(K, 6\) with K >= 2 samples, got shape "
            r"\(5, 5\)",
        ),
        (
            lambda: viewer.trajectory_viewer(
                sk.robots.puma560(), [np.zeros((5, 6)), np.zeros((4, 6))]
            ),
            ValueError,
            r"paths\[1\] must have as many samples as paths\[0\], 5, got 4",
        ),
        (
            lambda: viewer.trajectory_viewer(
                sk.robots.puma560(), np.full((3, 6), np.nan)
            ),
            ValueError,
            r"paths\[0\] must be finite, got nan",
        ),
        (
            lambda: viewer.trajectory_viewer(
                sk.robots.puma560(), np.zeros((3, 6)), times=[0, 2, 1]
            ),
            ValueError,
            "times must increase, got a step of -1 s",
        ),
        (
            lambda: viewer.trajectory_viewer(
                sk.robots.puma560(), np.zeros((3, 6)), times=[0, 1]
            ),
            ValueError,
            r"times must be 3 finite sample times \(s\), one per sample, got shape "
            r"\(2,\)",
        ),
        (
            lambda: viewer.trajectory_viewer(
                sk.robots.puma560(), np.zeros((3, 6)), labels=["a", "b"]
            ),
            ValueError,
            r"labels must be 1 names \(str\), one per path, got \['a', 'b'\]",
        ),
        (
            lambda: viewer.trajectory_viewer(
                sk.robots.puma560(), {"a": np.zeros((3, 6))}, labels=["a"]
            ),
            ValueError,
            "labels must be None when paths is a dict",
        ),
        (
            lambda: viewer.trajectory_viewer(
                sk.robots.puma560(), [np.zeros((3, 6))] * 5
            ),
            ValueError,
            "paths must hold 1 to 4 trajectories, got 5",
        ),
    ],
)
def test_a_bad_trajectory_is_refused_with_the_reason(call, error, message):
    with pytest.raises(error, match=message):
        call()


def test_the_time_slider_obeys_the_slider_rules_but_starts_at_its_first_time():
    # tests/slider_rules.py: a player's time may start at the low end of its range
    # (only there: a time slider is not a joint kept off its limits), every other rule
    # holds.
    from slider_rules import problems

    model = model_of(viewer.trajectory_viewer(sk.robots.puma560(), np.zeros((4, 6))))
    time = model["slider"]
    assert problems(time, starts_at_an_end=True) == []
    assert problems(time) == [
        "t [0.0, 2.0] step 0.01 at 0.0: default not strictly inside the range"
    ]
    assert problems({**time, "value": 2.0}, starts_at_an_end=True) == [
        "t [0.0, 2.0] step 0.01 at 2.0: default not strictly inside the range"
    ]
