"""The parallel chapter is a lecture: it derives before it calls,
shows its mathematics, and asks the student to implement and to check.

Read from the chapter's source, notebooks/parallel_kinematics.md.
"""

import re
import tomllib
from pathlib import Path

from exercise_syntax import SOLUTION_DIRECTIVE, exercise_directive

SOURCE = Path(__file__).resolve().parents[2] / "notebooks" / "parallel_kinematics.md"


def text():
    return SOURCE.read_text(encoding="utf-8")


# sphinx-exercise's directive labelled parallel_kinematics-exercise-N opens exercise N
EXERCISE = exercise_directive("parallel_kinematics")


def exercises():
    """Exercise number -> its statement and solution."""
    section = text().split("\n## Exercises", 1)[1]
    parts = EXERCISE.split(section)
    return {int(n): body for n, body in zip(parts[1::2], parts[2::2])}


def test_at_least_twelve_display_equations():
    blocks = re.findall(r"^\$\$\n(.+?)\n\$\$$", text(), flags=re.M | re.S)
    assert len(blocks) >= 12
    assert all(block.strip() for block in blocks)


def test_problem_set_numbered_with_one_solution_each():
    bodies = exercises()
    assert len(bodies) >= 8  # the course's minimum (CONTRIBUTING.md)
    assert list(bodies) == list(range(1, len(bodies) + 1))
    assert all(len(SOLUTION_DIRECTIVE.findall(body)) == 1 for body in bodies.values())


def kinds(body):
    """The kinds of an exercise's tag, ``*(KIND, KIND; difficulty N; ...)*``."""
    tag = re.match(r"\*\(([^;]*);", body.strip())
    return {kind.strip() for kind in tag.group(1).split(",")} if tag else set()


def test_exercises_by_kind():
    found = [kinds(body) for body in exercises().values()]
    assert all(found), "every exercise starts with its tag"
    assert sum("implement it yourself" in k for k in found) >= 3
    assert sum("self-checking" in k for k in found) >= 3


def test_no_private_import():
    assert not re.search(r"\b(screwkit|sk)\._", text())
    assert "import _" not in text()


def test_inverse_kinematics_are_written_before_they_are_compared():
    # each mechanism's IK is a function of the chapter's, called before the library's
    source = text()
    for mine, library in [
        ("def stewart_ik", "stewart.ik(T_tilted)"),
        ("def rrr_ik", "rrr.ik_all(T_rrr)"),
        ("def delta_ik", "delta.ik(T_delta"),
        ("def newton_fk", "stewart.fk(rho_tilted"),
        ("sp.real_roots(sextic)", "rpr.fk_all("),
        ("def line_jacobian", "stewart.jacobian(T_tilted)"),
        ("def delta_fk", "delta.fk_all(theta_delta)"),
        ("def reachable", "stewart.workspace(xy, xy"),
    ]:
        assert source.index(mine) < source.index(library), mine


def test_each_answer_box_has_its_key_and_its_check():
    path = SOURCE.parents[1] / "screwkit" / "answers" / "parallel_kinematics.toml"
    keys = tomllib.loads(path.read_text(encoding="utf-8"))
    bodies = exercises()
    boxed = {
        number
        for number, body in bodies.items()
        if 'sk.exercises.answer_box("parallel_kinematics"' in body
    }
    assert boxed == {int(n) for n in keys["exercise"]}
    for number in boxed:
        body = bodies[number]
        assert f'sk.exercises.answer_box("parallel_kinematics", {number})' in body
        assert f'sk.exercises.check("parallel_kinematics", {number},' in body
        assert "self-checking" in kinds(body)
