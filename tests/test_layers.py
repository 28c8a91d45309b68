"""screwkit's layers: every import points down the one order below, and none closes a
circle.

``ORDER`` is the one table of the package's layers, bottom up (CONTRIBUTING.md). A
module may import the modules listed before it (the layers below, and the modules before
it in its own layer), never one listed after it or itself: so no circle can form.
Imports are read from the source with ``ast``, at the top of a file and inside functions
alike. Only the display layer may import inside a function (matplotlib, ipywidgets and
PIL, whose import time a student should not pay before the first figure, and screwkit
modules below it); elsewhere every import is at the top of the file. To add a module,
add it to its layer here: a screwkit module that is not listed fails the test, and a
listed module that does not exist (yet) is skipped.

A folder (a family, such as ``screwkit/ik/``) lists its modules as ``ik.<name>``, each
at its own layer; the folder's entry point (its ``__init__``) is listed as ``ik``, at
the layer of what it imports at the top. Python runs the entry point before any module
of the folder, so importing ``ik.newton`` also imports what ``ik`` imports at the top:
the checker counts both. What the entry point loads on first use (its ``LAZY`` table:
module -> names) counts where it is loaded: ``from .ik import analytic_ik`` imports
``ik.dispatch``."""

import ast
from pathlib import Path

import pytest

PACKAGE = Path(__file__).resolve().parents[1] / "screwkit"

