"""screwkit's public names: ``__all__`` lists every public submodule and name, each
resolves, ``import screwkit`` warns of nothing, and a moved module's old path is gone
(no release was tagged, so a moved module moves)."""

import importlib
import pkgutil
import subprocess
import sys
import warnings

import pytest

import screwkit as sk


def public_submodules():
    return {
        info.name
        for info in pkgutil.iter_modules(sk.__path__)
        if not info.name.startswith("_")
    }


def test_every_public_submodule_is_in_all():
    expected = public_submodules()
    assert expected - set(sk.__all__) == set()
    assert "mobility_analysis" in expected and "tolerances" in expected


def test_every_name_in_all_resolves_and_is_listed_once():
    assert len(sk.__all__) == len(set(sk.__all__))
    for name in sk.__all__:
        assert getattr(sk, name) is not None, name


def test_every_public_attribute_is_in_all():
    # what `import screwkit` binds (functions, classes, submodules it imports)
    public = {
        name
        for name in vars(sk)
        if not name.startswith("_") and name not in {"importlib"}
    }
    missing = public - set(sk.__all__)
    assert missing == set()


def test_importing_screwkit_warns_of_nothing():
    code = (
        "import warnings; warnings.simplefilter('error'); import screwkit as sk; "
        "sk.mobility; sk.limbs.revolute; sk.mobility_analysis.Mobility"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_sk_mobility_is_the_function_and_the_module_has_its_own_name():
    module = importlib.import_module("screwkit.mobility_analysis")
    assert sk.mobility is module.mobility and callable(sk.mobility)
    assert sk.mobility_analysis is module
    assert sk.mobility([[([0, 0, 1], [0, 0, 0], 0)]]).number == 1


@pytest.mark.parametrize(
    "old",
    ["joints", "mobility", "subproblems", "spherical_wrist", "ur_ik", "stanford_ik"],
)
def test_the_old_module_paths_are_gone(old):
    """sk.joints, screwkit.mobility (the module; sk.mobility is the function) and the
    ik family's flat paths moved before any release: no alias stays behind."""
    assert (
        importlib.machinery.PathFinder.find_spec(f"screwkit.{old}", sk.__path__) is None
    )
    assert callable(sk.mobility)
    if old != "mobility":
        with pytest.raises(AttributeError):
            getattr(sk, old)


def test_star_import_exports_no_module_alias():
    namespace = {}
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        exec("from screwkit import *", namespace)
    assert "joints" not in namespace and callable(namespace["mobility"])
