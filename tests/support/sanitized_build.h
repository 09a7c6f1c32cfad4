// Whether this test binary is built with AddressSanitizer (IMPLICITFIT_SANITIZE: clang -O1, see
// scripts/build_dir.sh). Only for the few statistical assertions whose outcome depends on the
// compiler's rounding; the code under test runs either way.
#pragma once

#if defined(__SANITIZE_ADDRESS__)  // GCC
#define IMPLICITFIT_TEST_SANITIZED 1
#elif defined(__has_feature)  // clang
#if __has_feature(address_sanitizer)
#define IMPLICITFIT_TEST_SANITIZED 1
#endif
#endif

namespace testsupport {
#ifdef IMPLICITFIT_TEST_SANITIZED
constexpr bool kSanitizedBuild = true;
#else
constexpr bool kSanitizedBuild = false;
#endif
}  // namespace testsupport
