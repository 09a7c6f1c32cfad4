// The structure of a spline node (what is not a fitted parameter): degrees, control-point
// counts, knot vectors, rational weights, the box and cells of a volume, the kind of a curve.
// The control points (surfaces, curves) and coefficients (volumes) are the node's parameters
// in the model's flat vector. Limits keep every evaluation and every buffer bounded; the model
// reader refuses larger nodes with a message naming the field (model/file/spline_json.h).
#pragma once

#include <string>
#include <vector>

#include "model/splines/bspline_basis.h"

namespace implicitfit {

// A curve skeleton's kind (skeleton_offset with "curve": model/splines/curve_skeleton.h).
enum class CurveKind {
  kBSpline = 0,  // B-spline or NURBS (a Bezier curve is the clamped case with n = p + 1)
  kEllipse = 1,  // c + A cos(2 pi t) + B sin(2 pi t), t in [0, 1]
  kHelix = 2,    // c + A cos(2 pi t) + B sin(2 pi t) + C t, t in [0, turns]
};

struct SplineLimits {
  static constexpr int kMaxDegree = 7;                 // surfaces and curves (<= kMaxSplineDegree)
  static constexpr int kMaxVolumeDegree = 5;           // bspline_volume
  static constexpr int kMaxControlPoints = 1 << 16;    // surface n_u n_v, curve n
  static constexpr int kMaxControlPointsPerAxis = 4096;
  static constexpr long long kMaxVolumeCoefficients = 1 << 21;  // (n_x + k)(n_y + k)(n_z + k)
  static constexpr int kMaxVolumeCells = 128;          // per axis
  static constexpr double kMaxHelixTurns = 1000.0;
  static constexpr double kMinWeight = 1e-9;           // rational weights must exceed this
};

struct SplineStructure {
  int degree[3] = {0, 0, 0};
  int count[3] = {0, 0, 0};         // control points (coefficients) along each parameter
  std::vector<double> knots[3];     // per parameter direction (volume: clamped uniform)
  std::vector<double> weights;      // rational weights (same layout as the points); empty: 1
  double box[6] = {0, 0, 0, 0, 0, 0};  // bspline_volume: x0, y0, z0, x1, y1, z1
  int cells[3] = {0, 0, 0};            // bspline_volume: cells per axis
  CurveKind curve = CurveKind::kBSpline;
  double turns = 1.0;  // helix: the parameter range [0, turns]

  bool rational() const { return !weights.empty(); }
  double weight(int i) const { return weights.empty() ? 1.0 : weights[i]; }
  // The parameter range [u_p, u_n] of direction d.
  double Begin(int d) const { return knots[d][degree[d]]; }
  double End(int d) const { return knots[d][count[d]]; }
};

// "" when the structure is valid (degrees, counts, knots, weights within SplineLimits), else
// the problem, starting with the field it concerns ("knots_u: ...", "weights[3]: ...").
std::string SurfaceStructureProblem(const SplineStructure& s);
std::string CurveStructureProblem(const SplineStructure& s);
std::string VolumeStructureProblem(int degree, const double box[6], const int cells[3]);

// The structure of a bspline_volume: degree k, box, cells; counts and clamped uniform knots
// filled in (model/splines/bspline_volume.h).
SplineStructure BSplineVolumeStructure(int degree, const double box[6], const int cells[3]);

}  // namespace implicitfit
