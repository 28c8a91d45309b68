"""The in-page viewers computed by screwkit/static/viewer/ agree with screwkit, in
Chromium.

Each figure is rendered into a page of headless Chromium (the system Chromium through
pytest-playwright's fixtures, no network, WebGL by SwiftShader); the page's forward
kinematics, exponential of a twist, manipulability ellipsoid and platform leg lengths
are compared with screwkit's (or with the formula written here) on random
configurations; the page's layout, scrolling, keyboard and accessible names are
checked as a reader would meet them. Run by `make site-check` (it needs
.ci/requirements.txt); skipped without Chromium.
"""

import math

import harness
import numpy as np
import pytest

import screwkit as sk
from screwkit import viewer

pytest.importorskip("pytest_playwright")
pytestmark = pytest.mark.skipif(
    harness.CHROMIUM is None, reason="needs Chromium (apt-get install chromium)"
)


@pytest.fixture
def page(page):
    """pytest-playwright's page (a fresh one per test, in the system Chromium: the
    repository's conftest.py), keeping its errors in ``page.errors``."""
    harness.collect_errors(page)
    return page


def show(page, figure, width=760):
    page.set_content(
        f"<html><body style='max-width:{width}px'>{figure.html(library=True)}"
        "</body></html>"
    )
    assert page.errors == []
    return figure.id


def random_configurations(chain, count, seed):
    rng = np.random.default_rng(seed)
    low, high = (
        np.clip(chain.qlim[:, 0], -np.pi, None),
        np.clip(chain.qlim[:, 1], None, np.pi),
    )
    return rng.uniform(low, high, size=(count, chain.n))


def page_fk(page, figure_id, Q):
    return np.array(
        page.evaluate(
            """([id, Q]) => {
            const v = window.screwkit.viewers[id];
            return Q.map(q => window.screwkit.chainPose(v.figure.model, q).tool);
        }""",
            [figure_id, Q.tolist()],
        )
    ).reshape(-1, 4, 4)


@pytest.mark.parametrize(
    "make",
    [
        sk.robots.puma560,
        sk.robots.kawasaki_cx210l,
        lambda: sk.robots.planar([0.3, 0.25, 0.2]),
    ],
    ids=["puma560", "kawasaki", "planar3"],
)
def test_page_fk_equals_chain_fk(page, make):
    chain = make()
    Q = random_configurations(chain, 200, seed=1)
    figure_id = show(page, viewer.robot_viewer(chain))
    np.testing.assert_allclose(page_fk(page, figure_id, Q), chain.fk(Q), atol=1e-9)


@pytest.mark.skipif(
    not hasattr(sk.Chain, "from_screws"), reason="Chain.from_screws not there yet"
)
def test_page_fk_of_a_helical_poe_chain(page):
    chain = sk.Chain.from_screws(
        [[0, 0, 1, 0, 0, 0], [1, 0, 0, 0, 0.3, 0.05], [0, 0, 0, 0, 1, 0]],
        np.array([[1, 0, 0, 0.5], [0, 1, 0, 0], [0, 0, 1, 0.4], [0, 0, 0, 1]]),
    )
    Q = np.random.default_rng(2).uniform(-1, 1, size=(100, chain.n))
    figure_id = show(page, viewer.robot_viewer(chain))
    np.testing.assert_allclose(page_fk(page, figure_id, Q), chain.fk(Q), atol=1e-9)


def test_page_ellipsoid_equals_screwkit(page):
    puma = sk.robots.puma560()
    figure_id = show(page, viewer.robot_viewer(puma, ellipsoid=True))
    for q in random_configurations(puma, 30, seed=3):
        radii, w = page.evaluate(
            """([id, q]) => {
                const m = window.screwkit.viewers[id].figure.model;
                const e = window.screwkit.ellipsoid(m, window.screwkit.chainPose(m, q));
                return [e.radii, e.w];
            }""",
            [figure_id, q.tolist()],
        )
        _, expected, _ = sk.jacobians.ellipsoid(puma, q, rows="position")
        np.testing.assert_allclose(sorted(radii, reverse=True), expected, atol=1e-9)
        assert w == pytest.approx(puma.manipulability(q, rows="position"), abs=1e-9)


