"""Screenshots of every in-page viewer of the book at 1280 and 390 px, for review.

Each viewer is built as its chapter builds it, shown alone in a page of headless
Chromium (the system's, driven by Playwright; no network) in a column as wide as the
book's, and saved as a small PNG under ``screenshots/viewers/``. It also prints each
viewer's redraw time (ms, median of 30 slider moves, after the first) and fails on a
JavaScript error or on a viewer wider than the viewport. Run: ``.venv/bin/python
tools/viewer_screenshots.py``.
"""

import pathlib
import statistics
import sys

import numpy as np

import screwkit as sk
from screwkit import parallel, viewer

ROOT = pathlib.Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / ".ci"))
import harness  # noqa: E402 (.ci/harness.py: the fenced system Chromium)

OUT = ROOT / "screenshots" / "viewers"
COLUMN = 760  # px: about the book's text column at 1280 px


class StandInPlatform:
    """A 6-6 Gough-Stewart platform (the catalogue's comes from
    sk.robots.stewart_gough())."""

    name = "6-6 Gough-Stewart platform (stand-in)"
    planar = False

    def __init__(self):
        a = np.radians([0, 60, 120, 180, 240, 300]) + np.radians([-10, 10] * 3)
        b = np.radians([0, 120, 240]).repeat(2) + np.radians([-50, 50] * 3)
        self.base_points = 0.5 * np.c_[np.cos(a), np.sin(a), np.zeros(6)]
        self.platform_points = 0.3 * np.c_[np.cos(b), np.sin(b), np.zeros(6)]
        self.leg_limits = np.tile([0.5, 0.75], (6, 1))

    def home(self):
        return sk.transl(0, 0, 0.55)


def figures():
    """(file stem, Viewer) of every viewer the chapters show, built as they build it."""
    puma = sk.robots.puma560()
    kawasaki = sk.robots.kawasaki_cx210l()
    puma_poe = sk.Chain.from_screws(
        puma.screw_axes(), puma.home(), qlim=puma.qlim, name="PUMA 560 (PoE)"
    )
    q_base = np.radians([0, 30, 0, 0, 45, 0])
    panda = sk.robots.panda()
    found = [
        ("puma_fk-puma560", viewer.robot_viewer(puma, puma.configurations["nominal"])),
        ("poe-puma560", viewer.robot_viewer(puma_poe, puma.configurations["nominal"])),
        (
            "jacobians-ellipsoid",
            viewer.robot_viewer(
                puma, q_base + np.radians([0, 0, -20, 0, 0, 0]), ellipsoid=True
            ),
        ),
        (
            "kawasaki_workspace-cx210l",
            viewer.robot_viewer(kawasaki, kawasaki.configurations["table2_1"]),
        ),
        (
            "rigid_motions-screw",
            viewer.screw_motion_viewer([0, 0, 1], [0.5, 0.0, 0.0], 0.12),
        ),
        (
            "platform-stand-in",
            viewer.show_platform(StandInPlatform(), pose=[0.05, 0, 0.67, 0, 12, 0]),
        ),
        (
            "puma_ik-ur5e",
            viewer.robot_viewer(
                sk.robots.ur5e(), np.array([0.4, -1.3, 1.7, 0.2, 1.1, -0.6])
            ),
        ),
        ("puma_ik-panda", viewer.robot_viewer(panda, panda.configurations["ready"])),
        (
            "parallel_kinematics-stewart",
            viewer.show_platform(sk.robots.stewart_gough()),
        ),
        ("parallel_kinematics-3rpr", viewer.show_platform(parallel.planar_3rpr())),
        ("motion_in_time-screw_vs_line", motion_paths(puma)),
    ]
    for name, builder in [
        ("3-PRRR", "pm_3prrr"),
        ("3-PR(Pa)R", "pm_3prpar"),
        ("4-PRRU", "pm_4prru"),
        ("6-UPS", "pm_6ups"),
    ]:
        m = sk.mobility(getattr(sk.robots, builder)())
        found.append(
            (
                f"mobility-{builder}",
                viewer.show_mechanism(builder, twists=m, title=f"{name}: {m.type}"),
            )
        )
    found.append(("mobility-figure_slider", stepped_mechanisms()))
    return found


