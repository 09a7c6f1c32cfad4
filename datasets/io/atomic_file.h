// Writes a whole file or nothing. The content goes to a temporary in the target's folder
// (datasets/io/output_path.h: a short per-process name, held under flock while it exists, so a
// concurrent run never deletes it and the next run removes it if this one is killed), is
// flushed and fsync'ed, then renamed over the target (atomic on POSIX filesystems). A symbolic
// link is written through (its target gets the content, the link stays); an existing target
// keeps its permission bits (and owner, when allowed). "-" writes to standard output. A failure
// at any point removes the temporary and throws InputError naming the path; the old file is
// left as it was.
//
// OutputTransaction (all or nothing over a whole run): while one is open, every
// WriteFileAtomically only stages its file (written, flushed, not renamed); Commit() then
// writes staged standard output and renames every file; a transaction destroyed without
// Commit (an exception, exit 2) removes every temporary: the run leaves none of its outputs.
#pragma once

#include <string>

namespace implicitfit {

void WriteFileAtomically(const std::string& path, const std::string& content);

// Where `path`'s content is now: its staged temporary while an open transaction holds a write
// to it (a command reading back what it wrote, e.g. fit --view of its --out), else `path`.
std::string CurrentFileLocation(const std::string& path);

class OutputTransaction {
 public:
  OutputTransaction();  // at most one at a time per process
  ~OutputTransaction();
  OutputTransaction(const OutputTransaction&) = delete;
  OutputTransaction& operator=(const OutputTransaction&) = delete;
  // Standard output for "-" outputs (a descriptor the command's own printing does not use:
  // apps/output_guard.cc moves that to stderr); default 1.
  void SetStdoutDescriptor(int fd);
  // Renames every staged file into place (stdout first); throws InputError when one fails.
  void Commit();
};

}  // namespace implicitfit
