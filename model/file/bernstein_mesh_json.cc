#include "model/file/bernstein_mesh_json.h"

#include <algorithm>
#include <cmath>

#include "model/file/model_json.h"

namespace implicitfit {
namespace {

using nlohmann::json;

// A mesh larger than this many control points is refused (a typo in "cells" should not
// allocate gigabytes).
constexpr long long kMaxMeshControlPoints = 200'000'000;
constexpr long long kMaxMeshDegree = kMaxPatchDegree;  // model_json.h

[[noreturn]] void Fail(const std::string& where, const std::string& problem) {
  throw ModelFormatError(where + ": " + problem);
}

double FiniteNumber(const json& v, const std::string& where) {
  if (!v.is_number()) Fail(where, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) Fail(where, "must be finite");
  if (std::abs(x) > kMaxModelMagnitude)
    Fail(where, "magnitude " + json(x).dump() + " exceeds " + json(kMaxModelMagnitude).dump() +
                    " (beyond what the evaluators handle)");
  return x;
}

long long Integer(const json& node, const std::string& key, const std::string& path) {
  if (!node.contains(key) || !node.at(key).is_number_integer())
    Fail(path + "." + key, "missing or not an integer");
  return node.at(key).get<long long>();
}

}  // namespace

int ReadBernsteinMeshNode(const json& node, const std::string& path, const std::string& name,
                          Model* model) {
  const long long k = Integer(node, "degree", path);
  if (k < 1 || k > kMaxMeshDegree)
    Fail(path + ".degree", "must be an integer in 1.." + std::to_string(kMaxMeshDegree));
  const long long continuity = Integer(node, "continuity", path);
  if (continuity != 0 && continuity != 1) Fail(path + ".continuity", "must be 0 or 1");
  const std::string gp = path + ".grid";
  if (!node.contains("grid") || !node.at("grid").is_object()) Fail(gp, "missing or not an object");
  const json& g = node.at("grid");
  for (auto it = g.begin(); it != g.end(); ++it)
    if (it.key() != "origin" && it.key() != "cell" && it.key() != "cells" && it.key() != "splits")
      Fail(gp + "." + it.key(), "unknown field of a grid (origin, cell, cells, splits)");
  BernsteinGrid grid;
  if (!g.contains("origin") || !g.at("origin").is_array() || g.at("origin").size() != 3)
    Fail(gp + ".origin", "must be an array of 3 numbers");
  for (int a = 0; a < 3; ++a)
    grid.origin[a] = FiniteNumber(g.at("origin")[a], gp + ".origin[" + std::to_string(a) + "]");
  if (!g.contains("cell")) Fail(gp + ".cell", "missing");
  grid.cell = FiniteNumber(g.at("cell"), gp + ".cell");
  if (!(grid.cell >= kMinModelLength)) Fail(gp + ".cell", "must be >= 1e-12");
  if (!g.contains("cells") || !g.at("cells").is_array() || g.at("cells").size() != 3)
    Fail(gp + ".cells", "must be an array of 3 positive integers");
  long long count = 6 * NumBernsteinControlPoints(k);
  for (int a = 0; a < 3; ++a) {
    const json& c = g.at("cells")[a];
    const std::string where = gp + ".cells[" + std::to_string(a) + "]";
    if (!c.is_number_integer() || c.get<long long>() < 1) Fail(where, "must be an integer >= 1");
    const long long n = c.get<long long>();
    if (n > kMaxMeshControlPoints || count * n > kMaxMeshControlPoints)
      Fail(gp + ".cells",
           "the mesh would exceed " + std::to_string(kMaxMeshControlPoints) + " control points");
    count *= n;
    grid.cells[a] = static_cast<int>(n);
  }
  if (g.contains("splits")) {  // adaptive refinement (model/bernstein/grid_refinement.h)
    const json& sp = g.at("splits");
    if (!sp.is_string()) Fail(gp + ".splits", "must be a string of split flags '0'/'1'");
    // Each '1' adds 7 leaves: bound the count before building anything.
    const std::string flags = sp.get<std::string>();
    const long long ones = std::count(flags.begin(), flags.end(), '1');
    const long long per_leaf = 6 * NumBernsteinControlPoints(k);
    if (count / per_leaf + 7 * ones > kMaxMeshControlPoints / per_leaf)
      Fail(gp + ".splits",
           "the mesh would exceed " + std::to_string(kMaxMeshControlPoints) + " control points");
    try {
      grid.refinement = RefinementFromSplits(grid.cells, flags);
    } catch (const std::invalid_argument& e) {
      Fail(gp + ".splits", e.what());
    }
    count = grid.NumTetrahedra() * NumBernsteinControlPoints(k);
  }
  if (node.contains("c0_faces")) {  // faces declared C0 only (creases)
    const std::string fp = path + ".c0_faces";
    const json& f = node.at("c0_faces");
    if (!f.is_array()) Fail(fp, "must be an array of [tetrahedron, face] pairs");
    grid.sharp.assign(static_cast<size_t>(grid.NumTetrahedra()), 0);
    for (size_t i = 0; i < f.size(); ++i) {
      const std::string where = fp + "[" + std::to_string(i) + "]";
      const json& e = f[i];
      if (!e.is_array() || e.size() != 2 || !e[0].is_number_integer() || !e[1].is_number_integer())
        Fail(where, "must be a pair [tetrahedron, face] of integers");
      const long long t = e[0].get<long long>(), o = e[1].get<long long>();
      if (t < 0 || t >= grid.NumTetrahedra())
        Fail(where, "tetrahedron must be in 0.." + std::to_string(grid.NumTetrahedra() - 1));
      if (o < 0 || o > 3) Fail(where, "face must be 0..3 (the opposite vertex)");
      grid.sharp[static_cast<size_t>(t)] |= static_cast<unsigned char>(1u << o);
    }
  }
  const std::string cp = path + ".control_points";
  if (!node.contains("control_points")) Fail(cp, "missing");
  const json& v = node.at("control_points");
  if (!v.is_array() || static_cast<long long>(v.size()) != count)
    Fail(cp, "must be an array of " + std::to_string(count) +
                 (grid.refined() ? " numbers (6 x leaves x (k+1)(k+2)(k+3)/6)"
                                 : " numbers (6 nx ny nz (k+1)(k+2)(k+3)/6)"));
  std::vector<double> b(static_cast<size_t>(count));
  for (size_t i = 0; i < b.size(); ++i)
    b[i] = FiniteNumber(v[i], cp + "[" + std::to_string(i) + "]");
  return model->AddBernsteinMesh(static_cast<int>(k), grid, static_cast<int>(continuity), b, name);
}

void WriteBernsteinMeshNode(const Model& model, const ModelNode& node, json* out) {
  const BernsteinGrid& g = node.grid;
  (*out)["degree"] = node.degree;
  (*out)["grid"] = {{"origin", {g.origin[0], g.origin[1], g.origin[2]}},
                    {"cell", g.cell},
                    {"cells", {g.cells[0], g.cells[1], g.cells[2]}}};
  if (g.refined() && g.MaxLevel() > 0) (*out)["grid"]["splits"] = SplitsOf(g.refinement);
  (*out)["continuity"] = node.continuity;
  if (g.HasSharpFaces()) {
    json faces = json::array();
    for (size_t t = 0; t < g.sharp.size(); ++t)
      for (int o = 0; o < 4; ++o)
        if ((g.sharp[t] >> o) & 1) faces.push_back({t, o});
    (*out)["c0_faces"] = faces;
  }
  const auto begin = model.parameters().begin() + node.first_parameter;
  (*out)["control_points"] = std::vector<double>(begin, begin + node.num_parameters);
}

}  // namespace implicitfit
