#include "model/splines/spline_structure.h"

#include <cmath>
#include <string>


namespace implicitfit {

SplineStructure BSplineVolumeStructure(int degree, const double box[6], const int cells[3]) {
  SplineStructure s;
  for (int a = 0; a < 3; ++a) {
    s.degree[a] = degree;
    s.cells[a] = cells[a];
    s.count[a] = cells[a] + degree;
    s.box[a] = box[a];
    s.box[3 + a] = box[3 + a];
    s.knots[a] = ClampedUniformKnots(degree, s.count[a], box[a], box[3 + a]);
  }
  return s;
}

namespace {

std::string Direction(int d) { return d == 0 ? "u" : "v"; }

std::string WeightsProblem(const SplineStructure& s, long long count) {
  if (!s.rational()) return "";
  if (static_cast<long long>(s.weights.size()) != count)
    return "weights: must hold " + std::to_string(count) + " numbers (one per control point)";
  for (size_t i = 0; i < s.weights.size(); ++i)
    if (!std::isfinite(s.weights[i]) || !(s.weights[i] > SplineLimits::kMinWeight))
      return "weights[" + std::to_string(i) + "]: must be finite and > " +
             std::to_string(SplineLimits::kMinWeight);
  return "";
}

std::string DegreeAndCountProblem(int degree, int count, int max_degree, const std::string& d) {
  if (degree < 1 || degree > max_degree)
    return "degree" + d + ": must be an integer in 1.." + std::to_string(max_degree);
  if (count < degree + 1 || count > SplineLimits::kMaxControlPointsPerAxis)
    return "control points" + d + ": " + std::to_string(count) + " given, need " +
           std::to_string(degree + 1) + ".." +
           std::to_string(SplineLimits::kMaxControlPointsPerAxis) + " (degree + 1 at least)";
  return "";
}

}  // namespace

std::string SurfaceStructureProblem(const SplineStructure& s) {
  for (int d = 0; d < 2; ++d) {
    std::string problem = DegreeAndCountProblem(s.degree[d], s.count[d], SplineLimits::kMaxDegree,
                                                " along " + Direction(d));
    if (!problem.empty()) return problem;
    problem = KnotVectorProblem(s.knots[d], s.degree[d], s.count[d]);
    if (!problem.empty()) return "knots_" + Direction(d) + ": " + problem;
  }
  const long long n = static_cast<long long>(s.count[0]) * s.count[1];
  if (n > SplineLimits::kMaxControlPoints)
    return "control points: " + std::to_string(n) + " exceed the limit of " +
           std::to_string(SplineLimits::kMaxControlPoints);
  return WeightsProblem(s, n);
}

std::string CurveStructureProblem(const SplineStructure& s) {
  if (s.curve == CurveKind::kEllipse) return "";
  if (s.curve == CurveKind::kHelix) {
    if (!std::isfinite(s.turns) || !(s.turns > 0.0) || s.turns > SplineLimits::kMaxHelixTurns)
      return "turns: must be in (0, " + std::to_string(SplineLimits::kMaxHelixTurns) + "]";
    return "";
  }
  std::string problem =
      DegreeAndCountProblem(s.degree[0], s.count[0], SplineLimits::kMaxDegree, "");
  if (!problem.empty()) return problem;
  problem = KnotVectorProblem(s.knots[0], s.degree[0], s.count[0]);
  if (!problem.empty()) return "knots: " + problem;
  return WeightsProblem(s, s.count[0]);
}

std::string VolumeStructureProblem(int degree, const double box[6], const int cells[3]) {
  if (degree < 1 || degree > SplineLimits::kMaxVolumeDegree)
    return "degree: must be an integer in 1.." + std::to_string(SplineLimits::kMaxVolumeDegree);
  long long total = 1;
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(box[a]) || !std::isfinite(box[3 + a]) || !(box[a] < box[3 + a]))
      return "box: needs finite x0 < x1, y0 < y1, z0 < z1";
    if (cells[a] < 1 || cells[a] > SplineLimits::kMaxVolumeCells)
      return "cells: every entry must be in 1.." + std::to_string(SplineLimits::kMaxVolumeCells);
    total *= cells[a] + degree;
  }
  if (total > SplineLimits::kMaxVolumeCoefficients)
    return "coefficients: " + std::to_string(total) + " exceed the limit of " +
           std::to_string(SplineLimits::kMaxVolumeCoefficients);
  return "";
}

}  // namespace implicitfit
