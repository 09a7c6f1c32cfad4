// A user file opened for reading, safely: the path is opened without blocking (a named pipe
// cannot hang the open) and must be a regular file; a directory, FIFO, socket or device
// (/dev/zero, /dev/stdin, a terminal; also through symbolic links) is refused with InputError
// before a byte is read, so no input can block forever or stream without end. The file is then
// read once, in chunks (lines or byte ranges), never slurped unless asked with a cap:
// readers allocate for what they have parsed, not for what a header claims.
#pragma once

#include <string>
#include <vector>

namespace implicitfit {

class InputFile {
 public:
  explicit InputFile(const std::string& path);  // throws InputError naming the file
  ~InputFile();
  InputFile(const InputFile&) = delete;
  InputFile& operator=(const InputFile&) = delete;

  const std::string& path() const { return path_; }
  unsigned long long size() const { return size_; }  // bytes at open (fstat)

  // The next line without its '\n' (a trailing '\r' is kept); false at the end of the file.
  // A line longer than max_line bytes throws InputError naming the file and the line.
  bool ReadLine(std::string* line, size_t max_line);
  // Lines read so far (the 1-based number of the line ReadLine returned last).
  long line_number() const { return line_number_; }
  // Offset of the first byte not yet returned by ReadLine.
  unsigned long long offset() const { return consumed_; }

  // Exactly n bytes at `offset` (independent of ReadLine); false when the file is shorter.
  bool ReadAt(unsigned long long offset, void* buffer, size_t n) const;

  // The whole file; InputError when it is larger than max_bytes (the message names the limit
  // and `how_to_raise`).
  std::string ReadAll(unsigned long long max_bytes, const std::string& how_to_raise);

 private:
  bool Fill();
  std::string path_;
  int fd_ = -1;
  unsigned long long size_ = 0, consumed_ = 0;
  long line_number_ = 0;
  std::vector<char> buffer_;
  size_t begin_ = 0, end_ = 0;  // unread bytes of buffer_
  bool eof_ = false;
};

}  // namespace implicitfit
