#!/usr/bin/env bash
# AddressSanitizer + UndefinedBehaviorSanitizer (IMPLICITFIT_SANITIZE=ON, in ./build-asan).
# Without arguments: builds everything and runs the whole suite (what .ci/run does; Python tests
# included, with the runtimes preloaded into the interpreter). With test target names, e.g.
# `scripts/sanitize.sh datasets_tests`, builds and runs only those. Any sanitizer report fails
# the run (UBSan does not recover, leaks are reported).
set -euo pipefail
cd "$(dirname "$0")/.."
export IMPLICITFIT_SANITIZE=ON
if [ $# -eq 0 ]; then
  exec bash scripts/test.sh
fi
bash scripts/setup.sh
source scripts/build_dir.sh
launcher=()
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build_dir" "${build_options[@]}" "${launcher[@]}" >/dev/null
cmake --build "$build_dir" -j "$(nproc)" --target "$@"
for target in "$@"; do
  "$(find "$build_dir/tests" -type f -name "$target" -perm -u+x | head -1)"
done
