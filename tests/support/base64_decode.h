// An independent Base64 decoder (RFC 4648, standard alphabet) for the tests of view pages, so
// that what view/base64.h encodes is checked by code that does not share its tables.
#pragma once

#include <string>
#include <vector>

namespace testsupport {

inline std::vector<unsigned char> Base64Decode(const std::string& text) {
  auto value = [](char c) -> unsigned {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    return c == '+' ? 62 : 63;
  };
  std::vector<unsigned char> out;
  unsigned bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=') break;
    bits = ((bits << 6) | value(c)) & 0xffffff;
    count += 6;
    if (count >= 8) {
      count -= 8;
      out.push_back(static_cast<unsigned char>((bits >> count) & 255));
    }
  }
  return out;
}

}  // namespace testsupport
