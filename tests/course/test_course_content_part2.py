"""The course's content promises for the Jacobian, Kawasaki, redundancy and mobility
chapters, the course plan and the references, read from the sources and the stored
notebooks: exercises with their own solutions and answer boxes, slips once
found in the prose fixed, the plan's weeks, every cited key in the bibliography."""

import json
import pathlib
import re
import tomllib

import pytest
from exercise_syntax import SOLUTION, old_syntax
from pybtex.database import parse_file

ROOT = pathlib.Path(__file__).resolve().parents[2]
CHAPTERS = [
    "configuration_space",
    "jacobians",
    "kawasaki_workspace",
    "redundancy",
    "motion_in_time",
    "mobility",
]


def source(name):
    return (ROOT / "notebooks" / f"{name}.md").read_text(encoding="utf-8")


def outputs(name):
    """Each code cell's source and its printed text, from the stored notebook."""
    notebook = json.loads(
        (ROOT / "notebooks" / f"{name}.ipynb").read_text(encoding="utf-8")
    )
    for cell in notebook["cells"]:
        if cell["cell_type"] == "code":
            text = "".join("".join(o.get("text", "")) for o in cell.get("outputs", []))
            yield "".join(cell["source"]), text, cell.get("outputs", [])


def exercises(name):
    """The exercises section split into exercises: {number: text up to the next one}."""
    text = old_syntax(source(name).split("\n## Exercises\n", 1)[1])
    parts = re.split(r"\n\*\*(\d+)\.\*\* ", "\n" + text)
    return {int(n): body for n, body in zip(parts[1::2], parts[2::2])}


@pytest.mark.parametrize("name", CHAPTERS)
def test_at_least_eight_exercises_each_with_its_own_solution(name):
    found = exercises(name)
    assert len(found) >= 8 and sorted(found) == list(range(1, len(found) + 1))
    for number, body in found.items():
        assert len(SOLUTION.findall(body)) == 1, f"{name} exercise {number}"


@pytest.mark.parametrize("name", CHAPTERS)
def test_by_hand_and_implement_it_exercises(name):
    bodies = exercises(name).values()
    assert sum(b.startswith("*(by hand") for b in bodies) >= 2
    assert sum(b.startswith("*(implement it yourself") for b in bodies) >= 2


@pytest.mark.parametrize("name", CHAPTERS)
def test_answer_boxes_match_the_answer_keys(name):
    boxes = {
        (int(n))
        for c, n in re.findall(
            r'sk\.exercises\.answer_box\("(\w+)", (\d+)\)', source(name)
        )
        if c == name
    }
    keys = tomllib.loads((ROOT / "screwkit" / "answers" / f"{name}.toml").read_text())
    assert len(boxes) >= 2
    assert boxes == {int(n) for n in keys["exercise"]}
    for (
        number
    ) in boxes:  # each box sits in its own exercise, whose solution shows the check
        body = exercises(name)[number]
        assert f'sk.exercises.answer_box("{name}", {number})' in body
        assert f'sk.exercises.check("{name}", {number},' in body


def test_mobility_exercise_3_uses_only_what_the_chapter_introduced():
    text = source("mobility")
    assert "Kong and Gosselin's conditions" not in text
    body, exercise_3 = text.split("\n## Exercises\n")[0], exercises("mobility")[3]
    assert r"\alpha" in exercise_3
    # alpha is defined in the 4-PRRU section, before the exercises
    section = body.split("### 4-PRRU: Schönflies motion")[1].split("\n### ")[0]
    assert r"w = R_x(\alpha)" in section


def test_mobility_explains_the_parallelogram_as_a_uu_chain_and_checks_it():
    section = source("mobility").split("### 3-PR(Pa)R")[1].split("\n### ")[0]
    assert "universal joint" in section and "3-system" in section
    checked = [text for code, text, _ in outputs("mobility") if "five = " in code]
    assert len(checked) == 1
    # one header, then one line a limb (44 characters at most: a phone)
    assert "P, U at A1, U at B1 span the limb's LTS:\n" in checked[0]
    assert [f"  limb {i}: True" in checked[0] for i in (1, 2, 3)] == [True] * 3


def _gain_table():
    """{k: (max error in mm, clamped %)} as the Try-the-gain cell printed it; an error
    printed as "> 0.1 mm" (machine-dependent past that) is read as infinity."""
    cell = [text for code, text, _ in outputs("redundancy") if "gain_runs = {" in code]
    assert len(cell) == 1
    rows = re.findall(
        r"^\s*([\d.]+)\s+[\d.]+\s+[\d.]+\s+(> 0\.1|[\d.]+) mm\s+([\d.]+)%$",
        cell[0],
        re.MULTILINE,
    )
    return {
        float(k): (float("inf") if e == "> 0.1" else float(e), float(c))
        for k, e, c in rows
    }


