// One case of the hostile-input battery (hostile_battery_test.cc): files a careless or unlucky
// user has, the command they run, and what must happen: the exit code, the words the message
// must hold (the file or option it names), the files the run may write. The runner adds what
// holds for every case: no crash, no hang (a wall-clock bound), bounded memory, every other
// file in the case's folder exactly as before (type, mode, content, link target), no
// temporary left, and for exit 2 none of the outputs written (all or nothing).
#pragma once

#include <functional>
#include <ostream>
#include <string>
#include <vector>

namespace hostile {

struct RunOutcome;

struct Case {
  std::string name;  // unique, letters, digits and _ (a gtest name)
  std::string family;
  // Creates the user's files in `dir` (the case's scratch folder, also the working directory).
  std::function<void(const std::string& dir)> setup;
  // The command after the CLI, run by /bin/sh in the folder: "{cli}" is replaced by the tool
  // (for cases that run it more than once); without "{cli}" the tool comes first.
  std::string args;
  int exit_code = 2;
  std::vector<std::string> mention;  // substrings stderr must hold
  std::vector<std::string> outputs;  // files (relative) the run may create or replace
  std::vector<std::string> must_exist;  // files (relative) that must exist afterwards
  double seconds = 20.0;                // wall-clock bound (x4 under the sanitizers)
  long long address_space = 0;          // RLIMIT_AS for this case (0: the runner's default)
  bool sanitized = false;               // also in the smaller set run under the sanitizers
  std::string defect;                   // the issue-26 defect this case is the regression test of
  // Extra checks after the run (e.g. a link still a link, a mode kept): messages of failures.
  std::function<std::vector<std::string>(const std::string& dir, const RunOutcome& run)> check;
};

// gtest prints a parameter by this (not its bytes).
inline void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

struct RunOutcome {
  int exit_code = -1;
  std::string out, err;
};

std::vector<Case> ReaderCases();
std::vector<Case> ModelCases();
std::vector<Case> OptionCases();
std::vector<Case> OutputCases();
std::vector<Case> BatchCases();
std::vector<Case> DegenerateCases();

// File makers for the cases (hostile_files.cc).
void Write(const std::string& path, const std::string& bytes);
std::string PlaneXyz(int n, bool normals = true, double noise = 0.002,
                     unsigned seed = 7);  // z = 0.1 x + noise, x and y uniform in [-1, 1]
std::string SphereXyz(int n, double radius = 1.0, bool normals = true);  // centre 0
std::string NoisySphereXyz(int n, double noise);  // unit sphere, radial Gaussian noise, no normals
std::string PlyBinaryHeader(long long vertices, const std::string& extra_properties = "");
std::string PlyAsciiPoints(int n);  // a valid ASCII PLY of n sphere points
std::string PcdHeader(const std::string& data, long long points,
                      const std::string& fields = "x y z", const std::string& size = "4 4 4",
                      const std::string& type = "F F F", const std::string& count = "1 1 1");
std::string SphereModel(double radius = 1.0);
std::string PlaneModel();
std::string PatchModel(int degree);        // a Bernstein patch of the degree (all control points 1)
std::string BlobsModel(int count);         // `count` Gaussian blobs on a line
std::string WideUnionModel(int children);  // a union of `children` spheres
void MakeFifo(const std::string& path);
void MakeSymlink(const std::string& target, const std::string& link);

}  // namespace hostile
