#!/usr/bin/env bash
# Installs the Debian packages implicitfit builds with, when any is missing. Idempotent and
# silent when everything is already there. Needs root (or sudo) only when it installs.
set -euo pipefail
packages=(cmake g++ make libceres-dev libeigen3-dev libpcl-dev libflann-dev libopenmpi-dev
          openmpi-bin nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev
          clang libclang-rt-14-dev  # clang: the fuzzers (scripts/fuzz.sh)
          pybind11-dev python3-dev python3-numpy python3-pytest  # the Python module (python/)
          python3-venv python3-pip python3-setuptools python3-wheel  # pip install . (pyproject.toml)
          libcgal-dev  # CGAL: bench/detect_comparison only
          libsuitesparse-dev  # SuiteSparseQR: continuity projection of patch meshes
          libopenblas-serial-dev  # BLAS for CHOLMOD, ahead of Ceres' ATLAS (fit/CMakeLists.txt)
          libglpk-dev  # GLPK: exact LPs of the minimum-zone fits
          libjs-three  # three.js, inlined into the pages of `implicitfit view` (view/)
          chromium  # headless Chromium: `view --png` and the browser tests (tests/view/)
          chromium-driver python3-selenium  # the browser tests drive one Chromium
          python3-jsonschema  # tests/docs/check_schemas.py: the JSON Schemas of docs/schemas
          cloudcompare)  # a real client of detect --ply (tests/apps/detect_cloudcompare_test.cc)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0
echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
[ "$(id -u)" -ne 0 ] && sudo_cmd=(sudo)
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