#: The layers, bottom up; within a layer, a module may import those listed before it.
ORDER = [
    (
        "checks and engines",
        [
            "tolerances",
            "_lazy",
            "_docstrings",
            "_checks",
            "_numeric",
            "_exact",
            "_certificates",
            "_notation",
        ],
    ),
    # _compiled (an engine) builds its exponentials with the rigid-motion kernels (skew)
    ("rigid motions", ["transforms", "orientation", "_compiled"]),
    # motion's entry point loads its modules on first use (its LAZY table), so the
    # chains can compute their second order with motion._second_order
    (
        "Lie algebra",
        ["lie", "ik._quartic", "ik.subproblems", "motion", "motion._second_order"],
    ),
    # lines reads screw systems (a ScrewSystem of lines); _system_geometry is the
    # kernel of ScrewSystem's principal screws and classification
    ("screws", ["screws", "_system_geometry", "systems", "_line_geometry", "lines"]),
    # ik.newton (numeric IK) needs of a chain only its methods: Chain.numeric_ik calls
    # it; the entry point of screwkit.ik loads only it and the subproblems at the top
    # (the closed form on first use), so chains can import it; urdf is read by
    # Chain.from_urdf; the computations on a chain (links' checks of its joint values,
    # jacobians, motion.acceleration and the exact and fast kinematics) take it as
    # their first argument and import no chain: the Chain's methods are these functions
    (
        "chains",
        [
            "links",
            "urdf",
            "ik.newton",
            "ik",
            "jacobians",
            "motion.acceleration",
            "_exact_kinematics",
            "_fast_kinematics",
            "chains",
        ],
    ),
    (
        "catalogue",
        [
            "limbs",
            "parallel.legs",
            "parallel.numeric",
            "parallel.search",
            "parallel.proven",
            "parallel.model",
            "parallel.catalogue",
            "parallel",
            "robots",
        ],
    ),
    (
        "algorithms",
        [
            "ik._closed_form",
            "ik._one_pose",
            "ik.spherical_wrist",
            "ik.ur",
            "ik.stanford",
            "ik._general_kinematics",
            "ik.general",
            "ik.decomposed",
            "ik.dispatch",
            "motion.trajectory",
            "motion.differential_ik",
            "workspace",
            "redundancy",
            "mobility_analysis",
            "statics",
            "contact",
        ],
    ),
    (
        "display",
        [
            "_sliders",
            "_mechanism_plot",
            "_line_plots",
            "parallel.plotting",
            "plotting",
            "schematic",
            "_viewer_page",
            "_viewer_mechanisms",
            "_stepped_figure",
            "viewer",
            "widgets",
            "_variants",
            "_variants.configuration_space",
            "_variants.rigid_motions",
            "_variants.screws",
            "_variants.lines",
            "_variants.mobility",
            "_variants.poe",
            "_variants.puma_fk",
            "_variants.puma_ik",
            "_variants.jacobians",
            "_variants.statics",
            "_variants.kawasaki_workspace",
            "_variants.redundancy",
            "_variants.motion_in_time",
            "_variants.parallel_kinematics",
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
#: The folders of screwkit that are packages (a family each).
FOLDERS = sorted(path.parent.name for path in PACKAGE.glob("*/__init__.py"))


def path_of(module):
    """The file of a module named as in ORDER: ``lie``, ``ik.newton``, ``ik`` (the
    folder's ``__init__``)."""
    parts = module.split(".")
    if len(parts) == 1 and parts[0] in FOLDERS:
        return PACKAGE / parts[0] / "__init__.py"
    return PACKAGE.joinpath(*parts).with_suffix(".py")


MODULES = sorted(
    [path.stem for path in PACKAGE.glob("*.py")]
    + [
        f"{folder}.{path.stem}" if path.stem != "__init__" else folder
        for folder in FOLDERS
        for path in (PACKAGE / folder).glob("*.py")
    ]
)


def lazy_table(folder):
    """The ``LAZY`` table of a folder's entry point ({module: names}), or {}."""
    tree = ast.parse(path_of(folder).read_text(encoding="utf-8"))
    for node in tree.body:
        if isinstance(node, ast.Assign) and any(
            isinstance(t, ast.Name) and t.id == "LAZY" for t in node.targets
        ):
            return ast.literal_eval(node.value)
    return {}


LAZY = {folder: lazy_table(folder) for folder in FOLDERS}


def resolve(module, level, name, alias):
    """The module of ORDER that ``from <level dots><name> import <alias>`` in
    ``module`` imports (``alias`` itself when it is a module of a folder)."""
    parts = module.split(".")
    folder = parts if module in FOLDERS else parts[:-1]  # the importer's package
    base = folder[: len(folder) - (level - 1)] if level else []
    if level == 0:
        name = name.removeprefix("screwkit").lstrip(".")
    target = ".".join([*base, *([name] if name else [])])
    if alias and f"{target}.{alias}".strip(".") in RANK:
        return f"{target}.{alias}".strip(".")
    for lazy, names in LAZY.get(target, {}).items():
        if alias in names:  # a name the entry point loads on first use
            return f"{target}.{lazy}"
    return target or alias


def imports(module, source=None):
    """(line, imported screwkit module or None, top-level name, inside a function) for
    every import statement of ``module`` (its file, or ``source``). A module of a
    folder counts with the folder's entry point, which Python runs first."""
    if source is None:
        source = path_of(module).read_text(encoding="utf-8")
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
                    local = (
                        resolve(module, 0, name, None)
                        if name.startswith("screwkit.")
                        else None
                    )
                    found.append((child.lineno, local, name.split(".")[0], in_function))
            elif isinstance(child, ast.ImportFrom):
                if child.level == 0 and not (child.module or "").startswith("screwkit"):
                    found.append(
                        (child.lineno, None, child.module.split(".")[0], in_function)
                    )
                    continue
                for alias in child.names:  # from .x import y, from . import x, ...
                    target = resolve(module, child.level, child.module, alias.name)
                    found.append((child.lineno, target, "screwkit", in_function))
            visit(child, nested)

    visit(tree, False)
    # the entry point of a folder runs before any of its modules
    entries = {
        target.split(".")[0]
        for _, target, _, _ in found
        if target and "." in target and target.split(".")[0] != module.split(".")[0]
    }
    found += [(0, folder, "screwkit", False) for folder in sorted(entries)]
    return found


def test_every_module_is_in_the_order():
    missing = [m for m in MODULES if m != TOP and m not in RANK]
    assert not missing, f"add these screwkit modules to a layer of ORDER: {missing}"


def test_what_a_folder_loads_on_first_use_is_a_listed_module_of_it():
    unlisted = [
        f"{folder}.{module}"
        for folder, table in LAZY.items()
        for module in table
        if f"{folder}.{module}" not in RANK
    ]
    assert not unlisted


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
        ("chains", "from .workspace import sweep\n"),
        ("transforms", "from .screws import axis_coordinates\n"),
        ("screws", "import screwkit.chains\n"),
        ("lie", "from . import lie\n"),  # itself
        ("chains", "from .nowhere import thing\n"),  # not in ORDER
        # a folder: its modules, and the names its entry point loads on first use
        ("chains", "from .ik.dispatch import analytic_ik\n"),
        ("chains", "from .ik import analytic_ik\n"),
        ("chains", "from .ik import dispatch\n"),
        ("ik.newton", "from .dispatch import analytic_ik\n"),
        ("ik.subproblems", "from .. import chains\n"),
        ("lie", "from .ik.newton import numeric_ik\n"),  # and the entry point
    ],
)
def test_the_checker_sees_an_upward_import(module, source):
    assert upward(module, imports(module, source))


@pytest.mark.parametrize(
    "module, source, flagged",
    [
        ("ik.dispatch", "def f():\n    from ..robots import puma560\n", True),
        ("ik.dispatch", "def f():\n    import re\n", True),
        ("plotting", "def f():\n    import matplotlib.pyplot as plt\n", False),
        ("viewer", "def f():\n    from . import plotting\n", False),
        ("plotting", "def f():\n    import json\n", True),
        ("ik.dispatch", "from ..robots import puma560\n", False),
    ],
)
def test_the_checker_sees_a_lazy_import(module, source, flagged):
    assert bool(lazy(module, imports(module, source))) is flagged


@pytest.mark.parametrize(
    "module, source",
    [
        ("chains", "from .ik import newton\n"),
        ("chains", "from .ik.newton import numeric_ik\n"),
        ("ik.dispatch", "from .spherical_wrist import CONFIGURATIONS\n"),
        ("ik.dispatch", "from ..robots import puma560\n"),
        ("ik", "from .newton import numeric_ik\n"),
    ],
)
def test_the_checker_lets_a_downward_import_of_a_folder_pass(module, source):
    assert not upward(module, imports(module, source))
