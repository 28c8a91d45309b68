#!/usr/bin/env bash
# Runs a command on another floating-point path: NumPy with the CPU's widest dispatched
# SIMD set turned off (NPY_DISABLE_CPU_FEATURES, chosen by .ci/fp_path.py: AVX-512 where
# the CPU has it, else AVX2/FMA3), and OpenBLAS on an old core's kernels
# (OPENBLAS_CORETYPE). Under strict nbval, a stored output that depends on the last
# digits of a sum, a sin or a tie then fails here, in CI, rather than on a student's
# machine with another CPU. CI runs the highest supported Python's `make test` (its
# tests and strict nbval over every chapter) this way.
# Usage: [PYTHON=.venv/bin/python] .ci/other_fp_path.sh [command ...]
#   (default command: strict nbval over notebooks/ with $PYTHON)
set -euo pipefail
cd "$(dirname "$0")/.."
PY=${PYTHON:-.venv/bin/python}

"$PY" -m pytest -q -p no:cacheprovider .ci/test_fp_path.py  # the rule, on this machine too
disable=$("$PY" .ci/fp_path.py)
if [ -z "$disable" ]; then
  echo "other_fp_path: NumPy dispatches no SIMD set on this CPU; the default path only"
else
export NPY_DISABLE_CPU_FEATURES="$disable"
echo "other_fp_path: NPY_DISABLE_CPU_FEATURES=\"$disable\""
# OpenBLAS (NumPy's matrix products, SVDs, solves) picks its kernels by CPU too: an old
# core's kernels (Prescott: SSE3, on every x86-64; ARMv8's generic ones) sum in another
# order, so a table ordered by round-off shows up here (the IK chapter's Pieper table did)
case "$(uname -m)" in
  x86_64) export OPENBLAS_CORETYPE=Prescott ;;
  aarch64) export OPENBLAS_CORETYPE=ARMV8 ;;
esac
echo "other_fp_path: OPENBLAS_CORETYPE=${OPENBLAS_CORETYPE:-unchanged}"
# the variable really changes NumPy's dispatch, in this Python and in a notebook kernel
"$PY" .ci/fp_path.py --check
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
"$PY" - "$tmp/kernel_sees_it.ipynb" <<'EOF'
import sys
import nbformat
check = ("import os, sys\n"
         "sys.path.insert(0, os.path.join(os.environ['FP_PATH_ROOT'], '.ci'))\n"
         "import fp_path\n"
         "assert fp_path.main(['--check']) == 0")
nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(check)])
nbformat.write(nb, sys.argv[1])
EOF
FP_PATH_ROOT=$PWD "$PY" -m pytest --nbval-lax "$tmp/kernel_sees_it.ipynb" -p no:cacheprovider -q \
  --rootdir "$tmp" >"$tmp/kernel.log" 2>&1 || { cat "$tmp/kernel.log"; exit 1; }
fi
if [ $# -eq 0 ]; then
  set -- "$PY" -m pytest --nbval --nbval-sanitize-with .nbval_sanitize.cfg \
    -p no:cacheprovider -q notebooks
fi
"$@"