@pytest.mark.parametrize("pitch", [0.0, 0.12, -0.3, np.inf])
def test_page_screw_motion_equals_screw_motion(page, pitch):
    s, r = np.array([1.0, 2.0, 2.0]) / 3, np.array([0.4, -0.2, 0.1])
    start = sk.transl(0.1, 0.2, 0.3) @ sk.homogeneous(sk.rotx(0.7), [0, 0, 0])
    figure = viewer.screw_motion_viewer(s, r, pitch, start=start, theta=0.0)
    figure_id = show(page, figure)
    angles = np.random.default_rng(4).uniform(-2 * np.pi, 2 * np.pi, 50)
    poses = page.evaluate(
        """([id, angles]) => angles.map(t =>
        window.screwkit.viewers[id].figure.pose(t))""",
        [figure_id, angles.tolist()],
    )
    expected = sk.screw_motion(s, r, pitch, angles) @ start
    np.testing.assert_allclose(np.reshape(poses, (-1, 4, 4)), expected, atol=1e-12)


def test_moving_a_slider_redraws(page):
    figure_id = show(page, viewer.robot_viewer(sk.robots.puma560(), ellipsoid=True))
    before = page.evaluate(
        "id => document.getElementById(id).querySelector('canvas').toDataURL()",
        figure_id,
    )
    caption = page.locator(f"[id='{figure_id}'] .screwkit-caption").inner_text()
    page.locator(f"[id='{figure_id}'] input[type=range]").nth(1).fill("90")
    after = page.evaluate(
        "id => document.getElementById(id).querySelector('canvas').toDataURL()",
        figure_id,
    )
    assert after != before
    assert page.locator(f"[id='{figure_id}'] .screwkit-caption").inner_text() != caption
    assert page.errors == []


# In the page: where the tool point and every joint point of a robot figure fall in
# normalised device coordinates (inside the picture when both lie in [-1, 1]).
PROJECTED = """id => {
    const v = window.screwkit.viewers[id], S = v.stage, f = v.figure;
    const pose = window.screwkit.chainPose(f.model, v.sliders.map(
        s => +s.input.value * s.spec.scale));
    return f.points(pose).map(p => {
        const n = new S.THREE.Vector3(p[0], p[1], p[2]).project(S.camera);
        return [n.x, n.y];
    });
}"""


def site_check_moves(model):
    """Each slider's value after the site check's move (.ci/site_check.py,
    MOVE_CONTROL): a third of its range further along its grid, wrapping past its
    top."""
    moves = []
    for s in model["sliders"]:
        count = math.floor((s["max"] - s["min"]) / s["step"] + 0.5)
        here = math.floor((s["value"] - s["min"]) / s["step"] + 0.5)
        jump = max(1, math.floor(count / 3 + 0.5))
        moves.append(s["min"] + s["step"] * ((here + jump) % (count + 1)))
    return moves


@pytest.mark.parametrize(
    "make, pose",
    [(sk.robots.puma560, "nominal"), (sk.robots.panda, "ready")],
    ids=["puma560", "panda"],
)
def test_the_arm_stays_in_the_picture_and_every_joint_moves_it(page, make, pose):
    # The site check's moves lift the PUMA's wrist (q1 to 107, q2 to 135, q3 to -90 deg)
    # and swing the Panda's hand beyond the first view: the view must follow, so that
    # the wrist joints' moves still show.
    chain = make()
    figure = viewer.robot_viewer(chain, chain.configurations[pose])
    figure_id = show(page, figure)
    root = page.locator(f"[id='{figure_id}']")
    snapshot = (
        f"() => document.getElementById('{figure_id}').querySelector('canvas')"
        ".toDataURL()"
    )
    for k, value in enumerate(site_check_moves(figure.model)):
        before = page.evaluate(snapshot)
        root.locator("input[type=range]").nth(k).fill(f"{value:g}")
        assert page.evaluate(snapshot) != before, f"moving q{k + 1} changed nothing"
        inside = np.abs(page.evaluate(PROJECTED, figure_id))
        assert inside.max() <= 1.0, f"after q{k + 1}: a joint or the tool left the view"
    assert page.errors == []


def test_the_gripper_is_drawn_on_the_tool_frame(page):
    # The gripper (palm and fingers) is a group placed by the tool pose itself, so the
    # wrist's turn shows: its matrix is chain.fk at the sliders' values, to 1e-9.
    puma = sk.robots.puma560()
    figure_id = show(page, viewer.robot_viewer(puma))
    root = page.locator(f"[id='{figure_id}']")
    degrees = [10, -30, 40, 70, -50, 120]
    for k, value in enumerate(degrees):
        root.locator("input[type=range]").nth(k).fill(str(value))
    matrix, parts = page.evaluate(
        """id => {
        const g = window.screwkit.viewers[id].figure.gripper.group;
        g.updateMatrixWorld(true);
        return [g.matrixWorld.clone().transpose().toArray(), g.children.length];
    }""",
        figure_id,
    )
    np.testing.assert_allclose(
        np.reshape(matrix, (4, 4)), puma.fk(np.radians(degrees)), atol=1e-9
    )
    assert parts == 4  # stub, palm and two fingers


