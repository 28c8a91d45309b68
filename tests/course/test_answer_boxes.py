"""The answer boxes stored in the chapters' notebooks: each carries its chapter's
current key, and the page's JavaScript (in Node) gives the same verdict and message as
``sk.exercises.check`` for typed answers of every kind (units, commas, ranges)."""

import json
import re
from pathlib import Path

import pytest
from node_verdicts import NODE, node_verdicts

from screwkit import exercises


def box_key(chapter, number):
    """The key as the page gets it: the JSON in the answer box's HTML."""
    page = exercises.answer_box(chapter, number, script=False)._repr_html_()
    payload = re.search(r'<script type="application/json">(.*?)</script>', page)
    return json.loads(payload.group(1).replace("<\\/", "</"))


NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"


def stored_boxes():
    """(chapter, number, key) of every answer box stored in a chapter notebook."""
    found = []
    for path in sorted(NOTEBOOKS.glob("*.ipynb")):
        for cell in json.loads(path.read_text(encoding="utf-8"))["cells"]:
            for out in cell.get("outputs", []):
                page = "".join(out.get("data", {}).get("text/html", ""))
                box = re.search(r'id="sk-exercise-([a-z0-9_]+)-(\d+)-', page)
                if box:
                    payload = re.search(
                        r'<script type="application/json">(.*?)</script>', page
                    )
                    key = json.loads(payload.group(1).replace("<\\/", "</"))
                    found.append((box.group(1), int(box.group(2)), key))
    return found


def test_stored_boxes_carry_the_current_keys():
    # a key changed without re-running its chapter would leave the page checking the
    # old one
    boxes = stored_boxes()
    assert len(boxes) >= 30
    for chapter, number, key in boxes:
        assert key == box_key(chapter, number), (chapter, number)


# typed answers of every kind, for every stored box: the page and Python must agree
BOX_TEXTS = ["92.69 deg", "-87.31 deg", "-5 N m", "-5 Nm", "4.05 N", "4,05", "10 W"]
BOX_TEXTS += ["0.5 m/rad", "200/s", "sqrt(3) m^2", "42.34 deg", "-75.85 deg", "-5 N"]
BOX_TEXTS += ["1, 2, 3", "0.1 m, 0.2 m, 0.3 m", "2 rad/s", "1,5", "2", "1 m"]


@pytest.mark.skipif(NODE is None, reason="needs Node.js")
def test_stored_boxes_answer_in_node_as_in_python():
    boxes = stored_boxes()
    page = iter(node_verdicts([[t, key] for _, _, key in boxes for t in BOX_TEXTS]))
    for chapter, number, _ in boxes:
        for text in BOX_TEXTS:
            correct, message = next(page)
            want = exercises.check(chapter, number, text)
            assert correct is want.correct, (chapter, number, text)
            assert message == want.message, (chapter, number, text)
