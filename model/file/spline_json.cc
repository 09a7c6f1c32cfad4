#include "model/file/spline_json.h"

#include <cmath>
#include <stdexcept>

#include "model/file/model_json.h"
#include "model/splines/curve_skeleton.h"

namespace implicitfit {
namespace {

using nlohmann::json;

[[noreturn]] void Refuse(const std::string& where, const std::string& problem) {
  throw ModelFormatError(where + ": " + problem);
}

const json& Field(const json& node, const std::string& key, const std::string& path) {
  if (!node.is_object() || !node.contains(key)) Refuse(path + "." + key, "missing");
  return node.at(key);
}

double Finite(const json& v, const std::string& where) {
  if (!v.is_number()) Refuse(where, "must be a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) Refuse(where, "must be finite");
  return x;
}

// An array of numbers of any length up to `most` (exactly `size` when size >= 0).
std::vector<double> Numbers(const json& v, const std::string& where, long long size,
                            long long most) {
  if (!v.is_array()) Refuse(where, "must be an array of numbers");
  if (size >= 0 && static_cast<long long>(v.size()) != size)
    Refuse(where, "must hold " + std::to_string(size) + " numbers");
  if (static_cast<long long>(v.size()) > most)
    Refuse(where, "holds " + std::to_string(v.size()) + " numbers, more than the limit of " +
                      std::to_string(most));
  std::vector<double> out;
  out.reserve(v.size());
  for (size_t i = 0; i < v.size(); ++i) out.push_back(Finite(v[i], where + "[" + std::to_string(i) + "]"));
  return out;
}

// A list of points [[x, y, z], ...] of at least `least` and at most `most` points.
std::vector<double> Points(const json& v, const std::string& where, size_t least, long long most) {
  if (!v.is_array() || v.size() < least)
    Refuse(where, "must be an array of at least " + std::to_string(least) + " points [x, y, z]");
  if (static_cast<long long>(v.size()) > most)
    Refuse(where, "holds " + std::to_string(v.size()) + " points, more than the limit of " +
                      std::to_string(most));
  std::vector<double> out;
  for (size_t i = 0; i < v.size(); ++i) {
    const std::vector<double> x = Numbers(v[i], where + "[" + std::to_string(i) + "]", 3, 3);
    out.insert(out.end(), x.begin(), x.end());
  }
  return out;
}

long long Integer(const json& v, const std::string& where) {
  if (!v.is_number_integer()) Refuse(where, "must be an integer");
  return v.get<long long>();
}

int Degree(const json& v, const std::string& where, int most) {
  const long long k = Integer(v, where);
  if (k < 1 || k > most) Refuse(where, "must be an integer in 1.." + std::to_string(most));
  return static_cast<int>(k);
}

void CheckKeysOf(const json& object, const std::vector<std::string>& allowed,
                 const std::string& where) {
  if (!object.is_object()) Refuse(where, "must be an object");
  for (auto it = object.begin(); it != object.end(); ++it) {
    bool known = false;
    for (const std::string& key : allowed) known |= it.key() == key;
    if (!known) Refuse(where + "." + it.key(), "unknown field");
  }
}

// Knots of direction d from `key` when present, else clamped uniform on [0, 1].
void ReadKnots(const json& node, const std::string& key, const std::string& path, int d,
               SplineStructure* s) {
  if (node.contains(key)) {
    s->knots[d] = Numbers(node.at(key), path + "." + key, -1,
                          SplineLimits::kMaxControlPointsPerAxis + SplineLimits::kMaxDegree + 1);
    const std::string problem = KnotVectorProblem(s->knots[d], s->degree[d], s->count[d]);
    if (!problem.empty()) Refuse(path + "." + key, problem);
  } else {
    s->knots[d] = ClampedUniformKnots(s->degree[d], s->count[d], 0.0, 1.0);
  }
}

json Slice(const std::vector<double>& p, size_t begin, size_t size) {
  return json(std::vector<double>(p.begin() + begin, p.begin() + begin + size));
}

json PointList(const std::vector<double>& p, size_t begin, int count) {
  json list = json::array();
  for (int i = 0; i < count; ++i) list.push_back(Slice(p, begin + 3 * i, 3));
  return list;
}

// The count of degree + 1 .. kMaxControlPointsPerAxis checked up front (before the knots).
void RequireCount(int count, int degree, const std::string& where) {
  if (count < degree + 1)
    Refuse(where, "degree " + std::to_string(degree) + " needs at least " +
                      std::to_string(degree + 1) + " control points along it, not " +
                      std::to_string(count));
}

}  // namespace

int ReadBSplineSurfaceNode(const json& node, const std::string& path, const std::string& name,
                           Model* model) {
  SplineStructure s;
  const json& degree = Field(node, "degree", path);
  if (!degree.is_array() || degree.size() != 2)
    Refuse(path + ".degree", "must be [p, q], the degrees along u and v");
  for (int d = 0; d < 2; ++d)
    s.degree[d] = Degree(degree[d], path + ".degree[" + std::to_string(d) + "]",
                         SplineLimits::kMaxDegree);
  const json& rows = Field(node, "control_points", path);
  const std::string at = path + ".control_points";
  if (!rows.is_array() || rows.empty() || !rows[0].is_array())
    Refuse(at, "must be an array of rows of points [[[x, y, z], ...], ...]");
  if (rows.size() > SplineLimits::kMaxControlPointsPerAxis ||
      rows[0].size() > SplineLimits::kMaxControlPointsPerAxis ||
      static_cast<long long>(rows.size()) * static_cast<long long>(rows[0].size()) >
          SplineLimits::kMaxControlPoints)
    Refuse(at, "more than the limit of " + std::to_string(SplineLimits::kMaxControlPoints) +
                   " control points (" + std::to_string(SplineLimits::kMaxControlPointsPerAxis) +
                   " per direction)");
  s.count[0] = static_cast<int>(rows.size());
  s.count[1] = static_cast<int>(rows[0].size());
  RequireCount(s.count[0], s.degree[0], at);
  RequireCount(s.count[1], s.degree[1], at + "[0]");
  std::vector<double> points;
  for (size_t i = 0; i < rows.size(); ++i) {
    const std::string row = at + "[" + std::to_string(i) + "]";
    if (!rows[i].is_array() || static_cast<int>(rows[i].size()) != s.count[1])
      Refuse(row, "every row must hold " + std::to_string(s.count[1]) + " points");
    const std::vector<double> x = Points(rows[i], row, 1, s.count[1]);
    points.insert(points.end(), x.begin(), x.end());
  }
  ReadKnots(node, "knots_u", path, 0, &s);
  ReadKnots(node, "knots_v", path, 1, &s);
  if (node.contains("weights")) {
    const json& w = node.at("weights");
    if (!w.is_array() || static_cast<int>(w.size()) != s.count[0])
      Refuse(path + ".weights", "must hold " + std::to_string(s.count[0]) + " rows of " +
                                    std::to_string(s.count[1]) + " weights");
    for (size_t i = 0; i < w.size(); ++i) {
      const std::vector<double> row =
          Numbers(w[i], path + ".weights[" + std::to_string(i) + "]", s.count[1], s.count[1]);
      for (size_t j = 0; j < row.size(); ++j)
        if (!(row[j] > SplineLimits::kMinWeight))
          Refuse(path + ".weights[" + std::to_string(i) + "][" + std::to_string(j) + "]",
                 "must be > 0");
      s.weights.insert(s.weights.end(), row.begin(), row.end());
    }
  }
  try {
    return model->AddBSplineSurface(s, points, name);
  } catch (const std::invalid_argument& e) {
    Refuse(path, e.what());
  }
}

void WriteBSplineSurfaceNode(const Model& model, const ModelNode& node, json* out) {
  const SplineStructure& s = node.spline;
  const std::vector<double>& p = model.parameters();
  (*out)["degree"] = {s.degree[0], s.degree[1]};
  (*out)["knots_u"] = s.knots[0];
  (*out)["knots_v"] = s.knots[1];
  json rows = json::array(), weights = json::array();
  for (int i = 0; i < s.count[0]; ++i) {
    rows.push_back(PointList(p, node.first_parameter + 3 * i * s.count[1], s.count[1]));
    if (s.rational())
      weights.push_back(Slice(s.weights, static_cast<size_t>(i) * s.count[1], s.count[1]));
  }
  (*out)["control_points"] = rows;
  if (s.rational()) (*out)["weights"] = weights;
}

int ReadBSplineVolumeNode(const json& node, const std::string& path, const std::string& name,
                          Model* model) {
  const int k = Degree(Field(node, "degree", path), path + ".degree",
                       SplineLimits::kMaxVolumeDegree);
  const std::vector<double> box = Numbers(Field(node, "box", path), path + ".box", 6, 6);
  const json& c = Field(node, "cells", path);
  if (!c.is_array() || c.size() != 3) Refuse(path + ".cells", "must be [n_x, n_y, n_z]");
  int cells[3];
  for (int a = 0; a < 3; ++a) {
    const long long n = Integer(c[a], path + ".cells[" + std::to_string(a) + "]");
    if (n < 1 || n > SplineLimits::kMaxVolumeCells)
      Refuse(path + ".cells[" + std::to_string(a) + "]",
             "must be an integer in 1.." + std::to_string(SplineLimits::kMaxVolumeCells));
    cells[a] = static_cast<int>(n);
  }
  const std::string problem = VolumeStructureProblem(k, box.data(), cells);
  if (!problem.empty()) Refuse(path, problem);
  const long long count = static_cast<long long>(cells[0] + k) * (cells[1] + k) * (cells[2] + k);
  const std::vector<double> coefficients =
      Numbers(Field(node, "coefficients", path), path + ".coefficients", count, count);
  return model->AddBSplineVolume(k, box.data(), cells, coefficients, name);
}

void WriteBSplineVolumeNode(const Model& model, const ModelNode& node, json* out) {
  const SplineStructure& s = node.spline;
  (*out)["degree"] = s.degree[0];
  (*out)["box"] = std::vector<double>(s.box, s.box + 6);
  (*out)["cells"] = {s.cells[0], s.cells[1], s.cells[2]};
  (*out)["coefficients"] = Slice(model.parameters(), node.first_parameter, node.num_parameters);
}

int ReadCurveSkeletonOffset(const json& curve, const std::string& where, double radius,
                            const std::vector<double>& features, const std::string& name,
                            Model* model) {
  if (!curve.is_object() || curve.size() != 1)
    Refuse(where, "must be an object with exactly one of bspline, bezier, ellipse, helix, segment");
  const std::string kind = curve.begin().key();
  const json& c = curve.begin().value();
  const std::string at = where + "." + kind;
  SplineStructure s;
  std::vector<double> vectors;
  if (kind == "segment") {
    const std::vector<double> ends = Points(c, at, 2, 2);
    const int index = model->AddSkeletonOffset(SkeletonKind::kSegments, ends, radius, name);
    return features.empty() ? index : model->AddSkeletonFeatures(index, features);
  } else if (kind == "bspline" || kind == "bezier") {
    const bool bezier = kind == "bezier";
    CheckKeysOf(c, bezier ? std::vector<std::string>{"control_points", "weights"}
                          : std::vector<std::string>{"degree", "knots", "control_points", "weights"},
                at);
    vectors = Points(Field(c, "control_points", at), at + ".control_points", 2,
                     SplineLimits::kMaxControlPointsPerAxis);
    s.count[0] = static_cast<int>(vectors.size() / 3);
    if (bezier) {
      s.degree[0] = s.count[0] - 1;
      if (s.degree[0] > SplineLimits::kMaxDegree)
        Refuse(at + ".control_points", "a Bezier curve of more than " +
                                           std::to_string(SplineLimits::kMaxDegree + 1) +
                                           " control points: use a bspline");
    } else {
      s.degree[0] = Degree(Field(c, "degree", at), at + ".degree", SplineLimits::kMaxDegree);
      RequireCount(s.count[0], s.degree[0], at + ".control_points");
    }
    ReadKnots(c, "knots", at, 0, &s);
    if (c.contains("weights")) {
      s.weights = Numbers(c.at("weights"), at + ".weights", s.count[0], s.count[0]);
      for (size_t i = 0; i < s.weights.size(); ++i)
        if (!(s.weights[i] > SplineLimits::kMinWeight))
          Refuse(at + ".weights[" + std::to_string(i) + "]", "must be > 0");
    }
  } else if (kind == "ellipse" || kind == "helix") {
    const bool helix = kind == "helix";
    CheckKeysOf(c, helix ? std::vector<std::string>{"center", "axes", "rise", "turns"}
                         : std::vector<std::string>{"center", "axes"},
                at);
    s.curve = helix ? CurveKind::kHelix : CurveKind::kEllipse;
    vectors = Numbers(Field(c, "center", at), at + ".center", 3, 3);
    const std::vector<double> axes = Points(Field(c, "axes", at), at + ".axes", 2, 2);
    const double cross[3] = {axes[1] * axes[5] - axes[2] * axes[4],
                             axes[2] * axes[3] - axes[0] * axes[5],
                             axes[0] * axes[4] - axes[1] * axes[3]};
    if (!(cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2] > 0.0))
      Refuse(at + ".axes", "the two semi-diameters must not be parallel (nor zero)");
    vectors.insert(vectors.end(), axes.begin(), axes.end());
    if (helix) {
      const std::vector<double> rise = Numbers(Field(c, "rise", at), at + ".rise", 3, 3);
      vectors.insert(vectors.end(), rise.begin(), rise.end());
      s.turns = Finite(Field(c, "turns", at), at + ".turns");
      if (!(s.turns > 0.0) || s.turns > SplineLimits::kMaxHelixTurns)
        Refuse(at + ".turns", "must be in (0, " + std::to_string(SplineLimits::kMaxHelixTurns) +
                                  "]");
    }
  } else {
    Refuse(at, "unknown curve (bspline, bezier, ellipse, helix or segment)");
  }
  int index;
  try {
    index = model->AddCurveSkeletonOffset(s, vectors, radius, name);
  } catch (const std::invalid_argument& e) {
    Refuse(at, e.what());
  }
  return features.empty() ? index : model->AddSkeletonFeatures(index, features);
}

json WriteCurveSkeleton(const Model& model, const ModelNode& node) {
  const SplineStructure& s = node.spline;
  const std::vector<double>& p = model.parameters();
  const size_t b = node.first_parameter;
  json curve;
  if (s.curve == CurveKind::kBSpline) {
    curve["degree"] = s.degree[0];
    curve["knots"] = s.knots[0];
    curve["control_points"] = PointList(p, b, s.count[0]);
    if (s.rational()) curve["weights"] = s.weights;
    return json{{"curve", {{"bspline", curve}}}};
  }
  curve["center"] = Slice(p, b, 3);
  curve["axes"] = PointList(p, b + 3, 2);
  if (s.curve == CurveKind::kEllipse) return json{{"curve", {{"ellipse", curve}}}};
  curve["rise"] = Slice(p, b + 9, 3);
  curve["turns"] = s.turns;
  return json{{"curve", {{"helix", curve}}}};
}

std::vector<std::vector<double>> ReadCurveFeatures(const json& list, const std::string& where) {
  if (!list.is_array() || list.empty() || list.size() > 4096)
    Refuse(where, "must be an array of 1..4096 curve features");
  std::vector<std::vector<double>> out;
  for (size_t f = 0; f < list.size(); ++f) {
    const std::string at = where + "[" + std::to_string(f) + "]";
    CheckKeysOf(list[f], {"curve", "width", "depth", "radius", "flare"}, at);
    std::vector<double> c = Points(Field(list[f], "curve", at), at + ".curve", 1, 4096);
    const double w = Finite(Field(list[f], "width", at), at + ".width");
    const double d = Finite(Field(list[f], "depth", at), at + ".depth");
    const double r = Finite(Field(list[f], "radius", at), at + ".radius");
    const double flare = Finite(Field(list[f], "flare", at), at + ".flare");
    if (!(w > 0)) Refuse(at + ".width", "must be > 0");
    if (!(r > 0)) Refuse(at + ".radius", "must be > 0");
    if (d < 0) Refuse(at + ".depth", "must be >= 0");
    if (flare < 0 || flare > 1) Refuse(at + ".flare", "must be in [0, 1]");
    c.insert(c.end(), {w, d, r, flare});
    out.push_back(std::move(c));
  }
  return out;
}

json WriteCurveFeatures(const Model& model, const ModelNode& node) {
  const std::vector<double>& p = model.parameters();
  size_t q = node.first_parameter + 1 + ColemanFeatures::kPerFeature * node.count;
  json list = json::array();
  for (int n : node.curve_vertices) {
    const size_t e = q + 3 * n;
    list.push_back({{"curve", PointList(p, q, n)},
                    {"width", p[e]},
                    {"depth", p[e + 1]},
                    {"radius", p[e + 2]},
                    {"flare", p[e + 3]}});
    q = e + 4;
  }
  return list;
}

}  // namespace implicitfit
