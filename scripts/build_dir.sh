# Sourced by the build scripts: the build folder and its CMake options. IMPLICITFIT_SANITIZE=ON
# (CI sets it) builds everything with ASan + UBSan in ./build-asan; otherwise Release in ./build.
if [ "${IMPLICITFIT_SANITIZE:-OFF}" = ON ]; then
  build_dir=build-asan
  # clang: instrumented code compiles 1.4x slower than plain GCC -O3, GCC's instrumented 2-4x.
  # Consumers of the sanitized package (scripts/examples.sh) must use the same compiler: GCC's
  # and clang's sanitizer runtimes do not mix.
  compiler_options=(-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++)
  build_options=(-DCMAKE_BUILD_TYPE=Release -DIMPLICITFIT_SANITIZE=ON "${compiler_options[@]}")
else
  build_dir=build
  compiler_options=()
  build_options=(-DCMAKE_BUILD_TYPE=Release)
fi