# ---- platforms: a stand-in with the interface of sk.robots.stewart_gough() ----


class StandIn:
    """Six legs: base points on a circle of 0.5 m, platform points on one of 0.3 m."""

    name = "stand-in 6-6 platform"
    planar = False

    def __init__(self, limits=True):
        a = np.radians([0, 60, 120, 180, 240, 300]) + np.radians([-10, 10] * 3)
        b = np.radians([0, 120, 240]).repeat(2) + np.radians([-50, 50] * 3)
        self.base_points = 0.5 * np.c_[np.cos(a), np.sin(a), np.zeros(6)]
        self.platform_points = 0.3 * np.c_[np.cos(b), np.sin(b), np.zeros(6)]
        self.leg_limits = np.tile([0.5, 0.75], (6, 1)) if limits else None

    def home(self):
        return sk.transl(0, 0, 0.55) @ sk.homogeneous(sk.rotz(0.1), [0, 0, 0])


class PlanarStandIn:
    name = "stand-in 3-RPR"
    planar = True
    base_points = np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.5, 0.9, 0.0]])
    platform_points = np.array([[-0.1, -0.06, 0.0], [0.1, -0.06, 0.0], [0.0, 0.1, 0.0]])
    leg_limits = None

    def home(self):
        return sk.transl(0.5, 0.35, 0.0)


def expected_legs(pm, pose):
    """|p + R b_i - a_i| with the sliders' absolute pose: p = (x, y, z), R = Rz(yaw)
    Ry(pitch) Rx(roll); planar p = (x, y, z_home), R = Rz(phi)."""
    if pm.planar:
        p, R = np.array([pose[0], pose[1], pm.home()[2, 3]]), sk.rotz(pose[2])
    else:
        p = np.asarray(pose[:3])
        R = sk.rotz(pose[5]) @ sk.roty(pose[4]) @ sk.rotx(pose[3])
    return np.linalg.norm(p + pm.platform_points @ R.T - pm.base_points, axis=1)


@pytest.mark.parametrize("pm", [StandIn(), PlanarStandIn()], ids=["spatial", "planar"])
def test_page_leg_lengths_equal_the_formula(page, pm):
    figure_id = show(page, viewer.show_platform(pm))
    rng = np.random.default_rng(5)
    n = 3 if pm.planar else 6
    home = [s["value"] * s["scale"] for s in viewer.show_platform(pm).model["sliders"]]
    offsets = home + rng.uniform(-0.15, 0.15, size=(100, n))
    lengths = page.evaluate(
        """([id, V]) => {
            const f = window.screwkit.viewers[id].figure;
            return V.map(v => window.screwkit.legLengths(f.model, f.pose(v)));
        }""",
        [figure_id, offsets.tolist()],
    )
    expected = np.array([expected_legs(pm, v) for v in offsets])
    np.testing.assert_allclose(lengths, expected, atol=1e-9)


def test_a_leg_outside_its_limits_is_marked_and_announced(page):
    pm = StandIn()
    figure_id = show(page, viewer.show_platform(pm))
    root = page.locator(f"[id='{figure_id}']")
    z = root.locator("input[type=range]").nth(2)
    z.fill(z.get_attribute("max"))  # the platform lifted to the top of its slider
    yaw = np.radians(float(root.locator("input[type=range]").nth(5).input_value()))
    legs = expected_legs(pm, [0, 0, float(z.get_attribute("max")), 0, 0, yaw])
    outside = [i + 1 for i, x in enumerate(legs) if not 0.5 <= x <= 0.75]
    assert outside  # the slider's top reaches past the 0.75 m limit (checked here)
    caption = root.locator(".screwkit-caption")
    assert caption.get_attribute("aria-live") == "polite"
    text = caption.inner_text()
    assert ", ".join(f"{x:.3f}" for x in legs) in text
    assert (
        f"Outside the limits: leg{'s' if len(outside) > 1 else ''} "
        f"{', '.join(map(str, outside))}." in text
    )
    marked = root.locator(".screwkit-labels span.screwkit-bad").all_inner_texts()
    assert marked == [f"{i} !" for i in outside]


# ---- the page as a reader meets it: layout, scrolling, keyboard, accessible names ----


