// Writes a whole file or nothing: the content goes to "<path>.tmp.<pid>" in the same folder,
// is flushed, then renamed over <path> (rename is atomic on POSIX filesystems). A failure at
// any point removes the temporary and throws InputError naming <path>; <path> is never left
// half-written.
#pragma once

#include <string>

namespace implicitfit {

void WriteFileAtomically(const std::string& path, const std::string& content);

}  // namespace implicitfit
