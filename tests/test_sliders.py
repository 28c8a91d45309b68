"""The sliders screwkit builds (the in-page viewer's and the live widgets') obey the
course's slider rules (tests/slider_rules.py), and a joint's range lies within its
limits. The chapters' sliders are checked in tests/course/test_chapter_sliders.py."""

import json
import math
import re

import numpy as np
import pytest
from slider_rules import problems

import screwkit as sk
from screwkit import viewer, widgets


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
