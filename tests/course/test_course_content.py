"""The chapters' slips stay fixed, and their problem sets stay complete.

Read from the chapters' sources (notebooks/NAME.md) and stored outputs
(notebooks/NAME.ipynb), or by running the call a chapter tells the reader to run.
"""

import json
import re
from pathlib import Path

import pytest
import sympy as sp
from exercise_syntax import SOLUTION, old_syntax

from screwkit import exercises

NOTEBOOKS = Path(__file__).resolve().parents[2] / "notebooks"
CHAPTERS = [
    "configuration_space",
    "rigid_motions",
    "screws",
    "poe",
    "puma_fk",
    "puma_ik",
]


def source(name):
    return (NOTEBOOKS / f"{name}.md").read_text(encoding="utf-8")


def outputs(name):
    """The text each code cell printed or displayed, in order."""
    notebook = json.loads((NOTEBOOKS / f"{name}.ipynb").read_text(encoding="utf-8"))
    texts = []
    for cell in notebook["cells"]:
        if cell["cell_type"] != "code":
            continue
        text = ""
        for out in cell.get("outputs", []):
            text += "".join(out.get("text", "")) + "".join(
                out.get("data", {}).get("text/plain", "")
            )
        texts.append(text)
    return texts


def exercises_section(name):
    text = source(name)
    return old_syntax(text[text.index("## Exercises") :])


@pytest.mark.parametrize("name", CHAPTERS)
def test_problem_set_is_complete(name):
    section = exercises_section(name)
    numbers = [int(n) for n in re.findall(r"^\*\*(\d+)\.\*\*", section, flags=re.M)]
    assert len(numbers) >= 8 and numbers == list(range(1, len(numbers) + 1))
    solutions = len(SOLUTION.findall(section))
    assert solutions == len(numbers), "one hidden solution per exercise"
    assert section.count("*(by hand") >= 2
    assert section.count("*(implement it yourself") >= 2
    boxes = re.findall(rf'sk\.exercises\.answer_box\("{name}", (\d+)\)', section)
    checks = re.findall(rf'sk\.exercises\.check\("{name}", (\d+),', section)
    assert len(boxes) >= 2 and set(boxes) <= set(checks)
    for number in boxes:  # every box has a key
        exercises.answer_key(name, int(number))


def test_rigid_motions_try_it_runs_with_an_infinite_pitch():
    # the page says: change `pitch` to `sp.oo` for a prismatic one and run the cell
    from screwkit.viewer import screw_motion_viewer

    assert "to `sp.oo` for a prismatic one" in source("rigid_motions")
    figure = screw_motion_viewer([0, 0, 1], [0.5, 0.0, 0.0], sp.oo)
    assert "slider d (m) [-1, 1]" in repr(figure)
    assert "slider theta (deg)" in repr(screw_motion_viewer([0, 0, 1], [0.5, 0, 0], 0))


def test_puma_fk_prints_its_dh_table_once_with_units_and_separated_columns():
    texts = outputs("puma_fk")
    tables = [t for t in texts if "α (deg)" in t or "PUMA 560: standard DH" in t]
    assert len(tables) == 1, "the DH table is shown once"
    (table,) = tables
    assert "limits (deg)" in table
    assert re.search(r"3 R\s+q3\s+0\.15005\s+0\.0203\s+-90\s+\[-225, 45\]", table)
    notebook = json.loads((NOTEBOOKS / "puma_fk.ipynb").read_text(encoding="utf-8"))
    html = [
        out["data"]["text/html"]
        for cell in notebook["cells"]
        for out in cell.get("outputs", [])
        if "screwkit-chain" in "".join(out.get("data", {}).get("text/html", ""))
    ]
    assert html == [], "no second, typeset copy of the table"


def test_puma_fk_viewer_text_points_to_the_poe_chapter():
    text = source("puma_fk")
    viewer = text[: text.index("robot_viewer(puma")]
    paragraph = viewer[viewer.rindex("Move the arm yourself") :]
    assert "next section" not in paragraph and "{doc}`poe`" in paragraph


def test_puma_fk_teaches_the_common_normal_procedure():
    text = source("puma_fk")
    assert text.count("common normal") >= 5
    assert "## Assigning DH frames to an arm: the procedure" in text
    assert "On a new arm" in text


def code_cells(name):
    return re.findall(r"```\{code-cell\} ipython3\n(.*?)```", source(name), flags=re.S)


def test_puma_ik_basins_figure_says_how_it_shows_all_eight_solutions():
    (cell,) = [c for c in code_cells("puma_ik") if "Basins of attraction" in c]
    assert "(dots: the solutions)" not in cell
    assert "dots: the eight solutions" in cell and "shift" in cell
    # the eight (q1, q3) dots are distinct once the wrist pairs are drawn apart
    import numpy as np

    import screwkit as sk
    from screwkit.ik import CONFIGURATIONS

    puma = sk.robots.puma560()
    closed = sk.ik.puma560_ik_all(puma.fk(np.radians([20, 40, -110, 30, 50, -20])))
    shifts = np.array([-4 if c[2] == "n" else 4 for c in CONFIGURATIONS])
    dots = np.c_[np.degrees(closed[:, 0]), np.degrees(closed[:, 2]) + shifts]
    gaps = np.linalg.norm(dots[:, None] - dots[None], axis=-1) + 100 * np.eye(8)
    assert gaps.min() > 3


def test_puma_ik_exercise_3_solution_gives_numbers():
    section = exercises_section("puma_ik")
    solution = section[section.index("**3.**") : section.index("**4.**")]
    assert "2.6" in solution and "`ruf`" in solution and "`run`" in solution


def test_puma_ik_newton_raphson_is_written_out_and_compared():
    text = source("puma_ik")
    assert "def newton_ik(" in text
    assert "sk.ik.numeric_ik(puma, T, q0, damping=0)" in text
    printed = "\n".join(outputs("puma_ik"))
    assert "same joint vector to 1e-12: True" in printed
