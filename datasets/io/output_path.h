// Where an output really goes, checked before any work (docs/cli.md, "File safety"):
//   - "-" is standard output;
//   - a symbolic link is followed to its target (up to 40 links), so the write replaces the
//     target's content and the link stays;
//   - the target must be a regular file or not exist yet: a directory, device node, FIFO or
//     socket is refused (write to "-" for stdout);
//   - its folder must exist and take a new file (ProbeOutputFolder creates and removes one).
// Two paths name the same file when they have the same device and inode, or the same
// normalised absolute path (after following symbolic links): an output equal to an input or to
// another output is refused by the command line (apps/output_guard.h).
// Temporaries (datasets/io/atomic_file.h) are "<dir>/.<name prefix>.implicitfit-<pid>-<n>.tmp",
// each held under an exclusive flock(2) by the process writing it; RemoveStaleTemporaries
// deletes only those whose lock is free and whose process is gone (a run killed with -9), never
// a concurrent run's.
#pragma once

#include <string>
#include <sys/types.h>

namespace implicitfit {

struct OutputTarget {
  std::string path;      // as given
  std::string target;    // the file written: symbolic links followed ("-": stdout)
  bool stdout_ = false;  // "-"
  bool exists = false;   // the target exists (a regular file)
  mode_t mode = 0;       // its permission bits when it exists
  uid_t owner = 0;
  gid_t group = 0;
  dev_t device = 0;
  ino_t inode = 0;
};

// Follows links and checks the target's kind and folder; throws InputError naming `path`.
OutputTarget ResolveOutputPath(const std::string& path);

// Creates and removes a temporary in the target's folder: InputError naming `path` when the
// folder does not take new files (missing, not a folder, read-only, full of inodes).
void ProbeOutputFolder(const OutputTarget& target);

// The identity of an existing or future file for comparisons: the normalised absolute path
// (links followed), and device/inode when it exists.
struct FileIdentity {
  std::string normalised;
  bool exists = false;
  dev_t device = 0;
  ino_t inode = 0;
  bool SameFileAs(const FileIdentity& other) const;
};
FileIdentity IdentifyFile(const std::string& path);

// "<dir>/.<prefix of name>.implicitfit-<pid>-<n>.tmp" for `target` (short enough for any
// file-name length limit).
std::string TemporaryPathFor(const std::string& target);

// Removes the temporaries of dead processes in `dir` (see the header comment); returns how many.
int RemoveStaleTemporaries(const std::string& dir);

}  // namespace implicitfit
