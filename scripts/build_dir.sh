# Sourced by the build scripts: the build folder and its CMake options. IMPLICITFIT_SANITIZE=ON
# (CI sets it) builds everything with ASan + UBSan in ./build-asan; otherwise Release in ./build.
if [ "${IMPLICITFIT_SANITIZE:-OFF}" = ON ]; then
  build_dir=build-asan
  build_options=(-DCMAKE_BUILD_TYPE=Release -DIMPLICITFIT_SANITIZE=ON)
else
  build_dir=build
  build_options=(-DCMAKE_BUILD_TYPE=Release)
fi
