"""The tests' way to drive a headless Chromium: the project's one browser harness,
``.ci/harness.py`` (the system Chromium through Playwright, fenced off the network
except 127.0.0.1, nothing downloaded), loaded from its file so that the tests and the
CI scripts launch the browser the same way."""

import importlib.util
from pathlib import Path

_HARNESS = Path(__file__).resolve().parents[1] / ".ci" / "harness.py"

if _HARNESS.exists():
    _spec = importlib.util.spec_from_file_location("harness", _HARNESS)
    _harness = importlib.util.module_from_spec(_spec)
    _spec.loader.exec_module(_harness)
    CHROMIUM = _harness.CHROMIUM
    launch = _harness.launch
    collect_errors = _harness.collect_errors
else:  # screwkit's tests alone (nox's unit_lowest snapshot has no .ci/): no browser
    CHROMIUM = launch = collect_errors = None
