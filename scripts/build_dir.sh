# Sourced by the build scripts: the build folder and its CMake options. IMPLICITFIT_SANITIZE=ON
# (scripts/sanitize.sh, CI) builds the library, command line, tests, Python module and fuzzers
# with clang, ASan + UBSan, at -O1 in ./build-asan; otherwise Release (GCC) in ./build, with the
# benchmark programs unless IMPLICITFIT_BUILD_BENCHMARKS=OFF (CI: they are measurement
# programs, never run there, and the slowest units to compile).
if [ "${IMPLICITFIT_SANITIZE:-OFF}" = ON ]; then
  build_dir=build-asan
  # clang: instrumented code compiles 1.4x slower than plain GCC -O3, GCC's instrumented 2-4x.
  # Consumers of the sanitized package (scripts/examples.sh) must use the same compiler: GCC's
  # and clang's sanitizer runtimes do not mix.
  compiler_options=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
  # The benchmarks (CGAL, PCL surface: the slowest units to compile) are left out: they are
  # measurement programs, not tests; the plain build (scripts/test.sh) compiles them. The
  # fuzzers (scripts/fuzz.sh) are built here too, instead of in a third tree.
  build_options=(-DCMAKE_BUILD_TYPE=Release -DIMPLICITFIT_SANITIZE=ON
                 -DIMPLICITFIT_BUILD_BENCHMARKS=OFF -DIMPLICITFIT_BUILD_FUZZERS=ON
                 "${compiler_options[@]}")
else
  build_dir=build
  compiler_options=()
  build_options=(-DCMAKE_BUILD_TYPE=Release
                 "-DIMPLICITFIT_BUILD_BENCHMARKS=${IMPLICITFIT_BUILD_BENCHMARKS:-ON}")
fi
