#include "datasets/io/text_file.h"

#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "datasets/io/io_error.h"

namespace implicitfit {

std::string ReadTextFile(const std::string& path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) throw FileError(path, std::strerror(errno));
  if (S_ISDIR(st.st_mode)) throw FileError(path, "is a directory, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FileError(path, std::string("cannot open: ") + std::strerror(errno));
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw FileError(path, "read error");
  return buffer.str();
}

}  // namespace implicitfit
