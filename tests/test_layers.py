"""screwkit's layers: every import points down the one order below, and none closes a
circle.

``ORDER`` is the one table of the package's layers, bottom up (design.md, "Layers"). A
module may import the modules listed before it (the layers below, and the modules before
it in its own layer), never one listed after it or itself: so no circle can form.
Imports are read from the source with ``ast``, at the top of a file and inside functions
alike. Only the display layer may import inside a function (matplotlib, ipywidgets and
PIL, whose import time a student should not pay before the first figure, and screwkit
modules below it); elsewhere every import is at the top of the file. To add a module,
add it to its layer here: a screwkit module that is not listed fails the test, and a
listed module that does not exist (yet) is skipped."""

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "screwkit"

#: The layers, bottom up; within a layer, a module may import those listed before it.
ORDER = [
    ("checks and engines", ["tolerances", "_checks", "_numeric", "_exact", "_certificates", "_notation"]),
    # _compiled (an engine) builds its exponentials with the rigid-motion kernels (skew)
    ("rigid motions", ["transforms", "orientation", "_compiled"]),
    ("Lie algebra", ["lie", "subproblems"]),
    ("screws", ["screws", "systems"]),
    # _newton (numeric IK) needs of a chain only its methods: Chain.numeric_ik calls it;
    # urdf is read by Chain.from_urdf
    ("chains", ["links", "urdf", "_newton", "chains"]),
    (
        "catalogue",
        [
            "limbs",
            "joints",
            "_parallel_legs",
            "_parallel_numeric",
            "_parallel_search",
            "_parallel_catalogue",
            "parallel",
            "robots",
        ],
    ),
    (
        "algorithms",
        [
            "jacobians",
            "_closed_form",
            "spherical_wrist",
            "ur_ik",
            "stanford_ik",
            "ik",
            "workspace",
            "redundancy",
            "mobility",
        ],
    ),
    (
        "display",
        [
            "_sliders",
            "_mechanism_plot",
            "_parallel_plot",
            "plotting",
            "viewer",
            "widgets",
            "exercises",
        ],
    ),
]

#: The package's entry point re-exports every layer (and loads the display layer
#: lazily).
TOP = "__init__"

#: What the display layer may import inside a function.
LAZY_ALLOWED = ("matplotlib", "mpl_toolkits", "ipywidgets", "PIL")

RANK = {
    module: rank
    for rank, module in enumerate(m for _, modules in ORDER for m in modules)
}
LAYER = {module: layer for layer, modules in ORDER for module in modules}
MODULES = sorted(path.stem for path in PACKAGE.glob("*.py"))


def imports(module, source=None):
    """(line, imported screwkit module or None, top-level name, inside a function) for
    every import statement of ``module`` (its file, or ``source``)."""
    if source is None:
        source = (PACKAGE / f"{module}.py").read_text(encoding="utf-8")
    tree = ast.parse(source)
    found = []

    def visit(node, in_function):
        for child in ast.iter_child_nodes(node):
            nested = in_function or isinstance(
                child, (ast.FunctionDef, ast.AsyncFunctionDef, ast.Lambda)
            )
            if isinstance(child, ast.Import):
                for alias in child.names:
                    name = alias.name
                    local = name.split(".")[1] if name.startswith("screwkit.") else None
                    found.append((child.lineno, local, name.split(".")[0], in_function))
            elif isinstance(child, ast.ImportFrom):
                if child.level == 0 and not (child.module or "").startswith("screwkit"):
                    found.append(
                        (child.lineno, None, child.module.split(".")[0], in_function)
                    )
                    continue
                base = (child.module or "").removeprefix("screwkit").lstrip(".")
                if base:  # from .x import y, from screwkit.x import y
                    found.append(
                        (child.lineno, base.split(".")[0], "screwkit", in_function)
                    )
                else:  # from . import x, y
                    for alias in child.names:
                        found.append(
                            (child.lineno, alias.name, "screwkit", in_function)
                        )
            visit(child, nested)

    visit(tree, False)
    return found


def test_every_module_is_in_the_order():
    missing = [m for m in MODULES if m != TOP and m not in RANK]
    assert not missing, f"add these screwkit modules to a layer of ORDER: {missing}"


def test_the_order_lists_each_module_once():
    listed = [m for _, modules in ORDER for m in modules]
    assert len(listed) == len(set(listed))


def upward(module, found):
    """The imports of ``found`` that point at or above ``module`` in ORDER, as
    sentences."""
    wrong = []
    for line, target, _, _ in found:
        if target is None:
            continue
        if target not in RANK:
            wrong.append(f"line {line}: imports {target}, which is not in ORDER")
        elif RANK[target] >= RANK[module]:
            wrong.append(
                f"line {line}: imports {target} ({LAYER[target]}), at or above "
                f"{module} ({LAYER[module]}) in ORDER"
            )
    return wrong


def lazy(module, found):
    """The imports of ``found`` inside a function that the layer of ``module`` may not
    make."""
    inside = [
        (line, target or top) for line, target, top, in_function in found if in_function
    ]
    if LAYER.get(module) == "display":
        inside = [
            (line, name)
            for line, name in inside
            if name not in LAZY_ALLOWED and name not in RANK
        ]
    return inside


@pytest.mark.parametrize("module", [m for m in MODULES if m != TOP])
def test_imports_point_down(module):
    wrong = upward(module, imports(module))
    assert not wrong, f"screwkit.{module}: " + "; ".join(wrong)


@pytest.mark.parametrize("module", [m for m in MODULES if m != TOP])
def test_imports_at_the_top(module):
    inside = lazy(module, imports(module))
    assert not inside, (
        f"screwkit.{module} imports inside a function (only the display layer "
        f"may, and only {', '.join(LAZY_ALLOWED)}): {inside}"
    )


def test_the_entry_point_imports_only_listed_modules():
    unlisted = [
        target for _, target, _, _ in imports(TOP) if target and target not in RANK
    ]
    assert not unlisted


# the checker itself, on made-up sources: the four edges that once closed screwkit's
# circle
@pytest.mark.parametrize(
    "module, source",
    [
        ("_checks", "def check_chain(value):\n    from .chains import Chain\n"),
        ("chains", "from .jacobians import geometric_jacobian\n"),
        ("transforms", "from .screws import axis_coordinates\n"),
        ("screws", "import screwkit.chains\n"),
        ("lie", "from . import lie\n"),  # itself
        ("chains", "from .nowhere import thing\n"),  # not in ORDER
    ],
)
def test_the_checker_sees_an_upward_import(module, source):
    assert upward(module, imports(module, source))


@pytest.mark.parametrize(
    "module, source, flagged",
    [
        ("ik", "def f():\n    from .robots import puma560\n", True),
        ("ik", "def f():\n    import re\n", True),
        ("plotting", "def f():\n    import matplotlib.pyplot as plt\n", False),
        ("viewer", "def f():\n    from . import plotting\n", False),
        ("plotting", "def f():\n    import json\n", True),
        ("ik", "from .robots import puma560\n", False),
    ],
)
def test_the_checker_sees_a_lazy_import(module, source, flagged):
    assert bool(lazy(module, imports(module, source))) is flagged


def test_the_old_module_path_of_the_limb_builders_still_works():
    import screwkit as sk
    from screwkit import joints, limbs

    assert (
        joints.revolute is limbs.revolute and sk.joints.spherical is sk.limbs.spherical
    )
    assert sorted(joints.__all__) == sorted(limbs.__all__)
