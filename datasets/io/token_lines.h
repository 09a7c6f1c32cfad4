// Internal to datasets/: walks the text data of a file line by line from a byte offset,
// splitting each non-blank line into whitespace-separated tokens and keeping the 1-based line
// number for messages. Used by the ASCII checks of the PLY and PCD readers.
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace implicitfit {

class TokenLines {
 public:
  // `first_line` is the line number of the byte at `offset`.
  TokenLines(const std::string& bytes, size_t offset, long first_line)
      : bytes_(bytes), pos_(offset), line_(first_line - 1) {}

  // Advances to the next non-blank line; false at the end of the data.
  bool Next() {
    while (pos_ < bytes_.size()) {
      size_t end = bytes_.find('\n', pos_);
      if (end == std::string::npos) end = bytes_.size();
      std::istringstream in(bytes_.substr(pos_, end - pos_));
      pos_ = end + 1;
      ++line_;
      tokens_.clear();
      for (std::string t; in >> t;) tokens_.push_back(t);
      if (!tokens_.empty()) return true;
    }
    return false;
  }
  const std::vector<std::string>& tokens() const { return tokens_; }
  long line() const { return line_; }  // of the current line (after the end: the last line)

 private:
  const std::string& bytes_;
  size_t pos_;
  long line_;
  std::vector<std::string> tokens_;
};

}  // namespace implicitfit
