"""The test files build robots and figures when a test asks for them, never at import: a
file's import must not construct a chain, a parallel manipulator or a matplotlib figure
(shared ones come from conftest.py's fixtures or a file's cached builder functions)."""

import importlib.util
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.figure  # noqa: E402
import pytest  # noqa: E402

import screwkit as sk  # noqa: E402
from screwkit.parallel import ParallelManipulator  # noqa: E402

HERE = Path(__file__).parent
#: Every test file, in tests/ and its folders (tests/course/, ...), and the modules the
#: test files share (builders, references, ...), whose import must build nothing either.
TEST_FILES = sorted(HERE.rglob("test_*.py"))
SHARED = sorted(
    path
    for path in HERE.rglob("*.py")
    if not path.name.startswith(("test_", "conftest"))
    and (path.name == "__init__.py" or not (path.parent / "__init__.py").exists())
)


def test_every_test_file_is_found():
    """The layout's folders are searched: the course's tests are among the files."""
    names = {path.relative_to(HERE).as_posix() for path in TEST_FILES}
    assert "test_fixtures.py" in names and "course/test_answer_keys.py" in names


@pytest.mark.parametrize(
    "path", TEST_FILES + SHARED, ids=lambda p: p.relative_to(HERE).as_posix()
)
def test_importing_a_test_file_builds_no_robot_and_no_figure(
    path, monkeypatch, request
):
    ignored = [Path(p).resolve() for p in request.config.getoption("ignore") or []]
    if any(other == path or other in path.parents for other in ignored):
        pytest.skip(f"{path.name} is not run here (--ignore)")
    check_import(path, monkeypatch)


def check_import(path, monkeypatch):
    """Import the file at path afresh, as pytest would (its folder first on sys.path);
    fail if that builds a robot or a figure."""
    for folder in {HERE, path.parent}:  # pytest puts both on sys.path (rootdir-less)
        monkeypatch.syspath_prepend(str(folder))
    built = []
    for cls in (sk.Chain, ParallelManipulator, matplotlib.figure.Figure):
        original = cls.__init__

        def counting(self, *args, _original=original, _cls=cls, **kwargs):
            built.append(_cls.__name__)
            _original(self, *args, **kwargs)

        monkeypatch.setattr(cls, "__init__", counting)
    if path.name == "__init__.py":  # a package: fresh, with its modules
        name = f"_fresh_{path.parent.name}"
        spec = importlib.util.spec_from_file_location(
            name, path, submodule_search_locations=[str(path.parent)]
        )
    else:
        name = f"_fresh_{path.stem}"
        spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, name, module)
    try:
        spec.loader.exec_module(module)
    except (
        ModuleNotFoundError
    ) as error:  # a test of the course, screwkit installed alone
        root = error.name.split(".")[0]
        if root == "screwkit" or any(HERE.rglob(f"{root}.py")) or any(HERE.rglob(root)):
            raise  # screwkit's or the tests' own module: a real failure
        pytest.skip(f"{path.name} needs {error.name}, not installed here")
    finally:
        for key in [k for k in sys.modules if k.startswith(f"{name}.")]:
            del sys.modules[key]
    assert not built, f"importing {path.name} built {sorted(set(built))}"


def test_the_check_sees_a_robot_built_at_import(tmp_path, monkeypatch):
    """The check above can fail: a file that builds the PUMA at import is caught."""
    bad = tmp_path / "test_bad.py"
    bad.write_text("import screwkit as sk\nPUMA = sk.robots.puma560()\n")
    with pytest.raises(AssertionError, match=r"built \['Chain'\]"):
        check_import(bad, monkeypatch)
