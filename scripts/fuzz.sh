#!/usr/bin/env bash
# Builds the cloud-reader fuzzers and the model-file fuzzer with clang (libFuzzer +
# AddressSanitizer + UBSan) in ./build-fuzz and runs each for FUZZ_SECONDS (default 60), seeded
# with the bundled sample clouds (models: tests/fuzz/model_corpus and a dictionary of its keys). With FUZZ_RUNS set (CI), each runs that many inputs from the fixed seed 1 instead,
# so a run is repeatable. Exits non-zero on the first finding (the crashing input is left in
# build-fuzz/).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${FUZZ_SECONDS:-60}"
budget=(-max_total_time="$seconds")
[ -n "${FUZZ_RUNS:-}" ] && budget=(-runs="$FUZZ_RUNS" -seed=1)
flags="-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -g -O1"
cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang \
  -DCMAKE_CXX_COMPILER=clang++ "-DCMAKE_CXX_FLAGS=$flags" -DIMPLICITFIT_BUILD_FUZZERS=ON \
  -DIMPLICITFIT_BUILD_BENCHMARKS=OFF -DIMPLICITFIT_BUILD_PYTHON=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)" --target ply_reader_fuzzer pcd_reader_fuzzer xyz_reader_fuzzer \
  model_json_fuzzer
for format in ply pcd xyz; do
  corpus="build-fuzz/corpus_$format"
  mkdir -p "$corpus"
  cp datasets/data/*."$format" "$corpus"/ 2>/dev/null || true
  [ "$format" = xyz ] && cp datasets/data/*.xyz "$corpus"/
  echo "fuzz: $format (${budget[*]})" >&2
  (cd build-fuzz && ASAN_OPTIONS=detect_leaks=0 "tests/fuzz/${format}_reader_fuzzer" \
     "${budget[@]}" -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 "corpus_$format")
done
mkdir -p build-fuzz/corpus_model
cp tests/fuzz/model_corpus/*.json build-fuzz/corpus_model/
echo "fuzz: model (${budget[*]})" >&2
(cd build-fuzz && ASAN_OPTIONS=detect_leaks=0 tests/fuzz/model_json_fuzzer "${budget[@]}" \
   -max_len=65536 -rss_limit_mb=2048 -print_final_stats=1 -dict=../tests/fuzz/model_json.dict \
   corpus_model)
