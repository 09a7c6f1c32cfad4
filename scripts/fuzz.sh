#!/usr/bin/env bash
# Builds the cloud-reader fuzzers and the model-file fuzzer with clang (libFuzzer +
# AddressSanitizer + UBSan) and runs each for FUZZ_SECONDS (default 60), seeded with the bundled
# sample clouds (models: tests/fuzz/model_corpus and a dictionary of its keys). With FUZZ_RUNS
# set (CI), each runs that many inputs from the fixed seed 1 instead, so a run is repeatable.
# Exits non-zero on the first finding (the crashing input is left in the build folder).
# IMPLICITFIT_SANITIZE=ON (.ci/run): the fuzzers are built in the sanitized tree ./build-asan
# (scripts/build_dir.sh turns them on there), so CI compiles the libraries twice, not three
# times; otherwise in ./build-fuzz, a tree of their own with every source instrumented.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-60}"
budget=(-max_total_time="$seconds")
[ -n "${FUZZ_RUNS:-}" ] && budget=(-runs="$FUZZ_RUNS" -seed=1)
fuzzers=(ply_reader_fuzzer pcd_reader_fuzzer xyz_reader_fuzzer model_json_fuzzer)
if [ "${IMPLICITFIT_SANITIZE:-OFF}" = ON ]; then
  bash scripts/setup.sh
  source scripts/build_dir.sh
  dir="$build_dir"
  launcher=()
  command -v ccache >/dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  cmake -S . -B "$dir" "${build_options[@]}" "${launcher[@]}" >/dev/null
else
  dir=build-fuzz
  flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -g -O1"
  cmake -S . -B "$dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
    -DCMAKE_CXX_COMPILER=clang++ "-DCMAKE_CXX_FLAGS=$flags" -DIMPLICITFIT_BUILD_FUZZERS=ON \
    -DIMPLICITFIT_BUILD_BENCHMARKS=OFF -DIMPLICITFIT_BUILD_PYTHON=OFF >/dev/null
fi
cmake --build "$dir" -j "$(nproc)" --target "${fuzzers[@]}"
for format in ply pcd xyz; do
  corpus="$dir/corpus_$format"
  mkdir -p "$corpus"
  cp datasets/data/*."$format" "$corpus"/ 2>/dev/null || true
  echo "fuzz: $format (${budget[*]})" >&2
  (cd "$dir" && ASAN_OPTIONS=detect_leaks=0 "tests/fuzz/${format}_reader_fuzzer" \
     "${budget[@]}" -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 "corpus_$format")
done
mkdir -p "$dir/corpus_model"
cp tests/fuzz/model_corpus/*.json "$dir/corpus_model/"
echo "fuzz: model (${budget[*]})" >&2
(cd "$dir" && ASAN_OPTIONS=detect_leaks=0 tests/fuzz/model_json_fuzzer "${budget[@]}" \
   -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 -dict=../tests/fuzz/model_json.dict \
   corpus_model)
