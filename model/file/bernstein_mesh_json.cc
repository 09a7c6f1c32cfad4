#include "model/file/bernstein_mesh_json.h"

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
    if (it.key() != "origin" && it.key() != "cell" && it.key() != "cells")
      Fail(gp + "." + it.key(), "unknown field of a grid (origin, cell, cells)");
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
  const std::string cp = path + ".control_points";
  if (!node.contains("control_points")) Fail(cp, "missing");
  const json& v = node.at("control_points");
  if (!v.is_array() || static_cast<long long>(v.size()) != count)
    Fail(cp, "must be an array of " + std::to_string(count) +
                 " numbers (6 nx ny nz (k+1)(k+2)(k+3)/6)");
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
  (*out)["continuity"] = node.continuity;
  const auto begin = model.parameters().begin() + node.first_parameter;
  (*out)["control_points"] = std::vector<double>(begin, begin + node.num_parameters);
}

}  // namespace implicitfit
