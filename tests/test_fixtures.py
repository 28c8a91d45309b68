"""The test files build robots and figures when a test asks for them, never at import: a
file's import must not construct a chain, a parallel manipulator or a matplotlib figure
(shared ones come from conftest.py's fixtures or a file's cached builder functions)."""

import importlib.util
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.figure  # noqa: E402
import pytest  # noqa: E402

import screwkit as sk  # noqa: E402
from screwkit.parallel import ParallelManipulator  # noqa: E402

HERE = Path(__file__).parent
TEST_FILES = sorted(HERE.glob("test_*.py"))


@pytest.mark.parametrize("path", TEST_FILES, ids=lambda p: p.name)
def test_importing_a_test_file_builds_no_robot_and_no_figure(
    path, monkeypatch, request
):
    ignored = [Path(p) for p in request.config.getoption("ignore") or []]
    if any(other.exists() and path.samefile(other) for other in ignored):
        pytest.skip(f"{path.name} is not run here (--ignore)")
    check_import(path, monkeypatch)


def check_import(path, monkeypatch):
    """Import the file at path afresh; fail if that builds a robot or a figure."""
    built = []
    for cls in (sk.Chain, ParallelManipulator, matplotlib.figure.Figure):
        original = cls.__init__

        def counting(self, *args, _original=original, _cls=cls, **kwargs):
            built.append(_cls.__name__)
            _original(self, *args, **kwargs)

        monkeypatch.setattr(cls, "__init__", counting)
    spec = importlib.util.spec_from_file_location(f"_fresh_{path.stem}", path)
    try:
        spec.loader.exec_module(importlib.util.module_from_spec(spec))
    except (
        ModuleNotFoundError
    ) as error:  # a test of the course, screwkit installed alone
        if error.name.split(".")[0] == "screwkit":
            raise
        pytest.skip(f"{path.name} needs {error.name}, not installed here")
    assert not built, f"importing {path.name} built {sorted(set(built))}"


def test_the_check_sees_a_robot_built_at_import(tmp_path, monkeypatch):
    """The check above can fail: a file that builds the PUMA at import is caught."""
    bad = tmp_path / "test_bad.py"
    bad.write_text("import screwkit as sk\nPUMA = sk.robots.puma560()\n")
    with pytest.raises(AssertionError, match=r"built \['Chain'\]"):
        check_import(bad, monkeypatch)
