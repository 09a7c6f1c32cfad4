#include "datasets/io/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "datasets/io/io_error.h"
#include "datasets/io/read_limits.h"

namespace implicitfit {
namespace {

constexpr size_t kChunk = 1 << 16;

ReadLimits& Limits() {
  static ReadLimits limits;
  return limits;
}

const char* KindOf(mode_t mode) {
  if (S_ISFIFO(mode)) return "a named pipe (FIFO)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

}  // namespace

const ReadLimits& CurrentReadLimits() { return Limits(); }
void SetReadLimits(const ReadLimits& limits) { Limits() = limits; }

InputFile::InputFile(const std::string& path) : path_(path) {
  // O_NONBLOCK: opening a FIFO for reading would otherwise wait for a writer.
  fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd_ < 0) throw FileError(path, std::strerror(errno));
  struct stat st;
  if (::fstat(fd_, &st) != 0) {
    const int e = errno;
    ::close(fd_);
    throw FileError(path, std::strerror(e));
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd_);
    throw FileError(path, "is a directory, not a file");
  }
  if (!S_ISREG(st.st_mode)) {
    ::close(fd_);
    throw FileError(path, std::string("is ") + KindOf(st.st_mode) +
                              ", not a regular file (implicitfit reads regular files only)");
  }
  const int flags = ::fcntl(fd_, F_GETFL);
  if (flags >= 0) ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK);
  size_ = static_cast<unsigned long long>(st.st_size);
}

InputFile::~InputFile() {
  if (fd_ >= 0) ::close(fd_);
}

bool InputFile::Fill() {
  if (eof_) return false;
  if (begin_ > 0) {  // keep the unread tail at the front
    std::memmove(buffer_.data(), buffer_.data() + begin_, end_ - begin_);
    end_ -= begin_;
    begin_ = 0;
  }
  if (buffer_.size() < end_ + kChunk) buffer_.resize(end_ + kChunk);
  while (true) {
    const ssize_t n = ::read(fd_, buffer_.data() + end_, kChunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileError(path_, std::string("read error: ") + std::strerror(errno));
    if (n == 0) {
      eof_ = true;
      return false;
    }
    end_ += static_cast<size_t>(n);
    return true;
  }
}

bool InputFile::ReadLine(std::string* line, size_t max_line) {
  size_t scanned = begin_;
  while (true) {
    // (memchr on an empty buffer's null data() is undefined even for 0 bytes)
    const void* nl =
        end_ > scanned ? std::memchr(buffer_.data() + scanned, '\n', end_ - scanned) : nullptr;
    if (nl) {
      const size_t stop = static_cast<const char*>(nl) - buffer_.data();
      if (stop - begin_ > max_line) break;
      line->assign(buffer_.data() + begin_, stop - begin_);
      consumed_ += stop + 1 - begin_;
      begin_ = stop + 1;
      ++line_number_;
      return true;
    }
    if (end_ - begin_ > max_line) break;
    scanned = end_ - begin_;  // Fill moves the unread bytes to the front
    if (!Fill()) {
      if (begin_ == end_) return false;
      line->assign(buffer_.data() + begin_, end_ - begin_);  // last line without '\n'
      consumed_ += end_ - begin_;
      begin_ = end_;
      ++line_number_;
      return true;
    }
  }
  throw LineError(path_, line_number_ + 1,
                  "line longer than " + std::to_string(max_line) + " bytes (not a text line)");
}

bool InputFile::ReadAt(unsigned long long offset, void* buffer, size_t n) const {
  char* out = static_cast<char*>(buffer);
  size_t done = 0;
  while (done < n) {
    const ssize_t r = ::pread(fd_, out + done, n - done, static_cast<off_t>(offset + done));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) throw FileError(path_, std::string("read error: ") + std::strerror(errno));
    if (r == 0) return false;
    done += static_cast<size_t>(r);
  }
  return true;
}

std::string InputFile::ReadAll(unsigned long long max_bytes, const std::string& how_to_raise) {
  auto too_large = [&]() {
    return FileError(path_, "larger than the limit of " + std::to_string(max_bytes) +
                                " bytes (raise it with " + how_to_raise + ")");
  };
  if (size_ > max_bytes) throw too_large();
  std::string all;
  all.reserve(static_cast<size_t>(size_));
  all.append(buffer_.data() + begin_, end_ - begin_);
  begin_ = end_;
  char chunk[kChunk];
  while (true) {  // the size may have changed since fstat: stop at the limit regardless
    const ssize_t n = ::read(fd_, chunk, sizeof chunk);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) throw FileError(path_, std::string("read error: ") + std::strerror(errno));
    if (n == 0) break;
    if (all.size() + static_cast<size_t>(n) > max_bytes) throw too_large();
    all.append(chunk, static_cast<size_t>(n));
  }
  eof_ = true;
  consumed_ += all.size();
  return all;
}

}  // namespace implicitfit
