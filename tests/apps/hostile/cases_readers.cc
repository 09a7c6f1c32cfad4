// Hostile cloud files (text, PLY, PCD; FIFOs, devices, folders) through the commands that read
// clouds: each file is refused with exit 2 and a message naming it, fast, without allocating
// what a forged header claims.
#include <cstdint>
#include <cstring>
#include <filesystem>

#include "apps/hostile/hostile_case.h"

namespace hostile {
namespace {

struct CloudFile {
  std::string id, name;  // case id; file name (its extension picks the reader)
  std::string bytes;
  std::string mention;   // words the message must hold besides the file name
  std::string defect;
  int exit_code = 2;     // 0: a valid file that must still be read quickly
};

std::string Floats(std::initializer_list<float> values) {
  std::string out(values.size() * 4, '\0');
  size_t i = 0;
  for (float v : values) std::memcpy(&out[4 * i++], &v, 4);
  return out;
}

std::vector<CloudFile> TextClouds() {
  return {
      {"xyz_empty", "c.xyz", "", "no points", ""},
      {"xyz_comments", "c.xyz", "# a\n# b\n\n", "no points", ""},
      {"xyz_garbage", "c.xyz", std::string("\x7f" "ELF\x02\x01\x01\0\0\0", 10) + "garbage\n", "", ""},
      {"xyz_nan", "c.xyz", "0 0 0\n1 nan 0\n0 1 0\n", "c.xyz:2", ""},
      {"xyz_inf", "c.xyz", "0 0 0\n1 0 inf\n", "c.xyz:2", ""},
      {"xyz_two_columns", "c.xyz", "0 0 0\n1 2\n", "c.xyz:2", ""},
      {"xyz_seven_columns", "c.xyz", "1 2 3 4 5 6 7\n", "c.xyz:1", ""},
      {"xyz_mixed_columns", "c.xyz", "0 0 0\n1 1 1 0 0 1\n", "c.xyz:2", ""},
      {"xyz_endless_line", "c.xyz", std::string(300000, '1') + "\n", "longer than", ""},
      {"xyz_word", "c.xyz", "0 0 zero\n", "c.xyz:1", ""},
      {"xyz_nul", "c.xyz", std::string("0 0 0\n\0\0\0\n", 10), "c.xyz:2", ""},
      {"xyz_overflow", "c.xyz", "0 0 1e999\n", "c.xyz:1", ""},
      {"xyzl_fraction_label", "c.xyzl", "0 0 0 1.5\n", "c.xyzl:1", ""},
  };
}

std::vector<CloudFile> PlyClouds() {
  const std::string ascii = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                            "property float y\nproperty float z\nend_header\n";
  return {
      {"ply_empty", "c.ply", "", "empty", ""},
      {"ply_not_ply", "c.ply", "plx\nformat ascii 1.0\n", "not a PLY", ""},
      {"ply_no_end_header", "c.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", "end_header", ""},
      {"ply_billion_vertices", "c.ply", PlyBinaryHeader(1000000000) + Floats({0, 0, 0}),
       "1000000000", ""},
      {"ply_huge_count", "c.ply",
       "ply\nformat binary_little_endian 1.0\nelement vertex 18446744073709551615\nproperty float "
       "x\nproperty float y\nproperty float z\nend_header\n" + Floats({0, 0, 0}),
       "18446744073709551615", ""},
      {"ply_ascii_short", "c.ply", ascii + "0 0 0\n1 1 1\n", "c.ply:10", ""},
      {"ply_ascii_extra", "c.ply", ascii + "0 0 0\n1 1 1\n2 2 2\n3 3 3\n", "c.ply:11", ""},
      {"ply_ascii_word", "c.ply", ascii + "0 0 0\n1 x 1\n2 2 2\n", "c.ply:9", ""},
      {"ply_ascii_nan", "c.ply", ascii + "0 0 0\n1 nan 1\n2 2 2\n", "c.ply:9", ""},
      {"ply_vertex_list", "c.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "property float z\nproperty list uint int idx\nend_header\n0 0 0 400" +
           [] {
             std::string s;
             for (int i = 0; i < 400; ++i) s += " 7";
             return s + "\n";
           }(),
       "list property", "PLY list property in the vertex element aborts PCL (SIGABRT)"},
      {"ply_vertex_list_binary", "c.ply",
       PlyBinaryHeader(1, "property list uchar int idx\n") + Floats({0, 0, 0}) + "\x01" +
           std::string(4, '\0'),
       "list property", "PLY list property in the vertex element aborts PCL (SIGABRT)"},
      {"ply_no_z", "c.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "end_header\n0 0\n",
       "x, y or z", ""},
      {"ply_unknown_type", "c.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n", "quad", ""},
      {"ply_bad_format", "c.ply", "ply\nformat utf8 1.0\nend_header\n", "utf8", ""},
      {"ply_negative_count", "c.ply", "ply\nformat ascii 1.0\nelement vertex -1\nend_header\n",
       "malformed element", ""},
      {"ply_binary_truncated", "c.ply", PlyBinaryHeader(3) + Floats({0, 0, 0, 1, 1}), "truncated",
       ""},
      {"ply_faces_forged", "c.ply",
       PlyBinaryHeader(3).insert(PlyBinaryHeader(3).find("end_header"),
                                 "element face 4000000000\nproperty list uchar int "
                                 "vertex_indices\n") +
           Floats({0, 0, 0, 1, 0, 0, 0, 1, 0}) + "\x03" + std::string(12, '\0'),
       "", ""},
      {"ply_duplicate_property", "c.ply",
       "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
       "property float z\nproperty float x\nend_header\n0 0 0 0\n",
       "twice", ""},
      {"ply_comment_flood", "c.ply",
       "ply\nformat ascii 1.0\n" + [] {
         std::string s;
         for (int i = 0; i < 200000; ++i) s += "comment hostile\n";
         return s;
       }() + "element vertex 300\nproperty float x\nproperty float y\nproperty float z\n"
             "property float nx\nproperty float ny\nproperty float nz\nend_header\n" +
           PlaneXyz(300),
       "", "", 0},
  };
}

std::vector<CloudFile> PcdClouds() {
  std::string bomb = PcdHeader("binary_compressed", 100000000);
  const std::uint32_t sizes[2] = {64, 1200000000u};
  bomb.append(reinterpret_cast<const char*>(sizes), 8);
  bomb.append(64, '\0');
  const std::string nan_points =
      PcdHeader("ascii", 302) + "nan nan nan\n" + PlaneXyz(300, false) + "nan nan nan\n";
  return {
      {"pcd_empty", "c.pcd", "", "empty", ""},
      {"pcd_garbage", "c.pcd", "\x89PNG\r\n\x1a\n garbage", "", ""},
      {"pcd_no_data", "c.pcd", "VERSION 0.7\nFIELDS x y z\n", "DATA", ""},
      {"pcd_points_mismatch", "c.pcd",
       PcdHeader("ascii", 2).replace(PcdHeader("ascii", 2).find("POINTS 2"), 8, "POINTS 5") +
           "0 0 0\n1 1 1\n",
       "POINTS", ""},
      {"pcd_width_overflow", "c.pcd",
       "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n"
       "WIDTH 4294967296\nHEIGHT 4294967296\nDATA binary\n",
       "", ""},
      {"pcd_billion_binary", "c.pcd", PcdHeader("binary", 1000000000) + Floats({0, 0, 0}),
       "", ""},
      {"pcd_lzf_bomb", "c.pcd", bomb, "compressed", "a compressed PCD expands to 7 GB"},
      {"pcd_binary_truncated", "c.pcd", PcdHeader("binary", 3) + Floats({0, 0, 0, 1}),
       "truncated", ""},
      {"pcd_ascii_inf", "c.pcd", PcdHeader("ascii", 2) + "0 0 0\n1 inf 0\n", "c.pcd:13", ""},
      {"pcd_ascii_word", "c.pcd", PcdHeader("ascii", 2) + "0 0 0\n1 y 0\n", "c.pcd:13", ""},
      {"pcd_bad_size", "c.pcd", PcdHeader("ascii", 1, "x y z", "4 4 3") + "0 0 0\n", "SIZE", ""},
      {"pcd_bad_type", "c.pcd", PcdHeader("ascii", 1, "x y z", "4 4 4", "F F Q") + "0 0 0\n",
       "TYPE", ""},
      {"pcd_no_z", "c.pcd", PcdHeader("ascii", 1, "x y", "4 4", "F F", "1 1") + "0 0\n", "x, y",
       ""},
      {"pcd_count_zero", "c.pcd", PcdHeader("ascii", 1, "x y z", "4 4 4", "F F F", "1 0 1") +
                                      "0 0\n",
       "COUNT", ""},
      {"pcd_data_unknown", "c.pcd", PcdHeader("lz4", 1) + "0 0 0\n", "DATA", ""},
      {"pcd_nan_points_counted", "c.pcd", nan_points + "", "2 of 302 records dropped",
       "NaN PCD points are dropped without a count", 0},
      {"pcd_all_nan", "c.pcd", PcdHeader("ascii", 2) + "nan nan nan\nnan nan nan\n", "no points",
       ""},
  };
}

// A command that reads CLOUD: {args with the cloud, the outputs it may write}.
struct Reader {
  std::string id, args;
  std::vector<std::string> outputs;
};

const std::vector<Reader> kReaders = {
    {"fit", "fit {c} --model plane --out m.json --report r.json", {"m.json", "r.json"}},
    {"eval", "eval s.json {c}", {}},
};

const std::vector<Reader> kAllReaders = {
    {"fit", "fit {c} --model plane --out m.json --report r.json", {"m.json", "r.json"}},
    {"eval", "eval s.json {c}", {}},
    {"detect", "detect {c} --out scene.json --labels l.txt", {"scene.json", "l.txt"}},
    {"reconstruct", "reconstruct {c} --out m.json --report r.json", {"m.json", "r.json"}},
    {"design", "design {c} --count 4 --out m.json", {"m.json"}},
};

std::string Replace(std::string s, const std::string& from, const std::string& to) {
  for (size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size()))
    s.replace(at, from.size(), to);
  return s;
}

}  // namespace