def test_several_outputs_rendered_in_any_order_all_mount(page):
    # The library comes with one output only; an output placed before it waits for it.
    puma = sk.robots.puma560()
    carrier = viewer.robot_viewer(puma)
    later, screw = (
        viewer.robot_viewer(puma),
        viewer.screw_motion_viewer([0, 0, 1], [0, 0, 0], 0),
    )
    steps = viewer.stepped_figure(str, "k", "1/s", values=viewer.grid(0, 1, 0.5))
    page.set_content(
        "<html><body>"
        + steps.html()
        + later.html(library=False)
        + screw.html(library=False)
        + carrier.html(library=True)
        + "</body></html>"
    )
    for figure in (steps, later, screw, carrier):
        assert page.evaluate(
            "id => document.getElementById(id).dataset.mounted", figure.id
        )
    assert page.locator(".screwkit-note").count() == 0  # every "waiting" note is gone
    assert page.locator(f"[id='{later.id}'] canvas").count() == 1
    assert page.errors == []


@pytest.mark.parametrize("width", [390, 1280])
def test_viewer_fits_its_column_and_names_itself(page, width):
    page.set_viewport_size({"width": width, "height": 800})
    figure = viewer.robot_viewer(sk.robots.puma560(), ellipsoid=True)
    figure_id = show(page, figure, width=width - 16)
    box = page.evaluate(
        """id => {
        const root = document.getElementById(id), c = root.querySelector('canvas');
        const r = c.getBoundingClientRect();
        return {right: r.right, width: r.width, pixels: c.width, page:
        document.documentElement.scrollWidth,
                role: c.getAttribute('role'), label: c.getAttribute('aria-label'),
                touch: getComputedStyle(c).touchAction, live:
                root.querySelector('.screwkit-caption') .getAttribute('aria-live'),
                ratio: window.devicePixelRatio};
    }""",
        figure_id,
    )
    assert box["right"] <= width and box["page"] <= width
    assert box["width"] >= min(width - 40, 700) * 0.9  # it fills its column
    assert box["pixels"] == round(box["width"] * box["ratio"])
    assert box["role"] == "img" and box["label"].startswith(
        "PUMA 560: a serial robot arm of 6"
    )
    assert box["touch"] == "pan-y" and box["live"] == "polite"
    page.set_viewport_size({"width": 1280, "height": 800})


def test_the_wheel_scrolls_the_page_and_ctrl_wheel_zooms(page):
    figure_id = show(page, viewer.robot_viewer(sk.robots.puma560()))
    prevented = page.evaluate(
        """id => {
        const c = document.getElementById(id).querySelector('canvas');
        const v = window.screwkit.viewers[id].stage, out = [];
        for (const ctrlKey of [false, true]) {
            const zoom = v.zoom;
            const e = new WheelEvent('wheel', {deltaY: 100, ctrlKey, cancelable: true,
            bubbles: true}); c.dispatchEvent(e); out.push([e.defaultPrevented, v.zoom
            !== zoom]);
        }
        return out;
    }""",
        figure_id,
    )
    assert prevented == [[False, False], [True, True]]


def test_keyboard_orbits_and_zooms_when_focused(page):
    figure_id = show(page, viewer.robot_viewer(sk.robots.puma560()))
    canvas = page.locator(f"[id='{figure_id}'] canvas")
    snapshot = (
        f"() => document.getElementById('{figure_id}')"
        ".querySelector('canvas').toDataURL()"
    )
    before = page.evaluate(snapshot)
    canvas.focus()
    canvas.press("ArrowLeft")
    turned = page.evaluate(snapshot)
    canvas.press("+")
    assert page.evaluate(f"() => window.screwkit.viewers['{figure_id}'].stage.zoom") < 1
    canvas.press("0")
    assert turned != before
    assert page.evaluate(snapshot) == before  # reset: the first view again


def test_slider_rows_do_not_reflow_and_labels_do_not_overlap(page):
    figure_id = show(page, viewer.robot_viewer(sk.robots.puma560()), width=374)
    root = page.locator(f"[id='{figure_id}']")

    def boxes():
        return [
            root.locator(".screwkit-controls > *").nth(k).bounding_box()
            for k in range(4 * 6)
        ]

    before = boxes()
    for k in range(6):
        slider = root.locator("input[type=range]").nth(k)
        slider.fill(slider.get_attribute("min"))
    after = boxes()
    assert (
        before == after
    )  # readouts of fixed width: nothing moves when a value changes
    for row in range(
        6
    ):  # label | slider | readout | unit, left to right, not overlapping
        cells = after[4 * row : 4 * row + 4]
        assert all(
            a["x"] + a["width"] <= b["x"] + 0.5 for a, b in zip(cells, cells[1:])
        )


