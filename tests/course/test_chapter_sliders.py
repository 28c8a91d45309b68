"""Every slider of the course's chapters behaves, by the rules of
tests/slider_rules.py.

The sliders are collected from the chapters as executed: every in-page figure stores its
sliders in its output (the JSON the page reads), and nbval checks that these stored
outputs are what a fresh execution gives. Sliders built by hand in a chapter
(ipywidgets' FloatSlider or IntSlider called directly) would bypass the rules, so none
may be."""

import glob
import json
import re

import nbformat
import pytest
from slider_rules import multiple, problems

CHAPTERS = sorted(glob.glob("notebooks/*.ipynb"))
WITH_SLIDERS = {
    "rigid_motions",
    "puma_fk",
    "jacobians",
    "kawasaki_workspace",
    "redundancy",
}


def sliders_in(notebook_path):
    """The sliders of every in-page figure stored in the notebook's outputs, each with
    whether it is a trajectory player's time (which starts at its first time)."""
    sliders = []
    for cell in nbformat.read(notebook_path, 4).cells:
        for output in cell.get("outputs", []):
            html = output.get("data", {}).get("text/html", "")
            for payload in re.findall(
                r'<script type="application/json">(.*?)</script>', html, re.S
            ):
                model = json.loads(payload.replace("<\\/", "</"))
                player = model.get("kind") == "trajectory"  # time starts at its start
                sliders += [
                    (s, player)
                    for s in model.get("sliders", [])
                    + [model[k] for k in ("slider",) if k in model]
                ]
    return sliders


@pytest.mark.parametrize("path", CHAPTERS)
def test_every_slider_of_the_chapter_behaves(path):
    sliders = sliders_in(path)
    chapter = path.split("/")[-1][: -len(".ipynb")]
    if chapter in WITH_SLIDERS:
        assert sliders, f"{chapter} shows no interactive figure"
    assert [p for s, player in sliders for p in problems(s, player)] == []


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
            s["label"]: s for s, _ in sliders_in(f"notebooks/{chapter}.ipynb")
        }
    q3 = by_label["jacobians"]["q3"]
    assert multiple(q3["value"], q3["step"]) and multiple(0.0 - q3["min"], q3["step"])
    assert q3["value"] == -20.0
    q3 = by_label["puma_fk"]["q3"]
    assert (q3["min"], q3["max"], q3["value"]) == (-225.0, 45.0, -180.0)
