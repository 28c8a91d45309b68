"""The wheel holds every folder of screwkit: pyproject.toml lists its packages by name, so
a new family folder (ik/, motion/, parallel/) must be added there or `pip install .`
ships a screwkit that cannot import it."""

import tomllib
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]


def test_every_package_folder_is_listed_in_pyproject():
    with open(ROOT / "pyproject.toml", "rb") as f:
        listed = set(tomllib.load(f)["tool"]["setuptools"]["packages"])
    folders = {
        ".".join(init.parent.relative_to(ROOT).parts)
        for init in (ROOT / "screwkit").rglob("__init__.py")
    }
    assert folders == listed, f"folders {sorted(folders)}, listed {sorted(listed)}"