def test_mechanism_viewer_draws_each_limb(page):
    figure_id = show(page, viewer.show_mechanism("pm_3prpar"))
    labels = page.locator(f"[id='{figure_id}'] .screwkit-labels span").all_inner_texts()
    assert labels == ["limb 1", "limb 2", "limb 3"]
    canvas = page.locator(f"[id='{figure_id}'] canvas")
    snapshot = (
        f"() => document.getElementById('{figure_id}')"
        ".querySelector('canvas').toDataURL()"
    )
    before = page.evaluate(snapshot)
    box = canvas.bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.down()
    page.mouse.move(
        box["x"] + box["width"] / 2 + 80, box["y"] + box["height"] / 2, steps=4
    )
    page.mouse.up()
    assert page.evaluate(snapshot) != before  # a drag turns it
    assert page.errors == []


def swipe(cdp, x, y, dx, dy, steps=10):
    """One finger from (x, y) moved by (dx, dy) px in ``steps`` moves, then lifted."""
    cdp.send(
        "Input.dispatchTouchEvent",
        {"type": "touchStart", "touchPoints": [{"x": x, "y": y}]},
    )
    for k in range(1, steps + 1):
        point = {"x": x + dx * k / steps, "y": y + dy * k / steps}
        cdp.send(
            "Input.dispatchTouchEvent", {"type": "touchMove", "touchPoints": [point]}
        )
    cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})


def test_a_swipe_or_the_wheel_over_the_viewer_scrolls_the_page(page):
    # As a reader meets it: a long page, the pointer (or a finger) on the drawing. (With
    # the old `touch-action: none` the same swipe leaves the page where it was.)
    figure = viewer.robot_viewer(sk.robots.puma560())
    content = (
        f"<html><body style='margin:0'>{figure.html(library=True)}"
        "<div style='height:3000px'></div></body></html>"
    )
    page.set_viewport_size({"width": 1280, "height": 700})
    page.set_content(content)
    box = page.locator(f"[id='{figure.id}'] canvas").bounding_box()
    page.mouse.move(box["x"] + box["width"] / 2, box["y"] + box["height"] / 2)
    page.mouse.wheel(0, 300)
    page.wait_for_function("() => window.scrollY > 0", timeout=5000)
    assert (
        page.evaluate(f"() => window.screwkit.viewers['{figure.id}'].stage.zoom") == 1
    )
    with page.context.browser.new_context(
        viewport={"width": 390, "height": 700}, has_touch=True
    ) as phone:
        tab = phone.new_page()
        tab.set_content(content)
        box = tab.locator(f"[id='{figure.id}'] canvas").bounding_box()
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        cdp = phone.new_cdp_session(tab)
        snapshot = (
            f"() => document.getElementById('{figure.id}')"
            ".querySelector('canvas').toDataURL()"
        )
        before = tab.evaluate(snapshot)
        swipe(cdp, x, y, 120, 0)  # sideways: turns the view, the page stays
        assert tab.evaluate("() => window.scrollY") == 0
        assert tab.evaluate(snapshot) != before
        swipe(cdp, x, y, 0, -200)  # up: the page scrolls
        tab.wait_for_function("() => window.scrollY > 100", timeout=5000)
        tab.evaluate("() => window.scrollTo(0, 0)")
        box = tab.locator(f"[id='{figure.id}'] canvas").bounding_box()
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2

        def fingers(gap):
            return [{"x": x - gap, "y": y, "id": 0}, {"x": x + gap, "y": y, "id": 1}]

        cdp.send(
            "Input.dispatchTouchEvent",
            {"type": "touchStart", "touchPoints": fingers(20)},
        )
        for gap in (24, 28, 32, 36, 40):  # two fingers apart: a pinch zooms the view in
            cdp.send(
                "Input.dispatchTouchEvent",
                {"type": "touchMove", "touchPoints": fingers(gap)},
            )
        cdp.send("Input.dispatchTouchEvent", {"type": "touchEnd", "touchPoints": []})
        zoom = tab.evaluate(f"() => window.screwkit.viewers['{figure.id}'].stage.zoom")
        assert zoom == pytest.approx(20 / 40, rel=0.15)  # the fingers' gap doubled
        assert tab.evaluate("() => visualViewport.scale") == 1  # the page did not zoom


