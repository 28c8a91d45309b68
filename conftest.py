"""pytest for the whole repository (``make test`` collects ``tests`` and screwkit's
doctests).

screwkit's deprecated alias modules (their docstring begins "Deprecated alias") warn
when imported, and the tests turn screwkit's DeprecationWarnings into errors: their
doctests (they have none) are not collected. ``tests/`` checks that each alias warns.
"""

import ast
from pathlib import Path


def _is_deprecated_alias(path):
    docstring = ast.get_docstring(ast.parse(path.read_text(encoding="utf-8"))) or ""
    return docstring.startswith("Deprecated alias")


collect_ignore = [
    str(path.relative_to(Path(__file__).parent))
    for path in sorted((Path(__file__).parent / "screwkit").glob("*.py"))
    if _is_deprecated_alias(path)
]