def motion_paths(puma):
    """The motion chapter's PUMA on the screw motion and the straight line + slerp
    between two poses, over a 3 s quintic (joint paths from the closed-form IK)."""
    from screwkit.motion import trajectory as tr

    q_first = np.radians([0, -30, 20, 0, 40, 0])
    T0, T1 = puma.fk(q_first), puma.fk(np.radians([90, -10, -10, 60, 60, 30]))
    timing = tr.quintic(3.0)
    times = timing.times(61)
    s = timing(times)
    paths = {
        "screw motion": tr.follow_path(puma, tr.screw_path(T0, T1, s), q_first),
        "straight line + slerp": tr.follow_path(
            puma, tr.cartesian_path(T0, T1, s), q_first
        ),
    }
    return viewer.trajectory_viewer(puma, paths, times=times)


def stepped_mechanisms():
    """The mobility chapter's drop-down of drawings (computed now, stepped in the
    page)."""
    import matplotlib

    matplotlib.use("Agg")
    choices = {"3-PRRR": "pm_3prrr", "3-PR(Pa)R": "pm_3prpar", "4-PRRU": "pm_4prru"}

    def draw(name):
        limbs = getattr(sk.robots, choices[name])()
        m = sk.mobility(limbs)
        values = sk.robots.DRAWING_VALUES[choices[name]]
        ax = sk.plotting.draw_mechanism(
            limbs, values, twists=m, title=f"{name}: mobility {m.number} ({m.type})"
        )
        return ax.figure

    return viewer.stepped_figure(
        draw, "mechanism", choices=list(choices), value="4-PRRU"
    )


TIME = """id => {
    const v = window.screwkit.viewers[id], times = [];
    if (!v.sliders.length) {
        const t = performance.now();
        v.redraw();
        return [performance.now() - t];
    }
    const input = v.sliders[0].input, low = +input.min, high = +input.max;
    for (let k = 0; k < 31; k++) {
        input.value = String(low + (high - low) * ((k * 7) % 31) / 30);
        const t = performance.now();
        input.dispatchEvent(new Event("input"));
        times.push(performance.now() - t);
    }
    return times.slice(1);
}"""


def small(png, path):
    """Save the screenshot ``png`` (bytes) as a 128-colour PNG: a third of the bytes."""
    import io

    from PIL import Image

    image = Image.open(io.BytesIO(png)).convert("RGB")
    image.quantize(colors=128, method=Image.Quantize.MEDIANCUT).save(
        path, optimize=True
    )


def main():
    OUT.mkdir(parents=True, exist_ok=True)
    problems = []
    print(f"{'viewer':32} {'width':>5} {'redraw ms (median, max)':>24}")
    with harness.launch() as browser:
        for width in (1280, 390):
            page = browser.new_page(viewport={"width": width, "height": 900})
            errors = harness.collect_errors(page)
            for stem, figure in figures():
                page.set_content(
                    f"<!DOCTYPE html><html><head><meta name='viewport' content="
                    f"'width=device-width'></head><body style='margin:0;padding:12px'>"
                    f"<main style='max-width:{COLUMN}px;margin:auto'>"
                    f"{figure.html(library=True)}</main></body></html>"
                )
                wide = page.evaluate("() => document.documentElement.scrollWidth")
                if wide > width:
                    problems.append(f"{stem} at {width} px: the page is {wide} px wide")
                root = page.locator(f"[id='{figure.id}']")
                small(root.screenshot(scale="css"), OUT / f"{stem}-{width}.png")
                if figure.model["kind"] == "steps":  # frames computed in Python
                    print(f"{stem:32} {width:>5} {'(precomputed frames)':>24}")
                    continue
                times = page.evaluate(TIME, figure.id)
                print(
                    f"{stem:32} {width:>5} {statistics.median(times):>12.1f} "
                    f"{max(times):>10.1f}"
                )
            problems += [f"at {width} px: JavaScript error: {e}" for e in errors]
            page.close()
    for problem in problems:
        print(problem)
    sys.exit(1 if problems else 0)


if __name__ == "__main__":
    main()
