// Base64 (RFC 4648, standard alphabet, '=' padding) of raw bytes: how a view page carries its
// typed arrays inside JSON (view/page_html.h), decoded in the browser by atob(). Written here
// (20 lines) rather than pulling a library in for it: none of the project's dependencies offers
// it (OpenSSL's EVP_EncodeBlock would be a new dependency).
#pragma once

#include <cstddef>
#include <string>

namespace implicitfit {

std::string Base64Encode(const void* data, std::size_t bytes);

}  // namespace implicitfit
