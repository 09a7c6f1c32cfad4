// Outputs that would destroy or mislead: an output equal to an input or to another output
// (same path, normalised path, symbolic or hard link), device nodes, FIFOs and folders as
// outputs, missing folders (refused at once, not after the fit), symbolic links (written
// through, the link and the mode kept), 250-byte names, "-" for standard output, full or closed
// standard output, temporaries of killed runs.
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include <filesystem>

#include "apps/hostile/hostile_case.h"
#include "support/file_snapshot.h"

namespace hostile {
namespace {

// A command writing OUT (the placeholder) from the case's inputs.
struct Writer {
  std::string id, args;  // "{out}" the output under test
  std::string input;     // the input file a same-file output would destroy
  std::vector<std::string> other_outputs;
  double seconds;
};

const std::vector<Writer> kWriters = {
    {"fit", "fit c.xyz --model plane --out {out} --report r.json", "c.xyz", {"r.json"}, 15},
    {"sample", "sample s.json --count 200 --out {out}", "s.json", {}, 15},
    {"mesh", "mesh s.json --cell 0.2 --out {out}", "s.json", {}, 15},
    {"design", "design c.xyz --count 4 --out {out}", "c.xyz", {}, 15},
    {"detect", "detect s.xyz --out {out} --labels l.txt", "s.xyz", {"l.txt"}, 30},
    {"reconstruct", "reconstruct s.xyz --scene scene.json --out {out}", "s.xyz", {}, 30},
};

// The extension each writer's output needs.
std::string OutName(const Writer& w, const std::string& stem) {
  if (w.id == "mesh") return stem + ".ply";
  if (w.id == "sample") return stem + ".xyz";
  return stem + ".json";
}

std::string Replace(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

void Inputs(const std::string& dir) {
  Write(dir + "/c.xyz", PlaneXyz(300));
  Write(dir + "/s.xyz", SphereXyz(600));
  Write(dir + "/s.json", SphereModel());
  Write(dir + "/scene.json",
        "{\"format\": \"implicitfit-scene\", \"version\": 1, \"cloud\": \"s.xyz\", \"points\": "
        "600, \"primitives\": [{\"name\": \"p0\", \"model\": {\"type\": \"sphere\", \"center\": "
        "[0, 0, 0], \"radius\": 1}, \"points\": 600, \"rms_distance\": 0, "
        "\"standard_deviations\": {}, \"normal_side\": \"outward\"}], \"unassigned\": 0}\n");
}

Case Make(const Writer& w, const std::string& id, const std::string& out, int exit_code,
          const std::string& mention, const std::string& defect) {
  Case c;
  c.family = "outputs";
  c.name = id + "_" + w.id;
  c.args = Replace(w.args, "{out}", out);
  c.exit_code = exit_code;
  if (!mention.empty()) c.mention = {mention};
  c.outputs = w.other_outputs;
  c.seconds = w.seconds;
  c.defect = defect;
  c.setup = Inputs;
  return c;
}

// A case on the standard inputs with this command.
Case Plain(const std::string& name, const std::string& args, int exit_code,
           const std::string& mention, const std::string& defect) {
  Case c;
  c.family = "outputs";
  c.name = name;
  c.setup = Inputs;
  c.args = args;
  c.exit_code = exit_code;
  if (!mention.empty()) c.mention = {mention};
  c.defect = defect;
  return c;
}

std::vector<std::string> LinkStillLink(const std::string& dir, const std::string& link,
                                       const std::string& target, unsigned mode) {
  std::vector<std::string> problems;
  struct stat st;
  if (::lstat((dir + "/" + link).c_str(), &st) != 0 || !S_ISLNK(st.st_mode))
    problems.push_back(link + " is no longer a symbolic link");
  if (::stat((dir + "/" + target).c_str(), &st) != 0 || st.st_size == 0)
    problems.push_back(target + " (the link's target) was not written");
  else if ((st.st_mode & 07777) != mode)
    problems.push_back(target + " mode " + std::to_string(st.st_mode & 07777) + ", was " +
                       std::to_string(mode));
  return problems;
}

// The cases of one writer's output path: the input itself (by name, normalised, linked), a folder,
// a FIFO, a device, a missing or file-blocked folder, a link through which it would write, a
// name too long.
void AddOutputPathCases(const Writer& w, std::vector<Case>* cases) {
  // The output is the input: by the same name, a normalised name, a symbolic and a hard link.
  Case same =
      Make(w, "out_is_input", w.input, 2, "input", "fit c.xyz --out c.xyz replaces the input");
  same.sanitized = true;
  cases->push_back(same);
  cases->push_back(Make(w, "out_is_input_dotted", "./sub/../" + w.input, 2, "input", ""));
  cases->back().setup = [](const std::string& dir) {
    Inputs(dir);
    std::filesystem::create_directory(dir + "/sub");
  };
  Case via_link = Make(w, "out_is_input_via_link", "alias", 2, "input", "");
  via_link.setup = [w](const std::string& dir) {
    Inputs(dir);
    MakeSymlink(w.input, dir + "/alias");
  };
  cases->push_back(via_link);
  Case hard = Make(w, "out_is_input_hard_link", "hard", 2, "input", "");
  hard.setup = [w](const std::string& dir) {
    Inputs(dir);
    ::link((dir + "/" + w.input).c_str(), (dir + "/hard").c_str());
  };
  cases->push_back(hard);
  // Folders, devices, FIFOs as outputs; a missing folder (refused before the work).
  Case folder = Make(w, "out_is_folder", "d", 2, "directory", "");
  folder.setup = [](const std::string& dir) {
    Inputs(dir);
    std::filesystem::create_directory(dir + "/d");
  };
  cases->push_back(folder);
  Case fifo = Make(w, "out_is_fifo", OutName(w, "f"), 2, "FIFO",
                   "write-then-rename replaces a device node with a regular file");
  fifo.setup = [w](const std::string& dir) {
    Inputs(dir);
    MakeFifo(dir + "/" + OutName(w, "f"));
  };
  fifo.sanitized = w.id == "fit";
  cases->push_back(fifo);
  Case device = Make(w, "out_is_device_link", OutName(w, "null"), 2, "device", "");
  device.setup = [w](const std::string& dir) {
    Inputs(dir);
    MakeSymlink("/dev/null", dir + "/" + OutName(w, "null"));
  };
  cases->push_back(device);
  Case missing = Make(w, "out_in_missing_folder", "missing/" + OutName(w, "o"), 2, "missing", "");
  missing.seconds = 3;  // at once, not after the fit
  missing.sanitized = w.id == "reconstruct";
  cases->push_back(missing);
  Case under_file = Make(w, "out_under_a_file", w.input + "/" + OutName(w, "o"), 2, "", "");
  cases->push_back(under_file);
  // Through a symbolic link: the target gets the content, the link stays, the mode is kept.
  Case through = Make(w, "out_through_link", OutName(w, "link"), 0, "",
                      "write-then-rename replaces a symlink; turns a 0600 file into 0644");
  const std::string link = OutName(w, "link"), target = OutName(w, "target");
  through.setup = [link, target](const std::string& dir) {
    Inputs(dir);
    Write(dir + "/" + target, "old\n");
    ::chmod((dir + "/" + target).c_str(), 0600);
    MakeSymlink(target, dir + "/" + link);
  };
  through.outputs.push_back(target);
  through.check = [link, target](const std::string& dir, const RunOutcome&) {
    return LinkStillLink(dir, link, target, 0600);
  };
  through.sanitized = w.id == "fit" || w.id == "sample";
  cases->push_back(through);
  // A 250-byte name (its temporary must still fit the 255-byte limit).
  const std::string long_name = OutName(w, std::string(245, 'n'));
  Case long_case = Make(w, "out_long_name", long_name, 0, "", "fails for ~250-character names");
  long_case.outputs.push_back(long_name);
  long_case.must_exist = {long_name};
  long_case.sanitized = w.id == "fit";
  cases->push_back(long_case);
}

}  // namespace

std::vector<Case> OutputCases() {
  std::vector<Case> cases;
  for (const Writer& w : kWriters) AddOutputPathCases(w, &cases);
  // A missing output folder after a long run: refused before the run (it was 11.5 s).
  for (const auto& [id, args] : std::vector<std::pair<std::string, std::string>>{
           {"reconstruct_detect_missing_folder", "reconstruct big.xyz --out missing/m.json"},
           {"patch_mesh_missing_folder", "fit big.xyz --model patch-mesh --out missing/m.json"}}) {
    Case c = Plain(id, args, 2, "missing",
                   "output paths checked before any work (reconstruct: 11.5 s)");
    c.setup = [](const std::string& dir) { Write(dir + "/big.xyz", SphereXyz(30000)); };
    c.seconds = 2;
    c.sanitized = true;
    cases.push_back(c);
  }
  // Two outputs of one run naming one file.
  const std::vector<std::pair<std::string, std::string>> twins = {
      {"fit_out_is_report", "fit c.xyz --model plane --out m.json --report m.json"},
      {"fit_out_is_report_dotted", "fit c.xyz --model plane --out m.json --report ./m.json"},
      {"detect_out_is_labels", "detect s.xyz --out o.json --labels o.json"},
      {"detect_labels_is_ply", "detect s.xyz --out o.json --labels l.ply --ply l.ply"},
      {"detect_out_is_report", "detect s.xyz --out o.json --report o.json"},
      {"reconstruct_mesh_is_report",
       "reconstruct s.xyz --scene scene.json --out o.json --mesh r.ply --report r.ply"},
      {"reconstruct_out_is_scene", "reconstruct s.xyz --scene scene.json --out scene.json"},
      {"fit_out_is_init", "fit s.xyz --init s.json --out s.json"},
  };
  for (const auto& [id, args] : twins) {
    Case c = Plain(id, args, 2, "refused",
                   "--out equal to --report or to --labels silently overwrites");
    c.sanitized = id == "fit_out_is_report";
    cases.push_back(c);
  }
  // All or nothing: the report must not be written when the model cannot be.
  Case report_alone =
      Plain("fit_report_without_model",
            "fit s.xyz --model patch-mesh --report r.json --out missing/m.json", 2, "missing",
            "a failed run can leave a report saying success beside a missing model");
  report_alone.outputs = {"r.json"};  // checked: must not exist (exit 2)
  report_alone.seconds = 5;
  report_alone.sanitized = true;
  cases.push_back(report_alone);
  // Standard output: "-" as the output, full, closed.
  Case dash = Plain("fit_out_stdout", "fit c.xyz --model plane --out -", 0, "", "");
  dash.check = [](const std::string&, const RunOutcome& r) {
    std::vector<std::string> p;
    if (r.out.find("\"implicitfit-model\"") == std::string::npos)
      p.push_back("the model did not go to stdout");
    if (r.out.find("inliers") != std::string::npos) p.push_back("the summary went to stdout too");
    return p;
  };
  cases.push_back(dash);
  Case dash_mesh = dash;
  dash_mesh.name = "mesh_out_stdout";
  dash_mesh.args = "mesh s.json --cell 0.2 --out - | head -c 3 | grep -q ply";
  dash_mesh.check = nullptr;
  cases.push_back(dash_mesh);
  for (const std::string& command : {std::string("eval s.json c.xyz"),
                                     std::string("check s.json --patches-only"),
                                     std::string("fit c.xyz --model plane --out m.json")}) {
    const std::string id = command.substr(0, command.find(' '));
    Case full = Plain(id + "_stdout_full", command + " > /dev/full", 2, "standard output",
                      id == "eval" ? "eval exits 0 when stdout is full or closed" : "");
    full.outputs = {"m.json"};
    full.sanitized = id == "eval";
    cases.push_back(full);
    Case closed = full;
    closed.name = id + "_stdout_closed";
    closed.args = command + " >&-";
    cases.push_back(closed);
  }
  // Temporaries: a killed run's is removed by the next run; a live run's is kept.
  Case stale = Plain("stale_temporary_removed", "fit c.xyz --model plane --out m.json", 0, "",
                     "kill -9 of a single command leaves its temporary for good");
  stale.setup = [](const std::string& dir) {
    Inputs(dir);
    Write(dir + "/.m.json.implicitfit-99999999-0.tmp", "{\"half\": ");
  };
  stale.outputs = {"m.json", ".m.json.implicitfit-99999999-0.tmp"};
  stale.check = [](const std::string& dir, const RunOutcome&) {
    std::vector<std::string> p;
    if (::access((dir + "/.m.json.implicitfit-99999999-0.tmp").c_str(), F_OK) == 0)
      p.push_back("the temporary of a killed run (pid 99999999) is still there");
    return p;
  };
  stale.sanitized = true;
  cases.push_back(stale);
  return cases;
}

}  // namespace hostile
