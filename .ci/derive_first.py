"""Derive, then call: a chapter computes a result before it asks screwkit for it.

The rule: no chapter calls a library function for a result before the chapter (or one
before it in _toc.yml) has derived or computed it once without that function. The
table `DERIVED_FIRST` names each such pair: the chapter, the library call (a regex) and
the marker of the derivation in plain NumPy/SymPy (a regex). Only the chapter's code
cells count: a derivation in a hidden solution block is not on the page.

The rule, for each row: the first code line of the chapter that matches the call comes
after the first code line that matches the marker, in the same chapter or, when the row
names another chapter in `derived_in`, in that chapter, which must come earlier in
_toc.yml. `ALLOWED_EARLY` lists the named exceptions, each with its reason; an entry
that is no longer needed is reported too, so the list stays short and true.
"""

import os
import re

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..")

# (chapter, name, call regex, marker regex, chapter holding the derivation or None)
DERIVED_FIRST = [
    (
        "configuration_space",
        "grubler_kutzbach",
        r"grubler_kutzbach\(",
        r"m \* \(N - 1 - J\) \+ f",
        None,
    ),
    ("screws", "ScrewSystem.rank", r"\.rank\b(?!\s*\()", r"matrix_rank\(", None),
    (
        "screws",
        "ScrewSystem.reciprocal",
        r"\.reciprocal\(\)",
        r"np\.linalg\.svd\(|\.nullspace\(\)",
        None,
    ),
    (
        "lines",
        "ScrewSystem.principal_screws",
        r"\.principal_screws\(\)",
        r"\(A - h \* D\)\.det\(\)",
        None,
    ),
    (
        "mobility",
        "grubler_kutzbach",
        r"grubler_kutzbach\(",
        r"m \* \(N - 1 - J\) \+ f",
        "configuration_space",
    ),
    (
        "puma_ik",
        "ik.subproblem1",
        r"sk\.ik\.subproblem1\(",
        r"def my_subproblem1\(",
        None,
    ),
    (
        "puma_ik",
        "ik.subproblem2",
        r"sk\.ik\.subproblem2\(",
        r"def my_subproblem2\(",
        None,
    ),
    (
        "puma_ik",
        "ik.subproblem3",
        r"sk\.ik\.subproblem3\(",
        r"def my_subproblem3\(",
        None,
    ),
    (
        "puma_ik",
        "ik.subproblem5",
        r"sk\.ik\.subproblem5\(",
        r"def my_subproblem5\(",
        None,
    ),
    (
        "puma_ik",
        "ik.subproblem6",
        r"sk\.ik\.subproblem6\(",
        r"def my_subproblem6\(",
        None,
    ),
    (
        "puma_ik",
        "ik.general_6r_ik",
        r"sk\.ik\.general_6r_ik\(",
        r"def my_general_6r\(",
        None,
    ),
    (
        "jacobians",
        "jacobians.determinant_symbolic",
        r"determinant_symbolic\(",
        r"\]\.det\(\)",  # a block's det: J[:3, :3].det()
        None,
    ),
    (
        "motion_in_time",
        "trajectory.via_points",
        r"\.via_points\(",
        r"def clamped_velocities\(",
        None,
    ),
    (
        "parallel_kinematics",
        "3-RPR fk_all",
        r"\brpr\.fk_all\(",
        r"def loop\(",
        None,
    ),
    (
        "parallel_kinematics",
        "Stewart fk_all",
        r"\bstewart\.fk_all\(",
        r"def newton_fk\(",
        None,
    ),
    (
        "parallel_kinematics",
        "delta fk_all",
        r"\bdelta\.fk_all\(",
        r"def delta_fk\(",
        None,
    ),
    (
        "parallel_kinematics",
        "workspace",
        r"\.workspace\(",
        r"def (rpr_)?reachable\(",  # the 3-RPR's, then the Stewart's
        None,
    ),
]

# (chapter, name): why the chapter may call it before its derivation. Entries that
# begin "not yet derived" are open items (the chapter should derive it), not
# exceptions: remove each when the chapter gains the derivation (the check then says
# the entry is stale).
ALLOWED_EARLY = {}


def toc_chapters(root=ROOT):
    """The chapters under notebooks/ in _toc.yml order, as names without folder."""
    with open(os.path.join(root, "_toc.yml"), encoding="utf-8") as handle:
        return re.findall(r"file:\s*notebooks/(\w+)", handle.read())


def code_lines(text):
    """The (line number, text) of every line inside a code cell of a MyST chapter."""
    found, inside = [], False
    for number, line in enumerate(text.splitlines(), start=1):
        if not inside and line.startswith("```{code-cell}"):
            inside = True
        elif inside and line.startswith("```"):
            inside = False
        elif inside and not line.startswith(":"):  # skip the cell's options
            found.append((number, line))
    return found


def first_match(lines, pattern):
    """The line number of the first of `lines` that matches `pattern`, or None."""
    regex = re.compile(pattern)
    return next((number for number, line in lines if regex.search(line)), None)


def check(texts, order, table=DERIVED_FIRST, allowed=ALLOWED_EARLY, folder="notebooks"):
    """Problems of the rule on chapter texts {name: MyST text}, as sentences.

    `order` lists the chapters in _toc.yml order. A row whose chapter is not in
    `texts` is skipped (so a test can check one synthetic chapter).
    """
    lines = {name: code_lines(text) for name, text in texts.items()}
    problems, used = [], set()
    for chapter, name, call, marker, derived_in in table:
        if chapter not in lines:
            continue
        path = f"{folder}/{chapter}.md"
        called = first_match(lines[chapter], call)
        if called is None:
            problems.append(
                f"{path}: no code cell calls {name} (/{call}/); update DERIVED_FIRST "
                "in .ci/derive_first.py"
            )
            continue
        source = derived_in or chapter
        derived = first_match(lines.get(source, []), marker)
        if derived_in and derived_in in order and chapter in order:
            ok = order.index(derived_in) < order.index(chapter) and derived is not None
        else:
            ok = derived is not None and derived < called
        if (chapter, name) in allowed:
            used.add((chapter, name))
            if ok:
                problems.append(
                    f"{path}: {name} is now derived before line {called}; remove "
                    f"({chapter!r}, {name!r}) from ALLOWED_EARLY in .ci/derive_first.py"
                )
            continue
        if not ok:
            where = (
                f"{folder}/{source}.md has no code matching /{marker}/"
                if derived is None
                else f"its derivation is at {folder}/{source}.md:{derived}"
            )
            problems.append(
                f"{path}:{called}: calls {name} before the chapter derives it "
                f"({where}); compute it once in plain NumPy/SymPy in a code cell "
                "before this call, or name the exception in ALLOWED_EARLY "
                "(.ci/derive_first.py)"
            )
    rows = {(row[0], row[1]) for row in table if row[0] in lines}
    for key in sorted(set(allowed) - used):
        if key[0] in lines and key not in rows:
            problems.append(f"ALLOWED_EARLY names {key}, which DERIVED_FIRST lacks")
    return problems


def check_chapters(folder, root=ROOT):
    """Problems of the rule on the chapters of `folder` (empty: all good)."""
    texts = {}
    for chapter in toc_chapters(root):
        path = os.path.join(folder, chapter + ".md")
        if os.path.exists(path):
            with open(path, encoding="utf-8") as handle:
                texts[chapter] = handle.read()
    return check(texts, toc_chapters(root), folder=folder)
