"""Binder builds the course: its Python is a supported one and its requirements resolve
on it.

Binder (repo2docker) takes its Python from binder/runtime.txt and installs
binder/requirements.txt (the course's pins, JupyterLab and screwkit) with pip. The
resolution test runs pip's dry run with that exact minor version of Python; it is
skipped, saying why, when this machine has no such interpreter or no access to the
package index."""

import glob
import json
import os
import re
import shutil
import subprocess
import tomllib
from pathlib import Path

import pytest
from packaging.specifiers import SpecifierSet
from packaging.version import Version

ROOT = Path(__file__).resolve().parents[2]
PYPROJECT = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
REQUIRES_PYTHON = SpecifierSet(PYPROJECT["requires-python"])
CLASSIFIED = [
    Version(c.rsplit(" ", 1)[-1])
    for c in PYPROJECT["classifiers"]
    if re.fullmatch(r"Programming Language :: Python :: 3\.\d+", c)
]
NETWORK_ERRORS = (
    "NewConnectionError",
    "Temporary failure in name resolution",
    "Name or service not known",
    "Network is unreachable",
    "ConnectTimeout",
    "Could not fetch URL",
    "No route to host",
)


def binder_python():
    """The 'X.Y' of binder/runtime.txt ('python-X.Y')."""
    runtime = (ROOT / "binder" / "runtime.txt").read_text().strip()
    match = re.fullmatch(r"python-(3\.\d+)", runtime)
    assert match, f"binder/runtime.txt must read 'python-3.X', got {runtime!r}"
    return match.group(1)


def interpreter(minor):
    """A working `pythonX.Y` on this machine (pyenv's own or on PATH), or None."""
    pyenv = Path(os.environ.get("PYENV_ROOT", Path.home() / ".pyenv"))
    candidates = sorted(
        glob.glob(str(pyenv / "versions" / f"{minor}.*" / "bin" / f"python{minor}"))
    )
    candidates.append(shutil.which(f"python{minor}"))
    for path in filter(None, candidates):
        # a pyenv shim of an inactive version is on PATH yet fails when run
        if subprocess.run([path, "-c", ""], capture_output=True).returncode == 0:
            return path
    return None


def test_binder_python_is_in_the_supported_range():
    minor = Version(binder_python())
    assert minor in REQUIRES_PYTHON, (
        f"Binder's Python {minor} is outside {REQUIRES_PYTHON}"
    )
    assert minor in CLASSIFIED, f"Binder's Python {minor} is not among {CLASSIFIED}"


def test_the_classifiers_state_the_supported_range():
    """The classifiers name consecutive minor versions, the lowest being
    requires-python's."""
    assert CLASSIFIED == [
        Version(f"3.{n}") for n in range(CLASSIFIED[0].minor, CLASSIFIED[-1].minor + 1)
    ]
    assert all(version in REQUIRES_PYTHON for version in CLASSIFIED)
    assert Version(f"3.{CLASSIFIED[0].minor - 1}") not in REQUIRES_PYTHON


def test_binder_requirements_are_the_course_pins_and_jupyterlab():
    lines = [
        line.split("#")[0].strip()
        for line in (ROOT / "binder" / "requirements.txt").read_text().splitlines()
    ]
    lines = [line for line in lines if line]
    assert lines[0] == "-r ../requirements.txt"
    assert [line.split("==")[0] for line in lines[1:]] == ["jupyterlab"]
    assert re.fullmatch(r"jupyterlab==4\.\d+\.\d+", lines[1])


def test_binder_requirements_resolve_for_binders_python(tmp_path):
    minor = binder_python()
    python = interpreter(minor)
    if python is None:
        pytest.skip(
            f"no Python {minor} on this machine to resolve binder/requirements.txt with"
        )
    report = tmp_path / "report.json"
    # run from the repository's root, as repo2docker does, so that `-e .` is screwkit
    result = subprocess.run(
        [
            python,
            "-m",
            "pip",
            "install",
            "--dry-run",
            "--ignore-installed",
            "--quiet",
            "--disable-pip-version-check",
            "--retries",
            "1",
            "--timeout",
            "30",
            "--report",
            str(report),
            "--requirement",
            "binder/requirements.txt",
        ],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=900,
    )
    if result.returncode and any(error in result.stderr for error in NETWORK_ERRORS):
        pytest.skip(
            f"no access to the package index: {result.stderr.strip().splitlines()[-1]}"
        )
    assert result.returncode == 0, result.stderr
    resolved = json.loads(report.read_text())
    assert resolved["environment"]["python_version"] == minor
    versions = {
        item["metadata"]["name"].lower(): item["metadata"]["version"]
        for item in resolved["install"]
    }
    assert "screwkit" in versions
    pins = dict(
        re.fullmatch(r"([A-Za-z0-9_.-]+)==(\S+)", line).groups()
        for line in (
            (ROOT / "requirements.txt").read_text().splitlines()
            + (ROOT / "binder" / "requirements.txt").read_text().splitlines()
        )
        if re.fullmatch(r"[A-Za-z0-9_.-]+==\S+", line.strip())
    )
    for name, version in pins.items():
        assert versions[name.lower()] == version, (
            f"{name}: pinned {version}, resolved {versions}"
        )
