"""Every slider of the course behaves (issue 18, item 4).

The rules: the default lies on the slider's grid and strictly inside its range; the grid
is anchored at 0 (both ends are multiples of the step), so 0 and round values are
reachable; a joint's range lies within its limits; every slider names its unit.

The sliders are collected from the chapters as executed: every in-page figure stores its
sliders in its output (the JSON the page reads), and nbval checks that these stored
outputs are what a fresh execution gives. Sliders built by hand in a chapter
(ipywidgets' FloatSlider or IntSlider called directly) would bypass the rules, so none
may be."""

import glob
import json
import math
import re

import nbformat
import numpy as np
import pytest

import screwkit as sk
from screwkit import viewer, widgets

CHAPTERS = sorted(glob.glob("notebooks/*.ipynb"))
WITH_SLIDERS = {
    "rigid_motions",
    "puma_fk",
    "jacobians",
    "kawasaki_workspace",
    "redundancy",
}


def multiple(x, step):
    return abs(x / step - round(x / step)) < 1e-9 * max(1.0, abs(x / step))


def problems(slider):
    """What is wrong with one slider (dict with label, unit, min, max, step, value)."""
    low, high, step, value = (slider[k] for k in ("min", "max", "step", "value"))
    name = f"{slider['label']} [{low}, {high}] step {step} at {value}"
    found = []
    if not slider.get("unit"):
        found.append(f"{name}: names no unit")
    if not (step > 0 and low < high):
        found.append(f"{name}: not a range")
    if not (multiple(low, step) and multiple(high, step)):
        found.append(
            f"{name}: grid not anchored at 0, so 0 and round values are unreachable"
        )
    if not multiple(value - low, step):
        found.append(f"{name}: default not on the grid")
    if not low < value < high:
        found.append(f"{name}: default not strictly inside the range")
    return found


def sliders_in(notebook_path):
    """The sliders of every in-page figure stored in the notebook's outputs."""
    sliders = []
    for cell in nbformat.read(notebook_path, 4).cells:
        for output in cell.get("outputs", []):
            html = output.get("data", {}).get("text/html", "")
            for payload in re.findall(
                r'<script type="application/json">(.*?)</script>', html, re.S
            ):
                model = json.loads(payload.replace("<\\/", "</"))
                sliders += model.get("sliders", []) + [
                    model[k] for k in ("slider",) if k in model
                ]
    return sliders


@pytest.mark.parametrize("path", CHAPTERS)
def test_every_slider_of_the_chapter_behaves(path):
    sliders = sliders_in(path)
    chapter = path.split("/")[-1][: -len(".ipynb")]
    if chapter in WITH_SLIDERS:
        assert sliders, f"{chapter} shows no interactive figure"
    assert [p for s in sliders for p in problems(s)] == []


@pytest.mark.parametrize("path", sorted(glob.glob("notebooks/*.md")))
def test_no_chapter_builds_a_slider_by_hand(path):
    with open(path, encoding="utf-8") as f:
        source = f.read()
    assert re.findall(r"(?:Float|Int)(?:Log)?Slider\(", source) == []


def test_the_known_bad_sliders_are_gone():
    # Jacobians: q3 of the PUMA from -20 deg; PUMA FK: q3 of the nominal pose, -180 deg,
    # inside the limits [-225, 45] deg rather than on the edge of a range clipped to
    # 180.
    by_label = {}
    for chapter in ("jacobians", "puma_fk"):
        by_label[chapter] = {
            s["label"]: s for s in sliders_in(f"notebooks/{chapter}.ipynb")
        }
    q3 = by_label["jacobians"]["q3"]
    assert multiple(q3["value"], q3["step"]) and multiple(0.0 - q3["min"], q3["step"])
    assert q3["value"] == -20.0
    q3 = by_label["puma_fk"]["q3"]
    assert (q3["min"], q3["max"], q3["value"]) == (-225.0, 45.0, -180.0)


def test_robot_sliders_lie_within_the_joint_limits():
    puma = sk.robots.puma560()
    html = viewer.robot_viewer(puma, puma.configurations["nominal"])._repr_html_()
    model = json.loads(re.search(r'"application/json">(.*?)</script>', html).group(1))
    for slider, (low, high) in zip(model["sliders"], np.degrees(puma.qlim)):
        assert low - 1e-9 <= slider["min"] < slider["max"] <= high + 1e-9
        assert slider["scale"] == pytest.approx(math.pi / 180)


def test_live_widget_sliders_obey_the_same_rules():
    puma = sk.robots.puma560()
    live = widgets.joint_sliders(puma, puma.configurations["nominal"])
    found = []
    for widget in live.widget.children[:-1]:  # the last child is the output area
        label, unit = re.fullmatch(r"(\S+) \((.+)\)", widget.description).groups()
        found += problems(
            {
                "label": label,
                "unit": unit,
                "min": widget.min,
                "max": widget.max,
                "step": widget.step,
                "value": widget.value,
            }
        )
    assert found == []
    assert len(live.widget.children) == puma.n + 1
