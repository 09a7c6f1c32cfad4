// The state of every entry under a folder (recursively, links not followed): its type,
// permission bits, size and a content hash (files) or target (symbolic links), so that a test
// can prove a command left a user's files exactly as they were. Device nodes and FIFOs are
// recorded by type and mode only (reading them could block).
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace testsupport {

struct EntryState {
  char type = '?';  // f file, d folder, l link, p FIFO, c/b device, s socket
  unsigned mode = 0;
  std::uintmax_t size = 0;
  std::uint64_t hash = 0;  // FNV-1a of the content (files)
  std::string link;        // the target (links)
  bool operator==(const EntryState& o) const {
    return type == o.type && mode == o.mode && size == o.size && hash == o.hash && link == o.link;
  }
  std::string Describe() const {
    return std::string(1, type) + " mode " + std::to_string(mode) + " size " +
           std::to_string(size) + " hash " + std::to_string(hash) + (link.empty() ? "" : " -> " + link);
  }
};

inline std::uint64_t HashFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::uint64_t h = 1469598103934665603ULL;
  char buffer[1 << 16];
  while (in) {
    in.read(buffer, sizeof buffer);
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      h ^= static_cast<unsigned char>(buffer[i]);
      h *= 1099511628211ULL;
    }
  }
  return h;
}

// Relative path -> state, for every entry under `dir`.
inline std::map<std::string, EntryState> SnapshotFolder(const std::string& dir) {
  namespace fs = std::filesystem;
  std::map<std::string, EntryState> out;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(dir, fs::directory_options::none, ec), end;
       !ec && it != end; it.increment(ec)) {
    const std::string path = it->path().string();
    struct stat st;
    if (::lstat(path.c_str(), &st) != 0) continue;
    EntryState e;
    e.mode = st.st_mode & 07777;
    if (S_ISREG(st.st_mode)) {
      e.type = 'f';
      e.size = static_cast<std::uintmax_t>(st.st_size);
      e.hash = HashFile(path);
    } else if (S_ISDIR(st.st_mode)) {
      e.type = 'd';
      e.mode = 0;  // folders: their presence only
    } else if (S_ISLNK(st.st_mode)) {
      e.type = 'l';
      e.mode = 0;
      e.link = fs::read_symlink(it->path(), ec).string();
    } else if (S_ISFIFO(st.st_mode)) {
      e.type = 'p';
    } else if (S_ISCHR(st.st_mode)) {
      e.type = 'c';
    } else if (S_ISBLK(st.st_mode)) {
      e.type = 'b';
    } else if (S_ISSOCK(st.st_mode)) {
      e.type = 's';
    }
    out[fs::relative(it->path(), dir, ec).string()] = e;
  }
  return out;
}

}  // namespace testsupport
