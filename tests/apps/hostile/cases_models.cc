// Hostile model files through every command that reads models (eval, mesh, sample, check):
// refused at read time with exit 2 and the file named, never an internal error later, never
// hours of meshing.
#include "apps/hostile/hostile_case.h"

namespace hostile {
namespace {

struct ModelFile {
  std::string id, bytes, mention, defect;
};

std::string Doc(const std::string& root) {
  return "{\"format\": \"implicitfit-model\", \"version\": 1, \"root\": " + root + "}";
}

std::string Deep(int depth) {
  std::string s;
  for (int i = 0; i < depth; ++i) s += "{\"type\": \"complement\", \"children\": [";
  s += "{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1}";
  for (int i = 0; i < depth; ++i) s += "]}";
  return Doc(s);
}

std::vector<ModelFile> Files() {
  const std::string sphere = "{\"type\": \"sphere\", \"center\": [0, 0, 0], \"radius\": 1}";
  return {
      {"empty", "", "invalid JSON", ""},
      {"not_json", "sphere radius 1\n", "invalid JSON", ""},
      {"truncated", Doc(sphere).substr(0, 60), "invalid JSON", ""},
      {"nan_literal", Doc("{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": NaN}"),
       "invalid JSON", ""},
      {"number_overflow", Doc("{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1e400}"),
       "invalid JSON", ""},
      {"duplicate_key",
       Doc("{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1, \"radius\": -5}"),
       "duplicate key", "JSON duplicate keys pass (last wins)"},
      {"duplicate_top_key",
       "{\"format\": \"implicitfit-model\", \"version\": 1, \"version\": 1, \"root\": " + sphere +
           "}",
       "duplicate key", "JSON duplicate keys pass (last wins)"},
      {"duplicate_nested_key",
       Doc("{\"type\": \"union\", \"delta\": 0.1, \"epsilon\": 0.05, \"order\": 3, \"children\": "
           "[" + sphere + ", {\"type\": \"sphere\", \"center\": [1,0,0], \"center\": [2,0,0], "
           "\"radius\": 1}]}"),
       "duplicate key", "JSON duplicate keys pass (last wins)"},
      {"radius_1e200", SphereModel(1e200), "exceeds",
       "models with radius 1e200 read, then internal errors in mesh"},
      {"centre_1e300",
       Doc("{\"type\": \"sphere\", \"center\": [1e300, 0, 0], \"radius\": 1}"), "exceeds",
       "models with radius 1e200 read, then internal errors in mesh"},
      {"radius_1e_minus_300", SphereModel(1e-300), "radius", ""},
      {"negative_radius", SphereModel(-1), "radius", ""},
      {"patch_degree_100", PatchModel(100), "degree",
       "a degree-100 patch (3 MB) takes hours to mesh or sample"},
      {"patch_degree_11", PatchModel(11), "degree",
       "a degree-100 patch (3 MB) takes hours to mesh or sample"},
      {"blobs_100000", BlobsModel(100000), "blobs", "10^5 blobs take hours to mesh or sample"},
      {"deep_100000", Deep(100000), "deeper", ""},
      {"wide_union_12000", WideUnionModel(12000), "nodes", ""},
      {"unknown_field", Doc("{\"type\": \"sphere\", \"center\": [0,0,0], \"radius\": 1, "
                            "\"colour\": \"red\"}"),
       "colour", ""},
      {"wrong_type", Doc("{\"type\": \"sphere\", \"center\": \"origin\", \"radius\": 1}"),
       "center", ""},
      {"unknown_node", Doc("{\"type\": \"hypersphere\", \"radius\": 1}"), "hypersphere", ""},
      {"version_2", "{\"format\": \"implicitfit-model\", \"version\": 2, \"root\": " + sphere +
                        "}",
       "version", ""},
      {"array_document", "[1, 2, 3]", "", ""},
      {"control_points_short",
       Doc("{\"type\": \"bernstein_patch\", \"degree\": 2, \"vertices\": "
           "[[0,0,0],[1,0,0],[0,1,0],[0,0,1]], \"control_points\": [1, 2]}"),
       "control_points", ""},
      {"degenerate_tetrahedron",
       Doc("{\"type\": \"bernstein_patch\", \"degree\": 1, \"vertices\": "
           "[[0,0,0],[1,0,0],[2,0,0],[3,0,0]], \"control_points\": [1, 2, 3, 4]}"),
       "vertices", ""},
  };
}

struct ModelCommand {
  std::string id, args;
  std::vector<std::string> outputs;
};

const std::vector<ModelCommand> kCommands = {
    {"eval", "eval m.json p.xyz", {}},
    {"mesh", "mesh m.json --out o.ply", {"o.ply"}},
    {"sample", "sample m.json --count 100 --out o.xyz", {"o.xyz"}},
    {"check", "check m.json", {}},
};

}  // namespace

std::vector<Case> ModelCases() {
  std::vector<Case> cases;
  int n = 0;
  for (const ModelFile& f : Files())
    for (const ModelCommand& command : kCommands) {
      Case c;
      c.family = "models";
      c.name = "model_" + f.id + "_" + command.id;
      c.setup = [f](const std::string& dir) {
        Write(dir + "/m.json", f.bytes);
        Write(dir + "/p.xyz", "0 0 0\n1 1 1\n");
      };
      c.args = command.args;
      c.mention = {"m.json"};
      if (!f.mention.empty()) c.mention.push_back(f.mention);
      c.outputs = command.outputs;
      c.seconds = 10;
      c.defect = f.defect;
      c.sanitized = n++ % 4 == 0;
      cases.push_back(c);
    }
  // Special files as models: never read.
  const std::vector<std::pair<std::string, std::string>> specials = {{"fifo", "FIFO"},
                                                                     {"devzero", "device"}};
  for (const auto& [id, mention] : specials)
    for (const ModelCommand& command : kCommands) {
      Case c;
      c.family = "models";
      c.name = "model_" + id + "_" + command.id;
      const std::string kind = id;
      c.setup = [kind](const std::string& dir) {
        if (kind == "fifo")
          MakeFifo(dir + "/m.json");
        else
          MakeSymlink("/dev/zero", dir + "/m.json");
        Write(dir + "/p.xyz", "0 0 0\n1 1 1\n");
      };
      c.args = command.args;
      c.mention = {"m.json", mention};
      c.outputs = command.outputs;
      c.seconds = 10;
      c.defect = "a FIFO input blocks forever; readers load the whole stream";
      c.sanitized = command.id == "eval";
      cases.push_back(c);
    }
  // A model larger than --max-json-mb: refused before parsing.
  for (const ModelCommand& command : kCommands) {
    Case c;
    c.family = "models";
    c.name = "model_over_json_limit_" + command.id;
    c.setup = [](const std::string& dir) {
      Write(dir + "/m.json", BlobsModel(100000));  // about 2.2 MiB
      Write(dir + "/p.xyz", "0 0 0\n");
    };
    c.args = command.args + " --max-json-mb 1";
    c.mention = {"max-json-mb"};
    c.outputs = command.outputs;
    cases.push_back(c);
    c.name = "model_over_json_limit_env_" + command.id;
    c.args = "env IMPLICITFIT_MAX_JSON_MB=abc {cli} " + command.args;
    c.mention = {"IMPLICITFIT_MAX_JSON_MB"};
    cases.push_back(c);
  }
  return cases;
}

}  // namespace hostile
