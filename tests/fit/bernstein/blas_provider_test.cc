// fit/CMakeLists.txt links OpenBLAS ahead of Ceres, whose Debian package brings ATLAS's generic
// build (41% of a bracket's patch-mesh run in its kernels; bench/RESULTS.md, "OpenBLAS instead of
// ATLAS"). Which library serves a BLAS or LAPACK call is decided by the dynamic linker: the first
// definition in the process's global scope, the one dlsym(RTLD_DEFAULT) returns, is the one
// CHOLMOD's supernodal factorisations call (this binary links implicitfit::fit, as every
// program that fits does). A link order that put ATLAS's libf77blas first again
// would keep every result and silently slow every fit; this test sees it.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <string>

namespace implicitfit {
namespace {

// The shared object that defines `symbol` for this process ("" if none does).
std::string Provider(const char* symbol) {
  void* address = dlsym(RTLD_DEFAULT, symbol);
  Dl_info info;
  if (address == nullptr || dladdr(address, &info) == 0 || info.dli_fname == nullptr) return "";
  return info.dli_fname;
}

TEST(BlasProvider, CholmodsBlasAndLapackCallsGoToOpenBlas) {
  const std::string openblas = IMPLICITFIT_OPENBLAS_LIBRARY;
  if (openblas.empty()) GTEST_SKIP() << "built without OpenBLAS (fit/CMakeLists.txt)";
  // gemm, gemv, trsv: CHOLMOD's supernodal updates and solves; potrf: its dense blocks.
  for (const char* symbol : {"dgemm_", "dgemv_", "dtrsv_", "dsyrk_", "dpotrf_"}) {
    const std::string provider = Provider(symbol);
    ASSERT_FALSE(provider.empty()) << symbol << " is not defined in this process";
    EXPECT_NE(provider.find("openblas"), std::string::npos)
        << symbol << " comes from " << provider << ", not OpenBLAS";
  }
}

}  // namespace
}  // namespace implicitfit
