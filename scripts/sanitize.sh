#!/usr/bin/env bash
# Builds the test suite with AddressSanitizer and UndefinedBehaviorSanitizer in ./build-asan and
# runs it; any sanitizer report fails the run (UBSan does not recover, leaks are reported).
# Give test target names to build and run only those, e.g. `scripts/sanitize.sh datasets_tests`.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
flags="-fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer"
# No Python module: an ASan-built extension cannot load into the uninstrumented interpreter.
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DIMPLICITFIT_BUILD_BENCHMARKS=OFF -DIMPLICITFIT_BUILD_PYTHON=OFF \
  "-DCMAKE_CXX_FLAGS=$flags" "-DCMAKE_EXE_LINKER_FLAGS=$flags" >/dev/null
export ASAN_OPTIONS=detect_leaks=1
if [ $# -eq 0 ]; then
  cmake --build build-asan -j "$(nproc)"
  ctest --test-dir build-asan --output-on-failure -j "$(nproc)"
  exit
fi
cmake --build build-asan -j "$(nproc)" --target "$@"
for target in "$@"; do
  "$(find build-asan/tests -type f -name "$target" -perm -u+x | head -1)"
done
