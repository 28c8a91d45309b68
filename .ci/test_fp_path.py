"""The rule of .ci/fp_path.py: which SIMD set the second nbval run turns off.

The CPUs below are written out from NumPy's documentation of its dispatch targets
(numpy.org/devdocs/reference/simd/build-options.html), not read from this machine; the
last test asks this machine's NumPy and checks the variable really changes its
dispatch.
"""

import os
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import fp_path  # noqa: E402

# NumPy >= 2.4 dispatches x86 levels
NEW_DISPATCH = ["X86_V3", "X86_V4", "AVX512_ICL", "AVX512_SPR"]
# NumPy 1.26 / 2.0 to 2.3 dispatched sets
OLD_DISPATCH = ["SSSE3", "SSE41", "POPCNT", "SSE42", "AVX", "F16C", "FMA3", "AVX2"]
OLD_DISPATCH += ["AVX512F", "AVX512CD", "AVX512_KNL", "AVX512_SKX", "AVX512_CLX"]
OLD_DISPATCH += ["AVX512_CNL", "AVX512_ICL", "AVX512_SPR"]


def cpu(*names):
    return {name: True for name in names}


def test_an_avx512_machine_loses_its_avx512_loops_and_keeps_avx2():
    ice_lake = cpu(
        "X86_V2", "AVX2", "FMA3", "X86_V3", "AVX512F", "X86_V4", "AVX512_ICL"
    )
    assert fp_path.widest_set(ice_lake, NEW_DISPATCH) == (
        "AVX-512",
        ["X86_V4", "AVX512_ICL"],
    )
    skylake_x = cpu("AVX", "FMA3", "AVX2", "AVX512F", "AVX512CD", "AVX512_SKX")
    assert fp_path.widest_set(skylake_x, OLD_DISPATCH) == (
        "AVX-512",
        ["AVX512F", "AVX512CD", "AVX512_SKX"],
    )


def test_an_avx2_machine_without_avx512_loses_avx2_and_fma3():
    zen = cpu("X86_V2", "AVX", "F16C", "FMA3", "AVX2", "X86_V3")
    zen.update({"X86_V4": False, "AVX512F": False})
    assert fp_path.widest_set(zen, NEW_DISPATCH) == ("AVX2/FMA3", ["X86_V3"])
    assert fp_path.widest_set(zen, OLD_DISPATCH) == ("AVX2/FMA3", ["FMA3", "AVX2"])


def test_arm_and_a_machine_with_nothing_dispatched():
    apple_m1 = cpu("NEON", "ASIMD", "ASIMDHP", "ASIMDDP", "ASIMDFHM")
    arm_dispatch = ["ASIMDHP", "ASIMDDP", "ASIMDFHM", "SVE"]
    assert fp_path.widest_set(apple_m1, arm_dispatch) == (
        "ASIMD extensions",
        ["ASIMDHP", "ASIMDDP", "ASIMDFHM"],
    )
    graviton3 = cpu("ASIMD", "ASIMDHP", "ASIMDDP", "SVE")
    assert fp_path.widest_set(graviton3, arm_dispatch) == ("SVE", ["SVE"])
    assert fp_path.widest_set(cpu("SSE2", "X86_V2"), NEW_DISPATCH) == (None, [])


def run(env_value):
    env = dict(os.environ, NPY_DISABLE_CPU_FEATURES=env_value)
    return subprocess.run(
        [sys.executable, str(Path(__file__).parent / "fp_path.py"), "--check"],
        env=env,
        capture_output=True,
        text=True,
    )


def test_the_variable_changes_this_machines_dispatch():
    chosen = subprocess.run(
        [sys.executable, str(Path(__file__).parent / "fp_path.py")],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    features, dispatch = fp_path._numpy_cpu()
    assert all(features[name] for name in chosen)  # on without the variable
    if chosen:
        assert run(" ".join(chosen)).returncode == 0  # and off under it
    # a feature NumPy does not dispatch cannot be disabled (NumPy warns and ignores
    # it): it stays on, and --check says so
    try:
        from numpy._core._multiarray_umath import __cpu_baseline__ as baseline
    except ImportError:  # NumPy 1
        from numpy.core._multiarray_umath import __cpu_baseline__ as baseline
    fixed = next(
        name
        for name, on in features.items()
        if on and name not in dispatch and name not in baseline
    )
    failed = run(fixed)
    assert failed.returncode == 1 and f"still on: {fixed}" in failed.stderr
