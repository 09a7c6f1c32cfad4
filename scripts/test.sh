#!/usr/bin/env bash
# Builds everything and runs the whole test suite (the README's test command). With
# IMPLICITFIT_SANITIZE=ON (.ci/run) the suite runs under AddressSanitizer + UBSan, and any
# sanitizer report fails it (UBSan does not recover; leaks are reported).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/build.sh
source scripts/build_dir.sh
ctest --test-dir "$build_dir" --output-on-failure -j "$(nproc)"
