"""screwkit's public names: ``__all__`` lists every public submodule and name, each
resolves, ``import screwkit`` warns of nothing, and the moved paths (``sk.joints``,
``screwkit.mobility`` the module) still work with a DeprecationWarning."""

import importlib
import pkgutil
import subprocess
import sys
import warnings

import pytest

import screwkit as sk

#: The ik family's old flat paths, kept one release as deprecated aliases of the
#: modules of screwkit/ik/ (each warns on import): not public names.
IK_FAMILY_FLAT = {"subproblems", "spherical_wrist", "ur_ik", "stanford_ik"}


def public_submodules():
    return {
        info.name
        for info in pkgutil.iter_modules(sk.__path__)
        if not info.name.startswith("_")
    }


def test_every_public_submodule_is_in_all():
    expected = public_submodules() - set(sk._DEPRECATED_MODULES) - IK_FAMILY_FLAT
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
        if not name.startswith("_")
        and name not in {"importlib", "sys", "types", "warnings"}
    }
    missing = public - set(sk.__all__) - IK_FAMILY_FLAT - {"joints"}
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


def test_the_old_module_path_of_mobility_works_and_warns():
    with pytest.deprecated_call(match="use screwkit.mobility_analysis"):
        from screwkit.mobility import Mobility, grubler_kutzbach
    assert Mobility is sk.Mobility and grubler_kutzbach is sk.grubler_kutzbach
    import screwkit.mobility  # noqa: F401 (the import must not rebind sk.mobility)

    assert sk.mobility is sk.mobility_analysis.mobility


def test_every_name_read_from_sk_joints_warns_and_is_the_limb_builder():
    for _ in range(2):
        with pytest.deprecated_call(match="use screwkit.limbs"):
            prismatic = sk.joints.prismatic
        assert prismatic is sk.limbs.prismatic
    with pytest.raises(AttributeError, match="no attribute 'nothing'"):
        sk.joints.nothing  # noqa: B018 (the read is the test)


def test_importing_the_joints_module_warns():
    code = (
        "import warnings, screwkit\n"
        "with warnings.catch_warnings(record=True) as caught:\n"
        "    warnings.simplefilter('always')\n"
        "    import screwkit.joints\n"
        "assert any(issubclass(w.category, DeprecationWarning) "
        "and 'screwkit.limbs' in str(w.message) for w in caught), caught\n"
        "with warnings.catch_warnings(record=True) as caught:\n"
        "    warnings.simplefilter('always')\n"
        "    screwkit.joints.revolute\n"
        "assert [w.category for w in caught] == [DeprecationWarning], caught\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True)


def test_a_deprecated_name_is_not_exported_by_star():
    namespace = {}
    with warnings.catch_warnings():
        warnings.simplefilter("error", DeprecationWarning)
        exec("from screwkit import *", namespace)
    assert "joints" not in namespace and callable(namespace["mobility"])