std::vector<Case> ReaderCases() {
  std::vector<Case> cases;
  int n = 0;
  for (const auto& list : {TextClouds(), PlyClouds(), PcdClouds()})
    for (const CloudFile& f : list)
      for (const Reader& r : kReaders) {
        Case c;
        c.family = "readers";
        c.name = f.id + "_" + r.id;
        c.setup = [f](const std::string& dir) {
          Write(dir + "/" + f.name, f.bytes);
          Write(dir + "/s.json", SphereModel());
        };
        c.args = Replace(r.args, "{c}", f.name);
        c.exit_code = f.exit_code;
        if (f.exit_code == 2) c.mention = {f.name};
        if (!f.mention.empty()) c.mention.push_back(f.mention);
        if (f.exit_code == 0) c.outputs = r.outputs;
        c.outputs = r.outputs;
        c.seconds = 10;
        c.defect = f.defect;
        c.sanitized = n++ % 3 == 0 || !f.defect.empty();
        cases.push_back(c);
      }
  // Files that are not regular files: never read (a FIFO would block, /dev/zero never ends).
  struct Special {
    std::string id, name, mention, defect;
    std::function<void(const std::string&)> make;
  };
  const std::vector<Special> specials = {
      {"fifo_xyz", "c.xyz", "FIFO", "a FIFO input blocks forever",
       [](const std::string& p) { MakeFifo(p); }},
      {"fifo_ply", "c.ply", "FIFO", "a FIFO input blocks forever (PLY read twice)",
       [](const std::string& p) { MakeFifo(p); }},
      {"fifo_pcd", "c.pcd", "FIFO", "a FIFO input blocks forever (PCD read twice)",
       [](const std::string& p) { MakeFifo(p); }},
      {"devzero_xyz", "c.xyz", "character device",
       "readers load the whole stream (/dev/zero through a symlink: 4 GB, bad_alloc)",
       [](const std::string& p) { MakeSymlink("/dev/zero", p); }},
      {"devzero_ply", "c.ply", "character device", "",
       [](const std::string& p) { MakeSymlink("/dev/zero", p); }},
      {"folder_xyz", "c.xyz", "directory", "",
       [](const std::string& p) { std::filesystem::create_directory(p); }},
      {"missing_xyz", "c.xyz", "No such file", "", [](const std::string&) {}},
  };
  for (const Special& s : specials)
    for (const Reader& r : kAllReaders) {
      Case c;
      c.family = "readers";
      c.name = s.id + "_" + r.id;
      c.setup = [s](const std::string& dir) {
        s.make(dir + "/" + s.name);
        Write(dir + "/s.json", SphereModel());
      };
      c.args = Replace(r.args, "{c}", s.name);
      c.mention = {s.name, s.mention};
      c.outputs = r.outputs;
      c.seconds = 10;
      c.defect = s.defect;
      c.sanitized = r.id == "fit" || r.id == "eval";
      cases.push_back(c);
    }
  return cases;
}

}  // namespace hostile
