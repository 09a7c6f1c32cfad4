// Internal to datasets/: walks the text data of a file line by line from where its reader is
// (datasets/io/input_file.h: streamed, never the whole file in memory), splitting each
// non-blank line into whitespace-separated tokens and keeping the 1-based line number for
// messages. Used by the ASCII checks of the PLY and PCD readers.
#pragma once

#include <string>
#include <vector>

#include "datasets/io/input_file.h"
#include "datasets/io/read_limits.h"

namespace implicitfit {

class TokenLines {
 public:
  explicit TokenLines(InputFile* file) : file_(file) {}

  // Advances to the next non-blank line; false at the end of the data.
  bool Next() {
    while (file_->ReadLine(&text_, CurrentReadLimits().max_line_bytes)) {
      tokens_.clear();
      size_t i = 0;
      while (i < text_.size()) {
        while (i < text_.size() && IsSpace(text_[i])) ++i;
        const size_t start = i;
        while (i < text_.size() && !IsSpace(text_[i])) ++i;
        if (i > start) tokens_.emplace_back(text_, start, i - start);
      }
      if (!tokens_.empty()) return true;
    }
    return false;
  }
  const std::vector<std::string>& tokens() const { return tokens_; }
  long line() const { return file_->line_number(); }  // of the current line (at the end: the last)

 private:
  static bool IsSpace(char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
  }
  InputFile* file_;
  std::string text_;
  std::vector<std::string> tokens_;
};

}  // namespace implicitfit
