"""screwkit's tolerances live in one module, named and documented, and length
tolerances follow the instance's own size.

The rule the scan enforces: outside ``screwkit/tolerances.py``, no tolerance-like
float literal appears in screwkit's code (docstrings and comments are not code):

* any ``x`` with ``0 < |x| < 1e-3``: a tolerance, a step or a guard by its size alone;
* an ``x`` with ``1e-3 <= |x| <= 0.05`` used as a tolerance is: a parameter's default
  (``tolerance=0.01``), a keyword argument (``damping=0.01``) or a term of a comparison
  (``abs(t) < 1e-2``).

Such a literal belongs in tolerances.py with its reason. Elements of a tuple or list
display are data, not tolerances (a slider's candidate steps), and are not flagged; nor
are the published parameters of the catalogue (``robots.py``: a link of 0.0203 m is a
length, not a tolerance).
"""

import ast
import re
from pathlib import Path

import numpy as np
import pytest

import screwkit as sk
from screwkit import links, tolerances
from screwkit.tolerances import length_scale

PACKAGE = Path(sk.__file__).resolve().parent


#: The largest literal that is flagged when it is used as a tolerance (a default, a
#: keyword argument, a term of a comparison); below 1e-3 every literal is.
TOLERANCE_LIKE = 0.05

#: Modules whose literals are published data, not tolerances.
DATA_MODULES = {"robots.py"}


def _nodes(tree, kind):
    """The ids of the nodes within the parts of ``tree`` that ``kind`` names."""
    found = set()
    for node in ast.walk(tree):
        if kind == "display" and isinstance(node, (ast.Tuple, ast.List)):
            found.update(id(element) for element in node.elts)
            continue
        if kind == "display":
            continue
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)):
            parts = node.args.defaults + [d for d in node.args.kw_defaults if d]
        elif isinstance(node, ast.Call):
            parts = [keyword.value for keyword in node.keywords]
        elif isinstance(node, ast.Compare):
            parts = [node]
        else:
            continue
        found.update(id(n) for part in parts for n in ast.walk(part))
    return found


def bare_tolerances(source):
    """(line, value) of every tolerance-like float literal (the module's docstring)
    outside tuple/list displays."""
    tree = ast.parse(source)
    in_display, as_tolerance = _nodes(tree, "display"), _nodes(tree, "use")
    return sorted(
        (node.lineno, node.value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Constant)
        and isinstance(node.value, float)
        and id(node) not in in_display
        and (
            0 < abs(node.value) < 1e-3
            or (1e-3 <= abs(node.value) <= TOLERANCE_LIKE and id(node) in as_tolerance)
        )
    )


def scanned_files():
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE)
        if (
            relative.parent == Path(".")
            and path.name in {"tolerances.py"} | DATA_MODULES
        ):
            continue
        yield path


def test_the_scan_finds_a_bare_tolerance():
    source = "def f(x, tol=1e-9):\n    return abs(x) < 2.5e-12 and x != 0.5\n"
    assert bare_tolerances(source) == [(1, 1e-9), (2, 2.5e-12)]
    assert bare_tolerances("STEPS = (0.01, 0.0001)\n") == []
    # from 1e-3 to 0.05, a literal is flagged where it is used as a tolerance
    source = (
        "def f(x, tolerance=0.01):\n"  # 1: a default
        "    g(x, damping=0.01)\n"  # 2: a keyword argument
        "    small = abs(x) < 1e-2\n"  # 3: a comparison
        "    big = abs(x) > 2 * 0.05\n"  # 4: a term of one
        "    return x * 0.04 + h(0.01, 0.3)\n"  # 5: arithmetic, a positional value
    )
    assert bare_tolerances(source) == [(1, 0.01), (2, 0.01), (3, 0.01), (4, 0.05)]
    assert bare_tolerances("def f(x, scale=0.4, step=0.06):\n    pass\n") == []


@pytest.mark.parametrize(
    "path", list(scanned_files()), ids=lambda p: str(p.relative_to(PACKAGE))
)
def test_no_bare_tolerance_literal_outside_tolerances_py(path):
    found = bare_tolerances(path.read_text(encoding="utf-8"))
    assert not found, (
        f"{path.name} has bare tolerance literals (line, value) {found}: name them in "
        "screwkit/tolerances.py with the reason for their value"
    )


