#!/usr/bin/env bash
# Configures and builds implicitfit (Release) in ./build, after installing what is missing.
# IMPLICITFIT_SANITIZE=ON: the same with AddressSanitizer + UBSan, in ./build-asan.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
source scripts/build_dir.sh
launcher=()  # ccache, when installed, makes rebuilds of unchanged files instant
command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S . -B "$build_dir" "${build_options[@]}" "${launcher[@]}" "$@" >/dev/null
cmake --build "$build_dir" -j "$(nproc)"
