#!/usr/bin/env bash
# Builds everything and runs the whole test suite (the README's test command). With
# IMPLICITFIT_SANITIZE=ON (.ci/run) the suite runs under AddressSanitizer + UBSan, and any
# sanitizer report fails it (UBSan does not recover; leaks are reported); that run leaves the
# heavy statistical tests listed in tests/sanitizer_exclusions.txt to the plain run.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
source scripts/build_dir.sh
exclude=()
if [ "${IMPLICITFIT_SANITIZE:-OFF}" = ON ]; then
  pattern=$(grep -v '^[[:space:]]*\(#\|$\)' tests/sanitizer_exclusions.txt |
            sed 's/^/^/; s/$/$/' | paste -sd '|')
  [ -n "$pattern" ] && exclude=(-E "$pattern")
fi
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)" "${exclude[@]}"
