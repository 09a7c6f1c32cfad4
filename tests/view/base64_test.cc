// Base64 of view pages (view/base64.h): the test vectors of RFC 4648 section 10, and random
// bytes decoded back by an independent decoder (tests/support/base64_decode.h).
#include "view/base64.h"

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "support/base64_decode.h"

namespace implicitfit {
namespace {

std::string Encode(const std::string& s) { return Base64Encode(s.data(), s.size()); }

TEST(Base64, Rfc4648Vectors) {
  EXPECT_EQ(Encode(""), "");
  EXPECT_EQ(Encode("f"), "Zg==");
  EXPECT_EQ(Encode("fo"), "Zm8=");
  EXPECT_EQ(Encode("foo"), "Zm9v");
  EXPECT_EQ(Encode("foob"), "Zm9vYg==");
  EXPECT_EQ(Encode("fooba"), "Zm9vYmE=");
  EXPECT_EQ(Encode("foobar"), "Zm9vYmFy");
}

TEST(Base64, RandomBytesDecodeBack) {
  std::mt19937 rng(5);
  for (int n = 0; n < 200; ++n) {
    std::vector<unsigned char> bytes(n);
    for (unsigned char& b : bytes) b = static_cast<unsigned char>(rng() & 255);
    const std::string text = Base64Encode(bytes.data(), bytes.size());
    EXPECT_EQ(text.size(), (n + 2) / 3 * 4u);
    EXPECT_EQ(testsupport::Base64Decode(text), bytes) << n;
  }
}

}  // namespace
}  // namespace implicitfit
