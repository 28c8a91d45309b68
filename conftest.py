"""pytest for the whole repository (``make test`` collects ``tests`` and screwkit's
doctests; ``make site-check`` the browser tests of ``.ci/``).

The browser tests use pytest-playwright's fixtures (``browser``, ``page``), installed
with ``.ci/requirements.txt``; here they are pointed at the project's one browser: the
system Chromium with the fence of ``.ci/harness.py`` (no host but 127.0.0.1, no
background requests, nothing downloaded). Without pytest-playwright (``make test``,
screwkit's tests alone) the browser tests skip and say why.
"""

import importlib.util
from pathlib import Path

import pytest

_HARNESS = Path(__file__).resolve().parent / ".ci" / "harness.py"

if importlib.util.find_spec("pytest_playwright") and _HARNESS.exists():
    _spec = importlib.util.spec_from_file_location("harness", _HARNESS)
    _harness = importlib.util.module_from_spec(_spec)
    _spec.loader.exec_module(_harness)

    @pytest.fixture(scope="session")
    def browser_type_launch_args(browser_type_launch_args):
        """pytest-playwright's launch options: the system Chromium, fenced."""
        return {
            **browser_type_launch_args,
            "executable_path": _harness.executable(),
            "args": _harness.FLAGS,
        }