def test_redundancy_try_the_gain_prose_is_what_its_frames_show():
    table = _gain_table()
    assert sorted(table) == [0.0, 2.5, 5.0, 7.5, 10.0, 12.5, 15.0, 17.5, 20.0]
    prose = source("redundancy").split("### Try the gain")[1].split("## The two-arm")[0]
    prose = re.sub(r"```.*?```", "", prose, flags=re.DOTALL)
    prose = " ".join(prose.split())
    assert "stays the same" not in prose
    # every error the prose quotes is the table's, at the gain it names
    assert f"{table[17.5][0]:.3f} mm" in prose
    assert f"{table[20.0][1]:.1f}% of the steps" in prose
    assert all(abs(table[k][0] - 0.032) < 5e-4 for k in table if k <= 15)
    assert "up to $k = 15$ the tip error stays at 0.032 mm" in prose
    # past 0.1 mm only that is printed, and the prose says why
    assert table[17.5][0] < 0.1 and table[20.0][0] == float("inf")
    assert "prints only that it is over 0.1 mm" in prose


def test_redundancy_timing_pointer_goes_to_the_benchmarks():
    text = source("redundancy")
    assert "measured below" not in text
    section = text.split("### Try the gain")[1].split("```")[0]
    assert "{doc}`../book/benchmarks`" in section
    assert (ROOT / "benchmarks" / "bench_redundancy.py").exists()


def test_jacobians_force_ellipsoid_section_with_a_figure():
    text = source("jacobians")
    section = text.split("## The force ellipsoid")[1].split("\n## ")[0]
    assert "1/\\sigma_i" in section and "J J^\\mathsf{T} F" in section
    cells = list(outputs("jacobians"))
    figures = [
        o
        for code, _, outs in cells
        if "force = tip" in code
        for o in outs
        if "image/png" in o.get("data", {})
    ]
    assert len(figures) == 1


def test_course_plan_has_at_least_twelve_weeks_and_is_in_the_toc():
    toc = (ROOT / "_toc.yml").read_text(encoding="utf-8")
    getting_started = toc.split("caption: Getting started")[1].split("caption:")[0]
    files = re.findall(r"file: (\S+)", getting_started)
    assert files.index("book/course_plan") == files.index("book/how_to_use") + 1
    plan = (ROOT / "book" / "course_plan.md").read_text(encoding="utf-8")
    weeks = re.findall(r"^### Week (\d+)", plan, re.MULTILINE)
    # a semester: 12 to 14 teaching weeks, and a project week at the end
    assert 12 <= len(weeks) <= 15 and weeks == [
        str(i) for i in range(1, len(weeks) + 1)
    ]
    for week in plan.split("### Week ")[1:]:
        assert "**Exercises**" in week and "**Lab**" in week and "{doc}`" in week
    assert "parallel_kinematics" in plan and "shorter course" in plan.lower()


def test_every_cited_key_is_in_the_bibliography():
    bib = parse_file(str(ROOT / "book" / "references.bib")).entries
    pages = list((ROOT / "notebooks").glob("*.md")) + list((ROOT / "book").glob("*.md"))
    cited = set()
    for page in pages:
        for group in re.findall(
            r"\{cite(?::\w+)?\}`([^`]+)`", page.read_text(encoding="utf-8")
        ):
            cited.update(k.strip() for k in group.split(","))
    assert cited and cited <= set(bib)


@pytest.mark.parametrize(
    "key, names",
    [
        ("murray1994mathematical", ["Murray, Li and Sastry"]),
        ("spong2006robot", ["Spong"]),
        ("fu1987robotics", ["Fu, Gonzalez and Lee"]),
        ("sugihara2011solvability", ["Sugihara"]),
    ],
)
def test_works_named_in_the_text_are_cited_where_named(key, names):
    bib = parse_file(str(ROOT / "book" / "references.bib")).entries
    assert key in bib
    pages = list((ROOT / "notebooks").glob("*.md")) + list((ROOT / "book").glob("*.md"))
    text = "\n".join(p.read_text(encoding="utf-8") for p in pages)
    for name in names:
        for match in re.finditer(re.escape(name), text):
            nearby = text[match.start() : match.start() + 200]
            assert f"{{cite}}`{key}`" in nearby, f"{name!r} named without {key}"
