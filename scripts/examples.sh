#!/usr/bin/env bash
# Installs implicitfit (built in ./build) as a packager would, DESTDIR=<tmp>/root with the prefix
# /opt/implicitfit, and fails if any file lands outside <tmp>/root/opt/implicitfit (an absolute
# install destination, e.g. a Python site-packages); then builds examples/ as a separate
# consumer project that declares only LANGUAGES CXX against that prefix (find_package(implicitfit),
# implicitfit::implicitfit) and runs the five examples (every_job: every job's public header). .ci/run calls it; it fails if any step
# fails. IMPLICITFIT_SANITIZE=ON: the sanitized build (./build-asan), whose package passes the
# sanitizer link flags on.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
work="$(mktemp -d /tmp/implicitfit_install.XXXXXX)"
trap 'rm -rf "$work"' EXIT
source scripts/build_dir.sh
[ -f "$build_dir/CMakeCache.txt" ] || cmake -S . -B "$build_dir" "${build_options[@]}" >/dev/null
targets=(implicitfit implicitfit_model implicitfit_fit implicitfit_datasets implicitfit_jobs)
grep -q '^IMPLICITFIT_BUILD_PYTHON:BOOL=ON' "$build_dir/CMakeCache.txt" && targets+=(implicitfit_python)
cmake --build "$build_dir" -j "$(nproc)" --target "${targets[@]}"
# Every component (the Python module included), as `cmake --install --prefix P` does.
destdir="$work/root"
prefix=/opt/implicitfit
DESTDIR="$destdir" cmake --install "$build_dir" --prefix "$prefix" >/dev/null
outside="$(cd "$destdir" && find . -not -type d | sed 's|^\.||' | grep -v "^$prefix/" || true)"
if [ -n "$outside" ]; then
  echo "examples: cmake --install --prefix $prefix wrote outside the prefix:" >&2
  echo "$outside" >&2
  exit 1
fi
installed="$destdir$prefix"
echo "examples: installed to $installed ($(find "$installed" -type f | wc -l) files, none outside" \
     "the prefix)" >&2
cmake -S examples -B "$work/examples-build" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$installed" "${compiler_options[@]}" >/dev/null
cmake --build "$work/examples-build" -j "$(nproc)"
"$work/examples-build/fit_sphere" datasets/data/cgal_sphere_single.xyz
"$work/examples-build/convex_patch"
"$work/examples-build/smooth_csg" "$work/part.json"
"$work/examples-build/mesh_and_sample" "$work/sphere.ply"
"$work/examples-build/every_job"  # sample, detect, reconstruct, mesh, design, patch mesh
echo "examples: all five built against the installed package (LANGUAGES CXX) and ran" >&2
