"""The in-page viewers computed by screwkit/static/viewer.js agree with screwkit, in Chromium.

Each figure is rendered into a page of headless Chromium (system Chromium driven by
Playwright, no network); the page's forward kinematics, exponential of a twist and
manipulability ellipsoid are compared with screwkit's on random configurations.
Run by `make site-check` (it needs .ci/requirements.txt); skipped without Chromium.
"""
import shutil

import numpy as np
import pytest

import screwkit as sk
from screwkit import viewer

playwright = pytest.importorskip("playwright.sync_api")
CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
FLAGS = ["--no-sandbox", "--disable-gpu", "--disable-background-networking",
         "--disable-component-update", "--disable-sync", "--no-first-run", "--disable-quic",
         "--host-resolver-rules=MAP * ~NOTFOUND, EXCLUDE 127.0.0.1"]
pytestmark = pytest.mark.skipif(CHROMIUM is None, reason="needs Chromium (apt-get install chromium)")


@pytest.fixture(scope="module")
def page():
    with playwright.sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=FLAGS)
        page = browser.new_page()
        errors = []
        page.on("pageerror", lambda error: errors.append(str(error)))
        page.on("console", lambda m: m.type == "error" and errors.append(m.text))
        page.errors = errors
        yield page
        browser.close()


def show(page, figure):
    page.set_content(f"<html><body>{figure._repr_html_()}</body></html>")
    assert page.errors == []
    return figure.id


def random_configurations(chain, count, seed):
    rng = np.random.default_rng(seed)
    low, high = np.clip(chain.qlim[:, 0], -np.pi, None), np.clip(chain.qlim[:, 1], None, np.pi)
    return rng.uniform(low, high, size=(count, chain.n))


def page_fk(page, figure_id, Q):
    return np.array(page.evaluate(
        """([id, Q]) => {
            const v = window.screwkit.viewers[id];
            return Q.map(q => window.screwkit.chainPose(v.figure.model, q).tool);
        }""", [figure_id, Q.tolist()])).reshape(-1, 4, 4)


@pytest.mark.parametrize("make", [sk.robots.puma560, sk.robots.kawasaki_cx210l,
                                  lambda: sk.robots.planar([0.3, 0.25, 0.2])],
                         ids=["puma560", "kawasaki", "planar3"])
def test_page_fk_equals_chain_fk(page, make):
    chain = make()
    Q = random_configurations(chain, 200, seed=1)
    figure_id = show(page, viewer.robot_viewer(chain))
    np.testing.assert_allclose(page_fk(page, figure_id, Q), chain.fk(Q), atol=1e-9)


@pytest.mark.skipif(not hasattr(sk.Chain, "from_screws"), reason="Chain.from_screws not there yet")
def test_page_fk_of_a_helical_poe_chain(page):
    chain = sk.Chain.from_screws(
        [[0, 0, 1, 0, 0, 0], [1, 0, 0, 0, 0.3, 0.05], [0, 0, 0, 0, 1, 0]],
        np.array([[1, 0, 0, 0.5], [0, 1, 0, 0], [0, 0, 1, 0.4], [0, 0, 0, 1]]))
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
            }""", [figure_id, q.tolist()])
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
        """([id, angles]) => angles.map(t => window.screwkit.viewers[id].figure.pose(t))""",
        [figure_id, angles.tolist()])
    expected = sk.screw_motion(s, r, pitch, angles) @ start
    np.testing.assert_allclose(np.reshape(poses, (-1, 4, 4)), expected, atol=1e-12)


def test_moving_a_slider_redraws(page):
    figure_id = show(page, viewer.robot_viewer(sk.robots.puma560(), ellipsoid=True))
    before = page.evaluate("id => document.getElementById(id).querySelector('canvas').toDataURL()",
                           figure_id)
    caption = page.locator(f"[id='{figure_id}'] .screwkit-caption").inner_text()
    page.locator(f"[id='{figure_id}'] input[type=range]").nth(1).fill("90")
    after = page.evaluate("id => document.getElementById(id).querySelector('canvas').toDataURL()",
                          figure_id)
    assert after != before
    assert page.locator(f"[id='{figure_id}'] .screwkit-caption").inner_text() != caption
    assert page.errors == []