def test_the_sliders_drive_the_drawn_pose_exactly(page):
    # Moving the sliders as a reader does: the pose drawn (tool frame, joint markers) is
    # chain.fk at the sliders' values, to 1e-9.
    puma = sk.robots.puma560()
    figure_id = show(page, viewer.robot_viewer(puma))
    root = page.locator(f"[id='{figure_id}']")
    degrees = [30, -45, 20, 90, -60, 15]
    for k, value in enumerate(degrees):
        root.locator("input[type=range]").nth(k).fill(str(value))
    drawn = page.evaluate(
        """id => {
        const f = window.screwkit.viewers[id].figure, m = f.toolFrame[2][0];
        return {tool: f.lastPose.tool, joint4: f.joints[3].mesh.position.toArray(),
                zArrowStart: m.position.toArray(), caption: document.getElementById(id)
                .querySelector('.screwkit-caption').textContent};
    }""",
        figure_id,
    )
    expected = puma.fk(np.radians(degrees))
    np.testing.assert_allclose(np.reshape(drawn["tool"], (4, 4)), expected, atol=1e-9)
    x, y, z = expected[:3, 3]
    assert drawn["caption"].startswith(f"Tool at ({x:.3f}, {y:.3f}, {z:.3f}) m.")
    _, points = puma.joint_axes(np.radians(degrees))  # joint 4's marker on its axis
    np.testing.assert_allclose(
        drawn["joint4"], points[3], atol=1e-6
    )  # float32 in three


def test_the_canvas_uses_the_device_pixel_ratio(page):
    figure = viewer.robot_viewer(sk.robots.puma560())
    with page.context.browser.new_context(
        viewport={"width": 390, "height": 700}, device_scale_factor=2
    ) as phone:
        tab = phone.new_page()
        tab.set_content(f"<html><body>{figure.html(library=True)}</body></html>")
        css, pixels = tab.evaluate(
            f"""() => {{
            const c = document.getElementById('{figure.id}').querySelector('canvas');
            return [c.getBoundingClientRect().width, c.width];
        }}"""
        )
        assert pixels == round(2 * css) and css <= 390


def test_the_readout_gives_the_tools_orientation(page):
    # Moving a wrist joint changes the numbers: the readout's roll, pitch, yaw are
    # those of chain.fk at the sliders (screwkit.orientation.rpy_from_rotation), to the
    # 0.1 deg printed.
    puma = sk.robots.puma560()
    figure_id = show(page, viewer.robot_viewer(puma))
    root = page.locator(f"[id='{figure_id}']")
    caption = root.locator(".screwkit-caption")
    degrees = [20, -40, 30, 0, 50, 0]
    for k, value in enumerate(degrees):
        root.locator("input[type=range]").nth(k).fill(str(value))
    texts = []
    for q4 in (0, 35, -70):
        root.locator("input[type=range]").nth(3).fill(str(q4))
        degrees[3] = q4
        rpy = np.degrees(
            sk.orientation.rpy_from_rotation(puma.fk(np.radians(degrees))[:3, :3])
        )
        text = caption.inner_text()
        assert (
            f"Roll, pitch, yaw ({rpy[0]:.1f}, {rpy[1]:.1f}, {rpy[2]:.1f}) deg." in text
        )
        texts.append(text)
    assert len(set(texts)) == 3


def test_a_planar_platform_is_seen_from_above(page):
    # The camera looks down the z axis (to the orbit's limit of 86 deg), x to the
    # right and y up on the screen: the base's x axis projects rightwards, its y axis
    # upwards.
    figure_id = show(page, viewer.show_platform(PlanarStandIn()))
    ends, looking = page.evaluate(
        """id => {
        const S = window.screwkit.viewers[id].stage;
        return [[[0, 0, 0], [0.1, 0, 0], [0, 0.1, 0]].map(p => {
            const n = new S.THREE.Vector3(p[0], p[1], p[2]).project(S.camera);
            return [n.x * S.width / 2, n.y * S.height / 2];
        }), S.camera.getWorldDirection(new S.THREE.Vector3()).toArray()];
    }""",
        figure_id,
    )
    assert looking[2] < -np.cos(np.radians(5))  # down, within 5 deg of -z
    o, x, y = np.asarray(ends)  # px from the centre, y up
    # (within 3 deg: the perspective and the 4 deg left by the orbit's limit)
    assert (x - o)[0] > 0 and abs((x - o)[1]) < 0.05 * (x - o)[0]
    assert (y - o)[1] > 0 and abs((y - o)[0]) < 0.05 * (y - o)[1]


# ---- trajectories: joint paths computed in Python, played in the page ----


def puma_paths(samples=31, duration=3.0):
    """The motion chapter's two paths of the PUMA (screw motion, straight line +
    slerp) between two poses, timed by a quintic and solved by the closed-form IK."""
    puma = sk.robots.puma560()
    q_start = np.radians([0, -30, 20, 0, 40, 0])
    T0, T1 = puma.fk(q_start), puma.fk(np.radians([90, -10, -10, 60, 60, 30]))
    timing = sk.motion.trajectory.quintic(duration)
    times = timing.times(samples)
    s = timing(times)
    paths = {
        "screw motion": sk.motion.trajectory.follow_path(
            puma, sk.motion.trajectory.screw_path(T0, T1, s), q_start=q_start
        ),
        "straight line": sk.motion.trajectory.follow_path(
            puma, sk.motion.trajectory.cartesian_path(T0, T1, s), q_start=q_start
        ),
    }
    return puma, paths, times


