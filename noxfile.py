"""The Python versions the course claims, each tested in a fresh virtual environment.

    nox -s course-3.11 course-3.13   the course's pinned environment and `make test`
    nox -s unit_lowest               screwkit alone (`pip install .`) at the lowest
                                     versions its dependency bounds admit, with its unit
                                     tests (the fast tier) and doctests
    nox -l                           every session (`course` runs on each supported
                                     version)

Install nox with `python3 -m pip install -r .ci/nox-requirements.txt` (nox and uv), in a
virtual environment of its own. The supported range is `requires-python` in
pyproject.toml; keep `SUPPORTED` here, the Makefile, the classifiers and the README in
step with it. Each session prints how long it took.
"""

import os
import re
import shutil
import time
from pathlib import Path

import nox

HERE = Path(__file__).resolve().parent
SUPPORTED = ["3.11", "3.12", "3.13"]
LOWEST, HIGHEST = SUPPORTED[0], SUPPORTED[-1]

# The course's tests (chapters, book, Binder), not screwkit's: not in the snapshot.
COURSE_ONLY_TESTS = ["tests/course"]

# Prints each test file (argv) that imports a module this environment lacks: a test of
# the course (nbformat, jupytext, ...), not of screwkit, when screwkit is installed
# alone.
_NEEDS_MISSING_MODULE = """
import ast, importlib.util, os, sys
for path in sys.argv[1:]:
    sys.path[:0] = ["tests", os.path.dirname(path)]  # the tests' own shared modules
    tree = ast.parse(open(path, encoding="utf-8").read())
    roots = {alias.name.split(".")[0] for node in tree.body
             if isinstance(node, ast.Import) for alias in node.names}
    roots |= {node.module.split(".")[0] for node in tree.body
              if isinstance(node, ast.ImportFrom) and node.module and not node.level}
    missing = sorted(name for name in roots if importlib.util.find_spec(name) is None)
    if missing:
        print(path, ",".join(missing))
"""

nox.options.sessions = [f"course-{LOWEST}", f"course-{HIGHEST}", "unit_lowest"]
nox.options.error_on_missing_interpreters = True
os.environ.setdefault("UV_PYTHON_DOWNLOADS", "never")  # use the machine's Pythons only


def _use_pyenv_interpreters():
    """Put each supported pyenv interpreter on PATH ahead of pyenv's shims.

    A pyenv shim such as `python3.12` is found on PATH even when it is not pyenv's
    active version, and then fails when run; nox would pick it and stop. Links to the
    real interpreters in .nox/pythons come first instead. Without pyenv nothing changes.
    """
    versions = Path(os.environ.get("PYENV_ROOT", Path.home() / ".pyenv")) / "versions"
    links = HERE / ".nox" / "pythons"
    for minor in SUPPORTED:
        found = sorted(
            versions.glob(f"{minor}.*/bin/python{minor}"),
            key=lambda path: [int(n) for n in re.findall(r"\d+", path.parts[-3])],
        )
        if found:
            links.mkdir(parents=True, exist_ok=True)
            link = links / f"python{minor}"
            link.unlink(missing_ok=True)
            link.symlink_to(found[-1])
    if links.is_dir():
        os.environ["PATH"] = f"{links}{os.pathsep}{os.environ['PATH']}"


_use_pyenv_interpreters()


def _pins(*names):
    """The exact pins of `names` in requirements.txt, e.g. ['pytest==9.2.0']."""
    pins = {}
    for line in (HERE / "requirements.txt").read_text().splitlines():
        match = re.match(r"([A-Za-z0-9_.-]+)==\S+", line.strip())
        if match:
            pins[match.group(1).lower()] = match.group(0)
    return [pins[name] for name in names]


class _Timer:
    """Prints how long a session took, also when it fails."""

    def __init__(self, session):
        self.session = session

    def __enter__(self):
        self.start = time.perf_counter()

    def __exit__(self, *exc):
        seconds = time.perf_counter() - self.start
        outcome = "failed" if exc[0] else "passed"
        self.session.log(f"{self.session.name} {outcome} in {seconds:.0f} s")


@nox.session(python=SUPPORTED, venv_backend="venv")
def course(session):
    """The course's pinned environment (requirements.txt) and `make test`, here: the
    fast tier of the tests and strict nbval over every chapter (the slow tiers, Binder's
    resolve among them, which does not depend on this session's Python, run once, in
    `make test-all`)."""
    with _Timer(session):
        session.run(
            "make",
            "test",
            f"VENV={session.virtualenv.location}",
            f"PYTHON={session.virtualenv.location}/bin/python",
            external=True,
        )


@nox.session(python=LOWEST, venv_backend="uv")
def unit_lowest(session):
    """screwkit alone, at the lower bounds of its dependencies (uv lowest-direct).

    Only screwkit's own dependencies are resolved to their lowest versions; the test
    tools are the course's pins. It runs in a snapshot of pyproject.toml, screwkit/ and
    tests/ (no build files in the working tree), and the tests import the installed
    screwkit.
    """
    with _Timer(session):
        snapshot = Path(session.create_tmp()).resolve() / "snapshot"
        shutil.rmtree(snapshot, ignore_errors=True)
        snapshot.mkdir()
        for name in ["pyproject.toml", "README.md"]:
            shutil.copy(HERE / name, snapshot / name)
        for name in ["screwkit", "tests", "tools"]:
            shutil.copytree(
                HERE / name,
                snapshot / name,
                ignore=shutil.ignore_patterns("__pycache__"),
            )
        session.install(
            "--resolution",
            "lowest-direct",
            str(snapshot),
            *_pins("pytest", "hypothesis"),
        )
        session.run(
            "uv",
            "pip",
            "list",
            "--python",
            session.virtualenv.location,
            external=True,
            silent=False,
        )
        session.chdir(snapshot)
        tests = sorted(
            str(path.relative_to(snapshot))
            for path in snapshot.glob("tests/**/test_*.py")
        )
        report = session.run("python", "-c", _NEEDS_MISSING_MODULE, *tests, silent=True)
        course_only = COURSE_ONLY_TESTS + [
            line.split()[0] for line in report.splitlines()
        ]
        session.log(
            "not run here (course tests, needing missing modules): "
            + "; ".join(report.splitlines())
        )
        ignores = [f"--ignore={path}" for path in course_only]
        # `pytest`, not `python -m pytest`, so that the tests import the installed
        # screwkit. The fast tier (tests/conftest.py): every module at its lowest
        # bounds; the slow tiers (the same code on heavier inputs, and the references)
        # run once, on the course's pins, in `make test-all`; `nox -s unit_lowest --
        # --tier all` runs them here too.
        session.run(
            "pytest", "tests", *ignores, "-q", *(session.posargs or ["--tier", "fast"])
        )
        session.run("pytest", "--pyargs", "screwkit", "--doctest-modules", "-q")
