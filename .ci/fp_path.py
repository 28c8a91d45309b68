"""Another floating-point path for NumPy: the widest dispatched SIMD set, disabled.

NumPy compiles some loops (sin, cos, exp, log, reductions, ...) several times, one per
SIMD set, and picks the widest the CPU has at import; the last digits of a result can
depend on that choice. ``NPY_DISABLE_CPU_FEATURES`` turns sets off. The course's stored
outputs must not depend on it, so CI runs strict nbval a second time with the widest set
this CPU has turned off (``.ci/other_fp_path.sh``): on a machine with AVX-512 the
AVX-512 loops are replaced by the AVX2 ones (an AMD laptop's), on a machine with AVX2
and no AVX-512 the AVX2/FMA3 loops by the SSE4.2 baseline.

    python .ci/fp_path.py            prints the value for NPY_DISABLE_CPU_FEATURES
                                     (empty when NumPy dispatches no SIMD set here)
    python .ci/fp_path.py --check    under that variable: fails unless each named set
                                     is off in NumPy's __cpu_features__
"""

import os
import sys

# The families of NumPy's dispatch targets, widest first. NumPy >= 2.4 names x86 levels
# (X86_V3 = AVX2 + FMA3 + ..., X86_V4 = AVX-512 F/CD/BW/DQ/VL); older NumPy names the
# sets (AVX2, FMA3, AVX512F, AVX512_SKX, ...). Arm: SVE, then the ASIMD extensions.
FAMILIES = [
    ("AVX-512", lambda name: name.startswith("AVX512") or name == "X86_V4"),
    ("AVX2/FMA3", lambda name: name in {"X86_V3", "AVX2", "FMA3"}),
    ("SVE", lambda name: name.startswith("SVE")),
    ("ASIMD extensions", lambda name: name in {"ASIMDHP", "ASIMDDP", "ASIMDFHM"}),
]


def widest_set(features, dispatch):
    """The family name and the features to disable: the widest family of which this
    CPU has at least one dispatched feature; ``(None, [])`` when there is none.

    Parameters
    ----------
    features : dict of str to bool
        NumPy's ``__cpu_features__``: which features this CPU has.
    dispatch : list of str
        NumPy's ``__cpu_dispatch__``: the features NumPy compiled extra loops for (only
        these can be disabled; disabling a baseline feature is an error).
    """
    for family, member in FAMILIES:
        names = [name for name in dispatch if member(name) and features.get(name)]
        if names:
            return family, names
    return None, []


def _numpy_cpu():
    try:
        from numpy._core import _multiarray_umath as umath  # NumPy 2
    except ImportError:  # NumPy 1
        from numpy.core import _multiarray_umath as umath
    return umath.__cpu_features__, list(umath.__cpu_dispatch__)


def main(argv):
    features, dispatch = _numpy_cpu()
    if argv == ["--check"]:
        wanted = (
            os.environ.get("NPY_DISABLE_CPU_FEATURES", "").replace(",", " ").split()
        )
        if not wanted:
            print("fp_path: NPY_DISABLE_CPU_FEATURES is not set", file=sys.stderr)
            return 1
        still_on = [name for name in wanted if features.get(name, False)]
        on = [name for name, value in features.items() if value]
        print(f"fp_path: NumPy's dispatch with {' '.join(wanted)} off: {' '.join(on)}")
        if still_on:
            print(f"fp_path: still on: {' '.join(still_on)}", file=sys.stderr)
            return 1
        return 0
    if argv:
        print(__doc__, file=sys.stderr)
        return 2
    print(" ".join(widest_set(features, dispatch)[1]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