def test_the_drawn_arms_are_the_paths_poses_at_the_sliders_time(page):
    # Scrubbing the time slider as a reader does: at a sample time each arm's gripper
    # is chain.fk of its path's sample; between two samples, of the joint values
    # interpolated linearly (np.interp), to 1e-9.
    puma, paths, times = puma_paths()
    figure = viewer.trajectory_viewer(puma, paths, times=times)
    figure_id = show(page, figure)
    root = page.locator(f"[id='{figure_id}']")
    Q = [np.array(p["q"]) for p in figure.model["paths"]]
    for t in (times[10], 1.23, times[-1]):
        root.locator("input[type=range]").fill(f"{t:.2f}")
        t = round(t, 2)
        grippers = page.evaluate(
            """id => window.screwkit.viewers[id].figure.arms.map(a => {
                const g = a.gripper.group;
                g.updateMatrixWorld(true);
                return g.matrixWorld.clone().transpose().toArray();
            })""",
            figure_id,
        )
        for q, drawn in zip(Q, grippers):
            expected = puma.fk([np.interp(t, times, q[:, j]) for j in range(6)])
            np.testing.assert_allclose(np.reshape(drawn, (4, 4)), expected, atol=1e-9)
        assert root.get_attribute("data-time") == f"{t:.3f}"
    assert page.errors == []


# What the player shows while it plays, recorded in the page as it changes (a check
# made from here after the click could come after a short animation has ended, on a
# loaded machine): the play button's label and the caption's aria-live.
RECORD_TRANSITIONS = """id => {
  const root = document.getElementById(id);
  const button = root.querySelector('button.screwkit-play');
  const caption = root.querySelector('.screwkit-caption');
  window.seen = {labels: [], live: []};
  new MutationObserver(() => window.seen.labels.push(button.textContent.trim()))
    .observe(button, {childList: true, characterData: true, subtree: true});
  new MutationObserver(() => window.seen.live.push(caption.getAttribute('aria-live')))
    .observe(caption, {attributes: true, attributeFilter: ['aria-live']});
}"""


def test_play_moves_the_arms_and_stops_at_the_end(page):
    puma, paths, times = puma_paths(duration=3.0)
    figure_id = show(page, viewer.trajectory_viewer(puma, paths, times=times))
    root = page.locator(f"[id='{figure_id}']")
    button = root.locator("button.screwkit-play")
    caption = root.locator(".screwkit-caption")
    snapshot = (
        f"() => document.getElementById('{figure_id}').querySelector('canvas')"
        ".toDataURL()"
    )
    before, text = page.evaluate(snapshot), caption.inner_text()
    assert (
        button.inner_text().endswith("Play")
        and root.get_attribute("data-time") == "0.000"
    )
    page.evaluate(RECORD_TRANSITIONS, figure_id)
    button.click()
    page.wait_for_function(
        f"() => !document.getElementById('{figure_id}').dataset.playing", timeout=30000
    )
    seen = page.evaluate("window.seen")
    # Pause while it played, Play at the end; no announcement per frame while it played
    assert [label[-5:].strip() for label in seen["labels"]] == ["Pause", "Play"]
    assert seen["live"] == ["off", "polite"]
    assert root.get_attribute("data-time") == "3.000"
    assert page.evaluate(snapshot) != before and caption.inner_text() != text
    assert caption.inner_text().startswith("t = 3.00 s. screw motion: tool at")
    button.click()  # at the end, play starts again from the first time
    page.wait_for_function(
        f"() => +document.getElementById('{figure_id}').dataset.time < 2",
        timeout=5000,
    )
    assert page.errors == []


def test_pause_stops_the_arms_where_they_are(page):
    # a long motion, so that the pause always comes before its end, however slowly
    # a loaded machine delivers the clicks
    puma, paths, times = puma_paths(duration=60.0)
    figure_id = show(page, viewer.trajectory_viewer(puma, paths, times=times))
    root = page.locator(f"[id='{figure_id}']")
    button = root.locator("button.screwkit-play")
    button.click()  # play
    page.wait_for_function(
        f"() => +document.getElementById('{figure_id}').dataset.time > 0",
        timeout=10000,
    )
    button.click()  # pause
    page.wait_for_function(
        f"() => !document.getElementById('{figure_id}').dataset.playing", timeout=10000
    )
    paused = root.get_attribute("data-time")
    page.wait_for_timeout(300)
    assert root.get_attribute("data-time") == paused and 0 < float(paused) < 60
    assert button.inner_text().endswith("Play")
    assert page.errors == []