def test_every_core_constant_is_documented():
    source = (PACKAGE / "tolerances.py").read_text(encoding="utf-8")
    core = source.split("# ---- core")[1].split("# ---- ik")[0]
    constants = re.findall(r"^([A-Z_]+) = ", core, flags=re.MULTILINE)
    assert len(constants) >= 10
    for name in constants:
        before = core.split(f"\n{name} = ")[0].rstrip().splitlines()[-1]
        assert before.startswith("#:"), f"{name} has no '#:' comment saying why"
        assert 0 < getattr(tolerances, name) < 1e-3


def test_the_old_names_are_the_constants():
    from screwkit import _checks, _numeric, orientation, transforms

    assert _numeric.TOL == tolerances.RANK_TOL
    assert _checks.ORTHONORMAL_TOL == tolerances.ROTATION_TOL
    assert orientation.UNIT_TOL == tolerances.ROTATION_TOL
    assert links.UNIT_TOL == tolerances.UNIT_SCREW_TOL
    assert transforms.ZERO_AXIS == tolerances.ZERO_TOL


def test_length_scale_is_the_largest_entry():
    assert length_scale([0.3, -0.25], np.array([[1.5, 0.0]])) == 1.5
    assert length_scale(np.zeros((2, 3))) == 1.0  # nothing to scale
    assert length_scale([0.3, 0.25]) * 1000 == length_scale([300.0, 250.0])


@pytest.mark.parametrize("unit", [1.0, 1000.0])
def test_a_small_pitch_is_helical_in_metres_and_in_millimetres(unit):
    # the axis z through (1, 0, 0) m with pitch 1e-11 m/rad: v = r x s + h s
    screw = np.array([0, 0, 1, 0, -1 * unit, 1e-11 * unit])
    assert links.joint_kind(screw, length_scale(screw[3:])) is links.Joint.HELICAL
    # round-off of a revolute joint's pitch (1e-16 relative) stays revolute
    screw[5] = 1e-16 * unit
    assert links.joint_kind(screw, length_scale(screw[3:])) is links.Joint.REVOLUTE


def test_a_chain_in_millimetres_has_the_joints_of_the_chain_in_metres():
    axes = np.array([[0, 0, 1, 0, -0.4, 2e-10], [0, 1, 0, -0.3, 0.2, 0]])
    metres = sk.Chain.from_screws(axes, np.eye(4))
    mm = axes.copy()
    mm[:, 3:] *= 1000
    millimetres = sk.Chain.from_screws(mm, np.eye(4))
    assert metres.joints == millimetres.joints == (sk.Joint.HELICAL,) * 2


@pytest.mark.parametrize("unit", [1.0, 1000.0])
def test_the_start_configuration_scales_with_the_arm(unit):
    from screwkit import redundancy, robots

    lengths = np.array([0.3, 0.25, 0.2])
    arm = robots.planar(lengths * unit)
    q = redundancy.start_configuration(arm, [0.4 * unit, 0.3 * unit], [0.1, 0.4, 0.3])
    # the reached point, by the planar forward kinematics written out
    angles = np.cumsum(q)
    reached = np.array(
        [np.sum(lengths * np.cos(angles)), np.sum(lengths * np.sin(angles))]
    )
    assert np.linalg.norm(reached - [0.4, 0.3]) < 1e-10


@pytest.mark.parametrize("unit", [1.0, 1000.0])
def test_a_parallelogram_is_found_in_any_unit(unit):
    from screwkit._viewer_mechanisms import _parallelograms

    z = np.array([0.0, 0.0, 1.0])
    a1, a2 = np.array([0.0, 0.0, 0.0]), np.array([0.0, 0.5, 0.0]) * unit
    b1, b2 = a1 + np.array([0.3, 0.0, 0.0]) * unit, a2 + [0.3 * unit, 0.0, 0.0]
    limb = [("revolute", z, p) for p in (a1, a2, b1, b2)]
    assert _parallelograms(limb) == [0]
    # a side shorter than LENGTH_TOL times the limb's size (1e-10 of it) is no side
    short = np.array([0.0, 1e-10, 0.0]) * unit
    points = (a1, a1 + short, b1, b1 + short)
    assert _parallelograms([("revolute", z, p) for p in points]) == []
