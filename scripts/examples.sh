#!/usr/bin/env bash
# Installs implicitfit (built in ./build) to a fresh temporary prefix, then builds examples/ as a
# separate consumer project against it (find_package(implicitfit), implicitfit::implicitfit) and
# runs the three examples. .ci/run calls it; it fails if any step fails. IMPLICITFIT_SANITIZE=ON:
# the sanitized build (./build-asan), whose package passes the sanitizer link flags on.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
prefix="$(mktemp -d /tmp/implicitfit_install.XXXXXX)"
trap 'rm -rf "$prefix"' EXIT
source scripts/build_dir.sh
[ -f "$build_dir/CMakeCache.txt" ] || cmake -S . -B "$build_dir" "${build_options[@]}" >/dev/null
cmake --build "$build_dir" -j "$(nproc)" --target implicitfit implicitfit_model implicitfit_fit \
  implicitfit_datasets
# Everything but the Python module (component "python" goes to the system site-packages).
cmake --install "$build_dir" --prefix "$prefix" --component Unspecified >/dev/null
echo "examples: installed to $prefix" >&2
cmake -S examples -B "$prefix/examples-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" "${compiler_options[@]}" >/dev/null
cmake --build "$prefix/examples-build" -j "$(nproc)"
"$prefix/examples-build/fit_sphere" datasets/data/cgal_sphere_single.xyz
"$prefix/examples-build/convex_patch"
"$prefix/examples-build/smooth_csg" "$prefix/part.json"
echo "examples: all three built against the installed package and ran" >&2