def test_the_site_checks_rule_presses_play_and_sees_the_arm_move(page, tmp_path):
    # A small built "book": a page whose viewer plays, one whose page stops every
    # animation frame (so play cannot move it), one whose page swallows a click on a
    # playing viewer (so it cannot pause), and a chapter whose code calls
    # trajectory_viewer but whose page shows none. The trajectory lasts 1 s, so on a
    # busy machine it may end before the second click: the rule must still pass the
    # first page and name the other three.
    import json

    import site_check

    puma, paths, times = puma_paths(samples=11, duration=1.0)
    figure = viewer.trajectory_viewer(puma, paths, times=times)
    frozen = "<script>window.requestAnimationFrame = () => 0;</script>"
    (tmp_path / "notebooks").mkdir()
    (tmp_path / "notebooks" / "plays.html").write_text(figure.page())
    (tmp_path / "notebooks" / "frozen.html").write_text(
        figure.page().replace("<body>", "<body>" + frozen, 1)
    )
    stuck = (
        "<script>document.addEventListener('click', e => {"
        " if (e.target.closest('.screwkit-play')"
        " && e.target.closest('.screwkit-viewer').dataset.playing === '1')"
        " e.stopPropagation(); }, true);</script>"
    )
    (tmp_path / "notebooks" / "stuck.html").write_text(
        figure.page().replace("<body>", "<body>" + stuck, 1)
    )
    (tmp_path / "notebooks" / "none.html").write_text("<html><body>text</body></html>")
    sources = tmp_path / "_sources" / "notebooks"
    sources.mkdir(parents=True)
    cell = {"cell_type": "code", "source": ["sk.viewer.trajectory_viewer(puma, Q)"]}
    (sources / "none.ipynb").write_text(json.dumps({"cells": [cell]}))
    server = site_check.serve(str(tmp_path))
    try:
        site = site_check.Site(
            root=str(tmp_path),
            origin=f"http://127.0.0.1:{server.server_address[1]}/",
            pages=[
                "notebooks/plays.html",
                "notebooks/frozen.html",
                "notebooks/stuck.html",
                "notebooks/none.html",
            ],
            tmp=str(tmp_path),
        )
        problems = site_check.trajectories_play_in(page.context.browser, site)
    finally:
        server.shutdown()
    assert problems == [
        f"notebooks/frozen.html: play on {figure.id} did not move it: its time went "
        "from 0 s to 0 s in 10 s",
        f"notebooks/stuck.html: play on {figure.id} did not pause on a second click",
        "notebooks/none.html: its code calls trajectory_viewer but the page has no "
        "player (a viewer with a play button)",
    ]


def test_the_play_rule_passes_a_player_that_ended_before_the_second_click(
    page, tmp_path, monkeypatch
):
    # What a busy machine does to a 1 s trajectory: the rule waits until its time has
    # reached the end, where the player stops by itself; a click then would play it
    # again, so the rule's second click must still find a player that pauses.
    import site_check

    puma, paths, times = puma_paths(samples=11, duration=1.0)
    figure = viewer.trajectory_viewer(puma, paths, times=times)
    (tmp_path / "notebooks").mkdir()
    (tmp_path / "notebooks" / "plays.html").write_text(figure.page())
    monkeypatch.setattr(site_check, "PLAYED_S", 1.0)
    server = site_check.serve(str(tmp_path))
    try:
        site = site_check.Site(
            root=str(tmp_path),
            origin=f"http://127.0.0.1:{server.server_address[1]}/",
            pages=["notebooks/plays.html"],
            tmp=str(tmp_path),
        )
        problems = site_check.trajectories_play_in(page.context.browser, site)
    finally:
        server.shutdown()
    assert problems == []


def test_the_site_checks_waits_follow_the_page_not_a_clock(page):
    # A sidebar that closes 1.2 s after its button is pressed (a slow transition, or a
    # busy machine): `becomes` sees it close, where the fixed 0.4 s pause it replaced
    # did not; and a sidebar that never closes is still reported.
    import site_check

    page.set_content(
        "<nav id='side'><a href='#'>a chapter</a></nav><script>"
        "setTimeout(() => document.getElementById('side').hidden = true, 1200);"
        "</script>"
    )
    links = "#side a"
    assert page.evaluate(site_check.VISIBLE, links) == 1
    assert site_check.becomes(page, site_check.VISIBLE, links, "=== 0", seconds=5)
    page.set_content("<nav id='side'><a href='#'>a chapter</a></nav>")
    assert not site_check.becomes(page, site_check.VISIBLE, links, "=== 0", seconds=1)
